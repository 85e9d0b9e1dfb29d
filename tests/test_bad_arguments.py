"""Every public function and class parameter against bad values. Generated from the core's
descriptions (tests/descriptions.py): the settings classes' constructors and ``replace``, the render
keywords (``RenderOptions``' fields) and the smoothing keywords; a number gives the probes of its
rule's bounds, a choice its names, unknown ones and those the same parameter takes elsewhere, a flag
its bools. Written here only what a description cannot say: the probes of each compound kind
(KINDS), a rule that is not a range, rules between parameters, the device's limits, how a setting
is rendered, and the functions no description covers.

A legal value gives a result with finite floats (a filter such as Sobel may pass non-finite pixels
through) or a documented domain error (ConvergenceError); anything else raises TypeError,
ValueError or IndexError whose message starts with the parameter's name (see _named), some with a
hint (colours above 1: "divide by 255"); nothing crashes or hangs, and the next valid call gives
the same result as before. The renderer's probes render 16x16 images with one shared Renderer; a
setting its constructor accepts must also render.
"""

from __future__ import annotations

import atexit
import math
import os
import re
import shutil
import tempfile
import time
from collections import namedtuple
from pathlib import Path
from typing import Any, Callable, Dict, List, Optional, Set, Tuple

import numpy as np
import pytest
from PIL import Image

import descriptions
from conftest import need
import toonmesh as tm
from toonmesh import edges as te
from toonmesh import testing
from toonmesh.data import load_obj

# ------------------------------------------------------------------------------------------------
# What a parameter takes, and its probes: (label, value, expected outcome). A compound argument
# (an array, a colour, a settings object) takes a tuple of such probes, written out below.
OK = "ok"  # the outcome of a legal value
FLAG = "flag"  # a parameter that takes True/False or a NumPy bool
Probes = List[Tuple[str, Any, Any]]
Table = Tuple[Tuple[str, Any, Any], ...]  # a compound argument's probes
# A number in [lo, hi] (open ends where asked), never NaN: an int or float (or NumPy number). An
# Integer: an int (or NumPy integer), and in `only` where given. Legal values above `slow_above`
# would take long: they are not probed.
Number = namedtuple("Number", "lo hi open_lo open_hi slow_above", defaults=(False, False, math.inf))
Integer = namedtuple("Integer", "lo hi slow_above only", defaults=(math.inf, None))
# A str from `valid` (case-insensitively where `any_case`); `invalid`: names that exist elsewhere
# but not here; `empty`: what "" gives; `more`: probes of other forms it takes (an Outlines object).
Name = namedtuple("Name", "valid invalid any_case empty more", defaults=((), False, ValueError, ()))
Refused = namedtuple("Refused", "exc hint")  # a refusal whose message also contains `hint`
# A parameter by name and kind (FLAG, Number, Integer, Name or a compound argument's probes);
# `none`: what None gives (OK where it is the default); `also`: extra legal outcomes (no GPU).
Param = namedtuple("Param", "name kind none also", defaults=(TypeError, ()))
# One public function or method: `call(**base)` is a valid call; `also`: documented domain errors
# a legal probe may raise.
Case = namedtuple("Case", "name call base params also", defaults=((),))


def _ranged(k: Any, values: List[Tuple[str, Any]]) -> Probes:
    """Values of the right type: OK within the kind's range, ValueError outside it and beyond what
    the parameter holds (a float: an int beyond a float; an int: beyond 64 bits, [0, 2**64) for an
    unsigned one such as a seed, else [-2**63, 2**63)); a legal value above ``k.slow_above`` is
    left out."""
    out: Probes = []
    for label, v in values:
        if isinstance(k, Integer):
            x: float = int(v)
            held = 0 <= x < 2**64 if k.lo >= 0 and k.hi >= 2**63 else -(2**63) <= x < 2**63
            legal = held and k.lo <= x <= k.hi and (k.only is None or x in k.only)
        else:
            held = not (isinstance(v, int) and abs(v) > 1e308)
            x = float(v) if held else math.inf
            above, below = (x > k.lo if k.open_lo else x >= k.lo), (x < k.hi if k.open_hi else x <= k.hi)
            legal = held and not math.isnan(x) and above and below
        if not (legal and x > k.slow_above):
            out.append((label, v, OK if legal else ValueError))
    return out


def probes(p: Param) -> Probes:
    k, none = p.kind, [("none", None, p.none)]
    if isinstance(k, Number):
        mid = 0.5 * ((k.lo if math.isfinite(k.lo) else -1e3) + (k.hi if math.isfinite(k.hi) else 1e3))
        return _ranged(k, [
            ("nan", float("nan")), ("inf", float("inf")), ("-inf", float("-inf")), ("negative", -1.0), ("zero", 0.0),
            ("int zero", 0), ("lo", k.lo), ("hi", k.hi), ("mid", mid), ("huge float", 1e308), ("huge int", 2**63),
            ("int beyond float", 10**400), ("numpy float32", np.float32(mid)),
            ("numpy int", np.int64(round(max(min(mid, 1e18), -1e18)))), ("numpy nan", np.float64("nan")),
        ]) + [("bool", True, TypeError), ("numpy bool", np.True_, TypeError), ("string", "1", TypeError),
              ("list", [mid], TypeError), ("complex", 1 + 0j, TypeError)] + none
    if isinstance(k, Integer):
        return _ranged(k, [
            ("zero", 0), ("negative", -1), ("lo", k.lo), ("hi", k.hi), ("above hi", k.hi + 1), ("below lo", k.lo - 1),
            ("2**63", 2**63), ("-2**63-1", -(2**63) - 1), ("2**64", 2**64),
            ("numpy int8", np.int8(min(max(k.lo, 0), 100))), ("numpy uint64 max", np.uint64(2**64 - 1)),
            *([(str(v), v) for v in range(k.lo + 1, k.hi)] if k.hi - k.lo <= 8 else []),
        ]) + [("float", 2.5, TypeError), ("integral float", 2.0, TypeError), ("nan", float("nan"), TypeError),
              ("bool", True, TypeError), ("numpy bool", np.False_, TypeError), ("string", "3", TypeError)] + none
    if k == FLAG:
        return [("True", True, OK), ("False", False, OK), ("numpy True", np.True_, OK),
                ("numpy False", np.bool_(False), OK), ("one", 1, TypeError), ("zero", 0, TypeError),
                ("string no", "no", TypeError), ("empty string", "", TypeError), ("list", [True], TypeError),
                ("0-d array", np.array(True), TypeError)] + none
    if isinstance(k, Name):
        return [(v, v, OK) for v in k.valid] + [(f"{v} (not here)", v, ValueError) for v in k.invalid] + [
            *k.more, ("upper case", k.valid[0].upper(), OK if k.any_case else ValueError),
            ("unknown", "bogus", ValueError), ("empty", "", k.empty), ("int", 3, TypeError),
            ("bytes", k.valid[0].encode(), TypeError), ("list", [k.valid[0]], TypeError)] + none
    return list(k) + none


# ------------------------------------------------------------------------------------------------
# Parameters generated from the core's descriptions, with what a description cannot say
# Described rules that are not ranges, by (owner, name): an integer's values, a float's minimum (excluded) or None.
GPU = tm.gpu_info()
RULES: Dict[Tuple[str, str], Any] = {
    ("Shadows", "size"): tuple(2**k for k in range(6, 14)),
    ("RenderOptions", "msaa"): tuple(n for n in (1, 4) if n in GPU["msaa_samples"]),  # and the device's
    ("Camera.look_at", "near"): 0.0, ("Camera.look_at", "far"): 0.0,  # "> 0 for a perspective camera"
    ("Camera.orthographic", "near"): None, ("Camera.orthographic", "far"): None}  # (not an orthographic one)
# Legal values above SLOW take long: not probed. DEVICE_MAX: the device's limits (an image's side).
SLOW = {"iterations": 1000, "vertex_iterations": 1000, "smooth.implicit.iterations": 20, "Shadows.size": 2048}
BETWEEN = {"Material.hatching.width": "spacing"}  # a rule between parameters: a maximum that is another's default
DEVICE_MAX = {"RenderOptions.width": GPU["max_texture_size"], "RenderOptions.height": GPU["max_texture_size"]}
ANY_CASE = ("smooth.",)  # the smoothing functions' names are case-insensitive
# Every choice a parameter of each name takes anywhere, for the names it does not take here.
SMOOTHING = descriptions.smoothing()
SETTINGS = {cls.__name__: descriptions.constructors(cls) for cls in descriptions.settings_classes()}
CHOICES: Dict[str, Set[str]] = {}
for _p in [k for m in SMOOTHING for k in m["keywords"]] + [p for cs in SETTINGS.values() for c in cs for p in c[3]]:
    if _p["kind"] == "choice":
        CHOICES.setdefault(_p["name"], set()).update(_p["choices"])


def described_param(owner: str, d: Dict[str, Any], none: Any, compound: Dict[str, Any],
                    defaults: Dict[str, Any]) -> Param:
    """The probes of the described parameter ``d`` of ``owner`` ("Class.constructor" or
    "smooth.method"); ``compound``: the probes of each kind a description cannot enumerate."""
    name, kind, key = d["name"], d["kind"], f"{owner}.{d['name']}"
    slow = SLOW.get(key, SLOW.get(name, math.inf))
    if kind in ("int", "float"):
        lo, hi, (open_lo, open_hi) = d["min"], min(d["max"], DEVICE_MAX.get(key, math.inf)), d["exclusive"]
        if key in BETWEEN:
            hi = min(hi, defaults[BETWEEN[key]])
        rule = RULES.get((owner, name), RULES.get((owner.split(".")[0], name), KeyError))
        assert not d.get("rule") or rule is not KeyError or key in BETWEEN, f"{key}: an unknown rule: {d['rule']!r}"
        if kind == "float":
            lo, open_lo = (max(lo, rule), True) if isinstance(rule, float) and d.get("rule") else (lo, open_lo)
            return Param(name, Number(lo, hi, open_lo, open_hi, slow_above=slow), none=none)
        # an integer range's ends: the next integer inward where excluded, the 64-bit limits where infinite
        ends = [(int(b) + step * x if math.isfinite(b) else (2**63 - 1 if b > 0 else -(2**63)))
                for b, x, step in ((lo, open_lo, 1), (hi, open_hi, -1))]
        return Param(name, Integer(ends[0], ends[1], slow, rule if isinstance(rule, tuple) else None), none=none)
    if kind == "bool":
        return Param(name, FLAG, none=none)
    if kind == "choice":
        invalid = tuple(sorted(CHOICES[name] - set(d["choices"])))
        return Param(name, Name(tuple(d["choices"]), invalid, any_case=owner.startswith(ANY_CASE)), none=none)
    probes = compound.get(d.get("class", kind), compound.get(name))
    assert probes is not None, f"{key}: no probes for a {kind} (add them to the compound kinds)"
    return Param(name, probes, none=none)


# ------------------------------------------------------------------------------------------------
# The meshes, images and other arrays, and the functions no description covers: the smoothing
# functions' arrays, the edges, shapes and threads
V, F = tm.shapes.icosphere(1, noise=0.05, seed=2)  # 42 vertices, 80 faces
N = len(V)
MESH = dict(vertices=V, faces=F)


def _with(a: np.ndarray, where: Tuple[int, ...], value: float) -> np.ndarray:
    b = a.copy()
    b[where] = value
    return b


