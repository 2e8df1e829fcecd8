"""Reading the SVG figures in tests: build a variant with chosen values, then find its elements."""
import dataclasses
import xml.etree.ElementTree as ET
from decimal import Decimal

from exgen.draw.values import derived_value
from exgen.figures import checks
from exgen.solve.variant import build_variant, make_variant

SVG = "{http://www.w3.org/2000/svg}"


def variant_of(bank, template_id, seed=1, extra=(), **values):
    """A variant of a bank template with some printed values replaced (numbers or words), solved
    without drawing checks; `extra` adds parameters the template lacks."""
    template = bank.get(template_id)
    if extra:
        template = dataclasses.replace(template, params=template.params + tuple(extra))
    printed = {p.name: p.exact for p in make_variant(template, seed).params}
    printed.update({k: v if isinstance(v, str) else Decimal(str(v)) for k, v in values.items()})
    for spec in template.params:  # givens worked out from others follow the replaced values
        if spec.derived and spec.name not in values:
            printed[spec.name] = derived_value(spec.equals, printed)
    return build_variant(template, printed, check=False)


def root(svg: str) -> ET.Element:
    return ET.fromstring(svg)


def texts(svg: str) -> list[str]:
    """The labels as the drawing code wrote them (script digits as Unicode sub- and superscripts)."""
    return checks.texts(svg)


def elements(svg: str, cls: str, tag: str = "line") -> list[ET.Element]:
    return [e for e in root(svg).iter(f"{SVG}{tag}") if cls in e.get("class", "").split()]


def circles(svg: str, cls: str) -> list[ET.Element]:
    return elements(svg, cls, "circle")
