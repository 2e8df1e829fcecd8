"""What each `exgen` command does: read its arguments, call the library, print. Every module a command
needs is imported when the command runs, so `exgen list` does not pay for PDF, grading or the web."""
from __future__ import annotations

import json
import os
import secrets
import sys
from pathlib import Path

from ..errors import ExgenError

CLOSE_MISTAKE_MEANS = ("a mistake that close is marked right: for these values the grader cannot tell it from "
                       "the answer; sheets never draw such values")
EXPORT_SUFFIX = {"moodle": ".xml", "qti": ".zip", "canvas": ".zip"}
SEED_MAX = 2**65 - 1  # sheets' seeds are below 2^64, practice's from 2^64 (exgen.draw.seeds.PRACTICE_SEEDS)


def _progress(items, total, label="working"):
    from ..runtime.progress import progress

    return progress(items, total, label)


def _bank(args, full: bool = True):
    """The bank; `full` False for commands that only list or draw (see exgen.load.bank.load_bank)."""
    from ..load.bank import load_bank

    return load_bank([Path(p) for p in args.bank], full)


def _secret(args, default: Path | None, create: bool) -> tuple[bytes, str]:
    """The course secret and where it came from: --secret-file, else $EXGEN_SECRET, else `default`."""
    from ..draw.seeds import ENV_VAR, load_secret

    explicit = bool(args.secret_file)
    path = Path(args.secret_file) if explicit else default
    secret, source = load_secret(path, create=create, explicit=explicit)
    if explicit and os.environ.get(ENV_VAR):
        print(f"Using the secret file {path}; ${ENV_VAR} is set but --secret-file wins.", file=sys.stderr)
    if source.endswith("(new)"):
        print(f"Created a new course secret in {path}. Keep it private: grading needs it.", file=sys.stderr)
        source = source[: -len(" (new)")]
    elif not source.startswith("$"):
        from ..draw.seeds import exposure

        warning = exposure(Path(source))
        if warning:
            print(f"warning: {warning}", file=sys.stderr)
    return secret, source


def _tidy(out: Path) -> None:
    """What interrupted runs left beside the output folder: removed, or named."""
    from ..runtime.outdir import tidy

    for note in tidy(out):
        print(f"note: {note}", file=sys.stderr)


def _roster(path: Path) -> list:
    """The roster's students; which columns were read, when a learning system named them."""
    from ..issue.roster import read_roster

    roster = read_roster(path)
    read = [f"{field}s from `{header}`" for field, header in roster.columns.items()
            if header.strip().lower() != field]
    if read:
        print(f"note: {path}: {', '.join(read)}", file=sys.stderr)
    return list(roster.students)


def _assignment_and_roster(args):
    """The bank, the assignment (checked against it) and the roster path (option, else the file's)."""
    from ..issue.assignment import load_assignment

    bank = _bank(args)
    assignment = load_assignment(Path(args.assignment), bank)
    roster = Path(args.roster) if args.roster else assignment.roster
    return bank, assignment, roster


def cmd_list(args) -> int:
    from ..render.unicode_math import text_to_plain

    bank = _bank(args, full=False)
    rows = [t for t in bank if args.chapter is None or t.chapter == args.chapter]
    width = max((len(t.id) for t in rows), default=0)
    for t in rows:
        source = f"  [{text_to_plain(t.source)}]" if t.source else ""
        print(f"{t.id:<{width}}  {text_to_plain(t.title)}{source}")
    print(f"\n{len(rows)} template(s)", file=sys.stderr)
    return 0


def cmd_show(args) -> int:
    from ..render.text import variant_text
    from ..solve.variant import make_variant

    template = _bank(args, full=False).get(args.id)
    seed = args.seed if args.seed is not None else secrets.randbits(32)
    variant = make_variant(template, seed)
    print(variant_text(variant, key=args.key))
    if args.figures:
        for path in _write_figures(variant, Path(args.figures), args.key):
            print(f"figure: {path}", file=sys.stderr)
    if args.seed is None:
        print(f"\n(seed {seed}: `exgen show {args.id} --seed {seed}` shows this variant again)", file=sys.stderr)
    return 0


