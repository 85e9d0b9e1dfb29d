"""The command line's defaults and choices are the core's: every flag that sets a described
setting shows the described default and offers the described choices, every flag that takes the
core's names offers exactly those, and each follows the core when it changes (nothing typed again
in the command line). A core error about a flag's value comes back naming the flag."""

from __future__ import annotations

import argparse
from typing import Any, Dict, Iterator, Tuple

import pytest

from test_cli import in_process, one_line_error
from toonmesh import _core, batch, cli, smooth
from toonmesh.arguments import _described_flags
from toonmesh._core import Dither, EyeDome, LineStyle, Material, Outlines, Paper, RenderOptions, Rim, Shadows

#: (command, dest) -> (class, constructor, parameter): flags whose default is the described one.
DESCRIBED = {
    ("render", "dither_amount"): (Dither, "", "amount"),
    ("render", "rim_color"): (Rim, "", "color"),
    ("render", "rim_width"): (Rim, "", "width"),
    ("render", "paper_strength"): (Paper, "", "strength"),
    ("render", "eye_dome_radius"): (EyeDome, "", "radius"),
    ("render", "hatch_spacing"): (Material, "hatching", "spacing"),
    ("render", "hatch_width"): (Material, "hatching", "width"),
    ("render", "hatch_mode"): (Material, "hatching", "mode"),
    ("render", "band_antialias"): (RenderOptions, "", "band_antialias"),
    ("render", "shadow_size"): (Shadows, "", "size"),
    ("render", "shadow_strength"): (Shadows, "", "strength"),
    ("render", "shadow_bias"): (Shadows, "", "bias"),
    ("render", "suggestive"): (Outlines, "", "suggestive"),
    ("render", "outputs"): (RenderOptions, "", "outputs"),
    ("render", "msaa"): (RenderOptions, "", "msaa"),
    ("render", "supersample"): (RenderOptions, "", "supersample"),
    ("render", "pixel_ratio"): (RenderOptions, "", "pixel_ratio"),
    ("render", "glass_layers"): (RenderOptions, "", "glass_layers"),
    ("render", "opacity"): (Material, "bands", "opacity"),
    ("edges", "crease_angle"): (Outlines, "", "crease_angle"),
    ("edges", "weld"): (Outlines, "", "weld"),
    ("edges", "contours"): (Outlines, "", "contours"),
    ("edges", "suggestive"): (Outlines, "", "suggestive"),
    ("edges", "curvature_smoothing"): (Outlines, "", "curvature_smoothing"),
    ("edges", "join_kinds"): (Outlines, "", "join_kinds"),
    ("edges", "suggestive_coherence"): (Outlines, "", "suggestive_coherence"),
    ("edges", "stroke_width"): (LineStyle, "", "width"),
    ("render", "hidden"): (Outlines, "", "hidden"),
    ("render", "intersection"): (Outlines, "", "intersection"),
    ("edges", "hidden"): (Outlines, "", "hidden"),
    ("edges", "intersection"): (Outlines, "", "intersection"),
    ("edges", "visibility"): (Outlines, "", "visibility"),
    ("edges", "max_occlusion"): (Outlines, "", "max_occlusion"),
}
#: render's ink lines start from toonmesh demo's: dest -> the Outlines attribute it starts from.
FROM_THE_DEMO = {
    "outlines": "kind", "crease_angle": "crease_angle", "taper": "taper", "width_by_depth": "width_by_depth",
    "contours": "contours", "curvature_smoothing": "curvature_smoothing", "join_kinds": "join_kinds",
    "suggestive_coherence": "suggestive_coherence",
    "image_rule": "image_rule", "normal_angle": "normal_angle", "depth_jump": "depth_jump",
    "normal_threshold": "normal_threshold", "depth_threshold": "depth_threshold",
    "visibility": "visibility", "max_occlusion": "max_occlusion",
}
#: What toonmesh demo's lines choose differently from the core's defaults.
DEMO_CHOICES = {"kind", "crease_angle"}
#: Flags whose default is the command line's own (a file, a size, a word of its own), or nothing.
OWN = {
    ("render", "out"), ("render", "video"), ("edges", "out"), ("render", "size"), ("render", "style"), ("render", "color"), ("render", "dither"), ("render", "shadows"),
    ("render", "rim"), ("render", "paper"), ("render", "eye_dome"),
    ("render", "outline_width"), ("render", "views"), ("render", "fps"), ("render", "up"), ("render", "smooth"),
    ("render", "smooth_method"), ("render", "normals"), ("render", "backend"),
    ("smooth", "out"), ("smooth", "method"), ("smooth", "weld"), ("smooth", "crease_angle"), ("smooth", "force"),
    ("edges", "eye"), ("edges", "up"), ("edges", "size"), ("edges", "smooth_strokes"),
    ("edges", "order"), ("edges", "simplify"), ("edges", "backend"),
    ("demo", "out"), ("demo", "width"), ("demo", "height"), ("demo", "backend"),
}


