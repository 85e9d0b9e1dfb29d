"""The command line: ``toonmesh`` (console script) and ``python -m toonmesh``.

    toonmesh render MESH... -o OUT|--video OUT [--size WxH] [--style S] [--normals MODE] [--views N [--fps N]] [--up x|y|z] ...
    toonmesh smooth IN -o OUT [--method M] [--iterations N] [--preset P] [--lamb X] ... [--crease-angle DEG] [--weld]
    toonmesh edges MESH -o lines.svg|lines.npz [--eye X Y Z] [--crease-angle DEG] [--smooth-strokes PX]
    toonmesh bench smooth|edges|render|effects|viewer|all [--quick] [--json FILE]
    toonmesh demo
    toonmesh --version

Mesh files are read and written through trimesh (``pip install 'toonmesh[io]'``). A mistake
(a missing file, a bad size, an unreadable mesh, a missing package) prints one line to stderr and
exits with status 1 (2 for a bad command line); ``toonmesh COMMAND --help`` lists the options.

A flag that sets one of the core's settings takes its choices, default and help from the core's
description of it (``_described_flags``); a value the core refuses is a bad command line naming
the flag.
"""

from __future__ import annotations

import argparse
import inspect
import os
import sys
import time
import warnings
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

import numpy as np

from toonmesh import _core, smooth
from toonmesh.rendering import _strokes
from toonmesh._core import __version__
from toonmesh.arguments._described import described
from toonmesh.arguments._described_flags import (
    CORE_DEFAULT, FLAGS_BY_SETTING, add_described, add_param, errors_as_flags, sets, styles,
)
from toonmesh.files._write import (
    IMAGE_SUFFIXES, Part, check_distinct_names, check_not_input, check_writable, image_suffix, seam_normals, view_paths,
    write_parts,
)
from toonmesh.edges._line_drawing import summary, view_lines, write_npz, write_svg
from toonmesh.files._load import (
    OWN_COLOURS_WHITE, Surface, file_up_axis, read_mesh, read_surfaces, up_conventions,
)
from toonmesh.edges import feature_edges
from toonmesh._core import (Camera, Dither, EyeDome, Light, LineStyle, Material, Outlines, Paper, RenderOptions, Rim,
                            Shadows)
from toonmesh.rendering._render import Mesh, RenderResult, gpu_info, render
from toonmesh.scene._scene import normal_mode
from toonmesh.rendering._video import DEFAULT_FPS, DEFAULT_SECONDS, VIDEO_SUFFIXES, check_fps, check_video_size, save_video, video_writer
from toonmesh.rendering._views import check_views
from toonmesh.batch import SMOOTH_METHODS as RENDER_SMOOTH_METHODS, render_views

__all__ = ["main"]

#: The command line's word for "leave it out", before the core's names of --outlines and --dither.
NONE = "none"
#: The style whose strokes --hatch-spacing, --hatch-width and --hatch-mode set (Material.hatching).
HATCHING = "hatching"
HATCH_FLAGS = ("spacing", "width", "mode")
#: Image size of ``toonmesh render``, ``edges`` and ``demo`` unless --size (--width, --height) says.
DEFAULT_SIZE = (800, 600)
#: ``toonmesh smooth``'s method unless --method says: Taubin's, which does not shrink the mesh.
SMOOTH_METHOD = "taubin"
#: ``toonmesh smooth`` keeps in place the vertices on edges whose faces meet at more than this
#: many degrees, unless --crease-angle says: a CAD part keeps its edges and corners (a coarse one
#: is otherwise rounded into a blob), while the noise of a scan, folding its faces by less, is
#: smoothed (at 30 degrees, the renderer's crease, strong noise is kept as creases).
SMOOTH_CREASE_ANGLE = 60.0
#: The metavar of ``toonmesh smooth``'s flags of numbers (--iterations N, --lamb X).
SMOOTH_METAVARS = {"int": "N", "float": "X"}
#: A smoothing whose largest vertex move is more than this share of the model's bounding-box
#: diagonal is named in a warning: the shape itself changed.
SMOOTH_MOVE_WARNING = 0.05

#: The ink lines of ``toonmesh demo``, and of ``toonmesh render`` unless its flags say otherwise.
DEMO_OUTLINES = Outlines("mesh", width=2.0, crease_angle=60.0)
DEMO_LINE_WIDTH = float(getattr(DEMO_OUTLINES.styles["silhouette"], "width"))


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
    """--size: WIDTHxHEIGHT, or one number for a square; the core checks the range."""
    parts = text.lower().split("x")
    try:
        if len(parts) > 2:
            raise ValueError
        w, h = int(parts[0]), int(parts[-1])
        RenderOptions(width=w, height=h)
    except ValueError as exc:
        why = f"{exc}; " if str(exc).startswith(("width", "height")) else ""
        raise argparse.ArgumentTypeError(f"{why}expected WIDTHxHEIGHT in pixels (e.g. 640x480), got {text!r}") from None
    return w, h


def _fps(text: str) -> int:
    try:
        return check_fps(int(text))
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc).removeprefix("fps: ") if "fps:" in str(exc)
                                         else f"expected an integer, got {text!r}") from None


