"""Timing helpers shared by the benchmark suites."""

from __future__ import annotations

import math
import numbers
import re
import statistics
import time
from contextlib import contextmanager
from typing import Any, Callable, Dict, Iterator, List, Optional, Sequence, Tuple


def median_time(fn: Callable[[], Any], repeat: int = 3, warmup: int = 1) -> float:
    """Median wall time of ``fn()`` in seconds over ``repeat`` runs, after ``warmup`` runs."""
    for _ in range(warmup):
        fn()
    times = []
    for _ in range(max(1, repeat)):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def table(headers: Sequence[str], rows: List[Sequence[Any]], title: Optional[str] = None) -> str:
    """A Markdown table (it reads well in a terminal and pastes into the documentation). Inside
    :func:`recording`, its rows are also kept as records for ``--json``."""
    _record(headers, rows, title)
    cells = [[_fmt(c) for c in r] for r in rows]
    widths = [max(len(h), *(len(r[i]) for r in cells)) if cells else len(h) for i, h in enumerate(headers)]
    out = []
    if title:
        out.append(f"\n### {title}\n")
    out.append("| " + " | ".join(h.ljust(w) for h, w in zip(headers, widths)) + " |")
    out.append("|" + "|".join("-" * (w + 2) for w in widths) + "|")
    for r in cells:
        out.append("| " + " | ".join(c.ljust(w) for c, w in zip(r, widths)) + " |")
    return "\n".join(out)


def _fmt(c: Any) -> str:
    if isinstance(c, float):
        if c == 0:
            return "0"
        if abs(c) >= 100:
            return f"{c:.0f}"
        if abs(c) >= 1:
            return f"{c:.2f}"
        return f"{c:.3g}"
    return str(c)


def ms(seconds: float) -> str:
    return f"{seconds * 1e3:.1f} ms"


# ---------------------------------------------------------------------------------------------
# Tables as JSON records (``--json FILE``)

_recording: Optional[Tuple[str, List[Dict[str, Any]]]] = None

_NUMBER = re.compile(r"^([-+]?(?:\d[\d,]*\.?\d*|\.\d+)(?:e[-+]?\d+)?)\s*(ms|s|x|%|MiB|GB/s)?$", re.I)


@contextmanager
def recording(suite: str) -> Iterator[List[Dict[str, Any]]]:
    """Collects the rows of every :func:`table` printed inside the block as records."""
    global _recording
    rows: List[Dict[str, Any]] = []
    previous, _recording = _recording, (suite, rows)
    try:
        yield rows
    finally:
        _recording = previous


def _record(headers: Sequence[str], rows: List[Sequence[Any]], title: Optional[str]) -> None:
    if _recording is None:
        return
    suite, out = _recording
    for i, row in enumerate(rows):
        rec: Dict[str, Any] = {"suite": suite, "table": title or headers[0], "row": i}
        units: Dict[str, str] = {}
        for h, cell in zip(headers, row):
            rec[h], unit = record_value(cell)
            if unit:
                units[h] = unit
        if units:
            rec["units"] = units
        out.append(rec)


def record_value(cell: Any) -> Tuple[Any, Optional[str]]:
    """A table cell as a JSON value and its unit: numbers stay numbers, and text that reads as a
    number with an optional unit ("47.8 ms", "3.3x", "1,024", "2.00e-02") becomes a float and
    that unit; empty cells, "-" (no value) and NaN become None; other text stays text."""
    if cell is None or isinstance(cell, bool):
        return cell, None
    if isinstance(cell, numbers.Integral):
        return int(cell), None
    if isinstance(cell, numbers.Real):
        return (None if math.isnan(cell) else float(cell)), None
    text = str(cell).strip()
    if text in ("", "-"):
        return None, None
    m = _NUMBER.match(text)
    if m is None:
        return text, None
    return float(m.group(1).replace(",", "")), m.group(2)
