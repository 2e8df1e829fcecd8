"""Find, load and validate template files.

Every problem in a file is collected before loading stops, each naming the file, the key and
the line, so an author fixes a bank in one pass (mkdocs-style) rather than one error per run.
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from pathlib import Path

from ..errors import BankError, ExgenError, TemplateError, UnknownTemplate
from ..runtime.yamlfile import YamlFileError, read_yaml
from .reader import TemplateReader
from .template import Template
from .versions import data_digest

BANKS_ENV = "EXGEN_BANKS"

@dataclass(frozen=True)
class Bank:
    """All templates by id, in a stable order."""

    templates: dict[str, Template]

    def get(self, template_id: str) -> Template:
        try:
            return self.templates[template_id]
        except KeyError:
            raise UnknownTemplate(template_id, sorted(self.templates)) from None

    def __iter__(self):
        return iter(self.templates.values())

    def __len__(self) -> int:
        return len(self.templates)


def bank_dirs(extra: list[Path] | None = None) -> list[Path]:
    """The packaged bank, then $EXGEN_BANKS, then any directories given explicitly (each must exist)."""
    from_env = [Path(p) for p in os.environ.get(BANKS_ENV, "").split(os.pathsep) if p]
    for where, dirs in ((f"${BANKS_ENV}", from_env), ("--bank", list(extra or []))):
        for directory in dirs:
            if not directory.is_dir():
                raise ExgenError(f"{directory} (from {where}): no such folder of templates")
    return [Path(str(resources.files("exgen.banks")))] + from_env + list(extra or [])


def refuse_code_in(folder: Path, extra: list[Path] | None = None) -> None:
    """Stop before a folder of templates that is, holds or lies in `folder`, one students wrote (the answers
    handed in): its YAML would be read as templates and its code run. A bank is the instructor's own."""
    written = Path(folder).resolve()
    for directory in bank_dirs(extra):
        found = directory.resolve()
        if found == written or found.is_relative_to(written) or written.is_relative_to(found):
            raise ExgenError(f"{directory}: a folder of templates cannot be, hold or lie in the folder of answers "
                             f"handed in ({folder}): a bank's code runs when it loads; keep the two apart")


def load_bank(extra: list[Path] | None = None, full: bool = True) -> Bank:
    """Every template of the bank. `full` False leaves out the checks that import code or parse text
    (that each solver and figure function exists, that texts name only parameters, that reported units
    are units): a command that reads titles or draws one template starts without importing them all,
    and a mistake there is reported when the template is used, or by `exgen validate`."""
    return _load_bank(tuple(bank_dirs(extra)), full)


@lru_cache(maxsize=8)
def _load_bank(dirs: tuple[Path, ...], full: bool = True) -> Bank:
    templates: dict[str, Template] = {}
    errors: list[TemplateError] = []
    for directory in dirs:
        for path in sorted(directory.rglob("*.yaml")):
            try:
                template = load_template(path, full, directory)
            except BankError as exc:
                errors.extend(exc.errors)
                continue
            if template.id in templates:
                errors.append(TemplateError(path, "id", f"{template.id!r} is also defined in {templates[template.id].path}"))
                continue
            templates[template.id] = template
    if errors:
        raise BankError(errors)
    return Bank(templates)


def load_template(path: Path, full: bool = True, bank_dir: Path | None = None) -> Template:
    """Read one template file, raising BankError with every problem found in it (`full`: see load_bank).
    `bank_dir` is the folder of templates it belongs to (its own code may lie anywhere in it); by default
    the file's own folder."""
    try:
        root, data = read_yaml(path, "a template file")
    except YamlFileError as exc:
        raise BankError([TemplateError(path, "", exc.detail, exc.line, exc.column)]) from None
    reader = TemplateReader(path, root, full, data, bank_dir)
    template = reader.template(data, data_digest(_issued(data)))
    if reader.errors:
        raise BankError(reader.errors)
    return template


def _issued(data):
    """What sheets, keys and grades depend on, for the template's version: all of it but the parts'
    practice hints, which no sheet shows and no mark depends on (adding one re-issues nothing)."""
    if not isinstance(data, dict) or not isinstance(data.get("parts"), list):
        return data
    parts = [{k: v for k, v in p.items() if k != "hints"} if isinstance(p, dict) else p for p in data["parts"]]
    return {**data, "parts": parts}
