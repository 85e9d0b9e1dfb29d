"""Mesh smoothing: Laplacian, Taubin, HC and implicit, with trimesh/pymeshlab presets, and
feature-preserving smoothing by normal filtering (bilateral and guided) that keeps creases sharp.

Every function takes ``(vertices, faces)`` or a ``trimesh.Trimesh`` (read, never modified) and
returns a new ``(N, 3)`` array of the input's float dtype (float32 in, float32 out; float64 in,
float64 out). Units are those of the input coordinates. The work runs in parallel outside the
GIL and gives the same bits for any thread count (see :func:`toonmesh.set_num_threads`).

Without a preset (the default) the behaviour is the clean one: each vertex is averaged over its
distinct edge-neighbours with rows that sum to one, boundaries are handled as asked, and
vertices that no face uses stay where they are. Presets reproduce other libraries, quirks
included:

``preset="trimesh"``
    trimesh's ``filter_laplacian`` / ``filter_taubin`` / ``filter_humphrey`` (operator from
    directed half-edges, so boundary and duplicate-face vertices drift toward the origin as they
    do there; volume constraint on by default; Taubin counts passes, not pairs).
``preset="pymeshlab"``
    pymeshlab's ``apply_coord_laplacian_smoothing`` (cotangent weights and pymeshlab's step
    count by default), ``apply_coord_taubin_smoothing`` and ``apply_coord_hc_laplacian_smoothing``
    (one step per iteration, and one iteration by default, like one call).
``preset="paper"``
    Al-Rousan et al. 2016: every vertex moves to the plain mean of its neighbours
    (``laplacian`` only; a full step, boundaries free); for :func:`guided`, Zhang et al.
    2015's rule as their published code has it (vertices fitted after every pass, the faces
    within two mean distances between adjacent centroids, ``sigma_s`` in those distances,
    ``sigma_r=0.35``, no comparison of the faces' own normals).

Each function's keywords, their ranges and their defaults (with each preset's own) are the
core's description of the method (``toonmesh._core._smoothing_description()``), from which the
functions' signatures, the "Parameters" lines of their docstrings, the ``...Options`` TypedDicts
below and the ``toonmesh smooth`` command's flags are made.

An argument a preset does not have (say ``boundary`` with ``preset="trimesh"``) raises
``ValueError`` instead of being ignored. ``weld=True`` works with every preset: the preset's
algorithm then runs on the welded mesh, as the peer's filter would on that mesh.

Seams. A textured or flat-shaded mesh stores a point once per UV island or normal (an STL
once per face), and those copies share no edge: smoothed as they are, a seam is a boundary on
both sides, so its two sides move apart (cracks) or, with ``boundary="fixed"``, stay
unsmoothed. ``weld=True`` smooths the welded mesh instead (vertices at exactly the same
position are one vertex) and gives every copy its position's result.

Degenerate input stays finite. Cotangent weights use ``cot = cos / max(sin, 1e-4)`` per corner
(``|cot| <= 1e4``), a corner with a zero-length side adds nothing, an edge's weight is clamped at
zero, and a vertex whose weights sum to zero falls back to uniform weights: every step is then a
convex combination of neighbours and no vertex leaves the input's bounding box.

Any scale works: a mesh whose largest coordinate is beyond 2^200 (about 1.6e60) or below
2^-200 is scaled by a power of two (exactly) for the computation and back, so cotangents,
volumes and sums neither overflow nor underflow, from subnormal coordinates up to float64's
largest value. Precision is relative to the coordinates' magnitude, as always in floating point:
a mesh of size 1 placed at 1e10 is smoothed to about 1e-6.
"""

from __future__ import annotations

import inspect
import textwrap
from typing import TYPE_CHECKING, Any, Callable, Dict, List, Mapping, Optional, TypedDict

import numpy as np
import numpy.typing as npt

from toonmesh import _core
from toonmesh.arguments._input import mesh_arrays

if TYPE_CHECKING:
    from typing_extensions import Unpack

__all__ = ["laplacian", "taubin", "hc", "implicit", "bilateral", "guided"]

#: What every smoothing function returns: new positions, of the input's float dtype.
Positions = npt.NDArray[np.floating[Any]]

