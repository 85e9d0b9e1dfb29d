"""The settings classes derived from the core's description (src/render/settings): each value's
repr evaluates back to an equal object, pickles round trip, `replace` changes exactly the field
it names and checks it as the constructor does, the description matches the class, and the
committed stub is what scripts/stubs.py writes from the description."""

from __future__ import annotations

import copy
import math
import pickle
import subprocess
import sys
from pathlib import Path
from typing import Any, Dict, List

import pytest

import toonmesh as tm

ROOT = Path(__file__).resolve().parent.parent
# every settings class the core lists, as the package exports it
CLASSES = [getattr(tm, name) for name in tm._core.SETTINGS_CLASSES]

# Values made every way the classes offer, defaults and changed ones.
VALUES: List[Any] = [
    tm.Material.bands(),
    tm.Material.bands("#336699", thresholds=[0.1, 0.6], values=[0.2, 0.5, 1.0], dither="blue"),
    tm.Material.bands(preset="paper", per_vertex=True),
    tm.Material.lambert((0.2, 0.4, 0.6), ambient=(0.1, 0.1, 0.1)),
    tm.Material.phong(shininess=7.5, specular="#808080"),
    tm.Material.thresholded_phong(t_h=-0.2, t_s=0.9, highlight="paper", dither=tm.Dither("bayer8", amount=0.3)),
    tm.Material.hatching(ink="#202020", spacing=9, width=2.0, mode="triplanar"),
    tm.Material.lut([0.2, 0.6, 1.0], "#ff8800"),
    tm.Dither(),
    tm.Rim(),
    tm.Rim("#3366ff", width=0.45, softness=0.1, strength=1.0, side="shadowed", blend="mix"),
    tm.Material.lambert(rim=tm.Rim(side="lit"), per_vertex=True),
    tm.Paper(),
    tm.Paper(space="surface", scale=4.0, strength=0.9, tone=0.0),
    tm.Dither("bayer2", space="object", amount=0.5, scale=4),
    tm.Light.key(),
    tm.Light.directional((1, -2, -3), color="#ffeecc", intensity=0.8, shadows=tm.Shadows(1024, 0.5, "none")),
    tm.Light.point((0, 3, 0), space="camera"),
    tm.Shadows(),
    tm.Camera.fit(),
    tm.Camera.fit((0, 0, 1), up=(0, 1, 0), margin=1.2, orthographic=True),
    tm.Camera.look_at((0, 1, 5), (0, 0.5, 0), fov_y=20, near=0.1, far=50),
    tm.Camera.orthographic((3, 3, 3), height=4.0),
    tm.LineStyle(),
    tm.LineStyle("#ff0000", 3.0),
    tm.Outlines(),
    tm.Outlines("mesh", color="#0000ff", width=2, crease=False, suggestive=True, curvature_smoothing=1.0, taper=8),
    tm.Outlines("image", image_rule="paper", normal_threshold=0.5),
    tm.RenderOptions(),
    tm.RenderOptions(width=64, height=48, outlines="mesh", outputs=("color", "depth"), lights=[tm.Light.point((1, 1, 1))],
                     material=tm.Material.hatching(), camera=tm.Camera.look_at((0, 0, 4)), background="#00000000"),
    tm.RenderOptions(paper=tm.Paper(strength=1.0), outlines="image"),
]


def _fields(value: Any) -> Dict[str, Any]:
    return {f["name"]: getattr(value, f["name"]) for f in type(value).describe()["fields"]}


@pytest.mark.parametrize("value", VALUES, ids=repr)
def test_repr_evaluates_to_an_equal_value(value):
    text = repr(value)
    assert "..." not in text and "{" not in text, text
    again = eval(text, {name: getattr(tm, name) for name in tm.__all__})
    assert again == value and hash(again) == hash(value), text
    assert repr(again) == text


@pytest.mark.parametrize("value", VALUES, ids=repr)
def test_pickles_and_copies_round_trip(value):
    assert pickle.loads(pickle.dumps(value)) == value
    assert copy.deepcopy(value) == value


