"""A private runtime directory for Mesa's drivers when the environment has no usable one.

Mesa's software rasterisers probe for a Wayland display when a device is created; without a valid
``XDG_RUNTIME_DIR`` (the usual case in containers, CI and cron jobs) the Wayland client library
prints "error: XDG_RUNTIME_DIR is invalid or not set in the environment." on stderr, which reads
like a failure on every successful render. Giving the process a private, empty 0700 directory
instead (as a login session would) keeps stderr for real errors. A valid directory is left alone.
"""

from __future__ import annotations

import atexit
import os
import shutil
import stat
import sys
import tempfile


def _usable(path: str) -> bool:
    try:
        st = os.stat(path)
    except OSError:
        return False
    return os.path.isabs(path) and stat.S_ISDIR(st.st_mode) and os.access(path, os.W_OK | os.X_OK)


def ensure_runtime_dir() -> None:
    """Sets ``XDG_RUNTIME_DIR`` to a private temporary directory (removed at exit) on Linux
    when it is unset or not a writable absolute directory."""
    if not sys.platform.startswith("linux") or _usable(os.environ.get("XDG_RUNTIME_DIR", "")):
        return
    try:
        path = tempfile.mkdtemp(prefix="toonmesh-runtime-")  # created 0700
    except OSError:
        return  # nowhere to put one: the message is harmless, rendering works regardless
    os.environ["XDG_RUNTIME_DIR"] = path
    atexit.register(shutil.rmtree, path, ignore_errors=True)
