"""Headless rendering: :func:`toonmesh.render`, :class:`toonmesh.Renderer` and what they give back.

- :mod:`._render`: the renderers and the one draw path every render takes.
- :mod:`._results`: the core's results read into :class:`toonmesh.RenderResult` and
  :class:`toonmesh.RenderStack`.
- :mod:`._strokes`: a render's lines as a pen draws them (``RenderResult.strokes`` and ``.svg``).
- :mod:`._video`: turntables written as GIF, MP4 or WebM.
- :mod:`._views`: the turntable of fitted cameras of the command line and batch renders.
- :mod:`._runtime_dir`: a private runtime directory for Mesa's drivers, set before any device.

Users import these names from the package's front door (:mod:`toonmesh`); nothing here imports it.
"""
