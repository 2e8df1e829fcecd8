"""Turn one template file's parsed YAML into a Template, collecting every problem with its line.

Each key is checked where it is read (its type, its names, its references to the solver and figures), so
an author sees every mistake of a file in one pass; `exgen.load.bank` finds the files and gathers the errors.
"""
from __future__ import annotations

from decimal import Decimal, InvalidOperation
from functools import partial
from pathlib import Path

from ..answertypes import answer_type, names as answer_type_names
from ..errors import TemplateError
from ..runtime.yamlfile import place
from . import expr, references
from .domains import domain_of, drawn_values, parse_domain
from .keypaths import key_words
from .template import MistakeSpec, ParamSpec, PartSpec, ReportSpec, Template
from .text import STEPS, undeclared_names

TEMPLATE_KEYS = {"id", "title", "chapter", "section", "topic", "source", "params", "require",
                 "solver", "statement", "parts", "figure", "key_figures", "report"}
PARAM_KEYS = {"unit", "label", "symbol", "min", "max", "step", "choices", "value", "equals", "domain", "given",
              "also_solves"}
REPORT_KEYS = {"what", "value", "unit", "range"}
PART_KEYS = {"id", "ask", "answer", "unit", "type", "tol", "points", "mistakes", "uses", "hints"}  # and the type's own
MAX_VALUES = 100_000



def _is_text(spec: ParamSpec) -> bool:
    return bool(spec.choices) and all(isinstance(c, str) for c in spec.choices)