#: Each smoothing method as the core describes it, by name: its help, its keywords (name, kind,
#: range or choices, default, the presets' defaults, help) and its presets.
_DESCRIBED: Dict[str, Dict[str, Any]] = {m["method"]: m for m in _core._smoothing_description()}

#: The Python type of each kind of keyword.
_TYPES = {"int": int, "float": float, "choice": str, "bool": bool}

#: The keyword every function takes besides the described ones: it is the mesh's, not the method's.
_PINNED = "pinned"

#: What every smoothing function's docstring says of the mesh, ``pinned`` and the result
#: (Google-style sections; the described keywords' entries go between ``_MESH`` and ``_PINNED``).
_MESH = """
        vertices: (N, 3) float32 or float64 array, or a ``trimesh.Trimesh``. Vertex positions,
            any memory order. With a Trimesh, leave ``faces`` as None.
        faces: (M, 3) int32, int64, uint32 or uint64 array. Triangles as vertex indices.
            Degenerate, duplicate, flipped and non-manifold faces are allowed; vertices no face
            uses stay where they are (except under ``preset="trimesh"``).
"""

_PINNED_ENTRY = """
        pinned: 1-D array of vertex indices (any integer dtype), or (N,) bool mask, optional.
            Vertices that must not move (a list or tuple works too; an empty one pins nothing).
            With ``weld=True``, a position is pinned when any of its copies is.
"""

_RESULT = """
    Returns:
        (N, 3) ndarray of the input's float dtype: a new array.

    Raises:
        TypeError: A wrong dtype (positions must be float32/float64, faces
            int32/int64/uint32/uint64, in either byte order), or an option of the wrong Python
            type: integers take ints (or NumPy integers), numbers take ints or floats (or NumPy
            numbers), never bools or strings; ``volume_constraint`` takes True or False (or a
            NumPy bool) only.
        ValueError: A wrong shape, NaN or inf, an empty mesh, an unknown option or one the
            preset lacks, a value out of range (NaN never is in range; an int beyond 64 bits is
            refused), or a result that would overflow the dtype.
        IndexError: A face or pinned index outside ``[0, N)``.
        KeyboardInterrupt: Ctrl-C (or any signal whose handler raises) stops the work between
            two steps, or two iterations of the implicit solve, within a few milliseconds.
"""


def _annotation(keyword: Mapping[str, Any]) -> str:
    """The type of a described keyword as a TypedDict or stub writes it: ``Optional[float]``, or
    ``bool`` for a flag that takes no None (``weld``)."""
    t = _TYPES[keyword["kind"]].__name__
    return f"Optional[{t}]" if keyword["optional"] else t


def _number(x: float) -> str:
    """A described bound or default as the docs write it: ``0``, ``-0.53``, ``1e-10``, ``1e+12``."""
    if float(x).is_integer() and abs(x) < 1e9:
        return str(int(x))
    return repr(x) if 1e-4 <= abs(x) < 1e9 else f"{x:g}"


def _value(keyword: Mapping[str, Any], v: Any) -> str:
    """A described value as Python spells it."""
    if isinstance(v, bool) or v is None:
        return str(v)
    if isinstance(v, str):
        return f'"{v}"'
    return repr(float(v)) if keyword["kind"] == "float" and float(v).is_integer() else _number(v)


def _allowed(rule: Mapping[str, Any]) -> str:
    """A described range in words: ``in [0, 1]``, ``in (0, 1)``, ``> 0``, ``>= 0``."""
    lo, hi = rule["exclusive"]
    if rule["max"] == float("inf"):
        return f"{'>' if lo else '>='} {_number(rule['min'])}"
    return f"in {'[('[lo]}{_number(rule['min'])}, {_number(rule['max'])}{'])'[hi]}"


def _kind_in_words(keyword: Mapping[str, Any]) -> str:
    """What a keyword takes, as its docstring entry opens: ``float in [0, 1]``, or its
    choices."""
    if keyword["kind"] == "choice":
        names = [f'"{c}"' for c in keyword["choices"]]
        return ", ".join(names[:-1]) + f" or {names[-1]}" if len(names) > 1 else names[0]
    if keyword["kind"] == "bool":
        return "bool"
    return f"{keyword['kind']} {_allowed(keyword)}"


