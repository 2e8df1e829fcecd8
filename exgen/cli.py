"""The `exgen` command: parses arguments, calls the library, prints. Errors meant for the user
are printed as one message (no traceback) with exit status 1."""
from __future__ import annotations

import argparse
import json
import os
import secrets
import sys
from pathlib import Path

from . import __version__
from .errors import ExgenError

CLOSE_MISTAKE = "lands within"  # exgen.variant.mistakes_apart's warning, for values a user gave
CLOSE_MISTAKE_MEANS = ("a mistake that close is marked right: for these values the grader cannot tell it from "
                       "the answer; sheets never draw such values")
EXPORT_SUFFIX = {"moodle": ".xml", "qti": ".zip", "canvas": ".zip"}
SEED_MAX = 2**65 - 1  # sheets' seeds are below 2^64, practice's from 2^64 (exgen.seeds.PRACTICE_SEEDS)


def _progress(items, total, label="working"):
    from .progress import progress

    return progress(items, total, label)


def _bank(args, full: bool = True):
    """The bank; `full` False for commands that only list or draw (see exgen.bank.load_bank)."""
    from .bank import load_bank

    return load_bank([Path(p) for p in args.bank], full)


def _count(minimum: int, maximum: int | None = None):
    """An argparse type: a whole number within [minimum, maximum], else a one-line usage error."""
    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
        if value < minimum or (maximum is not None and value > maximum):
            bounds = f"from {minimum} to {maximum}" if maximum is not None else f"of at least {minimum}"
            raise argparse.ArgumentTypeError(f"{value} is out of range: give a whole number {bounds}")
        return value

    return parse


def _digits(text: str) -> str:
    if not text.isdigit():
        raise argparse.ArgumentTypeError(f"{text!r} is not a Canvas id (a number, as in the assignment's address)")
    return text


class _Parser(argparse.ArgumentParser):
    """Usage mistakes as one line (and the --help hint), like every other error of the command."""

    def error(self, message: str):
        self.exit(2, f"{self.prog}: {message} (see `{self.prog} --help`)\n")


def _secret(args, default: Path | None, create: bool) -> tuple[bytes, str]:
    """The course secret and where it came from: --secret-file, else $EXGEN_SECRET, else `default`."""
    from .seeds import ENV_VAR, load_secret

    explicit = bool(args.secret_file)
    path = Path(args.secret_file) if explicit else default
    secret, source = load_secret(path, create=create, explicit=explicit)
    if explicit and os.environ.get(ENV_VAR):
        print(f"Using the secret file {path}; ${ENV_VAR} is set but --secret-file wins.", file=sys.stderr)
    if source.endswith("(new)"):
        print(f"Created a new course secret in {path}. Keep it private: grading needs it.", file=sys.stderr)
        source = source[: -len(" (new)")]
    return secret, source


def _assignment_and_roster(args):
    """The bank, the assignment (checked against it) and the roster path (option, else the file's)."""
    from .assignment import load_assignment

    bank = _bank(args)
    assignment = load_assignment(Path(args.assignment), bank)
    roster = Path(args.roster) if args.roster else assignment.roster
    return bank, assignment, roster


def cmd_list(args) -> int:
    from .render.unicode_math import text_to_plain

    bank = _bank(args, full=False)
    rows = [t for t in bank if args.chapter is None or t.chapter == args.chapter]
    width = max((len(t.id) for t in rows), default=0)
    for t in rows:
        source = f"  [{text_to_plain(t.source)}]" if t.source else ""
        print(f"{t.id:<{width}}  {text_to_plain(t.title)}{source}")
    print(f"\n{len(rows)} template(s)", file=sys.stderr)
    return 0


def cmd_show(args) -> int:
    from .render.text import variant_text
    from .variant import make_variant

    template = _bank(args, full=False).get(args.id)
    seed = args.seed if args.seed is not None else secrets.randbits(32)
    print(variant_text(make_variant(template, seed), key=args.key))
    if args.seed is None:
        print(f"\n(seed {seed}: `exgen show {args.id} --seed {seed}` shows this variant again)", file=sys.stderr)
    return 0