def _views(text: str) -> int:
    try:
        return check_views(int(text))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected an integer >= 1, got {text!r}") from None


def _normals(text: str) -> Any:
    """--normals: a normal mode by name, or auto:DEGREES; the core checks both."""
    name, sep, angle = text.partition(":")
    try:
        return normal_mode((name, float(angle)) if sep else name, 0)
    except ValueError as exc:
        why = f"{exc}; " if str(exc).startswith("normals") else ""
        raise argparse.ArgumentTypeError(f"{why}expected a mode or auto:DEGREES (e.g. auto:45), got {text!r}") from None


def _outputs(text: str) -> List[str]:
    names = [n.strip() for n in text.split(",") if n.strip()]
    bad = [n for n in names if n not in _core.IMAGE_OUTPUTS]
    if bad or not names:
        raise argparse.ArgumentTypeError(
            f"expected a comma-separated list of {', '.join(_core.IMAGE_OUTPUTS)}, got {text!r}")
    return names


def _keyword_default(fn: Callable[..., Any], keyword: str) -> Any:
    """The default of ``fn``'s ``keyword``: the flag that passes it on starts where ``fn`` does."""
    return inspect.signature(fn).parameters[keyword].default


def default_style() -> str:
    """--style's default: the model of the core's default material."""
    return str(described(RenderOptions, "material")["default"].model).replace("_", "-")


def _add_size_argument(p: argparse.ArgumentParser, what: str) -> None:
    size = p.add_argument("--size", type=_size, default=DEFAULT_SIZE, metavar="WxH",
                          help=f"{what} (default {DEFAULT_SIZE[0]}x{DEFAULT_SIZE[1]})")
    sets(p, size, (RenderOptions, "width"), (RenderOptions, "height"))


def pass_through(fn: Callable[..., Any], keyword: str, value: Any, flag: str) -> Dict[str, Any]:
    """``{keyword: value}`` when ``fn`` takes that keyword, for a flag whose feature may not be
    in this version of toonmesh yet; otherwise a one-line error naming the flag."""
    if keyword not in inspect.signature(fn).parameters:
        name = getattr(fn, "__qualname__", getattr(fn, "__name__", "the function"))
        raise CliError(f"{flag}: not available in toonmesh {__version__} ({name} has no {keyword}= option)")
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
    """The RenderOptions keywords of ``toonmesh render``'s flags, checked by the core."""
    style = getattr(Material, args.style.replace("-", "_"))
    material_kw: Dict[str, Any] = {}
    if args.color is not None:
        material_kw["color"] = args.color
    material_kw["opacity"] = args.opacity
    if args.dither != NONE:
        with errors_as_flags(args, Dither):
            material_kw["dither"] = Dither(args.dither, amount=args.dither_amount)
    if args.rim != NONE:
        with errors_as_flags(args, Rim):
            material_kw["rim"] = Rim(args.rim_color, width=args.rim_width, side=args.rim)
    hatch = {name: getattr(args, f"hatch_{name}") for name in HATCH_FLAGS}
    if args.style == HATCHING:
        material_kw.update(hatch)
    elif any(value != described(Material, name, HATCHING)["default"] for name, value in hatch.items()):
        raise CliError(f"{', '.join('--hatch-' + name for name in HATCH_FLAGS)}: only with --style {HATCHING}")
    with errors_as_flags(args, Material):  # a model without bands takes no dither: the core says so
        material = style(**material_kw)
        own_colors_material = None if args.color is not None else style(**material_kw, color=OWN_COLOURS_WHITE)
    options: Dict[str, Any] = dict(
        width=args.size[0], height=args.size[1], material=material, outputs=args.outputs,
        own_colors_material=own_colors_material,
        msaa=args.msaa, supersample=args.supersample, pixel_ratio=args.pixel_ratio,
        band_antialias=args.band_antialias, glass_layers=args.glass_layers,
    )
    if args.paper != NONE:
        with errors_as_flags(args, Paper):
            options["paper"] = Paper(space=args.paper, strength=args.paper_strength)
    if args.eye_dome is not None:
        with errors_as_flags(args, EyeDome):
            options["eye_dome"] = EyeDome(strength=args.eye_dome, radius=args.eye_dome_radius)
    if args.shadows:
        with errors_as_flags(args, Shadows):
            options["lights"] = [Light.key().replace(shadows=Shadows(size=args.shadow_size, bias=args.shadow_bias, strength=args.shadow_strength))]
    if args.outlines == NONE and args.suggestive:
        raise CliError(f"--suggestive: suggestive contours are ink lines; not with --outlines {NONE}")
    if args.outlines != NONE:
        with errors_as_flags(args, Outlines):
            options["outlines"] = Outlines(
                args.outlines, width=args.outline_width, crease_angle=args.crease_angle, contours=args.contours,
                join_kinds=args.join_kinds, taper=args.taper, width_by_depth=args.width_by_depth,
                suggestive=args.suggestive or None, curvature_smoothing=args.curvature_smoothing,
                suggestive_coherence=args.suggestive_coherence,
                **_visibility_options(args), image_rule=args.image_rule, normal_angle=args.normal_angle, depth_jump=args.depth_jump,
                normal_threshold=args.normal_threshold, depth_threshold=args.depth_threshold)
    return options


