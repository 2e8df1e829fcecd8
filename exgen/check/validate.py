"""`exgen validate`: draw many variants of each template and check what must always hold.

A solver that raises anything but a rejection (InvalidDraw) fails the template: a crash is a defect,
never a redraw. Per variant: the constraints hold, every answer is a finite number of the asked kind, re-running
the derivation with its own answers changes nothing (ECF is consistent), and the key grades
itself at 100 %. Per template: every mistake a part names is recorded by the solver and has words
for the student, no feedback or hint states in fixed words what the draw decides, every part a part
`uses:` changes its answer, and seeds give distinct problems.
"""
from __future__ import annotations

import math
import time
from collections import Counter
from dataclasses import dataclass, field

from ..answertypes import answer_type
from .draw_words import misstatements
from ..draw.values import failed_requirement
from ..errors import ExgenError, FormatProblem, SolverFailure, WrongKind
from ..load.mistake_messages import default_messages
from ..load.template import ReportSpec, Template
from ..solve.variant import Variant, answer_for, make_variant, rerun

USES_TRIALS = 5  # draws in which a part's answer must follow the parts it uses
DISTINCT_WARNING = 0.9
TRIES_WARNING = 5.0


@dataclass
class Report:
    template: Template
    seeds: int
    problems: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    distinct: float = 0.0
    mean_tries: float = 0.0
    ms_per_variant: float = 0.0
    ranges: list[tuple[ReportSpec, float, float]] = field(default_factory=list)  # drawn min, max
    rejected: Counter = field(default_factory=Counter)  # why draws were turned down
    accepted: int = 0

    @property
    def ok(self) -> bool:
        return not self.problems

    def line(self) -> str:
        mark = "ok  " if self.ok else "FAIL"
        return (f"{mark} {self.template.id:<32} {self.distinct:6.1%} distinct, {self.mean_tries:4.2f} draws/variant, "
                f"{self.ms_per_variant:5.2f} ms/variant")

    def details(self) -> list[str]:
        """The drawn range of each reported quantity against its plausible range, then the commonest
        reasons draws were rejected (what a template author tightens or constructs differently)."""
        from ..units import format_number, pretty_unit

        lines = []
        for spec, low, high in self.ranges:
            unit = f" {pretty_unit(spec.unit)}" if spec.unit else ""
            lines.append(f"{spec.what}: drawn {format_number(low)} to {format_number(high)}{unit} "
                         f"(plausible {spec.low:g} to {spec.high:g})")
        draws = sum(self.rejected.values()) + self.accepted
        for reason, count in self.rejected.most_common(3):
            lines.append(f"rejected {count / max(draws, 1):.0%} of draws: {reason}")
        return lines


def validate_bank(templates: list[Template], seeds: int = 200, progress=None) -> list[Report]:
    items = progress(templates, len(templates), "validating") if progress else templates
    return [validate_template(t, seeds) for t in items]


def validate_template(template: Template, seeds: int = 200) -> Report:
    report = Report(template, seeds)
    variants, start = [], time.perf_counter()
    for seed in range(seeds):
        try:
            variants.append(make_variant(template, seed, rejected=report.rejected))
        except ExgenError as exc:  # a solver's crash among them: a defect, never a redraw
            report.problems.append(f"seed {seed}: {_problem(exc)}")
            if len(report.problems) >= 5:
                break
    if not variants:
        return report
    report.ms_per_variant = (time.perf_counter() - start) * 1000 / len(variants)
    report.mean_tries = sum(v.tries for v in variants) / len(variants)
    report.accepted = len(variants)
    report.distinct = len({tuple(p.text for p in v.params) for v in variants}) / len(variants)
    for variant in variants:
        for problem in check_variant(variant):
            if len(report.problems) < 10:
                report.problems.append(f"seed {variant.seed}: {problem}")
    _check_mistakes(template, variants, report)
    _check_texts(variants, report)
    _check_reports(template, variants, report)
    _check_uses(template, variants, report)
    if report.distinct < DISTINCT_WARNING:
        report.warnings.append(f"only {report.distinct:.0%} of {len(variants)} seeds give distinct data: widen the ranges")
    if report.mean_tries > TRIES_WARNING:
        report.warnings.append(f"{report.mean_tries:.1f} draws per accepted variant: most draws break a constraint")
    return report


def _problem(exc: ExgenError) -> str:
    """A seed's problem; for a solver's crash, the exception and where it rose (the report names the template)."""
    if isinstance(exc, SolverFailure):
        return f"the solver failed with {exc.reason}" + (f" at {exc.where}" if exc.where else "")
    return str(exc)


def _check_reports(template: Template, variants: list[Variant], report: Report) -> None:
    """The drawn range of every `report:` quantity; one outside its plausible range is a problem."""
    for i, spec in enumerate(template.report):
        values = [v.derived[i].value for v in variants if len(v.derived) > i]
        finite = [x for x in values if math.isfinite(x)]
        if finite:
            report.ranges.append((spec, min(finite), max(finite)))
        odd = [r for r in (v.derived[i] for v in variants if len(v.derived) > i) if not r.plausible]
        if odd:
            report.problems.append(f"{spec.what}: {len(odd)} of {len(values)} draws outside {spec.low:g} to {spec.high:g}")


