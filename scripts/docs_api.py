"""The API reference (docs/api/): a MkDocs hook and a griffe extension.

The reference is made by mkdocstrings from the docstrings, read by griffe. This file

- checks that every public function, class and method has a docstring (a public name without
  one is a warning, which fails the strict build; data attributes and properties are described
  in their class's docstring);
- gives the compiled core's functions and classes the signatures of its type stub
  (python/toonmesh/_core.pyi, generated from the core's description of its settings), where the
  compiled module has none (``bands(*args, **kwargs)``), while their docstrings stay the module's;
- adds to each settings class of the core its constructors' keywords and its fields (help,
  type, default), read from the core's description of the class (``Class.describe()``);
- leaves out what is not an entry: names a module imports or leaves out of its ``__all__``,
  namedtuple fields' "Alias for field number N" (the fields are described in their class's
  docstring) and descriptors' memory addresses shown as defaults;
- writes each API page's summary table (``<!-- api-summary -->``), the index page's table of
  every entry (``<!-- api-index -->``) and the render keywords' table
  (``<!-- render-keywords -->``), read from the core's description of ``RenderOptions``;
- turns the docstrings' Sphinx roles (``:class:`Material```) into links to the entries.

mkdocs.yml names this file twice: as a hook, and as a griffe extension of mkdocstrings
(``scripts/docs_api.py:PublicApi``).
"""

from __future__ import annotations

import html
import importlib.util
import logging
import re
import sys
import textwrap
import warnings
from pathlib import Path
from typing import Dict, Iterator, List, Optional, Tuple

import griffe

log = logging.getLogger("mkdocs.hooks.api")

ROOT = Path(__file__).resolve().parent.parent
STUB = ROOT / "python" / "toonmesh" / "_core.pyi"

#: the documented modules: the package (with toonmesh.smooth, .edges and .shapes, which it lists in
#: __all__) and the public modules it does not import
MODULES = ("toonmesh", "toonmesh.smooth", "toonmesh.edges", "toonmesh.shapes", "toonmesh.batch",
           "toonmesh.data", "toonmesh.figures", "toonmesh.cli", "toonmesh.testing", "toonmesh.pytest_plugin")

#: the render keywords' table's anchor (docs/api/rendering.md), which roles naming the
#: ``RenderKeywords`` TypedDict link to
RENDER_KEYWORDS = "toonmesh.RenderKeywords"
RENDER_KEYWORDS_ANCHOR = "render-keywords"
#: the API pages' folder in docs/
API_DIR = "api/"
#: a mkdocstrings entry in a page: ``::: toonmesh.render``
ENTRY = re.compile(r"^:::\s+(\S+)", re.M)
#: a Sphinx role as the rendered page shows it: ``:class:<code>Material</code>``
ROLE_HTML = re.compile(r":(?:py:)?(?:class|func|meth|attr|data|mod|exc|obj):<code>~?([\w.]+?)(?:\(\))?</code>")
#: the same role in markdown (the summary tables' first lines)
ROLE_MD = re.compile(r":(?:py:)?(?:class|func|meth|attr|data|mod|exc|obj):`~?([\w.]+?)(?:\(\))?`")


def load(python_dir: Path, public: bool = True) -> griffe.Module:
    """The package as griffe reads it (inspected): with ``public``, as the reference shows it
    (this file's extension applied), else every name it holds."""
    extensions = griffe.load_extensions(PublicApi()) if public else None
    with warnings.catch_warnings():  # importing every module to read it: their deprecation notices
        warnings.simplefilter("ignore", DeprecationWarning)
        return griffe.load("toonmesh", search_paths=[str(python_dir), *sys.path], force_inspection=True,
                           extensions=extensions)


def _target(member: griffe.Object) -> Optional[griffe.Object]:
    """What ``member`` is: itself, or what an alias names; None where that cannot be found."""
    if not member.is_alias:
        return member
    try:
        return member.final_target
    except (griffe.AliasResolutionError, griffe.CyclicAliasError):
        return None


