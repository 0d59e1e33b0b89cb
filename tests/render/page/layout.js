// The page's layout at the window's width (the browser test loads it at 390 and at 1280 px): how wide
// the document is, what sticks out past the window, and each video's box and picture, once every
// video's metadata has loaded. The result is window.probeResult, which browser.py awaits.
window.probeResult = new Promise(resolve => {
  window.addEventListener("load", () => {
    const videos = [...document.querySelectorAll("video")];
    const loaded = v => new Promise(done => {
      if (v.readyState >= 1 || v.error) return done();
      v.addEventListener("loadedmetadata", done);
      v.addEventListener("error", done);
    });
    Promise.all(videos.map(loaded)).then(() => {
      const width = document.documentElement.clientWidth;
      // what reaches past the window's right edge, tables' insides aside (their box scrolls)
      const outside = [...document.body.querySelectorAll("*")]
        .filter(e => e.getBoundingClientRect().right > width + 0.5 && !e.parentElement.closest(".table"))
        .map(e => e.tagName.toLowerCase() + (e.className ? "." + e.className : ""));
      resolve({
        width: width,
        scrollWidth: document.documentElement.scrollWidth,
        outside: outside,
        videos: videos.map(v => {
          const b = v.getBoundingClientRect(), s = getComputedStyle(v);
          const border = parseFloat(s.borderTopWidth) + parseFloat(s.borderBottomWidth);
          return { src: v.currentSrc, top: b.top, width: b.width - border, height: b.height - border,
                   videoWidth: v.videoWidth, videoHeight: v.videoHeight, objectFit: s.objectFit,
                   objectPosition: s.objectPosition };
        }),
        tables: [...document.querySelectorAll(".table")].map(t => ({ overflowX: getComputedStyle(t).overflowX,
                                                                      right: t.getBoundingClientRect().right })),
        // each table's columns: the left edge of every row's i-th cell (the header's first)
        columns: [...document.querySelectorAll("table")].map(t => [...t.rows].map(
          r => [...r.cells].map(c => Math.round(c.getBoundingClientRect().left)))),
        // each table's headings, and of every cell of its body: its right edge and the label drawn
        // before it (a phone's card: its column's heading; "none" where no label is drawn)
        cells: [...document.querySelectorAll("table")].map(t => ({
          headings: [...t.tHead.rows[0].cells].map(c => c.textContent),
          rows: [...t.tBodies[0].rows].map(r => [...r.cells].map(c => ({
            right: c.getBoundingClientRect().right, label: getComputedStyle(c, "::before").content }))),
        })),
      });
    });
  });
});
