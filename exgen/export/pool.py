"""A question pool for a learning system: each question of an assignment (or each template named)
drawn N times, and every variant as an export item (its text, figure, gaps and worked solution).

A learning system picks one variant per student, so the pool is drawn from seeds keyed by the course
secret (exgen.draw.seeds.pool_seed) like every sheet: the answers of a pool cannot be rebuilt without it.
A part whose answer type no learning system can grade (a formula) is left out of the item, and the
pool says so in its notices; a question left with no part is left out whole.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from fractions import Fraction

from markupsafe import Markup

from ..answertypes import answer_type
from ..answertypes.lms import NoLmsForm
from ..draw.seeds import pool_seed
from ..figures import figure_svg, key_figure_svgs, Drawn
from ..load.template import Template
from ..render.context import key_context
from ..runtime.progress import Progress, silent
from ..solve.variant import Variant, make_variant
from .html import render
from .mistakes import ordered_wrongs


@dataclass(frozen=True)
class PoolQuestion:
    """One question of the pool: a template at some points, and its variants."""

    number: int
    slot: str
    template: Template
    points: float
    variants: tuple[Variant, ...]


@dataclass(frozen=True)
class Pool:
    title: str
    scope: str  # the assignment id, or "pool" for a list of templates
    questions: tuple[PoolQuestion, ...]

    @property
    def count(self) -> int:
        return sum(len(q.variants) for q in self.questions)


def build_pool(title: str, scope: str, specs: list[tuple[str, Template, float]], secret: bytes, count: int,
               progress: Progress = silent) -> Pool:
    """`count` variants of each (slot, template, points), drawn from the secret's pool seeds."""
    jobs = [(n, slot, template, points, i) for n, (slot, template, points) in enumerate(specs, start=1)
            for i in range(1, count + 1)]
    drawn: dict[int, list[Variant]] = {}
    for n, slot, template, points, i in progress(jobs, len(jobs), "drawing"):
        drawn.setdefault(n, []).append(make_variant(template, pool_seed(secret, scope, slot, i)))
    questions = tuple(PoolQuestion(n, slot, template, points, tuple(drawn[n]))
                      for n, (slot, template, points) in enumerate(specs, start=1))
    return Pool(title, scope, questions)


# ---- items: one variant as every export writes it --------------------------------------------------

@dataclass(frozen=True)
class Figure:
    """An SVG figure as a file of the export (`name` unique within the item)."""

    name: str
    svg: str
    caption: str

    @property
    def data(self) -> bytes:
        return self.svg.encode("utf-8")


@dataclass(frozen=True)
class ItemPart:
    id: str
    ask: Markup
    points: float
    gaps: tuple = ()
    missing: str = ""  # why the part is not in the export

    @property
    def exported(self) -> bool:
        return not self.missing