def _write_figures(variant, folder: Path, key: bool) -> list[Path]:
    """The variant's sheet figure (and with `key` its key figures) as SVG files named as a sheet's folder names them."""
    from ..figures import question_figures

    drawn = question_figures("q1", variant)
    figures = ([drawn.sheet] if drawn.sheet else []) + (list(drawn.key) if key else [])
    if not figures:
        raise ExgenError(f"{variant.template.id} has no figure{'' if key else ' on its sheet'}")
    folder.mkdir(parents=True, exist_ok=True)
    for figure in figures:
        (folder / figure.name).write_text(figure.svg, encoding="utf-8")
    return [folder / figure.name for figure in figures]


def cmd_solve(args) -> int:
    from ..check.given import parse_settings, solve
    from ..render.unicode_math import text_to_plain

    template = _bank(args).get(args.id)
    variant, warnings = solve(template, parse_settings(args.set))
    from ..solve.variant import MISTAKE_CLOSE, MISTAKE_IS_ANSWER

    close = [w for w in warnings if MISTAKE_CLOSE in w or MISTAKE_IS_ANSWER in w]
    for warning in warnings:
        print(f"warning: {warning}", file=sys.stderr)
        if close and warning is close[-1]:
            print(f"  ({CLOSE_MISTAKE_MEANS})", file=sys.stderr)
    if args.json:
        print(json.dumps(solution_json(variant), indent=2, ensure_ascii=False))
        return 0
    if args.steps:
        from ..render.text import variant_text

        print(variant_text(variant, key=True))
        return 0
    print(text_to_plain(template.title))
    for part_id, answer in variant.answers.items():
        print(f"  ({part_id}) {text_to_plain(variant.asks[part_id])}: {answer.text}")
    return 0


def _given_json(p) -> dict:
    """A given as printed, and in the SI unit the working uses (ω in rad/s for a speed in rpm)."""
    from ..units import si_unit

    out = {"value": p.text, "unit": p.unit}
    if isinstance(p.si, float) and p.unit and si_unit(p.unit) not in (None, p.unit):
        out.update(si=p.si, si_unit=si_unit(p.unit))
    return out


def solution_json(variant) -> dict:
    """Every part's value and unit, and every step's: its ask as plain text (and as written, with LaTeX)."""
    from ..render.unicode_math import text_to_plain

    def plain(value):
        return value if isinstance(value, (int, float, str)) else str(value)

    return {
        "template": variant.template.id,
        "given": {p.name: _given_json(p) for p in variant.params},
        "parts": {
            part_id: {"ask": text_to_plain(variant.asks[part_id]), "ask_latex": variant.asks[part_id],
                      "value": plain(a.value), "unit": a.part.unit, "text": a.text}
            for part_id, a in variant.answers.items()
        },
        "steps": [{"name": s.name, "value": plain(s.value), "unit": s.unit} for s in variant.steps],
        "derived": [{"what": r.spec.what, "value": r.value, "unit": r.spec.unit, "plausible": [r.spec.low, r.spec.high],
                     "ok": r.plausible} for r in variant.derived],
    }


def cmd_generate(args) -> int:
    from ..issue.generate import default_jobs, generate

    bank, assignment, roster_path = _assignment_and_roster(args)
    if roster_path is None:
        raise ExgenError("give the class list with --roster ROSTER.csv (or `roster:` in the assignment file)")
    students = _roster(roster_path)
    if args.print and args.no_pdf:
        raise ExgenError("--print joins the sheets' PDFs: leave out --no-pdf")
    secret, source = _secret(args, assignment.secret_file, create=True)
    recorded = source if source.startswith("$") else str(Path(source).resolve())
    _tidy(Path(args.out))
    issued = generate(assignment, students, bank, secret, Path(args.out), pdf=not args.no_pdf,
                      key_pdf=not args.no_key_pdf, jobs=args.jobs or default_jobs(), progress=_progress,
                      secret_source=recorded, print_bundle=args.print)
    kinds = "sheet (Markdown, PDF), answer form" if not args.no_pdf else "sheet (Markdown), answer form"
    keys = "keys (Markdown, PDF)" if not (args.no_pdf or args.no_key_pdf) else "keys (Markdown)"
    print(f"{len(issued.sheets)} student(s): {kinds} in {issued.out / 'students'}; {keys} in {issued.out / 'keys'}")
    if args.print:
        print(f"for printing: {issued.out / 'print' / 'sheets.pdf'} (every sheet, roster order)"
              + (f", {issued.out / 'print' / 'keys.pdf'} (every key)" if not args.no_key_pdf else ""))
    print(f"manifest: {issued.manifest}")
    return 0


