"""What the Python side checks of its arguments, and the core's description of them.

- :mod:`._checks`: the type rules for a flag, an integer and a number, with errors that name the
  argument (for the functions written in Python; the core checks its own).
- :mod:`._input`: a mesh as every public function takes it, (V, F) arrays or a
  ``trimesh.Trimesh``, as NumPy arrays without copying.
- :mod:`._described`: the core's description of its settings (kind, choices, bounds, help,
  default), read where a front end needs it instead of typing it again.
- :mod:`._described_flags`: the command line's flags made from that description.

Nothing here imports the rest of the package; everything above takes its checks from here.
"""
