"""Practice: a fresh problem from where the student is weakest, each part checked as the grader checks
an answer file (same reading, tolerances, named mistakes and error carried forward), hints, the worked
solution, and every step kept in the progress file. The terminal and the browser both drive this.

A problem is (template, seed) like any sheet's question, so it is rebuilt, not stored: its seed comes
from the practice range (exgen.draw.seeds.PRACTICE_SEEDS), never one a sheet can have, and a variant whose
printed values the student has already met is never served again.
"""
from __future__ import annotations

import hashlib
import random
from collections import OrderedDict
from dataclasses import dataclass
from threading import Lock

from graders.grade import grade_variant
from graders.marking import is_blank
from graders.results import BLANK, CARRIED, CORRECT, UNREADABLE, WRONG, PartResult

from exgen.draw.seeds import PRACTICE_SEEDS, practice_seed
from exgen.errors import ExgenError
from exgen.figures import figure_svg, key_figure_svgs
from exgen.load.references import resolve
from exgen.load.template import Template
from exgen.render.solution import Solution, solution
from exgen.solve.variant import Variant, make_variant

from . import mastery
from .hints import Hint, hint_ladder
from .progress import Progress, Row
from .scope import Catalogue, Scope, topic_of
from .store import CheckRow, Store

DRAWS = 25          # fresh seeds tried for a template before it counts as exhausted for this student
CACHED = 256        # variants kept in memory (a page, its checks and its solution reuse one)
EXHAUSTED = "you have met every variant of {label} that could be drawn; choose another topic"
NO_PROBLEM = "there is no practice problem {id}"
NO_PART = "the problem has no part {part!r}"
#: How a part went (Practice.parts_done), besides graders' WRONG and BLANK.
RIGHT_FIRST, AFTER_HINT, AFTER_SOLUTION = "right first", "right after a hint", "after the solution"


class NoProblem(ExgenError, LookupError):
    """A problem id the progress file does not have."""


@dataclass(frozen=True)
class Problem:
    """A served problem: its record and its variant, rebuilt from the seed."""

    id: int
    scope: Scope
    variant: Variant

    @property
    def template(self) -> Template:
        return self.variant.template


@dataclass(frozen=True)
class State:
    """What the student has done on a problem: the latest check of each part, hints shown per part, the
    parts ever answered right (against the key: their numbers may now be shown in hints)."""

    checks: dict[str, CheckRow]
    hints: dict[str, int]
    solution: bool
    right: frozenset[str] = frozenset()
    answered: frozenset[str] = frozenset()  # parts with a readable answer (right or wrong): their evidence is in

    def hint_cost(self, part_id: str) -> float:
        """What the part's next hint costs, as a share of its credit."""
        return mastery.next_hint_cost(part_id in self.answered, self.solution, self.hints.get(part_id, 0))

    def solution_cost(self, parts) -> bool:
        """Whether opening the worked solution now costs anything: some part is still to be answered."""
        return not self.solution and any(p.id not in self.answered for p in parts)


def variant_digest(variant: Variant) -> str:
    """Two seeds that print the same values are the same problem to a student."""
    printed = "\n".join(f"{p.name}={p.text}" for p in variant.params)
    return hashlib.sha256(f"{variant.template.id}\n{printed}".encode("utf-8")).hexdigest()[:32]


