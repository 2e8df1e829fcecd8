"""Reading a figure back from its SVG: its labels with their boxes, its lines, and where text
collides with text or sits on a line. Used by the tests over every template's figures.
"""
from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass

from .layout import SUBSCRIPTS, SUPERSCRIPTS, TextBox, boxes_overlap, circle_hits, path_points, segment_hits, text_box

SVG = "{http://www.w3.org/2000/svg}"
_TO_SUB = str.maketrans("0123456789", SUBSCRIPTS)
_TO_SUP = str.maketrans("0123456789−", SUPERSCRIPTS)
#: Lines a label may touch: hidden outlines (clipped inside a part in front of them).
IGNORED = {"hidden"}


@dataclass(frozen=True)
class Label:
    text: str
    box: TextBox
    cls: str


def _content(element: ET.Element) -> str:
    """A <text>'s words as written by the drawing code, its shifted smaller tspans as script digits."""
    out = [element.text or ""]
    for span in element.iter(f"{SVG}tspan"):
        dy = float(span.get("dy", "0"))
        text = span.text or ""
        if span.get("font-size") is not None:
            text = text.translate(_TO_SUB if dy > 0 else _TO_SUP)
        text = text.replace("\u22c5", "\u00b7")   # a unit's dot, set from the math face
        out.append(text + (span.tail or ""))
    return "".join(out)


def _rotation(element: ET.Element) -> float:
    transform = element.get("transform", "")
    if not transform.startswith("rotate("):
        return 0.0
    return float(transform[len("rotate("):].split()[0].rstrip(")"))


def labels(svg: str) -> list[Label]:
    """Every label of a figure with its ink box, measured as the drawing code measured it."""
    root = ET.fromstring(svg)
    base = float(root.get("font-size", "14"))
    out = []
    for element in root.iter(f"{SVG}text"):
        content = _content(element)
        box = text_box((float(element.get("x")), float(element.get("y"))), content,
                       element.get("text-anchor", "start"), float(element.get("font-size", base)),
                       element.get("font-weight") == "bold", element.get("font-style") == "italic",
                       _rotation(element))
        out.append(Label(content, box, element.get("class", "")))
    return out


def texts(svg: str) -> list[str]:
    return [label.text for label in labels(svg)]


def strokes(svg: str):
    """(segments, circles) of every line drawn, but for ignored classes and filled arrowheads."""
    root = ET.fromstring(svg)
    segments, circles = [], []
    for element in root:  # not into <defs>: a clip outline is not drawn
        tag = element.tag.replace(SVG, "")
        if set(element.get("class", "").split()) & IGNORED or element.get("clip-path"):
            continue
        if tag == "line":
            segments.append(((float(element.get("x1")), float(element.get("y1"))),
                              (float(element.get("x2")), float(element.get("y2")))))
        elif tag == "circle":
            circles.append(((float(element.get("cx")), float(element.get("cy"))), float(element.get("r"))))
        elif tag == "polygon" and element.get("fill") != "black":
            points = [tuple(map(float, p.split(","))) for p in element.get("points").split()]
            segments.extend(zip(points, points[1:] + points[:1]))
        elif tag == "path":
            for points in path_points(element.get("d")):
                segments.extend(zip(points, points[1:]))
    return segments, circles


def collisions(svg: str, gap: float = 0.5) -> list[str]:
    """What is wrong with a figure's text: labels that overlap, and labels a line runs through."""
    found = labels(svg)
    problems = []
    for i, a in enumerate(found):
        for b in found[i + 1:]:
            if not _apart(a.box, b.box, gap) and boxes_overlap(a.box, b.box, gap):
                problems.append(f"{a.text!r} overlaps {b.text!r}")
    segments, circles = strokes(svg)
    for label in found:
        if any(segment_hits(label.box, p, q, -gap) for p, q in _near(label.box, segments, gap)):
            problems.append(f"a line runs through {label.text!r}")
        if any(circle_hits(label.box, c, r, -gap) for c, r in circles):
            problems.append(f"a circle runs through {label.text!r}")
    return problems


def _apart(a: TextBox, b: TextBox, gap: float) -> bool:
    """Upright boxes clear of each other along x or y by `gap`: what boxes_overlap finds for them, found
    without its general (turned) test; a turned box always takes that test."""
    if a.angle or b.angle:
        return False
    return a.x1 + gap <= b.x0 or b.x1 + gap <= a.x0 or a.y1 + gap <= b.y0 or b.y1 + gap <= a.y0


def _near(box: TextBox, segments, gap: float):
    """The segments that may reach an upright box shrunk by `gap` (the others surely miss it); all of
    them for a turned box."""
    if box.angle:
        return segments
    x0, y0, x1, y1 = box.x0 + gap, box.y0 + gap, box.x1 - gap, box.y1 - gap
    return [(p, q) for p, q in segments if not (p[0] < x0 and q[0] < x0 or p[0] > x1 and q[0] > x1 or
                                                p[1] < y0 and q[1] < y0 or p[1] > y1 and q[1] > y1)]
