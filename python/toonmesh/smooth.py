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
    pymeshlab's ``apply_coord_laplacian_smoothing`` (cotangent weights and 3 steps by default),
    ``apply_coord_taubin_smoothing`` and ``apply_coord_hc_laplacian_smoothing`` (one step per
    iteration; the default is 1, like one call).
``preset="paper"``
    Al-Rousan et al. 2016: every vertex moves to the plain mean of its neighbours
    (``laplacian`` only; ``lamb=1``, boundaries free).

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
from typing import TYPE_CHECKING, Any, Callable, Mapping, Optional, TypedDict, get_type_hints

import numpy as np
import numpy.typing as npt

from toonmesh import _core
from toonmesh.arguments._input import mesh_arrays

if TYPE_CHECKING:
    from typing_extensions import Unpack

__all__ = ["laplacian", "taubin", "hc", "implicit", "bilateral", "guided"]

#: What every smoothing function returns: new positions, of the input's float dtype.
Positions = npt.NDArray[np.floating[Any]]

_COMMON = """
    Parameters shared by every smoothing function
    ----------------------------------------------
    vertices : (N, 3) float32 or float64 array, or trimesh.Trimesh
        Vertex positions, any memory order. With a Trimesh, leave ``faces`` as None.
    faces : (M, 3) int32, int64, uint32 or uint64 array
        Triangles as vertex indices. Degenerate, duplicate, flipped and non-manifold faces are
        allowed; vertices no face uses stay where they are (except under ``preset="trimesh"``).
    pinned : 1-D array of vertex indices (any integer dtype), or (N,) bool mask, optional
        Vertices that must not move (a list or tuple works too; an empty one pins nothing).
    preset : None, "trimesh", "pymeshlab" or "paper"
        Reproduce another library's filter (see the module docs). Default None.
    weld : bool, default False
        Smooth the welded mesh: vertices at exactly the same position (UV seams, split
        normals, an STL's per-face copies) are one vertex, so seams neither open into cracks
        nor count as boundaries, and every copy gets the same result, its position's. A
        position is pinned when any of its copies is. The result keeps the input's rows (each
        copy its own). With a preset, the preset's algorithm runs on the welded mesh.

    Returns
    -------
    (N, 3) ndarray of the input's float dtype: a new array.

    Raises
    ------
    TypeError
        A wrong dtype (positions must be float32/float64, faces int32/int64/uint32/uint64, in
        either byte order), or an option of the wrong Python type: integers take ints (or NumPy
        integers), numbers take ints or floats (or NumPy numbers), never bools or strings;
        ``volume_constraint`` takes True or False (or a NumPy bool) only.
    ValueError
        A wrong shape, NaN or inf, an empty mesh, an unknown option or one the preset lacks, a
        value out of range (NaN never is in range; an int beyond 64 bits is refused), or a
        result that would overflow the dtype.
    IndexError
        A face or pinned index outside ``[0, N)``.
    KeyboardInterrupt
        Ctrl-C (or any signal whose handler raises) stops the work between two steps, or two
        iterations of the implicit solve, within a few milliseconds.
"""


class Options(TypedDict, total=False):
    """The keywords every smoothing function takes (each function's own are in its
    ``...Options``). A keyword left out, or None, is the function's default."""

    iterations: Optional[int]
    pinned: Optional[Any]
    weld: bool


class LaplacianFamilyOptions(Options, total=False):
    """The keywords of the Laplacian family (:func:`laplacian`, :func:`taubin`, :func:`hc`,
    :func:`implicit`): the operator's weights, the boundary's rule and the preset."""

    weights: Optional[str]
    boundary: Optional[str]
    preset: Optional[str]


def _signature(options: type) -> inspect.Signature:
    """A smoothing function's signature, as ``help()``, the command line and the API docs read
    it: the mesh, then each keyword of ``options`` (a TypedDict), None by default (the
    function's own default), or False for a flag that takes no None (``weld``)."""
    mesh = [
        inspect.Parameter("vertices", inspect.Parameter.POSITIONAL_OR_KEYWORD, annotation=Any),
        inspect.Parameter("faces", inspect.Parameter.POSITIONAL_OR_KEYWORD, default=None, annotation=Any),
    ]
    keywords = [
        inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, default=False if hint is bool else None,
                          annotation=hint)
        for name, hint in get_type_hints(options).items()
    ]
    return inspect.Signature(mesh + keywords, return_annotation=Positions)


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


class LaplacianOptions(LaplacianFamilyOptions, total=False):
    """The keywords of :func:`laplacian`, for type checkers (see its docstring)."""

    lamb: Optional[float]
    volume_constraint: Optional[bool]


