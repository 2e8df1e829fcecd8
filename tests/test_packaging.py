"""An installed exgen (not only the editable one the tests run from) holds every package of the source:
setuptools installs only the packages pyproject.toml lists, so a new one left out works here and fails
for every user."""
import tomllib
from pathlib import Path

ROOT = Path(__file__).parent.parent


def test_every_package_of_the_source_is_listed_for_installing():
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["setuptools"]
    listed = set(config["packages"])
    found = {".".join(init.parent.relative_to(ROOT).parts) for top in ("exgen", "graders", "practice")
             for init in (ROOT / top).rglob("__init__.py")}
    assert found <= listed, sorted(found - listed)
