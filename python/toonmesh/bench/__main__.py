"""Command line: python -m toonmesh.bench SUITE [--quick] [--accuracy] [--repeat N] [--json FILE] [options]."""

from __future__ import annotations

import argparse
import importlib
import json
import sys
from typing import Any, Dict, List, Sequence

from toonmesh.bench import _timing

SUITES = ("smooth", "denoise", "edges", "lines", "render", "effects", "viewer", "viewer_browser", "scenes", "temporal")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The benchmark's options, shared with ``toonmesh bench``."""
    parser.add_argument("suite", choices=SUITES + ("all",))
    parser.add_argument("--quick", action="store_true", help="small meshes and few repeats (a smoke run)")
    parser.add_argument("--accuracy", action="store_true",
                        help="only the tables of error against time (what accuracy costs), for plotting")
    parser.add_argument("--repeat", type=int, default=3, help="timed runs per case; the median is reported")
    parser.add_argument("--json", default=None, metavar="FILE",
                        help="also write every table's rows to FILE as a JSON list of records")


def takes_extra_options(suite: str) -> bool:
    """Whether the suite runs the render benchmark, whose options (``--size``, ...) are its own."""
    return suite in ("render", "all")


def run(args: argparse.Namespace, rest: Sequence[str]) -> int:
    """Runs the chosen suites; ``rest`` are the render suite's own options."""
    suites = SUITES if args.suite == "all" else (args.suite,)
    records: List[Dict[str, Any]] = []
    for name in suites:
        try:
            module = importlib.import_module(f"toonmesh.bench.{name}")
        except ModuleNotFoundError as exc:
            if exc.name == f"toonmesh.bench.{name}":
                print(f"[{name}] not available in this version", file=sys.stderr)
                continue
            raise
        job = getattr(module, "accuracy", None) if args.accuracy else module.main
        if job is None:
            print(f"[{name}] has no accuracy tables", file=sys.stderr)
            continue
        with _timing.recording(name) as rows:
            job(quick=args.quick, repeat=args.repeat, extra=list(rest) if name == "render" else ())
        records.extend(rows)
        if args.json:  # after each suite, so a long run that stops keeps what it measured
            _write_json(args.json, records)
    if args.json:  # also when no suite had anything to run
        _write_json(args.json, records)
    return 0


def _write_json(path: str, records: List[Dict[str, Any]]) -> None:
    with open(path, "w") as f:
        json.dump(records, f, indent=1)


def main(argv: "list[str] | None" = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m toonmesh.bench", description=__doc__)
    add_arguments(parser)
    args, rest = parser.parse_known_args(argv)
    # Only the render suite has options of its own; anything else is a mistake worth stopping
    # for, since a full run takes many minutes.
    if rest and not takes_extra_options(args.suite):
        parser.error(f"unrecognised arguments: {' '.join(rest)}")
    return run(args, rest)


if __name__ == "__main__":
    sys.exit(main())
