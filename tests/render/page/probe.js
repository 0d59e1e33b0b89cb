// What the browser test asks of the lecture page (page_browser_test.sh injects this script first
// into a copy of index.html): every error the page raises, each video's state once it has loaded a
// frame (or failed) and once it has decoded its last one, each image's and poster's decoded size,
// every link and id. browser.py awaits `window.probeResult`.
"use strict";
const probe = { errors: [], videos: [], images: [], links: [], ids: [] };
// script errors, and resources that fail to load (the capture phase sees those too)
window.addEventListener("error", (e) => {
  const where = e.target && (e.target.currentSrc || e.target.src || e.target.href);
  probe.errors.push(where ? "cannot load " + where : String(e.message));
}, true);
window.addEventListener("unhandledrejection", (e) => probe.errors.push("unhandled: " + String(e.reason)));

// a video settles when it has a frame to show (readyState 2) or fails; a lecturer pressing play asks
// for the data, so the probe does (preload="metadata" alone need not decode a frame)
function settled(video) {
  return new Promise((resolve) => {
    const done = () => resolve();
    if (video.readyState >= 2 || video.error) return done();
    video.addEventListener("loadeddata", done, { once: true });
    video.addEventListener("error", done, { once: true });
    video.querySelectorAll("source").forEach((s) => s.addEventListener("error", done, { once: true }));
    video.preload = "auto";
    video.load();
  });
}

// then its last frame: seeking there decodes it, so a video cut short fails here
function lastFrame(video) {
  return new Promise((resolve) => {
    if (video.error || !(video.duration > 0)) return resolve(false);
    const done = (ok) => () => resolve(ok && video.readyState >= 2 && !video.error);
    video.addEventListener("seeked", done(true), { once: true });
    video.addEventListener("error", done(false), { once: true });
    video.currentTime = Math.max(0, video.duration - 0.05);
  });
}

function decoded(image) {
  return image.complete ? Promise.resolve() : new Promise((resolve) => {
    image.addEventListener("load", resolve, { once: true });
    image.addEventListener("error", resolve, { once: true });
  });
}

// the result, once every video and image has settled (tests/render/page/browser.py awaits it)
window.probeResult = new Promise((resolve) => window.addEventListener("load", () => measure().then(resolve)));

async function measure() {
  const videos = [...document.querySelectorAll("video")];
  const images = [...document.querySelectorAll("img")];
  // posters raise no error event of their own: each is loaded as an image too
  const posters = videos.map((v) => Object.assign(new Image(), { src: v.poster }));
  await Promise.all([...videos.map(settled), ...images.map(decoded), ...posters.map(decoded)]);
  const first = videos.map((v) => ({ readyState: v.readyState, error: v.error ? v.error.code : null }));
  const ends = await Promise.all(videos.map(lastFrame));
  for (const [k, v] of videos.entries()) {
    const end = ends[k];
    probe.videos.push({
      src: v.currentSrc, readyState: first[k].readyState, error: first[k].error, lastFrame: end,
      duration: v.duration, videoWidth: v.videoWidth, videoHeight: v.videoHeight,
      width: Number(v.getAttribute("width")), height: Number(v.getAttribute("height")),
      statedDuration: Number(v.dataset.duration), poster: v.poster, posterWidth: posters[k].naturalWidth,
    });
  }
  for (const i of images)
    probe.images.push({ src: i.currentSrc, naturalWidth: i.naturalWidth, naturalHeight: i.naturalHeight,
                        width: Number(i.getAttribute("width")), height: Number(i.getAttribute("height")) });
  for (const a of document.querySelectorAll("a[href]")) probe.links.push(a.href);
  for (const e of document.querySelectorAll("[id]")) probe.ids.push(e.id);
  return probe;
}