def laplacian(vertices: Any, faces: Any = None, **options: Unpack[LaplacianOptions]) -> Positions:
    """Explicit Laplacian smoothing: ``x <- x + lamb * (A x - x)``, repeated.

    ``A x`` is the weighted mean of each vertex's neighbours.

    Parameters
    ----------
    iterations : int, default 10 (pymeshlab preset: 3)
        Number of steps (>= 0).
    lamb : float in [0, 1], default 0.5 (paper preset: 1.0)
        Step size; 1 moves each vertex all the way to its neighbours' mean. Not used by the
        pymeshlab preset, whose update is ``(x + S) / (C + 1)``.
    weights : "uniform", "cotangent" or "distance", default "uniform" (pymeshlab: "cotangent")
        Neighbour weights. Cotangent and inverse-distance weights are recomputed from the
        current positions at each step (trimesh's inverse-distance weights are computed once,
        as trimesh does).
    boundary : "fixed", "free" or "slide", default "fixed" (pymeshlab: "slide")
        What vertices on a boundary edge (an edge with one face) do: stay put, average like
        interior vertices, or average only with their boundary neighbours (sliding along the
        boundary; pymeshlab's ``boundary=True``).
    volume_constraint : bool, default False (trimesh preset: True)
        After each step, rescale about the initial centre of mass to restore the enclosed
        volume. Skipped on meshes that enclose no volume.
    """
    return _call(laplacian, vertices, faces, options)


class TaubinOptions(LaplacianFamilyOptions, total=False):
    """The keywords of :func:`taubin`, for type checkers (see its docstring)."""

    lamb: Optional[float]
    mu: Optional[float]


def taubin(vertices: Any, faces: Any = None, **options: Unpack[TaubinOptions]) -> Positions:
    """Taubin (lambda/mu) smoothing, which removes noise without shrinking the mesh.

    Each iteration is a shrink step ``x += lamb (A x - x)`` then an inflate step
    ``x += mu (A x - x)`` (so 10 iterations are 20 passes, as in pymeshlab and open3d). With
    ``preset="trimesh"``, ``iterations`` counts passes instead: even passes shrink, odd passes
    inflate, and ``mu`` defaults to -0.5 (trimesh's ``nu=0.5``).

    Parameters
    ----------
    iterations : int, default 10
    lamb : float in [0, 1], default 0.5
    mu : float in [-1, 0], default -0.53 (trimesh preset: -0.5)
        Inflate factor; pymeshlab stores both factors as float32, and so does its preset.
    weights, boundary
        As in :func:`laplacian` (pymeshlab and trimesh presets: uniform only).
    """
    return _call(taubin, vertices, faces, options)


class HcOptions(LaplacianFamilyOptions, total=False):
    """The keywords of :func:`hc`, for type checkers (see its docstring)."""

    alpha: Optional[float]
    beta: Optional[float]


def hc(vertices: Any, faces: Any = None, **options: Unpack[HcOptions]) -> Positions:
    """HC smoothing (Vollmer, Mencl and Mueller 1999): Laplacian smoothing that pushes each
    vertex back toward its original and previous positions, so the mesh does not shrink.

    Per iteration, with ``o`` the original positions::

        p = A x
        b = p - (alpha o + (1 - alpha) x)
        x <- p - (beta b + (1 - beta) A b)

    ``preset="pymeshlab"`` reproduces ``apply_coord_hc_laplacian_smoothing`` instead (no alpha,
    beta fixed at 0.5, ``x <- q - beta (q - x) + (1 - beta) A (q - x)`` with ``q = A x``; one
    iteration is one call, and the default is 1).

    Parameters
    ----------
    iterations : int, default 10 (pymeshlab preset: 1)
    alpha : float in [0, 1], default 0.1
        Pull toward the original positions.
    beta : float in [0, 1], default 0.5
        How much of the correction is the vertex's own versus its neighbours' mean.
    weights, boundary
        As in :func:`laplacian`.
    """
    return _call(hc, vertices, faces, options)


class ImplicitOptions(LaplacianFamilyOptions, total=False):
    """The keywords of :func:`implicit`, for type checkers (see its docstring)."""

    step: Optional[float]
    tol: Optional[float]
    max_iter: Optional[int]
    volume_constraint: Optional[bool]


def implicit(vertices: Any, faces: Any = None, **options: Unpack[ImplicitOptions]) -> Positions:
    """Implicit (backward Euler) Laplacian smoothing: solves ``((1 + step) I - step A) x' = x``.

    Stable for any step size, so one large step replaces many explicit ones (Desbrun et al.
    1999). The sparse system is solved in parallel by Jacobi-preconditioned BiCGSTAB to a
    relative residual ``tol``; the operator is rebuilt from the current positions at each
    iteration when the weights depend on them.

    Parameters
    ----------
    step : float >= 0, default 1.0 (trimesh preset: 0.5, its ``lamb``)
        Time step, in units of one explicit step with ``lamb=1``.
    iterations : int, default 1 (trimesh preset: 10)
    tol : float in (0, 1), default 1e-10
        Relative residual at which the solve stops.
    max_iter : int, default 10000
        Solver iterations before :class:`toonmesh.ConvergenceError` is raised.
    weights : "uniform", "cotangent" or "distance", default "uniform"
    boundary : "fixed" or "free", default "fixed"
    volume_constraint : bool, default False (trimesh preset: True)
    """
    return _call(implicit, vertices, faces, options)


