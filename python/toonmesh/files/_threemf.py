"""3MF files of the production extension, read by toonmesh: their components name objects in other
model parts of the package (``p:path="/3D/Objects/part.model"``), which trimesh merges into one
geometry per component (every object of that part in each) and places no build item of (its ids
collide with the root model's). Here each object is looked up in the model part that its
component or build item names, and placed with the transforms composed (build item, then each
component down to the mesh). Read with the standard library; other 3MF files are read by trimesh
as before.
"""

from __future__ import annotations

import io
import posixpath
import re
import xml.etree.ElementTree as ET
import zipfile
from typing import Dict, List, Optional, Tuple

import numpy as np

from toonmesh.files._checks import MeshFileError

#: The production extension's namespace, whose ``path`` attribute names another model part.
PRODUCTION = "http://schemas.microsoft.com/3dmanufacturing/production/2015/06"
#: The relationship type of a package's root model (its ``_rels/.rels``).
MODEL_RELATIONSHIP = "http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"
#: The deepest nesting of components followed (a deeper one is taken for a cycle).
MAX_DEPTH = 32

_PATH = f"{{{PRODUCTION}}}path"

#: An object: (model part, object id).
Key = Tuple[str, str]


def read(path: str, data: bytes) -> Optional[Tuple[Dict[Key, Tuple[str, np.ndarray, np.ndarray]],
                                                   List[Tuple[Key, np.ndarray]]]]:
    """The geometries ({(part, id): (name, V (N, 3) float64, F (M, 3) int64)}) and their
    placements ([(key, 4x4 world transform)], one per mesh object reached from each build item)
    of a 3MF file (its bytes ``data``) whose root model uses the production extension's
    ``path``; None for any other 3MF (read by trimesh).

    Raises:
        MeshFileError: a part that is not well-formed XML, an object named but not defined,
            components nested deeper than :data:`MAX_DEPTH`, a malformed transform, vertex or
            triangle, naming the file and the part.
    """
    try:
        package = zipfile.ZipFile(io.BytesIO(data))
        names = {n.lower().lstrip("/"): n for n in package.namelist()}
        root = _root_part(package, names)
        if root is None or not _names_other_parts(package.read(names[root])):
            return None
        reader = _Reader(path, package, names, root)
        model = reader.model(root)
        if not any(_PATH in e.attrib for e in model.iter() if e.tag.endswith(("}component", "}item"))):
            return None
        placements: List[Tuple[Key, np.ndarray]] = []
        build = next((e for e in model if e.tag.endswith("}build")), None)
        for number, item in enumerate([] if build is None else [e for e in build if e.tag.endswith("}item")], 1):
            part = reader.part_of(item, root)
            reader.place(part, reader.attribute(item, "objectid", f"build item {number}"),
                         reader.transform(item, f"build item {number}"), placements, f"build item {number}", 0)
    except zipfile.BadZipFile as exc:
        raise MeshFileError(f"{path}: not a readable 3MF package ({exc})") from None
    return reader.geometries, placements


def _names_other_parts(model: bytes) -> bool:
    """Whether a model part's bytes may hold the production extension's ``path`` attribute (its
    namespace declared, and ``PREFIX:path`` written): found without parsing the XML, so that
    other 3MF files cost trimesh's reading alone."""
    prefixes = re.findall(rb'xmlns:([A-Za-z_][\w.-]*)\s*=\s*["\']' + re.escape(PRODUCTION.encode()), model)
    return any(model.find(p + b":path") >= 0 for p in prefixes)


def _root_part(package: zipfile.ZipFile, names: Dict[str, str]) -> Optional[str]:
    """The root model part's name (lower case, no leading slash): the one ``_rels/.rels`` names,
    else ``3D/3dmodel.model``."""
    rels = names.get("_rels/.rels")
    if rels is not None:
        try:
            for rel in ET.fromstring(package.read(rels)):
                target = rel.attrib.get("Target", "").lower().lstrip("/")
                if rel.attrib.get("Type") == MODEL_RELATIONSHIP and target in names:
                    return target
        except ET.ParseError:
            pass
    return next((n for n in names if n.endswith("3d/3dmodel.model")), None)


