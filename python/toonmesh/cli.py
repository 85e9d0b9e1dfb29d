"""The command line: ``toonmesh`` (console script) and ``python -m toonmesh``.

    toonmesh render MESH... -o OUT [--size WxH] [--style S] [--normals MODE] [--views N] [--up x|y|z] ...
    toonmesh smooth IN OUT [--method M] [--iterations N] [--preset P] [--weld]
    toonmesh edges MESH -o lines.svg|lines.npz [--eye X Y Z] [--crease-angle DEG] [--smooth-strokes PX]
    toonmesh bench smooth|edges|render|effects|viewer|all [--quick] [--json FILE]
    toonmesh demo
    toonmesh --version

Mesh files are read and written through trimesh (``pip install 'toonmesh[io]'``). A mistake
(a missing file, a bad size, an unreadable mesh, a missing package) prints one line to stderr and
exits with status 1 (2 for a bad command line); ``toonmesh COMMAND --help`` lists the options.
"""

from __future__ import annotations

import argparse
import inspect
import os
import sys
import time
import warnings
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

import toonmesh as tm
from toonmesh import _core, _strokes
from toonmesh._files import (
    IMAGE_SUFFIXES, check_distinct_names, image_suffix, read_mesh, seam_normals, view_paths, write_mesh,
)
from toonmesh._load import OWN_COLOURS_WHITE, read_surfaces
from toonmesh._views import UP_AXES, up_vector, view_direction

__all__ = ["main"]

# the shading models and outline kinds the core has
STYLES: Dict[str, Callable[..., Any]] = {m.replace("_", "-"): getattr(tm.Material, m) for m in _core.MODELS}
STYLES["hatching"] = tm.Material.hatching  # bands drawn as strokes
OUTLINES = ("none",) + _core.OUTLINE_KINDS
SMOOTH_METHODS = ("laplacian", "taubin", "hc", "implicit")
BACKENDS = ("auto", "vulkan", "gl")


#: The ink lines of ``toonmesh demo``, and of ``toonmesh render`` unless its flags say otherwise.
DEMO_OUTLINES = tm.Outlines("mesh", width=2.0, crease_angle=60.0)
DEMO_LINE_WIDTH = float(getattr(DEMO_OUTLINES.styles["silhouette"], "width"))
#: The hatching material's defaults (spacing and width of its strokes, in pixels).
HATCHING: Dict[str, Any] = dict(tm.Material.hatching().hatch_style or {})


def mesh_file(name: str) -> str:
    """A mesh argument: a file, or the name of a mesh shipped with toonmesh (``bunny``) when no
    file of that name exists."""
    if os.path.exists(name):
        return name
    from toonmesh import data

    packaged = data.packaged(name)
    if packaged is not None:
        return packaged
    raise FileNotFoundError(f"{name}: no such file (meshes shipped with toonmesh: {', '.join(data.PACKAGED)})")


class CliError(Exception):
    """A mistake on the command line; printed as one line, exit status 2."""

    def __init__(self, message: str, prog: str = "toonmesh"):
        super().__init__(message)
        self.prog = prog


class _Parser(argparse.ArgumentParser):
    """argparse, but a mistake is one line on stderr instead of the usage block."""

    def error(self, message: str) -> Any:  # type: ignore[override]
        raise CliError(f"{message} (see {self.prog} --help)", self.prog)


def _size(text: str) -> Tuple[int, int]:
    parts = text.lower().split("x")
    try:
        w, h = (int(parts[0]), int(parts[0])) if len(parts) == 1 else (int(parts[0]), int(parts[1]))
        if len(parts) > 2 or w < 1 or h < 1:
            raise ValueError
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT in pixels, both >= 1 (e.g. 640x480), got {text!r}") from None
    return w, h


