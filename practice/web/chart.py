"""Mastery per topic as a picture: an SVG bar chart written as text, like the problems' figures.

Each bar carries its percentage and level in words, so the picture does not depend on colour; the
page gives the same figures as a table beside it.
"""
from __future__ import annotations

from html import escape

from ..mastery import MASTERED

ROW, LABEL, BAR, GAP = 26, 150, 300, 8
COLOURS = {"not started": "#c8c8c8", "weak": "#c0392b", "learning": "#d68910", "mastered": "#1e8449"}


def mastery_chart(entries: list[dict]) -> str:
    """`entries`: dicts with name, chapter, mastery (practice.mastery.Mastery) and standing."""
    height = GAP * 2 + ROW * len(entries) + 24
    width = LABEL + BAR + 150
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {width} {height}" role="img" '
           f'aria-labelledby="chart-title chart-desc" class="chart" font-size="13">',
           '<title id="chart-title">Mastery per topic</title>',
           f'<desc id="chart-desc">{escape(_description(entries))}</desc>']
    threshold = LABEL + BAR * MASTERED / 100
    for i, entry in enumerate(entries):
        y = GAP + ROW * i
        standing = entry["standing"]
        length = BAR * standing["percent"] / 100 if standing["started"] else 0  # the figure shown, not a hair more
        out.append(f'<text x="{LABEL - 8}" y="{y + 17}" text-anchor="end">'
                   f'{escape(entry["name"])} <tspan fill="#666">({entry["chapter"]})</tspan></text>')
        out.append(f'<rect x="{LABEL}" y="{y + 4}" width="{BAR}" height="{ROW - 8}" fill="#f2f2f2"/>')
        if length:
            out.append(f'<rect x="{LABEL}" y="{y + 4}" width="{length:.1f}" height="{ROW - 8}" '
                       f'fill="{COLOURS[standing["level"]]}"/>')
        out.append(f'<text x="{LABEL + BAR + 8}" y="{y + 17}">{escape(standing["text"])}'
                   + (f' · {escape(standing["level"])}' if standing["started"] else "") + "</text>")
    bottom = GAP + ROW * len(entries)
    out.append(f'<line x1="{threshold:.1f}" y1="{GAP}" x2="{threshold:.1f}" y2="{bottom}" stroke="#333" '
               'stroke-dasharray="4 3"/>')
    out.append(f'<text x="{threshold:.1f}" y="{bottom + 16}" text-anchor="middle" fill="#333">'
               f'mastered from {MASTERED} %</text>')
    out.append("</svg>")
    return "\n".join(out)


def _description(entries: list[dict]) -> str:
    return "; ".join(f'{e["name"]}: {e["standing"]["text"]}' for e in entries) or "No topics."
