"""The render benchmark's peer renderers (moderngl, pyrender, PyVista), each in a process of its
own (a GL platform is chosen at import, and a crash stays there), driven frame by frame.

The parent starts a worker (``python -m toonmesh.bench._peers NAME SUBDIVISIONS``), which
uploads the mesh once and answers one frame request at a time with the seconds that frame took,
measured in the worker. So the parent can take the renderers in turns, frame by frame, and a
change in the machine's load falls on all of them alike.

Protocol: one JSON object a line. The worker's lines on stdout start with ``@@``; its first says
``{"ready": ..., "renderer": ..., "msaa": ...}`` or ``{"error": ...}``; each request
``{"frame": "color"|"color+depth", "width": W, "height": H}`` gets ``{"t": seconds}`` or
``{"error": ...}``; an empty line or end of input ends it.
"""

from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
import tempfile
import time
from typing import Any, Callable, Dict, Optional, Tuple

import numpy as np

EYE = (0.0, 0.0, 3.2)
FOV_Y = 40.0
NEAR, FAR = 0.5, 10.0
LIGHT = (0.0, 0.0, 1.0)  # toward the light, from the surface: a headlight along the view
BASE = (0.94, 0.54, 0.24)

# name: (the module it needs, environment, what it is)
PEERS: Dict[str, Tuple[str, Dict[str, str]]] = {
    "moderngl": ("moderngl", {}),
    "moderngl, culled": ("moderngl", {}),
    "pyrender OSMesa": ("pyrender", {"PYOPENGL_PLATFORM": "osmesa"}),
    "pyrender EGL": ("pyrender", {"PYOPENGL_PLATFORM": "egl"}),
    "PyVista": ("pyvista", {}),
}

_MARK = "@@"


def installed(name: str) -> bool:
    """Whether the peer's Python package can be imported here (it may still fail to start)."""
    return importlib.util.find_spec(PEERS[name][0]) is not None


class PeerProcess:
    """A running peer worker. ``info`` is its first answer (``error`` when it could not start)."""

    def __init__(self, name: str, subdivisions: int, timeout: float = 600.0):
        self.name = name
        self._log = tempfile.TemporaryFile(mode="w+")
        env = dict(os.environ, **PEERS[name][1])
        self._proc: Optional[subprocess.Popen] = subprocess.Popen(
            [sys.executable, "-m", "toonmesh.bench._peers", name, str(subdivisions)],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=self._log, text=True, env=env,
        )
        self.info = self._answer(timeout)

    def frame(self, frame: str, width: int, height: int) -> float:
        """Seconds one frame took in the worker; NaN once the worker has failed."""
        if self._proc is None or "error" in self.info:
            return float("nan")
        assert self._proc.stdin is not None
        self._proc.stdin.write(json.dumps({"frame": frame, "width": width, "height": height}) + "\n")
        self._proc.stdin.flush()
        answer = self._answer(600.0)
        if "error" in answer:
            self.info = answer
            return float("nan")
        return float(answer["t"])

    def _answer(self, timeout: float) -> Dict[str, Any]:
        assert self._proc is not None and self._proc.stdout is not None
        t0 = time.perf_counter()
        while time.perf_counter() - t0 < timeout:
            line = self._proc.stdout.readline()
            if not line:  # the worker ended
                return {"error": self._last_error()}
            if line.startswith(_MARK):
                return dict(json.loads(line[len(_MARK):]))
        return {"error": "timed out"}

    def _last_error(self) -> str:
        self._log.seek(0)
        lines = [ln.strip() for ln in self._log.read().splitlines() if ln.strip()]
        return (lines[-1] if lines else "the worker ended without a word")[:90]

    def close(self) -> None:
        if self._proc is None:
            return
        try:
            if self._proc.poll() is None and self._proc.stdin is not None:
                self._proc.stdin.write("\n")
                self._proc.stdin.flush()
                self._proc.stdin.close()
            self._proc.wait(timeout=60)
        except (OSError, subprocess.TimeoutExpired):
            self._proc.kill()
            self._proc.wait()
        self._proc = None
        self._log.close()


# ---------------------------------------------------------------------------------------------
# In the worker


