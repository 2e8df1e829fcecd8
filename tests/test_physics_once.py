"""Physics is written once: every public function of exgen/mechanics (tested there against the course
text) is what some solver calls while it works a drawn problem, so a slip in it changes a key. A function
no solver reaches is either physics a solver redoes inline or dead code; both are refused here.

Found by instrumentation: each public function and method of the mechanics modules is wrapped, wherever a
mechanics or solver module holds it, and marked when called while a solver runs, over a few draws of
every template (a few, so that each branch a template's data can take is met)."""
import functools
import importlib
import inspect
import pkgutil
import sys

import exgen.mechanics
import exgen.solvers
import exgen.solve.variant
from exgen.solve.variant import make_variant

SEEDS = range(8)


def _modules(package):
    return [importlib.import_module(f"{package.__name__}.{m.name}") for m in pkgutil.iter_modules(package.__path__)]


def public_physics() -> dict:
    """Every public function and method defined in a mechanics module -> its name ('belts.tension_ratio')."""
    found = {}
    for module in _modules(exgen.mechanics):
        short = module.__name__.rsplit(".", 1)[1]
        for name, obj in vars(module).items():
            if name.startswith("_") or getattr(obj, "__module__", None) != module.__name__:
                continue
            if inspect.isfunction(obj):
                found[obj] = f"{short}.{name}"
            elif inspect.isclass(obj):
                for method, fn in vars(obj).items():
                    if not method.startswith("_") and inspect.isfunction(fn):
                        found[(obj, method)] = f"{short}.{name}.{method}"
    return found


def reached(monkeypatch, bank) -> tuple[set, dict]:
    physics = public_physics()
    called, solving = set(), [False]

    def wrap(fn, label):
        @functools.wraps(fn)
        def counted(*args, **kwargs):
            if solving[0]:
                called.add(label)
            return fn(*args, **kwargs)
        return counted

    wrapped = {}
    for key, label in physics.items():
        if isinstance(key, tuple):
            owner, method = key
            monkeypatch.setattr(owner, method, wrap(vars(owner)[method], label))
        else:
            wrapped[key] = wrap(key, label)
    _modules(exgen.solvers)
    for name, module in list(sys.modules.items()):  # wherever a module holds one by name
        if name.startswith(("exgen.mechanics.", "exgen.solvers.")):
            for attr, obj in list(vars(module).items()):
                if inspect.isfunction(obj) and obj in wrapped:
                    monkeypatch.setattr(module, attr, wrapped[obj])
    solver = exgen.solve.variant.run_solver

    def run_solver(*args, **kwargs):
        solving[0] = True
        try:
            return solver(*args, **kwargs)
        finally:
            solving[0] = False

    monkeypatch.setattr(exgen.solve.variant, "run_solver", run_solver)
    for template in bank:
        for seed in SEEDS:
            make_variant(template, seed)
    return called, physics


def test_every_public_mechanics_function_is_reached_from_a_solver(bank, monkeypatch):
    called, physics = reached(monkeypatch, bank)
    never = sorted(set(physics.values()) - called)
    assert not never, f"public mechanics no solver calls (call it where the solver works it inline, or remove it): {never}"


def test_the_instrumentation_sees_a_call_inside_a_solver_and_not_outside(bank, monkeypatch):
    """The check itself: tension_ratio is reached through a belt solver, and a call made outside any solver
    (a figure's, a test's) does not count."""
    from exgen.mechanics import belts

    called, _ = reached(monkeypatch, [bank.get("belts.drive_geometry")])
    assert "belts.alpha_open" in called and "belts.tension_ratio" not in called
    belts.tension_ratio(0.3, 3.0)
    assert "belts.tension_ratio" not in called
