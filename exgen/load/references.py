"""The code a template names: its solver and its figures, in exgen's own packages or in its bank folder.

`solver: belts:belt_power` is the function `belt_power` of exgen.solvers.belts; `solver: ./cam.py:rise`
is the function `rise` of the file cam.py beside the template file (a path relative to it, inside the
folder of templates it was loaded from), so an instructor's folder of templates brings its own code.
`figure:` and `key_figures:` name figure functions the same way (exgen.figures, or a file of the bank).

A bank folder's files are the instructor's own code, trusted as a Python package the instructor installs
is: a file a template names runs when that template is loaded in full or drawn. Nothing else in a bank
folder runs, a file outside it is refused, and grading never takes its code from the folder of answers
handed in (exgen.load.bank.refuse_code_in).
"""
from __future__ import annotations

import importlib
import importlib.util
import sys
from functools import lru_cache
from hashlib import sha256
from pathlib import Path

from ..errors import ExgenError

#: Where a packaged reference ('belts:belt_power') is looked up, by what it names.
PACKAGES = {"solvers": "exgen.solvers", "figures": "exgen.figures"}


def is_local(reference: str) -> bool:
    """Whether a reference names a file of the bank ('./cam.py:rise') rather than a packaged module."""
    return reference.rpartition(":")[0].endswith(".py")


def split(reference: str) -> tuple[str, str]:
    """'belts:belt_power' -> ('belts', 'belt_power'); '/bank/cam.py:rise' -> ('/bank/cam.py', 'rise')."""
    module, _, function = reference.rpartition(":")
    return module, function


def local_file(reference: str) -> Path | None:
    """The file a bank reference (as a loaded template holds it: an absolute path) names, else None."""
    return Path(split(reference)[0]) if is_local(reference) else None


def check(reference: str, kind: str, template_file: Path, bank_dir: Path, full: bool = True) -> str:
    """The reference as a loaded template holds it (a bank file by its absolute path), after checking that
    what it names is there: the module or file, and, with `full`, its function (importing its code).
    Raises ValueError with the problem in words."""
    module, function = split(str(reference))
    package = PACKAGES[kind]
    if not function.isidentifier() or not (module.isidentifier() or module.endswith(".py")):
        raise ValueError(f"must be 'module:function' naming a function in {package}, or './file.py:function' "
                         f"naming one in a file beside the template")
    if module.endswith(".py"):
        reference = f"{_bank_file(module, template_file, bank_dir).as_posix()}:{function}"
    elif not (Path(__file__).parent.parent / kind / f"{module}.py").is_file():
        raise ValueError(f"no module {package}.{module}")
    if full:
        try:
            found = getattr(_module(reference, kind), function, None)
        except ExgenError as exc:
            raise ValueError(str(exc)) from None
        if not callable(found):
            where = module if module.endswith(".py") else f"{package}.{module}"
            raise ValueError(f"{where} has no function {function!r}")
    return reference


def _bank_file(written: str, template_file: Path, bank_dir: Path) -> Path:
    if Path(written).is_absolute() or not written.startswith(("./", "../")):
        raise ValueError(f"{written!r}: write a file of the bank as a path from the template file, "
                         f"starting ./ (./{Path(written).name})")
    path = (template_file.parent / written).resolve()
    if not path.is_relative_to(Path(bank_dir).resolve()):
        raise ValueError(f"{written} lies outside the folder of templates {bank_dir}: a bank's code stays in it")
    if not path.is_file():
        raise ValueError(f"no file {written} beside {template_file.name}")
    return path


def resolve(reference: str, kind: str):
    """The function a loaded template's reference names, imported on first use."""
    module, function = split(reference)
    found = getattr(_module(reference, kind), function, None)
    if not callable(found):  # a bank loaded without its full check (exgen.load.bank.load_bank)
        where = module if is_local(reference) else f"{PACKAGES[kind]}.{module}"
        raise ExgenError(f"{reference!r}: {where} has no function {function!r}")
    return found


def _module(reference: str, kind: str):
    """The module of a reference: exgen.<package>.<name>, or a bank file loaded once by its path.
    ExgenError when it cannot be imported (a bank file's own error named, with its line)."""
    module = split(reference)[0]
    if not is_local(reference):
        try:
            return importlib.import_module(f"{PACKAGES[kind]}.{module}")
        except ImportError:
            raise ExgenError(f"no module {PACKAGES[kind]}.{module}") from None
    try:
        return _bank_module(module)
    except Exception as exc:  # noqa: BLE001  (the instructor's own code: whatever it raised, said in one line)
        raise ExgenError(f"{module} cannot be imported: {type(exc).__name__}: {exc}") from None


@lru_cache(maxsize=None)
def _bank_module(path: str):
    """A bank's own file, imported as a module named for its path (registered, as a dataclass in it needs)."""
    name = f"_exgen_bank_{sha256(path.encode('utf-8')).hexdigest()[:12]}_{Path(path).stem}"
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise ImportError(f"not a Python file: {path}")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    except BaseException:
        del sys.modules[name]
        raise
    return module