def _choices(cls: Any, name: str) -> Tuple[str, ...]:
    """A described choice's names, as the command line reads them (so that a changed core shows)."""
    return tuple(_described_flags.described(cls, name)["choices"])


def core_choices() -> Dict[Tuple[str, str], Tuple[str, ...]]:
    """(command, dest) -> the names the flag must offer, read from the core now."""
    styles = tuple(c["name"].replace("_", "-") for c in Material.describe()["constructors"] if c["name"])
    names = {
        ("render", "style"): styles,
        ("render", "dither"): ("none",) + tuple(_core.DITHER_PATTERNS),
        ("render", "rim"): ("none",) + tuple(_choices(Rim, "side")),
        ("render", "paper"): ("none",) + tuple(_choices(Paper, "space")),
        ("render", "hatch_mode"): tuple(_core.HATCH_MODES),
        ("render", "outlines"): ("none",) + tuple(_core.OUTLINE_KINDS),
        ("render", "contours"): tuple(_core.CONTOUR_RULES),
        ("edges", "contours"): tuple(_core.CONTOUR_RULES),
        ("render", "image_rule"): tuple(_core.IMAGE_RULES),
        ("render", "smooth_method"): ("paper",) + tuple(_core.SMOOTH_METHODS),
        ("smooth", "method"): tuple(_core.SMOOTH_METHODS),
        ("smooth", "preset"): tuple(_core.SMOOTH_PRESETS),
        ("smooth", "weights"): tuple(_core.SMOOTH_WEIGHTS),
        ("smooth", "boundary"): tuple(_core.SMOOTH_BOUNDARIES),
    }
    for command in ("render", "edges", "demo"):
        names[(command, "backend")] = tuple(_core.BACKENDS)
    return names


def core_param(cls: Any, constructor: str, name: str) -> Dict[str, Any]:
    (made_by,) = [c for c in cls.describe()["constructors"] if c["name"] == constructor]
    (param,) = [p for p in made_by["params"] if p["name"] == name]
    return dict(param)


