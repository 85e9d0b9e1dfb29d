"""Mesh files read and written: the one reading path of :func:`toonmesh.load`, the command line
and batch renders.

- :mod:`._load`: a file (or a ``trimesh.Scene``) into :class:`toonmesh.Mesh` objects (and
  points and lines), through trimesh after the checks; each file (the mesh file, its MTL,
  textures and buffers) opened once, its bytes shared by the checks and trimesh.
- :mod:`._checks`: what trimesh does not check (OBJ lines, PLY header counts, glTF accessors,
  the files a mesh file names), one layer beside the parser.
- :mod:`._ply`: PLY triangle strips and float colours, where trimesh falls short.
- :mod:`._polygons`: concave polygons (OBJ, PLY, OFF) split by ear clipping (trimesh splits every
  one as a fan).
- :mod:`._threemf`: 3MF files of the production extension (parts in other model files), which
  trimesh places wrong.
- :mod:`._points_lines`: points and lines (PLY without faces, OBJ ``l`` and ``p``, ``.xyz``,
  glTF points and line modes) as :class:`toonmesh.Points` and :class:`toonmesh.Lines`.
- :mod:`._gltf`: glTF triangle fans and specular-glossiness materials, made readable by trimesh.
- :mod:`._archives`: zip and tar archives and compressed files, unpacked.
- :mod:`._write`: meshes written back (``toonmesh smooth``) and renders saved.

Users import :func:`toonmesh.load` from the package's front door; nothing here imports it.
"""