def _another(field: Dict[str, Any], now: Any) -> Any:
    """A legal value of `field` that differs from `now` (None where none is easy to name)."""
    kind = field["kind"]
    if kind == "bool":
        return not now
    if kind in ("float", "int"):
        lo, hi = field["slider"]
        new = lo + 0.37 * (hi - lo) if kind == "float" else int(lo + (hi - lo) // 3)
        return new if new != now else None
    if kind == "choice":
        others = [c for c in field["choices"] if c != now]
        return others[0] if others else None
    if kind == "color":
        return (0.25, 0.5, 0.75) if now != (0.25, 0.5, 0.75) else (0.5, 0.5, 0.5)
    return None


@pytest.mark.parametrize("value", VALUES, ids=repr)
def test_replace_changes_only_the_field_named(value):
    before = _fields(value)
    changed = 0
    for field in type(value).describe()["fields"]:
        name, now = field["name"], before[field["name"]]
        if field["fixed"] or now is None:
            continue
        new = _another(field, now)
        if new is None:
            continue
        try:
            out = value.replace(**{name: new})
        except ValueError as exc:  # a value the core's rules refuse: the field, or the one it clashes with
            assert str(exc).split(":")[0] in before, exc
            continue
        after = _fields(out)
        assert after[name] != now, name
        assert {k: v for k, v in after.items() if k != name} == {k: v for k, v in before.items() if k != name}, name
        assert out.replace(**{name: now}) == value, name
        changed += 1
    assert changed > 0


def test_replace_checks_as_the_constructor_does():
    with pytest.raises(ValueError, match="^crease_angle"):
        tm.Outlines().replace(crease_angle=200)
    with pytest.raises(TypeError, match="^crease_angel: .*did you mean 'crease_angle'"):
        tm.Outlines().replace(crease_angel=20)
    with pytest.raises(ValueError, match="^shininess: only a phong material has it"):
        tm.Material.bands().replace(shininess=3)
    with pytest.raises(ValueError, match="^thresholds"):
        tm.Material.bands().replace(thresholds=[0.5, 0.2, 0.9, 0.95])
    # None: the field's default, as in the constructor
    assert tm.Outlines(crease_angle=45).replace(crease_angle=None) == tm.Outlines()
    hatch = tm.Material.hatching()
    assert hatch.replace(values=[0.1, 0.2, 0.3, 0.4, 0.5]).hatch_style == hatch.hatch_style


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_the_description_is_the_class(cls):
    d = cls.describe()
    assert d["class"] == cls.__name__
    for c in d["constructors"]:
        make = cls if not c["name"] else getattr(cls, c["name"])
        required = [(0.0, 0.0, 5.0)] * c["required"]
        value = make(*required)
        for p in c["params"][c["required"]:]:
            if any(f["name"] == p["name"] for f in d["fields"]):
                assert getattr(value, p["name"]) == p["default"], (c["name"], p["name"])
        # each constructor-only parameter is accepted by name
        assert make(*required, **{c["params"][-1]["name"]: None}) == value if c["params"] else True
    for f in d["fields"]:
        assert f["help"] and f["kind"], f
        if f["kind"] in ("float", "int"):
            assert f["min"] < f["max"], f
            # a control spans finite numbers within the rule
            lo, hi = f["slider"]
            assert math.isfinite(lo) and math.isfinite(hi) and f["min"] <= lo < hi <= f["max"], f
            assert len(f["exclusive"]) == 2 and all(isinstance(e, bool) for e in f["exclusive"]), f


def test_every_settings_class_is_the_cores_and_exported():
    from toonmesh import _core

    assert len(CLASSES) >= 8
    for cls in CLASSES:
        assert cls is getattr(_core, cls.__name__) and cls.__name__ in tm.__all__
        assert cls.__doc__ and cls.describe()["class"] == cls.__name__
    # and each class a settings field names is one of them
    named = {f["class"] for c in CLASSES for f in c.describe()["fields"] if f["kind"] == "setting"}
    assert named <= set(_core.SETTINGS_CLASSES), named


def test_unknown_and_misplaced_arguments_are_named():
    with pytest.raises(TypeError, match="^widht: not a parameter of LineStyle; did you mean 'width'"):
        tm.LineStyle(widht=2)
    with pytest.raises(TypeError, match="^direction: Light.directional needs it"):
        tm.Light.directional()
    with pytest.raises(TypeError, match="at most 1 positional"):
        tm.Material.bands("#ffffff", [0.5])


def test_the_stub_is_what_the_generator_writes():
    r = subprocess.run([sys.executable, str(ROOT / "scripts" / "stubs.py"), "--check"], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


def test_a_field_the_constructor_does_not_take_is_written_as_a_replace():
    for changed in (dict(ambient="#111111"), dict(specular="#222222"), dict(ambient="#111111", specular="#333333")):
        m = tm.Material.bands("#888888").replace(**changed)
        text = repr(m)
        assert text.startswith("Material.bands(") and ".replace(" in text, text
        assert eval(text, vars(tm)) == m
    # a value its constructor makes as it is needs no replace
    assert ".replace(" not in repr(tm.Material.bands("#888888"))


def test_every_number_field_is_refused_outside_its_rule_naming_it():
    for cls in CLASSES:
        for f in cls.describe()["fields"]:
            if f["kind"] != "float" or f["fixed"]:
                continue
            for c in cls.describe()["constructors"]:
                make = cls if not c["name"] else getattr(cls, c["name"])
                value = make(*[(0.0, 0.0, 5.0)] * c["required"])
                if getattr(value, f["name"]) is None and not f["optional"]:
                    continue
                try:
                    value.replace(**{f["name"]: f["slider"][0]})
                except ValueError:
                    continue  # this value has no such field (a fitted camera's fov_y on an orthographic one)
                # past a closed max by more than a rounding (a float32 field's max is float32's largest)
                for bad in (float("nan"), f["max"] if f["exclusive"][1] else f["max"] + max(1.0, abs(f["max"]) * 1e-3)):
                    if math.isinf(bad) and not f["exclusive"][1]:
                        continue
                    with pytest.raises(ValueError, match=f["name"]):
                        value.replace(**{f["name"]: bad})