def _but(table: Table, outcomes: Dict[str, Any]) -> Table:
    """``table`` with other outcomes for the probes that ``outcomes`` names (None: left out)."""
    return tuple((n, v, outcomes.get(n, e)) for n, v, e in table if outcomes.get(n, e) is not None)


VERTICES = (("float64", V, OK), ("float32", V.astype(np.float32), OK), ("big-endian float64", V.astype(">f8"), OK),
            ("big-endian float32", V.astype(">f4"), OK), ("fortran order", np.asfortranarray(V), OK),
            ("strided view", np.repeat(V, 2, axis=1)[:, ::2], OK), ("nested list", V.tolist(), OK),
            ("huge but finite", V * 1e307, OK), ("tiny", V * 1e-310, OK), ("int64", V.astype(np.int64), TypeError),
            ("float16", V.astype(np.float16), TypeError), ("complex", V.astype(complex), TypeError),
            ("bool", V > 0, TypeError), ("strings", V.astype(str), TypeError), ("object", V.astype(object), TypeError),
            ("a string", "vertices", TypeError), ("nan", _with(V, (3, 1), np.nan), ValueError),
            ("inf", _with(V, (3, 1), np.inf), ValueError), ("-inf", _with(V, (0, 0), -np.inf), ValueError),
            ("shape (N, 2)", V[:, :2].copy(), ValueError), ("shape (N, 4)", np.hstack([V, V[:, :1]]), ValueError),
            ("shape (N, 3, 1)", V[:, :, None].copy(), ValueError), ("flat", V.ravel().copy(), ValueError),
            ("empty", np.zeros((0, 3)), ValueError), ("scalar", np.float64(1.0), ValueError),
            ("ragged list", [[0.0, 0.0, 0.0], [1.0, 0.0]], TypeError))
FACES = (("int64", F, OK), ("int32", F.astype(np.int32), OK), ("uint32", F.astype(np.uint32), OK),
         ("uint64", F.astype(np.uint64), OK), ("big-endian int32", F.astype(">i4"), OK),
         ("big-endian uint64", F.astype(">u8"), OK), ("fortran order", np.asfortranarray(F), OK),
         ("nested list", F.tolist(), OK), ("one face", F[:1].copy(), OK),
         ("repeated index", np.vstack([F, [[0, 0, 1]]]), OK), ("int8", F.astype(np.int8), TypeError),
         ("float", F.astype(float), TypeError), ("bool", F > 0, TypeError), ("strings", F.astype(str), TypeError),
         ("negative index", _with(F, (5, 2), -1), IndexError), ("index N", _with(F, (5, 2), N), IndexError),
         ("index 2**40", _with(F, (5, 2), 2**40), IndexError),
         ("uint64 2**63", _with(F.astype(np.uint64), (0, 0), 2**63), IndexError),
         ("shape (M, 4)", np.hstack([F, F[:, :1]]), ValueError), ("shape (M, 2)", F[:, :2].copy(), ValueError),
         ("flat", F.ravel().copy(), ValueError), ("empty", np.zeros((0, 3), np.int64), ValueError),
         ("a string", "faces", TypeError))
PINNED = (("indices", np.array([0, 5]), OK), ("list", [0, 5], OK),
          ("tuple of bools", tuple(i < 3 for i in range(N)), OK), ("bool mask", np.arange(N) < 3, OK),
          ("int8", np.array([1], np.int8), OK), ("uint16", np.array([1], np.uint16), OK),
          ("big-endian int32", np.array([1, 2], ">i4"), OK), ("uint64", np.array([1], np.uint64), OK),
          ("empty list", [], OK), ("empty float array", np.array([]), OK), ("all", np.arange(N), OK),
          ("negative", np.array([-1]), IndexError), ("index N", np.array([N]), IndexError),
          ("uint64 max", np.array([2**64 - 1], np.uint64), IndexError), ("float", np.array([1.0]), TypeError),
          ("strings", np.array(["1"]), TypeError), ("mask too short", np.ones(N - 1, bool), ValueError),
          ("2-D array", np.array([[0, 1]]), ValueError), ("2-D list", [[0, 1]], TypeError), ("scalar", 3, TypeError))
# three numbers: a point (a direction refuses zero)
VEC3 = (("tuple", (0.3, 0.2, 5.0), OK), ("ints", (0, 0, 5), OK), ("array", np.array([0.3, 0.2, 5.0]), OK),
        ("float32 array", np.array([0.3, 0.2, 5.0], np.float32), OK), ("bytes", b"abc", TypeError),
        ("big-endian array", np.array([0.3, 0.2, 5.0], ">f8"), OK),
        ("numpy scalars", (np.float32(0.3), np.int64(0), np.float64(5)), OK), ("huge", (1e300, 0.0, 5.0), OK),
        ("zero", (0, 0, 0), OK), ("nan", (0.0, float("nan"), 5.0), ValueError),
        ("inf", (0.0, 0.0, float("inf")), ValueError), ("two numbers", (0.0, 5.0), ValueError),
        ("four numbers", (0.0, 0.0, 5.0, 1.0), ValueError),
        ("shape (1, 3)", np.array([[0.0, 0.0, 5.0]]), (TypeError, ValueError)),
        ("bools", (True, False, True), TypeError), ("strings", ("0", "0", "5"), TypeError),
        ("a string", "abc", TypeError), ("bool array", np.array([True, False, True]), TypeError),
        ("scalar", 5.0, TypeError))
NONZERO_VEC3 = _but(VEC3, {"zero": ValueError})
EDGE_PAIRS = np.array([[0, 1], [1, 2], [2, 0], [3, 4]])
EDGES = (("int64", EDGE_PAIRS, OK), ("int32", EDGE_PAIRS.astype(np.int32), OK),
         ("uint8", EDGE_PAIRS.astype(np.uint8), OK), ("big-endian", EDGE_PAIRS.astype(">i8"), OK),
         ("list", EDGE_PAIRS.tolist(), OK), ("empty", np.zeros((0, 2), np.int64), OK), ("empty list", [], OK),
         ("float", EDGE_PAIRS.astype(float), TypeError), ("bool", EDGE_PAIRS > 1, TypeError),
         ("negative", np.array([[0, -1]]), IndexError), ("huge", np.array([[0, 2**40]]), IndexError),
         ("shape (K, 3)", np.array([[0, 1, 2]]), ValueError), ("flat", np.array([0, 1]), ValueError),
         ("a string", "edges", TypeError))
# segments: an index past the vertices is out of range too
SEGMENT_EDGES = (EDGES + (("index N", np.array([[0, N]]), IndexError),))
IMG = np.random.default_rng(3).random((9, 11))
IMAGES = (("float64", IMG, OK), ("float32", IMG.astype(np.float32), OK), ("float16", IMG.astype(np.float16), OK),
          ("big-endian", IMG.astype(">f8"), OK), ("uint8", (IMG * 255).astype(np.uint8), OK),
          ("int16", (IMG * 1000).astype(np.int16), OK), ("bool", IMG > 0.5, OK),
          ("channels", np.dstack([IMG, IMG, IMG]), OK), ("fortran order", np.asfortranarray(IMG), OK),
          ("list", IMG.tolist(), OK), ("one pixel", IMG[:1, :1].copy(), OK), ("huge values", IMG * 1e300, OK),
          ("tiny values", IMG * 1e-300, OK), ("nan pixel", _with(IMG, (2, 2), np.nan), "nonfinite ok"),
          ("inf pixel", _with(IMG, (2, 2), np.inf), "nonfinite ok"), ("complex", IMG.astype(complex), TypeError),
          ("strings", IMG.astype(str), TypeError), ("object", IMG.astype(object), TypeError),
          ("1-D", IMG[0].copy(), ValueError), ("4-D", IMG[None, :, :, None].copy(), ValueError),
          ("empty", np.zeros((0, 4)), ValueError), ("a string", "image", TypeError))
MASKS = (("bool", IMG > 0.3, OK), ("uint8", (IMG > 0.3).astype(np.uint8), OK),
         ("wrong shape", np.ones((3, 3), bool), ValueError), ("strings", (IMG > 0.3).astype(str), TypeError),
         ("a string", "mask", TypeError))
# shapes.lathe: (radius, height) points, poles only at the ends
PROFILES = (("list of pairs", [(0, 0), (1, 0.5), (0, 1)], OK), ("open ends", [(1.0, 0.0), (1.0, 1.0)], OK),
            ("int", np.array([[0, 0], [2, 1], [0, 2]]), OK),
            ("float32", np.array([[0, 0], [1, 1], [0, 2]], np.float32), OK),
            ("big-endian", np.array([[0, 0], [1, 1], [0, 2]], ">f8"), OK), ("one point", [(0.0, 0.0)], ValueError),
            ("empty", np.zeros((0, 2)), ValueError), ("three columns", np.ones((3, 3)), ValueError),
            ("flat", [0.0, 1.0, 2.0], ValueError), ("nan", [(0, 0), (np.nan, 1), (0, 2)], ValueError),
            ("inf", [(0, 0), (1, np.inf), (0, 2)], ValueError),
            ("negative radius", [(0, 0), (-1, 1), (0, 2)], ValueError),
            ("pole inside", [(1, 0), (0, 1), (1, 2)], ValueError),
            ("a point twice", [(0, 0), (1, 1), (1, 1), (0, 2)], ValueError),
            ("two poles", [(0, 0), (0, 1)], ValueError), ("bools", np.array([[False, False], [True, True]]), TypeError),
            ("complex", np.array([[0, 0], [1j, 1], [0, 2]]), TypeError),
            ("strings", [("a", "b"), ("c", "d")], TypeError), ("ragged", [(0, 0), (1,), (0, 2)], TypeError),
            ("a string", "profile", TypeError))
# shapes.box: a corner is 3 finite numbers (hi's legal probes sit above lo=(-1, -1, -1), lo's
# below hi=(1, 1, 1) once negated)
CORNERS = (("tuple", (1, 2, 3), OK), ("float32", np.array([1, 1, 1], np.float32), OK),
           ("two numbers", (1.0, 1.0), TypeError), ("nan", (1.0, np.nan, 1.0), ValueError),
           ("inf", (1.0, 1.0, np.inf), ValueError), ("bools", (True, True, True), TypeError),
           ("strings", ("a", "b", "c"), TypeError), ("ragged", [(1, 2), 3], TypeError),
           ("a string", "box", TypeError))
NORMAL_BUF = np.dstack([IMG, 1 - IMG, np.ones_like(IMG)]).astype(np.float32)
DEPTH_BUF = 1.0 + IMG


def buffers(name: str, good: np.ndarray) -> Table:
    """A buffer of detect_edges; a depth buffer of another size than the normal one is refused naming depth."""
    return (("wrong size", good[:4], ValueError),) * (name == "depth") + (
        ("float64", good.astype(np.float64), OK), ("float32", good.astype(np.float32), OK),
        ("big-endian", good.astype(">f8"), OK), ("int", (good * 10).astype(np.int32), OK),
        ("inf background", _with(good, (0, 0), np.inf), "nonfinite ok"), ("complex", good.astype(complex), TypeError),
        ("strings", good.astype(str), TypeError), ("empty", good[:0], ValueError),
        ("1-D", good.ravel()[:5].copy(), ValueError), ("a string", name, TypeError))


