"""`exgen report GRADED_DIR`: the item analysis of a grading run as a self-contained HTML page (inline
CSS and SVG, nothing fetched) and as Markdown, from its results.json. `exgen grade` writes both too."""
from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path

import jinja2
from markupsafe import Markup, escape

from .analysis import LOW_DISCRIMINATION, analyse
from .charts import facility_svg, histogram_svg
from .echo import shown, shown_code
from .gradebooks import points
from .record import read_record

LAYOUTS = Path(__file__).parent / "layouts"
HTML, MARKDOWN = "item-analysis.html", "item-analysis.md"
_MD_SPECIAL = str.maketrans({c: "\\" + c for c in "\\`*_[]<>|"})


@lru_cache(maxsize=2)
def _environment(autoescape: bool) -> jinja2.Environment:
    return jinja2.Environment(loader=jinja2.FileSystemLoader(str(LAYOUTS)), undefined=jinja2.StrictUndefined,
                              autoescape=autoescape, trim_blocks=True, lstrip_blocks=True, keep_trailing_newline=True)


def _code_spans(text) -> Markup:
    """Text escaped for HTML, with its `quoted` parts (a reason quotes what a file says) as <code>."""
    return Markup(re.sub(r"`([^`<>]*)`", r"<code>\1</code>", str(escape(text))))


def _md(text) -> str:
    """Text (which may quote what a student typed) as literal Markdown on one line."""
    return shown(str(text), 400).translate(_MD_SPECIAL)


def _clean(record):
    """Every text of a record as one line without control or bidi characters: results.json may come
    from anywhere (an older exgen, an edit by hand) and quotes what students typed and named their files.
    Each distinct text is cleaned once (statuses, part names and mistakes recur in every sheet)."""
    done: dict[str, str] = {}

    def clean(value):
        if isinstance(value, str):
            text = done.get(value)
            if text is None:
                text = done[value] = shown(value, 2000)
            return text
        if isinstance(value, list):
            return [v if isinstance(v, _LEAVES) else clean(v) for v in value]
        if isinstance(value, dict):
            return {k: v if isinstance(v, _LEAVES) else clean(v) for k, v in value.items()}
        return value

    return clean(record)


_LEAVES = (int, float, type(None))  # left as they are, without a call for each (a class's marks)


def report_pages(record: dict) -> dict[str, str]:
    analysis = analyse(_clean(record))
    common = {"a": analysis, "points": points, "low": LOW_DISCRIMINATION}
    html = _environment(True).get_template("analysis.html.j2").render(
        common, histogram=histogram_svg(analysis), facility=facility_svg(analysis), quoted=_code_spans)
    markdown = _environment(False).get_template("analysis.md.j2").render(
        common, md=_md, code=lambda text: shown_code(text, 300))
    return {HTML: html, MARKDOWN: markdown}


def write_report(folder: Path, out: Path | None = None) -> dict[str, Path]:
    """Read FOLDER/results.json and write the two pages into `out` (default: the same folder)."""
    record = read_record(Path(folder))
    out = Path(out) if out else Path(folder)
    out.mkdir(parents=True, exist_ok=True)
    paths = {}
    for name, text in report_pages(record).items():
        (out / name).write_text(text, encoding="utf-8")
        paths[name] = out / name
    return paths
