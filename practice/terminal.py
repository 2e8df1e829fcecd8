"""`exgen practice`: problems in the terminal, one part at a time, in plain text.

No colour, no cursor control and nothing read but lines, so it works the same in a bare terminal
and over a pipe (tests drive it through stdin). At a part's prompt a student types an answer, as in
an answer file ("168.8 deg", "2 kN"), or one letter: h (a hint), s (the worked solution), n (the next
problem), q (quit with a summary). End of input quits as q does.
"""
from __future__ import annotations

import os
import shlex
import shutil
import subprocess
import sys
import textwrap
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, TextIO

from graders.results import BLANK, CARRIED, CORRECT, UNREADABLE, WRONG

from exgen.answertypes import answer_type
from exgen.render.targets import PLAIN
from exgen.render.text import ask_text, key_lines, line_text, statement_text, WIDTH
from .mastery import Mastery, costs
from .progress import Row
from .scope import Scope, topic_of
from .session import AFTER_HINT, AFTER_SOLUTION, RIGHT_FIRST, Practice, Problem

RULE = "─" * WIDTH
HELP = ("Type your answer with its unit (a bare number is read in the unit asked), or: "
        "h hint · s worked solution · n next problem · q quit")
COSTS = "Help costs credit on the parts it helps with: {hint}; {solution}."
FIGURE_GIVEN = "The figure is the problem's data; open it to answer"
OPEN_SUGGESTED = "(Figures are kept beside your progress file; `exgen practice --open` opens each in your viewer.)"
FIGURE_UNWRITTEN = "The figure could not be written to {path} ({reason}); the web pages (`exgen serve`) show it."
SOLUTION_SHOWN = "(Parts answered from now on are checked, but count for nothing in your progress.)"
#: An unreadable answer has no lead: its message says what could not be read, and that it is a format problem.
VERDICTS = {CORRECT: "Right.", CARRIED: "Right, from your earlier answer:", WRONG: "Not right:"}
NEXT, QUIT = "next", "quit"


@dataclass
class Tally:
    """This sitting's counts, for the summary at the end."""

    problems: list = field(default_factory=list)  # the problems served
    hints: int = 0
    solutions: int = 0
    topics: dict[str, Mastery] = field(default_factory=dict)  # mastery when the sitting began