# The smoothing functions: the mesh and the pinned vertices here, every keyword described.
CASES: List[Case] = [
    Case(f"smooth.{m['method']}", getattr(tm.smooth, m["method"]), MESH,
         [Param("vertices", VERTICES), Param("faces", FACES), Param("pinned", PINNED, none=OK)]
         + [described_param(f"smooth.{m['method']}", k, OK if k["optional"] else TypeError, {},
                            {k2["name"]: k2["default"] for k2 in m["keywords"]}) for k in m["keywords"]],
         also=(tm.ConvergenceError,) if m["method"] == "implicit" else ())
    for m in SMOOTHING
]
EDGE_INDEX = te.EdgeIndex(V, F)
# Two crossing meshes, and lists of meshes: an error names the mesh ("meshes[1].faces: ...")
CROSSING = [(V, F), (V + 0.3, F)]
MESH_LISTS = (("two meshes", CROSSING, OK), ("a tuple of them", tuple(CROSSING), OK), ("one mesh", CROSSING[:1], OK),
              ("no mesh", [], OK), ("float32 and float64", [(V.astype(np.float32), F), CROSSING[1]], OK),
              ("a mesh, not a list", CROSSING[0], TypeError), ("an item not a mesh", [CROSSING[0], 3], TypeError),
              ("an item of vertices alone", [CROSSING[0], (V,)], TypeError),
              ("a NaN vertex", [CROSSING[0], (_with(V, (2, 1), np.nan), F)], ValueError),
              ("a face out of range", [CROSSING[0], (V, F + N)], IndexError),
              ("float faces", [(V, F.astype(float)), CROSSING[1]], TypeError), ("a string", "meshes", TypeError))
CURVED_VERTICES = _but(VERTICES, {"tiny": ValueError})  # a mesh 1e-310 across: its curvature is beyond float64
MESH_PARAMS = [Param("vertices", VERTICES), Param("faces", FACES)]
CREASE = Param("crease_angle", Number(0.0, 180.0), none=OK)  # None: the core's default
POSITIVE = Number(0.0, math.inf, open_hi=True)
NOISE_AND_SEED = [Param("noise", POSITIVE), Param("seed", Integer(0, 2**64 - 1))]  # relative noise
# The edge functions' view: an eye point (the origin is one) or a direction (never zero); a valid one of each.
EYE = Param("eye", VEC3, none=ValueError)
DIRECTION = Param("direction", NONZERO_VEC3, none=ValueError)
AN_EYE, A_DIRECTION = dict(eye=(0.3, 0.2, 5.0)), dict(direction=(0.3, 0.2, -1.0))
# Suggestive contours' derivative threshold and curvature smoothing (None: their defaults).
SUGGESTIVE = [Param("threshold", POSITIVE, none=OK), Param("smoothing", POSITIVE, none=OK)]
WELD = Param("weld", FLAG)
SEGMENTS = Param("segments", Integer(3, 4096, slow_above=64))
CASES += [
    *[Case(name, call, dict(MESH, crease_angle=20.0, weld=False), [*MESH_PARAMS, CREASE, WELD])
      for name, call in (("edges.feature_edges", te.feature_edges), ("edges.EdgeIndex", te.EdgeIndex))],
    *[Case(name, call, dict(MESH, **AN_EYE, weld=False), [*MESH_PARAMS, EYE, WELD])
      for name, call in (("edges.silhouette", te.silhouette), ("edges.contours", te.contours))],
    Case("edges.silhouette(direction=)", te.silhouette, dict(MESH, **A_DIRECTION), [DIRECTION]),
    Case("edges.EdgeIndex.feature_edges", EDGE_INDEX.feature_edges, dict(crease_angle=20.0), [CREASE]),
    *[Case(f"edges.EdgeIndex.{name}", getattr(EDGE_INDEX, name), AN_EYE, [EYE]) for name in ("silhouette", "contours")],
    Case("edges.EdgeIndex.outlines", EDGE_INDEX.outlines, dict(**A_DIRECTION, kinds=False),
         [DIRECTION, Param("kinds", FLAG)]),
    Case("edges.EdgeIndex.suggestive_contours", EDGE_INDEX.suggestive_contours,
         dict(**A_DIRECTION, threshold=0.01, smoothing=1.0), [DIRECTION, *SUGGESTIVE]),
    Case("edges.EdgeIndex.segments", EDGE_INDEX.segments, dict(edges=EDGE_PAIRS), [Param("edges", SEGMENT_EDGES)]),
    Case("edges.curvature", te.curvature, dict(MESH, smoothing=1.0),
         [Param("vertices", CURVED_VERTICES), Param("faces", FACES), Param("smoothing", POSITIVE)]),
    Case("edges.suggestive_contours", te.suggestive_contours,
         dict(MESH, **A_DIRECTION, threshold=0.01, smoothing=1.0, weld=True),
         [Param("vertices", CURVED_VERTICES), Param("faces", FACES), DIRECTION, *SUGGESTIVE, WELD]),
    Case("edges.chains", te.chains, dict(edges=EDGE_PAIRS), [Param("edges", EDGES)]),
    Case("edges.segments", te.segments, dict(vertices=V, edges=EDGE_PAIRS),
         [Param("vertices", VERTICES), Param("edges", SEGMENT_EDGES)]),
    *[Case(f"edges.{f.__name__}", f, dict(meshes=CROSSING, self_intersections=False),
           [Param("meshes", MESH_LISTS), Param("self_intersections", FLAG)])
      for f in (te.intersections, te.intersection_lines)],
    *[Case(f"edges.{f.__name__}", f, dict(image=IMG, mask=None, convention="skimage"),
           [Param("image", IMAGES), Param("mask", MASKS, none=OK), Param("convention", Name(("skimage", "opencv")))])
      for f in (te.sobel, te.sobel_h, te.sobel_v)],
    Case("edges.detect_edges", te.detect_edges,
         dict(normal=NORMAL_BUF, depth=DEPTH_BUF, normal_threshold=1.0, depth_threshold=0.1),
         [Param("normal", buffers("normal", NORMAL_BUF), none=OK), Param("depth", buffers("depth", DEPTH_BUF), none=OK),
          Param("normal_threshold", POSITIVE), Param("depth_threshold", POSITIVE)]),
    Case("shapes.icosphere", tm.shapes.icosphere, dict(subdivisions=1, noise=0.1, seed=0),
         [Param("subdivisions", Integer(0, 10, slow_above=4)), *NOISE_AND_SEED]),
    Case("shapes.grid", tm.shapes.grid, dict(n=5, noise=0.1, seed=0),
         [Param("n", Integer(2, 4096, slow_above=64)), *NOISE_AND_SEED]),
    Case("shapes.torus", tm.shapes.torus, dict(major=1.0, minor=0.4, segments=5, tube_segments=4),
         [Param("major", Number(0.4, math.inf, open_lo=True, open_hi=True)), SEGMENTS,
          Param("minor", Number(0.0, 1.0, open_lo=True, open_hi=True)), SEGMENTS._replace(name="tube_segments")]),
    Case("shapes.lathe", tm.shapes.lathe, dict(profile=[(0.0, 0.0), (1.0, 0.5), (0.0, 1.0)], segments=5),
         [Param("profile", PROFILES), SEGMENTS]),
    Case("shapes.box", tm.shapes.box, dict(lo=(-1.0, -1.0, -1.0), hi=(1.0, 1.0, 1.0)),
         [Param("lo", tuple((label, -np.asarray(v) if want is OK else v, want) for label, v, want in CORNERS)),
          Param("hi", CORNERS)]),
    Case("shapes.pawn", tm.shapes.pawn, dict(segments=5), [SEGMENTS]),
    Case("shapes.uv_sphere", tm.shapes.uv_sphere, dict(segments=5, rings=4),
         [SEGMENTS, Param("rings", Integer(2, 4096, slow_above=64))]),
    Case("shapes.teapot", tm.shapes.teapot, {"subdivisions": 2}, [Param("subdivisions", Integer(2, 64, slow_above=8))]),
    Case("set_num_threads", tm.set_num_threads, dict(n=0), [Param("n", Integer(0, 1024, slow_above=8))]),
]

# ------------------------------------------------------------------------------------------------
# The renderer's table: 16x16 images, one shared Renderer
#: A point cloud's positions: (N, 3) floats, finite, at least one point.
POINT_POSITIONS = (("float64", V, OK), ("float32", V.astype(np.float32), OK), ("one point", V[:1], OK),
                   ("nested list", V.tolist(), OK), ("none", np.zeros((0, 3)), ValueError),
                   ("2 columns", V[:, :2], ValueError), ("nan", _with(V, (3, 1), np.nan), ValueError),
                   ("inf", _with(V, (0, 0), np.inf), ValueError), ("strings", V.astype(str), TypeError),
                   ("a string", "points", TypeError))
RENDERER = tm.Renderer()
HANDLE = RENDERER.add_mesh(V, F)
OTHER_HANDLE = tm.Renderer().add_mesh(V, F)  # a mesh of another renderer
REMOVED_HANDLE = RENDERER.add_mesh(V, F)
RENDERER.remove_mesh(REMOVED_HANDLE)
SMALL = dict(width=16, height=16)
SNAPSHOTS = TURNTABLES = tempfile.mkdtemp(prefix="toonmesh-bad-arguments-")  # what the probes write
atexit.register(shutil.rmtree, SNAPSHOTS, ignore_errors=True)
FRAMED = dict(SMALL, outputs=("color", "normal", "depth"), outlines="mesh", msaa=1, supersample=1)
BYTE_CODES = Refused(ValueError, "divide by 255")  # 0-255 codes get a hint
# an sRGB colour: '#rrggbb' or 3 numbers in [0, 1] (with alpha, '#rrggbbaa' or 4 numbers too)
COLOUR = (("hex", "#ff8040", OK), ("hex without #", "ff8040", OK), ("hex upper case", "#FF8040", OK),
          ("bytes", b"\x00\x00\x01", TypeError), ("bytearray", bytearray(b"\x00\x00\x01"), TypeError),
          ("hex with alpha", "#ff804080", ValueError), ("tuple", (1.0, 0.5, 0.25), OK), ("ints", (1, 0, 0), OK),
          ("black", (0, 0, 0), OK), ("list", [0.2, 0.4, 0.6], OK), ("array", np.array([1.0, 0.5, 0.25]), OK),
          ("float32 array", np.array([1.0, 0.5, 0.25], np.float32), OK),
          ("big-endian array", np.array([1.0, 0.5, 0.25], ">f8"), OK),
          ("numpy scalars", (np.float32(1.0), np.int64(0), np.float64(0.5)), OK),
          ("four numbers", (1.0, 0.5, 0.25, 0.5), ValueError), ("0-255 codes", (255, 128, 0), BYTE_CODES),
          ("uint8 codes", np.array([255, 128, 0], np.uint8), BYTE_CODES),
          ("just above 1", (1.0001, 0.0, 0.0), BYTE_CODES), ("huge", (1e300, 0.0, 0.0), BYTE_CODES),
          ("negative", (-0.1, 0.0, 0.0), ValueError), ("nan", (float("nan"), 0.0, 0.0), ValueError),
          ("inf", (0.0, float("inf"), 0.0), ValueError), ("int beyond float", (10**400, 0, 0), ValueError),
          ("two numbers", (1.0, 0.0), ValueError), ("five numbers", (1.0, 0.0, 0.0, 1.0, 0.0), ValueError),
          ("empty tuple", (), ValueError), ("short hex", "#fff", ValueError), ("bad hex", "#gg0000", ValueError),
          ("colour name", "white", ValueError), ("empty string", "", ValueError),
          ("bools", (True, False, True), TypeError), ("strings", ("1", "0", "0"), TypeError),
          ("nested", [[1.0, 0.0, 0.0]], TypeError), ("complex", (1j, 0.0, 0.0), TypeError), ("scalar", 0.5, TypeError))