def _default_in_words(keyword: Mapping[str, Any]) -> str:
    """A keyword's default without a preset: ``default 0.5``, or ``optional`` where it is
    measured (its words then follow the help, :func:`_parameters`)."""
    return "optional" if keyword.get("default_words") else f"default {_value(keyword, keyword['default'])}"


def _presets_in_words(keyword: Mapping[str, Any]) -> str:
    """The presets whose default or range differs, grouped by value:
    ``paper, pymeshlab presets: 1.0; trimesh preset: in [-1000000, 1000000]`` ("" for none)."""
    by_value: Dict[str, List[str]] = {}
    for preset, v in keyword["presets"].items():
        by_value.setdefault(_value(keyword, v), []).append(preset)
    for preset, rule in keyword.get("preset_ranges", {}).items():
        by_value.setdefault(_allowed(rule), []).append(preset)
    return "; ".join(f"{', '.join(names)} preset{'s' if len(names) > 1 else ''}: {v}" for v, names in by_value.items())


def _sentence(text: str) -> str:
    """``text`` as a sentence: its first letter upper case, a full stop at the end."""
    return f"{text[0].upper()}{text[1:]}."


def _parameters(method: str) -> str:
    """The entries of ``method``'s keywords in its docstring's "Args" section, one a keyword,
    from its description: ``name: type and range, default (the presets' own). Help.``"""
    lines = []
    for k in _DESCRIBED[method]["keywords"]:
        text = f"{k['name']}: {_kind_in_words(k)}, {_default_in_words(k)}"
        presets = _presets_in_words(k)
        text += f" ({presets}). " if presets else ". "
        text += _sentence(k["help"])
        if k.get("default_words"):
            text += f" By default {k['default_words']}."
        lines += textwrap.wrap(text, 96, initial_indent=" " * 8, subsequent_indent=" " * 12)
    return "\n".join(lines) + "\n"


def _signature(method: str) -> inspect.Signature:
    """A smoothing function's signature, as ``help()``, the command line and the API docs read
    it: the mesh, then each described keyword of ``method``, None by default (the method's or
    preset's own default), or its default for a flag that takes no None (``weld``); then
    ``pinned``."""
    mesh = [
        inspect.Parameter("vertices", inspect.Parameter.POSITIONAL_OR_KEYWORD, annotation=Any),
        inspect.Parameter("faces", inspect.Parameter.POSITIONAL_OR_KEYWORD, default=None, annotation=Any),
    ]
    keywords = [
        inspect.Parameter(
            k["name"], inspect.Parameter.KEYWORD_ONLY,
            default=None if k["optional"] else k["default"],
            annotation=Optional[_TYPES[k["kind"]]] if k["optional"] else _TYPES[k["kind"]],
        )
        for k in _DESCRIBED[method]["keywords"]
    ]
    pinned = inspect.Parameter(_PINNED, inspect.Parameter.KEYWORD_ONLY, default=None, annotation=Optional[Any])
    return inspect.Signature(mesh + keywords + [pinned], return_annotation=Positions)


def _call(smoother: Callable[..., Positions], vertices: Any, faces: Any, options: Mapping[str, Any]) -> Positions:
    """The core's smoother of the public function ``smoother`` (its namesake) on what it was
    given. A keyword ``smoother`` does not take is a TypeError, as for any Python function;
    every option's type and value is checked in the core, which names it in the error."""
    try:
        inspect.signature(smoother).bind(vertices, faces, **options)
    except TypeError as exc:
        raise TypeError(f"{smoother.__name__}() {exc}") from None
    V, F = mesh_arrays(vertices, faces)
    return _core._smooth(smoother.__name__, (V, F), **options)  # type: ignore[no-any-return]


# @generated keywords: `python scripts/stubs.py` writes this block from the core's description
class SmoothingOptions(TypedDict, total=False):
    """The keywords every smoothing function takes, for type checkers."""

    iterations: Optional[int]
    weld: bool
    pinned: Optional[Any]


class LaplacianOptions(SmoothingOptions, total=False):
    """The keywords of :func:`laplacian`, for type checkers (see its docstring)."""

    lamb: Optional[float]
    weights: Optional[str]
    boundary: Optional[str]
    volume_constraint: Optional[bool]
    preset: Optional[str]