def _public_members(obj: griffe.Object) -> Iterator[Tuple[str, griffe.Object]]:
    """The public members ``obj`` documents: its ``__all__`` where it has one, else the names
    without an underscore that are its own (not imported from elsewhere, not inherited)."""
    exports = obj.exports if obj.is_module else None
    for name, member in obj.members.items():
        if name.startswith("_") or name == "annotations":
            continue
        if exports is not None and name not in exports:
            continue
        target = _target(member)
        if target is None or not target.path.startswith("toonmesh"):
            continue
        if exports is None and obj.is_module and member.is_alias:
            continue  # imported into the module, documented where it is defined
        if obj.is_class and target.parent is not obj and not member.is_alias:
            continue  # inherited
        yield name, target


def undocumented(python_dir: Path) -> List[str]:
    """Full names of the public functions, classes and methods of MODULES without a docstring."""
    package = load(python_dir, public=False)
    missing = set()
    seen = set()
    stack = [package[name[len("toonmesh."):]] if name != "toonmesh" else package for name in MODULES]
    while stack:
        obj = stack.pop()
        if obj.path in seen:
            continue
        seen.add(obj.path)
        for name, member in obj.members.items():
            if name.startswith("_"):
                continue
            if member.is_alias:
                member = _target(member)
                if member is None or not member.path.startswith("toonmesh"):
                    continue  # imported from elsewhere (numpy, typing): not toonmesh's to document
            if obj.is_class and member.parent is not obj:
                continue  # inherited
            if member.is_module and not member.path.startswith(obj.path + "."):
                continue
            if member.is_class or member.is_function:
                if not (member.docstring and member.docstring.value.strip()):
                    missing.add(member.path)
            if member.is_class or (member.is_module and member.path in MODULES):
                stack.append(member)
    return sorted(missing)


# ---------------------------------------------------------------------------------------------
# The griffe extension


class PublicApi(griffe.Extension):
    """Signatures from the core's stub; no namedtuple field aliases; no memory addresses."""

    def on_package(self, *, pkg: griffe.Module, **kwargs) -> None:
        if pkg.name != "toonmesh":
            return
        stub = griffe.visit("_core", filepath=STUB, code=STUB.read_text(encoding="utf-8"))
        _signatures_from_stub(pkg["_core"], stub)
        _settings_sections(pkg["_core"])
        _tidy(pkg, set())


def _signatures_from_stub(runtime: griffe.Object, stub: griffe.Object) -> None:
    """The stub's parameters and return types on the compiled objects, whose own signatures are
    ``(*args, **kwargs)`` or untyped; a settings class's ``__new__`` becomes its ``__init__``."""
    for name, declared in stub.members.items():
        if declared.is_alias or name not in runtime.members:
            continue
        found = _target(runtime.members[name])
        if found is None or found.kind is not declared.kind:
            continue
        if declared.is_class:
            _signatures_from_stub(found, declared)
            new = declared.members.get("__new__")
            if new is not None and new.is_function:
                params = [griffe.Parameter("self", kind=griffe.ParameterKind.positional_or_keyword)]
                params += [_readable(p) for p in list(new.parameters)[1:]]
                found.set_member("__init__", griffe.Function("__init__", parameters=griffe.Parameters(*params),
                                                             returns=None))
        elif declared.is_function:
            found.parameters = griffe.Parameters(*(_readable(p) for p in declared.parameters))
            found.returns = declared.returns


