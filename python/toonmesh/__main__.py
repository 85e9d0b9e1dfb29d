"""``python -m toonmesh``: the command line (see :mod:`toonmesh.cli`)."""

import sys

from toonmesh.cli import main

if __name__ == "__main__":
    sys.exit(main())
