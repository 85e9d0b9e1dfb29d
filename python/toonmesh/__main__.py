"""Command line: ``python -m toonmesh demo`` (render the built-in scene to a PNG) and
``python -m toonmesh smooth`` (smooth a built-in noisy mesh and report what changed)."""

from __future__ import annotations

import argparse
import sys
import time
from typing import List, Optional


def _demo(args: argparse.Namespace) -> int:
    t0 = time.perf_counter()
    import numpy as np

    import toonmesh as tm
    from toonmesh.data import bunny

    V, F = bunny()
    # a ground plane under the bunny, as a second mesh with its own material
    lo, hi = V.min(axis=0), V.max(axis=0)
    c, r = (lo + hi) / 2, float(np.linalg.norm(hi - lo))
    plane_v = np.array([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]], dtype=np.float64) * r * 0.6
    plane_v += [c[0], lo[1], c[2]]
    plane_f = np.array([[0, 2, 1], [0, 3, 2]])
    scene = [
        tm.Mesh(V, F, material=tm.Material.bands("#f08a3c")),
        tm.Mesh(plane_v, plane_f, material=tm.Material.bands("#9ec5e8", thresholds=(0.2, 0.6), values=(0.55, 0.8, 1.0))),
    ]
    result = tm.render(
        scene,
        camera=tm.Camera.fit((0.25, 0.35, 1.0), margin=0.8),
        lights=[tm.Light.directional((0.6, -0.5, -0.45), space="camera")],
        width=args.width,
        height=args.height,
        msaa=4,
        backend=args.backend,
        background=(1.0, 1.0, 1.0, 1.0),
    )
    result.save(args.out)
    info = tm.gpu_info(args.backend)
    print(f"wrote {args.out} ({result.width}x{result.height}) on {info['name']} ({info['backend']})")
    print("passes: " + ", ".join(f"{name} {secs * 1e3:.1f} ms" for name, secs in result.timings.items()))
    print(f"total from start: {time.perf_counter() - t0:.2f} s")
    return 0


def _write_obj(path: str, V: "np.ndarray", F: "np.ndarray") -> None:
    with open(path, "w") as fh:
        fh.write("".join(f"v {x:.9g} {y:.9g} {z:.9g}\n" for x, y, z in V))
        fh.write("".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in F))


def _smooth(args: argparse.Namespace) -> int:
    import numpy as np

    import toonmesh as tm

    V, F = tm.shapes.icosphere(args.subdivisions, args.noise, args.seed)
    t0 = time.perf_counter()
    out = getattr(tm.smooth, args.method)(V, F, iterations=args.iterations)
    dt = time.perf_counter() - t0
    r_in, r_out = np.linalg.norm(V, axis=1), np.linalg.norm(out, axis=1)
    print(f"noisy unit icosphere: {len(V)} vertices, {len(F)} faces, noise {args.noise}")
    print(f"{args.method}, {args.iterations} iterations: {dt * 1e3:.1f} ms")
    print(f"radius spread (std): {r_in.std():.4f} -> {r_out.std():.4f}")
    print(f"mean radius:         {r_in.mean():.4f} -> {r_out.mean():.4f}")
    print(f"largest vertex move: {np.linalg.norm(out - V, axis=1).max():.4f}")
    if args.out:
        _write_obj(args.out, out, F)
        print(f"wrote {args.out}")
    return 0


def main(argv: Optional[List[str]] = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m toonmesh", description="toonmesh command line")
    sub = parser.add_subparsers(dest="command", required=True)
    demo = sub.add_parser("demo", help="render the built-in scene (the Stanford bunny, toon-shaded) to a PNG")
    demo.add_argument("--out", default="toonmesh-demo.png", help="output PNG path (default: %(default)s)")
    demo.add_argument("--width", type=int, default=800)
    demo.add_argument("--height", type=int, default=600)
    demo.add_argument("--backend", choices=("auto", "vulkan", "gl"), default=None, help="default: $TOONMESH_BACKEND, else auto")
    demo.set_defaults(run=_demo)
    sm = sub.add_parser("smooth", help="smooth a built-in noisy icosphere and report what changed")
    sm.add_argument("--method", default="laplacian", choices=["laplacian", "taubin", "hc", "implicit"])
    sm.add_argument("--iterations", type=int, default=10)
    sm.add_argument("--subdivisions", type=int, default=5)
    sm.add_argument("--noise", type=float, default=0.03)
    sm.add_argument("--seed", type=int, default=0)
    sm.add_argument("--out", default="toonmesh-smoothed.obj", help="OBJ file to write ('' for none)")
    sm.set_defaults(run=_smooth)
    args = parser.parse_args(argv)
    return int(args.run(args))


if __name__ == "__main__":
    sys.exit(main())