def _is_video(meshes: Sequence[str], out: str, views: int, outputs: List[str], size: Tuple[int, int],
              who: str) -> bool:
    """Whether ``out`` (given as ``who``: -o or --video) names a video (a turntable of one mesh's
    colour), its writer and size checked before any render."""
    suffix = os.path.splitext(out)[1].lower()
    if suffix not in VIDEO_SUFFIXES:
        if who == "--video":
            raise CliError(f"--video: expected a {', '.join(VIDEO_SUFFIXES)} file name, got {out}")
        return False
    if len(meshes) != 1:
        raise CliError(f"{who}: a {suffix} video is the turntable of one mesh, got {len(meshes)} meshes")
    if views < 2:
        raise CliError(f"{who}: a {suffix} video needs --views N with N >= 2 (the turntable's frames), got {views}")
    if outputs != ["color"]:
        raise CliError(f"{who}: a {suffix} video holds the colour output only, not {','.join(outputs)}")
    check_video_size(suffix, size[0], size[1], "--size")
    video_writer(suffix, who)
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    return True


def cmd_render(args: argparse.Namespace) -> int:
    """toonmesh render: mesh files to toon-shaded images, or one mesh's turntable as a video."""
    args.meshes = [mesh_file(m) for m in args.meshes]  # before any work: a typo in the last name costs nothing
    options = render_options(args)
    who = "--video" if args.video is not None else "-o"
    args.out = args.video if args.video is not None else args.out
    video = os.path.splitext(args.out)[1].lower() in VIDEO_SUFFIXES or who == "--video"
    if args.views is None:  # one view, or a turntable of DEFAULT_SECONDS at --fps
        args.views = max(2, round(DEFAULT_SECONDS * args.fps)) if video else 1
    if _is_video(args.meshes, args.out, args.views, args.outputs, args.size, who):
        frames: List[np.ndarray] = []
        _render_to(args, options, [[args.out] * args.views], quiet=True,
                   save=lambda result, _: frames.append(result.color))
        save_video(args.out, np.stack(frames), args.fps, progress=sys.stderr.isatty(), who=who)
        print(f"wrote {args.out} ({len(frames)} frames at {args.fps} fps, {args.size[0]}x{args.size[1]})")
        return 0
    return _render_to(args, options, _render_targets(args.meshes, args.out, args.views, args.outputs))


def _render_to(args: argparse.Namespace, options: Dict[str, Any], targets: List[List[str]], quiet: bool = False,
               **save: Any) -> int:
    """Renders every mesh's views into ``targets`` (``save``: as ``render_views`` takes it) and
    says what it wrote (unless ``quiet``: the frames of a video) and which up axis each mesh was
    drawn with."""
    t0 = time.perf_counter()
    bar = _progress(len(args.meshes) * args.views)
    rows: List[Dict[str, Any]] = []
    try:
        for mesh, files in zip(args.meshes, targets):
            # the renderer checks what depends on the device (msaa) and the smoothing
            with errors_as_flags(args, RenderOptions, render_views, smooth):
                done = render_views(
                    mesh, files, up=args.up, backend=args.backend, smooth_iterations=args.smooth,
                    smooth_method=args.smooth_method, normals=args.normals, **save, **options,
                )
            rows.extend(done)
            if bar is not None:
                bar.update(len(done))
    finally:
        if bar is not None:
            bar.close()
    info = gpu_info(args.backend)
    where = f"on {info['name']} ({info['backend']})"
    secs = time.perf_counter() - t0
    ups = "; ".join(dict.fromkeys(up_note(r["mesh"], args.up, r["up"]) for r in rows))
    if quiet:
        pass
    elif len(rows) == 1:
        r = rows[0]
        drawn = ", ".join(f"{r[k]:,} {k}" for k in ("faces", "points", "segments") if r[k]) or "0 faces"
        print(f"wrote {r['path']} ({args.size[0]}x{args.size[1]}, {drawn}) in {secs:.2f} s {where}")
    else:
        render_s = sum(r["render_s"] for r in rows)
        print(f"wrote {len(rows)} images to {args.out} ({len(args.meshes)} meshes x {args.views} views) "
              f"in {secs:.2f} s, {render_s / len(rows) * 1e3:.1f} ms per render {where}")
    print(ups)
    return 0


def up_note(path: str, given: Optional[str], used: str) -> str:
    """Which up axis a mesh file was drawn with, and why: ``--up``, its format's convention, or
    the default where the format has none."""
    name = os.path.basename(path)
    if given is not None:
        return f"{name}: up {used} (--up)"
    suffix = os.path.splitext(path)[1].lower()
    why = f"the {suffix} convention" if file_up_axis(path) is not None else f"the default; {suffix or 'this file'} has no convention"
    return f"{name}: up {used} ({why}; --up to change)"


# --------------------------------------------------------------------------------------------
# smooth