_TURN = np.array([[0.0, -1.0, 0.0, 0.5], [1.0, 0.0, 0.0, -2.0], [0.0, 0.0, 1.0, 3.0], [0.0, 0.0, 0.0, 1.0]])
_LIGHTS = [tm.Light.key(), tm.Light.directional((1.0, -1.0, -1.0)), tm.Light.point((2.0, 2.0, 2.0), space="camera")]
# The probes of each kind a description cannot enumerate, in one place: by the field's kind, its settings class
# for a setting, or its name where the rule depends on what the numbers mean (a vec3's zero, thresholds, up).
KINDS: Dict[str, Any] = {
    "color": COLOUR, "rgba": _but(COLOUR, {"hex with alpha": OK, "four numbers": OK}),
    # a mesh's 4x4 affine model -> world matrix
    "matrix": (("identity", np.eye(4), OK), ("nested list", np.eye(4).tolist(), OK),
               ("float32", np.eye(4, dtype=np.float32), OK), ("int", np.eye(4, dtype=np.int64), OK),
               ("big-endian", np.eye(4).astype(">f8"), OK), ("fortran order", np.asfortranarray(_TURN), OK),
               ("turn, move and scale", np.diag([1e3, 1e3, 1e3, 1.0]) @ _TURN, OK),
               ("tiny scale", np.diag([1e-3, 1e-3, 1e-3, 1.0]), OK), ("mirror", np.diag([-1.0, 1.0, 1.0, 1.0]), OK),
               ("singular", np.zeros((4, 4)), ValueError), ("flattening", np.diag([1.0, 1.0, 0.0, 1.0]), ValueError),
               ("projective", _with(np.eye(4), (3, 2), 0.5), ValueError),
               ("nan", _with(np.eye(4), (0, 3), np.nan), ValueError),
               ("inf", _with(np.eye(4), (1, 1), np.inf), ValueError), ("3x3", np.eye(3), ValueError),
               ("4x3", np.eye(4)[:, :3].copy(), ValueError), ("flat", np.eye(4).ravel(), (TypeError, ValueError)),
               ("bool", np.eye(4) > 0, TypeError), ("complex", np.eye(4) * (1 + 1j), TypeError),
               ("strings", np.eye(4).astype(str), TypeError), ("object", np.eye(4).astype(object), TypeError),
               ("ragged", [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0]], TypeError), ("a string", "identity", TypeError)),
    # the outputs of a render with outlines drawn ("outline" and "lines" need them)
    "names": (("color", ("color",), OK), ("a name", "depth", OK), ("list", ["color", "normal"], OK),
              ("every output", ("color", "normal", "depth", "outline", "lines"), OK), ("set", {"normal"}, OK),
              ("numpy strings", np.array(["color", "depth"]), OK), ("repeated", ("color", "color"), OK),
              ("outline", ("outline",), OK), ("lines", ("lines",), OK), ("empty", (), ValueError),
              ("unknown", ("colour",), ValueError), ("upper case", ("COLOR",), ValueError),
              ("empty name", ("",), ValueError), ("int", 5, TypeError), ("int in list", ("color", 3), TypeError),
              ("bytes", b"color", TypeError), ("nested", [["color"]], TypeError)),
    # up to 8 lights
    "lights": (("a light", tm.Light.key(), OK), ("a list", _LIGHTS, OK), ("a tuple", tuple(_LIGHTS), OK),
               ("none", [], OK), ("eight", [tm.Light.key()] * 8, OK), ("nine", [tm.Light.key()] * 9, ValueError),
               ("a string", "sun", TypeError), ("a string in the list", [tm.Light.key(), "sun"], TypeError),
               ("None in the list", [None], TypeError), ("an int", 1, TypeError),
               ("a material", tm.Material.bands(), TypeError)),
    # one kind of outline: drawn or not, its LineStyle, or its colour
    "style": (("True", True, OK), ("False", False, OK), ("numpy True", np.True_, OK),
              ("a LineStyle", tm.LineStyle("#ff0000", 3.0), OK), ("a colour", "#00ff00", OK),
              ("colour numbers", (0.0, 0.0, 1.0), OK),
              ("0-255 codes", (0, 0, 255), BYTE_CODES), ("a word", "thick", ValueError),
              ("an int", 3, TypeError), ("a list of a bool", [True], TypeError),
              ("an Outlines", tm.Outlines(), TypeError)),
    # a LUT material's factors or rgb rows, at most 256, finite in float32
    "table": (("kang_table", tm.kang_table(), OK), ("list", [0.2, 0.6, 1.0], OK), ("one entry", [1.0], OK),
              ("rgb rows", np.array([[0.2, 0.1, 0.0], [1.0, 0.9, 0.8]]), OK),
              ("float32", np.linspace(0, 1, 8, dtype=np.float32), OK), ("256 entries", np.ones(256), OK),
              ("factors above 1", [0.5, 2.0], OK), ("257 entries", np.ones(257), ValueError), ("empty", [], ValueError),
              ("negative", [0.5, -0.1], ValueError), ("nan", [0.5, float("nan")], ValueError),
              ("inf", [float("inf")], ValueError), ("beyond float32", [1e39], ValueError),
              ("rows of 2", [[1.0, 0.5]], ValueError), ("rows of 4", np.ones((2, 4)), ValueError),
              ("bools", [True, False], TypeError), ("strings", ["0.5"], TypeError), ("a string", "ramp", TypeError),
              ("bytes", b"\x01\x02", TypeError), ("a number", 0.5, TypeError)),
    # the paper's grain: grey, RGB or RGBA in [0, 1] or uint8
    "image": (("a grey uint8 image", np.arange(12, dtype=np.uint8).reshape(3, 4), OK),
              ("an RGBA float image", np.full((2, 3, 4), 0.25), OK), ("a 1x1 image", np.ones((1, 1)), OK),
              ("a list", [[0.0, 1.0]], TypeError), ("a string", "rough", TypeError), ("1-D", np.zeros(4), ValueError),
              ("empty", np.zeros((0, 4)), ValueError), ("5 channels", np.zeros((2, 2, 5)), ValueError),
              ("NaN", np.array([[np.nan, 0.0]]), ValueError), ("above 1", np.array([[1.5]]), ValueError),
              ("negative", np.array([[-1, 0]], np.int16), ValueError),
              ("complex", np.zeros((2, 2), complex), TypeError)),
    # the bands' thresholds: increasing, one fewer than the values
    "thresholds": (("paper's", (0.2, 0.5, 0.7, 0.9), OK), ("array", np.array([-0.5, 0.0, 0.5, 0.99]), OK),
                   ("float32", np.array([0.1, 0.2, 0.3, 0.4], np.float32), OK),
                   ("beyond [-1, 1]", (-5.0, 0.0, 1.0, 5.0), OK), ("decreasing", (0.9, 0.7, 0.5, 0.2), ValueError),
                   ("three, for five values", (0.2, 0.5, 0.9), ValueError), ("bytes", b"\x01\x02\x03\x04", TypeError),
                   ("repeated", (0.2, 0.5, 0.5, 0.9), ValueError), ("nan", (0.2, float("nan"), 0.7, 0.9), ValueError),
                   ("inf", (0.2, 0.5, 0.7, float("inf")), ValueError),
                   ("strings", ("0.2", "0.5", "0.7", "0.9"), TypeError), ("a string", "0.5", TypeError),
                   ("a number", 0.5, TypeError)),
    "values": (("paper's", (0.0, 0.2, 0.7, 0.9, 1.0), OK), ("above 1", (0.0, 0.5, 1.0, 2.0, 4.0), OK),
               ("array", np.linspace(0, 1, 5), OK), ("negative", (-0.1, 0.2, 0.7, 0.9, 1.0), ValueError),
               ("nan", (0.0, 0.2, float("nan"), 0.9, 1.0), ValueError),
               ("beyond float32", (0.0, 0.2, 0.7, 0.9, 1e39), ValueError), ("two", (0.0, 1.0), ValueError),
               ("bools", (False, True, True, True, True), TypeError), ("a number", 1.0, TypeError)),
    # the view runs along (0.3, 0.2, 5): see BASES
    "up": (("y", (0.0, 1.0, 0.0), OK), ("ints", (1, 1, 0), OK), ("array", np.array([0.2, 1.0, 0.1]), OK),
           ("float32 array", np.array([0.0, 1.0, 0.0], np.float32), OK), ("long", (0.0, 1e300, 0.0), OK),
           ("short", (0.0, 1e-300, 0.0), OK), ("along the view", (0.3, 0.2, 5.0), ValueError),
           ("against the view", (-0.6, -0.4, -10.0), ValueError), ("zero", (0, 0, 0), ValueError),
           ("nan", (0.0, float("nan"), 0.0), ValueError), ("inf", (0.0, float("inf"), 0.0), ValueError),
           ("two numbers", (0.0, 1.0), ValueError), ("bools", (False, True, False), TypeError),
           ("a string", "up", TypeError)),
    "direction": NONZERO_VEC3, "position": VEC3, "target": VEC3,
    "eye": _but(VEC3, {"zero": None}),  # an eye on the target: test_render_errors.py
    "Material": (("bands", tm.Material.bands(), OK), ("lambert", tm.Material.lambert("#80c0ff"), OK),
                 ("phong", tm.Material.phong(shininess=8), OK),
                 ("thresholded phong", tm.Material.thresholded_phong(per_vertex=True), OK),
                 ("lut", tm.Material.lut(), OK), ("a name", "bands", TypeError), ("the class", tm.Material, TypeError),
                 ("a light", tm.Light.key(), TypeError), ("a dict", {"model": "bands"}, TypeError)),
    "Camera": (("fit", tm.Camera.fit(), OK),
               ("fit orthographic", tm.Camera.fit((0.0, 1.0, 0.0), up=(0.0, 0.0, 1.0), orthographic=True), OK),
               ("look_at", tm.Camera.look_at((0.3, 0.2, 5.0), fov_y=20.0), OK),
               ("orthographic", tm.Camera.orthographic((0.3, 0.2, 5.0), height=3.0), OK),
               ("a name", "front", TypeError), ("a list", [tm.Camera.fit()], TypeError),
               ("a light", tm.Light.key(), TypeError), ("an int", 1, TypeError)),
    "Outlines": Name(("mesh", "image", "both"), more=(
        ("Outlines()", tm.Outlines(), OK), ("Outlines('image')", tm.Outlines("image", color="#204080", width=3.0), OK),
        ("True", True, TypeError), ("a LineStyle", tm.LineStyle(), TypeError))),
    "Paper": (("a Paper", tm.Paper(), OK),
              ("a Paper on the surface, of an image", tm.Paper(np.eye(3), space="surface"), OK),
              ("True", True, TypeError), ("a name", "paper", TypeError), ("a Rim", tm.Rim(), TypeError)),
    "EyeDome": (("an EyeDome", tm.EyeDome(), OK), ("a strong, wide EyeDome", tm.EyeDome(strength=3.0, radius=4.0), OK),
                ("True", True, TypeError), ("a number", 1.0, TypeError), ("a Paper", tm.Paper(), TypeError)),
    "Rim": (("a Rim", tm.Rim(), OK),
            ("a coloured, lit-side Rim", tm.Rim("#3366ff", width=0.5, side="lit", blend="mix"), OK),
            ("True", True, TypeError), ("a name", "rim", TypeError), ("a colour", (1.0, 1.0, 1.0), TypeError),
            ("a Dither", tm.Dither(), TypeError)),
    "Dither": (("a pattern name", "bayer8", OK), ("blue", "blue", OK),
               ("a Dither", tm.Dither("bayer2", space="object"), OK), ("an unknown name", "noise", ValueError),
               ("upper case", "BAYER4", ValueError), ("True", True, TypeError), ("an int", 4, TypeError),
               ("a list", ["bayer4"], TypeError), ("an Outlines", tm.Outlines(), TypeError)),
    "Shadows": (("True", True, OK), ("False", False, OK), ("numpy True", np.True_, OK),
                ("a Shadows", tm.Shadows(size=512, filter="none"), OK), ("a word", "yes", TypeError),
                ("an int", 1, TypeError), ("a list of a bool", [True], TypeError),
                ("an Outlines", tm.Outlines(), TypeError)),
}
# What only the renderer's own functions take: meshes, cameras, a backend, normals, a mesh's colours and texture.
OUTPUTS_WITHOUT_OUTLINES = (("color", ("color",), OK), ("normal and depth", ("normal", "depth"), OK),
                            ("outline", ("outline",), ValueError), ("lines", ("color", "lines"), ValueError))