def cmd_solve(args) -> int:
    from .render.unicode_math import text_to_plain
    from .solve import parse_settings, solve

    template = _bank(args).get(args.id)
    variant, warnings = solve(template, parse_settings(args.set))
    close = [w for w in warnings if CLOSE_MISTAKE in w]
    for warning in warnings:
        print(f"warning: {warning}", file=sys.stderr)
        if close and warning is close[-1]:
            print(f"  ({CLOSE_MISTAKE_MEANS})", file=sys.stderr)
    if args.json:
        print(json.dumps(solution_json(variant), indent=2, ensure_ascii=False))
        return 0
    if args.steps:
        from .render.text import variant_text

        print(variant_text(variant, key=True))
        return 0
    print(text_to_plain(template.title))
    for part_id, answer in variant.answers.items():
        print(f"  ({part_id}) {text_to_plain(variant.asks[part_id])}: {answer.text}")
    return 0


def _given_json(p) -> dict:
    """A given as printed, and in the SI unit the working uses (ω in rad/s for a speed in rpm)."""
    from .render.working import si_unit

    out = {"value": p.text, "unit": p.unit}
    if isinstance(p.si, float) and p.unit and si_unit(p.unit) not in (None, p.unit):
        out.update(si=p.si, si_unit=si_unit(p.unit))
    return out


def solution_json(variant) -> dict:
    """Every part's value and unit, and every step's: its ask as plain text (and as written, with LaTeX)."""
    from .render.unicode_math import text_to_plain

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
    from .assignment import load_roster
    from .generate import default_jobs, generate

    bank, assignment, roster_path = _assignment_and_roster(args)
    if roster_path is None:
        raise ExgenError("give the class list with --roster ROSTER.csv (or `roster:` in the assignment file)")
    students = load_roster(roster_path)
    if args.print and args.no_pdf:
        raise ExgenError("--print joins the sheets' PDFs: leave out --no-pdf")
    secret, source = _secret(args, assignment.secret_file, create=True)
    recorded = source if source.startswith("$") else str(Path(source).resolve())
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

    from .assignment import load_roster
    from .manifest import read_manifest
    from .outdir import check_target

    manifest = read_manifest(Path(args.issued))
    submissions = Path(args.submissions)
    if not submissions.is_dir():
        raise ExgenError(f"{submissions}: no such folder" if not submissions.exists() else
                         f"{submissions}: not a folder: give the folder holding the answer files")
    check_target(Path(args.out), "grade")  # before any work: a folder that cannot be replaced stops here
    bank = _bank(args)
    recorded = Path(manifest.secret_source) if manifest.secret_source and not manifest.secret_source.startswith("$") \
        else None
    secret, source = _secret(args, recorded, create=False)
    roster = load_roster(Path(args.roster)) if args.roster else None
    from .generate import default_jobs

    batch = grade_issued(manifest, bank, secret, submissions, secret_source=source, force=args.force, roster=roster,
                         progress=_progress, jobs=args.jobs or default_jobs())
    for warning in batch.warnings:
        print(f"WARNING: {warning}", file=sys.stderr)
    from graders.copying import signs_of_copying

    signs = signs_of_copying(batch, manifest.assignment, bank, secret, manifest.codes)
    paths = write_results(batch, Path(args.out), signs, canvas_id=args.canvas_id or "")
    print(batch.summary())
    for name, path in paths.items():
        print(f"{name}: {path}")
    return 0


def cmd_export(args) -> int:
    from .export import writer
    from .export.pool import build_pool, notices

    suffix = EXPORT_SUFFIX[args.format]
    if Path(args.out).suffix.lower() != suffix:  # a .zip of Moodle XML would fail at import, after all the work
        raise ExgenError(f"--out {args.out}: {args.format} writes a {suffix} file (e.g. --out pool-{args.format}{suffix})")
    bank = _bank(args)
    files = [s for s in args.sources if s.lower().endswith((".yaml", ".yml"))]
    if files and (len(files) > 1 or len(args.sources) > 1):
        raise ExgenError("give one assignment file, or template ids, not both")
    if files:
        from .assignment import load_assignment

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


