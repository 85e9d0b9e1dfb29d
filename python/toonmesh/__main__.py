"""Command line: ``python -m toonmesh {demo,smooth} ...``."""

from __future__ import annotations

import argparse
import sys
import time
from typing import List, Optional

import numpy as np

import toonmesh as tm
from toonmesh import _core


def _write_obj(path: str, V: np.ndarray, F: np.ndarray) -> None:
    with open(path, "w") as fh:
        fh.write("".join(f"v {x:.9g} {y:.9g} {z:.9g}\n" for x, y, z in V))
        fh.write("".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in F))


def _smooth_demo(args: argparse.Namespace) -> int:
    V, F = _core.icosphere(args.subdivisions, args.noise, args.seed)
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
    parser = argparse.ArgumentParser(prog="python -m toonmesh", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    for name, help_text in (("demo", "the main demo"), ("smooth", "smooth a built-in noisy mesh")):
        p = sub.add_parser(name, help=help_text)
        p.add_argument("--method", default="laplacian", choices=["laplacian", "taubin", "hc", "implicit"])
        p.add_argument("--iterations", type=int, default=10)
        p.add_argument("--subdivisions", type=int, default=5)
        p.add_argument("--noise", type=float, default=0.03)
        p.add_argument("--seed", type=int, default=0)
        p.add_argument("--out", default="toonmesh-smoothed.obj", help="OBJ file to write ('' for none)")
    args = parser.parse_args(argv)
    return _smooth_demo(args)


if __name__ == "__main__":
    sys.exit(main())