class Terminal:
    def __init__(self, practice: Practice, scope: Scope, *, ask: Callable[[str], str] | None = None,
                 out: TextIO | None = None, open_figures: bool = False, figures: Path | None = None):
        self.practice, self.scope = practice, scope
        self.out = out or sys.stdout
        self.ask = ask or _ask
        self.open_figures = open_figures
        self._figures = figures
        self._suggested = False  # --open suggested once a sitting
        self.tally = Tally()

    def say(self, text: str = "") -> None:
        print(text, file=self.out, flush=True)

    def tell(self, text: str, lead: str = "  ") -> None:
        """A sentence or two (feedback, a hint, a note) wrapped to the page, continued under its first word."""
        self.say(textwrap.fill(text, WIDTH, initial_indent=lead, subsequent_indent=lead + "  ",
                               break_long_words=False, break_on_hyphens=False))

    def run(self) -> int:
        self.tally.topics = {k: r.mastery for k, r in self.practice.table("topic").items()}
        self.say(f"Practising {self.practice.catalogue.label(self.scope)}.")
        self.tell(HELP, lead="")
        self.tell(COSTS.format(**costs()), lead="")
        self._figures = self._figures or figures_folder(self.practice.store.path)
        while self.problem(self.practice.next_problem(self.scope)) != QUIT:
            pass
        self.summary()
        return 0

    # ---- one problem ------------------------------------------------------------------------

    def problem(self, problem: Problem) -> str:
        self.tally.problems.append(problem)
        variant = problem.variant
        row = self.practice.table("topic").get(topic_of(problem.template))
        standing = f"  ·  {topic_of(problem.template)}: {_standing(row.mastery if row else Mastery())}"
        self.say(RULE)
        self.say(f"Problem {problem.id}  ·  {problem.template.title}{standing}")
        self.say()
        self.say(statement_text(variant))
        self.show_figures(problem)
        self.say()
        for part in problem.template.parts:
            self.say(ask_text(variant, part))
        solved = False
        for part in problem.template.parts:
            outcome = self.part(problem, part, solved)
            if outcome in (NEXT, QUIT):
                return outcome
            solved = solved or outcome == "solution"
        self.say()
        return self.between(problem, solved)

    def show_figures(self, problem: Problem) -> None:
        svg = self.practice.figure(problem)
        if not svg:
            return
        path = self._write(f"problem-{problem.id}.svg", svg)
        if path is None:
            return
        given = any(not spec.given for spec in problem.template.params)  # what it draws is not in the text
        self.say()
        self.say(f"{FIGURE_GIVEN if given else 'Figure'}: {path}")  # a path is never wrapped
        if self.open_figures:
            open_file(path)
        elif not self._suggested and can_open():
            self._suggested = True
            self.tell(OPEN_SUGGESTED, lead="")

    def _write(self, name: str, svg: str) -> Path | None:
        """The figure written beside the progress file, kept after the sitting; None (said) if it cannot be."""
        path = self._figures / name
        try:
            self._figures.mkdir(parents=True, exist_ok=True)
            path.write_text(svg, encoding="utf-8")
        except OSError as exc:
            self.tell(FIGURE_UNWRITTEN.format(path=path, reason=exc.strerror or exc), lead="")
            return None
        return path

    def part(self, problem: Problem, part, solved: bool) -> str:
        """Prompt for one part until it is right, skipped (empty line), or the student moves on."""
        prompt = f"({part.id}) [{answer_type(part).form_hint(part)}] > "
        if part is not problem.template.parts[0]:  # the first follows the list of parts
            self.say()
            self.say(ask_text(problem.variant, part))
        while True:
            try:
                text = self.ask(prompt).strip()
            except EOFError:
                self.say()
                return QUIT
            command = text.lower()
            if command in ("q", "quit"):
                return QUIT
            if command in ("n", "next"):
                return NEXT
            if command in ("h", "hint"):
                self.hint(problem, part.id)
                continue
            if command in ("s", "solution"):
                self.solution(problem)
                solved = True
                continue
            if command in ("?", "help"):
                self.tell(HELP)
                self.tell(COSTS.format(**costs()))
                continue
            if not text:
                return "solution" if solved else "skipped"
            result = self.practice.check(problem, part.id, text)
            self.verdict(result)
            if result.correct:
                return "solution" if solved else "answered"
            if result.status == WRONG:
                self.tell("Try again, or press Enter to go on (h for a hint, s for the worked solution).")

    def verdict(self, result) -> None:
        if result.status == CORRECT:
            self.say(f"  {VERDICTS[CORRECT]}")
            return
        lead, message = VERDICTS.get(result.status, ""), PLAIN.text(result.message)
        self.tell(f"{lead} {message}" if lead else message[:1].upper() + message[1:])

    def hint(self, problem: Problem, part_id: str) -> None:
        given = self.practice.next_hint(problem, part_id)
        if given is None:
            count = len(self.practice.hints(problem, part_id))
            self.say("  No hints for this part: s shows the worked solution." if not count else
                     f"  That was the last of {count} hint(s): s shows the worked solution.")
            return
        self.tally.hints += 1
        level, hint = given
        if hint.line is not None:
            self.say(f"  Hint {level}:")
            for line in line_text(hint.line, "    "):
                self.say(line)
        else:
            self.tell(f"Hint {level}: {PLAIN.text(hint.text)}")

    def solution(self, problem: Problem) -> None:
        worked = self.practice.show_solution(problem)
        self.tally.solutions += 1
        self.say()
        for line in key_lines(problem.variant, worked):
            self.say(line)
        for name, svg in self.practice.key_figures(problem):
            path = self._write(f"problem-{problem.id}-{name}.svg", svg)
            if path is None:
                continue
            self.say(f"  Figure ({name.replace('_', ' ')}): {path}")
            if self.open_figures:
                open_file(path)
        self.say(SOLUTION_SHOWN)

    def between(self, problem: Problem, solved: bool) -> str:
        """After the last part: the solution on request, then the next problem or quit."""
        while True:
            try:
                text = self.ask("Enter (or n) for the next problem, s for the worked solution, q to quit > ")
            except EOFError:
                self.say()
                return QUIT
            command = text.strip().lower()
            if command in ("q", "quit"):
                return QUIT
            if command in ("", "n", "next"):
                return NEXT
            if command in ("s", "solution") and not solved:
                self.solution(problem)
                solved = True
            elif command in ("s", "solution"):
                self.say("The worked solution is above.")
            else:  # an answer typed once more, say: it would otherwise vanish without a word
                self.tell("Every part of this problem is done; that was not read as an answer.", lead="")

    # ---- the summary ------------------------------------------------------------------------

    def summary(self) -> None:
        t = self.tally
        done = Counter(how for problem in t.problems for how in self.practice.parts_done(problem).values())
        parts = sum(done.values())
        after = f", {done[AFTER_SOLUTION]} after the worked solution" if done[AFTER_SOLUTION] else ""
        self.say(RULE)
        self.tell(f"This sitting: {len(t.problems)} problem(s), {parts} part(s): {done[RIGHT_FIRST]} right at the "
                  f"first try, {done[AFTER_HINT]} right after a hint, {done[WRONG]} wrong at the first try, "
                  f"{done[BLANK]} left blank{after}; {t.hints} hint(s) and {t.solutions} worked solution(s) seen.",
                  lead="")
        rows = self.practice.table("topic")
        changed = [name for name, row in rows.items() if row.mastery != t.topics.get(name)]
        for name in changed:
            before = t.topics.get(name, Mastery())
            self.say(f"  {name}: {_standing(before)} → {_standing(rows[name].mastery)}")
        self.say(f"Progress is kept in {self.practice.store.path}; `{stats_command(self.practice.store.path)}` "
                 "shows all of it.")