class Practice:
    def __init__(self, bank, store: Store, assignment=None, rng: random.Random | None = None):
        self.catalogue = Catalogue(bank, assignment)
        self.store = store
        self.rng = rng or random.SystemRandom()
        self.progress = Progress(store, self._points)
        self._variants: OrderedDict[tuple[str, int], tuple[Variant, dict]] = OrderedDict()
        self._lock = Lock()
        self.ahead = None  # an ahead.Ahead, when figures are to be drawn ahead (the web server)

    def warm(self) -> None:
        """Do once, before the first student waits, what every template's first problem would do: import
        its solver and figure code and compile its texts (a variant drawn and dropped, nothing recorded)."""
        for template in self.catalogue.templates:
            variant = make_variant(template, PRACTICE_SEEDS.start)
            for part in template.parts:
                for hint in part.hints:
                    variant.fill(hint)
            if template.figure:
                resolve(template.figure, "figures")
        self.progress.refresh()

    def _points(self, template_id: str) -> dict[str, float] | None:
        template = self.catalogue.bank.templates.get(template_id)
        return {p.id: p.points for p in template.parts} if template else None

    # ---- problems ---------------------------------------------------------------------------

    def next_problem(self, scope: Scope) -> Problem:
        """A new problem in `scope`, from a template chosen by weakness, a variant never served before."""
        candidates: dict[str, list[str]] = {}
        for template in self.catalogue.templates_in(scope):
            candidates.setdefault(topic_of(template), []).append(template.id)
        topics, templates = self.progress.table("topic"), self.progress.table("template")
        avoid = self.store.last_template()
        while candidates:
            chosen = mastery.choose(candidates, {k: r.mastery for k, r in topics.items()},
                                    {k: r.mastery for k, r in templates.items()}, self.rng, avoid)
            problem = self._fresh(self.catalogue.by_id[chosen], scope)
            if problem is not None:
                return problem
            topic = topic_of(self.catalogue.by_id[chosen])
            candidates[topic].remove(chosen)
            if not candidates[topic]:
                del candidates[topic]
        raise ExgenError(EXHAUSTED.format(label=self.catalogue.label(scope)))

    def _fresh(self, template: Template, scope: Scope) -> Problem | None:
        served = self.store.variants_served(template.id)
        ready = self.ahead.take(template) if self.ahead is not None else None
        for attempt in range(DRAWS):
            seed, made = ready if attempt == 0 and ready is not None else (practice_seed(), {})
            variant = make_variant(template, seed)
            digest = variant_digest(variant)
            if digest in served:
                continue
            problem_id = self.store.add_problem(template, seed, digest, scope.key)
            if problem_id is not None:
                self._remember(template.id, seed, variant)[1].update(made)
                return Problem(problem_id, scope, variant)
        return None

    def problem(self, problem_id: int) -> Problem:
        row = self.store.problem(problem_id) if 0 < problem_id < 2**63 else None
        if row is None:
            raise NoProblem(NO_PROBLEM.format(id=problem_id))
        template = self.catalogue.bank.get(row.template)
        return Problem(row.id, Scope.parse(row.scope), self._variant(template, row.seed))

    def _variant(self, template: Template, seed: int) -> Variant:
        return self._cached(template, seed)[0]

    def _cached(self, template: Template, seed: int) -> tuple[Variant, dict]:
        key = (template.id, seed)
        with self._lock:
            if key in self._variants:
                self._variants.move_to_end(key)
                return self._variants[key]
        return self._remember(template.id, seed, make_variant(template, seed))

    def _remember(self, template_id: str, seed: int, variant: Variant) -> tuple[Variant, dict]:
        with self._lock:
            entry = self._variants.setdefault((template_id, seed), (variant, {}))
            while len(self._variants) > CACHED:
                self._variants.popitem(last=False)
            return entry

    def _memo(self, problem: Problem, name: str, make):
        """Something made once per variant (its figure, solution, hint ladders), kept with it."""
        memo = self._cached(problem.template, problem.variant.seed)[1]
        if name not in memo:
            memo[name] = make()
        return memo[name]

    def figure(self, problem: Problem) -> str | None:
        return self._memo(problem, "figure", lambda: figure_svg(problem.variant))

    def key_figures(self, problem: Problem) -> list[tuple[str, str]]:
        return self._memo(problem, "key_figures", lambda: key_figure_svgs(problem.variant))

    def worked(self, problem: Problem) -> Solution:
        return self._memo(problem, "solution", lambda: solution(problem.variant))

    # ---- answering --------------------------------------------------------------------------

    def state(self, problem: Problem) -> State:
        latest, right, answered = {}, set(), set()
        for check in self.store.checks(problem.id):
            latest[check.part] = check
            if check.status == CORRECT:
                right.add(check.part)
            if check.status in (CORRECT, CARRIED, WRONG):
                answered.add(check.part)
        shown: dict[str, int] = {}
        for hint in self.store.hints(problem.id):
            shown[hint.part] = max(shown.get(hint.part, 0), hint.level)
        return State(latest, shown, self.store.solution_shown(problem.id), frozenset(right), frozenset(answered))

    def parts_done(self, problem: Problem) -> dict[str, str]:
        """How each part went, as mastery counts it: RIGHT_FIRST, AFTER_HINT, WRONG, BLANK (no readable
        answer) or AFTER_SOLUTION (first answered once the worked solution was shown)."""
        checks = self.store.checks(problem.id)
        hinted = {}
        for hint in self.store.hints(problem.id):
            hinted.setdefault(hint.part, hint.at)
        solved = self.store.solution_at(problem.id)
        done = {}
        for part in problem.template.parts:
            first = next((c for c in checks if c.part == part.id and c.status in (CORRECT, CARRIED, WRONG)), None)
            if first is None:
                done[part.id] = BLANK
            elif solved is not None and first.at > solved:
                done[part.id] = AFTER_SOLUTION
            elif first.status == WRONG:
                done[part.id] = WRONG
            else:
                done[part.id] = AFTER_HINT if part.id in hinted and hinted[part.id] <= first.at else RIGHT_FIRST
        return done

    def check(self, problem: Problem, part_id: str, text: str) -> PartResult:
        """Mark one part against the variant, with the latest answers to the others for error carried
        forward; recorded unless blank (an unreadable answer is recorded, and is no evidence)."""
        self._part(problem, part_id)
        answers = {p: c.answer for p, c in self.state(problem).checks.items() if c.status not in (BLANK, UNREADABLE)}
        answers[part_id] = text
        result = next(r for r in grade_variant(problem.variant, answers).parts if r.part_id == part_id)
        if not is_blank(text):
            self.store.add_check(problem.id, part_id, text, result.status, result.mistake, result.message)
        return result

    def hints(self, problem: Problem, part_id: str, state: State | None = None) -> tuple[Hint, ...]:
        """The part's hints as they may be shown now: no number in them is the answer to a part not yet
        answered right (`state`, if already read)."""
        self._part(problem, part_id)
        right = (state or self.state(problem)).right
        return self._memo(problem, f"hints:{part_id}:{','.join(sorted(right))}",
                          lambda: hint_ladder(problem.variant, part_id, self.worked(problem), right))

    def next_hint(self, problem: Problem, part_id: str) -> tuple[int, Hint] | None:
        """The next hint of the part's ladder (recorded as shown), or None when there are no more."""
        state = self.state(problem)
        ladder = self.hints(problem, part_id, state)
        level = state.hints.get(part_id, 0) + 1
        if level > len(ladder):
            return None
        self.store.add_hint(problem.id, part_id, level)
        return level, ladder[level - 1]

    def show_solution(self, problem: Problem) -> Solution:
        """The worked solution, recorded as shown (parts answered after it earn no credit)."""
        worked = self.worked(problem)
        self.store.show_solution(problem.id)
        return worked

    def _part(self, problem: Problem, part_id: str) -> None:
        if part_id not in {p.id for p in problem.template.parts}:
            raise ExgenError(NO_PART.format(part=str(part_id)[:20]))

    # ---- progress ---------------------------------------------------------------------------

    def table(self, by: str = "topic") -> dict[str, Row]:
        return self.progress.table(by)
