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
