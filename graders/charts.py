"""The report's pictures as inline SVG: the spread of marks, and each part's facility with its
discrimination. Text in them is escaped; sizes are in px."""
from __future__ import annotations

from markupsafe import Markup, escape

from .analysis import LOW_DISCRIMINATION, Analysis

BAR, GAP, HEIGHT = 44, 6, 160
ROW, LABEL, WIDTH = 22, 80, 360


def histogram_svg(analysis: Analysis) -> Markup:
    """Columns of how many sheets scored 0-10 %, 10-20 %, ... 90-100 %."""
    counts = analysis.histogram
    top = max(counts, default=0) or 1
    width = len(counts) * (BAR + GAP) + 40
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{HEIGHT + 60}" role="img" '
           f'viewBox="0 -10 {width} {HEIGHT + 60}"><title>Distribution of marks (percent)</title>']
    for i, count in enumerate(counts):
        h = HEIGHT * count / top
        x, y = 30 + i * (BAR + GAP), 10 + HEIGHT - h
        out.append(f'<rect x="{x}" y="{y:.1f}" width="{BAR}" height="{h:.1f}" fill="#4a78b5"><title>'
                   f'{10 * i}-{10 * i + 10} %: {count}</title></rect>')
        if count:
            out.append(f'<text x="{x + BAR / 2}" y="{y - 3:.1f}" text-anchor="middle" font-size="12">{count}</text>')
        out.append(f'<text x="{x + BAR / 2}" y="{HEIGHT + 26}" text-anchor="middle" font-size="11">{10 * i}</text>')
    out.append(f'<line x1="28" y1="{HEIGHT + 10}" x2="{width - 8}" y2="{HEIGHT + 10}" stroke="#333"/>')
    out.append(f'<text x="{width / 2}" y="{HEIGHT + 45}" text-anchor="middle" font-size="12">mark (%)</text></svg>')
    return Markup("".join(out))


def facility_svg(analysis: Analysis) -> Markup:
    """A bar per part: the share right; red for none right, orange for low discrimination."""
    parts = analysis.parts
    height = len(parts) * ROW + 30
    total = LABEL + WIDTH + 160
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{total}" height="{height}" role="img" '
           f'viewBox="0 0 {total} {height}"><title>Facility of each part</title>']
    for i, part in enumerate(parts):
        y = 10 + i * ROW
        facility = part.facility or 0.0
        colour = "#c0392b" if part.statuses["wrong"] and part.right == 0 else (
            "#e08e0b" if part.discrimination is not None and part.discrimination < LOW_DISCRIMINATION else "#4a78b5")
        d = "–" if part.discrimination is None else f"{part.discrimination:+.2f}"
        out.append(f'<text x="{LABEL - 6}" y="{y + 14}" text-anchor="end" font-size="12">{escape(part.label)}</text>')
        out.append(f'<rect x="{LABEL}" y="{y + 2}" width="{WIDTH * facility:.1f}" height="{ROW - 6}" fill="{colour}">'
                   f'<title>{escape(part.label)}: {100 * facility:.0f} % right, discrimination {d}</title></rect>')
        out.append(f'<text x="{LABEL + WIDTH * facility + 4:.1f}" y="{y + 14}" font-size="11">{100 * facility:.0f} %'
                   f' · r {d}</text>')
    out.append(f'<line x1="{LABEL}" y1="6" x2="{LABEL}" y2="{height - 18}" stroke="#333"/>')
    out.append(f'<text x="{LABEL + WIDTH / 2}" y="{height - 4}" text-anchor="middle" font-size="11">share of '
               f'graded students right (bar) · point-biserial r; orange: r below {LOW_DISCRIMINATION}, red: '
               f'nobody right</text></svg>')
    return Markup("".join(out))
