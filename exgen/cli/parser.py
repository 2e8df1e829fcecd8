"""The `exgen` command line: every command with what it does, its arguments and an example."""
from __future__ import annotations

import argparse

from .. import __version__
from .commands import (SEED_MAX, cmd_decide, cmd_export, cmd_generate, cmd_grade, cmd_list, cmd_practice,
                       cmd_report, cmd_review, cmd_serve, cmd_show, cmd_solve, cmd_validate)


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


def _points(text: str) -> float:
    """An argparse type: a finite number of points, 0 or more."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of points") from None
    if not (value >= 0 and value != float("inf")):
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of points, 0 or more")
    return value


def _digits(text: str) -> str:
    if not text.isdigit():
        raise argparse.ArgumentTypeError(f"{text!r} is not a Canvas id (a number, as in the assignment's address)")
    return text


class _Parser(argparse.ArgumentParser):
    """Usage mistakes as one line (and the --help hint), like every other error of the command."""

    def error(self, message: str):
        self.exit(2, f"{self.prog}: {message} (see `{self.prog} --help`)\n")


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
    p.add_argument("--figures", metavar="DIR", help="also write its figures (the sheet's, and with --key the key's) "
                                                    "into DIR as SVG files, to look at while writing one")
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
    p.add_argument("--accept-limits", action="store_true",
                   help="grade even if walking the submissions folder reached a limit (tens of thousands of files "
                        "in no student's place, folders hundreds of levels down), past which a student's file could "
                        "be missed; report.md lists what was not looked at. Without it such a run writes nothing "
                        "and exits with status 1")
    p.add_argument("--canvas-id", type=_digits, help="the Canvas assignment's id, for the Canvas gradebook's column "
                                                     "(without it, importing makes a new assignment)")
    p.add_argument("--decisions", metavar="FILE", help="the review decisions to apply (default: OUT.decisions.yaml "
                                                       "beside the output folder, if there is one; `exgen decide` "
                                                       "writes it)")
    p.set_defaults(func=cmd_grade)

    p = _command(sub, "decide", "write a review decision: accept a spelling for everyone, or one student's answer",
                 "Write a review decision into the decisions file beside a graded folder (GRADED.decisions.yaml),\n"
                 "which `exgen grade` applies on every run: a spelling accepted for everyone on one part (read as\n"
                 "one of the part's choices, then graded against each student's own key), or one student's answer\n"
                 "accepted (full marks, or --points) or rejected, for the text they gave only. Checked against the\n"
                 "graded run first; nothing is written if the part, the choice or the student is not there.",
                 "exgen decide graded/tutorial5 --accept-spelling raises --question 2 --part b \\\n"
                 "      --means \"raises the bow\" --reviewer \"A. Lecturer\" --reason \"the wording invites it\"",
                 "exgen decide graded/tutorial5 --accept A21001 --question 2 --part a --points 0.5 \\\n"
                 "      --comment \"the sense is asked in (b)\" --reviewer \"A. Lecturer\" --reason \"value right\"")
    p.add_argument("graded", help="the folder `exgen grade` wrote (its --out)")
    which = p.add_mutually_exclusive_group(required=True)
    which.add_argument("--accept-spelling", metavar="TEXT", help="accept this spelling for everyone (with --means)")
    which.add_argument("--accept", metavar="STUDENT", help="accept this student's answer as graded")
    which.add_argument("--reject", metavar="STUDENT", help="reject this student's answer as graded (0 points)")
    which.add_argument("--withdraw", metavar="STUDENT", help="take back the decision on this student's part")
    which.add_argument("--withdraw-spelling", metavar="TEXT", help="take back the spelling accepted for the part")
    p.add_argument("--question", type=_count(1, 1000), required=True, metavar="N",
                   help="the question's number, as on the sheet")
    p.add_argument("--part", required=True, help="the part's letter (a, b, ...)")
    p.add_argument("--means", metavar="TEXT", help="what the spelling is read as: one of the part's choices, or "
                                                   "an answer the part reads")
    p.add_argument("--points", type=_points, metavar="X", help="with --accept: the points given (default: the "
                                                             "part's full marks)")
    p.add_argument("--comment", default="", help="what the student reads on their feedback: \"marked by hand: "
                                                 "COMMENT\"")
    p.add_argument("--reviewer", metavar="NAME", help="who decided (required but to withdraw)")
    p.add_argument("--reason", metavar="TEXT", help="why, for the record and the report (required but to withdraw)")
    p.add_argument("--decisions", metavar="FILE", help="the decisions file (default: GRADED.decisions.yaml "
                                                       "beside the folder)")
    p.set_defaults(func=cmd_decide)

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

    p = _command(sub, "review", "decide in the browser what grading could not: format problems, blanks, copying",
                 "Open a page on this computer listing every answer of a grading run that needs a human: each\n"
                 "format problem, each blank on a sheet whose other parts were answered, each part a sign of\n"
                 "copying rests on; the same text typed by many students stands as one row. Accept it (full or\n"
                 "part marks), reject it with a comment, or accept its spelling for everyone; each decision, with\n"
                 "the reviewer's name and a reason, goes to the decisions file, which `exgen grade` applies when\n"
                 "run again.",
                 "exgen review graded/tutorial1 --open", "exgen review graded/tutorial1 --reviewer \"A. Lecturer\"")
    p.add_argument("graded", help="the folder `exgen grade` wrote (its --out)")
    p.add_argument("--decisions", metavar="FILE", help="the decisions file (default: GRADED.decisions.yaml, beside "
                                                       "the folder; created at the first decision)")
    p.add_argument("--reviewer", default="", help="the name each decision is signed with (it can be changed on the page)")
    p.add_argument("--host", default="127.0.0.1", help="loopback address to listen on (default %(default)s; the page "
                                                       "never listens where another computer can reach it)")
    p.add_argument("--port", type=_count(0, 65535), default=8001, help="port (default %(default)s; 0: any free one)")
    p.add_argument("--open", action="store_true", help="open the page in the web browser")
    p.set_defaults(func=cmd_review)

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