_NORMAL_FILTERING = """
    Both filters work in two stages. First the face normals are filtered ``iterations`` times:
    each face's normal becomes the normalised sum, over the faces sharing a vertex with it
    (itself included), of ``area * exp(-d^2 / (2 sigma_s^2)) * exp(-r^2 / (2 sigma_r^2)) *
    normal``, with ``d`` the distance between face centroids and ``r`` the distance between
    the two faces' (guidance) normals; ``guided`` also compares the faces' own normals, with
    0.3 of that weight at the measured width (which they keep even where ``sigma_r`` is given).
    Faces across a crease have distant normals, so they do not average, and the crease stays
    sharp. Then the vertices are moved ``vertex_iterations``
    times to fit the filtered normals (Sun et al. 2007: each vertex moves by the mean of its
    offsets to its faces' planes); a move that would turn a face against its filtered normal
    is undone, so no face flips.

    Parameters
    ----------
    iterations : int >= 0, default 20
        Passes of normal filtering: more removes stronger noise, at a cost linear in the count.
    vertex_iterations : int >= 0, default 20
        Vertex-fitting steps after the normals are filtered (0 returns the input unchanged).
    sigma_s : float > 0, default 1.0
        Width of the spatial kernel, in mean edge lengths of the input mesh (so the default
        works at any scale and resolution).
    sigma_r : float > 0, optional
        Width of the range kernel, a distance between unit normals (``2 sin(angle / 2)``: 0.35
        is about 20 degrees). By default it is measured from the mesh: 0.35 times the 90th
        percentile, over pairs of faces sharing an edge, of the distance between their normals
        (which on a noisy part is the noise, creases being a minority of the pairs), clamped to
        [0.05, 0.6]. Smaller
        keeps more detail (and noise); larger smooths more (and rounds weaker creases).
    pinned : 1-D array of vertex indices, or (N,) bool mask, optional
        Vertices that must not move; they come back bit for bit.
    weld : bool, default False
        Filter the welded mesh (vertices at exactly the same position are one vertex), as in
        the Laplacian smoothers: seams of a textured or flat-shaded mesh neither open nor count
        as boundaries.

    Returns
    -------
    (N, 3) ndarray of the input's float dtype (float32 or float64): a new array, in the
    input's units. Vertices no face uses, and pinned vertices, are returned exactly.

    Raises
    ------
    TypeError
        A wrong dtype or an option of the wrong Python type (counts take ints, widths numbers,
        ``weld`` a bool).
    ValueError
        A wrong shape, NaN or inf, an empty mesh, or a value out of range.
    IndexError
        A face or pinned index outside ``[0, N)``.
    KeyboardInterrupt
        Ctrl-C stops the work between two passes.

    Boundaries, degenerate and non-manifold faces are allowed: a face with no area has no
    normal and no weight, and its vertices fit their other faces. The work runs in parallel
    outside the GIL and gives the same bits for any thread count.
"""


class NormalFilterOptions(Options, total=False):
    """The keywords of the normal filters (:func:`bilateral` and :func:`guided`)."""

    vertex_iterations: Optional[int]
    sigma_s: Optional[float]
    sigma_r: Optional[float]


def bilateral(vertices: Any, faces: Any = None, **options: Unpack[NormalFilterOptions]) -> Positions:
    """Feature-preserving smoothing by bilateral normal filtering (Zheng et al. 2011).

    Removes noise from flat and smoothly curved regions while keeping creases sharp: the range
    weights compare each face's normal with its neighbours' own normals. Fast, and good at
    light noise; under heavy noise the noisy normals themselves blur the creases, where
    :func:`guided` does better.
    """
    return _call(bilateral, vertices, faces, options)


def guided(vertices: Any, faces: Any = None, **options: Unpack[NormalFilterOptions]) -> Positions:
    """Feature-preserving smoothing by guided normal filtering (Zhang et al. 2015).

    As :func:`bilateral`, but the range weights compare guidance normals: at every pass, each
    face's guidance is the mean normal of the most consistent patch (a face with its vertex
    ring) that contains it, so a face next to a crease is guided by the side it lies on even
    where the noise is as strong as the crease; the faces' own normals weigh in too, so that
    features a few faces wide, where every patch crosses a crease, keep their sides apart.
    Better than :func:`bilateral` at medium and heavy noise, at about twice its cost.
    """
    return _call(guided, vertices, faces, options)


# each function's keywords, as callers see them (signature), and the documentation of those
# it shares with its family
for _f, _options, _shared in (
    (laplacian, LaplacianOptions, _COMMON),
    (taubin, TaubinOptions, _COMMON),
    (hc, HcOptions, _COMMON),
    (implicit, ImplicitOptions, _COMMON),
    (bilateral, NormalFilterOptions, _NORMAL_FILTERING),
    (guided, NormalFilterOptions, _NORMAL_FILTERING),
):
    _f.__signature__ = _signature(_options)  # type: ignore[union-attr]
    _f.__doc__ = (_f.__doc__ or "") + _shared
del _f, _options, _shared