def _positive(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        n = 0
    if n < 1:
        raise argparse.ArgumentTypeError(f"expected an integer >= 1, got {text!r}")
    return n


def _count(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        n = -1
    if n < 0:
        raise argparse.ArgumentTypeError(f"expected an integer >= 0, got {text!r}")
    return n


def _normals(text: str) -> Any:
    """--normals: smooth, flat, auto, or auto:DEGREES (the angle is checked by the renderer)."""
    name, sep, angle = text.partition(":")
    if name in ("smooth", "flat", "auto") and not sep:
        return name
    if name == "auto" and sep:
        try:
            return ("auto", float(angle))
        except ValueError:
            pass
    raise argparse.ArgumentTypeError(f"expected smooth, flat, auto or auto:DEGREES (e.g. auto:45), got {text!r}")


def _outputs(text: str) -> List[str]:
    names = [n.strip() for n in text.split(",") if n.strip()]
    bad = [n for n in names if n not in _core.IMAGE_OUTPUTS]
    if bad or not names:
        raise argparse.ArgumentTypeError(
            f"expected a comma-separated list of {', '.join(_core.IMAGE_OUTPUTS)}, got {text!r}")
    return names


def pass_through(fn: Callable[..., Any], keyword: str, value: Any, flag: str) -> Dict[str, Any]:
    """``{keyword: value}`` when ``fn`` takes that keyword, for a flag whose feature may not be
    in this version of toonmesh yet; otherwise a one-line error naming the flag."""
    if keyword not in inspect.signature(fn).parameters:
        name = getattr(fn, "__qualname__", getattr(fn, "__name__", "the function"))
        raise CliError(f"{flag}: not available in toonmesh {tm.__version__} ({name} has no {keyword}= option)")
    return {keyword: value}


def _progress(total: int) -> Any:
    """A tqdm bar on stderr for runs of several images, when stderr is a terminal and tqdm is
    installed; otherwise nothing."""
    if total <= 1 or not sys.stderr.isatty():
        return None
    try:
        from tqdm import tqdm
    except ImportError:
        return None
    return tqdm(total=total, unit="image", file=sys.stderr)


# --------------------------------------------------------------------------------------------
# render


def _render_targets(meshes: Sequence[str], out: str, views: int, outputs: List[str]) -> List[List[str]]:
    """The files each mesh's views are written to: ``out`` itself for one image with a .png or
    .npz name, else files named after the meshes in the folder ``out``."""
    suffix = os.path.splitext(out)[1].lower()
    if len(meshes) == 1 and views == 1 and suffix in IMAGE_SUFFIXES:
        if suffix == ".png" and outputs != ["color"]:
            raise CliError(f"-o: normal and depth outputs are written as .npz, not {suffix}")
        os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
        return [[out]]
    if suffix in IMAGE_SUFFIXES:
        raise CliError(f"-o: {len(meshes) * views} images are written: give a folder, not {out}")
    if suffix and not os.path.isdir(out):
        raise CliError(f"-o: images are written as .png or .npz (or into a folder), not {suffix}")
    if os.path.exists(out) and not os.path.isdir(out):
        raise CliError(f"-o: {out} is a file; several images need a folder")
    check_distinct_names(meshes)
    os.makedirs(out, exist_ok=True)
    return [view_paths(m, out, views, image_suffix(outputs)) for m in meshes]


def render_options(args: argparse.Namespace) -> Dict[str, Any]:
    """The RenderOptions keywords of ``toonmesh render``'s flags."""
    style = STYLES[args.style]
    material_kw: Dict[str, Any] = {}
    if args.color is not None:
        material_kw["color"] = args.color
    if args.dither != "none":
        material_kw["dither"] = tm.Dither(args.dither, amount=args.dither_amount)
    if args.style == "hatching":
        material_kw.update(spacing=args.hatch_spacing, width=args.hatch_width, mode=args.hatch_mode)
    elif (args.hatch_spacing, args.hatch_width, args.hatch_mode) != tuple(HATCHING[k] for k in ("spacing", "width", "mode")):
        raise CliError("--hatch-spacing, --hatch-width, --hatch-mode: only with --style hatching")
    if args.style == "lambert" or args.style == "phong":
        if "dither" in material_kw:
            raise CliError(f"--dither: not with --style {args.style} (it has no bands to dither between)")
    options: Dict[str, Any] = dict(
        width=args.size[0], height=args.size[1], material=style(**material_kw), outputs=args.outputs,
        own_colors_material=None if args.color is not None else style(**material_kw, color=OWN_COLOURS_WHITE),
        msaa=args.msaa, supersample=args.supersample, band_antialias=args.band_antialias,
    )
    if args.shadows:
        key = tm.Light.key()
        shadows = tm.Shadows(size=args.shadow_size, bias=args.shadow_bias)
        options["lights"] = [tm.Light.directional(key.direction, color=key.color, intensity=key.intensity,
                                                  space=key.space, shadows=shadows)]
    if args.suggestive and args.outlines in ("none", "image"):
        raise CliError(f"--suggestive: suggestive contours are mesh lines; they need --outlines mesh or both, "
                       f"not {args.outlines}")
    if args.outlines != "none":
        options["outlines"] = tm.Outlines(
            args.outlines, width=args.outline_width, crease_angle=args.crease_angle, contours=args.contours,
            join_kinds=args.join_kinds,
            taper=args.taper, width_by_depth=args.width_by_depth,
            suggestive=args.suggestive or None, curvature_smoothing=args.curvature_smoothing,
            image_rule=args.image_rule, normal_angle=args.normal_angle,
            depth_jump=args.depth_jump, normal_threshold=args.normal_threshold, depth_threshold=args.depth_threshold)
    return options


def cmd_render(args: argparse.Namespace) -> int:
    """toonmesh render: mesh files to toon-shaded images."""
    from toonmesh.batch import render_views

    args.meshes = [mesh_file(m) for m in args.meshes]  # before any work: a typo in the last name costs nothing
    options = render_options(args)
    targets = _render_targets(args.meshes, args.out, args.views, args.outputs)
    t0 = time.perf_counter()
    bar = _progress(len(args.meshes) * args.views)
    rows: List[Dict[str, Any]] = []
    try:
        for mesh, files in zip(args.meshes, targets):
            done = render_views(
                mesh, files, up=args.up, backend=args.backend, smooth_iterations=args.smooth,
                smooth_method=args.smooth_method, normals=args.normals, **options,
            )
            rows.extend(done)
            if bar is not None:
                bar.update(len(done))
    finally:
        if bar is not None:
            bar.close()
    info = tm.gpu_info(args.backend)
    where = f"on {info['name']} ({info['backend']})"
    secs = time.perf_counter() - t0
    if len(rows) == 1:
        r = rows[0]
        print(f"wrote {r['path']} ({args.size[0]}x{args.size[1]}, {r['faces']:,} faces) in {secs:.2f} s {where}")
    else:
        render_s = sum(r["render_s"] for r in rows)
        print(f"wrote {len(rows)} images to {args.out} ({len(args.meshes)} meshes x {args.views} views) "
              f"in {secs:.2f} s, {render_s / len(rows) * 1e3:.1f} ms per render {where}")
    return 0


# --------------------------------------------------------------------------------------------
# smooth


def cmd_smooth(args: argparse.Namespace) -> int:
    """toonmesh smooth: smooth a mesh file and write the result, keeping its texture
    coordinates, texture, colours and normal seams."""
    import numpy as np

    placed = read_surfaces(mesh_file(args.input), keep_seams=True)
    if len(placed) != 1 or placed[0][1] is not None:
        raise ValueError(f"{args.input}: a scene of {len(placed)} placed meshes; toonmesh smooth takes one mesh "
                         "(toonmesh.load and toonmesh.smooth in Python take scenes apart)")
    surface = placed[0][0]
    V, F = surface.vertices, surface.faces
    fn = getattr(tm.smooth, args.method)
    options = {k: getattr(args, k) for k in ("iterations", "preset", "weights", "boundary") if getattr(args, k) is not None}
    # a file split at UV or normal seams is one surface: smooth it welded, or the seams crack
    if args.weld or surface.normals is not None or surface.uv is not None:
        options.update(pass_through(fn, "weld", True, "--weld"))
    t0 = time.perf_counter()
    out = fn(V, F, **options)
    secs = time.perf_counter() - t0
    normals = None if surface.normals is None else seam_normals(out, F, surface.normals)
    write_mesh(args.output, out, F, surface, normals)
    moved = float(np.linalg.norm(out - V, axis=1).max()) if len(V) else 0.0
    diagonal = float(np.linalg.norm(V.max(axis=0) - V.min(axis=0))) if len(V) else 0.0
    share = f" ({moved / diagonal:.2%} of the bounding-box diagonal)" if diagonal > 0 else ""
    described = ", ".join(f"{k}={v}" for k, v in options.items())
    print(f"{args.input}: {len(V):,} vertices, {len(F):,} faces; {args.method}({described}) in {secs * 1e3:.1f} ms")
    print(f"largest vertex move {moved:.4g}{share}; wrote {args.output}")
    return 0


# --------------------------------------------------------------------------------------------
# edges


def _add_contour_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--contours", choices=tuple(_core.CONTOUR_RULES), default=tm.Outlines().contours,
                   help="silhouettes on face edges (Kang et al.), the smooth contour through the faces "
                        "(clean on scans), or auto: smooth unless the mesh is flat-shaded; default: %(default)s")
    p.add_argument("--suggestive", action="store_true", help="add suggestive contours (DeCarlo et al.; default: off)")
    p.add_argument("--curvature-smoothing", type=float, default=None, metavar="EDGES",
                   help="the width their curvature is measured at, in mean edge lengths (0: the one-ring "
                        "estimate; default: 2, at most 1%% of the bounding-box diagonal)")
    p.add_argument("--join-kinds", action=argparse.BooleanOptionalAction, default=tm.Outlines().join_kinds,
                   help="join strokes of different kinds that meet end to end into one (default: %(default)s)")


def cmd_edges(args: argparse.Namespace) -> int:
    """toonmesh edges: outline edges of a mesh file as SVG line art or NPZ arrays."""
    from toonmesh import _line_drawing

    suffix = os.path.splitext(args.out)[1].lower()
    if suffix not in (".svg", ".npz"):
        raise CliError(f"-o: expected a .svg or .npz file name, got {args.out}")
    _strokes.check_pixels("--smooth-strokes", args.smooth_strokes, _strokes.MAX_SMOOTH)
    _strokes.check_pixels("--simplify", args.simplify)
    V, F = read_mesh(mesh_file(args.mesh))
    if args.eye is not None:
        if not any(args.eye):
            raise CliError("--eye: the direction to look from must not be 0 0 0")
        camera = tm.Camera.fit(args.eye, up=up_vector(args.up), orthographic=True)
    else:
        camera = tm.Camera.fit(view_direction(args.up), up=up_vector(args.up))
    w, h = args.size
    lines = _line_drawing.view_lines(V, F, camera, width=w, height=h, crease_angle=args.crease_angle,
                                     weld=args.weld, stroke_width=args.stroke_width, hidden=args.hidden,
                                     backend=args.backend, contours=args.contours, suggestive=args.suggestive,
                                     join_kinds=args.join_kinds, curvature_smoothing=args.curvature_smoothing)
    if suffix == ".svg":
        _line_drawing.write_svg(args.out, lines, smooth=args.smooth_strokes, order=args.order, simplify=args.simplify)
    else:
        _line_drawing.write_npz(args.out, lines)
    print(f"{args.mesh}: {_line_drawing.summary(lines)} ({w}x{h}) to {args.out}")
    return 0


# --------------------------------------------------------------------------------------------
# bench, demo


def cmd_bench(args: argparse.Namespace) -> int:
    """toonmesh bench: the benchmark suites (see ``python -m toonmesh.bench``)."""
    from toonmesh.bench.__main__ import run

    return run(args, args.extra)


def cmd_demo(args: argparse.Namespace) -> int:
    """toonmesh demo: the papers' pipeline on the built-in scene, to a PNG: the Stanford bunny
    smoothed (Al-Rousan et al.), shaded with the thresholded Phong model, with ink outlines
    (Kang et al.'s silhouettes and creases, Borquez and Yepez's image-space edges), on a ground
    plane."""
    t0 = time.perf_counter()
    import numpy as np

    from toonmesh.data import bunny

    V, F = bunny()
    V = tm.smooth.laplacian(V, F, iterations=5, preset="paper")
    # a ground plane under the bunny, as a second mesh with its own material
    lo, hi = V.min(axis=0), V.max(axis=0)
    c, r = (lo + hi) / 2, float(np.linalg.norm(hi - lo))
    plane_v = np.array([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]], dtype=np.float64) * r * 0.6
    plane_v += [c[0], lo[1], c[2]]
    plane_f = np.array([[0, 2, 1], [0, 3, 2]])
    scene = [
        tm.Mesh(V, F, material=tm.Material.thresholded_phong("#f08a3c", t_h=0.1, t_s=0.9)),
        tm.Mesh(plane_v, plane_f, material=tm.Material.bands("#9ec5e8", thresholds=(0.2, 0.6), values=(0.55, 0.8, 1.0))),
    ]
    result = tm.render(
        scene,
        camera=tm.Camera.fit((0.25, 0.35, 1.0), margin=0.8),
        lights=[tm.Light.directional((0.6, -0.5, -0.45), space="camera")],
        width=args.width,
        height=args.height,
        supersample=2,
        outlines=DEMO_OUTLINES,
        backend=args.backend,
        background=(1.0, 1.0, 1.0, 1.0),
    )
    result.save(args.out)
    info = tm.gpu_info(args.backend)
    print(f"wrote {args.out} ({result.width}x{result.height}) on {info['name']} ({info['backend']})")
    print("passes: " + ", ".join(f"{name} {secs * 1e3:.1f} ms" for name, secs in result.timings.items()))
    print(f"total from start: {time.perf_counter() - t0:.2f} s")
    return 0


