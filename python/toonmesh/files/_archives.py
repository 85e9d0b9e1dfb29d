"""Zip and tar archives and compressed files (``.gz``, ``.bz2``, ``.xz``) of mesh files, unpacked
into a temporary folder so that each mesh file inside is read as the plain file is (toonmesh's own
checks, an STL's corners merged, an OBJ's MTL and textures found beside it).

Only regular files with relative names that stay inside the folder are unpacked, and at most
:data:`MAX_UNPACKED` bytes in all, counted as they are written (a small archive that claims or
inflates to more is refused).
"""

from __future__ import annotations

import bz2
import contextlib
import gzip
import lzma
import os
import tarfile
import tempfile
import zipfile
from typing import IO, Any, Callable, Dict, Iterator, List, Optional, Tuple

from toonmesh.files._checks import MeshFileError

#: The most bytes one archive or compressed file may unpack to.
MAX_UNPACKED = 1 << 31

#: Suffixes of archives (several files) and of compressed single files.
ARCHIVES = (".zip", ".tar", ".tar.gz", ".tgz", ".tar.bz2", ".tbz2", ".tar.xz", ".txz")
COMPRESSED: Dict[str, Callable[..., Any]] = {".gz": gzip.open, ".bz2": bz2.open, ".xz": lzma.open}


def kind(path: str) -> Optional[str]:
    """The archive or compression suffix ``path`` ends with (lower case), or None."""
    lower = path.lower()
    for suffix in ARCHIVES + tuple(COMPRESSED):  # archives first: .tar.gz is not a compressed .tar
        if lower.endswith(suffix):
            return suffix
    return None


@contextlib.contextmanager
def unpacked(path: str) -> Iterator[Tuple[str, List[str]]]:
    """(folder, the unpacked files' names relative to it, in the archive's order), removed on exit.

    Raises:
        MeshFileError: the archive cannot be read, or unpacks to more than :data:`MAX_UNPACKED`.
    """
    suffix = kind(path)
    with tempfile.TemporaryDirectory(prefix="toonmesh-") as folder:
        budget = [MAX_UNPACKED]
        try:
            if suffix == ".zip":
                names = _unzip(path, folder, budget)
            elif suffix in COMPRESSED:
                name = os.path.basename(path)[: -len(suffix)] or "mesh"
                with COMPRESSED[suffix](path) as source:
                    _copy(path, source, os.path.join(folder, name), budget)
                names = [name]
            else:
                names = _untar(path, folder, budget)
        except MeshFileError:
            raise
        except (OSError, EOFError, ValueError, zipfile.BadZipFile, tarfile.TarError, lzma.LZMAError) as exc:
            raise MeshFileError(f"{path}: cannot unpack ({' '.join(str(exc).split()) or type(exc).__name__})") from None
        yield folder, names


def _inside(name: str) -> Optional[str]:
    """``name`` as a relative path that stays inside the folder, or None."""
    name = name.replace("\\", "/")
    parts = [p for p in name.split("/") if p not in ("", ".")]
    if not parts or name.startswith("/") or ".." in parts or ":" in parts[0]:
        return None
    return os.path.join(*parts)


def _copy(path: str, source: IO[bytes], target: str, budget: List[int]) -> None:
    os.makedirs(os.path.dirname(target), exist_ok=True)
    with open(target, "wb") as out:
        while True:
            block = source.read(1 << 20)
            if not block:
                return
            budget[0] -= len(block)
            if budget[0] < 0:
                raise MeshFileError(f"{path}: unpacks to more than {MAX_UNPACKED:,} bytes; toonmesh unpacks at most "
                                    "that much")
            out.write(block)


def _unzip(path: str, folder: str, budget: List[int]) -> List[str]:
    names = []
    with zipfile.ZipFile(path) as archive:
        for info in archive.infolist():
            name = None if info.is_dir() else _inside(info.filename)
            if name is not None:
                with archive.open(info) as source:
                    _copy(path, source, os.path.join(folder, name), budget)
                names.append(name)
    return names


def _untar(path: str, folder: str, budget: List[int]) -> List[str]:
    names = []
    with tarfile.open(path) as archive:
        for member in archive:
            name = _inside(member.name) if member.isfile() else None
            source = None if name is None else archive.extractfile(member)
            if source is not None:
                with source:
                    _copy(path, source, os.path.join(folder, str(name)), budget)
                names.append(str(name))
    return names