def _smooth_output(args: argparse.Namespace) -> str:
    """OUT of toonmesh smooth: ``-o OUT``, or the positional OUT of earlier versions."""
    if args.out is not None and args.output is not None and args.out != args.output:
        raise CliError(f"-o: the output is given twice ({args.out} and {args.output}): give it once")
    out = args.out if args.out is not None else args.output
    if out is None:
        raise CliError("-o: the file to write is missing (toonmesh smooth IN -o OUT)")
    return str(out)


def smoothing_keywords() -> Dict[str, List[Tuple[str, Dict[str, Any]]]]:
    """Each keyword of the methods ``toonmesh smooth --method`` offers, as the core describes
    them: ``{keyword: [(method, its description of the keyword), ...]}``, in the order the
    methods list them; a flag each (``--max-iter`` for ``max_iter``), but --weld, the command
    line's own (on for a file split at seams)."""
    by_name: Dict[str, List[Tuple[str, Dict[str, Any]]]] = {}
    for method in _core.SMOOTH_METHODS:
        for k in smooth._DESCRIBED[method]["keywords"]:
            if k["name"] != "weld":
                by_name.setdefault(k["name"], []).append((method, k))
    return by_name


def _smoothing_defaults(uses: List[Tuple[str, Dict[str, Any]]]) -> str:
    """A smoothing flag's default in words, each method's with its presets' where they differ:
    ``laplacian: 0.5 (paper, pymeshlab presets: 1.0); taubin: 0.5``; just the default where every
    method's is the same."""
    by_text: Dict[str, List[str]] = {}
    for method, k in uses:
        presets = smooth._presets_in_words(k)
        text = smooth._default_in_words(k).replace("default ", "", 1) + (f" ({presets})" if presets else "")
        by_text.setdefault(text, []).append(method)
    if len(by_text) == 1 and len(uses) == len(_core.SMOOTH_METHODS):
        return next(iter(by_text))
    return "; ".join(f"{', '.join(methods)}: {text}" for text, methods in by_text.items())


def _check_smoothing_flags(args: argparse.Namespace, fn: Callable[..., Any], options: Dict[str, Any]) -> None:
    """A flag of a keyword the chosen method does not take is a bad command line naming it and
    the flags the method does take."""
    takes = inspect.signature(fn).parameters
    for name in options:
        if name not in takes:
            flags = [f"--{k.replace('_', '-')}" for k in smoothing_keywords() if k in takes]
            action = getattr(args, FLAGS_BY_SETTING)[(smooth.__name__, name)]
            raise argparse.ArgumentError(action, f"--method {args.method} takes no such option (its own: "
                                                 f"{', '.join(flags)})")


def cmd_smooth(args: argparse.Namespace) -> int:
    """toonmesh smooth: smooth a mesh file and write the result, keeping its texture
    coordinates, texture, colours, material colours, normal seams and parts."""

    out = _smooth_output(args)
    source = mesh_file(args.input)
    check_not_input(out, source, args.force)
    placed = read_surfaces(source, keep_seams=True)
    check_writable(out, len(placed), args.input)
    # each geometry once, with its placements; all smoothed together where the first one puts it
    grouped: Dict[int, Tuple[Surface, List[Any]]] = {}
    for surface, transform in placed:
        grouped.setdefault(id(surface), (surface, []))[1].append(transform)
    surfaces = [s for s, _ in grouped.values()]
    frames = [_frame(ts[0]) for _, ts in grouped.values()]
    world = [s.vertices @ T[:3, :3].T + T[:3, 3] for s, T in zip(surfaces, frames)]
    starts = np.cumsum([0] + [len(w) for w in world])
    V = np.concatenate(world)
    F = np.concatenate([s.faces + start for s, start in zip(surfaces, starts)])
    fn = getattr(smooth, args.method)
    options = {k: getattr(args, k) for k in smoothing_keywords() if getattr(args, k) is not None}
    _check_smoothing_flags(args, fn, options)
    # a file split at UV or normal seams, or into parts, is one surface: smooth it welded, or the seams crack
    if args.weld or len(surfaces) > 1 or any(s.normals is not None or s.uv is not None for s in surfaces):
        options.update(pass_through(fn, "weld", True, "--weld"))
    crease = args.crease_angle if args.crease_angle is not None else 180.0 if args.preset else SMOOTH_CREASE_ANGLE
    kept = np.zeros(0, np.int64)
    if crease != 180:  # vertices on creases stay: a CAD part keeps its edges and corners (the core checks DEG)
        with errors_as_flags(args, feature_edges):
            kept = np.unique(feature_edges(V, F, crease, weld=bool(options.get("weld"))).crease)
    t0 = time.perf_counter()
    with errors_as_flags(args, smooth):
        result = fn(V, F, **options, **({"pinned": kept} if len(kept) else {}))
    secs = time.perf_counter() - t0
    parts = []
    for k, (surface, transforms) in enumerate(grouped.values()):
        moved = result[starts[k] : starts[k + 1]] - world[k]  # back into the geometry's own frame
        R = frames[k][:3, :3]
        local = surface.vertices + (moved if np.array_equal(R, np.eye(3)) else moved @ np.linalg.pinv(R).T)
        normals = None if surface.normals is None else seam_normals(local, surface.faces, surface.normals)
        parts.append(Part(surface, local, normals, transforms))
    lost = write_parts(out, parts, force=args.force)
    if lost:
        warnings.warn(f"{out}: a {os.path.splitext(out)[1] or 'file without suffix'} file as written here holds no "
                      f"{', '.join(lost)}: not written", stacklevel=2)
    moves = np.linalg.norm(result - V, axis=1)
    moved, diagonal = (float(moves.max()), float(np.linalg.norm(np.ptp(V, axis=0)))) if len(V) else (0.0, 0.0)
    share = f" ({moved / diagonal:.2%} of the bounding-box diagonal)" if diagonal > 0 else ""
    given = ", ".join(f"{k}={v}" for k, v in options.items())
    pieces = f" in {len(surfaces)} parts" if len(surfaces) > 1 else ""
    print(f"{args.input}: {len(V):,} vertices, {len(F):,} faces{pieces}; {args.method}({given}) in {secs * 1e3:.1f} ms"
          + (f", {len(kept):,} vertices on creases over {crease:g} degrees kept" if len(kept) else ""))
    print(f"largest vertex move {moved:.4g}{share}; wrote {out}")
    if diagonal > 0 and moved > SMOOTH_MOVE_WARNING * diagonal:
        other = "" if args.method == SMOOTH_METHOD else f", --method {SMOOTH_METHOD}"
        warnings.warn(f"{out}: smoothing moved a vertex {moved / diagonal:.1%} of the model's size (its bounding-box "
                      f"diagonal), more than {SMOOTH_MOVE_WARNING:.0%}: the shape changed (fewer --iterations{other} "
                      "or a smaller --crease-angle keep it)", stacklevel=2)
    return 0


