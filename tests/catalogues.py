"""The catalogues the guides print, made from the code and the data they describe: every figure a template can
name (with the givens it reads and the templates that name it), the parts a new figure is drawn from (with
their parameters), every named mistake with its default text, and what each answer type overrides. `tests/test_docs.py` fails when a page is
out of step; `python -m tests.catalogues` rewrites them.
"""
from __future__ import annotations

import ast
import inspect
import re
import sys
from dataclasses import replace
from importlib import import_module, resources
from pathlib import Path


ROOT = Path(__file__).parent.parent
FIGURES_PAGE = ROOT / "docs" / "figures.md"
MISTAKES_PAGE = ROOT / "docs" / "mistakes.md"
ANSWER_TYPES_PAGE = ROOT / "docs" / "answertypes.md"
BEGIN, END = "<!-- made by python -m tests.catalogues: edit the code, not this -->", "<!-- end of the catalogue -->"
#: Modules of exgen.figures holding the parts figures are drawn from, in the order a newcomer meets them.
PARTS = ("svg", "symbols", "values", "pulleys", "tangents", "gears", "shafts", "polygons", "kinematic", "groove")


# ---- figures a template can name ----------------------------------------------------------------------------

def figure_modules():
    """exgen.figures' modules, by name, without the package's own and the checking and measuring ones."""
    folder = ROOT / "exgen" / "figures"
    skip = {"__init__", "checks", "metrics", "layout"}
    return {p.stem: import_module(f"exgen.figures.{p.stem}") for p in sorted(folder.glob("*.py")) if p.stem not in skip}


def template_figures(bank) -> dict[str, list[str]]:
    """'belts:belt_drive' -> the ids of the templates whose sheet or key shows it."""
    named: dict[str, list[str]] = {}
    for template in bank:
        for ref in ([template.figure] if template.figure else []) + list(template.key_figures):
            named.setdefault(ref, []).append(template.id)
    return named


class _Name(str):
    """A given's or step's name that notes when a figure looks it up (compares it, or a prefix of it)."""

    looked_up: set = set()
    __hash__ = str.__hash__

    def __eq__(self, other):
        same = str.__eq__(self, other)
        if same is True:
            _Name.looked_up.add(str(self))
        return same

    def startswith(self, prefix, *args):
        found = str.startswith(self, prefix, *args)
        if found:
            _Name.looked_up.add(str(self))
        return found


def reads(bank, ref: str, template_ids: list[str], seeds=(1, 2)) -> tuple[list[str], list[str]]:
    """The givens and the solver steps a figure looks up by name, drawn for the templates that name it:
    each variant's names are made to note being looked up, and the figure drawn from it."""
    from exgen.load.references import resolve
    from exgen.solve.variant import make_variant

    figure = resolve(ref, "figures")
    givens, steps = [], []
    for template_id in template_ids:
        for seed in seeds:
            variant = make_variant(bank.get(template_id), seed)
            noted = replace(variant, params=tuple(replace(p, name=_Name(p.name)) for p in variant.params),
                            steps=tuple(s._replace(name=_Name(s.name)) for s in variant.steps))
            _Name.looked_up = set()
            figure(noted)
            given = {p.name for p in variant.params}
            givens += [p.name for p in variant.params if p.name in _Name.looked_up and p.name not in givens]
            steps += [s.name for s in variant.steps if s.name in _Name.looked_up - given and s.name not in steps]
    return givens, steps


def needed(function) -> set[str]:
    """The names a figure cannot be drawn without: the string arguments of its `need(variant, "name")` calls
    (each stops the figure with an error naming what is missing), in it and in the functions of its module
    it hands the variant to."""
    module = inspect.getmodule(function)
    tree = ast.parse(inspect.getsource(module))
    functions = {n.name: n for n in tree.body if isinstance(n, ast.FunctionDef)}
    found, seen, todo = set(), set(), [function.__name__]
    while todo:
        name = todo.pop()
        if name in seen or name not in functions:
            continue
        seen.add(name)
        for node in ast.walk(functions[name]):
            if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.args
                    and isinstance(node.args[0], ast.Name) and node.args[0].id == "variant"):
                continue
            if node.func.id == "need" and len(node.args) > 1 and isinstance(node.args[1], ast.Constant):
                found.add(node.args[1].value)
            todo.append(node.func.id)
    return found