def _stubs():
    """scripts/stubs.py, which writes the stub: how it spells each kind of field's type."""
    spec = importlib.util.spec_from_file_location("toonmesh_stubs", ROOT / "scripts" / "stubs.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def shown(value) -> str:
    """A described default as the reference shows it: floats to 6 significant digits."""
    if isinstance(value, float):
        return f"{value:g}"
    if isinstance(value, (tuple, list)):
        inner = ", ".join(shown(v) for v in value)
        return f"({inner}{',' if len(value) == 1 else ''})" if isinstance(value, tuple) else f"[{inner}]"
    return repr(value)


def _sentence(text: str) -> str:
    text = " ".join(text.split())
    return text if text.endswith(".") else text + "."


def _settings_sections(core: griffe.Object) -> None:
    """Each settings class's fields (an "Attributes" section: type, help, default) and each of
    its constructors' keywords (an "Args" section: help, default), from the core's description
    of the class (``Class.describe()``), after the docstring the module gives it."""
    import toonmesh._core as runtime

    stubs = _stubs()
    for name in runtime.SETTINGS_CLASSES:
        cls = getattr(runtime, name)
        described = cls.describe()
        try:
            start = cls()
        except TypeError:
            start = None  # built by its static methods only: no one default for its fields
        taken = set()  # the fields the plain constructor takes: its "Args" say them
        for c in described["constructors"]:
            target = core[name].members.get(c["name"]) if c["name"] else core[name]
            if target is None:
                continue
            if not c["name"]:
                taken = {p["name"] for p in c["params"]}
            function = target if target.is_function else target.members.get("__init__")
            defaults = {p["name"]: p.get("default") for p in c["params"]}
            for parameter in function.parameters if function is not None else ():
                if defaults.get(parameter.name) is not None:
                    parameter.default = shown(defaults[parameter.name])  # what omitting it gives
            _append_section(target, "Args", [f"{p['name']}: {_sentence(p['help'])}" for p in c["params"]])
        replace = core[name].members.get("replace")
        if replace is not None:  # takes every field a value can change
            _append_section(replace, "Args", [f"{f['name']}: {_sentence(f['help'])}" for f in described["fields"]
                                              if not f["fixed"]])
        fields = []
        for f in described["fields"]:
            if f["name"] in taken:
                continue
            entry = f"{f['name']} ({stubs.gives(f)}): {_sentence(f['help'])}"
            if start is not None:
                entry += f" Default ``{shown(getattr(start, f['name']))}``."
            fields.append(entry)
        _append_section(core[name], "Attributes", fields)


def _append_section(obj: griffe.Object, title: str, entries: List[str]) -> None:
    if not entries:
        return
    lines = [f"{title}:"]
    for entry in entries:
        wrapped = textwrap.wrap(entry, 92)
        lines += ["    " + wrapped[0], *("        " + w for w in wrapped[1:])]
    if obj.docstring:  # keeps the parser mkdocstrings gave it
        obj.docstring.value = obj.docstring.value.rstrip() + "\n\n" + "\n".join(lines)
    else:
        obj.docstring = griffe.Docstring("\n".join(lines), parent=obj)


def _readable(p: griffe.Parameter) -> griffe.Parameter:
    """A stub's parameter with ``None`` for the stub's ``...`` default (None takes the core's),
    and ``Color`` for the stub's ``_Color``."""
    default = "None" if p.default is not None and str(p.default) == "..." else p.default
    annotation = p.annotation
    if annotation is not None and "_Color" in str(annotation):
        annotation = readable_type(str(annotation))
    return griffe.Parameter(p.name, annotation=annotation, kind=p.kind, default=default)


def readable_type(annotation: str) -> str:
    """A stub's type as the reference shows it: its colour type ``_Color`` (a string
    ``'#rrggbb'`` or three numbers in [0, 1], see the settings page) as ``Color``."""
    return annotation.replace("_Color", "Color")


#: names a module holds that are not its API: ``from __future__ import annotations``, the
#: ``TYPE_CHECKING`` switch
NOT_API = {"annotations", "TYPE_CHECKING"}


def _tidy(obj: griffe.Object, seen: set) -> None:
    """Leaves out of ``obj`` (and its modules and classes) what is not an entry."""
    if obj.path in seen:
        return
    seen.add(obj.path)
    exports = {str(e) for e in obj.exports} if obj.is_module and obj.exports is not None else None
    for name, member in list(obj.members.items()):
        if obj.is_module and obj.path != "toonmesh" and (member.is_alias or not member.is_module) and (
                name in NOT_API or (exports is not None and name not in exports and not name.startswith("_"))
                or (exports is None and member.is_alias)):
            obj.del_member(name)  # imported into the module, or not in its __all__
            continue
        if member.is_alias:
            continue
        if member.is_attribute:
            doc = member.docstring.value if member.docstring else ""
            if re.fullmatch(r"Alias for field number \d+", doc.strip()):
                obj.del_member(name)  # a namedtuple's field: its class's docstring says what it is
            elif member.value is not None and re.search(r" object at 0x[0-9a-fA-F]+", str(member.value)):
                member.value = None  # a descriptor (the viewer's settings): its value is no default
                member.labels.add("property")
        elif member.is_module or member.is_class:
            _tidy(member, seen)


# ---------------------------------------------------------------------------------------------
# The hook

_PACKAGE: Dict[str, griffe.Module] = {}


def _package(config) -> griffe.Module:
    if "toonmesh" not in _PACKAGE:
        _PACKAGE["toonmesh"] = load(Path(config["config_file_path"]).parent / "python")
    return _PACKAGE["toonmesh"]


def on_config(config):
    _PACKAGE.clear()
    for name in undocumented(Path(config["config_file_path"]).parent / "python"):
        log.warning("no docstring: %s (every public function, class and method of the API has one)", name)
    return config


def _lookup(package: griffe.Module, identifier: str) -> Optional[griffe.Object]:
    try:
        return _target(package[identifier[len("toonmesh."):]] if identifier != "toonmesh" else package)
    except KeyError:
        return None


def entries(package: griffe.Module, markdown: str) -> List[Tuple[str, griffe.Object]]:
    """The identifiers a page documents, each with its object: its ``:::`` entries and, for a
    module, its public members (a class's methods are found from the class's entry)."""
    out: List[Tuple[str, griffe.Object]] = []
    for identifier in ENTRY.findall(markdown):
        obj = _lookup(package, identifier)
        if obj is None:
            continue
        if obj.is_module:
            out += [(f"{identifier}.{name}", member) for name, member in _public_members(obj)]
        else:
            out.append((identifier, obj))
    return out


def _documented(package: griffe.Module, files) -> Dict[str, str]:
    """Every identifier the API pages show (their entries and their classes' public members),
    each with the page it is on."""
    out: Dict[str, str] = {}
    for f in files:
        if not (f.src_uri.startswith(API_DIR) and f.src_uri.endswith(".md")):
            continue
        text = Path(f.abs_src_path).read_text(encoding="utf-8")
        for identifier in ENTRY.findall(text):
            out[identifier] = f.src_uri
        for identifier, obj in entries(package, text):
            out[identifier] = f.src_uri
            if obj.is_class:
                for name, _ in _public_members(obj):
                    out[f"{identifier}.{name}"] = f.src_uri
    return out


_IDS: Dict[str, str] = {}


def on_files(files, config):
    _IDS.clear()
    _IDS.update(_documented(_package(config), files))
    _IDS[RENDER_KEYWORDS] = "api/rendering.md"  # the anchor above the render keywords' table
    return files


def resolve(name: str, known: Dict[str, str]) -> Optional[str]:
    """The identifier of the entry a role names: ``toonmesh.X`` or the entry whose path ends with
    ``name`` (the shortest, where a module's function and a class's method share a name)."""
    for candidate in (name, f"toonmesh.{name}"):
        if candidate in known:
            return candidate
    ends = sorted((i for i in known if i.endswith("." + name)), key=lambda i: i.count("."))
    if ends and (len(ends) == 1 or ends[0].count(".") < ends[1].count(".")):
        return ends[0]
    return None


def _first_line(obj: griffe.Object) -> str:
    """The docstring's first sentence (in its first paragraph), roles as links."""
    doc = obj.docstring.value.strip() if obj.docstring else ""
    first = " ".join(doc.split("\n\n")[0].split())
    first = re.split(r"(?<=[a-z0-9)\]`'])\. (?=[A-Z])", first, maxsplit=1)[0].rstrip(".") + "."
    first = ROLE_MD.sub(lambda m: _md_link(m.group(1)), first)
    return first.replace("|", "\\|")


def _md_link(name: str) -> str:
    identifier = resolve(name, _IDS)
    return f"[`{_shown(name)}`][{identifier}]" if identifier else f"`{_shown(name)}`"


def _shown(name: str) -> str:
    """A role's name as the page shows it: without the package's prefix."""
    return name[len("toonmesh."):] if name.startswith("toonmesh.") else name


def summary(rows: List[Tuple[str, griffe.Object]]) -> str:
    """A table of ``rows`` (identifier, object): each name linked to its entry, and one line."""
    lines = ['<div class="tm-api-table" markdown>', "", "| Name | What it is |", "| --- | --- |"]
    for identifier, obj in rows:
        short = identifier[len("toonmesh."):]
        call = "()" if obj.is_function else ""
        lines.append(f"| [`{short}{call}`][{identifier}] | {_first_line(obj)} |")
    return "\n".join(lines + ["", "</div>"]) + "\n"


def render_keywords() -> str:
    """The render keywords as a table (keyword, type, default, meaning), read from the core's
    description of ``RenderOptions``; the types are the stub's (scripts/stubs.py)."""
    import toonmesh

    stubs = _stubs()
    start = toonmesh.RenderOptions()
    lines = ['<div class="tm-api-table" markdown>', "", "| Keyword | Type | Default | Meaning |",
             "| --- | --- | --- | --- |"]
    for f in toonmesh.RenderOptions.describe()["fields"]:
        kind = readable_type(stubs.takes(f)) + (" or None" if f["optional"] else "")
        default = shown(getattr(start, f["name"]))
        help_ = f["help"].replace("|", "\\|")
        lines.append(f'| <span id="render-keywords.{f["name"]}">`{f["name"]}`</span> | `{kind}` | '
                     f"`{default}` | {help_} |")
    return "\n".join(lines + ["", "</div>"]) + "\n"


def on_page_markdown(markdown: str, page, config, files) -> str:
    """The API pages' tables: ``<!-- api-summary -->`` (the page's entries),
    ``<!-- api-index -->`` (every page's) and ``<!-- render-keywords -->``."""
    uri = page.file.src_uri
    if not uri.startswith(API_DIR):
        return markdown
    package = _package(config)
    if "<!-- api-summary -->" in markdown:
        markdown = markdown.replace("<!-- api-summary -->", summary(entries(package, markdown)))
    if "<!-- api-index -->" in markdown:
        sections = []
        # the pages in the navigation's order
        for f in [child.file for child in page.parent.children if child.is_page] if page.parent else []:
            if f.src_uri.startswith(API_DIR) and f.src_uri.endswith(".md") and f.src_uri != uri:
                text = Path(f.abs_src_path).read_text(encoding="utf-8")
                title = re.search(r"^# (.+)$", text, re.M)
                link = f.src_uri[len(API_DIR):]
                sections.append(f"## [{title.group(1) if title else link}]({link})\n\n"
                                + summary(entries(package, text)))
        markdown = markdown.replace("<!-- api-index -->", "\n".join(sections))
    if "<!-- render-keywords -->" in markdown:
        markdown = markdown.replace("<!-- render-keywords -->", render_keywords())
        # the table's heading is the entry that links to RenderKeywords reach, roles and the
        # signatures' ``Unpack[RenderKeywords]`` (named by the module Python gives the TypedDict
        # the core makes)
        import toonmesh

        autorefs = config.plugins["autorefs"]
        autorefs.register_anchor(page, RENDER_KEYWORDS, anchor=RENDER_KEYWORDS_ANCHOR)
        made_in = f"{toonmesh.RenderKeywords.__module__}.RenderKeywords"
        autorefs.register_anchor(page, made_in, anchor=RENDER_KEYWORDS_ANCHOR, primary=False)
    return markdown


def on_page_content(content: str, page, config, files) -> str:
    """The docstrings' roles (``:class:`Material``` shows as ``:class:<code>Material</code>``)
    as links to their entries (autorefs resolves them once every page is made); a role naming
    no entry shows as its name in code."""

    def link(m: "re.Match[str]") -> str:
        name = m.group(1)
        shown = f"<code>{html.escape(_shown(name))}</code>"
        identifier = resolve(name, _IDS)
        if identifier is None:
            return shown
        return f'<autoref identifier="{identifier}" optional>{shown}</autoref>'

    return ROLE_HTML.sub(link, content)