def _frame(transform: Any) -> Any:
    """A placement's 4x4 transform (identity for none)."""
    import numpy as np

    return np.eye(4) if transform is None else np.asarray(transform, dtype=np.float64)


# --------------------------------------------------------------------------------------------
# edges


def _add_contour_arguments(p: argparse.ArgumentParser, base: Optional[Outlines] = None) -> None:
    """The flags of the lines found on the mesh that render and edges share; their defaults are
    ``base``'s (None: the core's)."""
    def default(name: str) -> Any:
        return CORE_DEFAULT if base is None else getattr(base, name)

    add_described(p, "--contours", Outlines, "contours", default=default("contours"))
    add_described(p, "--suggestive", Outlines, "suggestive", action="store_true")
    add_described(p, "--curvature-smoothing", Outlines, "curvature_smoothing", default=default("curvature_smoothing"),
                  metavar="EDGES")
    add_described(p, "--suggestive-coherence", Outlines, "suggestive_coherence",
                  default=default("suggestive_coherence"))
    add_described(p, "--join-kinds", Outlines, "join_kinds", default=default("join_kinds"))
    add_described(p, "--visibility", Outlines, "visibility", default=default("visibility"))
    add_described(p, "--hidden", Outlines, "hidden", action="store_true", help_before="draw ")
    add_described(p, "--max-occlusion", Outlines, "max_occlusion", default=default("max_occlusion"), metavar="N")
    add_described(p, "--no-intersection", Outlines, "intersection", action="store_false", dest="intersection",
                  help_before="leave out the lines ")


def _visibility_options(args: argparse.Namespace) -> Dict[str, Any]:
    """The keywords of :class:`Outlines` that the visibility flags give (the core's defaults
    where a flag is not given)."""
    options: Dict[str, Any] = {"visibility": args.visibility, "max_occlusion": args.max_occlusion}
    if args.hidden:
        options["hidden"] = True
    if not args.intersection:
        options["intersection"] = False
    return {k: v for k, v in options.items() if v is not CORE_DEFAULT}