def _ask(prompt: str) -> str:
    """input(), echoing the line when it comes from a pipe, so that a transcript reads as a dialogue."""
    text = input(prompt)
    if not sys.stdin.isatty():
        print(text, flush=True)
    return text


def _standing(estimate: Mastery) -> str:
    return "not started" if estimate.problems == 0 else f"{estimate.text} ({estimate.level})"


def stats_command(path: Path) -> str:
    """The command that shows this progress file's table (naming the file unless it is the default)."""
    from .store import default_path

    same = Path(path).resolve() == Path(default_path()).resolve()
    return "exgen practice --stats" + ("" if same else f" --db {shlex.quote(str(path))}")


def stats_text(practice: Practice) -> str:
    """The per-topic table of `exgen practice --stats`: every chapter and topic, tried or not."""
    rows = practice.table("topic")
    lines = [f"{'topic':<16} {'mastery':>8}  {'level':<12} {'problems':>8} {'answers':>8} {'time':>8}"]
    for chapter in practice.catalogue.chapters():
        lines.append(f"Chapter {chapter.number}: {chapter.title}"
                     + ("" if chapter.topics else f"  ({practice.catalogue.absent})"))
        for topic in chapter.topics:
            row = rows.get(topic) or Row(topic, chapter.number, Mastery(), 0, 0, 0.0)
            shown = row.mastery.text if row.mastery.problems else "-"
            lines.append(f"  {topic:<14} {shown:>8}  {row.mastery.level:<12} {row.problems:>8} {row.checks:>8} "
                         f"{_duration(row.seconds):>8}")
    lines.append(f"\nProgress file: {practice.store.path}")
    return "\n".join(lines)


def _duration(seconds: float) -> str:
    minutes = round(seconds / 60)
    return f"{minutes // 60}h{minutes % 60:02d}" if minutes >= 60 else f"{minutes} min"


def figures_folder(progress: Path) -> Path:
    """Where the terminal keeps figures: beside the progress file, named after it (practice-figures/)."""
    progress = Path(progress)
    return progress.with_name(f"{progress.stem}-figures")


def can_open() -> bool:
    """Whether this system has a viewer `open_file` can start."""
    return sys.platform in ("win32", "darwin") or shutil.which("xdg-open") is not None


def open_file(path: Path) -> None:
    """Open a file in the system's viewer, without waiting for it and without its chatter."""
    try:
        if sys.platform == "win32":
            os.startfile(path)  # type: ignore[attr-defined]
            return
        opener = "open" if sys.platform == "darwin" else "xdg-open"
        subprocess.Popen([opener, str(path)], stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL, start_new_session=True)
    except OSError as exc:
        print(f"(could not open {path}: {exc.strerror or exc})", file=sys.stderr)