def first_sentence(obj) -> str:
    """A docstring's first sentence: to a full stop before a capital, or its end."""
    text = " ".join((inspect.getdoc(obj) or "").split())
    match = re.match(r"(.+?\.)(\s+[A-Z(]|$)", text)
    return match.group(1) if match else text


def figures_catalogue(bank) -> str:
    named = template_figures(bank)
    lines = ["### Figures a template can name", "",
             "`figure: module:function` (or `key_figures: [...]`). *Reads* is what the function looks up by name "
             "in the variants of the templates that name it: givens, and solver steps (in italics: drawn to size "
             "and labelled `?`, or worked from); a template reusing a figure gives its values those names. A name "
             "in bold is one the figure cannot be drawn without (without it, drawing stops with an error naming "
             "it); the others it draws when they are there.", "",
             "| figure | what it draws | reads | named by |", "|---|---|---|---|"]
    for stem, module in figure_modules().items():
        for name, function in inspect.getmembers(module, inspect.isfunction):
            if function.__module__ != module.__name__ or name.startswith("_"):
                continue
            parameters = list(inspect.signature(function).parameters)
            if parameters != ["variant"]:
                continue
            ref = f"{stem}:{name}"
            users = named.get(ref, [])
            givens, steps = reads(bank, ref, users)
            must = needed(function)
            read = ", ".join([f"**`{g}`**" if g in must else f"`{g}`" for g in givens]
                             + [f"***`{s}`***" if s in must else f"*`{s}`*" for s in steps])
            lines.append(f"| `{ref}` | {_cell(first_sentence(function))} | {read} | "
                         f"{', '.join(users) if users else '(none yet)'} |")
    lines += ["", "### Parts a new figure is drawn from", "",
              "| module | function | what it does |", "|---|---|---|"]
    for stem in PARTS:
        module = import_module(f"exgen.figures.{stem}")
        for name, obj in inspect.getmembers(module, lambda o: inspect.isfunction(o) or inspect.isclass(o)):
            if obj.__module__ != module.__name__ or name.startswith("_"):
                continue
            if inspect.isfunction(obj) and list(inspect.signature(obj).parameters) == ["variant"]:
                continue  # a whole figure: listed above
            lines.append(f"| `{stem}` | `{name}{_signature(obj)}` | {_cell(first_sentence(obj))} |")
            if inspect.isclass(obj) and stem in ("svg", "kinematic"):
                for method, member in inspect.getmembers(obj, inspect.isfunction):
                    if not method.startswith("_") and member.__qualname__.startswith(obj.__name__ + "."):
                        lines.append(f"| | `.{method}{_signature(member, drop_self=True)}` | "
                                     f"{_cell(first_sentence(member))} |")
    return "\n".join(lines) + "\n"


def _signature(obj, drop_self: bool = False) -> str:
    try:
        signature = inspect.signature(obj)
    except (TypeError, ValueError):
        return ""
    parameters = list(signature.parameters.values())[1 if drop_self else 0:]
    shown = []
    for p in parameters:
        text = p.name if p.default is inspect.Parameter.empty else f"{p.name}={p.default!r}"
        shown.append(text.replace("|", "\\|"))
    return f"({', '.join(shown)})"


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


# ---- named mistakes -------------------------------------------------------------------------------------------

def mistake_sections() -> list[tuple[str, list[str]]]:
    """The data file's sections ('# ---- speeds') with the names under each, in its order."""
    text = resources.files("exgen").joinpath("data/mistakes.yaml").read_text("utf-8")
    sections: list[tuple[str, list[str]]] = [("", [])]
    for line in text.splitlines():
        heading = re.match(r"# ---- (.+)", line)
        entry = re.match(r"([A-Za-z0-9_]+):", line)
        if heading:
            sections.append((heading.group(1).strip(), []))
        elif entry:
            sections[-1][1].append(entry.group(1))
    return [s for s in sections if s[1]]


