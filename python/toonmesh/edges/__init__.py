"""Outlines: feature edges and silhouettes found on the mesh, Sobel edges found in images.

Mesh space (Kang, Kim and Yoon): boundary, crease and non-manifold edges are found once per mesh
(:func:`feature_edges`, :class:`EdgeIndex`), silhouettes once per view (:func:`silhouette`,
:meth:`EdgeIndex.silhouette`). Image space (Borquez and Yepez): :func:`sobel`, :func:`sobel_h`,
:func:`sobel_v` give the numbers of ``skimage.filters`` (or OpenCV's, on request), and
:func:`detect_edges` applies the paper's per-buffer thresholds to normal and depth buffers.

Rules shared by every mesh-space function:

- An *edge* is an unordered vertex pair used by at least one face; it is reported once, smaller
  index first, and every edge array is sorted lexicographically (by first, then second index).
  Edge arrays are (K, 2) int64.
- An edge's *face-edges* are the sides of faces lying on it. Boundary: exactly one; manifold:
  two; non-manifold: three or more. A face that repeats an index, like (a, a, b), uses a-b twice
  and has no self-edge a-a.
- A face is *degenerate* when it repeats an index or its area is at most 1e-12 times its
  longest edge squared (zero-area and collinear faces). It has no normal, so an edge next to it
  is never a crease and never a silhouette; it still counts for boundary and non-manifold edges.
  Degenerate faces are listed in ``FeatureEdges.degenerate_faces``. (trimesh gives such faces a
  zero normal and a 90 degree angle to every neighbour, which creates creases at random.)
- Face normals follow the right-hand rule, (b - a) x (c - a), and are computed in float64, from
  rescaled edges where the face is too large or too small for the direct formula, so every
  rule holds for coordinates from subnormal up to about 1e307.
- Arguments: arrays in any memory order and either byte order; ``crease_angle`` (None: the
  core's default) and the thresholds are numbers (not bools, not strings), ``weld`` is True or
  False, ``eye`` and ``direction`` are three numbers. Anything else raises TypeError, ValueError or IndexError
  whose message starts with the argument's name.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import Any, List, NamedTuple, Optional, Tuple

import numpy as np

from toonmesh import _core
from toonmesh.arguments._input import _as_array, mesh_arrays

__all__ = [
    "Curvature",
    "EdgeDetection",
    "EdgeIndex",
    "FeatureEdges",
    "chains",
    "contours",
    "curvature",
    "detect_edges",
    "feature_edges",
    "intersection_lines",
    "intersections",
    "segments",
    "silhouette",
    "sobel",
    "sobel_h",
    "sobel_v",
    "suggestive_contours",
]


@dataclass(frozen=True)
class FeatureEdges:
    """View-independent outline edges of a mesh. All edge arrays are (K, 2) int64, smaller index
    first, sorted lexicographically.

    Attributes:
        boundary: edges with exactly one face-edge.
        crease: manifold edges whose two faces (both with a normal) meet at a dihedral angle
            above ``crease_angle``.
        crease_angles: (K,) float64, each crease's angle between the two face normals in
            degrees, in (crease_angle, 180]; computed as atan2(|n1 x n2|, n1 . n2), which stays
            accurate near 0 and 180 degrees.
        crease_convex: (K,) bool, True for a convex crease (a ridge), False for a concave one (a
            valley). With faces 1 and 2 and face 1 walking the edge from a to b, convex means
            (n1 x n2) . (b - a) >= 0. Meaningful when the two faces are consistently oriented.
        nonmanifold: edges with three or more face-edges.
        degenerate_faces: (D,) int64, faces without a normal (see the module rules).
        crease_angle: the threshold used, in degrees.
    """

    boundary: np.ndarray
    crease: np.ndarray
    crease_angles: np.ndarray
    crease_convex: np.ndarray
    nonmanifold: np.ndarray
    degenerate_faces: np.ndarray
    crease_angle: float

    @property
    def ridge(self) -> np.ndarray:
        """Convex creases, (K, 2) int64."""
        return self.crease[self.crease_convex]

    @property
    def valley(self) -> np.ndarray:
        """Concave creases, (K, 2) int64."""
        return self.crease[~self.crease_convex]

    @property
    def outlines(self) -> np.ndarray:
        """Boundary, crease and non-manifold edges together, (K, 2) int64, sorted, unique."""
        return _union(self.boundary, self.crease, self.nonmanifold)


def _crease_angle(crease_angle: Optional[float]) -> Any:
    """``crease_angle``, None being the core's default (the renderer's outlines use it too)."""
    return _core.DEFAULT_CREASE_ANGLE if crease_angle is None else crease_angle


def _features(raw: Tuple[Any, ...], crease_angle: float) -> FeatureEdges:
    boundary, crease, angles, convex, nonmanifold, degenerate = raw
    return FeatureEdges(boundary, crease, angles, convex, nonmanifold, degenerate, float(crease_angle))


#: Kinds of outline lines, by their code in the core (``edges::outlines::LineKind``).
_LINE_KINDS = _core.LINE_KINDS


def _edge_keys(edges: np.ndarray, n: int) -> np.ndarray:
    """One int64 per edge, lo * n + hi: sorts as the (lo, hi) rows do, and far faster than
    comparing rows (``np.unique(axis=0)`` took about a second on a million edges)."""
    e = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    return np.minimum(e[:, 0], e[:, 1]) * n + np.maximum(e[:, 0], e[:, 1])


def _union_keys(n: int, *keys: np.ndarray) -> np.ndarray:
    """Edges of the union of sorted-or-not key arrays, (K, 2) int64, sorted, each once."""
    k = np.concatenate(keys)
    # Stable sort is a merge sort: it merges already-sorted runs (cached static edges, a view's
    # silhouettes) in linear time.
    k.sort(kind="stable")
    if len(k):
        k = k[np.concatenate(([True], k[1:] != k[:-1]))]
    return np.stack([k // n, k % n], axis=1) if len(k) else np.zeros((0, 2), dtype=np.int64)


def _union(*parts: np.ndarray) -> np.ndarray:
    edges = [np.asarray(p, dtype=np.int64).reshape(-1, 2) for p in parts]
    n = 1 + max((int(e.max()) for e in edges if e.size), default=0)
    if n > 2**31:  # keys would overflow int64
        stacked = np.concatenate([np.sort(e, axis=1) for e in edges])
        return np.unique(stacked, axis=0) if len(stacked) else np.zeros((0, 2), dtype=np.int64)
    return _union_keys(n, *(_edge_keys(e, n) for e in edges))


def feature_edges(
    vertices: Any, faces: Any = None, crease_angle: Optional[float] = None, *, weld: bool = False
) -> FeatureEdges:
    """Boundary, crease and non-manifold edges of a triangle mesh.

    Args:
        vertices: (N, 3) float32 or float64 positions, or a ``trimesh.Trimesh`` (then leave
            ``faces`` out).
        faces: (M, 3) int32, int64, uint32 or uint64 vertex indices.
        crease_angle: threshold in degrees, in [0, 180]; an edge is a crease when the angle
            between its two face normals is strictly greater. None (the default): the core's
            default, 30, as the renderer's outlines.
        weld: True to merge vertices at exactly the same position first (UV seams and split
            normals store one point twice, which otherwise shows up as boundary edges). Edges
            then refer to the smallest index of each group of coincident vertices.

    Returns:
        :class:`FeatureEdges`. See the module docstring for the rules on order, face counts and
        degenerate faces.

    Raises:
        TypeError, ValueError, IndexError: bad input, naming the argument.
    """
    V, F = mesh_arrays(vertices, faces)
    angle = _crease_angle(crease_angle)
    return _features(_core._feature_edges((V, F), angle, weld), angle)


@dataclass(frozen=True)
class Curvature:
    """Principal curvatures per vertex and their derivatives (see :func:`curvature`). Units:
    curvatures in 1/length of the mesh's units, derivatives in 1/length^2.

    Attributes:
        k1, k2: (N,) float64, the principal curvatures, ``k1 >= k2``; positive where the surface
            bends away from its outward normal (a sphere of radius r: +1/r).
        d1, d2: (N, 3) float64 unit principal directions, tangent to the surface, with
            ``cross(d1, d2) == normals``.
        normals: (N, 3) float64 unit vertex normals the estimate used (weighted as Max 1999).
        derivatives: (N, 4) float64, the derivative of the second fundamental form in the
            (d1, d2) frame: C111, C112, C122, C222 (e.g. C111 = dk1/d(d1)); what suggestive
            contours need.
    """

    k1: np.ndarray
    k2: np.ndarray
    d1: np.ndarray
    d2: np.ndarray
    normals: np.ndarray
    derivatives: np.ndarray

    @property
    def mean(self) -> np.ndarray:
        """(N,) float64 mean curvature, (k1 + k2) / 2."""
        return 0.5 * (self.k1 + self.k2)

    @property
    def gaussian(self) -> np.ndarray:
        """(N,) float64 Gaussian curvature, k1 * k2."""
        return self.k1 * self.k2


def curvature(vertices: Any, faces: Any = None, *, smoothing: float = 0.0) -> Curvature:
    """Principal curvatures, directions and their derivatives at every vertex (Rusinkiewicz
    2004: a second fundamental form fitted per face from the vertex normals' change along its
    edges, averaged per vertex over its faces' Voronoi areas, and the same for its derivative).

    Scale-free: computed in coordinates divided by the mesh's size, so scaling the mesh by s
    scales the curvatures by 1/s and the derivatives by 1/s^2, at any scale or offset. Faces
    without area count for nothing; a vertex with no face of any area gets curvature 0 and some
    tangent frame, so every output is finite. Runs in parallel with the GIL released.

    Args:
        vertices: (N, 3) float32 or float64 positions, or a ``trimesh.Trimesh`` (then leave
            ``faces`` out).
        faces: (M, 3) integer vertex indices, counter-clockwise seen from outside.
        smoothing: measure the curvature at a feature size rather than the one-ring's: the
            width, in mean edge lengths, of a bell (zero beyond 2.5 widths) over which the
            normals, then the curvature tensors are averaged around every vertex before the
            next is fitted from them (as Rusinkiewicz's trimesh2 diffuses them), on the surface
            patch whose normals agree with the vertex's; the derivatives are fitted from the
            smoothed tensors. A scan's
            noise makes the one-ring estimate follow the scanner; 2 to 4 recovers the shape.
            Default 0: the one-ring estimate, the most accurate on a clean mesh.

    Returns:
        :class:`Curvature`, all arrays float64.

    Raises:
        TypeError, ValueError, IndexError: bad input, naming the argument.
    """
    V, F = mesh_arrays(vertices, faces)
    return Curvature(*_core._curvature((V, F), smoothing))


def _polylines(points: np.ndarray, starts: np.ndarray) -> List[np.ndarray]:
    return [points[a:b] for a, b in zip(starts[:-1], starts[1:])]


def contours(
    vertices: Any, faces: Any = None, *, eye: Any = None, direction: Any = None, weld: bool = False
) -> List[np.ndarray]:
    """Smooth contours of one view (Hertzmann and Zorin 2000): the zero set of n . (eye - p)
    (n . -direction for an orthographic view), its vertex values from the area-weighted vertex
    normals (the normals smooth shading uses) interpolated linearly, traced through the faces
    and chained across them. Only the face clusters where it can change sign are visited. Unlike :func:`silhouette` (face edges between front- and back-facing faces), it does
    not follow the triangulation, so it does not zigzag on scanned or noisy surfaces.

    Give exactly one of ``eye`` (3,) (perspective) or ``direction`` (3,) (orthographic), as
    in :func:`silhouette`. Hidden parts are not removed (a rendered frame removes them).

    Args:
        vertices: as in :func:`feature_edges` (a ``trimesh.Trimesh`` works too).
        faces: as in :func:`feature_edges`.
        weld: merge vertices at equal positions first, so that normal or UV seams neither split
            the normals nor cut the lines. Default False.

    Returns:
        A list of (K, 3) float64 polylines in the mesh's coordinates; a closed one repeats its
        first point at the end. Points lie on mesh edges.
    """
    V, F = mesh_arrays(vertices, faces)
    return _polylines(*_core._view_lines("contours", (V, F), eye, direction, weld))


def suggestive_contours(
    vertices: Any,
    faces: Any = None,
    *,
    eye: Any = None,
    direction: Any = None,
    threshold: Optional[float] = None,
    smoothing: Optional[float] = None,
    weld: bool = False,
) -> List[np.ndarray]:
    """Suggestive contours of one view (DeCarlo et al. 2003): where the radial curvature (the
    normal curvature along the view direction projected into the tangent plane, k1 cos^2 +
    k2 sin^2 of its angle to d1) is zero, its derivative along the projected view direction is
    positive, and the surface faces the viewer. They continue contours into the surface and
    draw the inner shape lines artists draw (a neck, a haunch, the inside of a bowl); a convex
    shape has none.

    Args:
        vertices: as in :func:`contours`.
        faces: as in :func:`contours`.
        eye: as in :func:`contours`.
        direction: as in :func:`contours`.
        weld: as in :func:`contours`.
        threshold: the derivative test, D_w kr / |w| > threshold / s^2, with s the mesh's
            feature size (1% of the reciprocal of the 10th percentile of |k|, at most 5% of half
            the bounding box's diagonal, as in the authors' implementation), so it does not
            depend on units; larger keeps only the strongest lines. Default (None) 0.01.
        smoothing: the width the curvature is measured at, in mean edge lengths, as
            :func:`curvature` takes it; the feature size above comes from that curvature.
            Default (None): 2, at most 1% of the bounding-box diagonal. A scan's noise lives
            at the edge length and draws no lines at 2; a coarse mesh (a few thousand
            vertices) keeps the features the cap protects.

    Per view, only faces where kr can change sign in some view are visited (a vertex with
    k1 > 0 and one with k2 <= 0): none on a convex shape.

    Returns:
        A list of (K, 3) float64 polylines, as :func:`contours` returns them; points where a
        line is cut by the derivative test lie inside faces.
    """
    V, F = mesh_arrays(vertices, faces)
    return _polylines(*_core._view_lines("suggestive", (V, F), eye, direction, weld, threshold, smoothing))


def silhouette(
    vertices: Any, faces: Any = None, *, eye: Any = None, direction: Any = None, weld: bool = False
) -> np.ndarray:
    """Silhouette edges for one view: (K, 2) int64, smaller index first, sorted.

    Give exactly one of ``eye`` and ``direction``.

    A face is front-facing when n . V < 0, with V the view vector (face point minus eye, or the
    direction), and back-facing otherwise: a face exactly edge-on (n . V = 0) counts as
    back-facing, as with back-face culling. An edge is a silhouette when its faces include at
    least one front-facing and one back-facing face: for a manifold edge that is the paper's
    (n1 . V)(n2 . V) <= 0 with that tie rule, for a non-manifold edge any such pair. Boundary
    edges (one face) are never silhouettes: they are outlines in every view, see
    :func:`feature_edges`. Edges next to a degenerate face are never silhouettes. An eye exactly
    on a face's plane sees that face edge-on.

    For many views of one mesh, build an :class:`EdgeIndex` once instead.

    Args:
        vertices: as in :func:`feature_edges` (a ``trimesh.Trimesh`` works too).
        faces: as in :func:`feature_edges`.
        eye: (3,) camera position, perspective view. The view vector is taken from the eye to
            each face (not one global direction), so the answer is exact per face.
        direction: (3,) direction the orthographic camera looks in (from the camera into the
            scene); its length does not matter.
        weld: as in :func:`feature_edges`.
    """
    V, F = mesh_arrays(vertices, faces)
    return _core._view_lines("silhouette", (V, F), eye, direction, weld)


class EdgeIndex:
    """Once-per-mesh outline data (edges, face normals, boundaries, creases) that answers
    silhouettes for each new view quickly: the paper's pre-processing / run-time split, for
    turntables and many views.

    Building costs about as much as :func:`feature_edges`; each :meth:`silhouette` is one pass
    over faces and one over edges, run in parallel with the GIL released. The index is
    immutable: one index may serve several threads at once.

    Args:
        vertices: as in :func:`feature_edges` (a ``trimesh.Trimesh`` works too), copied: later
            changes to the caller's arrays do not affect the index.
        faces: as in :func:`feature_edges`, copied too.
        crease_angle: threshold in degrees for :attr:`features` (None, the default: the core's
            default, 30).
        weld: merge coincident vertices first, as in :func:`feature_edges`.

    Attributes:
        features: :class:`FeatureEdges` at ``crease_angle``.
        boundary, crease, nonmanifold: shortcuts into :attr:`features`.
        vertices: (N, 3) float64 positions; face_normals: (M, 3) float64 unit normals (zero for
            degenerate faces).
    """

    def __init__(
        self, vertices: Any, faces: Any = None, *, crease_angle: Optional[float] = None, weld: bool = False
    ) -> None:
        V, F = mesh_arrays(vertices, faces)
        self._index = _core._EdgeIndex((V, F), weld)
        self.features = self.feature_edges(crease_angle)

    @cached_property
    def vertices(self) -> np.ndarray:
        """(N, 3) float64 positions the index was built from (read-only)."""
        v = self._index.vertices()
        v.flags.writeable = False
        return v

    @cached_property
    def face_normals(self) -> np.ndarray:
        """(M, 3) float64 unit face normals, zero for degenerate faces (read-only)."""
        n = self._index.face_normals()
        n.flags.writeable = False
        return n

    @property
    def n_vertices(self) -> int:
        return int(self._index.sizes[0])

    @property
    def n_faces(self) -> int:
        return int(self._index.sizes[1])

    @property
    def n_edges(self) -> int:
        """Number of distinct edges."""
        return int(self._index.sizes[2])

    @property
    def boundary(self) -> np.ndarray:
        return self.features.boundary

    @property
    def crease(self) -> np.ndarray:
        return self.features.crease

    @property
    def nonmanifold(self) -> np.ndarray:
        return self.features.nonmanifold

    def feature_edges(self, crease_angle: Optional[float] = None) -> FeatureEdges:
        """:class:`FeatureEdges` at another threshold, without rebuilding anything.

        Args:
            crease_angle: threshold in degrees; None (default): the core's default, 30.
        """
        angle = _crease_angle(crease_angle)
        return _features(self._index.feature_edges(angle), angle)

    def silhouette(self, *, eye: Any = None, direction: Any = None) -> np.ndarray:
        """Silhouette edges for one view; rules as in :func:`silhouette`.

        Args:
            eye: the eye's position for a perspective view, as in :func:`silhouette`.
            direction: the view direction for an orthographic view, as in :func:`silhouette`.

        Returns:
            (K, 2) int64 edges.
        """
        return self._index.view_lines("silhouette", eye, direction)

    def outlines(self, *, eye: Any = None, direction: Any = None, kinds: bool = False) -> Any:
        """Silhouettes of this view plus boundary, crease and non-manifold edges: everything a
        mesh-space outline pass draws (the renderer's own outline set).

        Args:
            eye: the eye's position for a perspective view, as in :func:`silhouette`.
            direction: the view direction for an orthographic view, as in :func:`silhouette`.
            kinds: also return each edge's kind; default False.

        Returns:
            (K, 2) int64 edges, sorted, each edge once; with ``kinds=True``, also each edge's kind
            as (K,) str: the first of "silhouette", "boundary", "nonmanifold", "ridge", "valley"
            that it is.
        """
        edges, codes = self._index.outlines(self.features.crease_angle, eye, direction, kinds)
        if codes is not None:
            return edges, np.asarray(_LINE_KINDS)[codes]
        return edges

    def segments(self, edges: Any) -> np.ndarray:
        """Edge end points of this mesh; see :func:`segments`.

        Args:
            edges: (K, 2) vertex indices.

        Returns:
            (K, 2, 3) float64 end points.
        """
        return segments(self.vertices, edges)

    def contours(self, *, eye: Any = None, direction: Any = None) -> List[np.ndarray]:
        """Smooth contours of one view, as :func:`contours` finds them (the index's ``weld``),
        without redoing the per-mesh work.

        Args:
            eye: the eye's position for a perspective view, as in :func:`contours`.
            direction: the view direction for an orthographic view, as in :func:`contours`.

        Returns:
            A list of (K, 3) float64 polylines.
        """
        return _polylines(*self._index.view_lines("contours", eye, direction))

    def suggestive_contours(
        self,
        *,
        eye: Any = None,
        direction: Any = None,
        threshold: Optional[float] = None,
        smoothing: Optional[float] = None,
    ) -> List[np.ndarray]:
        """Suggestive contours of one view, as :func:`suggestive_contours` finds them; the
        mesh's curvature is computed on the first call and kept for the next views with the same
        ``smoothing``.

        Args:
            eye: as in :func:`suggestive_contours`.
            direction: as in :func:`suggestive_contours`.
            threshold: as in :func:`suggestive_contours`.
            smoothing: as in :func:`suggestive_contours`.

        Returns:
            A list of (K, 3) float64 polylines.
        """
        return _polylines(*self._index.view_lines("suggestive", eye, direction, threshold, smoothing))

    def __repr__(self) -> str:
        return f"EdgeIndex({self.n_vertices} vertices, {self.n_faces} faces, {self.n_edges} edges)"


def _edge_array(edges: Any) -> np.ndarray:
    arr = _as_array("edges", edges)
    if arr.size == 0:
        return np.zeros((0, 2), dtype=np.int64)
    if arr.dtype.kind not in "iu":
        raise TypeError(f"edges: expected integer vertex indices, got dtype {arr.dtype}")
    if arr.ndim != 2 or arr.shape[1] != 2:
        raise ValueError(f"edges: expected shape (K, 2), got {arr.shape}")
    if arr.dtype.kind == "u" and arr.size and arr.max() > np.iinfo(np.int64).max:
        raise IndexError("edges: vertex index too large")
    return np.ascontiguousarray(arr, dtype=np.int64)


def chains(edges: Any) -> List[np.ndarray]:
    """Edges chained into polylines: a list of int64 vertex-index arrays.

    A chain runs between vertices whose degree in ``edges`` is not 2 (ends and junctions),
    through vertices of degree 2. Chains start from those vertices in ascending index order,
    taking their edges in the given order; the rest are closed loops, each started at the first
    unused edge (in the given order) from its first vertex and closed by repeating that vertex
    at the end. Every edge is used exactly once, so ``sum(len(c) - 1 for c in chains(e))`` equals
    ``len(e)``.

    Args:
        edges: (K, 2) integer vertex pairs, e.g. from :func:`silhouette` or :class:`FeatureEdges`.
    """
    flat, offsets = _core._chains(_edge_array(edges))
    return [flat[offsets[i] : offsets[i + 1]] for i in range(len(offsets) - 1)]


def segments(vertices: Any, edges: Any) -> np.ndarray:
    """End points of each edge, (K, 2, 3) in the dtype of ``vertices`` (float32 or float64),
    ready for ``matplotlib``'s ``Line3DCollection`` or for export.

    Args:
        vertices: (N, 3) float32 or float64 positions, finite, as everywhere else; or a
            ``trimesh.Trimesh``.
        edges: (K, 2) integer vertex pairs.

    Raises:
        TypeError, ValueError, IndexError: bad input, naming the argument.
    """
    if hasattr(vertices, "vertices") and hasattr(vertices, "faces"):
        vertices = vertices.vertices
    V, E = _as_array("vertices", vertices), _edge_array(edges)
    n = _core._vertex_count(V)
    outside = np.flatnonzero(((E < 0) | (E >= n)).any(axis=1))
    if outside.size:
        k = outside[0]
        raise IndexError(f"edges: edge {k} ({E[k, 0]}, {E[k, 1]}) refers to a vertex outside [0, {n})")
    return np.asarray(V, dtype=V.dtype.newbyteorder("="))[E]  # native byte order, as the core reads it


def _mesh_list(meshes: Any) -> List[Tuple[np.ndarray, np.ndarray]]:
    """Each of ``meshes`` as (V, F) (see :func:`intersections`), an error naming its place."""
    if (hasattr(meshes, "vertices") and hasattr(meshes, "faces")) or isinstance(meshes, (str, bytes, np.ndarray)) \
            or not hasattr(meshes, "__iter__"):
        raise TypeError("meshes: expected a list of meshes, each (vertices, faces) or a trimesh.Trimesh, "
                        f"got {type(meshes).__name__}")
    out = []
    for i, mesh in enumerate(meshes):
        try:
            pair = isinstance(mesh, (tuple, list)) and len(mesh) == 2
            out.append(mesh_arrays(*mesh) if pair else mesh_arrays(mesh, None))
        except (TypeError, ValueError) as exc:
            raise type(exc)(f"meshes[{i}]: {exc}") from None
    return out


def intersections(meshes: Any, *, self_intersections: bool = False) -> np.ndarray:
    """Intersection lines: where the surfaces of different meshes cross (a pin through a plate,
    two crossing pipes), as one segment per pair of crossing triangles, found through a
    bounding-volume hierarchy per mesh, in parallel with the GIL released.

    The rule for two triangles: the overlap of where each crosses the other's plane, computed in
    float64. Each end point is where an edge of one triangle crosses the other's plane, computed
    the same way for both triangles on that edge, so neighbouring segments share their ends
    exactly (:func:`intersection_lines` joins them). Coplanar triangles give no segment, nor
    degenerate ones, nor triangles touching only at a point; a corner within rounding of the
    other plane (relative to the triangles' size and coordinates, so at any scale or offset) lies
    on it and counts as on the side its normal points to, so an edge lying in the other surface
    is given once and two outward-facing meshes that only rest on each other give nothing.
    Triangles at shared positions (two meshes sharing a seam) only touch there.

    Args:
        meshes: a list of meshes in one frame, each ``(vertices, faces)`` (as
            :func:`feature_edges` takes them) or a ``trimesh.Trimesh``.
        self_intersections: also each mesh's crossings with itself, between faces that share
            no vertex. Default False.

    Returns:
        (N, 2, 3) float64 segment end points, in the meshes' coordinates and units: for each
        pair of meshes i < j in order, its segments sorted by the face of mesh i, then of mesh
        j; then, with ``self_intersections``, each mesh's own. Fewer than two meshes without
        ``self_intersections``: an empty (0, 2, 3) array (the meshes are still checked).

    Raises:
        TypeError, ValueError, IndexError: bad input, naming the mesh (``meshes[2].faces: ...``).
    """
    return _core._intersections(_mesh_list(meshes), self_intersections, False)


def intersection_lines(meshes: Any, *, self_intersections: bool = False) -> List[np.ndarray]:
    """The segments of :func:`intersections` joined into polylines where their ends meet, as
    :func:`chains` joins edges. A closed one (a pin through a plate gives one per face of the
    plate it crosses) repeats its first point at the end.

    Args:
        meshes: as in :func:`intersections`.
        self_intersections: as in :func:`intersections`.

    Returns:
        A list of (K, 3) float64 polylines in the meshes' coordinates.
    """
    return _polylines(*_core._intersection_lines(_mesh_list(meshes), self_intersections))


# ---------------------------------------------------------------------------------------------
# Sobel

def _float_image(image: Any, convention: Any) -> np.ndarray:
    """The float image the filter runs on, following the convention's dtype rules (the core
    checks ``convention`` itself)."""
    arr = _as_array("image", image)
    if arr.ndim not in (2, 3):
        raise ValueError(f"image: expected a 2-D (H, W) or 3-D (H, W, C) image, got shape {arr.shape}")
    if arr.size == 0:
        raise ValueError(f"image: must not be empty, got shape {arr.shape}")
    kind = arr.dtype.kind
    if kind == "f":
        if arr.dtype == np.float16:
            return arr.astype(np.float32)
        if arr.dtype in (np.float32, np.float64):
            return arr
        return arr.astype(np.float64)
    if kind == "b":
        return arr.astype(np.float64)
    if kind in "iu":
        if isinstance(convention, str) and convention == "opencv":
            return arr.astype(np.float64)
        # skimage's img_as_float: integers scaled to [0, 1] (signed: [-1, 1]) in float64
        scaled = np.multiply(arr, 1.0 / np.iinfo(arr.dtype).max, dtype=np.float64)
        return np.maximum(scaled, -1.0, out=scaled) if kind == "i" else scaled
    raise TypeError(f"image: unsupported dtype {arr.dtype} (expected a real number or bool image)")


def _erode(mask: Any, shape: Tuple[int, ...]) -> np.ndarray:
    m = _as_array("mask", mask)
    if m.dtype.kind not in "biuf":
        raise TypeError(f"mask: expected a boolean (or numeric) array, got dtype {m.dtype}")
    if m.shape != shape[:2]:
        raise ValueError(f"mask: expected shape {shape[:2]}, got {m.shape}")
    m = m.astype(bool)
    # Erosion by a full 3x3 footprint with pixels outside the image counting as False.
    padded = np.zeros((m.shape[0] + 2, m.shape[1] + 2), dtype=bool)
    padded[1:-1, 1:-1] = m
    out = np.ones_like(m)
    for dr in range(3):
        for dc in range(3):
            out &= padded[dr : dr + m.shape[0], dc : dc + m.shape[1]]
    return out


def _sobel(image: Any, mask: Any, output: str, convention: str) -> np.ndarray:
    img = _float_image(image, convention)
    if img.ndim == 2:
        result = _core._sobel(np.ascontiguousarray(img), output, convention)
    else:
        result = np.stack(
            [_core._sobel(np.ascontiguousarray(img[..., c]), output, convention) for c in range(img.shape[2])],
            axis=-1,
        )
    if mask is not None:
        eroded = _erode(mask, img.shape)
        result *= eroded[..., None] if result.ndim == 3 else eroded
    return result


_SOBEL_DOC = """

    Args:
        image: (H, W) image, or (H, W, C) filtered per channel (the last axis is channels; note
            that ``skimage.filters`` would instead treat a 3-D array as a volume). Any real or
            bool dtype, any memory order; never modified.
        mask: optional (H, W) array, True where the result is kept. As in ``skimage.filters``
            it is first eroded by one pixel (a full 3x3 footprint, pixels outside the image
            count as False), then the result is zeroed where the eroded mask is False.
        convention: ``"skimage"`` (default) gives the numbers of ``skimage.filters``: kernels
            [1, 0, -1] x [1, 2, 1] / 4, border 'reflect' (d c b a | a b c d). float32 in gives
            float32 out, float16 gives float32, other floats float64; integer images are scaled
            to [0, 1] (signed: [-1, 1]) and bool to {0, 1}, as skimage's ``img_as_float``, and give
            float64. ``"opencv"`` gives the numbers of ``cv2.Sobel(img, ddepth, dx, dy, ksize=3)``
            with its default border BORDER_REFLECT_101 (d c b | a b c d): unnormalised (a unit
            step gives 4), integers kept in their own units (as float64).

    Returns:
        An array of the image's shape in the float dtype above. Each output row is computed in
        one pass over the three input rows it needs, in parallel over row bands, with the GIL
        released.
    """


def sobel(image: Any, mask: Any = None, *, convention: str = "skimage") -> np.ndarray:
    return _sobel(image, mask, "magnitude", convention)


def sobel_h(image: Any, mask: Any = None, *, convention: str = "skimage") -> np.ndarray:
    return _sobel(image, mask, "h", convention)


def sobel_v(image: Any, mask: Any = None, *, convention: str = "skimage") -> np.ndarray:
    return _sobel(image, mask, "v", convention)


sobel.__doc__ = (
    """Sobel gradient magnitude.

    ``"skimage"``: sqrt((h^2 + v^2) / 2), as ``skimage.filters.sobel`` in 2-D (a unit step gives
    0.7071). ``"opencv"``: sqrt(h^2 + v^2), as ``cv2.magnitude`` of the two ``cv2.Sobel`` results
    (a unit step gives 4). h and v are :func:`sobel_h` and :func:`sobel_v`."""
    + _SOBEL_DOC
)
sobel_h.__doc__ = (
    """Sobel derivative along axis 0 (rows): the row below minus the row above, smoothed along the
    row, as ``skimage.filters.sobel_h`` (``"opencv"``: ``cv2.Sobel(img, ddepth, 0, 1)``)."""
    + _SOBEL_DOC
)
sobel_v.__doc__ = (
    """Sobel derivative along axis 1 (columns): the right neighbour minus the left, smoothed along
    the column, as ``skimage.filters.sobel_v`` (``"opencv"``: ``cv2.Sobel(img, ddepth, 1, 0)``)."""
    + _SOBEL_DOC
)


class EdgeDetection(NamedTuple):
    """Result of :func:`detect_edges`: ``mask`` (H, W) bool, and each buffer's gradient map
    max(|Gx|, |Gy|) (H, W), or None for a buffer that was not given."""

    mask: np.ndarray
    normal_gradient: Optional[np.ndarray]
    depth_gradient: Optional[np.ndarray]


def _buffer(name: str, value: Any, channels_axis: bool) -> np.ndarray:
    arr = _as_array(name, value)
    if arr.dtype.kind not in "fiub":
        raise TypeError(f"{name}: unsupported dtype {arr.dtype}")
    if arr.dtype not in (np.float32, np.float64):
        arr = arr.astype(np.float64)
    if channels_axis:
        if arr.ndim == 2:
            arr = arr[..., None]
        if arr.ndim != 3:
            raise ValueError(f"{name}: expected shape (H, W, C) or (H, W), got {arr.shape}")
    elif arr.ndim == 2:
        arr = arr[..., None]
    else:
        raise ValueError(f"{name}: expected shape (H, W), got {arr.shape}")
    if arr.size == 0:
        raise ValueError(f"{name}: must not be empty, got shape {arr.shape}")
    return np.ascontiguousarray(arr)


def detect_edges(
    normal: Any = None,
    depth: Any = None,
    *,
    normal_threshold: float = 1.0,
    depth_threshold: float = 0.1,
) -> EdgeDetection:
    """Image-space outlines by the rule of Borquez and Yepez: 3x3 Sobel on the normal buffer and
    on the depth buffer, an edge where max(|Gx|, |Gy|) exceeds that buffer's own threshold; the
    two results are combined with a logical or.

    Gx and Gy use the paper's unnormalised kernels Sx = [[1, 0, -1], [2, 0, -2], [1, 0, -1]] and
    Sy = Sx transposed (a unit step gives 4, so a threshold t finds steps larger than t / 4
    between neighbouring pixels), with the 'reflect' border, so the image border alone never
    makes an edge. For the normal buffer the gradient is the largest over its channels.

    Background: a pixel is background when its depth (or any normal channel) is not finite
    (inf or NaN). A pixel whose 3x3 neighbourhood mixes background and object gets an infinite
    gradient, so the object's outline against the background is always an edge; a pixel deep in
    the background gets 0. Use inf or NaN for background depth, not a large finite far value,
    or the outline's strength will depend on that value.

    Args:
        normal: (H, W, 3) normal buffer (any number of channels; (H, W) is one channel), or
            None to use depth alone.
        depth: (H, W) depth buffer, or None to use normals alone.
        normal_threshold: threshold for the normal buffer (unit normals; default 1.0, about a
            15 degree turn between neighbouring pixels). A finite number >= 0.
        depth_threshold: threshold for the depth buffer, in depth units times 4 (default 0.1,
            meant for a linear depth of order 1: scale it with your scene). A finite number >= 0.

    Returns:
        :class:`EdgeDetection` ``(mask, normal_gradient, depth_gradient)``; gradients are
        float32 when the buffer is float32, float64 otherwise.
    """
    if normal is None and depth is None:
        raise ValueError("normal, depth: give a normal buffer, a depth buffer, or both")
    gn = gd = None
    mask = None
    if normal is not None:
        nb = _buffer("normal", normal, channels_axis=True)
        gn, mask = _core._paper_edges("normal", nb, normal_threshold)
    if depth is not None:
        db = _buffer("depth", depth, channels_axis=False)
        if mask is not None and db.shape[:2] != mask.shape:
            raise ValueError(f"depth: shape {db.shape[:2]} does not match the normal buffer's {mask.shape}")
        gd, depth_mask = _core._paper_edges("depth", db, depth_threshold)
        mask = depth_mask if mask is None else mask | depth_mask
    assert mask is not None
    return EdgeDetection(mask, gn, gd)
