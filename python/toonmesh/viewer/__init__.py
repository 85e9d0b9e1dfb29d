"""The live view: :class:`toonmesh.Viewer` (``_viewer``), its widget (``_widget``, ``widget.js``
with the toolbar's triad in ``triad.js``, its styles in ``widget.css``), its controls (``_controls``, made field by field in ``_field_controls``), the
browser's drafts and the standalone page (``_draft``, ``draft.js``, ``moves.js``, ``page.js``),
its size (``_layout``) and the meshes its viewers share (``_uploads``)."""

from toonmesh.viewer._viewer import AXES, PROJECTIONS, Viewer, ViewerClosedError, ViewerCode

__all__ = ["AXES", "PROJECTIONS", "Viewer", "ViewerClosedError", "ViewerCode"]
