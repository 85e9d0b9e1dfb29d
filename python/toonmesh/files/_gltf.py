"""glTF documents made readable by trimesh where it falls short, before it reads them.

- Triangle fans (``mode`` 6), which trimesh refuses, are given an index accessor of the
  triangles they mean, (0, i, i + 1) of their vertices (or of their indices), in a buffer of
  their own, and read as triangles.
- A sparse accessor of floats (positions, normals, ... some of whose values the file replaces),
  whose replacements trimesh ignores, is given its values in full, in that buffer.
- Primitives of points and lines (modes 0 to 3), read by toonmesh
  (:mod:`toonmesh.files._points_lines`), are left out: trimesh would misread or drop them.
- A ``KHR_materials_pbrSpecularGlossiness`` material is drawn by its diffuse texture and
  factor, given to trimesh as the base colour (or by the base colour the file also carries).

The JSON is written again only where one of these is found; a GLB keeps its binary chunk.
"""

from __future__ import annotations

import base64
import copy
import json
import struct
from typing import Any, Dict, Optional

import numpy as np

from toonmesh.files._checks import gltf_accessor

_FANS = 6
#: The primitive modes of points and lines (POINTS, LINES, LINE_LOOP, LINE_STRIP).
POINTS_AND_LINES = (0, 1, 2, 3)
_FLOAT = 5126
_SPEC_GLOSS = "KHR_materials_pbrSpecularGlossiness"


def readable(path: str, doc: Dict[str, Any], data: bytes) -> Optional[bytes]:
    """The file's bytes with its fans as triangles, its sparse float accessors in full, its
    specular-glossiness materials as base colours and its points and lines left out, or None
    where it has none of them."""
    fans = [(m, p) for m, mesh in enumerate(doc.get("meshes") or [])
            for p, primitive in enumerate(mesh.get("primitives") or []) if primitive.get("mode") == _FANS]
    glossy = [i for i, mat in enumerate(doc.get("materials") or []) if _SPEC_GLOSS in (mat.get("extensions") or {})]
    sparse = [i for i, a in enumerate(doc.get("accessors") or [])
              if isinstance(a, dict) and "sparse" in a and a.get("componentType") == _FLOAT]
    read_here = any(p.get("mode", 4) in POINTS_AND_LINES for mesh in doc.get("meshes") or []
                    for p in mesh.get("primitives") or [])
    if not fans and not glossy and not sparse and not read_here:
        return None
    doc = copy.deepcopy(doc)
    buffers: Dict[int, Optional[bytes]] = {-1: data}
    blob = bytearray()
    for i in sparse:
        values = _dense(path, doc, i, buffers)
        if values is None:
            continue  # unreadable: trimesh reads it as it does
        accessor = doc["accessors"][i]
        doc.setdefault("bufferViews", []).append(
            {"buffer": len(doc["buffers"]), "byteOffset": len(blob), "byteLength": values.nbytes})
        accessor.pop("sparse")
        accessor["bufferView"], accessor["byteOffset"] = len(doc["bufferViews"]) - 1, 0
        blob += values.astype("<f4").tobytes()
    for i in glossy:
        material = doc["materials"][i]
        spec = material["extensions"].pop(_SPEC_GLOSS)
        pbr = material.setdefault("pbrMetallicRoughness", {})
        if "baseColorTexture" not in pbr and "diffuseTexture" in spec:
            pbr["baseColorTexture"] = spec["diffuseTexture"]
        if "baseColorFactor" not in pbr and "diffuseFactor" in spec:
            pbr["baseColorFactor"] = spec["diffuseFactor"]
        if not material["extensions"]:
            del material["extensions"]
    if fans:
        for m, p in fans:
            primitive = doc["meshes"][m]["primitives"][p]
            if "indices" in primitive:
                order = gltf_accessor(path, doc, primitive["indices"], buffers)
                if order is None:
                    continue  # unreadable: trimesh says why
                order = order.reshape(-1).astype(np.uint32)
            else:
                order = np.arange(int(doc["accessors"][primitive["attributes"]["POSITION"]]["count"]), dtype=np.uint32)
            if len(order) < 3:
                continue
            k = np.arange(1, len(order) - 1)
            triangles = np.stack([np.full_like(k, 0), k, k + 1], axis=1)
            indices = order[triangles].reshape(-1).astype("<u4")
            doc.setdefault("bufferViews", []).append(
                {"buffer": len(doc["buffers"]), "byteOffset": len(blob), "byteLength": indices.nbytes})
            doc.setdefault("accessors", []).append(
                {"bufferView": len(doc["bufferViews"]) - 1, "componentType": 5125, "count": len(indices),
                 "type": "SCALAR"})
            primitive["indices"] = len(doc["accessors"]) - 1
            primitive["mode"] = 4
            blob += indices.tobytes()
    for mesh in doc.get("meshes") or []:
        if "primitives" in mesh:
            mesh["primitives"] = [p for p in mesh["primitives"] if p.get("mode", 4) not in POINTS_AND_LINES]
    if blob:
        doc.setdefault("buffers", []).append(
            {"byteLength": len(blob), "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()})
    text = json.dumps(doc).encode()
    if not path.lower().endswith(".glb"):
        return text
    text += b" " * (-len(text) % 4)
    json_length = struct.unpack("<I", data[12:16])[0]
    rest = data[20 + json_length :]  # the binary chunk, as it was
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + rest
    return b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body


def _dense(path: str, doc: Dict[str, Any], index: int, buffers: Dict[int, Optional[bytes]]) -> Optional[np.ndarray]:
    """The (count, components) float32 values of sparse accessor ``index``: its buffer view's
    values (zeros where it has none) with the sparse indices' values put in; None where a part
    cannot be read."""
    accessor = doc["accessors"][index]
    try:
        sparse = accessor["sparse"]
        count = int(accessor["count"])
        components = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[accessor["type"]]
        parts = [{k: v for k, v in accessor.items() if k != "sparse"},
                 {"bufferView": sparse["indices"]["bufferView"], "byteOffset": sparse["indices"].get("byteOffset", 0),
                  "componentType": sparse["indices"]["componentType"], "count": sparse["count"], "type": "SCALAR"},
                 {"bufferView": sparse["values"]["bufferView"], "byteOffset": sparse["values"].get("byteOffset", 0),
                  "componentType": _FLOAT, "count": sparse["count"], "type": accessor["type"]}]
    except (LookupError, TypeError, ValueError):
        return None
    scratch = dict(doc, accessors=list(doc["accessors"]) + parts)  # read by the checks' accessor reader
    first = len(doc["accessors"])
    base = (gltf_accessor(path, scratch, first, buffers) if "bufferView" in accessor
            else np.zeros((count, components), np.float32))
    where = gltf_accessor(path, scratch, first + 1, buffers)
    values = gltf_accessor(path, scratch, first + 2, buffers)
    if base is None or where is None or values is None or base.shape != (count, components):
        return None
    where = where.reshape(-1).astype(np.int64)
    if len(where) != len(values) or (len(where) and (where.min() < 0 or where.max() >= count)):
        return None
    out = np.array(base, dtype=np.float32)
    out[where] = values
    return out
