// The orientation triad in a corner of the widget's view: the world's x, y and z axes (red,
// green, blue, labelled) as the camera sees them (draftBasis in moves.js), the nearest drawn
// last. Clicking a label views from that axis's + side.
const TRIAD_AXES = [["x", [1, 0, 0]], ["y", [0, 1, 0]], ["z", [0, 0, 1]]];
const TRIAD_LENGTH = 20;  // the axes' length in the SVG's units (its view box is 64 wide)

function createTriad(onAxis) {
  const NS = "http://www.w3.org/2000/svg";
  const make = (tag, cls) => { const e = document.createElementNS(NS, tag); e.setAttribute("class", cls); return e; };
  const svg = make("svg", "toonmesh-triad");
  svg.setAttribute("viewBox", "-32 -32 64 64");
  const axes = TRIAD_AXES.map(([name, dir]) => {
    const group = make("g", "toonmesh-triad-axis toonmesh-triad-" + name);
    group.dataset.axis = name;
    const line = make("line", "toonmesh-triad-line");
    line.setAttribute("x1", "0");
    line.setAttribute("y1", "0");
    const label = make("text", "toonmesh-triad-label");
    label.textContent = name;
    const title = make("title", "");
    title.textContent = "view from +" + name;
    label.appendChild(title);
    label.addEventListener("click", (e) => { e.preventDefault(); e.stopPropagation(); onAxis("+" + name); });
    label.addEventListener("pointerdown", (e) => e.stopPropagation());
    group.append(line, label);
    svg.appendChild(group);
    return { group, line, label, dir };
  });
  // turns the triad to the view of `cam` (eye, target, up: as the viewer's camera holds them)
  function update(cam) {
    const [f, s, u] = draftBasis(cam);
    const placed = axes.map((a) => ({ a, x: v3.dot(a.dir, s), y: -v3.dot(a.dir, u), near: -v3.dot(a.dir, f) }));
    placed.sort((p, q) => p.near - q.near);
    for (const { a, x, y } of placed) {
      a.line.setAttribute("x2", (x * TRIAD_LENGTH).toFixed(2));
      a.line.setAttribute("y2", (y * TRIAD_LENGTH).toFixed(2));
      a.label.setAttribute("x", (x * (TRIAD_LENGTH + 7)).toFixed(2));
      a.label.setAttribute("y", (y * (TRIAD_LENGTH + 7)).toFixed(2));
      svg.appendChild(a.group);  // in order: the nearest on top
    }
  }
  return { element: svg, update };
}