def cmd_validate(args) -> int:
    from .validate import validate_bank

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
    from .assignment import load_assignment
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


def _progress_options(p) -> None:
    from practice.store import default_path

    p.add_argument("--db", default=str(default_path()), metavar="FILE",
                   help="the progress file (SQLite; where it is by default: below)")
    p.epilog = (f"Your progress is kept in:\n  {default_path()}\n(--db FILE or $EXGEN_PRACTICE_DB sets another file)"
                + (f"\n\n{p.epilog}" if p.epilog else ""))
    p.add_argument("--assignment", metavar="A.yaml",
                   help="practise only this assignment's templates (with fresh numbers, never a sheet's)")


def _examples(*commands: str) -> str:
    return ("example:\n" if len(commands) == 1 else "examples:\n") + "\n".join(f"  {c}" for c in commands)


def _command(sub, name: str, summary: str, description: str, *examples: str) -> argparse.ArgumentParser:
    """A subcommand whose --help says what it does and shows it done (its description is wrapped by hand)."""
    return sub.add_parser(name, help=summary, description=description, epilog=_examples(*examples),
                          formatter_class=argparse.RawDescriptionHelpFormatter)


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="exgen", formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Unique, gradeable Mechanics of Machines problems: a tutorial sheet, answer file and key for\n"
                    "every student, grading of the answer files handed back, practice alone, pools for Moodle,\n"
                    "QTI 2.1 and Canvas.",
        epilog=_examples("exgen generate examples/tutorial1.yaml --out out/tutorial1",
                         "exgen grade out/tutorial1 submissions/ --out graded/tutorial1")
        + "\n\n`exgen COMMAND --help` says what each command does, with an example.")
    parser.add_argument("--version", action="version", version=f"exgen {__version__}")
    parser.add_argument("--bank", action="append", default=[], metavar="DIR",
                        help="an extra folder of templates (repeatable; also $EXGEN_BANKS)")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    p = _command(sub, "list", "list the templates",
                 "List the templates (the kinds of problem), each with the textbook example or problem it follows.",
                 "exgen list --chapter 2")
    p.add_argument("--chapter", type=int, metavar="N", help="only chapter N (1-7)")
    p.set_defaults(func=cmd_list)

    p = _command(sub, "show", "draw one variant of a template and print it",
                 "Draw one variant of a template and print it as a student would see it; --key adds the answers\n"
                 "and the worked solution. The same seed always gives the same variant.",
                 "exgen show belts.flat_belt_power --seed 7 --key")
    p.add_argument("id", help="a template id, as `exgen list` prints it")
    p.add_argument("--seed", type=_count(0, SEED_MAX), help="the variant's seed, 0 to 2^65-1 (default: a fresh one)")
    p.add_argument("--key", action="store_true", help="also print the answers and worked solution")
    p.set_defaults(func=cmd_show)

    p = _command(sub, "solve", "solve a template for values you give",
                 "Solve a template for values you give, e.g. to check a textbook problem: every parameter as\n"
                 "--set NAME=VALUE, with its unit (a bare number is read in the template's unit). Run it with\n"
                 "none to be told each parameter's name, meaning and unit.",
                 "exgen solve gears.gear_pair_power --set m=4mm --set t1=20 --set t2=60 --set tau1=100N*m \\\n"
                 "      --set N1=1000rpm --set eta=96% --steps")
    p.add_argument("id", help="a template id, as `exgen list` prints it")
    p.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="a given value with its unit, e.g. --set d1=600mm (repeat for each parameter)")
    p.add_argument("--json", action="store_true", help="print every part's value and unit as JSON")
    p.add_argument("--steps", action="store_true", help="print the worked solution")
    p.set_defaults(func=cmd_solve)

    p = _command(sub, "generate", "a sheet, answer form and key for every student on a roster",
                 "Issue an assignment: for every student on the roster a tutorial sheet (PDF and Markdown, with\n"
                 "figures) and an answer file to fill in, in OUT/students/ID/, and a key with worked solutions in\n"
                 "OUT/keys/ID/; OUT/manifest.json records what was issued, for grading. The roster and the course\n"
                 "secret come from the assignment file unless given here; the first run creates the secret.",
                 "exgen generate examples/tutorial1.yaml --out out/tutorial1 --print")
    p.add_argument("assignment", help="the assignment file (YAML)")
    p.add_argument("--roster", help="class list CSV with an id column (name, email optional)")
    p.add_argument("--out", required=True, help="output folder")
    p.add_argument("--secret-file", help="course secret file (default: the assignment's secret_file, or $EXGEN_SECRET)")
    p.add_argument("--no-pdf", action="store_true", help="Markdown only (fastest)")
    p.add_argument("--no-key-pdf", action="store_true",
                   help="keys in Markdown only; sheets still get their PDF (a key's PDF takes as long as three sheets')")
    p.add_argument("--jobs", type=_count(1), help="processes making PDFs (default: one per core, up to 8)")
    p.add_argument("--print", action="store_true", help="also print/sheets.pdf, every sheet in roster order (each "
                                                        "starting on a new leaf when printed on both sides), and "
                                                        "print/keys.pdf, every key")
    p.set_defaults(func=cmd_generate)

    p = _command(sub, "grade", "grade a folder of returned answer files against what was issued",
                 "Grade the answer files students hand back, each against the sheet issued to its student (whose\n"
                 "file it is, its name or folder says). Writes gradebook.csv (and gradebooks for Canvas and\n"
                 "Moodle), feedback/ID.md for each student, report.md with every file not graded and why, and\n"
                 "the item analysis. Stops before any mark if the secret or a template changed since issue.",
                 "exgen grade out/tutorial1 submissions/ --out graded/tutorial1")
    p.add_argument("issued", help="the folder `exgen generate` wrote (its --out), or its manifest.json")
    p.add_argument("submissions", help="folder of answer files (YAML, JSON or CSV), one per student, named or "
                                       "foldered by student id as a learning system downloads them")
    p.add_argument("--out", required=True, help="output folder for the gradebook, feedback and report")
    p.add_argument("--secret-file", help="course secret file (default: $EXGEN_SECRET, else the file the sheets "
                                         "were generated with)")
    p.add_argument("--roster", help="grade only these students (a class list CSV; all must have been issued sheets)")
    p.add_argument("--jobs", type=_count(1), help="processes reading and grading a large class (default: one per "
                                                  "core, up to 8; a class under 200 is graded in one)")
    p.add_argument("--force", action="store_true",
                   help="grade even if the secret or a template differs from what was issued (warned in the report)")
    p.add_argument("--canvas-id", type=_digits, help="the Canvas assignment's id, for the Canvas gradebook's column "
                                                     "(without it, importing makes a new assignment)")
    p.set_defaults(func=cmd_grade)

    p = _command(sub, "practice", "practise alone in the terminal: a problem at a time, checked as you go",
                 "Practise alone: fresh problems from where you are weakest, each part checked\n"
                 "as you answer it. At a prompt type an answer with its unit, or h (hint),\n"
                 "s (worked solution), n (next problem), q (quit).",
                 "exgen practice --topic gears", "exgen practice --stats")
    which = p.add_mutually_exclusive_group()
    which.add_argument("--chapter", type=_count(1), help="only this chapter")
    which.add_argument("--topic", metavar="ID", help="only this topic (belts, gears, ...) or template id")
    p.add_argument("--open", action="store_true", help="open each figure in the system's viewer")
    p.add_argument("--stats", action="store_true", help="print mastery per topic and stop")
    _progress_options(p)
    p.set_defaults(func=cmd_practice)

    p = _command(sub, "serve", "practise in the browser: a local web app on this computer",
                 "Start the practice web app on this computer (nothing is fetched from the\n"
                 "internet) and print its address.",
                 "exgen serve --open", "exgen serve --assignment examples/tutorial2.yaml")
    p.add_argument("--host", default="127.0.0.1",
                   help="address to listen on (default %(default)s: only this computer can reach it)")
    p.add_argument("--port", type=_count(0, 65535), default=8000, help="port (default %(default)s; 0: any free one)")
    p.add_argument("--open", action="store_true", help="open the app in the web browser")
    _progress_options(p)
    p.set_defaults(func=cmd_serve)

    p = _command(sub, "report", "item analysis of a grading run (HTML and Markdown)",
                 "Write the item analysis of a grading run again from its results.json: item-analysis.html\n"
                 "(one self-contained page) and item-analysis.md, with the spread of marks, each part's facility\n"
                 "and discrimination, the mistakes made, and signs of copying with their evidence.",
                 "exgen report graded/tutorial1")
    p.add_argument("graded", help="the folder `exgen grade` wrote (its --out)")
    p.add_argument("--out", help="where to write the pages (default: that folder)")
    p.set_defaults(func=cmd_report)

    p = _command(sub, "export", "a pool of variants per question for a learning system (Moodle, QTI 2.1, Canvas)",
                 "Write a question pool for a learning system: each question of an assignment (or each template\n"
                 "named) drawn N times, with its tolerances, named mistakes, figures and worked solution. The\n"
                 "system gives each student one variant of each question. How to import it: docs/lms.md.",
                 "exgen export moodle examples/tutorial1.yaml --variants 50 --out tutorial1-moodle.xml",
                 "exgen export canvas examples/tutorial1.yaml --variants 50 --out tutorial1-canvas.zip")
    p.add_argument("format", choices=("moodle", "qti", "canvas"), help="moodle: Moodle XML; qti: IMS QTI 2.1 package "
                                                                      "(zip); canvas: a QTI 1.2 zip for Canvas")
    p.add_argument("sources", nargs="+", metavar="SOURCE", help="an assignment file (its questions and points), or "
                                                                "template ids")
    p.add_argument("--variants", type=_count(1, 1000), default=20, help="variants per question (default 20)")
    p.add_argument("--out", required=True, help="the file to write (.xml for moodle, .zip for qti and canvas)")
    p.add_argument("--title", help="the quiz or category title (default: the assignment's)")
    p.add_argument("--secret-file", help="course secret file (default: the assignment's secret_file, or $EXGEN_SECRET)")
    p.set_defaults(func=cmd_export)

    p = _command(sub, "validate", "draw many variants of every template and check them",
                 "Draw many variants of every template (or of those named) and check what must always hold: the\n"
                 "constraints, finite answers of the kind asked, the key grading itself at 100 %, every named\n"
                 "mistake recorded and worded. Prints, per template, how many draws were rejected and why.",
                 "exgen validate belts.flat_belt_power gears.epicyclic --seeds 500")
    p.add_argument("ids", nargs="*", metavar="ID", help="only these templates")
    p.add_argument("--seeds", type=_count(1), default=200, help="variants drawn per template (default 200)")
    p.set_defaults(func=cmd_validate)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        status = args.func(args)
        sys.stdout.flush()  # a reader that went away (`exgen list | head`) shows here, not at exit
        return status
    except BrokenPipeError:
        return _reader_gone()
    except ExgenError as exc:
        print(f"exgen: {exc}", file=sys.stderr)
        return 1
    except OSError as exc:  # a folder or file the system refuses: say which, and why
        where = f"{exc.filename}: " if exc.filename else ""
        print(f"exgen: {where}{exc.strerror or exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("exgen: interrupted", file=sys.stderr)
        return 130


def _reader_gone() -> int:
    """The program reading our output closed it: stop quietly, as `yes | head` does, with the status a
    shell gives a process that SIGPIPE ended. Output still buffered goes nowhere instead of raising again
    when the interpreter flushes it at exit."""
    try:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    except (OSError, ValueError):  # stdout is no file (captured, replaced): nothing is flushed to it at exit
        pass
    return 128 + 13  # 128 + SIGPIPE


if __name__ == "__main__":
    sys.exit(main())
