"""The scene as Python describes it, below both the files and the renderer.

- :mod:`._scene`: :class:`toonmesh.Mesh` (geometry, material, transform, normals, up axis and
  colour), :class:`toonmesh.MeshHandle` and the normal modes.
- :mod:`._points`: :class:`toonmesh.Points` and :class:`toonmesh.Lines`, point clouds and ink lines.
- :mod:`._colors`: a mesh's colour keywords, and what a ``trimesh.Trimesh`` brings by itself.

Files (:mod:`toonmesh.files`) make meshes and the renderer (:mod:`toonmesh.rendering`) draws
them; both take them from here, so that neither needs the other to describe a scene.
"""
