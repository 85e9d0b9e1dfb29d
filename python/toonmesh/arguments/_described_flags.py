"""Command-line flags made from the core's description of its settings.

A flag that sets a described setting takes its type, choices, default and help from the class's
``describe()`` (or, for ``toonmesh smooth``, from the smoothing methods' description), so the
core stays the one place where they are written. Ranges are the core's
to check: an error it raises naming the setting (its message starts ``name:``) is reported as
an error of the flag that set it (:func:`errors_as_flags`), as argparse reports its own.
"""

from __future__ import annotations

import argparse
from contextlib import contextmanager
from typing import Any, Dict, Iterator, Optional, Sequence, Tuple

from toonmesh.arguments._described import described

#: The namespace attribute where a subcommand keeps which flag sets which setting:
#: ``{(class name, setting name): argparse.Action}``.
FLAGS_BY_SETTING = "flags_by_setting"

_TYPES = {"int": int, "float": float, "choice": str}


class _CoreDefault:
    """The marker of a flag whose default is the described one."""

    def __repr__(self) -> str:
        return "the core's default"


CORE_DEFAULT: Any = _CoreDefault()


def styles(cls: Any) -> Tuple[str, ...]:
    """The names of ``cls``'s named constructors as command-line words (``thresholded-phong``)."""
    return tuple(c["name"].replace("_", "-") for c in cls.describe()["constructors"] if c["name"])


def setting_help(param: Dict[str, Any], before: str = "", after: str = "", shown: str = "") -> str:
    """The described help with the default argparse fills in (``%`` escaped for it), or with
    ``shown`` where the default is told in words (one per method, say); a kind of line's style
    is "drawn" or "off" by default."""
    if shown:
        shown = shown.replace("%", "%%")
    elif param.get("kind") == "style":
        shown = "off" if param.get("default") in (None, False) else "drawn"
    elif param.get("kind") == "float" and isinstance(param.get("default"), float):
        shown = "%(default)g"
    else:
        shown = "%(default)s"
    return f"{before}{param['help'].replace('%', '%%')}{after} (default: {shown})"


def add_described(
    parser: argparse.ArgumentParser,
    flag: str,
    cls: Any,
    name: str,
    *,
    constructor: str = "",
    default: Any = CORE_DEFAULT,
    also_sets: Sequence[Tuple[Any, str]] = (),
    **options: Any,
) -> argparse.Action:
    """Adds ``flag`` for the described parameter ``name`` of ``cls`` (see :func:`add_param`;
    its default the described one unless ``default`` is given). ``also_sets``: more
    ``(class, setting)`` pairs the flag's value reaches, for :func:`errors_as_flags`."""
    param = described(cls, name, constructor)
    if default is not CORE_DEFAULT:
        param["default"] = default
    action = add_param(parser, flag, param, **options)
    sets(parser, action, (cls, name), *also_sets)
    return action


def add_param(
    parser: argparse.ArgumentParser,
    flag: str,
    param: Dict[str, Any],
    *,
    extra_choices: Sequence[str] = (),
    help_before: str = "",
    help_after: str = "",
    shown_default: str = "",
    **argparse_options: Any,
) -> argparse.Action:
    """Adds ``flag`` for a parameter as the core describes it (a dict of ``kind``, ``choices``,
    ``default`` and ``help``): its type from the kind (a bool is ``--flag/--no-flag`` unless
    ``action`` says otherwise), its choices (after ``extra_choices``, the command line's own
    words such as ``none``), its default and its help (the default shown as ``shown_default``
    says, if given)."""
    options: Dict[str, Any] = dict(
        default=param["default"], help=setting_help(param, help_before, help_after, shown_default)
    )
    kind = param["kind"]
    if kind == "bool":
        options["action"] = argparse.BooleanOptionalAction
    elif kind in _TYPES:
        options["type"] = _TYPES[kind]
    if param.get("choices"):
        options["choices"] = tuple(extra_choices) + tuple(param["choices"])
    options.update(argparse_options)
    return parser.add_argument(flag, **options)


def sets(parser: argparse.ArgumentParser, action: argparse.Action, *settings: Tuple[Any, str]) -> None:
    """Records that ``action``'s flag sets each ``(class, setting)`` of ``settings``."""
    flags: Optional[Dict[Tuple[str, str], argparse.Action]] = parser.get_default(FLAGS_BY_SETTING)
    if flags is None:
        flags = {}
        parser.set_defaults(**{FLAGS_BY_SETTING: flags})
    for cls, name in settings:
        flags[(cls.__name__, name)] = action


@contextmanager
def errors_as_flags(args: argparse.Namespace, *classes: Any) -> Iterator[None]:
    """Inside: a ValueError or TypeError of the core naming a setting of ``classes`` that a flag
    set becomes ``argparse.ArgumentError`` naming that flag (the core's words kept, so the
    setting's name shows too). A setting inside another (``silhouette.width``) counts by its
    last name."""
    try:
        yield
    except (ValueError, TypeError) as exc:
        flags: Dict[Tuple[str, str], argparse.Action] = getattr(args, FLAGS_BY_SETTING, None) or {}
        named = str(exc).split(":", 1)[0].strip()
        for cls in classes:
            for name in (named, named.rsplit(".", 1)[-1]):
                action = flags.get((cls.__name__, name))
                if action is not None:
                    raise argparse.ArgumentError(action, str(exc)) from exc
        raise