def cmd_grade(args) -> int:
    from graders.grade import grade_issued
    from graders.report import write_results

    from ..issue.manifest import read_manifest
    from ..load.bank import refuse_code_in
    from ..runtime.outdir import check_target

    manifest = read_manifest(Path(args.issued))
    submissions = Path(args.submissions)
    if not submissions.is_dir():
        raise ExgenError(f"{submissions}: no such folder" if not submissions.exists() else
                         f"{submissions}: not a folder: give the folder holding the answer files")
    _tidy(Path(args.out))
    check_target(Path(args.out), "grade")  # before any work: a folder that cannot be replaced stops here
    refuse_code_in(submissions, [Path(p) for p in args.bank])  # never a template, nor code, from students
    bank = _bank(args)
    recorded = Path(manifest.secret_source) if manifest.secret_source and not manifest.secret_source.startswith("$") \
        else None
    secret, source = _secret(args, recorded, create=False)
    roster = _roster(Path(args.roster)) if args.roster else None
    decisions = _decisions(args, manifest.assignment.id, submissions)
    from ..issue.generate import default_jobs

    batch = grade_issued(manifest, bank, secret, submissions, secret_source=source, force=args.force, roster=roster,
                         progress=_progress, jobs=args.jobs or default_jobs(), accept_limits=args.accept_limits,
                         decisions=decisions)
    for warning in batch.warnings:
        print(f"WARNING: {warning}", file=sys.stderr)
    for limit in batch.limits:
        print(f"WARNING: graded with --accept-limits: {limit}; a student's file there may have been missed",
              file=sys.stderr)
    from graders.copying import signs_of_copying

    signs = signs_of_copying(batch, manifest.assignment, bank, secret, manifest.codes)
    paths = write_results(batch, Path(args.out), signs, canvas_id=args.canvas_id or "")
    print(batch.summary())
    if batch.review is not None:
        _review_lines(batch.review)
    for name, path in paths.items():
        print(f"{name}: {path}")
    return 0


def _decisions(args, assignment: str, submissions: Path):
    """The review decisions to grade with: --decisions FILE, else OUT.decisions.yaml if it exists. Never a
    file among the submissions (a student could write one), nor inside the folder a run replaces."""
    from graders.decisions import DecisionsError, default_path, load_decisions

    out = Path(args.out)
    path = Path(args.decisions) if args.decisions else default_path(out)
    where = path.resolve()
    for folder, why in ((submissions, "among the submissions, where a student could write it"),
                        (out, "inside the folder exgen grade replaces, where it would be lost")):
        if where == folder.resolve() or folder.resolve() in where.parents:
            raise DecisionsError(path, f"the review decisions file is {why}: keep it beside the output folder "
                                       f"(the default is {default_path(out)})")
    return load_decisions(path, assignment, missing_ok=not args.decisions)


def _review_lines(review) -> None:
    """The decisions graded with, and each one that matched nothing graded (so changed no mark)."""
    from graders.report import where_in

    left = f"; {len(review.not_applied)} not applied (listed in report.md):" if review.not_applied else ""
    print(f"review: {review.path}: {review.decisions} decision(s) and {review.aliases} alias(es), which marked "
          f"{review.applied} answer(s){left}")
    for item in review.not_applied:
        print(f"  not applied: {where_in(review.path, item.line)}: {item.what}: {item.why}", file=sys.stderr)