def cmd_edges(args: argparse.Namespace) -> int:
    """toonmesh edges: outline edges of a mesh file as SVG line art or NPZ arrays."""
    suffix = os.path.splitext(args.out)[1].lower()
    if suffix not in (".svg", ".npz"):
        raise CliError(f"-o: expected a .svg or .npz file name, got {args.out}")
    _strokes.check_pixels("--smooth-strokes", args.smooth_strokes, _strokes.MAX_SMOOTH)
    _strokes.check_pixels("--simplify", args.simplify)
    with errors_as_flags(args, Outlines):
        outlines = Outlines("mesh", width=args.stroke_width, crease_angle=args.crease_angle, weld=args.weld,
                            contours=args.contours, suggestive=args.suggestive or None, join_kinds=args.join_kinds,
                            curvature_smoothing=args.curvature_smoothing,
                            suggestive_coherence=args.suggestive_coherence, **_visibility_options(args))
    path = mesh_file(args.mesh)
    V, F = read_mesh(path)
    with errors_as_flags(args, Camera):
        camera = Camera.fit(args.eye, orthographic=True) if args.eye is not None else Camera.fit()
    w, h = args.size
    up = args.up if args.up is not None else file_up_axis(path)
    lines = view_lines(V, F, camera, outlines, width=w, height=h, backend=args.backend, up=up)
    if suffix == ".svg":
        write_svg(args.out, lines, smooth=args.smooth_strokes, order=args.order, simplify=args.simplify)
    else:
        write_npz(args.out, lines)
    print(f"{args.mesh}: {summary(lines)} ({w}x{h}) to {args.out}")
    print(up_note(path, args.up, lines["seen"].up))
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
    V = smooth.laplacian(V, F, iterations=5, preset="paper")
    # a ground plane under the bunny, as a second mesh with its own material
    lo, hi = V.min(axis=0), V.max(axis=0)
    c, r = (lo + hi) / 2, float(np.linalg.norm(hi - lo))
    plane_v = np.array([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]], dtype=np.float64) * r * 0.45
    plane_v += [c[0], lo[1], c[2]]
    plane_f = np.array([[0, 2, 1], [0, 3, 2]])
    scene = [
        Mesh(V, F, material=Material.thresholded_phong("#f08a3c", t_h=0.1, t_s=0.9)),
        Mesh(plane_v, plane_f, material=Material.bands("#9ec5e8", thresholds=(0.2, 0.6), values=(0.55, 0.8, 1.0))),
    ]
    with errors_as_flags(args, RenderOptions):
        result = render(
            scene,
            camera=Camera.fit((0.25, 0.35, 1.0)),  # framed as near as the bunny and its ground allow
            lights=[Light.directional((0.6, -0.5, -0.45), space="camera")],
            width=args.width,
            height=args.height,
            supersample=2,
            outlines=DEMO_OUTLINES,
            backend=args.backend,
            background=(1.0, 1.0, 1.0, 1.0),
        )
    result.save(args.out)
    info = gpu_info(args.backend)
    print(f"wrote {args.out} ({result.width}x{result.height}) on {info['name']} ({info['backend']})")
    print("passes: " + ", ".join(f"{name} {secs * 1e3:.1f} ms" for name, secs in result.timings.items()))
    print(f"total from start: {time.perf_counter() - t0:.2f} s")
    return 0


# --------------------------------------------------------------------------------------------