def check_variant(variant: Variant) -> list[str]:
    """What must hold for every single variant."""
    problems = []
    broken = failed_requirement(variant.template, variant.si)
    if broken:
        problems.append(f"drawn values break {broken!r}")
    for part in variant.template.parts:
        problem = answer_type(part).problem(variant.answers[part.id].value, part)
        if problem:
            problems.append(f"part {part.id}: {problem}")
    problems += _check_ecf_identity(variant)
    problems += _check_key_grades_itself(variant)
    return problems


def _check_ecf_identity(variant: Variant) -> list[str]:
    """Substituting the right earlier answers must reproduce every answer exactly."""
    overrides = {variant.template.part(u).answer: variant.answers[u].si
                 for part in variant.template.parts for u in part.uses}
    if not overrides:
        return []
    derivation = rerun(variant, overrides)
    problems = []
    for part in variant.template.parts:
        again = answer_for(part, derivation).value
        expected = variant.answers[part.id].value
        same = again == expected if not isinstance(expected, float) else math.isclose(again, expected, rel_tol=1e-9)
        if not same:
            problems.append(f"part {part.id}: re-running with the right earlier answers gives {again!r}, not {expected!r}")
    return problems


def _check_key_grades_itself(variant: Variant) -> list[str]:
    """The key's printed answer, typed back, reads and is right: what a student copying it would score."""
    problems = []
    for part in variant.template.parts:
        kind, answer = answer_type(part), variant.answers[part.id]
        try:
            right = kind.matches(kind.read(answer.text, part).value, answer.value, part)
        except (FormatProblem, WrongKind) as exc:
            problems.append(f"part {part.id}: the key's own answer {answer.text!r} cannot be read back ({exc})")
            continue
        if not right:
            problems.append(f"part {part.id}: the key's own answer {answer.text!r} is not within "
                            f"{kind.tolerance_text(part)} of {answer.value!r}")
    return problems


def _check_mistakes(template: Template, variants: list[Variant], report: Report) -> None:
    """Every mistake a part names is one the solver records, and has words for the student. (That it
    never gives the right answer is enforced in every draw: exgen.solve.variant.mistakes_apart.)"""
    for part in template.parts:
        for mistake in part.mistakes:
            if not any(mistake.when in v.mistakes[part.id] for v in variants):
                report.problems.append(f"part {part.id}: names mistake {mistake.when!r}, which the solver never "
                                       "records apart from the answer")
            if not mistake.say and mistake.when not in default_messages():
                report.warnings.append(f"part {part.id}: mistake {mistake.when!r} has no `say:` and no default "
                                       "message in exgen/data/mistakes.yaml")


def _check_texts(variants: list[Variant], report: Report) -> None:
    """Every feedback text and hint is written with each variant it is shown beside, and none states in
    fixed words a value its draw decided otherwise (exgen.check.draw_words); each problem once, with the
    first seed that shows it."""
    found: dict[str, int] = {}
    for variant in variants:
        for problem in misstatements(variant):
            found.setdefault(problem, variant.seed)
    report.problems += [f"seed {seed}: {problem}" for problem, seed in list(found.items())[:10]]


def _check_uses(template: Template, variants: list[Variant], report: Report) -> None:
    """A part that says it is worked from an earlier one (`uses:`) must change when that one does:
    otherwise error carried forward would credit an answer the student's earlier one did not lead to."""
    for part in template.parts:
        for used_id in part.uses:
            kind = answer_type(template.part(used_id))
            depends = _depends(part, template.part(used_id), variants[:USES_TRIALS])
            if depends is None:
                report.problems.append(f"part {part.id}: uses ({used_id}), but {_a(kind.name)} answer is never "
                                       "carried forward")
            elif not depends:
                report.problems.append(f"part {part.id}: uses ({used_id}), but its answer does not change when "
                                       f"({used_id})'s does: work from it, or drop it from `uses:`")


def _depends(part, used, variants: list[Variant]) -> bool | None:
    """Whether some other answer to `used` moves `part`'s (None: answers of its type are never carried
    forward). True also when the solver takes none of the values tried, so nothing is claimed."""
    kind = answer_type(used)
    tried = False
    for variant in variants:
        others = kind.nudges(variant.answers[used.id].value, used)
        if not others:
            return None
        for other in others:
            try:
                again = answer_for(part, rerun(variant, kind.overrides(used, other, variant))).value
            except ExgenError:
                continue  # the solver refuses this value, or cannot work from it
            tried = True
            if not _same(again, variant.answers[part.id].value):
                return True
    return not tried


def _same(a, b) -> bool:
    if isinstance(a, float) and isinstance(b, float):
        return math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-12)
    return a == b


def _a(word: str) -> str:
    return f"an {word}" if word[:1] in "aeiou" else f"a {word}"
