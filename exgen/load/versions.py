"""A version per template that changes exactly when something that can change a number or a verdict does.

It covers the template's meaning (its parsed data, canonically serialised, so comments and layout do
not count), the code it runs (the import closure of its solver, packaged or a file of its bank folder, and
of the drawing and grading code, each module hashed from its syntax tree without docstrings, so comments
and formatting do not count),
the data files that code reads (unit and choice aliases, mistake texts), and the versions of the
numerical libraries. The manifest records each part, so a mismatch at grading names what changed.

Computed only when asked (generate, grade): parsing ~60 small modules costs ~0.1 s, and imports nothing.
"""
from __future__ import annotations

import ast
import hashlib
import importlib.util
import json
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from .references import local_file, split
from .template import Template

#: Packages whose modules are followed; anything else imported (numpy, pint) is counted by its version.
PACKAGES = ("exgen", "graders")
#: Every template runs these: drawing and the variant (numbers), grading (verdicts).
COMMON_ROOTS = ("exgen.solve.variant", "graders.marking")
#: Output only: what they print never changes a number or a verdict.
OUTPUT_ONLY = ("exgen.render", "exgen.figures", "exgen.cli", "exgen.issue.generate", "graders.report", "exgen.load.versions")
#: Folders of data files the code reads (aliases, messages).
DATA_DIRS = ("exgen/data", "graders/data")
LIBRARIES = ("numpy", "pint")
#: How a version names a file of a bank folder (a solver beside its template).
BANK_PREFIX = "bank:"


@dataclass(frozen=True)
class TemplateVersion:
    """The version (one digest) and what it is made of, by name."""

    digest: str
    template: str                 # the template's parsed data
    code: dict[str, str]          # "exgen/solvers/belts.py" -> hash of its syntax tree
    data: dict[str, str]          # "exgen/data/unit_aliases.txt" -> hash of its bytes
    libraries: dict[str, str]     # "numpy" -> installed version

    def record(self) -> dict:
        """What the manifest keeps for this template."""
        return {"version": self.digest, "template": self.template, "code": sorted(self.code),
                "data": sorted(self.data), "libraries": dict(self.libraries)}


def data_digest(data) -> str:
    """sha256 of parsed YAML data in one canonical form: key order, comments and layout do not count."""
    text = json.dumps(_canonical(data), sort_keys=True, separators=(",", ":"), ensure_ascii=False)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def _canonical(value):
    """JSON-ready, with types kept apart (1, 1.0, "1" and true are four different values)."""
    if isinstance(value, dict):
        if all(isinstance(k, str) for k in value):
            return {k: _canonical(v) for k, v in value.items()}
        return {"(map)": sorted(json.dumps([_canonical(k), _canonical(v)], sort_keys=True) for k, v in value.items())}
    if isinstance(value, (list, tuple)):
        return [_canonical(v) for v in value]
    if value is None or isinstance(value, (bool, int, str)):
        return value
    if isinstance(value, float):
        return {"(float)": repr(value)}
    return {f"({type(value).__name__})": str(value)}  # dates, binary: by their text


def template_version(template: Template) -> TemplateVersion:
    solver_file = local_file(template.solver)
    if solver_file is None:
        modules = _closure((f"exgen.solvers.{split(template.solver)[0]}",) + COMMON_ROOTS)
        code = {}
    else:  # a solver of the bank's own: its file, and ours that it imports
        modules = _closure(tuple(_imports("", solver_file)) + COMMON_ROOTS)
        code = {bank_name(template, solver_file): _code_hash(solver_file)}
    code.update({_relative(path): _code_hash(path) for path in modules})
    data = _data_files()
    libraries = _library_versions()
    digest = hashlib.sha256()
    for name, value in [("template", template.digest), *sorted(code.items()), *sorted(data.items()),
                        *sorted(libraries.items())]:
        digest.update(f"{name}\0{value}\n".encode("utf-8"))
    return TemplateVersion(digest.hexdigest(), template.digest, code, data, libraries)


def bank_name(template: Template, path: Path) -> str:
    """What a version calls a file of a bank: 'bank:<folder>/<path in it>', wherever the folder lies now."""
    root = Path(template.bank_dir or path.parent).resolve()
    return f"{BANK_PREFIX}{root.name}/{path.relative_to(root).as_posix()}"


def current_hash(name: str, template: Template | None = None) -> str | None:
    """What a name a version records ("exgen/solvers/belts.py", "exgen/data/x.txt", "numpy", or a file of
    `template`'s bank, "bank:course/cams.py") is now."""
    if name in LIBRARIES:
        return _library_versions()[name]
    if name.startswith(BANK_PREFIX):
        root = Path(template.bank_dir).resolve() if template is not None and template.bank_dir else None
        folder, _, rest = name[len(BANK_PREFIX):].partition("/")
        path = root / rest if root is not None and root.name == folder and rest else None
        return _code_hash(path) if path is not None and path.is_file() else None
    package, _, rest = name.partition("/")
    root = _roots().get(package)
    path = root / rest if root is not None and rest else None
    if path is None or not path.is_file():
        return None
    return _code_hash(path) if path.suffix == ".py" else hashlib.sha256(path.read_bytes()).hexdigest()


