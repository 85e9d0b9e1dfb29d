"""Uploads shared by the viewers of one scene. Re-running a notebook cell that ends in a viewer
keeps each earlier viewer alive in IPython's output history (``Out``), and each would hold an
upload of its own: its meshes and their line caches, about 13 MB for the bunny with mesh
outlines, and the draft it sends the browser, about 2 MB more. Viewers whose meshes have the
same contents on the same renderer share one upload instead, and one copy of equal drafts,
freed when the last of them is closed or freed."""

from __future__ import annotations

import hashlib
import threading
import weakref
from collections import OrderedDict
from typing import Any, List, Tuple

import numpy as np

from toonmesh.rendering._render import PlacedMesh, Renderer, place_meshes, remove_meshes
from toonmesh.scene._points import Points
from toonmesh.scene._scene import Mesh, own_normals


def _digest(value: Any) -> Tuple[Any, ...]:
    """A value as a key by content: an array (or an image) by its dtype, shape and bytes, a
    plain value as itself."""
    if value is None or isinstance(value, (str, int, float, bool, tuple)):
        return ("value", value)
    a = np.ascontiguousarray(np.asarray(value))
    return ("array", a.dtype.str, a.shape, hashlib.blake2b(a.tobytes(), digest_size=16).digest())


def content_key(mesh: Mesh) -> Tuple[Any, ...]:
    """What a mesh's upload depends on, by content: its arrays, colours and normals (a
    MeshHandle is its own upload: by identity)."""
    if isinstance(mesh, Points):  # a cloud: its arrays and radius
        return ("points", *(_digest(getattr(mesh, k)) for k in ("positions", "normals", "colors")), repr(mesh.radius))
    if mesh.handle is not None:
        return ("handle", id(mesh.handle))
    normals = _digest(mesh.normals) if own_normals(mesh.normals) else ("mode", mesh.normals)
    colors = tuple(sorted((k, _digest(v)) for k, v in mesh.colors.items()))
    return (_digest(mesh.vertices), _digest(mesh.faces), normals, colors)


#: How many of the drafts' bytes an upload keeps for its viewers to share.
KEPT_DRAFTS = 4


class SharedUpload:
    """One scene's meshes on a renderer, in order (``handles``), freed when nothing refers to
    it; and the bytes of the last drafts its viewers sent to the browser (mostly the meshes'
    buffers), so that viewers of the same view share one copy."""

    def __init__(self, renderer: Renderer, meshes: List[Mesh], smooth_iterations: int, where: str):
        placed, uploaded = place_meshes(renderer, meshes, smooth_iterations, where=where)
        self.handles = [p.handle for p in placed]
        self._drafts: "OrderedDict[bytes, bytes]" = OrderedDict()
        self._lock = threading.Lock()
        weakref.finalize(self, remove_meshes, renderer, uploaded)

    def shared_bytes(self, data: bytes) -> bytes:
        """``data``, or an equal bytes object a viewer of this upload already holds."""
        key = hashlib.blake2b(data, digest_size=16).digest()
        with self._lock:
            kept = self._drafts.get(key)
            if kept is not None and kept == data:
                self._drafts.move_to_end(key)
                return kept
            self._drafts[key] = data
            while len(self._drafts) > KEPT_DRAFTS:
                self._drafts.popitem(last=False)
            return data

    def placed(self, meshes: List[Mesh]) -> List[PlacedMesh]:
        """The meshes placed as each says (material, transform, up), on the shared upload."""
        return [PlacedMesh(h, m.material, m.transform, m.up) for h, m in zip(self.handles, meshes)]


_LOCK = threading.Lock()
_SHARED: "weakref.WeakValueDictionary[Tuple[Any, ...], SharedUpload]" = weakref.WeakValueDictionary()


def shared_upload(renderer: Renderer, meshes: List[Mesh], smooth_iterations: int, where: str) -> SharedUpload:
    """The upload of ``meshes`` (after ``smooth_iterations`` of smoothing) on ``renderer``: the
    one a live viewer of the same contents holds, or a new one. ``where`` names the meshes in
    errors."""
    key = (id(renderer), smooth_iterations, tuple(content_key(m) for m in meshes))
    with _LOCK:  # the renderer stays alive while an upload refers to it, so its id is not reused
        upload = _SHARED.get(key)
        if upload is None:
            upload = SharedUpload(renderer, meshes, smooth_iterations, where)
            _SHARED[key] = upload
        return upload