def cmd_decide(args) -> int:
    from graders.decide import DecideError, accept_spelling, decide_answer, withdraw

    decisions = Path(args.decisions) if args.decisions else None
    withdrawing = args.withdraw is not None or args.withdraw_spelling is not None
    given = [name for name in ("means", "points", "reviewer", "reason") if getattr(args, name) is not None]
    if withdrawing:
        if given or args.comment:
            raise DecideError(f"--{(given or ['comment'])[0]} is not for withdrawing a decision")
        _, done = withdraw(Path(args.graded), args.question, args.part, args.withdraw, args.withdraw_spelling,
                           decisions)
        print(done)
        return 0
    missing = [name for name in ("reviewer", "reason") if getattr(args, name) is None]
    if missing:
        raise DecideError(f"--{missing[0]} is required: every decision says who made it and why")
    if args.accept_spelling is not None:
        if args.means is None:
            raise DecideError("--accept-spelling needs --means: what the spelling is read as")
        if args.points is not None or args.comment:
            raise DecideError("--points and --comment are for --accept and --reject: a spelling is graded as usual")
        _, done = accept_spelling(Path(args.graded), args.question, args.part, args.accept_spelling, args.means,
                                  args.reviewer, args.reason, _bank(args), decisions)
    else:
        if args.means is not None:
            raise DecideError("--means is for --accept-spelling")
        verdict, student = ("accept", args.accept) if args.accept is not None else ("reject", args.reject)
        _, done = decide_answer(Path(args.graded), verdict, student.strip(), args.question, args.part, args.reviewer,
                                args.reason, args.points, args.comment, decisions)
    print(done)
    return 0


def cmd_export(args) -> int:
    from ..export import writer
    from ..export.pool import build_pool, notices

    suffix = EXPORT_SUFFIX[args.format]
    if Path(args.out).suffix.lower() != suffix:  # a .zip of Moodle XML would fail at import, after all the work
        raise ExgenError(f"--out {args.out}: {args.format} writes a {suffix} file (e.g. --out pool-{args.format}{suffix})")
    bank = _bank(args)
    files = [s for s in args.sources if s.lower().endswith((".yaml", ".yml"))]
    if files and (len(files) > 1 or len(args.sources) > 1):
        raise ExgenError("give one assignment file, or template ids, not both")
    if files:
        from ..issue.assignment import load_assignment

        assignment = load_assignment(Path(files[0]), bank)
        specs = [(q.slot, bank.get(q.template), q.points or bank.get(q.template).points) for q in assignment.questions]
        title, scope, default = assignment.title, assignment.id, assignment.secret_file
    else:
        templates = [bank.get(i) for i in args.sources]
        specs = [(f"q{n}", t, t.points) for n, t in enumerate(templates, start=1)]
        title, scope, default = args.title or "exgen problems", "pool", None
    secret, _ = _secret(args, default, create=default is not None)
    pool = build_pool(args.title or title, scope, specs, secret, args.variants, progress=_progress)
    for notice in notices(pool):
        print(f"note: {notice}", file=sys.stderr)
    path = writer(args.format)(pool, Path(args.out))
    print(f"{len(pool.questions)} question(s) x {args.variants} variant(s) as {args.format}: {path}")
    return 0


def cmd_report(args) -> int:
    from graders.item_report import write_report

    for name, path in write_report(Path(args.graded), Path(args.out) if args.out else None).items():
        print(f"{name}: {path}")
    return 0


def cmd_review(args) -> int:
    from graders.review_page.server import review

    return review(Path(args.graded), Path(args.decisions) if args.decisions else None, host=args.host, port=args.port,
                  open_browser=args.open, reviewer=args.reviewer, bank=lambda: _bank(args))


def cmd_validate(args) -> int:
    from ..check.validate import validate_bank

    bank = _bank(args)
    templates = [bank.get(i) for i in args.ids] if args.ids else list(bank)
    reports = validate_bank(templates, seeds=args.seeds, progress=_progress)
    failed = [r for r in reports if not r.ok]
    for report in reports:
        print(report.line())
        for problem in report.problems + report.warnings + report.details():
            print(f"    {problem}")
    print(f"\n{len(reports) - len(failed)} of {len(reports)} template(s) valid over {args.seeds} seeds each")
    return 1 if failed else 0


def _practice(args):
    """The practice core over the progress file, limited to an assignment's templates if one is given."""
    from ..issue.assignment import load_assignment
    from practice.session import Practice
    from practice.store import Store

    bank = _bank(args)
    assignment = load_assignment(Path(args.assignment), bank) if args.assignment else None
    return Practice(bank, Store(Path(args.db)), assignment)


def cmd_practice(args) -> int:
    from practice.terminal import Terminal, stats_text

    practice = _practice(args)
    if args.stats:
        print(stats_text(practice))
        return 0
    scope = practice.catalogue.choose(args.chapter, args.topic)
    return Terminal(practice, scope, open_figures=args.open).run()


def cmd_serve(args) -> int:
    from practice.web.server import serve

    return serve(_practice(args), host=args.host, port=args.port, open_browser=args.open)