@dataclass(frozen=True)
class Item:
    ident: str        # unique in the export: "q1-belts.flat_belt_power-07"
    name: str         # what a question bank lists
    question: PoolQuestion
    variant: Variant
    statement: Markup
    figure: Figure | None
    parts: tuple[ItemPart, ...]
    solution: Markup
    key_figures: tuple[Figure, ...]

    @property
    def exported_parts(self) -> tuple[ItemPart, ...]:
        return tuple(p for p in self.parts if p.exported)

    @property
    def gaps(self) -> tuple:
        return tuple(g for p in self.exported_parts for g in p.gaps)

    @property
    def points(self) -> float:
        return sum(p.points for p in self.exported_parts)

    def weights(self) -> list[tuple[ItemPart, object, int]]:
        """(part, gap, weight) with whole-number weights in the proportion of the marks (Moodle's cloze
        takes whole numbers only), the smallest that keep every proportion exact."""
        shares = [(p, g, Fraction(p.points).limit_denominator(1000) * g.share)
                  for p in self.exported_parts for g in p.gaps]
        scale = 1
        for _, _, share in shares:
            scale = scale * share.denominator // _gcd(scale, share.denominator)
        whole = [int(share * scale) for _, _, share in shares]
        common = 0
        for w in whole:
            common = _gcd(common, w)
        return [(p, g, w // (common or 1)) for (p, g, _), w in zip(shares, whole)]


def _gcd(a: int, b: int) -> int:
    while b:
        a, b = b, a % b
    return a


def make_item(question: PoolQuestion, index: int, variant: Variant, target, src: str = "") -> Item:
    """One variant as an item written with `target` (exgen.export.html); figures are referred to as
    `src` + file name."""
    template = variant.template
    tag = f"{index:0{len(str(len(question.variants)))}d}"
    slot = question.slot if question.slot[:1].isalpha() else f"q{question.slot}"  # an XML name starts with a letter
    ident = f"{slot}-{template.id}-{tag}"
    svg = figure_svg(variant)
    figure = Figure(f"{ident}.svg", svg, Drawn("", svg).title) if svg else None
    key_figures = tuple(Figure(f"{ident}-{name}.svg", text, Drawn("", text).title)
                        for name, text in key_figure_svgs(variant))
    scale = question.points / template.points
    parts = tuple(_item_part(variant, part, scale, target) for part in template.parts)
    solution = solution_html(variant, target, [(src + f.name, f.caption) for f in key_figures])
    return Item(ident, f"{template.title} ({question.slot}, variant {tag})", question, variant,
                target.text(variant.statement), figure, parts, solution, key_figures)


def _item_part(variant: Variant, part, scale: float, target) -> ItemPart:
    kind = answer_type(part)
    says = list(dict.fromkeys(m.when for m in part.mistakes))
    recorded = variant.mistakes.get(part.id, {})
    order = [n for n in says if n in recorded] + [n for n in recorded if n not in says]  # as the grader tries them
    mistakes = {name: (recorded[name], target.text(variant.mistake_message(part.id, name))) for name in order}
    ask = target.text(variant.asks[part.id])
    value = variant.answers[part.id].value
    try:
        gaps = kind.lms_gaps(part, value, mistakes)
    except NoLmsForm as exc:
        return ItemPart(part.id, ask, part.points * scale, (), str(exc))
    return ItemPart(part.id, ask, part.points * scale, tuple(_every_mistake(kind, part, value, mistakes, g) for g in gaps))


def _every_mistake(kind, part, value, mistakes: dict, gap):
    """A numeric gap with the wrong answer of each mistake taken alone (the gap lists a mistake whose value
    lies near an earlier one's once only), ordered so that a learning system names the mistake exgen's
    grader does (exgen.export.mistakes)."""
    if gap.kind != "numeric" or len(mistakes) < 2:
        return gap
    wrongs: list = []
    for name, mistake in mistakes.items():
        alone = next(g for g in kind.lms_gaps(part, value, {name: mistake}) if g.key == gap.key)
        wrongs += [w for w in alone.wrong if all(w.value != seen.value for seen in wrongs)]
    return replace(gap, wrong=ordered_wrongs(wrongs))


def solution_html(variant: Variant, target, key_figures: list[tuple[str, str]]) -> Markup:
    """The worked solution as the general feedback of an item: the given data, the working and the answers."""
    context = key_context(variant, target, key_figures)
    answers = [{"id": p.id, "answer": answer_type(p).key_text(variant.answers[p.id], target),
                "tolerance": _within(answer_type(p).tolerance_text(p), target)} for p in variant.template.parts]
    return Markup(render("solution.html.j2", q=context, answers=answers, target=target).strip())


def _within(tolerance: str, target) -> str:
    """The tolerance an answer is right within; none for a choice or a whole number, right only when exact."""
    return "" if tolerance == "exact" else target.prose(tolerance)


def notices(pool: Pool) -> list[str]:
    """What the export leaves out, once per template: parts no learning system can grade, whole questions."""
    out = []
    for question in pool.questions:
        template = question.template
        missing = []
        for part in template.parts:
            try:
                variant = question.variants[0]
                answer_type(part).lms_gaps(part, variant.answers[part.id].value, {})
            except NoLmsForm as exc:
                missing.append((part.id, str(exc)))
        if len(missing) == len(template.parts):
            out.append(f"{question.slot} ({template.id}) is left out: every part is {missing[0][1]}")
        for part_id, reason in missing if len(missing) < len(template.parts) else ():
            out.append(f"{question.slot} ({template.id}) part ({part_id}) is left out: {reason}; "
                       f"its other parts are exported")
    return out