CAMERAS = (("two", [tm.Camera.fit(), tm.Camera.look_at((0.3, 0.2, 5.0))], OK),
           ("tuple", (tm.Camera.fit((1.0, 0.0, 0.0)),), OK), ("none", [], OK), ("a camera", tm.Camera.fit(), TypeError),
           ("a string in the list", [tm.Camera.fit(), "front"], TypeError), ("a string", "front", TypeError),
           ("an int", 2, TypeError))
_MESH = tm.Mesh(V, F, material=tm.Material.lambert(), transform=_TURN, normals="flat")
MESHES = (("a handle", HANDLE, OK), ("a list", [HANDLE, HANDLE], OK), ("a tuple", (HANDLE,), OK),
          ("a Mesh", tm.Mesh(V, F), OK), ("a Mesh of a handle", tm.Mesh(HANDLE, transform=_TURN), OK),
          ("a Mesh with its own settings", _MESH, OK), ("handles and Meshes", [HANDLE, _MESH], OK), ("empty", [], OK),
          ("a handle of another renderer", OTHER_HANDLE, ValueError), ("a removed handle", REMOVED_HANDLE, ValueError),
          ("arrays", V, TypeError), ("a (V, F) pair", (V, F), TypeError), ("a string", "bunny", TypeError),
          ("None in the list", [HANDLE, None], TypeError), ("a mesh id", HANDLE.id, TypeError))
BACKEND = Name(("auto", "vulkan", "gl", "vk", "opengl", "gles", "egl", " vulkan "), any_case=True, empty=OK)
NORMALS = Name(("smooth", "flat", "auto"), more=(
    ("auto 45", ("auto", 45), OK), ("auto 0", ("auto", 0), OK), ("auto 180", ("auto", 180.0), OK),
    ("auto numpy", ("auto", np.float32(20)), OK), ("auto -1", ("auto", -1), ValueError),
    ("auto 181", ("auto", 181), ValueError), ("auto nan", ("auto", float("nan")), ValueError),
    ("auto inf", ("auto", float("inf")), ValueError), ("auto huge int", ("auto", 10**400), ValueError),
    ("smooth with an angle", ("smooth", 30), ValueError), ("auto string angle", ("auto", "45"), TypeError),
    ("auto bool angle", ("auto", True), TypeError), ("auto none angle", ("auto", None), TypeError),
    ("auto alone", ("auto",), TypeError), ("auto three", ("auto", 30, 1), TypeError),
    ("auto list", ["auto", 45], TypeError), ("own, one short", np.ones((len(V) - 1, 3)), ValueError),
    ("own, two columns", np.ones((len(V), 2)), ValueError), ("own, a zero row", np.zeros((len(V), 3)), ValueError),
    ("own, integers", np.ones((len(V), 3), dtype=np.int64), TypeError),
    ("own, a list", np.ones((len(V), 3)).tolist(), TypeError)))
UV = (V[:, :2] + 1.5) / 3.0
TEXTURE = (np.arange(4 * 4 * 3) * 5).astype(np.uint8).reshape(4, 4, 3)
# beyond [0, 1]: wrapped
UVS = (("float64", UV, OK), ("float32", UV.astype(np.float32), OK), ("big-endian", UV.astype(">f8"), OK),
       ("nested list", UV.tolist(), OK), ("beyond [0, 1]", UV * 7 - 3, OK),
       ("nan", _with(UV, (0, 0), np.nan), ValueError), ("inf", _with(UV, (1, 1), np.inf), ValueError),
       ("beyond float32", _with(UV, (0, 1), 1e300), ValueError), ("one too few", UV[:-1], ValueError),
       ("three columns", V, ValueError), ("flat", UV.ravel(), ValueError), ("int64", UV.astype(np.int64), TypeError),
       ("string", "uv", TypeError))
TEXTURES = (("uint8 rgb", TEXTURE, OK),
            ("uint8 rgba", np.concatenate([TEXTURE, np.full((4, 4, 1), 200, np.uint8)], -1), OK),
            ("float64", TEXTURE / 255.0, OK), ("float32", (TEXTURE / 255.0).astype(np.float32), OK),
            ("big-endian float", (TEXTURE / 255.0).astype(">f8"), OK),
            ("fortran order", np.asfortranarray(TEXTURE), OK), ("one pixel", TEXTURE[:1, :1], OK),
            ("PIL image", Image.fromarray(TEXTURE), OK), ("two channels", TEXTURE[..., :2], ValueError),
            ("grey (H, W)", TEXTURE[..., 0], ValueError), ("empty", np.zeros((0, 4, 3), np.uint8), ValueError),
            ("nan", _with(TEXTURE / 255.0, (0, 0), np.nan), ValueError),
            ("0-255 floats", TEXTURE.astype(np.float64) + 1, Refused(ValueError, "uint8")),
            ("int64", TEXTURE.astype(np.int64), TypeError), ("a file name", "checker.png", TypeError))
TEXTURED = dict(uv=UV, texture=TEXTURE, texture_filter=None, texture_wrap=None, alpha_cutoff=None)
TEXTURE_PARAMS = [  # a texture needs uv, and uv a texture
    Param("uv", UVS, none=ValueError), Param("texture", TEXTURES, none=ValueError),
    Param("texture_filter", Name(("linear", "nearest")), none=OK), Param("alpha_cutoff", Number(0.0, 1.0), none=OK),
    Param("texture_wrap", Name(("repeat", "clamp", "mirror")), none=OK)]


def mesh_colours(n: int) -> Table:
    """Colours of n vertices or faces: (n, 3) or (n, 4) sRGB, uint8 or in [0, 1] (0-255 floats: a hint)."""
    base = np.linspace(0.0, 1.0, n * 3).reshape(n, 3)
    return (("float64 rgb", base, OK),
            ("float32 rgba", np.concatenate([base, np.ones((n, 1))], 1).astype(np.float32), OK),
            ("uint8", (base * 255).astype(np.uint8), OK), ("big-endian", base.astype(">f8"), OK),
            ("fortran order", np.asfortranarray(base), OK), ("nested list", base.tolist(), OK),
            ("one too few", base[:-1], ValueError), ("two channels", base[:, :2], ValueError),
            ("five channels", np.ones((n, 5)), ValueError), ("flat", base.ravel(), ValueError),
            ("empty", np.zeros((0, 3)), ValueError), ("nan", _with(base, (0, 0), np.nan), ValueError),
            ("inf", _with(base, (0, 1), np.inf), ValueError), ("negative", _with(base, (1, 1), -0.1), ValueError),
            ("0-255 floats", base * 255, Refused(ValueError, "uint8")),
            ("int64", (base * 255).astype(np.int64), TypeError), ("float16", base.astype(np.float16), TypeError),
            ("string", "red", TypeError))


BOTH_COLOURS = (("with vertex colours too", np.zeros((len(F), 3)), ValueError),)
# Colours by vertex or by face (each None by default: not both).
MESH_COLOURS = [Param("vertex_colors", mesh_colours(N), none=OK), Param("face_colors", mesh_colours(len(F)), none=OK)]


def _rendered(make: Callable[..., Any], use: Callable[[Any], Dict[str, Any]]) -> Callable[..., Any]:
    """`make(**kw)` and a render that uses what it made: what a constructor accepts must render. A camera is
    checked for the scene when used too: one with non-finite matrices here (margin=1e308) is refused, naming it."""
    def call(**kw: Any) -> Any:
        made = make(**kw)
        try:
            return made, RENDERER.render(HANDLE, **SMALL, outputs=("color", "normal"), **use(made))
        except ValueError as exc:
            if isinstance(made, tm.Camera) and str(exc).startswith("camera: ") and "non-finite" in str(exc):
                return made, str(exc)
            raise
    call.make, call.use = make, use  # type: ignore[attr-defined]
    return call


def _added(**kw: Any) -> Any:
    """add_mesh, a render of the mesh (no "depth": a huge or tiny one's leaves float32), then remove_mesh."""
    handle = RENDERER.add_mesh(**kw)
    try:
        return handle, RENDERER.render(handle, **SMALL, outputs=("color", "normal"))
    finally:
        RENDERER.remove_mesh(handle)


EDGES = np.array([[0, 1], [1, 2], [2, 0]], np.int64)  # a triangle of the mesh's first vertices


def _lines_rendered(**kw: Any) -> Any:
    """The mesh with a Lines item of ``kw`` beside it, rendered."""
    return RENDERER.render([HANDLE, tm.Lines(**kw)], **SMALL, outputs=("color", "normal"))


def _mesh_rendered(**kw: Any) -> Any:
    return RENDERER.render(tm.Mesh(**kw), **SMALL, outputs=("color", "normal"))


def described_params(name: str, required: int, params: List[Dict[str, Any]]) -> List[Param]:
    """A settings constructor's parameters: None is the default of each but the required ones."""
    defaults = {p["name"]: p["default"] for p in params}
    return [described_param(name, p, TypeError if i < required else OK, KINDS, defaults) for i, p in enumerate(params)]


# The render keywords: RenderOptions' fields (None: the core's default, for every one).
((_, _, _, OPTIONS),) = SETTINGS["RenderOptions"]
FRAME = described_params("RenderOptions", 0, [p for p in OPTIONS if p["name"] != "camera"])
CAMERA = described_params("RenderOptions", 0, [p for p in OPTIONS if p["name"] == "camera"])


def _options_of(o: Any) -> Dict[str, Any]:
    """The keywords that make `o` again, read from its fields."""
    return {p["name"]: getattr(o, p["name"]) for p in OPTIONS}


# How a value of each settings class is rendered, and a valid call of the constructors that need
# one other than their first parameter left out.
USE: Dict[str, Callable[[Any], Dict[str, Any]]] = {
    "Material": lambda m: dict(material=m), "Dither": lambda d: dict(material=tm.Material.bands(dither=d)),
    "Paper": lambda paper: dict(paper=paper), "EyeDome": lambda e: dict(eye_dome=e), "Rim": lambda rim: dict(material=tm.Material.lambert(rim=rim)),
    "Light": lambda light: dict(lights=light), "Camera": lambda c: dict(camera=c),
    "Shadows": lambda sh: dict(lights=tm.Light.directional((1.0, -1.0, -2.0), shadows=sh)),
    "LineStyle": lambda s: dict(outlines=tm.Outlines("mesh", silhouette=s)), "Outlines": lambda o: dict(outlines=o),
}
BASES = {"Light.directional": dict(direction=(1.0, -1.0, -2.0)), "Light.point": dict(position=(1.0, -1.0, -2.0)),
         # the view runs along (0.3, 0.2, 5), as UP's probes expect
         "Camera.fit": dict(direction=(0.3, 0.2, 5.0)), "Camera.look_at": dict(eye=(0.6, 0.4, 10.0)),
         "Camera.orthographic": dict(eye=(0.6, 0.4, 10.0))}
