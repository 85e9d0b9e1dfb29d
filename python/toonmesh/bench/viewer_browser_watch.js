// The viewer_browser benchmark's watch on viewer `i` of the page (an arrow function, evaluated
// by Playwright): when each frame is shown (the viewer's data-frames-shown) and when the pointer
// is released and the exact frame follows (data-exact, data-busy). A frame counts only where it
// is shown as the user sees it: a draft drawn here on its canvas, visible and laid out over the
// view at its full size; a frame from the kernel in the view's image, opaque, at the view's full
// size. Frames that are not are counted apart (`hidden`). Whether what is shown so reaches the
// screen, screenshots tell (the benchmark's second drag).
(i) => {
  const root = document.querySelectorAll('.toonmesh-viewer')[i];
  const img = root.querySelector('img'), canvas = root.querySelector('canvas');
  const w = window.__watch = { shown: [], hidden: 0, up: null, exact: null };
  const fullSize = (el) => {
    const r = el.getBoundingClientRect(), v = img.getBoundingClientRect();
    return r.width > 0 && Math.abs(r.width - v.width) < 1 && Math.abs(r.height - v.height) < 1
      && Math.abs(r.left - v.left) < 1 && Math.abs(r.top - v.top) < 1;
  };
  function onScreen() {
    if (canvas && getComputedStyle(canvas).visibility === 'visible') {
      return fullSize(canvas) && canvas.width > 0 && canvas.height > 0;
    }
    return getComputedStyle(img).opacity === '1' && fullSize(img) && img.complete && img.naturalWidth > 0;
  }
  new MutationObserver(() => {
    const n = +root.dataset.framesShown, now = performance.now();
    if (n !== w.last) {
      w.last = n;
      if (onScreen()) w.shown.push(now);
      else w.hidden += 1;
    }
    if (w.up !== null && w.exact === null && root.dataset.exact === '1' && root.dataset.busy === '0') w.exact = now;
  }).observe(root, { attributes: true });
  root.addEventListener('pointerup', () => { w.up = performance.now(); }, true);
}