# --------------------------------------------------------------------------------------------


def build_parser(prog: str = "toonmesh") -> argparse.ArgumentParser:
    """The argument parser of every subcommand."""
    from toonmesh.bench.__main__ import add_arguments as add_bench_arguments

    parser = _Parser(prog=prog, description="Mesh smoothing, outlines and toon rendering from the shell.")
    parser.add_argument("--version", action="version", version=f"toonmesh {tm.__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    backend = dict(choices=BACKENDS, default=None, help="GPU backend (default: $TOONMESH_BACKEND, else auto)")
    up = dict(choices=UP_AXES, default="y",
              help="the mesh's up axis; the view is from the front, slightly above (z: front is -y). Default: y")

    p = sub.add_parser("render", help="render mesh files to toon-shaded images",
                       description="Render mesh files (OBJ, PLY, STL, OFF, GLB, ...) to PNG images, or NPZ with "
                                   "normal/depth outputs.")
    p.add_argument("meshes", nargs="+", metavar="MESH",
                   help="mesh files, or the name of a mesh shipped with toonmesh (bunny)")
    p.add_argument("-o", "--out", required=True, metavar="OUT",
                   help="an image file (.png, .npz) for one mesh and view, else a folder")
    p.add_argument("--size", type=_size, default=(800, 600), metavar="WxH", help="image size in pixels (default 800x600)")
    p.add_argument("--style", choices=tuple(STYLES), default="bands", help="shading model (default: %(default)s)")
    p.add_argument("--color", default=None, metavar="#RRGGBB",
                   help="base colour of the material, multiplying a file's own colours and textures (default: "
                        "the style's, and white under a file's own colours, so that they show as they are)")
    p.add_argument("--dither", choices=("none",) + tuple(_core.DITHER_PATTERNS), default="none",
                   help="dither between neighbouring bands with this pattern (default: %(default)s)")
    p.add_argument("--dither-amount", type=float, default=tm.Dither().amount, metavar="X",
                   help="how far into each band the dither reaches, in units of the light term (default %(default)g)")
    p.add_argument("--hatch-spacing", type=float, default=HATCHING["spacing"], metavar="PX",
                   help="--style hatching: pixels between strokes (default %(default)g)")
    p.add_argument("--hatch-width", type=float, default=HATCHING["width"], metavar="PX",
                   help="--style hatching: stroke width in pixels (default %(default)g)")
    p.add_argument("--hatch-mode", choices=("field", "triplanar"), default=HATCHING["mode"],
                   help="--style hatching: strokes along the form, or straight triplanar strokes, which also "
                        "take a file's colours (default %(default)s)")
    p.add_argument("--band-antialias", action=argparse.BooleanOptionalAction, default=tm.RenderOptions().band_antialias,
                   help="blend across band borders over about a pixel; --no-band-antialias for the papers' hard "
                        "borders (default: %(default)s)")
    p.add_argument("--shadows", action="store_true", help="the key light casts shadows (default: off)")
    p.add_argument("--shadow-size", type=int, default=tm.Shadows().size, metavar="TEXELS",
                   help="the shadow map's side (default %(default)d)")
    p.add_argument("--shadow-bias", type=float, default=tm.Shadows().bias, metavar="X",
                   help="shadow depth bias in texels per unit of slope (default %(default)g)")
    p.add_argument("--outlines", choices=OUTLINES, default=DEMO_OUTLINES.kind,
                   help="ink lines: on the mesh, from the image, both, or none (default: %(default)s, as toonmesh demo)")
    p.add_argument("--outline-width", type=float, default=DEMO_LINE_WIDTH, metavar="PX",
                   help="line width in pixels (default %(default)g)")
    p.add_argument("--crease-angle", type=float, default=DEMO_OUTLINES.crease_angle, metavar="DEG",
                   help="crease lines where faces meet at more than this (default %(default)g)")
    p.add_argument("--taper", type=float, default=DEMO_OUTLINES.taper, metavar="PX",
                   help="mesh lines thin toward their ends over this many pixels, to a fifth of the width (default %(default)g)")
    p.add_argument("--width-by-depth", action=argparse.BooleanOptionalAction, default=DEMO_OUTLINES.width_by_depth,
                   help="mesh lines wider near the camera, thinner far away (default: %(default)s)")
    _add_contour_arguments(p)
    p.add_argument("--image-rule", choices=tuple(_core.IMAGE_RULES), default=DEMO_OUTLINES.image_rule,
                   help="image-space lines: between pixels whose normals turn or depths jump, width pixels wide "
                        "and the same at any scale (discontinuity), or the paper's thresholded Sobel (paper); "
                        "default: %(default)s")
    p.add_argument("--normal-angle", type=float, default=DEMO_OUTLINES.normal_angle, metavar="DEG",
                   help="discontinuity rule: lines where the normal turns by more than this between pixels "
                        "(default %(default)g)")
    p.add_argument("--depth-jump", type=float, default=DEMO_OUTLINES.depth_jump, metavar="PX",
                   help="discontinuity rule: lines where depth jumps by more than this many pixel footprints "
                        "(default %(default)g)")
    p.add_argument("--normal-threshold", type=float, default=DEMO_OUTLINES.normal_threshold, metavar="X",
                   help="paper rule: threshold of the Sobel response on normals (default %(default)g)")
    p.add_argument("--depth-threshold", type=float, default=DEMO_OUTLINES.depth_threshold, metavar="X",
                   help="paper rule: threshold of the Sobel response on depth (default %(default)g)")
    p.add_argument("--views", type=_positive, default=1, metavar="N",
                   help="a turntable of N views about the up axis (default 1)")
    p.add_argument("--up", **up)  # type: ignore[arg-type]
    p.add_argument("--smooth", type=_count, default=0, metavar="N", help="smoothing iterations before rendering (default 0)")
    p.add_argument("--smooth-method", choices=("paper",) + SMOOTH_METHODS, default="paper",
                   help="paper (default): each vertex to its neighbours' mean (the renderer's own); or a "
                        "toonmesh.smooth method")
    p.add_argument("--normals", type=_normals, default="smooth", metavar="MODE",
                   help="smooth (default), flat (facets), or auto: hard edges where faces meet at more than "
                        "30 degrees, for boxes and CAD parts (auto:DEG for another angle)")
    p.add_argument("--outputs", type=_outputs, default=["color"], metavar="LIST",
                   help=f"comma-separated: {', '.join(_core.IMAGE_OUTPUTS)} (default color; anything but color "
                        "alone writes .npz)")
    # ranges are the renderer's to check (it knows the device)
    p.add_argument("--msaa", type=_positive, default=1, metavar="N", help="samples per pixel (1 or 4; default 1)")
    p.add_argument("--supersample", type=_positive, default=1, metavar="N",
                   help="render N times larger and average (default 1)")
    p.add_argument("--backend", **backend)  # type: ignore[arg-type]
    p.set_defaults(run=cmd_render)

    p = sub.add_parser("smooth", help="smooth a mesh file", description="Smooth a mesh file and write the result "
                                                                         "(the format follows OUT's suffix).")
    p.add_argument("input", metavar="IN", help="mesh file to read, or the name of a mesh shipped with toonmesh (bunny)")
    p.add_argument("output", metavar="OUT", help="mesh file to write (.obj, .ply, .stl, .off, .glb, ...)")
    p.add_argument("--method", choices=SMOOTH_METHODS, default="laplacian", help="default: %(default)s")
    p.add_argument("--iterations", type=_count, default=None, metavar="N", help="default: the method's (or preset's)")
    p.add_argument("--preset", choices=("trimesh", "pymeshlab", "paper"), default=None,
                   help="reproduce a peer library's filter (see the README; default: none)")
    p.add_argument("--weights", choices=("uniform", "cotangent", "distance"), default=None,
                   help="default: the method's (or preset's)")
    p.add_argument("--boundary", choices=("fixed", "free", "slide"), default=None,
                   help="default: the method's (or preset's)")
    p.add_argument("--weld", action="store_true",
                   help="treat vertices at the same position as one (default: off, but always on for a file "
                        "whose texture coordinates or normals split its vertices)")
    p.set_defaults(run=cmd_smooth)

    p = sub.add_parser("edges", help="outline edges of a mesh file as SVG or NPZ",
                       description="Silhouette, boundary, crease and non-manifold edges of one view, drawn as SVG "
                                   "(hidden lines removed) or saved as NPZ arrays.")
    p.add_argument("mesh", metavar="MESH", help="a mesh file, or the name of a mesh shipped with toonmesh (bunny)")
    p.add_argument("-o", "--out", required=True, metavar="OUT", help="lines.svg or lines.npz")
    p.add_argument("--eye", type=float, nargs=3, default=None, metavar=("X", "Y", "Z"),
                   help="look orthographically along -eye (default: the renderer's fit camera from --up)")
    p.add_argument("--up", **up)  # type: ignore[arg-type]
    p.add_argument("--crease-angle", type=float, default=tm.Outlines().crease_angle, metavar="DEG",
                   help="crease edges where faces meet at more than this (default %(default)g)")
    p.add_argument("--no-weld", dest="weld", action="store_false",
                   help="keep vertices at the same position apart (seams then show as boundaries; default: welded)")
    p.add_argument("--size", type=_size, default=(800, 600), metavar="WxH", help="drawing size (default 800x600)")
    p.add_argument("--hidden", action="store_true", help="draw hidden lines too (dashed; default: off)")
    _add_contour_arguments(p)
    p.add_argument("--stroke-width", type=float, default=tm.LineStyle().width, metavar="PX",
                   help="line width in pixels (default %(default)g)")
    p.add_argument("--smooth-strokes", type=float, default=0.0, metavar="PX",
                   help="smooth each stroke of the SVG over this many pixels along it; no point moves more "
                        "(default 0: off)")
    p.add_argument("--order", choices=_strokes.ORDERS, default="drawing",
                   help="drawing: as found; plotter: each next stroke nearest where the pen stopped "
                        "(default: %(default)s)")
    p.add_argument("--simplify", type=float, default=_strokes.SIMPLIFY, metavar="PX",
                   help="drop points within this many pixels of each stroke (default %(default)g; 0 keeps every point)")
    p.add_argument("--backend", **backend)  # type: ignore[arg-type]
    p.set_defaults(run=cmd_edges)

    p = sub.add_parser("bench", help="run the benchmark suites", description="Benchmarks: toonmesh and the peer "
                                                                            "libraries side by side.")
    add_bench_arguments(p)
    p.set_defaults(run=cmd_bench)

    p = sub.add_parser("demo", help="render the built-in scene (the Stanford bunny, toon-shaded) to a PNG")
    p.add_argument("--out", default="toonmesh-demo.png", help="output PNG path (default: %(default)s)")
    p.add_argument("--width", type=_positive, default=800, help="pixels (default %(default)d)")
    p.add_argument("--height", type=_positive, default=600, help="pixels (default %(default)d)")
    p.add_argument("--backend", **backend)  # type: ignore[arg-type]
    p.set_defaults(run=cmd_demo)
    return parser


def _one_line(exc: BaseException) -> str:
    return " ".join(str(exc).split()) or type(exc).__name__


def main(argv: Optional[List[str]] = None) -> int:
    """Runs the command line; returns the exit status (0, 1 for a failure, 2 for a bad command
    line, 130 when interrupted)."""
    parser = build_parser()
    with warnings.catch_warnings():
        warnings.simplefilter("default")
        warnings.showwarning = _one_line_warning  # type: ignore[assignment]
        return _run(parser, argv)


def _one_line_warning(message: Any, category: Any, *args: Any, **kwargs: Any) -> None:
    """A warning (what a file holds that is not drawn) as one line on stderr."""
    print(f"toonmesh: warning: {_one_line(message)}", file=sys.stderr)


def _run(parser: argparse.ArgumentParser, argv: Optional[List[str]]) -> int:
    from toonmesh.bench.__main__ import takes_extra_options

    try:
        args, extra = parser.parse_known_args(argv)
        if extra and not (args.command == "bench" and takes_extra_options(args.suite)):
            parser.error(f"unrecognised arguments: {' '.join(extra)}")
        args.extra = extra
        return int(args.run(args) or 0)
    except CliError as exc:
        print(f"{exc.prog}: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except (OSError, ValueError, TypeError, IndexError, ImportError, RuntimeError) as exc:
        print(f"toonmesh: error: {_one_line(exc)}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