def _perspective(fov_y: float, aspect: float, near: float, far: float) -> np.ndarray:
    f = 1.0 / np.tan(np.radians(fov_y) / 2)
    return np.array([[f / aspect, 0, 0, 0], [0, f, 0, 0],
                     [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)], [0, 0, -1, 0]])


def _vertex_normals(V: np.ndarray, F: np.ndarray) -> np.ndarray:
    n = np.zeros_like(V)
    face = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    for k in range(3):
        np.add.at(n, F[:, k], face)
    return n / np.linalg.norm(n, axis=1, keepdims=True)


def _moderngl(V: np.ndarray, F: np.ndarray, cull: bool = False) -> Tuple[Dict[str, Any], Callable[[str, int, int], None]]:
    """A plain Lambert shader (one directional light, per pixel) in an EGL standalone context;
    the frame read back with ``fbo.read_into`` into NumPy buffers, depth made linear in NumPy.
    With ``cull``, back faces are culled (right for this closed sphere seen from outside, which
    toonmesh decides for itself)."""
    import moderngl

    ctx = moderngl.create_standalone_context(backend="egl")
    prog = ctx.program(
        vertex_shader="""
            #version 330
            uniform mat4 mvp;
            in vec3 in_position; in vec3 in_normal;
            out vec3 normal;
            void main() { normal = in_normal; gl_Position = mvp * vec4(in_position, 1.0); }
        """,
        fragment_shader="""
            #version 330
            uniform vec3 light; uniform vec3 base;
            in vec3 normal; out vec4 color;
            void main() { color = vec4(base * (0.1 + max(dot(normalize(normal), light), 0.0)), 1.0); }
        """,
    )
    vbo = ctx.buffer(np.hstack([V, _vertex_normals(V, F)]).astype("f4").tobytes())
    ibo = ctx.buffer(F.astype("u4").tobytes())
    vao = ctx.vertex_array(prog, [(vbo, "3f 3f", "in_position", "in_normal")], index_buffer=ibo, index_element_size=4)
    prog["light"].value = LIGHT
    prog["base"].value = BASE
    ctx.enable(moderngl.DEPTH_TEST | moderngl.CULL_FACE if cull else moderngl.DEPTH_TEST)
    view = np.eye(4)
    view[:3, 3] = -np.asarray(EYE)
    targets: Dict[Tuple[int, int], Any] = {}

    def frame(kind: str, width: int, height: int) -> None:
        if (width, height) not in targets:
            fbo = ctx.framebuffer([ctx.renderbuffer((width, height), 4)], ctx.depth_renderbuffer((width, height)))
            bufs = (np.empty((height, width, 4), np.uint8), np.empty((height, width), np.float32),
                    np.empty((height, width), np.float32))
            targets[width, height] = fbo, bufs
        fbo, (color, zbuf, depth) = targets[width, height]
        prog["mvp"].write((_perspective(FOV_Y, width / height, NEAR, FAR) @ view).T.astype("f4").tobytes())
        fbo.use()
        fbo.clear(1.0, 1.0, 1.0, 1.0, depth=1.0)
        vao.render()
        fbo.read_into(color, components=4)  # bottom row first: color[::-1] is the image
        if kind == "color+depth":
            fbo.read_into(zbuf, components=1, attachment=-1, dtype="f4")
            # window depth to distance along the view axis, inf where nothing was drawn
            np.multiply(zbuf, 2.0 * (FAR - NEAR), out=depth)
            np.subtract(FAR + NEAR + (FAR - NEAR), depth, out=depth)
            np.divide(2.0 * FAR * NEAR, depth, out=depth)
            depth[zbuf == 1.0] = np.inf

    info = {"renderer": ctx.info["GL_RENDERER"], "msaa": "none (plain framebuffer)"}
    return info, frame


