#!/usr/bin/env bash
# The lecture page in a real browser (ctest page_browser): the pack the GNU Parallel test leaves
# (lecture_parallel), its index.html opened in headless Chromium with a probe script (probe.js,
# driven by browser.py over the DevTools pipe). Every video loads a frame (readyState ≥ 2, no media
# error) and decodes its last one, with the duration and frame size ffprobe reads from its MP4, and
# the page states both; every image and poster decodes at its stated size; every link reaches a file
# of the folder (or an id of the page); no script or loading error. A screenshot of the page at
# 1280 px wide (its first 1180 px: the header, the contents and the first scene's videos and panels)
# is compared with tests/golden/page/index.png. Then the layout at 390 and 1280 px (layout.js): no
# horizontal scroll, tables scrolling in their own box (at 390 px each row a card of labelled cells,
# all within the window), every video's controls below its picture.
#
# The mp4 is H.264: Debian's chromium plays it (its ffmpeg has the decoder), which this test shows by
# decoding every video's last frame, not by asking canPlayType.
#
# usage: bash page_browser_test.sh <pack-dir> <project-source-dir> <screenshot-check> <work-dir>
set -u

if [ $# -ne 4 ]; then
  echo "usage: $0 <pack-dir> <project-source-dir> <screenshot-check> <work-dir>" >&2
  exit 2
fi
PACK=$1
SRC=$2
SCREENSHOT_CHECK=$3
WORK=$4
HERE="$SRC/tests/render/page"
failed=0
fail() { echo "FAIL: $*"; failed=1; }

[ -f "$PACK/index.html" ] || { echo "FAIL: no page in $PACK (the lecture_parallel test renders it)"; exit 1; }
# a copy of the pack, the probe injected first into a copy of its page
rm -rf "$WORK"
mkdir -p "$WORK"
cp -r "$PACK" "$WORK/pack"
cp "$HERE/probe.js" "$WORK/pack/"
sed 's|<head>|<head>\n<script src="probe.js"></script>|' "$PACK/index.html" >"$WORK/pack/probe.html"

# what ffprobe says of each video: path, duration, width, height
for f in "$WORK"/pack/*/*.mp4; do
  echo "$f $(ffprobe -v error -select_streams v:0 -show_entries stream=width,height:format=duration -of default=nw=1:nk=1 "$f" | tr '\n' ' ')"
done >"$WORK/ffprobe"

start=$(date +%s%N)
python3 "$HERE/browser.py" "file://$WORK/pack/probe.html" "file://$WORK/pack/index.html" "$WORK/probe.json" \
  "$WORK/screenshot.png" 1280 ".seconds" ||
  { echo "FAIL: the browser could not open the page"; exit 1; }
echo "the browser: $(( ($(date +%s%N) - start) / 1000000 )) ms"

python3 - "$WORK/probe.json" "$WORK/ffprobe" "$WORK/pack" <<'PY' || failed=1
import json, os, sys, urllib.parse
probe = json.load(open(sys.argv[1]))
pack = sys.argv[3]
media = {}
for line in open(sys.argv[2]):
    path, *numbers = line.split()
    width, height, duration = int(numbers[0]), int(numbers[1]), float(numbers[2])
    media[path] = (width, height, duration)
bad = []
def path_of(url):
    return urllib.parse.unquote(urllib.parse.urlparse(url).path)
for e in probe["errors"]:
    bad.append("an error on the page: " + e)
if len(probe["videos"]) != len(media):
    bad.append("%d videos on the page, %d MP4s in the pack" % (len(probe["videos"]), len(media)))
for v in probe["videos"]:
    path = path_of(v["src"])
    name = os.path.relpath(path, pack)
    if v["error"] is not None or v["readyState"] < 2:
        bad.append("%s does not load: readyState %d, error %s" % (name, v["readyState"], v["error"]))
    if not v["lastFrame"]:
        bad.append("%s does not decode its last frame" % name)
    if path not in media:
        bad.append("%s is not one of the pack's MP4s" % name)
        continue
    width, height, duration = media[path]
    if (v["videoWidth"], v["videoHeight"]) != (width, height) or (v["width"], v["height"]) != (width, height):
        bad.append("%s: the browser decodes %dx%d, the page says %dx%d, ffprobe %dx%d" % (
            name, v["videoWidth"], v["videoHeight"], v["width"], v["height"], width, height))
    if abs(v["duration"] - duration) > 0.05 or abs(v["statedDuration"] - duration) > 0.05:
        bad.append("%s: the browser says %.3f s, the page %.3f s, ffprobe %.3f s" % (name, v["duration"], v["statedDuration"], duration))
    if v["posterWidth"] != width:
        bad.append("%s: its poster does not decode at %d px (%d)" % (name, width, v["posterWidth"]))
for i in probe["images"]:
    if i["naturalWidth"] == 0 or (i["naturalWidth"], i["naturalHeight"]) != (i["width"], i["height"]):
        bad.append("%s decodes at %dx%d, the page says %dx%d" % (os.path.relpath(path_of(i["src"]), pack),
                   i["naturalWidth"], i["naturalHeight"], i["width"], i["height"]))
ids = set(probe["ids"])
files = 0
for link in probe["links"]:
    url = urllib.parse.urlparse(link)
    if url.scheme != "file":
        bad.append("a link leaves the folder: " + link)
    elif url.fragment and path_of(link).endswith("/probe.html"):
        if url.fragment not in ids:
            bad.append("a link to no id: #" + url.fragment)
    elif not os.path.isfile(path_of(link)) or not os.path.realpath(path_of(link)).startswith(os.path.realpath(pack) + "/"):
        bad.append("a link to no file of the folder: " + link)
    else:
        files += 1
print("%d videos, %d images, %d links (%d to files) checked" % (len(probe["videos"]), len(probe["images"]), len(probe["links"]), files))
for b in bad:
    print("FAIL: " + b)
sys.exit(1 if bad or files == 0 or not probe["videos"] or not probe["images"] else 0)
PY

"$SCREENSHOT_CHECK" "$WORK/screenshot.png" || fail "the screenshot differs from tests/golden/page/index.png"

# the layout on a phone (390 px) and a laptop (1280 px): nothing wider than the window (videos and
# panels scale to it, tables scroll in their own box), and each video's picture above the strip
# where the browser draws the controls, so the frame's caption is never under them (paused or not)
cp "$HERE/layout.js" "$WORK/pack/"
sed 's|<head>|<head>\n<script src="layout.js"></script>|' "$PACK/index.html" >"$WORK/pack/layout.html"
for width in 390 1280; do
  python3 "$HERE/browser.py" "file://$WORK/pack/layout.html" "file://$WORK/pack/index.html" "$WORK/layout-$width.json" \
    "$WORK/screenshot-$width.png" "$width" ".seconds" || { fail "the browser could not open the page at $width px"; continue; }
  python3 - "$WORK/layout-$width.json" "$width" <<'PY' || failed=1
import json, sys
layout, width = json.load(open(sys.argv[1])), int(sys.argv[2])
# Chromium's media controls: a panel 72 px high at the bottom of the video's box (a row of buttons
# 48 px high over a 24 px timeline, as its screenshots show), over the picture unless the box leaves
# room for it below
CONTROLS = 72
bad = []
if layout["width"] != width or layout["scrollWidth"] > width:
    bad.append("the page is %d px wide in a %d px window (wider: %s)" % (layout["scrollWidth"], layout["width"],
               ", ".join(sorted(set(layout["outside"]))[:12])))
for t in layout["tables"]:
    if t["overflowX"] != "auto" or t["right"] > width + 0.5:
        bad.append("a table's box is not its own scroller inside the window: %s" % t)
# on a laptop every cell under its column's heading (a cell laid out inline would drift off its
# column), no label drawn before it; on a phone each row a card within the window, every cell after
# its column's heading
phone = width <= 600
if not phone:
    for rows in layout["columns"]:
        for r in rows[1:]:
            if len(r) == len(rows[0]) and r != rows[0]:
                bad.append("a table's cells stand at %s, its headings at %s" % (r, rows[0]))
                break
for t in layout["cells"]:
    labels = [json.dumps(h) for h in t["headings"]]
    for row in t["rows"]:
        shown = [c["label"] for c in row]
        if phone and (shown != labels or any(c["right"] > width + 0.5 for c in row)):
            bad.append("a card's cells read %s (their headings %s), reaching %.0f px" % (
                shown, labels, max(c["right"] for c in row)))
            break
        if not phone and any(label != "none" for label in shown):
            bad.append("a table's cells carry labels %s on a wide screen" % shown)
            break
for v in layout["videos"]:
    name = v["src"].rsplit("/", 1)[-1]
    scale = min(v["width"] / v["videoWidth"], v["height"] / v["videoHeight"])
    picture = v["videoHeight"] * scale
    if v["objectFit"] != "contain" or not v["objectPosition"].endswith(" 0%"):
        bad.append("%s: the picture is not kept whole at the box's top (%s, %s)" % (name, v["objectFit"], v["objectPosition"]))
    if abs(v["videoWidth"] * scale - v["width"]) > 1:
        bad.append("%s: the picture is %.0f px wide in a %.0f px box" % (name, v["videoWidth"] * scale, v["width"]))
    if v["height"] - picture < CONTROLS:
        bad.append("%s: the controls (the box's last %d px) cover the picture's last %.0f px, where the caption is" % (
            name, CONTROLS, CONTROLS - (v["height"] - picture)))
print("at %d px: the page %d px wide, %d videos with their controls below the picture, %d tables%s" % (
    width, layout["scrollWidth"], len(layout["videos"]), len(layout["tables"]), " laid out as cards" if phone else ""))
for b in bad:
    print("FAIL: " + b)
sys.exit(1 if bad or not layout["videos"] else 0)
PY
done
[ "$failed" -eq 0 ] && echo "ok: every video plays, every image decodes, every link resolves; the page looks as it did"
exit "$failed"