SETTING_CASES = [
    Case(name, _rendered(make, USE[cls]), BASES.get(name, {params[0]["name"]: None}),
         described_params(name, required, params))
    for cls, made_by in SETTINGS.items() if cls != "RenderOptions"
    for name, make, required, params in made_by if params
]


def _replace_case(case: Case) -> Case:
    """`replace` on the value a settings constructor makes, with the probes of each of its
    parameters that is a field: `replace` checks as the constructor does (None: the default)."""
    cls_name, _, ctor = case.name.partition(".")
    fields = {f["name"] for f in descriptions.fields(getattr(tm, cls_name)) if not f["fixed"]}
    make, use = case.call.make, case.call.use  # type: ignore[attr-defined]
    params = [p._replace(none=OK) for p in case.params if p.name in fields]
    return Case(f"{cls_name}.replace({ctor or cls_name})", _rendered(make(**case.base).replace, use), {}, params)


BACKEND_PARAM = Param("backend", BACKEND, none=OK, also=(tm.GpuUnavailableError,))
NORMALS_PARAM = Param("normals", NORMALS, none=OK)  # None: the default
SMOOTH_ITERATIONS = Param("smooth_iterations", Integer(0, 10**6, slow_above=3))
CASES += SETTING_CASES + [_replace_case(c) for c in SETTING_CASES] + [
    Case("render", tm.render, dict(vertices=V, faces=F, **dict(FRAMED, outputs=("color", "normal"))),
         [Param("vertices", VERTICES, none=OK), Param("faces", FACES), NORMALS_PARAM,  # no "depth": see _added
          SMOOTH_ITERATIONS, *CAMERA, BACKEND_PARAM, *FRAME]),
    Case("render(no outlines)", tm.render, dict(vertices=V, faces=F, **dict(FRAMED, outlines=None)),
         [Param("outputs", OUTPUTS_WITHOUT_OUTLINES, none=OK)]),
    Case("Points", tm.Points, dict(positions=V),
         [Param("positions", POINT_POSITIONS),
          Param("normals", (("unit", V / np.linalg.norm(V, axis=1, keepdims=True), OK), ("scaled", V * 3.0, OK),
                            ("a zero row", _with(V, (1, 0), 0.0) * np.eye(3)[0], ValueError),
                            ("too few rows", V[:2], ValueError), ("2 columns", V[:, :2], ValueError),
                            ("nan", _with(V, (0, 1), np.nan), ValueError), ("strings", V.astype(str), TypeError)),
                none=OK),
          Param("colors", (("uint8 RGB", np.full((len(V), 3), 200, np.uint8), OK),
                           ("float RGBA", np.full((len(V), 4), 0.5), OK), ("above 1", np.full((len(V), 3), 2.0), ValueError),
                           ("5 columns", np.zeros((len(V), 5)), ValueError), ("too few rows", np.zeros((2, 3)), ValueError)),
                none=OK),
          Param("radius", (("a float", 0.1, OK), ("one per point", np.full(len(V), 0.1), OK), ("zero", 0.0, ValueError),
                           ("negative", -1.0, ValueError), ("nan", np.nan, ValueError),
                           ("wrong length", np.full(2, 0.1), ValueError)),
                none=OK)]),
    Case("Lines", _lines_rendered, dict(positions=V, segments=None, color=None, width=None, transform=None),
         [Param("positions", _but(POINT_POSITIONS, {"one point": ValueError}), none=TypeError),
          Param("segments", (("int64", EDGES, OK), ("int32", EDGES.astype(np.int32), OK),
                             ("uint32", EDGES.astype(np.uint32), OK), ("none of them", EDGES[:0], OK),
                             ("past the end", _with(EDGES, (1, 1), len(V)), IndexError),
                             ("negative", _with(EDGES, (0, 0), -1), IndexError), ("floats", EDGES * 1.0, TypeError),
                             ("3 columns", np.hstack([EDGES, EDGES[:, :1]]), ValueError),
                             ("flat", EDGES.ravel(), ValueError), ("a string", "segments", TypeError)), none=OK),
          Param("color", KINDS["color"], none=OK), Param("width", Number(0.0, 64.0, open_lo=True), none=OK),
          Param("transform", KINDS["matrix"], none=OK)]),
    Case("Renderer.add_points", RENDERER.add_points, dict(points=tm.Points(V)),
         [Param("points", (("Points", tm.Points(V), OK), ("an array", V, TypeError), ("a Mesh", tm.Mesh(V, F), TypeError),
                           ("a Points of one point", tm.Points(V[:1]), OK), ("duplicates", tm.Points(np.ones((9, 3))), OK)))]),
    Case("points.normals", tm.points.normals, dict(positions=V, k=None),
         [Param("positions", POINT_POSITIONS),
          Param("k", (("12", 12, OK), ("3", 3, OK), ("256", 256, OK), ("2", 2, ValueError), ("257", 257, ValueError),
                      ("negative", -5, ValueError), ("a float", 3.5, TypeError), ("a string", "12", TypeError)),
                none=OK)]),
    Case("Renderer", tm.Renderer, dict(backend=None), [BACKEND_PARAM]),
    Case("gpu_info", tm.gpu_info, dict(backend=None), [BACKEND_PARAM]),
    Case("Renderer.render", RENDERER.render, dict(meshes=HANDLE, **FRAMED),
         [Param("meshes", MESHES, none=OK), *CAMERA, *FRAME]),
    Case("Renderer.render_many", RENDERER.render_many,
         dict(meshes=HANDLE, cameras=[tm.Camera.fit(), tm.Camera.fit((1.0, 0.0, 0.0))], **FRAMED),
         [Param("meshes", MESHES, none=OK), Param("cameras", CAMERAS), *FRAME]),
    Case("RenderOptions", lambda **kw: RENDERER.render(HANDLE, **_options_of(tm.RenderOptions(**kw))),
         FRAMED, [*CAMERA, *FRAME]),
    Case("RenderOptions.replace",
         lambda **kw: RENDERER.render(HANDLE, **_options_of(tm.RenderOptions(width=8).replace(**kw))),
         FRAMED, [*CAMERA, *FRAME]),
    Case("Renderer.add_mesh", _added, dict(vertices=V, faces=F, normals="smooth", smooth_iterations=0),
         [Param("vertices", VERTICES), Param("faces", FACES), NORMALS_PARAM, SMOOTH_ITERATIONS, *MESH_COLOURS]),
    Case("Renderer.add_mesh(textured)", _added, dict(vertices=V, faces=F, **TEXTURED), TEXTURE_PARAMS),
    # on a freshly added mesh, or on `mesh` when it is not a handle of it
    Case("Renderer.remove_mesh", lambda mesh: RENDERER.remove_mesh(RENDERER.add_mesh(V, F) if mesh is HANDLE else mesh),
         dict(mesh=HANDLE),
         [Param("mesh", ((("a handle", HANDLE, OK), ("a removed handle", REMOVED_HANDLE, OK),
                               ("a handle of another renderer", OTHER_HANDLE, ValueError),
                               ("a mesh id", HANDLE.id, TypeError), ("a Mesh", tm.Mesh(V, F), TypeError))))]),
    Case("Mesh", _mesh_rendered, dict(vertices=V, faces=F, material=None, transform=None, normals="smooth"),
         [Param("vertices", VERTICES), Param("faces", FACES), Param("material", KINDS["Material"], none=OK),
          Param("transform", KINDS["matrix"], none=OK), NORMALS_PARAM, *MESH_COLOURS]),
    Case("Mesh(textured)", _mesh_rendered, dict(vertices=V, faces=F, **TEXTURED), TEXTURE_PARAMS),
    Case("Mesh(vertex colours)", _mesh_rendered, dict(vertices=V, faces=F, vertex_colors=np.ones((N, 3))),
         [Param("face_colors", BOTH_COLOURS, none=OK)]),
]


def _viewer_call(method: str = "") -> Callable[..., Any]:
    """``method`` on a fresh 16x16 viewer of the shared handle (its constructor where ""): its
    frame, or what the method returns (a snapshot). A render's strokes and SVG: below."""
    def call(**kw: Any) -> Any:
        v = tm.Viewer(HANDLE, renderer=RENDERER, **SMALL) if method else tm.Viewer(renderer=RENDERER, **kw)
        try:
            result = getattr(v, method)(**kw) if method else None
            return v.frame if result is None else result
        finally:
            v.close()
    return call


DRAG = Number(-1e6, 1e6)
LINES = tm.render(V, F, outlines=tm.Outlines("mesh", taper=5.0), outputs=("lines",), width=64, height=64)
STROKE_PARAMS = [Param("smooth", Number(0.0, 4096.0)), Param("simplify", POSITIVE)]
VIEWER_SETTINGS = [p for p in FRAME if p.name != "outputs"]  # a viewer shows the colour image
CASES += [
    Case("Viewer", _viewer_call(),
         dict(vertices=V, faces=F, normals="smooth", image_format="png", drag_scale=0.5, controls=False, **SMALL),
         [Param("vertices", VERTICES), Param("faces", FACES), Param("image_format", Name(("png", "jpeg"))),
          NORMALS_PARAM, Param("drag_scale", Number(0.05, 1.0)), Param("controls", FLAG)]),
    *[Case(f"Viewer.{m}", _viewer_call(m), dict(dx=10.0, dy=-5.0), [Param("dx", DRAG), Param("dy", DRAG)])
      for m in ("orbit", "pan")],
    Case("Viewer.zoom", _viewer_call("zoom"), dict(factor=1.5), [Param("factor", Number(1e-3, 1e3))]),
    Case("Viewer.set", _viewer_call("set"), dict(SMALL, outlines="mesh", msaa=1, supersample=1), VIEWER_SETTINGS),
    Case("Viewer.snapshot", _viewer_call("snapshot"), FRAMED, FRAME),
    Case("Viewer.view_from", _viewer_call("view_from"), dict(axis="+x"), [Param("axis", Name(tm.viewer.AXES))]),
    Case("Viewer.turntable", _viewer_call("turntable"),  # the path's checks: tests/test_viewer_lifetime.py
         dict(path=os.path.join(TURNTABLES, "turn.gif"), seconds=0.5, fps=4),
         [Param("seconds", Number(0, 600, open_lo=True, slow_above=2)), Param("fps", Integer(1, 60))]),
    Case("RenderStack.save",  # the path's checks: tests/test_render_many.py
         RENDERER.render_many(HANDLE, [tm.Camera.fit(), tm.Camera.fit(turn=90)], **SMALL).save,
         dict(path=os.path.join(TURNTABLES, "stack.gif"), fps=4, progress=False),
         [Param("fps", Integer(1, 60)), Param("progress", FLAG)]),
    # its only argument is the path: tests/test_viewer_draft.py checks it
    Case("Viewer.to_html", _viewer_call("to_html"), dict(path=os.path.join(TURNTABLES, "page.html")), []),
    Case("RenderResult.strokes", LINES.strokes, dict(smooth=1.0, simplify=0.25), STROKE_PARAMS),
    Case("RenderResult.svg", LINES.svg, dict(order="drawing", simplify=0.25, smooth=1.0, widths="auto"), STROKE_PARAMS
         + [Param("order", Name(("drawing", "plotter"))), Param("widths", Name(("auto", "kind", "point")))]),
]

