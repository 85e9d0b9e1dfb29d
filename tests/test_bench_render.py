"""The render benchmark's machinery, on tiny sizes (no timings are asserted): peers that are
missing are reported, not raised; the peer worker's protocol; the Kang et al. table's rows."""

from __future__ import annotations

import io
import json
import sys

import numpy as np
import pytest

from toonmesh.bench import _peers
from toonmesh.bench import render as bench


def table_rows(text: str, title: str) -> list:
    block = text.split(f"### {title}")[1].split("###")[0]
    return [[c.strip() for c in line.split("|")[1:-1]] for line in block.splitlines()
            if line.startswith("| ") and not line.startswith("|--")][1:]


def test_missing_peers_are_reported_as_not_installed(monkeypatch, capsys):
    monkeypatch.setattr(_peers, "installed", lambda name: False)
    bench._frame_tables(1, [("colour 32x32", "color", 32, 32), ("colour + depth 32x24", "color+depth", 32, 24)],
                        repeat=1, skip_peers=False)
    out = capsys.readouterr().out
    rows = table_rows(out, "Frames")
    by_name = {(r[0], r[2]): r for r in rows}
    for peer in _peers.PEERS:
        assert by_name[peer, bench._Peer.SHADING[peer]][-2:] == ["not installed"] * 2
    toonmesh_rows = [r for r in rows if r[0].startswith("toonmesh")]
    assert toonmesh_rows and all(cell.endswith(" ms") for r in toonmesh_rows for cell in r[-2:])
    speedups = table_rows(out, "toonmesh's speed-up")
    assert len(speedups) == len(_peers.PEERS) * len(toonmesh_rows)
    assert all(r[-2:] == ["not installed"] * 2 for r in speedups)


def test_the_peer_worker_answers_each_frame_request_with_its_time(monkeypatch, capsys):
    drawn = []
    monkeypatch.setitem(_peers._SETUP, "moderngl",
                        lambda V, F: ({"renderer": "fake", "msaa": "none"}, lambda k, w, h: drawn.append((k, w, h))))
    requests = [{"frame": "color", "width": 8, "height": 4}, {"frame": "color+depth", "width": 2, "height": 2}]
    monkeypatch.setattr(sys, "stdin", io.StringIO("".join(json.dumps(r) + "\n" for r in requests) + "\n"))
    assert _peers.worker("moderngl", 1) == 0
    answers = [json.loads(line[2:]) for line in capsys.readouterr().out.splitlines() if line.startswith("@@")]
    assert answers[0]["ready"] and answers[0]["renderer"] == "fake" and answers[0]["setup_s"] >= 0
    assert [set(a) for a in answers[1:]] == [{"t"}, {"t"}] and all(a["t"] >= 0 for a in answers[1:])
    assert drawn == [("color", 8, 4), ("color+depth", 2, 2)]


def test_a_peer_that_cannot_start_says_why_in_a_line(monkeypatch, capsys):
    def broken(V, F):
        raise RuntimeError("no display\nmore detail")

    monkeypatch.setitem(_peers._SETUP, "PyVista", broken)
    monkeypatch.setattr(sys, "stdin", io.StringIO(""))
    assert _peers.worker("PyVista", 1) == 0
    (line,) = capsys.readouterr().out.splitlines()
    assert json.loads(line[2:]) == {"error": "RuntimeError: no display"}


def test_kang_table_has_each_model_and_stage_and_the_papers_figures(capsys):
    bench._kang(48, 32, views=2, repeat=1)
    rows = table_rows(capsys.readouterr().out, "Kang, Kim and Yoon's scenes")
    models = [r for r in rows if r[2].startswith("toonmesh")]
    assert {r[0] for r in models} == {"donut", "chess piece", "teapot", "sphere"}
    assert all(float(cell.split()[0]) > 0 for r in models for cell in r[3:])
    assert rows[-1][2].startswith("Kang et al.") and rows[-1][3:6] == [f"{x} fps" for x in bench.KANG_PAPER_FPS]


def test_render_bench_options_are_checked():
    assert bench._options(True, ["--only", "kang,frames", "--wide", "64x36"]).only == ("kang", "frames")
    for bad in (["--only", "kang,bogus"], ["--wide", "64"], ["--wide", "0x5"]):
        with pytest.raises(SystemExit):
            bench._options(True, bad)


def test_stroke_stats_count_short_strokes_and_turning():
    import numpy as np

    from toonmesh.bench.render import stroke_stats

    straight = np.array([[0.0, 0.0], [10.0, 0.0], [20.0, 0.0]])
    zigzag = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])
    n, short, median, turn = stroke_stats([straight, zigzag])
    assert n == 2 and short == 50.0 and median == pytest.approx((20 + 3 * np.sqrt(2)) / 2)
    assert turn == pytest.approx(100 * 2 * (np.pi / 2) / (20 + 3 * np.sqrt(2)))
    assert stroke_stats([straight])[3] == 0.0 and stroke_stats([]) == (0, 0.0, 0.0, 0.0)


def test_stroke_smoothing_table_keeps_every_point_within_the_radius():
    from toonmesh.bench.render import _stroke_smoothing

    rows = _stroke_smoothing(160, 1)
    assert len(rows) == 10
    for name, turning, moved, points, _ in rows:
        radius = float(name.split("smooth=")[1])
        assert 0 <= float(moved.split()[0]) <= radius and points > 0 and float(turning) > 0
    turns = {r[0]: float(r[1]) for r in rows}
    assert turns["contours='auto', smooth=4"] < turns["contours='auto', smooth=0"]


def test_the_points_table_times_both_uploads_and_frames(capsys):
    rows = bench.points_cost(2000, 32, repeat=1)
    assert rows and all(len(r) == 6 and r[-1].endswith("x") for r in rows)
    V, F = bench.uv_sphere(2000)
    assert abs(len(F) - 2000) < 200 and np.allclose(np.linalg.norm(V, axis=1), 1.0)
