"""Mastery per topic as a picture: an SVG bar chart written as text, like the problems' figures.

Each bar carries its percentage and level in words, so the picture does not depend on colour; the
page gives the same figures as a table beside it. A topic's name sits above its bar, so the chart is
narrow enough for a phone at its own size (WIDTH px): its labels, at FONT px, are never drawn smaller
(the stylesheet lets it grow, never shrink).
"""
from __future__ import annotations

from html import escape

from ..mastery import MASTERED

ROW, BAR, HEIGHT, GAP, FONT = 44, 200, 16, 8, 14
WIDTH = BAR + 130
COLOURS = {"not started": "#c8c8c8", "weak": "#c0392b", "learning": "#d68910", "mastered": "#1e8449"}


def mastery_chart(entries: list[dict]) -> str:
    """`entries`: dicts with name, chapter, mastery (practice.mastery.Mastery) and standing."""
    height = GAP * 2 + ROW * len(entries) + 24
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {WIDTH} {height}" width="{WIDTH}" '
           f'height="{height}" role="img" aria-labelledby="chart-title chart-desc" class="chart" font-size="{FONT}">',
           '<title id="chart-title">Mastery per topic</title>',
           f'<desc id="chart-desc">{escape(_description(entries))}</desc>']
    threshold = BAR * MASTERED / 100
    for i, entry in enumerate(entries):
        y = GAP + ROW * i
        standing = entry["standing"]
        length = BAR * standing["percent"] / 100 if standing["started"] else 0  # the figure shown, not a hair more
        out.append(f'<text x="0" y="{y + 14}">{escape(entry["name"])} '
                   f'<tspan fill="#595959">(chapter {entry["chapter"]})</tspan></text>')
        out.append(f'<rect x="0" y="{y + 20}" width="{BAR}" height="{HEIGHT}" fill="#f2f2f2"/>')
        if length:
            out.append(f'<rect x="0" y="{y + 20}" width="{length:.1f}" height="{HEIGHT}" '
                       f'fill="{COLOURS[standing["level"]]}"/>')
        out.append(f'<text x="{BAR + 8}" y="{y + 33}">{escape(standing["text"])}'
                   + (f' · {escape(standing["level"])}' if standing["started"] else "") + "</text>")
        out.append(f'<line x1="{threshold:.1f}" y1="{y + 17}" x2="{threshold:.1f}" y2="{y + 23 + HEIGHT}" '
                   'stroke="#333" stroke-dasharray="4 3"/>')  # across the bar, clear of the names
    bottom = GAP + ROW * len(entries)
    out.append(f'<text x="{threshold:.1f}" y="{bottom + 16}" text-anchor="middle" fill="#333">'
               f'mastered from {MASTERED} %</text>')
    out.append("</svg>")
    return "\n".join(out)


def _description(entries: list[dict]) -> str:
    return "; ".join(f'{e["name"]}: {e["standing"]["text"]}' for e in entries) or "No topics."
