"""glTF documents made readable by trimesh where it falls short, before it reads them.

- Triangle fans (``mode`` 6), which trimesh refuses, are given an index accessor of the
  triangles they mean, (0, i, i + 1) of their vertices (or of their indices), in a buffer of
  their own, and read as triangles.
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
_SPEC_GLOSS = "KHR_materials_pbrSpecularGlossiness"


def readable(path: str, doc: Dict[str, Any], data: bytes) -> Optional[bytes]:
    """The file's bytes with its fans as triangles and its specular-glossiness materials as base
    colours, or None where it has neither."""
    fans = [(m, p) for m, mesh in enumerate(doc.get("meshes") or [])
            for p, primitive in enumerate(mesh.get("primitives") or []) if primitive.get("mode") == _FANS]
    glossy = [i for i, mat in enumerate(doc.get("materials") or []) if _SPEC_GLOSS in (mat.get("extensions") or {})]
    if not fans and not glossy:
        return None
    doc = copy.deepcopy(doc)
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
        buffers: Dict[int, Optional[bytes]] = {-1: data}
        blob = bytearray()
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