class TemplateReader:
    """Turns parsed YAML into a Template, collecting errors with their lines."""

    def __init__(self, path: Path, root, full: bool = True, data=None, bank_dir: Path | None = None):
        self.path, self.root, self.errors, self.full, self.data = path, root, [], full, data
        self.bank_dir = bank_dir or path.parent

    def error(self, keypath: tuple, message: str) -> None:
        key = ".".join(str(k) for k in keypath)
        line, column = place(self.root, keypath)
        self.errors.append(TemplateError(self.path, key, message, line, column, key_words(keypath, self.data)))

    def error_below(self, keypath: tuple, keys: tuple, message: str) -> None:
        self.error(keypath + keys, message)

    def unknown_keys(self, mapping: dict, allowed: set, keypath: tuple) -> None:
        for key in mapping:
            if key not in allowed:
                self.error(keypath + (key,), f"unknown key; expected one of {', '.join(sorted(allowed))}")

    def template(self, data, digest: str) -> Template | None:
        if not isinstance(data, dict):
            self.error((), "a template file must be a mapping of keys (id, title, params, parts, ...)")
            return None
        self.unknown_keys(data, TEMPLATE_KEYS, ())
        for key in ("id", "title", "solver", "statement", "parts"):
            if not data.get(key):
                self.error((key,), "is required")
        params = self.params(data.get("params") or {})
        names = {p.name for p in params}
        require = self.require(data.get("require") or [], names)
        solver = self.reference(data.get("solver"), "solvers", ("solver",))
        figure = self.reference(data.get("figure"), "figures", ("figure",)) if data.get("figure") else None
        key_figures = self.key_figures(data.get("key_figures"))
        statement = str(data.get("statement") or "")
        self.check_text(statement, names, ("statement",))
        parts = self.parts(data.get("parts") or [], names)
        chapter = data.get("chapter", 0)
        if not isinstance(chapter, int):
            self.error(("chapter",), "must be a whole number")
        return Template(
            id=str(data.get("id", "")), title=str(data.get("title", "")), chapter=chapter if isinstance(chapter, int) else 0,
            section=str(data.get("section", "")), params=params, require=require, solver=solver or "",
            statement=statement, parts=parts, figure=figure, key_figures=key_figures,
            source=str(data.get("source", "")),
            topic=str(data.get("topic", "")), path=self.path, bank_dir=self.bank_dir, digest=digest,
            report=self.report(data.get("report") or []),
        )

    def params(self, data) -> tuple[ParamSpec, ...]:
        if not isinstance(data, dict):
            self.error(("params",), "must be a mapping of parameter names to specs")
            return ()
        out = []
        for name, spec in data.items():
            where = ("params", name)
            if not str(name).isidentifier():
                self.error(where, "a parameter name must be a plain identifier (letters, digits, _)")
                continue
            if name == STEPS:
                self.error(where, f"{STEPS!r} is the name under which feedback and hints read the solver's "
                                  "steps: name the parameter otherwise")
                continue
            if not isinstance(spec, dict):
                self.error(where, "must be a mapping such as {min: 1, max: 5, step: 0.5, unit: m}")
                continue
            self.unknown_keys(spec, PARAM_KEYS, where)
            given = spec.get("given", True)
            if not isinstance(given, bool):
                self.error(where + ("given",), "must be true or false (false: only what the figure draws)")
                given = True
            common = dict(name=name, unit=str(spec.get("unit", "")), label=str(spec.get("label", "")),
                          symbol=str(spec.get("symbol", "")), domain=self.domain(spec.get("domain"), where),
                          given=given)
            if "equals" in spec:
                formula = self.derived(spec["equals"], {p.name for p in out if not _is_text(p)}, where + ("equals",))
                if formula:
                    out.append(ParamSpec(**common, equals=formula))
            elif "value" in spec:
                out.append(ParamSpec(**common, choices=(self.number_or_text(spec["value"]),)))
            elif "choices" in spec:
                choices = spec["choices"]
                if not isinstance(choices, list) or not choices:
                    self.error(where + ("choices",), "must be a non-empty list")
                    continue
                words = tuple(self.number_or_text(c) for c in choices)
                out.append(ParamSpec(**common, choices=words, also_solves=self.also_solves(spec, words, where)))
            else:
                bounds = [self.decimal(spec.get(k), where + (k,)) for k in ("min", "max", "step")]
                if None in bounds:
                    continue
                low, high, step = bounds
                if step <= 0 or high < low:
                    self.error(where, "needs min <= max and step > 0")
                    continue
                count = (high - low) / step
                if count != count.to_integral_value():
                    self.error(where + ("step",), f"(max - min) = {high - low} is not a whole number of steps of {step}")
                    continue
                if count + 1 > MAX_VALUES:
                    self.error(where, f"more than {MAX_VALUES} values; use a coarser step")
                    continue
                out.append(ParamSpec(**common, min=low, max=high, step=step))
        for spec in out:  # what a template draws must make physical sense
            outside = [v for v in drawn_values(spec) if v not in domain_of(spec)]
            if outside:
                self.error(("params", spec.name), f"draws {outside[0]:g}, outside its domain "
                                                  f"{domain_of(spec).text()} (give `domain:` if that is wrong)")
        return tuple(out)

    def also_solves(self, spec, words, where) -> tuple:
        """`also_solves:` words `exgen solve` accepts beside a word parameter's choices (never drawn)."""
        extra = spec.get("also_solves")
        if extra is None:
            return ()
        if not all(isinstance(c, str) for c in words):
            self.error(where + ("also_solves",), "only a parameter whose choices are words takes `also_solves:`")
            return ()
        if not isinstance(extra, list) or not extra or not all(isinstance(c, str) for c in extra):
            self.error(where + ("also_solves",), "must be a non-empty list of words, such as [1-6-3-2-5-4]")
            return ()
        return tuple(extra)

    def domain(self, text, where) -> str:
        """A declared `domain:` interval, checked now so a typo names its file and line."""
        if text is None:
            return ""
        try:
            parse_domain(str(text))
        except ValueError as exc:
            self.error(where + ("domain",), str(exc))
            return ""
        return str(text)

    def derived(self, formula, earlier: set, where) -> str:
        """An `equals:` expression over earlier numeric parameters (checked, not yet evaluated)."""
        try:
            unknown = expr.names_in(expr.parse(str(formula))) - earlier
        except expr.ExpressionError as exc:
            self.error(where, str(exc))
            return ""
        if unknown:
            self.error(where, f"names no earlier numeric parameter: {', '.join(sorted(unknown))}")
            return ""
        return str(formula)

    @staticmethod
    def number_or_text(value):
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            return str(value)
        return Decimal(str(value))

    def decimal(self, value, where) -> Decimal | None:
        if value is None:
            self.error(where, "is required (or give `choices:` or `value:`)")
            return None
        try:
            if isinstance(value, bool):
                raise InvalidOperation
            return Decimal(str(value))
        except InvalidOperation:
            self.error(where, f"{value!r} is not a number")
            return None

    def require(self, data, names: set) -> tuple[str, ...]:
        if not isinstance(data, list):
            self.error(("require",), "must be a list of conditions such as \"d2 > d1\"")
            return ()
        for i, condition in enumerate(data):
            try:
                unknown = expr.names_in(expr.parse(str(condition))) - names
            except expr.ExpressionError as exc:
                self.error(("require", i), str(exc))
                continue
            if unknown:
                self.error(("require", i), f"names no parameter: {', '.join(sorted(unknown))}")
        return tuple(str(c) for c in data)

    def key_figures(self, data) -> tuple[str, ...]:
        """`key_figures:` a list of figure functions ('polygons:two_plane_polygons') only the key shows."""
        if data is None:
            return ()
        if not isinstance(data, list):
            self.error(("key_figures",), "must be a list such as [polygons:two_plane_polygons]")
            return ()
        refs = [self.reference(ref, "figures", ("key_figures", i)) for i, ref in enumerate(data)]
        return tuple(ref for ref in refs if ref)

    def report(self, data) -> tuple[ReportSpec, ...]:
        """`report:` entries: {what: belt density, value: m / A, unit: kg/m^3, range: [1000, 1500]}.
        Names in `value` are parameters or solver steps; steps are known only once the solver runs,
        so a wrong name is reported by `exgen validate`."""
        from .. import units
        from ..errors import QuantityError

        if not isinstance(data, list):
            self.error(("report",), "must be a list of {what, value, unit, range}")
            return ()
        out = []
        for i, item in enumerate(data):
            where = ("report", i)
            if not isinstance(item, dict):
                self.error(where, "must be a mapping such as {what: belt density, value: m / A, unit: kg/m^3, range: [1000, 1500]}")
                continue
            self.unknown_keys(item, REPORT_KEYS, where)
            missing = [k for k in ("what", "value", "range") if item.get(k) in (None, "")]
            for key in missing:
                self.error(where + (key,), "is required")
            if missing:
                continue
            try:
                expr.parse(str(item["value"]))
            except expr.ExpressionError as exc:
                self.error(where + ("value",), str(exc))
                continue
            unit = str(item.get("unit", ""))
            try:
                if self.full:
                    units.unit_info(unit)
            except QuantityError as exc:
                self.error(where + ("unit",), str(exc))
                continue
            bounds = item["range"]
            if (not isinstance(bounds, list) or len(bounds) != 2
                    or not all(isinstance(b, (int, float)) and not isinstance(b, bool) for b in bounds)
                    or bounds[0] >= bounds[1]):
                self.error(where + ("range",), "must be [low, high] with low < high, in the unit given")
                continue
            out.append(ReportSpec(str(item["what"]), str(item["value"]), unit, float(bounds[0]), float(bounds[1])))
        return tuple(out)

    def reference(self, ref, kind: str, where) -> str | None:
        """'belts:flat_belt_power' (exgen.<kind>.belts) or './cam.py:rise' (a file of the bank), checked;
        `full` also imports it and checks its function (exgen.load.references)."""
        if ref is None:
            return None
        try:
            return references.check(str(ref), kind, self.path, self.bank_dir, self.full)
        except ValueError as exc:
            self.error(where, str(exc))
            return None

    def check_text(self, text: str, names: set, where) -> None:
        if not self.full:
            return
        try:
            unknown = undeclared_names(text) - names
        except ValueError as exc:
            self.error(where, str(exc))
            return
        if unknown:
            self.error(where, f"refers to unknown parameter(s): {', '.join(sorted(unknown))}")

    def parts(self, data, names: set) -> tuple[PartSpec, ...]:
        if not isinstance(data, list):
            self.error(("parts",), "must be a list of parts")
            return ()
        out, seen = [], []
        for i, spec in enumerate(data):
            where = ("parts", i)
            if not isinstance(spec, dict):
                self.error(where, "must be a mapping with id, ask and answer")
                continue
            kind = spec.get("type", "number")
            if kind not in answer_type_names():
                self.error(where + ("type",), f"{kind!r} is not one of {', '.join(answer_type_names())}")
                kind = "number"
            answers = answer_type(kind)
            self.unknown_keys(spec, PART_KEYS | set(answers.part_keys), where)
            part_id = str(spec.get("id", ""))
            for key in ("id", "ask", "answer"):
                if not spec.get(key):
                    self.error(where + (key,), "is required")
            if part_id in seen:
                self.error(where + ("id",), f"part {part_id!r} appears twice")
            uses = tuple(str(u) for u in spec.get("uses") or ())
            for used in uses:
                if used not in seen:
                    self.error(where + ("uses",), f"{used!r} is not an earlier part")
            report = partial(self.error_below, where)
            options = answers.load_options(spec, report)
            tol = answers.load_tolerance(spec.get("tol"), report)
            self.check_text(str(spec.get("ask", "")), names, where + ("ask",))
            points = spec.get("points", 1)
            if isinstance(points, bool) or not isinstance(points, (int, float)) or points <= 0:
                self.error(where + ("points",), "must be a positive number")
                points = 1
            out.append(PartSpec(
                id=part_id, ask=str(spec.get("ask", "")), answer=str(spec.get("answer", "")),
                unit=str(spec.get("unit", "")), type=kind, tol=tol, points=float(points),
                mistakes=self.mistakes(spec.get("mistakes"), names, where), uses=uses, options=options,
                hints=self.hints(spec.get("hints"), names, where),
            ))
            seen.append(part_id)
        return tuple(out)

    def hints(self, data, names: set, where) -> tuple[str, ...]:
        """`hints:` a list of texts, first to last (they may name parameters, as an ask does)."""
        if data is None:
            return ()
        if not isinstance(data, list) or not all(isinstance(h, str) and h.strip() for h in data):
            self.error(where + ("hints",), "must be a list of hint texts, first to last")
            return ()
        for j, hint in enumerate(data):
            self.check_text(hint, names | {STEPS}, where + ("hints", j))
        return tuple(h.strip() for h in data)

    def mistakes(self, data, names: set, where) -> tuple[MistakeSpec, ...]:
        """`mistakes:` each {when: name, say: text}; a `say:` may name parameters and the solver's word steps
        (`{{ steps.name }}`), as a hint may."""
        if data is None:
            return ()
        if not isinstance(data, list):
            self.error(where + ("mistakes",), "must be a list of {when: name, say: text}")
            return ()
        out = []
        for j, item in enumerate(data):
            if not isinstance(item, dict) or not item.get("when"):
                self.error(where + ("mistakes", j), "needs `when:` naming a mistake value the solver records")
                continue
            self.unknown_keys(item, {"when", "say"}, where + ("mistakes", j))
            if item.get("say"):
                self.check_text(str(item["say"]), names | {STEPS}, where + ("mistakes", j, "say"))
            out.append(MistakeSpec(str(item["when"]), str(item.get("say", ""))))
        return tuple(out)