def flags(parser: argparse.ArgumentParser) -> Iterator[Tuple[str, str, argparse.Action]]:
    """(command, dest, action) of every option of every subcommand but bench (its own module's)."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for command, sub in action.choices.items():
                for a in sub._actions:
                    if a.option_strings and command != "bench" and not isinstance(a, argparse._HelpAction):
                        yield command, a.dest, a


def shown_default(action: argparse.Action) -> str:
    """The help of ``action`` as ``--help`` prints it (argparse's own expansion)."""
    return (action.help or "") % dict(vars(action), prog="toonmesh")


def formatted(value: Any, kind: str = "") -> str:
    if kind == "style":  # a kind of line: drawn by default or not
        return "off" if value in (None, False) else "drawn"
    return f"{value:g}" if isinstance(value, float) else str(value)


def smoothing_keywords() -> Dict[str, Dict[str, Dict[str, Any]]]:
    """{keyword: {method: its description}} of the methods ``toonmesh smooth --method`` offers,
    read from the core now; weld is the command line's own flag."""
    by_name: Dict[str, Dict[str, Dict[str, Any]]] = {}
    for method in _core._smoothing_description():
        if method["method"] in _core.SMOOTH_METHODS:
            for k in method["keywords"]:
                if k["name"] != "weld":
                    by_name.setdefault(k["name"], {})[method["method"]] = k
    return by_name


def test_every_flag_is_classified():
    found = {(command, dest) for command, dest, _ in flags(cli.build_parser())}
    smoothing = {("smooth", name) for name in smoothing_keywords()}
    known = set(DESCRIBED) | {("render", d) for d in FROM_THE_DEMO} | OWN | set(core_choices()) | smoothing
    assert found - known == set(), "classify these flags in this test: described, the demo's or the CLI's own"
    assert known - found == set(), "flags this test expects that the command line lacks"


def test_described_defaults_are_the_cores_and_help_shows_them():
    by_key = {(command, dest): action for command, dest, action in flags(cli.build_parser())}
    for key, (cls, constructor, name) in DESCRIBED.items():
        param, action = core_param(cls, constructor, name), by_key[key]
        assert action.default == param["default"], key
        assert f"default: {formatted(param['default'], param['kind'])})" in shown_default(action), key
        assert param["help"] in shown_default(action), key


def test_smooth_has_a_flag_per_described_keyword_showing_each_methods_defaults():
    """toonmesh smooth: a flag per keyword of the methods --method offers (--lamb, --max-iter, ...),
    of the described kind and choices, None by default (the method's or preset's own), its help
    the core's with every method's described default and each preset's that differs."""
    by_key = {(command, dest): action for command, dest, action in flags(cli.build_parser())}
    spelled = {int: "int", float: "float", str: "choice", None: "bool"}
    for name, methods in smoothing_keywords().items():
        action = by_key[("smooth", name)]
        assert action.option_strings[0] == "--" + name.replace("_", "-")
        assert action.default is None, name
        kinds = {k["kind"] for k in methods.values()}
        assert kinds == {spelled[action.type]}, name
        if kinds == {"choice"}:
            assert set(action.choices) == {c for k in methods.values() for c in k["choices"]}, name
        shown = shown_default(action)
        for method, k in methods.items():
            if k["help"] in shown:
                break
        else:
            raise AssertionError(f"{name}: no method's help in {shown!r}")
        for method, k in methods.items():
            for v in [k["default"], *k["presets"].values()]:
                assert v is None or (repr(v) if isinstance(v, float) else str(v)) in shown, (name, method, v)
            for preset in k["presets"]:
                assert preset in shown, (name, method, preset)
            defaults = {str((k["default"], k["presets"], k.get("preset_ranges"))) for k in methods.values()}
            if len(defaults) > 1:  # the methods' defaults differ: each is named
                assert method in shown, (name, method)


def test_render_lines_are_the_demos_which_differ_from_the_core_only_where_it_chooses():
    by_key = {(command, dest): action for command, dest, action in flags(cli.build_parser())}
    for dest, attribute in FROM_THE_DEMO.items():
        action = by_key[("render", dest)]
        assert action.default == getattr(cli.DEMO_OUTLINES, attribute), dest
        assert f"default: {formatted(action.default)})" in shown_default(action), dest
        if attribute not in DEMO_CHOICES:
            assert action.default == core_param(Outlines, "", attribute)["default"], dest
    assert by_key[("render", "outline_width")].default == cli.DEMO_LINE_WIDTH
    assert cli.DEMO_OUTLINES == Outlines(
        cli.DEMO_OUTLINES.kind, width=cli.DEMO_LINE_WIDTH, crease_angle=cli.DEMO_OUTLINES.crease_angle)


def test_choices_are_the_cores_names():
    by_key = {(command, dest): action for command, dest, action in flags(cli.build_parser())}
    for key, names in core_choices().items():
        assert tuple(by_key[key].choices or ()) == names, key
    for key, (cls, constructor, name) in DESCRIBED.items():
        choices = core_param(cls, constructor, name).get("choices")
        if choices and by_key[key].type is not cli._outputs:
            assert tuple(by_key[key].choices) == tuple(choices), key
    assert by_key[("render", "style")].default == RenderOptions().material.model.replace("_", "-")
    assert batch.SMOOTH_METHODS == ("paper",) + tuple(_core.SMOOTH_METHODS)


def test_the_normals_help_gives_the_cores_crease_angle(monkeypatch):
    def normals_help() -> str:
        (action,) = [a for c, d, a in flags(cli.build_parser()) if (c, d) == ("render", "normals")]
        return shown_default(action)

    assert f"more than {_core.DEFAULT_CREASE_ANGLE:g} degrees" in normals_help()
    monkeypatch.setattr(_core, "DEFAULT_CREASE_ANGLE", 42.0)
    assert "more than 42 degrees" in normals_help()


def _changed(param: Dict[str, Any]) -> Dict[str, Any]:
    """``param`` as a core with other defaults and its choices in another order would describe it."""
    param = dict(param)
    choices = list(param.get("choices") or [])
    if choices:
        param["choices"] = choices[::-1]
    default, kind = param["default"], param["kind"]
    if kind == "float":
        param["default"] = (default or 0.0) + 0.5
    elif kind == "int":
        param["default"] = (default or 0) + 1
    elif kind == "bool":
        param["default"] = not default
    elif kind == "choice":
        param["default"] = next(c for c in choices if c != default)
    return param


def test_flags_follow_the_core_when_it_changes(monkeypatch):
    """A default or choice list typed into the command line (even one equal to the core's today)
    stays behind when the core's changes: this catches it."""
    real = _described_flags.described

    def changed(cls: Any, name: str, constructor: str = "") -> Dict[str, Any]:
        return _changed(real(cls, name, constructor))

    monkeypatch.setattr(_described_flags, "described", changed)
    described_smoothing = {
        method: dict(d, keywords=[_changed(k) if k["name"] != "preset" else dict(k, choices=k["choices"][::-1])
                                  for k in d["keywords"]])
        for method, d in smooth._DESCRIBED.items()
    }
    monkeypatch.setattr(smooth, "_DESCRIBED", described_smoothing)
    for name in ("DITHER_PATTERNS", "HATCH_MODES", "OUTLINE_KINDS", "CONTOUR_RULES", "IMAGE_RULES", "SMOOTH_METHODS",
                 "SMOOTH_PRESETS", "SMOOTH_WEIGHTS", "SMOOTH_BOUNDARIES", "BACKENDS"):
        monkeypatch.setattr(_core, name, tuple(getattr(_core, name))[::-1])
    demo = cli.DEMO_OUTLINES.replace(kind="both", crease_angle=45.0, taper=2.0, width_by_depth=True, contours="faces",
                                     curvature_smoothing=1.0, join_kinds=True, image_rule="paper", normal_angle=40.0,
                                     depth_jump=5.0, normal_threshold=0.5, depth_threshold=0.2)
    monkeypatch.setattr(cli, "DEMO_OUTLINES", demo)
    by_key = {(command, dest): action for command, dest, action in flags(cli.build_parser())}

    for key, (cls, constructor, name) in DESCRIBED.items():
        expected = changed(cls, name, constructor)
        if expected["kind"] != "style":  # store_true: off unless given
            assert by_key[key].default == expected["default"], key
        if expected.get("choices") and by_key[key].type is not cli._outputs:
            assert list(by_key[key].choices) == expected["choices"], key
    for dest, attribute in FROM_THE_DEMO.items():
        assert by_key[("render", dest)].default == getattr(demo, attribute), dest
    for key, names in core_choices().items():
        # those read the description, batch, the smoothing methods' description
        if key not in (("render", "style"), ("render", "smooth_method"), ("smooth", "preset"), ("smooth", "weights"),
                       ("smooth", "boundary")):
            assert tuple(by_key[key].choices) == names, key
    first = {}  # each smoothing keyword as the first method --method offers describes it
    for method in _core.SMOOTH_METHODS:
        for k in described_smoothing[method]["keywords"]:
            first.setdefault(k["name"], k)
    for name in ("preset", "weights", "boundary", "iterations", "lamb", "mu", "tol"):
        action, k = by_key[("smooth", name)], first[name]
        if k["kind"] == "choice":
            assert list(action.choices)[: len(k["choices"])] == k["choices"], name
        else:
            assert _formatted_default(k) in shown_default(action), name


def _formatted_default(k: Dict[str, Any]) -> str:
    return repr(k["default"]) if k["kind"] == "float" else str(k["default"])


@pytest.mark.parametrize(
    "args, words",
    [
        (["edges", "bunny", "-o", "x.svg", "--crease-angle", "200"], ["--crease-angle", "crease_angle", "180"]),
        (["edges", "bunny", "-o", "x.svg", "--stroke-width", "100"], ["--stroke-width", "64"]),
        (["render", "bunny", "-o", "x.png", "--shadows", "--shadow-size", "100"], ["--shadow-size", "power of two"]),
        (["render", "bunny", "-o", "x.png", "--dither", "bayer4", "--dither-amount", "5"], ["--dither-amount", "amount"]),
        (["render", "bunny", "-o", "x.png", "--style", "lambert", "--dither", "bayer4"], ["--dither", "lambert"]),
        (["render", "bunny", "-o", "x.png", "--style", "hatching", "--hatch-spacing", "1"], ["--hatch-spacing"]),
        (["render", "bunny", "-o", "x.png", "--outline-width", "100"], ["--outline-width"]),
        (["render", "bunny", "-o", "x.png", "--outlines", "none", "--suggestive"], ["--suggestive", "none"]),
    ],
)
def test_a_core_error_names_the_flag(tmp_path, capsys, monkeypatch, args, words):
    monkeypatch.chdir(tmp_path)
    r = in_process(capsys, *args, check=False)
    assert r.returncode == 2
    one_line_error(r, *words)
    assert list(tmp_path.iterdir()) == []