def build_parser(prog: str = "toonmesh") -> argparse.ArgumentParser:
    """The argument parser of every subcommand."""
    from toonmesh.bench.__main__ import add_arguments as add_bench_arguments

    parser = _Parser(prog=prog, description="Mesh smoothing, outlines and toon rendering from the shell.")
    parser.add_argument("--version", action="version", version=f"toonmesh {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    backend = dict(choices=_core.BACKENDS, default=None, help="GPU backend (default: $TOONMESH_BACKEND, else auto)")
    up_help = f"; the formats' conventions: {up_conventions()}"

    p = sub.add_parser("render", help="render mesh files to toon-shaded images",
                       description="Render mesh files (OBJ, PLY, STL, OFF, GLB, ...) to PNG images, or NPZ with "
                                   "normal/depth outputs.")
    p.add_argument("meshes", nargs="+", metavar="MESH",
                   help="mesh files, or the name of a mesh shipped with toonmesh (bunny)")
    out = p.add_mutually_exclusive_group(required=True)
    out.add_argument("-o", "--out", metavar="OUT",
                     help="an image file (.png, .npz) for one mesh and view, a video (.gif, .mp4, .webm) of one "
                          "mesh's --views, else a folder")
    out.add_argument("--video", metavar="OUT",
                     help=f"one mesh's turntable as a video ({', '.join(VIDEO_SUFFIXES)}): --views frames all the way "
                          f"round, by default {DEFAULT_SECONDS:g} seconds at --fps")
    _add_size_argument(p, "image size in pixels")
    p.add_argument("--style", choices=styles(Material), default=default_style(),
                   help="shading model: one of Material's constructors (default: %(default)s)")
    color = p.add_argument("--color", default=None, metavar="#RRGGBB",
                           help="base colour of the material, multiplying a file's own colours and textures "
                                "(default: the style's, and white under a file's own colours, so that they show "
                                "as they are)")
    sets(p, color, (Material, "color"))
    add_described(p, "--opacity", Material, "opacity", constructor=default_style(), metavar="A")
    add_described(p, "--glass-layers", RenderOptions, "glass_layers", metavar="N")
    add_described(p, "--dither", Dither, "pattern", default=NONE, extra_choices=(NONE,),
                  help_before="dither between neighbouring bands; ", also_sets=[(Material, "dither")])
    add_described(p, "--dither-amount", Dither, "amount", metavar="X")
    add_described(p, "--rim", Rim, "side", default=NONE, extra_choices=(NONE,),
                  help_before="a rim light along the silhouette; ", also_sets=[(Material, "rim")])
    add_described(p, "--rim-color", Rim, "color", metavar="#RRGGBB")
    add_described(p, "--rim-width", Rim, "width", metavar="N.V")
    add_described(p, "--paper", Paper, "space", default=NONE, extra_choices=(NONE,),
                  help_before="paper grain over the image; ", also_sets=[(RenderOptions, "paper")])
    add_described(p, "--paper-strength", Paper, "strength", metavar="S")
    add_described(p, "--eye-dome", EyeDome, "strength", default=None, metavar="S", shown_default="off",
                  help_before="eye-dome lighting at this strength (surfaces darkened behind their neighbours, "
                              "as point-cloud viewers draw); ", also_sets=[(RenderOptions, "eye_dome")])
    add_described(p, "--eye-dome-radius", EyeDome, "radius", metavar="PX")
    for name in HATCH_FLAGS:
        add_described(p, f"--hatch-{name}", Material, name, constructor=HATCHING, help_before=f"--style {HATCHING}: ",
                      metavar=None if name == "mode" else "PX")
    add_described(p, "--band-antialias", RenderOptions, "band_antialias",
                  help_after="; --no-band-antialias for the papers' hard borders")
    p.add_argument("--shadows", action="store_true", help="the key light casts shadows (default: off)")
    add_described(p, "--shadow-size", Shadows, "size", metavar="TEXELS")
    add_described(p, "--shadow-bias", Shadows, "bias", metavar="X")
    add_described(p, "--shadow-strength", Shadows, "strength", metavar="S")
    add_described(p, "--outlines", Outlines, "kind", default=DEMO_OUTLINES.kind, extra_choices=(NONE,),
                  help_before="ink lines: ", help_after=f", or {NONE}; the default is toonmesh demo's")
    add_described(p, "--outline-width", Outlines, "width", default=DEMO_LINE_WIDTH, metavar="PX")
    add_described(p, "--crease-angle", Outlines, "crease_angle", default=DEMO_OUTLINES.crease_angle, metavar="DEG")
    add_described(p, "--taper", Outlines, "taper", default=DEMO_OUTLINES.taper, metavar="PX")
    add_described(p, "--width-by-depth", Outlines, "width_by_depth", default=DEMO_OUTLINES.width_by_depth)
    _add_contour_arguments(p, DEMO_OUTLINES)
    add_described(p, "--image-rule", Outlines, "image_rule", default=DEMO_OUTLINES.image_rule)
    add_described(p, "--normal-angle", Outlines, "normal_angle", default=DEMO_OUTLINES.normal_angle, metavar="DEG",
                  help_before="discontinuity rule: ")
    add_described(p, "--depth-jump", Outlines, "depth_jump", default=DEMO_OUTLINES.depth_jump, metavar="PX",
                  help_before="discontinuity rule: ")
    add_described(p, "--normal-threshold", Outlines, "normal_threshold", default=DEMO_OUTLINES.normal_threshold,
                  metavar="X")
    add_described(p, "--depth-threshold", Outlines, "depth_threshold", default=DEMO_OUTLINES.depth_threshold,
                  metavar="X")
    p.add_argument("--views", type=_views, default=None, metavar="N",
                   help="a turntable of N views about the up axis (default 1; for a video, "
                        f"{DEFAULT_SECONDS:g} seconds at --fps); with --video or -o turn.gif|.mp4|.webm, its frames "
                        "as a video")
    p.add_argument("--fps", type=_fps, default=DEFAULT_FPS, metavar="N",
                   help="frames per second of a video written by --video or -o turn.gif|.mp4|.webm "
                        "(default %(default)s)")
    add_described(p, "--up", RenderOptions, "up", help_after=up_help)
    smooth_flag = p.add_argument("--smooth", type=int, default=_keyword_default(render_views, "smooth_iterations"),
                                 metavar="N", help="smoothing iterations before rendering (default %(default)s)")
    sets(p, smooth_flag, (render_views, "smooth_iterations"), (smooth, "iterations"))
    p.add_argument("--smooth-method", choices=RENDER_SMOOTH_METHODS,
                   default=_keyword_default(render_views, "smooth_method"),
                   help=f"{RENDER_SMOOTH_METHODS[0]}: each vertex to its neighbours' mean (the renderer's own); or "
                        "a toonmesh.smooth method (default: %(default)s)")
    p.add_argument("--normals", type=_normals, default=_keyword_default(render_views, "normals"), metavar="MODE",
                   help=f"smooth, flat (facets), or auto: hard edges where faces meet at more than "
                        f"{_core.DEFAULT_CREASE_ANGLE:g} degrees, except a scan's short or zig-zagging creases "
                        "(auto:DEG for another angle); default: the file's own normals where it has them, else "
                        f"{_core._normal_mode(None, 0)}")
    add_described(p, "--outputs", RenderOptions, "outputs", type=_outputs, choices=None, metavar="LIST",
                  help_after=f": comma-separated, of {', '.join(_core.IMAGE_OUTPUTS)}; anything but color alone "
                             "writes .npz")
    add_described(p, "--msaa", RenderOptions, "msaa", metavar="N")
    add_described(p, "--supersample", RenderOptions, "supersample", metavar="N")
    add_described(p, "--pixel-ratio", RenderOptions, "pixel_ratio", metavar="R")
    p.add_argument("--backend", **backend)  # type: ignore[arg-type]
    p.set_defaults(run=cmd_render)

    p = sub.add_parser("smooth", help="smooth a mesh file", description="Smooth a mesh file and write the result "
                                                                         "(the format follows OUT's suffix).")
    p.add_argument("input", metavar="IN", help="mesh file to read, or the name of a mesh shipped with toonmesh (bunny)")
    p.add_argument("output", metavar="OUT", nargs="?", default=None, help="as -o OUT (the form of earlier versions)")
    p.add_argument("-o", "--out", metavar="OUT", default=None,
                   help="mesh file to write (.obj, .ply, .stl, .off, .glb, ...; several meshes: .glb or .obj); no "
                        "default: required, here or as OUT")
    p.add_argument("--method", choices=_core.SMOOTH_METHODS, default=SMOOTH_METHOD, help="default: %(default)s")
    crease = p.add_argument("--crease-angle", type=float, default=None, metavar="DEG",
                            help="vertices on edges where faces meet at more than DEG degrees stay in place, so that "
                                 "a CAD part keeps its edges and corners; 180 moves them too (default: "
                                 f"{SMOOTH_CREASE_ANGLE:g}, or 180 with --preset: the peer's filter as it is)")
    sets(p, crease, (feature_edges, "crease_angle"))
    for name, uses in smoothing_keywords().items():
        param = dict(uses[0][1], default=None)
        if param["kind"] == "choice":  # each name once, in the order the methods list them
            param["choices"] = list(dict.fromkeys(c for _, k in uses for c in k["choices"]))
        flag = add_param(p, "--" + name.replace("_", "-"), param, shown_default=_smoothing_defaults(uses),
                         **({"metavar": SMOOTH_METAVARS[param["kind"]]} if param["kind"] in SMOOTH_METAVARS else {}))
        sets(p, flag, (smooth, name))
    p.add_argument("--weld", action="store_true",
                   help="treat vertices at the same position as one (default: off, but always on for a file "
                        "whose texture coordinates or normals split its vertices)")
    p.add_argument("--force", action="store_true",
                   help="write over the input file, and over files beside OUT that this run did not write (its "
                        "MTL, its texture); default: refuse, naming them")
    p.set_defaults(run=cmd_smooth)

    p = sub.add_parser("edges", help="outline edges of a mesh file as SVG or NPZ",
                       description="Silhouette, boundary, crease and non-manifold edges of one view, drawn as SVG "
                                   "(hidden lines removed) or saved as NPZ arrays.")
    p.add_argument("mesh", metavar="MESH", help="a mesh file, or the name of a mesh shipped with toonmesh (bunny)")
    p.add_argument("-o", "--out", required=True, metavar="OUT", help="lines.svg or lines.npz")
    eye = p.add_argument("--eye", type=float, nargs=3, default=None, metavar=("X", "Y", "Z"),
                         help="look orthographically along -eye (default: the renderer's fitted camera, a "
                              "three-quarter view about the up axis)")
    sets(p, eye, (Camera, "direction"))
    add_described(p, "--up", RenderOptions, "up", help_after=up_help)
    add_described(p, "--crease-angle", Outlines, "crease_angle", metavar="DEG")
    add_described(p, "--no-weld", Outlines, "weld", action="store_false", dest="weld",
                  help_before="keep vertices at the same position apart (seams then show as boundaries). "
                              "Welding, on unless this flag is given: ")
    _add_size_argument(p, "drawing size")
    _add_contour_arguments(p)
    add_described(p, "--stroke-width", LineStyle, "width", metavar="PX", also_sets=[(Outlines, "width")])
    p.add_argument("--smooth-strokes", type=float, default=_keyword_default(RenderResult.svg_groups, "smooth"), metavar="PX",
                   help="smooth each stroke of the SVG over this many pixels along it; no point moves more "
                        "(default %(default)g: off)")
    p.add_argument("--order", choices=_strokes.ORDERS, default=_keyword_default(RenderResult.svg_groups, "order"),
                   help="drawing: as found; plotter: each next stroke nearest where the pen stopped "
                        "(default: %(default)s)")
    p.add_argument("--simplify", type=float, default=_keyword_default(RenderResult.svg_groups, "simplify"), metavar="PX",
                   help="drop points within this many pixels of each stroke (default %(default)g; 0 keeps every point)")
    p.add_argument("--backend", **backend)  # type: ignore[arg-type]
    p.set_defaults(run=cmd_edges)

    p = sub.add_parser("bench", help="run the benchmark suites", description="Benchmarks: toonmesh and the peer "
                                                                            "libraries side by side.")
    add_bench_arguments(p)
    p.set_defaults(run=cmd_bench)

    p = sub.add_parser("demo", help="render the built-in scene (the Stanford bunny, toon-shaded) to a PNG")
    p.add_argument("--out", default="toonmesh-demo.png", help="output PNG path (default: %(default)s)")
    add_described(p, "--width", RenderOptions, "width", default=DEFAULT_SIZE[0])
    add_described(p, "--height", RenderOptions, "height", default=DEFAULT_SIZE[1])
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
        try:
            return int(args.run(args) or 0)
        except argparse.ArgumentError as exc:  # the core refused a flag's value (errors_as_flags)
            prog = f"{parser.prog} {args.command}"
            raise CliError(f"{_one_line(exc)} (see {prog} --help)", prog) from None
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
