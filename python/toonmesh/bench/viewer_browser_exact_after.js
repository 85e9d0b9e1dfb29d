// The viewer_browser benchmark's wait (an arrow function, evaluated by Playwright): whether the
// `i`-th viewer on the page shows its exact frame after `n` frames shown, none on its way.
([i, n]) => {
  const r = document.querySelectorAll(".toonmesh-viewer")[i];
  return +r.dataset.framesShown > n && r.dataset.exact === "1" && r.dataset.busy === "0";
}