def mistakes_catalogue(bank) -> str:
    from exgen.load.mistake_messages import default_messages

    texts = default_messages()
    naming: dict[str, dict[str, list[str]]] = {}
    for template in bank:
        for part in template.parts:
            for mistake in part.mistakes:
                naming.setdefault(mistake.when, {}).setdefault(template.id, []).append(part.id)
    lines = []
    for title, names in mistake_sections():
        lines += [f"### {title[:1].upper() + title[1:]}", "", "| name | default text | named by |", "|---|---|---|"]
        for name in names:
            users = [f"{tid} ({', '.join(parts)})" for tid, parts in naming.get(name, {}).items()]
            shown = ", ".join(users[:3]) + (f" and {len(users) - 3} more" if len(users) > 3 else "")
            lines.append(f"| `{name}` | {_cell(texts[name])} | {shown or '(no template yet)'} |")
        lines.append("")
    own = {name: users for name, users in naming.items() if name not in texts}
    lines += ["### Named with a part's own words only", "",
              "These names have no default text: each part that names one says it in its own `say:` (the first "
              "is shown). Reuse one for the same slip with words of your own, or give it a default in "
              "`exgen/data/mistakes.yaml` when a second template needs it.", "",
              "| name | the first part's words | named by |", "|---|---|---|"]
    says = {(t.id, p.id, m.when): m.say for t in bank for p in t.parts for m in p.mistakes}
    for name in sorted(own):
        users = [f"{tid} ({', '.join(parts)})" for tid, parts in own[name].items()]
        tid, parts = next(iter(own[name].items()))
        shown = ", ".join(users[:3]) + (f" and {len(users) - 3} more" if len(users) > 3 else "")
        lines.append(f"| `{name}` | {_cell(says[(tid, parts[0], name)])} | {shown} |")
    lines.append("")
    return "\n".join(lines)


# ---- what each answer type overrides ----------------------------------------------------------------------

def answer_types_catalogue() -> str:
    """AnswerType's attributes and methods, in the order base.py defines them, with the types that
    override each."""
    from exgen.answertypes import registry
    from exgen.answertypes.base import AnswerType

    types = sorted(registry().values(), key=lambda t: t.name)
    lines = ["| member | what it is for | overridden by |", "|---|---|---|"]
    for name, member in AnswerType.__dict__.items():
        if name.startswith("_"):
            continue
        own = [t.name for t in types if _defines(type(t), name)]
        about = first_sentence(member) if callable(member) else _attribute_note(name)
        signature = _signature(member, drop_self=True) if callable(member) else ""
        lines.append(f"| `{name}{signature}` | {_cell(about)} | {', '.join(own) if own else '(none: the default serves)'} |")
    return "\n".join(lines) + "\n"


def _defines(cls, name: str) -> bool:
    """Whether a type's class (or a class of its own between it and AnswerType) sets `name`."""
    from exgen.answertypes.base import AnswerType

    return any(name in klass.__dict__ for klass in cls.__mro__ if klass is not AnswerType and klass is not object)


def _attribute_note(name: str) -> str:
    """The comment above a class attribute in base.py (`#: ...`)."""
    source = inspect.getsource(import_module("exgen.answertypes.base").AnswerType)
    match = re.search(rf"((?:\s*#:.*\n)+)\s*{name}\b", source)
    if match is None:
        return {"name": "The name a part gives as `type:`.",
                "default_tol": "The tolerance a part of this type has without `tol:`."}.get(name, "")
    return " ".join(line.strip()[2:].strip() for line in match.group(1).strip().splitlines())


# ---- the pages ---------------------------------------------------------------------------------------------

def with_catalogue(page: Path, catalogue: str) -> str:
    """The page's text with what stands between its markers replaced by `catalogue`."""
    text = page.read_text(encoding="utf-8")
    head, _, rest = text.partition(BEGIN)
    _, _, tail = rest.partition(END)
    if not rest:
        raise ValueError(f"{page}: no {BEGIN} marker")
    return f"{head}{BEGIN}\n\n{catalogue.strip()}\n\n{END}{tail}"


def pages(bank) -> dict[Path, str]:
    """Each page as the code and data make it now."""
    return {FIGURES_PAGE: with_catalogue(FIGURES_PAGE, figures_catalogue(bank)),
            MISTAKES_PAGE: with_catalogue(MISTAKES_PAGE, mistakes_catalogue(bank)),
            ANSWER_TYPES_PAGE: with_catalogue(ANSWER_TYPES_PAGE, answer_types_catalogue())}


if __name__ == "__main__":
    from exgen.load.bank import load_bank

    for path, text in pages(load_bank()).items():
        if path.read_text(encoding="utf-8") != text:
            path.write_text(text, encoding="utf-8")
            print(f"rewrote {path.relative_to(ROOT)}")
    sys.exit(0)