# ------------------------------------------------------------------------------------------------
# toonmesh.testing: comparisons of meshes, images and drawings, snapshots, and the cross-checks.
# A legal value that makes two things differ gives AssertionError, the comparison's outcome.
# A mesh to compare: a (vertices, faces) pair, positions alone, or a Trimesh-like object.
COMPARED = (("pair", (V, F), OK), ("list pair", [V, F], OK), ("positions alone", V, OK),
            ("float32 positions", (V.astype(np.float32), F), OK),
            ("int positions", (np.round(V * 100).astype(np.int64), F), OK),
            ("big-endian", (V.astype(">f8"), F.astype(">i4")), OK), ("nested lists", (V.tolist(), F.tolist()), OK),
            ("uint32 faces", (V, F.astype(np.uint32)), OK), ("moved", (V + 0.1, F), OK),
            ("faces turned and reordered", (V, np.roll(F[::-1], 1, axis=1)), OK),
            ("a face flipped", (V, np.vstack([F[:1, ::-1], F[1:]])), OK), ("fewer faces", (V, F[1:]), OK),
            ("fewer vertices", V[1:], OK), ("complex", V.astype(complex), TypeError), ("bool", V > 0, TypeError),
            ("strings", V.astype(str), TypeError), ("object", V.astype(object), TypeError),
            ("a string", "mesh", TypeError), ("ragged", [[0.0, 0.0, 0.0], [1.0, 0.0]], TypeError),
            ("float faces", (V, F.astype(float)), TypeError), ("nan", (_with(V, (3, 1), np.nan), F), ValueError),
            ("inf", (_with(V, (0, 0), np.inf), F), ValueError), ("shape (N, 2)", V[:, :2].copy(), ValueError),
            ("flat", V.ravel().copy(), ValueError), ("empty", np.zeros((0, 3)), ValueError),
            ("scalar", 1.0, ValueError), ("faces (M, 4)", (V, np.hstack([F, F[:, :1]])), ValueError),
            ("negative face index", (V, _with(F, (5, 2), -1)), IndexError),
            ("face index N", (V, _with(F, (5, 2), N)), IndexError))
IMG8 = (np.random.default_rng(5).random((9, 11, 4)) * 255).astype(np.uint8)
COLOUR_AND_LINES = tm.render(V, F, outlines="mesh", outputs=("color", "lines"), width=11, height=9)
DEPTH_ONLY = tm.render(V, F, outputs=("depth",), width=11, height=9)
IMAGES_TO_COMPARE = (("uint8 RGBA", IMG8, OK), ("floats in [0, 1]", IMG8 / 255.0, OK),
                     ("float32", (IMG8 / 255.0).astype(np.float32), OK), ("int16 levels", IMG8.astype(np.int16), OK),
                     ("bool", IMG8 > 100, OK), ("grey", IMG8[..., 0].copy(), OK), ("RGB", IMG8[..., :3].copy(), OK),
                     ("a render", COLOUR_AND_LINES, OK), ("another size", IMG8[:5], OK),
                     ("nested list", IMG8.tolist(), OK), ("fortran order", np.asfortranarray(IMG8), OK),
                     ("a render without colour", DEPTH_ONLY, ValueError), ("floats above 1", IMG8 * 1.0, ValueError),
                     ("nan", _with(IMG8 / 255.0, (2, 2, 0), np.nan), ValueError),
                     ("negative levels", IMG8.astype(np.int16) - 300, ValueError),
                     ("levels above 255", IMG8.astype(np.int16) + 300, ValueError),
                     ("1-D", IMG8[0, :, 0].copy(), ValueError),
                     ("5 channels", np.zeros((9, 11, 5), np.uint8), ValueError), ("4-D", IMG8[None], ValueError),
                     ("empty", np.zeros((0, 4), np.uint8), ValueError), ("complex", IMG8.astype(complex), TypeError),
                     ("strings", IMG8.astype(str), TypeError), ("object", IMG8.astype(object), TypeError),
                     ("a string", "image.png", TypeError), ("bytes", b"\x89PNG", TypeError))
DRAWINGS = (("a render", LINES, OK), ("its SVG", LINES.svg(), OK), ("its filled SVG", LINES.svg(widths="point"), OK),
            ("a list of lines", list(LINES.lines), OK), ("a tuple of lines", tuple(LINES.lines), OK),
            ("no lines", [], OK), ("a single point", [np.array([[3.0, 4.0]])], OK),
            ("int lines", [np.array([[0, 0], [5, 5]])], OK), ("a render without lines", DEPTH_ONLY, ValueError),
            ("not SVG", "lines", ValueError), ("broken SVG", "<svg", ValueError), ("other XML", "<html/>", ValueError),
            ("a line (K, 3)", [np.zeros((3, 3))], ValueError), ("an empty line", [np.zeros((0, 2))], ValueError),
            ("a nan point", [np.array([[0.0, 0.0], [np.nan, 1.0]])], ValueError),
            ("string points", [np.array([["a", "b"]])], TypeError), ("an array", np.zeros((4, 2)), TypeError),
            ("bytes", b"<svg/>", TypeError), ("an int", 3, TypeError))
# A mesh every peer smooths as toonmesh does: the vertex and face probes but those the peers cannot take
# (trimesh raises on unreferenced vertices after the last face index; values near float64's limits overflow).
PEER_VERTICES = _but(VERTICES, {"huge but finite": None, "tiny": None})
PEER_FACES = _but(FACES, {"one face": None})
PEER_ITERATIONS = Param("iterations", Integer(0, 10**6, slow_above=20), none=OK)
SHARE = Param("share", Number(0.0, 1.0))
COMPARED_MESHES = [Param("actual", COMPARED), Param("expected", COMPARED)]
POSITIVE_TOLERANCE = Number(0.0, math.inf, open_hi=True)
# one 8x8 frame of temporal_popping as another renderer gives it: ink, depth, view, projection
_INK = np.zeros((8, 8), bool)
_INK[3, 2:6] = True
_PERSPECTIVE = np.array([[2.0, 0, 0, 0], [0, 2.0, 0, 0], [0, 0, -1.0, -0.1], [0, 0, -1.0, 0]])
POPPING_FRAME = (_INK, np.full((8, 8), 2.0), np.eye(4), _PERSPECTIVE)
POPPING_FRAMES = (
    ("three frames", [POPPING_FRAME] * 3, OK), ("a tuple of frames", (POPPING_FRAME, POPPING_FRAME), OK),
    ("coverage as floats", [POPPING_FRAME, (_INK.astype(np.float32),) + POPPING_FRAME[1:]], OK),
    ("one frame", [POPPING_FRAME], ValueError), ("empty", [], ValueError), ("a string", "frames", TypeError),
    ("a dict", {0: POPPING_FRAME}, TypeError), ("not a frame", [POPPING_FRAME, 3], TypeError),
    ("three of four parts", [POPPING_FRAME, POPPING_FRAME[:3]], TypeError),
    ("NaN depth", [POPPING_FRAME, (_INK, np.full((8, 8), np.nan)) + POPPING_FRAME[2:]], ValueError),
    ("shapes differ", [POPPING_FRAME, (_INK[:4],) + POPPING_FRAME[1:]], ValueError),
    ("a 3x3 view", [POPPING_FRAME, POPPING_FRAME[:2] + (np.eye(3), _PERSPECTIVE)], ValueError),
    ("a singular projection", [POPPING_FRAME, POPPING_FRAME[:3] + (np.zeros((4, 4)),)], ValueError),
)
SNAPSHOT_VALUES = (("a render", COLOUR_AND_LINES, OK), ("an image", IMG8, OK), ("an SVG", LINES.svg(), OK),
                   ("lines", list(LINES.lines), OK), ("not SVG", "x", ValueError), ("an int", 3, TypeError))
# The peers each smooth the methods whose presets name them (the others of the family are refused).
FAMILY = {m["method"]: next(k["choices"] for k in m["keywords"] if k["name"] == "preset")
          for m in SMOOTHING if any(k["name"] == "preset" for k in m["keywords"])}
PEERS = {peer: tuple(m for m, presets in FAMILY.items() if peer in presets) for peer in ("trimesh", "pymeshlab")}
CASES += [
    Case("testing.assert_mesh_close", testing.assert_mesh_close,
         dict(actual=(V, F), expected=(V, F), rtol=1e-6, atol=0.0, check_faces=True),
         COMPARED_MESHES + [Param("rtol", POSITIVE_TOLERANCE), Param("atol", POSITIVE_TOLERANCE),
                            Param("check_faces", FLAG)], also=(AssertionError,)),
    Case("testing.mesh_difference", testing.mesh_difference, dict(actual=(V, F), expected=(V, F)),
         [Param(n, _but(COMPARED, {"fewer vertices": ValueError})) for n in ("actual", "expected")]),
    *[Case(f"testing.{name}", getattr(testing, name), dict(actual=IMG8, expected=IMG8, levels=8, **extra),
           [Param("actual", IMAGES_TO_COMPARE), Param("expected", IMAGES_TO_COMPARE), Param("levels", Integer(0, 255))]
           + ([SHARE] if extra else []), also=(AssertionError,))  # images of other sizes, or that differ
      for name, extra in (("assert_images_close", {"share": 0.001}), ("image_difference", {}))],
    *[Case(f"testing.{name}", getattr(testing, name), dict(actual=LINES, expected=LINES, pixels=1.0, **extra),
           [Param("actual", DRAWINGS), Param("expected", DRAWINGS), Param("pixels", Number(0.0, 1e6))]
           + ([SHARE] if extra else []), also=(AssertionError,))
      for name, extra in (("assert_drawings_close", {"share": 0.005}), ("drawing_difference", {}))],
    Case("testing.Snapshot", lambda **kw: (lambda s: (s.directory, s.test_name, s.update))(testing.Snapshot(**kw)),
         dict(directory=SNAPSHOTS, test_name="probe", update=False, written=None),
         [Param("directory", (("a str", SNAPSHOTS, OK), ("a Path", Path(SNAPSHOTS), OK), ("an int", 3, TypeError),
                              ("bytes", SNAPSHOTS.encode(), TypeError))),
          Param("test_name", (("a name", "test_x[gl]", OK), ("odd characters", "a/b c:d", OK),
                              ("empty", "", ValueError), ("an int", 3, TypeError))),
          Param("update", FLAG), Param("written", ((("a list", [], OK), ("a tuple", (), TypeError))), none=OK)]),
    # a Snapshot writing its references (update): the reference's name
    Case("testing.Snapshot(call)", lambda **kw: testing.Snapshot(SNAPSHOTS, "probe", update=True)(**kw).name,
         dict(value=COLOUR_AND_LINES, name=None, kind="auto", levels=8, pixels=1.0, share=None),
         [Param("value", SNAPSHOT_VALUES),
          Param("name", ((("a name", "other", OK), ("empty", "", ValueError), ("an int", 3, TypeError))), none=OK),
          Param("kind", Name(("auto", "image", "drawing"))), Param("levels", Integer(0, 255)),
          Param("pixels", Number(0.0, 1e6)), Param("share", Number(0.0, 1.0), none=OK)]),
    *[Case(f"testing.smoothing_vs_{peer}", getattr(testing, f"smoothing_vs_{peer}"),
           dict(vertices=V, faces=F, method="laplacian", iterations=3),
           [Param("vertices", PEER_VERTICES), Param("faces", PEER_FACES),
            Param("method", Name(methods, invalid=tuple(m for m in FAMILY if m not in methods))), PEER_ITERATIONS])
      for peer, methods in PEERS.items()],
    Case("testing.curvature_vs_libigl", testing.curvature_vs_libigl, dict(vertices=V, faces=F, radius=2, smoothing=0.0),
         [Param("vertices", PEER_VERTICES), Param("faces", PEER_FACES), Param("radius", Integer(1, 10)),
          Param("smoothing", POSITIVE)]),
    Case("testing.temporal_popping", testing.temporal_popping,
         dict(frames=[POPPING_FRAME, POPPING_FRAME], pixels=2.0, ink=0.5, depth_tolerance=0.01),
         [Param("frames", POPPING_FRAMES), Param("pixels", Number(0.0, 64.0)),
          Param("ink", Number(0.0, 1.0, open_lo=True)), Param("depth_tolerance", Number(0.0, 1.0))]),
    # values near float64's limit overflow in scikit-image's filter (not in toonmesh's)
    Case("testing.sobel_vs_skimage", testing.sobel_vs_skimage, dict(image=IMG, mask=None, which="sobel"),
         [Param("image", _but(IMAGES, {"huge values": None})),
          Param("mask", MASKS, none=OK), Param("which", Name(("sobel", "sobel_h", "sobel_v")))]),
]

