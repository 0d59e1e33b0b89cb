#!/usr/bin/env python3
"""Open a page in headless Chromium and report what its probe measured, and a screenshot.

Chromium is driven over its DevTools pipe (--remote-debugging-pipe: JSON messages, each ending in a
NUL byte, read on fd 3 and written on fd 4), so the test waits in real time for the probe's promise
`window.probeResult` to settle, however long decoding takes under load, rather than on a virtual time
budget, which runs out while media decode off the network.

usage: browser.py PROBE_URL PAGE_URL RESULT.json SCREENSHOT.png WIDTH [HIDE_SELECTOR]
  PROBE_URL       the page with the probe (probe.js), whose window.probeResult is awaited
  RESULT.json     what it resolves to
  PAGE_URL        the page itself, opened in a fresh tab for the screenshot
  SCREENSHOT.png  the page's first HEIGHT pixels at WIDTH, with HIDE_SELECTOR's elements made invisible
"""
import base64
import json
import os
import select
import shutil
import subprocess
import sys
import tempfile
import time

TIMEOUT = 60.0  # s for the whole session: a page that never settles fails, it does not hang
HEIGHT = 1180   # css pixels of the screenshot: the header, the contents, the first scene
# every video's metadata loaded and its loading over (its controls show its length, no spinner), and
# every image decoded
READY = ("Promise.all([...document.querySelectorAll('video')].map(v => new Promise(r => {"
         " const check = () => (v.readyState >= 1 && v.networkState !== 2) || v.error ? r() : setTimeout(check, 50);"
         " check(); })).concat([...document.images].map(i => i.decode().catch(() => 0))))")


class Browser:
    def __init__(self, profile):
        chromium = shutil.which("chromium") or shutil.which("chromium-browser")
        if not chromium:
            sys.exit("FAIL: no chromium on PATH (Debian: apt-get install chromium; `make test` installs it)")
        to_child, self.write_end = os.pipe()
        self.read_end, from_child = os.pipe()

        def pipes_on_3_and_4():
            # above 4 first, so that neither lands on the other
            a, b = os.dup(to_child), os.dup(from_child)
            os.dup2(a, 3)
            os.dup2(b, 4)

        self.process = subprocess.Popen(
            [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             "--hide-scrollbars", "--mute-audio", "--user-data-dir=" + profile, "--remote-debugging-pipe",
             "about:blank"],
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            preexec_fn=pipes_on_3_and_4, close_fds=False)
        os.close(to_child)
        os.close(from_child)
        self.buffer = b""
        self.next_id = 0
        self.events = []
        self.deadline = time.monotonic() + TIMEOUT

    def send(self, method, params=None, session=None):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self.write_end, json.dumps(message).encode() + b"\0")
        return self.next_id

    def receive(self):
        while b"\0" not in self.buffer:
            left = self.deadline - time.monotonic()
            if left <= 0 or not select.select([self.read_end], [], [], left)[0]:
                sys.exit("FAIL: the browser did not answer within %d s" % TIMEOUT)
            chunk = os.read(self.read_end, 1 << 20)
            if not chunk:
                sys.exit("FAIL: the browser closed its pipe")
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, params=None, session=None):
        wanted = self.send(method, params, session)
        while True:
            m = self.receive()
            if m.get("id") == wanted:
                if "error" in m:
                    sys.exit("FAIL: %s: %s" % (method, m["error"]))
                return m["result"]
            self.events.append(m)

    def wait_for(self, method):
        for i, m in enumerate(self.events):
            if m.get("method") == method:
                return self.events.pop(i)
        while True:
            m = self.receive()
            if m.get("method") == method:
                return m
            self.events.append(m)

    def close(self):
        try:
            self.send("Browser.close")
        except OSError:
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()


def main():
    if len(sys.argv) not in (6, 7):
        sys.exit(__doc__)
    url, page, result_path, screenshot_path, width = sys.argv[1:6]
    width = int(width)
    hide = sys.argv[6] if len(sys.argv) == 7 else ""
    with tempfile.TemporaryDirectory() as profile:
        b = Browser(profile)
        try:
            target = b.call("Target.createTarget", {"url": "about:blank"})["targetId"]
            s = b.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
            metrics = {"width": width, "height": HEIGHT, "deviceScaleFactor": 1, "mobile": False}
            b.call("Emulation.setDeviceMetricsOverride", metrics, s)
            b.call("Page.enable", {}, s)
            b.call("Page.navigate", {"url": url}, s)
            b.wait_for("Page.loadEventFired")
            # the probe's promise, awaited in real time
            r = b.call("Runtime.evaluate", {"expression": "window.probeResult", "awaitPromise": True,
                                            "returnByValue": True}, s)
            if "exceptionDetails" in r:
                sys.exit("FAIL: the probe threw: %s" % r["exceptionDetails"].get("text"))
            with open(result_path, "w") as f:
                json.dump(r["result"]["value"], f)
            # the page as a reader first sees it, in a tab of its own (the probe's tab has seeked
            # every video to its end): every video showing its poster, its length known
            target = b.call("Target.createTarget", {"url": "about:blank"})["targetId"]
            s = b.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
            b.call("Emulation.setDeviceMetricsOverride", metrics, s)
            b.call("Page.enable", {}, s)
            b.call("Page.navigate", {"url": page}, s)
            b.wait_for("Page.loadEventFired")
            b.call("Runtime.evaluate", {"expression": READY, "awaitPromise": True}, s)
            # the first HEIGHT pixels (the header, the contents, the first scene's videos and panels),
            # times that vary made invisible
            if hide:
                b.call("Runtime.evaluate", {"expression": "document.querySelectorAll(%s).forEach("
                       "e => e.style.visibility = 'hidden')" % json.dumps(hide)}, s)
            # once it stops changing: the video controls' loading spinner fades out after loading
            shot, previous = None, ""
            for _ in range(40):
                shot = b.call("Page.captureScreenshot", {"format": "png"}, s)["data"]
                if shot == previous:
                    break
                previous = shot
                time.sleep(0.25)
            with open(screenshot_path, "wb") as f:
                f.write(base64.b64decode(shot))
        finally:
            b.close()


if __name__ == "__main__":
    main()