class _Reader:
    """The model parts of one package, each parsed once, and the geometries read from them."""

    def __init__(self, path: str, package: zipfile.ZipFile, names: Dict[str, str], root: str) -> None:
        self.path, self.package, self.names, self.root = path, package, names, root
        self.models: Dict[str, ET.Element] = {}
        self.objects: Dict[str, Dict[str, ET.Element]] = {}
        self.geometries: Dict[Key, Tuple[str, np.ndarray, np.ndarray]] = {}

    def model(self, part: str) -> ET.Element:
        if part not in self.models:
            if part not in self.names:
                raise MeshFileError(f"{self.path}: the package has no part /{part}")
            try:
                model = ET.fromstring(self.package.read(self.names[part]))
            except ET.ParseError as exc:
                raise MeshFileError(f"{self.path}: /{self.names[part]} is not well-formed XML ({exc})") from None
            self.models[part] = model
            resources = [e for e in model if e.tag.endswith("}resources")]
            self.objects[part] = {o.attrib.get("id", ""): o for r in resources for o in r
                                  if o.tag.endswith("}object")}
        return self.models[part]

    def part_of(self, element: ET.Element, here: str) -> str:
        """The model part a component or build item names (its ``p:path``), else ``here``."""
        named = element.attrib.get(_PATH)
        if named is None:
            return here
        return posixpath.normpath(named.strip()).lower().lstrip("/")

    def attribute(self, element: ET.Element, name: str, where: str) -> str:
        value = element.attrib.get(name)
        if value is None:
            raise MeshFileError(f"{self.path}: {where} has no {name}")
        return value

    def transform(self, element: ET.Element, where: str) -> np.ndarray:
        """The 4x4 transform of a ``transform`` attribute (12 numbers, the 3MF's rows of a
        4x3 matrix that multiplies row vectors), identity where there is none."""
        text = element.attrib.get("transform")
        out = np.eye(4)
        if text is None:
            return out
        try:
            values = np.array(text.split(), dtype=np.float64)
        except ValueError:
            values = np.empty(0)
        if values.shape != (12,) or not np.isfinite(values).all():
            raise MeshFileError(f"{self.path}: {where}: expected a transform of 12 numbers, got {text[:80]!r}")
        out[:3, :] = values.reshape(4, 3).T
        return out

    def place(self, part: str, oid: str, transform: np.ndarray, out: List[Tuple[Key, np.ndarray]],
              where: str, depth: int) -> None:
        """Each mesh object reached from object ``oid`` of ``part`` with its world transform."""
        if depth > MAX_DEPTH:
            raise MeshFileError(f"{self.path}: components nested deeper than {MAX_DEPTH} (a cycle?) at {where}")
        self.model(part)
        obj = self.objects[part].get(oid)
        if obj is None:
            raise MeshFileError(f"{self.path}: {where} names object {oid} of /{self.names[part]}, which it does "
                                "not define")
        key = (part, oid)
        for child in obj:
            if child.tag.endswith("}mesh"):
                if key not in self.geometries:
                    self.geometries[key] = self.mesh(child, obj, key)
                out.append((key, transform))
            elif child.tag.endswith("}components"):
                for number, c in enumerate([c for c in child if c.tag.endswith("}component")], 1):
                    inner = f"component {number} of object {oid} (/{self.names[part]})"
                    self.place(self.part_of(c, part), self.attribute(c, "objectid", inner),
                               transform @ self.transform(c, inner), out, inner, depth + 1)

    def mesh(self, mesh: ET.Element, obj: ET.Element, key: Key) -> Tuple[str, np.ndarray, np.ndarray]:
        part, oid = key
        where = f"object {oid} of /{self.names[part]}"
        vertices = next((e for e in mesh if e.tag.endswith("}vertices")), None)
        triangles = next((e for e in mesh if e.tag.endswith("}triangles")), None)
        try:
            V = np.array([[v.attrib["x"], v.attrib["y"], v.attrib["z"]] for v in
                          ([] if vertices is None else vertices) if v.tag.endswith("}vertex")],
                         dtype=np.float64).reshape(-1, 3)
            F = np.array([[t.attrib["v1"], t.attrib["v2"], t.attrib["v3"]] for t in
                          ([] if triangles is None else triangles) if t.tag.endswith("}triangle")],
                         dtype=np.int64).reshape(-1, 3)
        except (KeyError, ValueError, OverflowError):
            raise MeshFileError(f"{self.path}: {where}: a vertex or triangle is malformed "
                                "(expected x, y, z numbers; v1, v2, v3 indices)") from None
        name = obj.attrib.get("name") or (oid if part == self.root else f"{posixpath.basename(part)}#{oid}")
        taken = {n for n, _, _ in self.geometries.values()}
        unique, k = name, 1
        while unique in taken:
            k += 1
            unique = f"{name}_{k}"
        return unique, V, F