class TaubinOptions(SmoothingOptions, total=False):
    """The keywords of :func:`taubin`, for type checkers (see its docstring)."""

    lamb: Optional[float]
    mu: Optional[float]
    weights: Optional[str]
    boundary: Optional[str]
    preset: Optional[str]


class HcOptions(SmoothingOptions, total=False):
    """The keywords of :func:`hc`, for type checkers (see its docstring)."""

    alpha: Optional[float]
    beta: Optional[float]
    weights: Optional[str]
    boundary: Optional[str]
    preset: Optional[str]


class ImplicitOptions(SmoothingOptions, total=False):
    """The keywords of :func:`implicit`, for type checkers (see its docstring)."""

    step: Optional[float]
    tol: Optional[float]
    max_iter: Optional[int]
    weights: Optional[str]
    boundary: Optional[str]
    volume_constraint: Optional[bool]
    preset: Optional[str]


class BilateralOptions(SmoothingOptions, total=False):
    """The keywords of :func:`bilateral`, for type checkers (see its docstring)."""

    vertex_iterations: Optional[int]
    sigma_s: Optional[float]
    sigma_r: Optional[float]


class GuidedOptions(SmoothingOptions, total=False):
    """The keywords of :func:`guided`, for type checkers (see its docstring)."""

    vertex_iterations: Optional[int]
    sigma_s: Optional[float]
    sigma_r: Optional[float]
    preset: Optional[str]
# @end generated keywords


def laplacian(vertices: Any, faces: Any = None, **options: Unpack[LaplacianOptions]) -> Positions:
    """Explicit Laplacian smoothing: ``x <- x + lamb * (A x - x)``, repeated.

    ``A x`` is the weighted mean of each vertex's neighbours. The pymeshlab preset takes no
    ``lamb``: its update is ``(x + S) / (C + 1)``, a full step.
    """
    return _call(laplacian, vertices, faces, options)


def taubin(vertices: Any, faces: Any = None, **options: Unpack[TaubinOptions]) -> Positions:
    """Taubin (lambda/mu) smoothing, which removes noise without shrinking the mesh.

    Each iteration is a shrink step ``x += lamb (A x - x)`` then an inflate step
    ``x += mu (A x - x)`` (so 10 iterations are 20 passes, as in pymeshlab and open3d). With
    ``preset="trimesh"``, ``iterations`` counts passes instead: even passes shrink, odd passes
    inflate, and ``mu`` is trimesh's ``-nu``. The pymeshlab and trimesh presets take uniform
    weights only.
    """
    return _call(taubin, vertices, faces, options)


def hc(vertices: Any, faces: Any = None, **options: Unpack[HcOptions]) -> Positions:
    """HC smoothing (Vollmer, Mencl and Mueller 1999): Laplacian smoothing that pushes each
    vertex back toward its original and previous positions, so the mesh does not shrink.

    Per iteration, with ``o`` the original positions::

        p = A x
        b = p - (alpha o + (1 - alpha) x)
        x <- p - (beta b + (1 - beta) A b)

    ``preset="pymeshlab"`` reproduces ``apply_coord_hc_laplacian_smoothing`` instead (no alpha,
    beta fixed at its default, ``x <- q - beta (q - x) + (1 - beta) A (q - x)`` with ``q = A x``;
    one iteration is one call).
    """
    return _call(hc, vertices, faces, options)


def implicit(vertices: Any, faces: Any = None, **options: Unpack[ImplicitOptions]) -> Positions:
    """Implicit (backward Euler) Laplacian smoothing: solves ``((1 + step) I - step A) x' = x``.

    Stable for any step size, so one large step replaces many explicit ones (Desbrun et al.
    1999). The sparse system is solved in parallel by Jacobi-preconditioned BiCGSTAB to a
    relative residual ``tol``; the operator is rebuilt from the current positions at each
    iteration when the weights depend on them. The trimesh preset's ``step`` is trimesh's
    ``lamb``.
    """
    return _call(implicit, vertices, faces, options)


