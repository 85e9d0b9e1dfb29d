"""Command line: python -m toonmesh.bench SUITE [--quick] [options]."""

from __future__ import annotations

import argparse
import importlib
import sys

SUITES = ("smooth", "edges", "render")


def main(argv: "list[str] | None" = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m toonmesh.bench", description=__doc__)
    parser.add_argument("suite", choices=SUITES + ("all",))
    parser.add_argument("--quick", action="store_true", help="small meshes and few repeats (a smoke run)")
    parser.add_argument("--repeat", type=int, default=3, help="timed runs per case; the median is reported")
    args, rest = parser.parse_known_args(argv)
    suites = SUITES if args.suite == "all" else (args.suite,)
    # Only the render suite has options of its own; anything else is a mistake worth stopping
    # for, since a full run takes many minutes.
    if rest and "render" not in suites:
        parser.error(f"unrecognised arguments: {' '.join(rest)}")
    for name in suites:
        try:
            module = importlib.import_module(f"toonmesh.bench.{name}")
        except ModuleNotFoundError as exc:
            if exc.name == f"toonmesh.bench.{name}":
                print(f"[{name}] not available in this version", file=sys.stderr)
                continue
            raise
        module.main(quick=args.quick, repeat=args.repeat, extra=rest if name == "render" else ())
    return 0


if __name__ == "__main__":
    sys.exit(main())
