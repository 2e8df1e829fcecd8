"""The code stands in layers, each importing only from those below it, along a question's lifecycle: the
foundation (errors, units), the physics, loading a bank, drawing, solving, the outputs, issuing and checking,
then graders, practice and the command line. Read from the real modules' syntax trees, every import counted
(a function's own included): none reaches up a layer, and no module imports itself round a cycle. Two that
did: units.py reached up into the renderers for the SI unit of each kind of quantity, and the renderers'
targets.py and equations.py imported each other for text widths. Graders depend on exgen, never exgen on
graders: the command line is the one place that reaches both (it offers `exgen grade`)."""
import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).parent.parent
SHELL = {"exgen/cli/commands.py"}  # the application's shell: it lazily imports every command's module
PACKAGES = ("exgen", "graders", "practice")

#: The layers, bottom first: a module may import from its own layer and those below. A module belongs to
#: the layer of the longest name that starts it.
LAYERS = (
    ("foundation", ("exgen", "exgen.errors", "exgen.units", "exgen.echo")),
    ("physics", ("exgen.mechanics",)),
    ("runtime", ("exgen.runtime",)),
    ("load", ("exgen.load", "exgen.answertypes")),
    ("draw", ("exgen.draw",)),
    ("solve", ("exgen.solve", "exgen.solvers")),
    ("render", ("exgen.figures", "exgen.render", "exgen.export")),
    ("issue and check", ("exgen.issue", "exgen.check")),
    ("graders", ("graders",)),
    ("practice", ("practice",)),
    ("command line", ("exgen.cli",)),
)
#: Names that stand for their package's __init__ alone, not for the modules inside it.
PACKAGE_ONLY = {"exgen"}


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


# ---- the graph of every module's imports ------------------------------------------------------------------

def module_files() -> dict[str, Path]:
    """Every module of the packages, by dotted name ("exgen.answertypes" is its __init__.py)."""
    found = {}
    for package in PACKAGES:
        for path in (ROOT / package).rglob("*.py"):
            parts = list(path.relative_to(ROOT).with_suffix("").parts)
            found[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return found


MODULES = module_files()


def imported(name: str, path: Path) -> set[str]:
    """The modules of ours `name` imports anywhere in it, relative imports resolved: `from x import y` is
    the module x.y when there is one, else x."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                up = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join(up + ([node.module] if node.module else []))
            found |= {f"{base}.{a.name}" if f"{base}.{a.name}" in MODULES else base for a in node.names}
    return {m for m in found if m in MODULES and m != name}


GRAPH = {name: imported(name, path) for name, path in MODULES.items()}


def layer(name: str) -> int:
    """The layer of a module, by the longest prefix LAYERS names."""
    matches = [(len(prefix), rank) for rank, (_, prefixes) in enumerate(LAYERS) for prefix in prefixes
               if name == prefix or (name.startswith(prefix + ".") and prefix not in PACKAGE_ONLY)]
    assert matches, f"{name} is in no layer: add it to LAYERS"
    return max(matches)[1]


def test_every_module_has_a_layer():
    """A new module is placed in a layer on purpose, not by falling under a package's name."""
    assert all(layer(name) >= 0 for name in MODULES)


@pytest.mark.parametrize("name", sorted(MODULES))
def test_no_module_imports_from_a_layer_above_its_own(name):
    upward = [f"{target} ({LAYERS[layer(target)][0]})" for target in sorted(GRAPH[name]) if layer(target) > layer(name)]
    assert upward == [], f"{name} ({LAYERS[layer(name)][0]}) imports from above: {', '.join(upward)}"


def test_no_module_imports_itself_round_a_cycle():
    """Depth-first over the whole graph; a module met again while still on the path closes a cycle."""
    state, cycles = {}, []

    def visit(name, path):
        state[name] = "open"
        for target in sorted(GRAPH[name]):
            if state.get(target) == "open":
                cycles.append(" -> ".join(path[path.index(target):] + [target]))
            elif target not in state:
                visit(target, path + [target])
        state[name] = "done"

    for name in sorted(GRAPH):
        if name not in state:
            visit(name, [name])
    assert cycles == []


def test_the_graph_is_read_from_the_real_modules():
    """The reader sees relative, absolute and function-level imports (a test that reads nothing passes)."""
    assert "exgen.mechanics.belts" in GRAPH["exgen.solvers.belts"]          # from ..mechanics import belts as mb
    assert "exgen.render.pdf" in GRAPH["exgen.issue.generate"]                     # inside a function
    assert "graders.grade" in GRAPH["exgen.cli.commands"] and "practice.session" in GRAPH["exgen.cli.commands"]
    assert {"exgen.answertypes", "exgen.cli.commands", "graders.grade", "practice.web.app"} <= set(MODULES)
    assert all(LAYERS[layer(m)][0] == "physics" for m in MODULES if m.startswith("exgen.mechanics."))


def test_exgen_never_imports_practice_outside_the_command_line():
    offenders = [name for name, targets in GRAPH.items() if name.startswith("exgen.") and not
                 name.startswith("exgen.cli") and any(t.split(".")[0] == "practice" for t in targets)]
    assert offenders == []