_NORMAL_FILTERING = """
    Both filters work in two stages. First the face normals are filtered ``iterations`` times:
    each face's normal becomes the normalised sum, over the faces sharing a vertex with it
    (itself included), of ``area * exp(-d^2 / (2 sigma_s^2)) * exp(-r^2 / (2 sigma_r^2)) *
    normal``, with ``d`` the distance between face centroids and ``r`` the distance between
    the two faces' (guidance) normals; ``guided`` also compares the faces' own normals, with a
    small share of that weight at the measured width (which they keep even where ``sigma_r`` is
    given). Faces across a crease have distant normals, so they do not average, and the crease
    stays sharp. Then the vertices are moved ``vertex_iterations`` times to fit the filtered
    normals (Sun et al. 2007: each vertex moves by the mean of its offsets to its faces'
    planes); a move that would turn a face against its filtered normal is undone, so no face
    flips. ``bilateral`` fits once, after its passes; ``guided`` after each of its later
    passes (the last 8 of the default 20), each next pass filtering the fitted mesh's normals,
    as Zhang et al.'s local scheme does after every pass. Boundaries, degenerate and
    non-manifold faces are allowed: a face with no area has no normal and no weight, and its
    vertices fit their other faces. The work runs in parallel
    outside the GIL and gives the same bits for any thread count.
"""

_NORMAL_FILTERING_MESH = """
        vertices: As in :func:`laplacian`.
        faces: As in :func:`laplacian`.
"""

_NORMAL_FILTERING_PINNED = """
        pinned: 1-D array of vertex indices, or (N,) bool mask, optional. Vertices that must
            not move; they come back bit for bit.
"""

_NORMAL_FILTERING_RESULT = """
    Returns:
        (N, 3) ndarray of the input's float dtype (float32 or float64): a new array, in the
        input's units. Vertices no face uses, and pinned vertices, are returned exactly.

    Raises:
        TypeError: A wrong dtype or an option of the wrong Python type (counts take ints,
            widths numbers, ``weld`` a bool).
        ValueError: A wrong shape, NaN or inf, an empty mesh, or a value out of range.
        IndexError: A face or pinned index outside ``[0, N)``.
        KeyboardInterrupt: Ctrl-C stops the work between two passes.
"""


def bilateral(vertices: Any, faces: Any = None, **options: Unpack[BilateralOptions]) -> Positions:
    """Feature-preserving smoothing by bilateral normal filtering (Zheng et al. 2011).

    Removes noise from flat and smoothly curved regions while keeping creases sharp: the range
    weights compare each face's normal with its neighbours' own normals. Fast, and good at
    light noise; under heavy noise the noisy normals themselves blur the creases, where
    :func:`guided` does better.
    """
    return _call(bilateral, vertices, faces, options)


def guided(vertices: Any, faces: Any = None, **options: Unpack[GuidedOptions]) -> Positions:
    """Feature-preserving smoothing by guided normal filtering (Zhang et al. 2015).

    As :func:`bilateral`, but the range weights compare guidance normals: at every pass, each
    face's guidance is the mean normal of the most consistent patch (a face with its vertex
    ring) that contains it, so a face next to a crease is guided by the side it lies on even
    where the noise is as strong as the crease; the faces' own normals weigh in too, so that
    features a few faces wide, where every patch crosses a crease, keep their sides apart.
    Better than :func:`bilateral` at medium and heavy noise and on irregular meshes, at two to
    three times its cost.
    """
    return _call(guided, vertices, faces, options)


# each function's keywords, as callers see them (signature), their lines of its docstring
# (from the core's description), and the documentation of what it shares with its family
for _f, _before, _mesh, _pinned, _after in (
    (laplacian, "", _MESH, _PINNED_ENTRY, _RESULT),
    (taubin, "", _MESH, _PINNED_ENTRY, _RESULT),
    (hc, "", _MESH, _PINNED_ENTRY, _RESULT),
    (implicit, "", _MESH, _PINNED_ENTRY, _RESULT),
    (bilateral, _NORMAL_FILTERING, _NORMAL_FILTERING_MESH, _NORMAL_FILTERING_PINNED, _NORMAL_FILTERING_RESULT),
    (guided, _NORMAL_FILTERING, _NORMAL_FILTERING_MESH, _NORMAL_FILTERING_PINNED, _NORMAL_FILTERING_RESULT),
):
    _f.__signature__ = _signature(_f.__name__)  # type: ignore[union-attr]
    _f.__doc__ = ((_f.__doc__ or "") + _before + "\n    Args:" + _mesh + _parameters(_f.__name__)
                  + _pinned.lstrip("\n") + _after)
del _f, _before, _mesh, _pinned, _after
