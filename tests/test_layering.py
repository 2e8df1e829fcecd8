"""The packages depend one way: graders on exgen, never exgen on graders. The command line is the one
place that reaches both (it offers `exgen grade`); everything else in exgen stands without grading."""
import ast
from pathlib import Path

ROOT = Path(__file__).parent.parent
SHELL = {"exgen/cli/commands.py"}  # the application's shell: it lazily imports every command's module


def imports(path: Path):
    """(module imported, whether at a module's top level) for every import in a file."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    top = set(map(id, tree.body))
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            yield from ((alias.name, id(node) in top) for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            yield node.module, id(node) in top


def test_exgen_never_imports_graders_outside_the_command_line():
    offenders = [str(p.relative_to(ROOT)) for p in (ROOT / "exgen").rglob("*.py")
                 if str(p.relative_to(ROOT)) not in SHELL
                 and any(name.split(".")[0] == "graders" for name, _ in imports(p))]
    assert offenders == []


def test_graders_import_exgen_at_the_top_only():
    hidden = [f"{p.relative_to(ROOT)}: {name}" for p in (ROOT / "graders").rglob("*.py")
              for name, at_top in imports(p) if name.split(".")[0] in ("exgen", "graders") and not at_top]
    assert hidden == []


def _relative_imports(path: Path) -> set[str]:
    """Sibling modules a file imports by relative import anywhere in it (a function's own import included)."""
    names = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and node.level == 1:
            names |= {node.module.split(".")[0]} if node.module else {a.name for a in node.names}
    return names


def test_the_renderers_modules_import_each_other_without_a_cycle():
    """Text widths were split between targets.py and equations.py, each importing the other."""
    folder = ROOT / "exgen" / "render"
    graph = {p.stem: _relative_imports(p) & {q.stem for q in folder.glob("*.py")} for p in folder.glob("*.py")}

    def cycle_from(start, path=()):
        for nxt in sorted(graph.get(start, ())):
            if nxt in path:
                return path[path.index(nxt):] + (start, nxt)
            found = cycle_from(nxt, path + (start,))
            if found:
                return found
        return None

    cycles = {m: cycle_from(m) for m in graph}
    assert not any(cycles.values()), {m: c for m, c in cycles.items() if c}


def test_units_knowledge_stands_below_the_renderers():
    """The SI unit of each kind of quantity is exgen.units' own: units.py reaches up into render for nothing."""
    reached = [name for name, _ in imports(ROOT / "exgen" / "units.py") if name.startswith("exgen.render")]
    tree = ast.parse((ROOT / "exgen" / "units.py").read_text(encoding="utf-8"))
    reached += [n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom) and n.level and n.module
                and n.module.startswith("render")]
    assert reached == []
