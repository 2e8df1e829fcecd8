"""How Moodle imports a question of a Moodle XML file and marks a response to it: ports of its PHP, for
the tests.

From moodle/moodle: question/format/xml/format.php (`import_headers`, `import_numerical`,
`import_multichoice`, `import_multianswer`; Moodle 4.x's `import_multianswer` reads no `<idnumber>`,
which newer versions do) and question/format.php (`clean_question_name`);
question/type/multianswer/questiontype.php (`qtype_multianswer_extract_question` and its regular
expressions); question/type/numerical/questiontype.php (`qtype_numerical_answer_processor::apply_units`)
and question.php (`grade_response`, `get_matching_answer`, `apply_unit_penalty`,
`qtype_numerical_answer::get_tolerance_interval`, nominal tolerance, PHP's default precision of 14);
question/type/multichoice: a single-answer question scores the fraction of the answer chosen.
"""
from __future__ import annotations

import html
import re
from dataclasses import dataclass, field

#: get_tolerance_interval: pow(10, -1 * ini_get('precision')), PHP's precision being 14.
EPSILON = 10.0 ** -14

# qtype_multianswer's regular expressions. PHP's lookbehind (?<!\\|&|&amp;) has alternatives of different
# widths, which Python's re refuses: it is written as three lookbehinds, which mean the same.
FRACTION = r"=|%(-?[0-9]+(?:[.,][0-9]*)?)%"
ANSWER = r".+?(?<!\\)(?<!&)(?<!&amp;)(?=[~#}]|$)"
FEEDBACK = r".*?(?<!\\)(?=[~}]|$)"
ALTERNATIVE = f"({FRACTION})?({ANSWER})(#({FEEDBACK}))?"
NUMBER = r"-?(([0-9]+[.,]?[0-9]*|[.,][0-9]+)([eE][-+]?[0-9]+)?)"
NUMERICAL_ALTERNATIVE = re.compile(f"^({NUMBER})(:{NUMBER})?$", re.S)
TYPES = (r"(NUMERICAL|NM)|(MULTICHOICE|MC)|(MULTICHOICE_V|MCV)|(MULTICHOICE_H|MCH)|"
         r"(SHORTANSWER|SA|MW)|(SHORTANSWER_C|SAC|MWC)|"
         r"(MULTICHOICE_S|MCS)|(MULTICHOICE_VS|MCVS)|(MULTICHOICE_HS|MCHS)|"
         r"(MULTIRESPONSE|MR)|(MULTIRESPONSE_H|MRH)|(MULTIRESPONSE_S|MRS)|(MULTIRESPONSE_HS|MRHS)")
ANSWER_REGEX = re.compile(r"\{([0-9]*):(" + TYPES + "):(" + ALTERNATIVE + "(~" + ALTERNATIVE + ")*)\\}", re.S)
GROUP_NUMERICAL, GROUP_MULTICHOICE, GROUP_ALTERNATIVES = 3, 4, 16


@dataclass
class NumericalAnswer:
    answer: str
    fraction: float
    feedback: str
    tolerance: float = 0.0

    def within(self, value: float) -> bool:
        """within_tolerance with the nominal interval: answer ± (tolerance + ε·max(|tol|, |answer|, ε))."""
        if self.answer == "*":
            return True
        answer = float(self.answer)
        tolerance = abs(self.tolerance) + EPSILON * max(abs(self.tolerance), abs(answer), EPSILON)
        return answer - tolerance <= value <= answer + tolerance


@dataclass
class Numerical:
    answers: list
    units: dict = field(default_factory=dict)  # name -> multiplier, in the file's order
    unitgradingtype: int = 0
    unitpenalty: float = 0.1

    def grade(self, response: str) -> tuple[float, str]:
        """grade_response: (fraction, the feedback of the answer matched)."""
        value, unit, multiplier = apply_units(response, self.units)
        answer = self.matching(value, multiplier)
        if answer is None:
            return 0.0, ""
        fraction = answer.fraction
        if not answer.unitisright:  # apply_unit_penalty
            if self.unitgradingtype == 1:
                fraction -= self.unitpenalty * fraction
            elif self.unitgradingtype == 2:
                fraction -= self.unitpenalty
        return max(fraction, 0.0), answer.feedback

    def matching(self, value, multiplier):
        """get_matching_answer: the first answer the scaled value, else the value, is within."""
        if value is None:
            return None
        scaled = value * multiplier if multiplier is not None else value
        for answer in self.answers:
            if answer.within(scaled):
                answer.unitisright = multiplier is not None
                return answer
            if answer.within(value):
                answer.unitisright = False
                return answer
        return None