def _pyrender(V: np.ndarray, F: np.ndarray) -> Tuple[Dict[str, Any], Callable[[str, int, int], None]]:
    """pyrender's OffscreenRenderer with its default material (metallic-roughness) and one
    directional light; its ``render`` always reads back colour and depth."""
    import pyrender
    import trimesh

    mesh = pyrender.Mesh.from_trimesh(trimesh.Trimesh(V, F, process=False), smooth=True)
    scene = pyrender.Scene(ambient_light=[0.1, 0.1, 0.1])
    scene.add(mesh)
    pose = np.eye(4)
    pose[:3, 3] = EYE
    scene.add(pyrender.PerspectiveCamera(yfov=np.radians(FOV_Y), znear=NEAR, zfar=FAR), pose=pose)
    scene.add(pyrender.DirectionalLight(intensity=3.0), pose=pose)
    renderer = pyrender.OffscreenRenderer(64, 64)

    def frame(kind: str, width: int, height: int) -> None:
        renderer.viewport_width, renderer.viewport_height = width, height
        renderer.render(scene)

    renderer.render(scene)
    from OpenGL import GL

    # With framebuffer objects (EGL) pyrender draws into a fixed 4x multisampled framebuffer;
    # without (OSMesa) into the context's own, single-sampled.
    msaa = "4x (fixed)" if renderer._platform.supports_framebuffers() else "none (OSMesa's buffer)"
    info = {"renderer": GL.glGetString(GL.GL_RENDERER).decode(), "msaa": msaa}
    return info, frame


def _pyvista(V: np.ndarray, F: np.ndarray) -> Tuple[Dict[str, Any], Callable[[str, int, int], None]]:
    """An off-screen Plotter with its default anti-aliasing and one headlight; a frame is
    ``render()`` and the image (``plotter.image``), and ``get_image_depth()`` for depth."""
    import pyvista as pv

    faces = np.hstack([np.full((len(F), 1), 3), F]).ravel()
    pl = pv.Plotter(off_screen=True, window_size=(64, 64), lighting="none")
    pl.add_light(pv.Light(light_type="headlight"))
    pl.add_mesh(pv.PolyData(V, faces), smooth_shading=True, color=BASE)
    pl.camera.position = EYE
    pl.camera.focal_point = (0.0, 0.0, 0.0)
    pl.camera.up = (0.0, 1.0, 0.0)
    pl.camera.view_angle = FOV_Y
    pl.camera.clipping_range = (NEAR, FAR)

    def frame(kind: str, width: int, height: int) -> None:
        if tuple(pl.window_size) != (width, height):
            pl.window_size = (width, height)
        pl.render()
        pl.image
        if kind == "color+depth":
            pl.get_image_depth(reset_camera_clipping_range=False)

    pl.show(auto_close=False)  # sets the window up; later frames are render() and a read-back
    window = pl.render_window
    aa = pv.global_theme.anti_aliasing
    samples = window.GetMultiSamples()
    info = {"renderer": f"VTK {pv.vtk_version_info[0]}.{pv.vtk_version_info[1]} {window.GetClassName()}",
            "msaa": f"{aa} ({samples} samples)" if aa == "msaa" else str(aa)}
    return info, frame


_SETUP = {"moderngl": _moderngl, "moderngl, culled": lambda V, F: _moderngl(V, F, cull=True), "pyrender OSMesa": _pyrender, "pyrender EGL": _pyrender, "PyVista": _pyvista}


def _say(obj: Dict[str, Any]) -> None:
    sys.stdout.write(_MARK + json.dumps(obj) + "\n")
    sys.stdout.flush()


def worker(name: str, subdivisions: int) -> int:
    """Runs one peer: sets it up, then answers frame requests from stdin until an empty line."""
    from toonmesh import shapes

    V, F = shapes.icosphere(subdivisions)
    try:
        t0 = time.perf_counter()
        info, frame = _SETUP[name](V, F)
        info["setup_s"] = time.perf_counter() - t0
    except ModuleNotFoundError as exc:
        _say({"error": f"not installed ({exc.name})"})
        return 0
    except Exception as exc:  # a peer that cannot start here: say why, in a line
        _say({"error": f"{type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''}"[:90]})
        return 0
    _say(dict(info, ready=True))
    for line in sys.stdin:
        if not line.strip():
            break
        req = json.loads(line)
        try:
            t0 = time.perf_counter()
            frame(req["frame"], req["width"], req["height"])
            _say({"t": time.perf_counter() - t0})
        except Exception as exc:
            _say({"error": f"{type(exc).__name__}: {exc}"[:90]})
    return 0


if __name__ == "__main__":
    sys.exit(worker(sys.argv[1], int(sys.argv[2])))
