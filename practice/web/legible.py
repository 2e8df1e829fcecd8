"""A figure on a page is drawn at least large enough that its smallest label reads as 0.8 of the body text.

A figure's SVG is sized for the PDF (its width in pt), and a page would shrink it to the column: on a
phone, labels set at 14 came out at about 6 px. Here the root's width and height are set (as attributes:
the pages forbid inline styles) so that the smallest label, subscripts aside, is LABEL_PX on screen; a
figure wider than the column then scrolls inside its box, and the box shows that it does.
"""
from __future__ import annotations

import re

#: 0.8 of the widest body text the stylesheet sets (17 px; 16 px on a phone, for which it is more).
LABEL_PX = 0.8 * 17
_ROOT = re.compile(r"<svg\b[^>]*>")
_BOX = re.compile(r'\bviewBox="[-\d.]+ [-\d.]+ ([\d.]+) ([\d.]+)"')
_SIZE = re.compile(r'\bfont-size="([\d.]+)"')
_TEXT = re.compile(r"<text\b[^>]*>")
_WIDTH = re.compile(r'\swidth="([\d.]+)(pt|px)?"')
_HEIGHT = re.compile(r'\sheight="[\d.]+(?:pt|px)?"')


def legible(svg: str) -> str:
    """The SVG with its root's width and height in px, no smaller than its natural size nor than it takes
    for its smallest label (a <text>'s own size, or the root's it inherits) to be LABEL_PX."""
    root = _ROOT.search(svg)
    box = _BOX.search(root.group()) if root else None
    if box is None:
        return svg
    width, height = float(box.group(1)), float(box.group(2))
    inherited = _SIZE.search(root.group())
    base = float(inherited.group(1)) if inherited else 16.0
    sizes = [float(m.group(1)) if (m := _SIZE.search(t)) else base for t in _TEXT.findall(svg)]
    if not sizes or width <= 0:
        return svg
    natural = _WIDTH.search(root.group())
    shown = float(natural.group(1)) * (4 / 3 if natural.group(2) == "pt" else 1) if natural else width
    needed = width * LABEL_PX / min(sizes)
    px = max(shown, needed)
    head = _HEIGHT.sub("", _WIDTH.sub("", root.group(), count=1), count=1)
    head = head.replace("<svg", f'<svg width="{px:.1f}" height="{px * height / width:.1f}"', 1)
    return svg[:root.start()] + head + svg[root.end():]
