"""Every settings object describes itself after any change: for each settings class, each of
its constructors and each (non-fixed) field its values have, a value made by the constructor
from drawn arguments and changed by ``replace`` to a drawn value evaluates back from its repr to
an equal value with the same hash and repr, and pickles round trip.

The values are drawn from the core's description (tests/descriptions.py): a number within its
rule's bounds or its slider's range, a choice from its choices, colours, 3-vectors, lists of
floats as long as the ones they replace, None where optional, and nested settings made by their
own class's constructors. No class or field is listed here."""

from __future__ import annotations

import pickle
from typing import Any, Dict, List, Tuple

import numpy as np
import pytest

import descriptions
import toonmesh as tm

from conftest import need

need("hypothesis")
from hypothesis import given, reject, settings, strategies as st  # noqa: E402
from hypothesis.extra import numpy as hnp  # noqa: E402

# A repr names the package's classes, and NumPy's for an image field (``array(..., dtype=...)``).
NAMESPACE = {name: getattr(tm, name) for name in tm.__all__}
NAMESPACE.update(array=np.array, float32=np.float32, float64=np.float64, uint8=np.uint8)
CLASSES = {cls.__name__: cls for cls in descriptions.settings_classes()}
BIG = 1e30  # drawn numbers stay within float32 (and far from overflow in a derived matrix)


def _floats(lo: float, hi: float, open_lo: bool = False, open_hi: bool = False) -> st.SearchStrategy:
    return st.floats(max(lo, -BIG), min(hi, BIG), exclude_min=open_lo and lo > -BIG, exclude_max=open_hi and hi < BIG,
                     allow_nan=False, allow_infinity=False)


def number(d: Dict[str, Any]) -> st.SearchStrategy:
    """Within the rule's bounds or the slider's range; a rule that is not a range keeps the
    values among the slider's ends and the default that it allows (the core says which)."""
    (lo, hi), (open_lo, open_hi), slider = (d["min"], d["max"]), d["exclusive"], d["slider"]
    if "rule" in d:
        return st.sampled_from(sorted({*slider, *([d["default"]] if d.get("default") is not None else [])}))
    if d["kind"] == "int":
        lo = lo + 1 if open_lo else lo
        hi = hi - 1 if open_hi else hi
        return st.integers(int(max(lo, -(2**31))), int(min(hi, 2**31)))
    return st.one_of(_floats(*slider), _floats(lo, hi, open_lo, open_hi))


COLOUR = st.one_of(st.tuples(*[st.floats(0.0, 1.0)] * 3), st.integers(0, 0xFFFFFF).map(lambda v: f"#{v:06x}"))
RGBA = st.one_of(COLOUR, st.tuples(*[st.floats(0.0, 1.0)] * 4))
VEC3 = st.tuples(*[st.floats(-1e3, 1e3)] * 3)


def _affine(t: Tuple[float, float, float], s: float) -> List[List[float]]:
    return [[s, 0.0, 0.0, t[0]], [0.0, s, 0.0, t[1]], [0.0, 0.0, s, t[2]], [0.0, 0.0, 0.0, 1.0]]


def value(d: Dict[str, Any], like: Any, required: bool = False) -> st.SearchStrategy:
    """A value of the described parameter ``d``; ``like``: the value it replaces (or its
    default), whose length a list of floats keeps (the rules between fields tie lengths); None
    where it is optional and not a required argument."""
    kind = d["kind"]
    kinds = {
        "bool": st.booleans, "color": lambda: COLOUR, "rgba": lambda: RGBA, "vec3": lambda: VEC3,
        "int": lambda: number(d), "float": lambda: number(d),
        "choice": lambda: st.sampled_from(d["choices"]),
        "names": lambda: st.lists(st.sampled_from(d["choices"]), min_size=1, max_size=3, unique=True),
        "setting": lambda: made(d["class"]),
        "style": lambda: st.one_of(st.booleans(), COLOUR, made("LineStyle")),
        "lights": lambda: st.lists(made("Light"), max_size=3),
        "matrix": lambda: st.builds(_affine, VEC3, st.floats(0.1, 10.0)),
        "image": lambda: hnp.arrays(np.uint8, hnp.array_shapes(min_dims=2, max_dims=2, max_side=4)),
        "table": lambda: st.lists(st.floats(0.0, 2.0), min_size=1, max_size=8),
        # as many as they replace, increasing and >= 0: both the bands' thresholds and values
        "floats": lambda: st.lists(st.floats(0.0, 1.0), min_size=len(like), max_size=len(like), unique=True).map(sorted),
    }
    assert kind in kinds, f"{d['name']}: no strategy for a {kind!r} (add one here)"
    drawn = st.deferred(kinds[kind])
    return st.one_of(st.none(), drawn) if d["optional"] and not required else drawn


def _made_by(make: Any, required: int, params: List[Dict[str, Any]]) -> st.SearchStrategy:
    """A value ``make`` makes from drawn arguments (the required ones and some of the others);
    arguments that the rules between fields refuse are not a case."""

    def call(kwargs: Dict[str, Any]) -> Any:
        try:
            return make(**kwargs)
        except ValueError:
            reject()

    values = {p["name"]: value(p, p.get("default"), i < required) for i, p in enumerate(params)}
    names = [p["name"] for p in params]
    return st.fixed_dictionaries({n: values[n] for n in names[:required]},
                                 optional={n: values[n] for n in names[required:]}).map(call)


def made(cls_name: str) -> st.SearchStrategy:
    """A value of the settings class ``cls_name``, by any of its constructors."""
    return st.one_of([_made_by(make, required, params)
                      for _, make, required, params in descriptions.constructors(CLASSES[cls_name])])


def _cases() -> List[Any]:
    """(constructor, a field) for every field a value it makes has: one it takes, or one whose
    value is not None on what it makes from its defaults (a bands material's ambient colour)."""
    out = []
    for cls in CLASSES.values():
        for name, make, required, params in descriptions.constructors(cls):
            taken = {p["name"]: p for p in params}
            plain = make(**{p["name"]: p["default"] for p in params[:required]})
            out += [pytest.param(make, required, params, f["name"] in taken and params.index(taken[f["name"]]) < required,
                                 taken.get(f["name"], f), id=f"{name or cls.__name__}.{f['name']}")
                    for f in descriptions.fields(cls)
                    if not f["fixed"] and (f["name"] in taken or getattr(plain, f["name"]) is not None)]
    return out


def _same(a: Any, b: Any) -> bool:
    return bool(a == b) and hash(a) == hash(b)


@pytest.mark.parametrize("make, required, params, is_required, field", _cases())
@settings(max_examples=max(1, settings().max_examples // 6))  # a few per field: 5 in CI
@given(data=st.data())
def test_repr_and_pickle_after_a_change(make: Any, required: int, params: List[Dict[str, Any]], is_required: bool,
                                        field: Dict[str, Any], data: Any) -> None:
    x = data.draw(_made_by(make, required, params), label="made")
    name = field["name"]
    change = {name: data.draw(value(field, getattr(x, name), is_required), label=name)}
    try:
        y = x.replace(**change)
    except ValueError as exc:  # a rule between fields: the message names one of the class's fields
        assert str(exc).split(":")[0].split("[")[0].split(".")[0] in {f["name"] for f in type(x).describe()["fields"]}, exc
        reject()
    text = repr(y)
    again = eval(text, dict(NAMESPACE))
    assert _same(again, y), f"{text} evaluates to {again!r}"
    assert repr(again) == text
    assert _same(pickle.loads(pickle.dumps(y)), y)
