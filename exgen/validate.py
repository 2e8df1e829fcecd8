"""`exgen validate`: draw many variants of each template and check what must always hold.

Per variant: the constraints hold, every answer is a finite number of the asked kind, re-running
the derivation with its own answers changes nothing (ECF is consistent), and the key grades
itself at 100 %. Per template: every mistake a part names is recorded by the solver somewhere,
mistakes rarely coincide with the right answer, and seeds give distinct problems.
"""
from __future__ import annotations

import math
import time
from collections import Counter
from dataclasses import dataclass, field

from .answertypes import answer_type
from .draw import failed_requirement
from .errors import ExgenError, FormatProblem, WrongKind
from .template import ReportSpec, Template
from .variant import Variant, answer_for, make_variant, rerun

COINCIDENCE_WARNING = 0.05  # share of draws where a mistake equals the answer
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
        from .units import format_number, pretty_unit

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
        except ExgenError as exc:
            report.problems.append(f"seed {seed}: {exc}")
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
    _check_reports(template, variants, report)
    if report.distinct < DISTINCT_WARNING:
        report.warnings.append(f"only {report.distinct:.0%} of {len(variants)} seeds give distinct data: widen the ranges")
    if report.mean_tries > TRIES_WARNING:
        report.warnings.append(f"{report.mean_tries:.1f} draws per accepted variant: most draws break a constraint")
    return report


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
    for part in template.parts:
        for mistake in part.mistakes:
            if part.type in ("integer", "choice"):
                continue  # a whole-number or word answer may coincide: the right answer is checked first
            values = [v.mistakes[part.id].get(mistake.when) for v in variants]
            recorded = [(v, m) for v, m in zip(variants, values) if m is not None]
            if not recorded:
                report.problems.append(f"part {part.id}: names mistake {mistake.when!r}, which the solver never records")
                continue
            same = sum(1 for v, m in recorded if _coincides(v.answers[part.id].value, m, part))
            if same / len(variants) > COINCIDENCE_WARNING:
                report.warnings.append(
                    f"part {part.id}: mistake {mistake.when!r} equals the right answer in {same} of {len(variants)} draws")


def _coincides(answer, mistake, part) -> bool:
    return answer_type(part).matches(mistake, answer, part)
