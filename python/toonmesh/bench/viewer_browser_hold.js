// The viewer_browser benchmark's hand on a drag (an arrow function, evaluated by Playwright):
// with the mouse held down at (x, y) on the element `target` (a CSS selector; its `index`-th
// match) selects, moves the pointer a pixel right and back every 40 ms until
// `window.__hold.stop()`, so that the view keeps moving (drafts, not the exact frame) while a
// screenshot is taken, and ends where it was.
([target, index, x, y]) => {
  const el = document.querySelectorAll(target)[index];
  const move = (to) => el.dispatchEvent(new PointerEvent('pointermove', { pointerId: 1, pointerType: 'mouse',
    isPrimary: true, clientX: to, clientY: y, buttons: 1, bubbles: true, cancelable: true }));
  let k = 0;
  const t = setInterval(() => move(x + (k++ % 2 === 0 ? 1 : 0)), 40);
  window.__hold = { stop: () => { clearInterval(t); if (k % 2 === 1) move(x); } };
}