# ------------------------------------------------------------------------------------------------
# Running the probes


def _finite_floats(result: Any) -> bool:
    """Every float inside `result` (tuples, lists, dicts, dataclasses, an EdgeIndex, a render's images,
    a scene setting's read-only fields) is finite; a render's depth is +inf where no mesh is."""
    if isinstance(result, np.ndarray):
        return result.dtype.kind != "f" or bool(np.isfinite(result).all())
    if isinstance(result, float):
        return math.isfinite(result)
    if isinstance(result, tm.RenderResult):
        if result.depth is not None and not np.all(np.isfinite(result.depth) | (result.depth == np.inf)):
            return False
        parts: List[Any] = [result.color, result.normal, result.outline, result.lines or [], result.view_matrix,
                            result.projection, result.near, result.far]
    elif isinstance(result, te.EdgeIndex):
        parts = [result.features, result.face_normals]
    elif isinstance(result, (tm.Material, tm.Light, tm.Camera, tm.LineStyle, tm.Outlines)):
        parts = [getattr(result, k) for k in dir(type(result))
                 if not k.startswith("_") and not callable(getattr(result, k))]
    elif isinstance(result, (dict, tuple, list, tm.RenderStack)):
        parts = list(result.values() if isinstance(result, dict) else result)
    else:
        parts = [getattr(result, k) for k in getattr(result, "__dataclass_fields__", ())]
    return all(_finite_floats(p) for p in parts)


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, tm.RenderResult):
        names = ("color", "normal", "depth", "outline", "lines", "line_kinds", "view_matrix", "projection")
        return isinstance(b, tm.RenderResult) and all(_same(getattr(a, n), getattr(b, n)) for n in names)
    if isinstance(a, tm.RenderStack):
        return isinstance(b, tm.RenderStack) and _same(list(a), list(b))
    if isinstance(a, tm.MeshHandle):  # a new upload: another id, the same mesh
        return isinstance(b, tm.MeshHandle) and all(getattr(a, k) == getattr(b, k) for k in ("n_vertices", "n_faces",
                                                                                            "normals"))
    if isinstance(a, tm.Renderer):
        return isinstance(b, tm.Renderer) and a.backend == b.backend
    if isinstance(a, tm.Points):  # its arrays, checked and kept
        return isinstance(b, tm.Points) and all(_same(getattr(a, k), getattr(b, k)) for k in
                                                ("positions", "normals", "colors", "radius", "material", "transform"))
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return isinstance(a, np.ndarray) and isinstance(b, np.ndarray) and np.array_equal(a, b, equal_nan=True)
    if isinstance(a, (tuple, list)):
        return type(a) is type(b) and len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    if hasattr(a, "__dataclass_fields__"):
        return all(_same(getattr(a, k), getattr(b, k)) for k in a.__dataclass_fields__)
    if isinstance(a, te.EdgeIndex):
        return _same(a.features, b.features)
    return bool(a == b) if a is not None else b is None


def _named(message: str) -> List[str]:
    """The arguments a message starts with: "name: ...", "name[i]: ..." or "name[i, j]: ..." for
    an element, "a, b: ..." for arguments that go together, "owner.name: ..." or
    "owner[i].name: ..." for a field of a compound argument (both owner and name count)."""
    parts = [n.split(".") for n in re.sub(r"\[[^\]]*\]", "", message.split(":")[0]).split(", ")]
    return [n for p in parts for n in (p[0], p[-1])]


ALL_PROBES = [pytest.param(case, p, label, value, expected, id=f"{case.name}:{p.name}={label}")
              for case in CASES for p in case.params for label, value, expected in probes(p)]
_REFERENCE: Dict[str, Any] = {}  # each case's valid call's result, before its probes


@pytest.mark.parametrize("case, param, label, value, expected", ALL_PROBES)
def test_bad_argument(case: Case, param: Param, label: str, value: Any, expected: Any) -> None:
    if case.name not in _REFERENCE:
        _REFERENCE[case.name] = case.call(**case.base)
    reference = _REFERENCE[case.name]
    kwargs = dict(case.base, **{param.name: value})
    legal_errors = tuple(param.also) + tuple(case.also)
    refused = expected.exc if isinstance(expected, Refused) else expected
    t0 = time.perf_counter()
    try:
        try:
            result = case.call(**kwargs)
        except legal_errors if expected in (OK, "nonfinite ok") else () as exc:  # type: ignore[misc]
            result = exc  # a documented domain error for a legal value
        except (TypeError, ValueError, IndexError) as exc:
            assert expected not in (OK, "nonfinite ok"), f"refused a legal value: {type(exc).__name__}: {exc}"
            assert isinstance(exc, refused), f"expected {refused}, got {type(exc).__name__}: {exc}"
            assert param.name in _named(str(exc)), f"the message does not start with the name: {exc}"
            if isinstance(expected, Refused):
                assert expected.hint in str(exc), f"no hint {expected.hint!r}: {exc}"
            result = exc
        else:
            assert expected in (OK, "nonfinite ok"), f"accepted a bad value, expected {expected}"
            if expected == OK:
                assert _finite_floats(result), "a legal value gave non-finite floats"
    finally:
        if case.name == "set_num_threads":
            tm.set_num_threads(0)
    assert time.perf_counter() - t0 < 30.0, "took suspiciously long"
    # The next valid call still works, and gives the same result as before.
    assert _same(case.call(**case.base), reference)


def test_every_public_callable_is_in_the_table() -> None:
    """A new public function, class or method must get its row in CASES (or be listed here as
    taking no arguments worth probing)."""
    def _methods(cls: type) -> Set[str]:  # a class's own public methods (static ones too), as "Class.method"
        return {f"{cls.__name__}.{n}" for n in vars(cls) if not n.startswith("_") and callable(getattr(cls, n))}
    covered = {c.name.split("(")[0] for c in CASES} | {"data.load_obj", "load"}  # they read files: see below
    no_arguments = {"get_num_threads", "data.bunny", "edges.FeatureEdges", "edges.EdgeDetection", "edges.Curvature",
                    "kang_table", "Light.key", "MeshHandle", "RenderStack", "RenderKeywords"}  # (a TypedDict)
    no_arguments |= {f"{c}.describe" for c in SETTINGS}  # what each settings class is made of, for front ends
    no_arguments |= {"Camera", "Light", "Material"}  # made by their static methods only (which have rows)
    no_arguments |= {"RenderResult"} | _methods(tm.RenderResult)  # they write its images: test_render*.py
    no_arguments |= {"Viewer.close", "Viewer.code", "Viewer.reframe", "Viewer.home"}  # tests/test_viewer.py
    # toonmesh.testing: what its comparisons return, and need_peer (test_testing.py: it imports a peer)
    no_arguments |= {"testing.MeshDifference", "testing.ImageDifference", "testing.DrawingDifference",
                     "testing.CurvatureAgreement", "testing.SobelDifference", "testing.TemporalPopping", "testing.PeerMissingError",
                     "testing.need_peer"}
    public = {f"smooth.{n}" for n in tm.smooth.__all__} | {f"shapes.{n}" for n in tm.shapes.__all__}
    public |= {f"edges.{n}" for n in te.__all__} | {"set_num_threads", "get_num_threads", "data.bunny", "data.load_obj"}
    public |= {f"testing.{n}" for n in testing.__all__ if callable(getattr(testing, n))}
    public |= {f"edges.{m}" for m in _methods(te.EdgeIndex)}
    # The renderer: every function and class at the top level, and each class's methods.
    for name in tm.__all__:
        obj = getattr(tm, name)
        if not callable(obj) or (isinstance(obj, type) and issubclass(obj, BaseException)):
            continue  # modules (above), __version__, exceptions
        public |= {name} | (_methods(obj) if isinstance(obj, type) else set())
    assert {"render", "Renderer.render", "Renderer.render_many", "Renderer.add_mesh", "Material.lut",
            "Camera.look_at", "Light.point", "Outlines", "LineStyle"} <= public  # the walk finds them
    missing = public - covered - no_arguments
    assert missing == set(), f"no bad-argument rows for {sorted(missing)}"


# The functions that read files get their own probes: a bad argument names ``path``; a bad file
# (toonmesh.load) names the file.
PATHS = [("int", 3, TypeError), ("none", None, TypeError), ("list", ["a.obj"], TypeError),
         ("bytes", b"a.obj", TypeError), ("missing file", "no/such/file.obj", FileNotFoundError),
         ("not an obj", "BAD", ValueError), ("short vertex line", "v 1 2\nf 1 2 3\n", ValueError),
         ("a good obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", OK)]


def _read(read: Callable[[Any], Any], tmp_path: Any, path: Any, expected: Any) -> Any:
    """``read(path)`` (an OBJ text written to a file first) when legal, else its exception."""
    if isinstance(path, str) and path.startswith(("v ", "BAD")):
        (tmp_path / "mesh.obj").write_text(path.replace("BAD", "this is not an obj file\nf a b c\n"))
        path = str(tmp_path / "mesh.obj")
    if expected == OK:
        return read(path)
    with pytest.raises(expected) as info:
        read(path)
    return path, str(info.value)


@pytest.mark.parametrize("label, path, expected", [p for p in PATHS if p[0] != "bytes"])
def test_load_obj_arguments(tmp_path: Any, label: str, path: Any, expected: Any) -> None:
    result = _read(load_obj, tmp_path, path, expected)
    if expected == OK:
        assert result[0].shape == (3, 3) and result[1].tolist() == [[0, 1, 2]]  # (vertices, faces)
    elif expected is not FileNotFoundError:
        assert result[1].startswith("path:")
    assert load_obj.__module__ == "toonmesh.data"


@pytest.mark.parametrize("label, path, expected", PATHS)
def test_load_arguments(tmp_path: Any, label: str, path: Any, expected: Any) -> None:
    need("trimesh")  # toonmesh.load reads through trimesh
    result = _read(tm.load, tmp_path, path, expected)
    if expected == OK:
        (mesh,) = result
        assert mesh.vertices.shape == (3, 3) and mesh.faces.tolist() == [[0, 1, 2]]
    elif expected is TypeError:
        assert result[1].startswith("path:")
    elif isinstance(path, str):
        assert result[1].startswith(result[0])  # the file, then what is wrong with it
