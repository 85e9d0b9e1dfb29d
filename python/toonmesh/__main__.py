"""Command line: ``python -m toonmesh demo [--out PATH] [--width W] [--height H] [--backend B]``."""

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


def main(argv: Optional[List[str]] = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m toonmesh", description="toonmesh command line")
    sub = parser.add_subparsers(dest="command", required=True)
    demo = sub.add_parser("demo", help="render the built-in scene (the Stanford bunny, toon-shaded) to a PNG")
    demo.add_argument("--out", default="toonmesh-demo.png", help="output PNG path (default: %(default)s)")
    demo.add_argument("--width", type=int, default=800)
    demo.add_argument("--height", type=int, default=600)
    demo.add_argument("--backend", choices=("auto", "vulkan", "gl"), default=None, help="default: $TOONMESH_BACKEND, else auto")
    demo.set_defaults(run=_demo)
    args = parser.parse_args(argv)
    return int(args.run(args))


if __name__ == "__main__":
    sys.exit(main())