@dataclass
class Choice:
    answers: list  # (text, fraction, feedback)

    def grade(self, chosen: str) -> tuple[float, str]:
        for text, fraction, feedback in self.answers:
            if text == chosen:
                return fraction, feedback
        return 0.0, ""


@dataclass
class Imported:
    qtype: str
    name: str
    idnumber: str | None
    parts: list  # the question itself, or a cloze question's subquestions in order
    weights: list = field(default_factory=list)


def apply_units(response: str, units: dict) -> tuple[float | None, str | None, float | None]:
    """qtype_numerical_answer_processor::apply_units, units after the number, '.' as the decimal point."""
    response = response.replace(" ", "")  # "Strip spaces (which may be thousands separators)"
    response = re.sub(r"(?:e|E|(?:x|\*|×)10(?:\^|\*\*))([+-]?\d+)", r"e\1", response)
    if "." in response or response.count(",") > 1:
        response = response.replace(",", "")
    else:
        response = response.replace(",", ".")
    match = re.match(r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:e[-+]?\d+)?", response)
    if not match:
        return None, None, None
    unit = response[match.end():]
    multiplier = 1 / units[unit] if unit in units else None
    return float(match.group(0)), unit, multiplier


def clean_question_name(name: str) -> str:
    """clean_question_name: PARAM_TEXT (tags stripped), trimmed, at most 255 characters."""
    name = re.sub(r"<[^>]*>", "", name).strip()
    return name if len(name) <= 255 else name[:251] + "..."


def import_question(element, version: str = "5") -> Imported:
    """A `<question>` as format.php imports it, under Moodle `version` ("4" or "5")."""
    qtype = element.get("type")
    name = clean_question_name((element.findtext("name/text") or "").strip())
    idnumber = element.findtext("idnumber")
    if qtype == "numerical":
        answers = [NumericalAnswer((a.findtext("text") or "").strip(), float(a.get("fraction", 0)) / 100,
                                   a.findtext("feedback/text") or "", float(a.findtext("tolerance") or 0))
                   for a in element.findall("answer")]
        units = {}
        for unit in element.findall("units/unit"):
            units.setdefault((unit.findtext("unit_name") or "").strip(), float(unit.findtext("multiplier") or 1))
        part = Numerical(answers, units, int(element.findtext("unitgradingtype") or 0),
                         float(element.findtext("unitpenalty") or 0.1))
        return Imported(qtype, name, idnumber, [part])
    if qtype == "multichoice":
        answers = [(a.findtext("text") or "", float(a.get("fraction", 0)) / 100, a.findtext("feedback/text") or "")
                   for a in element.findall("answer")]
        return Imported(qtype, name, idnumber, [Choice(answers)])
    if qtype == "cloze":
        parts, weights = extract_question((element.findtext("questiontext/text") or "").strip())
        return Imported("multianswer", name, idnumber if version >= "5" else None, parts, weights)
    raise NotImplementedError(qtype)


def extract_question(text: str) -> tuple[list, list]:
    """qtype_multianswer_extract_question: each {weight:TYPE:alternatives} in order, as a subquestion."""
    parts, weights = [], []
    while True:
        found = ANSWER_REGEX.search(text)
        if not found:
            return parts, weights
        weights.append(int(found.group(1)) if found.group(1) else 1)
        numerical = bool(found.group(GROUP_NUMERICAL))
        if not numerical and not found.group(GROUP_MULTICHOICE):
            raise NotImplementedError(found.group(2))
        remaining, alternatives = found.group(GROUP_ALTERNATIVES), []
        while True:
            alt = re.search("~?" + ALTERNATIVE, remaining, re.S)
            if not alt:
                break
            fraction = 1.0 if alt.group(1) == "=" else (0.01 * float(alt.group(2).replace(",", ".")) if alt.group(2) else 0.0)
            feedback = html.unescape(alt.group(5)).replace("\\}", "}").replace("\\#", "#") if alt.group(5) is not None else ""
            answer = alt.group(3)
            number = NUMERICAL_ALTERNATIVE.search(answer) if numerical else None
            if number:
                tolerance = float(number.group(6)) if number.group(6) is not None else 0.0
                alternatives.append(NumericalAnswer(number.group(1), fraction, feedback, tolerance))
            else:
                answer = html.unescape(answer).replace("\\}", "}").replace("\\#", "#")
                alternatives.append(NumericalAnswer(answer, fraction, feedback) if numerical else (answer, fraction, feedback))
            remaining = remaining.split(alt.group(0), 1)[1]
        parts.append(Numerical(alternatives) if numerical else Choice(alternatives))
        text = text.replace(found.group(0), "{#%d}" % len(parts), 1)
