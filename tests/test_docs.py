"""The README and docs/ as a newcomer follows them: every command in their code blocks is one the command
line takes, naming templates and example files that exist; every link and picture is there; the README's
first screen says what exgen is, how to install it, its main job and how to run the tests."""
import re
import shlex
from pathlib import Path

import pytest

from exgen.cli import build_parser

ROOT = Path(__file__).parent.parent
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
FENCE = re.compile(r"^```(\w*)\n(.*?)^```", re.S | re.M)
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def commands(page: Path) -> list[list[str]]:
    """Each `exgen ...` line of the page's code blocks, continuation lines joined, comments dropped."""
    found = []
    for _, block in FENCE.findall(page.read_text(encoding="utf-8")):
        for line in block.replace("\\\n", " ").splitlines():
            words = shlex.split(line, comments=True)
            if words[:1] in (["exgen"], [".venv/bin/exgen"]):
                found.append(words)
    return found


def anchors(page: Path) -> set[str]:
    """GitHub's anchors for the page's headings."""
    headings = re.findall(r"^#+ (.+)$", page.read_text(encoding="utf-8"), re.M)
    return {re.sub(r"[^\w\- ]", "", h.strip().lower()).replace(" ", "-") for h in headings}


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_every_command_shown_is_one_exgen_takes(page, bank):
    for argv in commands(page):
        args = build_parser().parse_args(argv[1:])  # a usage mistake exits here, naming it
        values = [v for v in vars(args).values() for v in (v if isinstance(v, list) else [v]) if isinstance(v, str)]
        for value in values:
            if value.startswith("examples/"):
                assert (ROOT / value).exists(), f"{page.name}: {' '.join(argv)}"
            elif re.fullmatch(r"[a-z]+\.[a-z0-9_]+", value) and value.split(".")[0] in {t.topic for t in bank}:
                assert value in {t.id for t in bank}, f"{page.name}: {' '.join(argv)}"


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_every_link_and_picture_is_there(page):
    for target in LINK.findall(page.read_text(encoding="utf-8")):
        if re.match(r"[a-z]+:", target):
            continue  # a web address
        path, _, anchor = target.partition("#")
        file = (page.parent / path).resolve() if path else page
        assert file.exists(), f"{page.name}: {target}"
        if anchor and file.suffix == ".md":
            assert anchor in anchors(file), f"{page.name}: {target}"


def test_the_readme_starts_a_newcomer_off_on_one_screen():
    """The README was 150 lines: what exgen is, installing it, its main job and the tests come first and
    fit a screen; the rest is in docs/, linked."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    before_more = text.split("## Read next")[0]
    assert len(before_more.splitlines()) <= 60
    assert "pip install -e ." in before_more and ". .venv/bin/activate" in before_more
    assert [c[1] for c in commands(ROOT / "README.md")] == ["generate", "grade"]
    assert ".venv/bin/python -m pytest" in before_more
    linked = {Path(t).name for t in LINK.findall(text)}
    assert {p.name for p in PAGES if p.parent.name == "docs"} <= linked  # every page of docs/ is reachable


def test_ci_runs_the_readme_test_command():
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    block = next(b for _, b in FENCE.findall((ROOT / "README.md").read_text(encoding="utf-8")) if "pytest" in b)
    assert block.strip() in ci


def test_the_readme_counts_the_templates_the_bank_has(bank):
    """The README said 77 problem templates, and nothing would have noticed the 78th."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    (count,) = re.findall(r"(\d+) problem templates", text)
    assert int(count) == len(bank)


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_every_test_file_a_page_names_is_there(page, bank):
    """The template guide's first step sent a newcomer to tests/test_mechanics_<topic>.py, and for the belts
    there is none. A name with `<topic>` in it must be a file for every topic of the bank; any other
    placeholder (`<chapter>`) must match some file."""
    text = page.read_text(encoding="utf-8")
    for name in re.findall(r"\btests/[\w/<>.-]+?\.py\b", text):
        names = [name.replace("<topic>", t.topic) for t in bank] if "<topic>" in name else [name]
        for each in names:
            assert sorted(ROOT.glob(re.sub(r"<[^>]+>", "*", each))), f"{page.name}: {each}"


def test_the_catalogues_are_in_step_with_the_code(bank):
    """The figures a template can name, the parts of a figure, the named mistakes and what each answer type
    overrides, as the guides print them: made from the code and data by tests/catalogues.py."""
    from catalogues import pages

    for path, text in pages(bank).items():
        assert path.read_text(encoding="utf-8") == text, f"{path.name} is out of step: python -m tests.catalogues"