def file_hashes(version: TemplateVersion) -> dict[str, str]:
    """Every code and data file a version is made of, with its hash."""
    return {**version.code, **version.data}


# ---- the import closure -----------------------------------------------------------------------------

@lru_cache(maxsize=1)
def _roots() -> dict[str, Path]:
    """Where each package's files are; graders is found, not imported (exgen never imports it)."""
    graders = importlib.util.find_spec("graders")
    return {"exgen": Path(__file__).parent.parent, "graders": Path(graders.origin).parent}


def _relative(path: Path) -> str:
    for package, root in _roots().items():
        if path.is_relative_to(root):
            return f"{package}/{path.relative_to(root).as_posix()}"
    return path.as_posix()


def _file_of(module: str) -> Path | None:
    """The file of a module of ours ("exgen.solvers.belts" -> .../solvers/belts.py), or None."""
    package, _, rest = module.partition(".")
    root = _roots().get(package)
    if root is None:
        return None
    base = root.joinpath(*rest.split(".")) if rest else root
    for candidate in (base.with_suffix(".py"), base / "__init__.py"):
        if candidate.is_file():
            return candidate
    return None


def _output_only(module: str) -> bool:
    return any(module == m or module.startswith(m + ".") for m in OUTPUT_ONLY)


@lru_cache(maxsize=64)
def _closure(roots: tuple[str, ...]) -> tuple[Path, ...]:
    """Files of every module of ours reachable by import from `roots` (lazy imports in functions too)."""
    seen: dict[str, Path] = {}
    todo = list(roots)
    while todo:
        module = todo.pop()
        if module in seen or _output_only(module):
            continue
        path = _file_of(module)
        if path is None:
            continue
        seen[module] = path
        parts = module.split(".")
        todo += [".".join(parts[:i]) for i in range(1, len(parts))]  # a module's packages run first
        todo += _imports(module, path)
        if path.name == "__init__.py" and _parsed(path)[2]:  # a registry of its own modules (answer types)
            todo += [f"{module}.{child.stem}" for child in path.parent.glob("*.py") if child.name != "__init__.py"]
    return tuple(sorted(set(seen.values())))


def _imports(module: str, path: Path) -> list[str]:
    """Modules of ours that `module` imports, relative imports resolved; `from x import y` may name a module y.
    A file of a bank (`module` "") has no package: only its imports of exgen by name count."""
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    found = []
    for level, name, names in _parsed(path)[0]:
        if level and not module:
            continue
        if level:
            base = package.split(".")
            source = ".".join(base[: len(base) - level + 1] + ([name] if name else []))
        else:
            source = name or ""
        if source.split(".")[0] in PACKAGES:
            found.append(source)
            found += [f"{source}.{alias}" for alias in names]
    return found


def _parsed(path: Path) -> tuple[tuple, str, bool]:
    """One parse per file text: its imports (level, module, names), the hash of its syntax tree, and
    whether it imports the modules of its own package by listing them (pkgutil.iter_modules: a registry).
    Keyed by the text, so a file edited while the process runs is read as it is now."""
    return _parsed_text(path.read_text(encoding="utf-8"), str(path))


@lru_cache(maxsize=None)
def _parsed_text(text: str, filename: str) -> tuple[tuple, str, bool]:
    tree = ast.parse(text, filename=filename)
    imports, registry = [], False
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            imports += [(0, alias.name, ()) for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            imports.append((node.level, node.module, tuple(alias.name for alias in node.names)))
        elif isinstance(node, ast.Attribute) and node.attr == "iter_modules":
            registry = True
    tree = _WithoutDocstrings().visit(tree)
    digest = hashlib.sha256(ast.dump(tree, include_attributes=False).encode("utf-8")).hexdigest()
    return tuple(imports), digest, registry


def _code_hash(path: Path) -> str:
    """sha256 of the module's syntax tree without docstrings: comments and formatting do not count."""
    return _parsed(path)[1]


class _WithoutDocstrings(ast.NodeTransformer):
    """Drops the docstring of the module, and of every class and function, from a (fresh) tree."""

    def _strip(self, node):
        self.generic_visit(node)
        body = node.body
        if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant) \
                and isinstance(body[0].value.value, str):
            node.body = body[1:] or [ast.Pass()]
        return node

    visit_Module = visit_ClassDef = visit_FunctionDef = visit_AsyncFunctionDef = _strip


@lru_cache(maxsize=1)
def _data_files() -> dict[str, str]:
    files = {}
    for package, root in _roots().items():
        for folder in (d for d in DATA_DIRS if d.startswith(package + "/")):
            directory = root / folder.partition("/")[2]
            if directory.is_dir():
                for path in sorted(p for p in directory.rglob("*") if p.is_file()):
                    files[_relative(path)] = hashlib.sha256(path.read_bytes()).hexdigest()
    return files


@lru_cache(maxsize=1)
def _library_versions() -> dict[str, str]:
    from importlib import metadata  # ~10 ms to import: only when a version is computed

    versions = {}
    for name in LIBRARIES:
        try:
            versions[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            versions[name] = "not installed"
    return versions
