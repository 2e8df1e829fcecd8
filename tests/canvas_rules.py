"""How canvas-lms reads a question that its QTI converter wrote (tests/qti_migration.py) and marks an answer
to it: ports of the Ruby, for the QTI 2.1 that the converter makes of exgen's export.

From instructure/canvas-lms, gems/plugins/qti_exporter/lib/qti/: choice_interaction.rb (`get_answers`,
`process_response_conditions`, `get_response_weight`, `get_base_value`, `set_question_type`, commit
146bcd0d1de97dc48e773125c44c64ac60d8097d), assessment_item_converter.rb (`get_feedback_id`,
`attach_feedback_values`, `get_feedback`, commit 0e63cfcdc7dc5602956598562ffd088796e3b65d) and
numeric_interaction.rb (`get_answer_values`, `get_canvas_answers`, commit
891bca30a891d527298b90df71c19956472a2a34); marking from app/models/quizzes/quiz_question/:
numerical_question.rb (`correct_answer_parts`, BigDecimal, commit 3eb03930e1f6844b31daf258e7e9273c4dc296c2)
and multiple_choice_question.rb (`correct_answer_parts`: right when the chosen answer's weight is 100,
commit 03199fe4e5a8bb12dd7aa3a6808a5100b3014db8). Nokogiri's CSS selectors match descendants, as `iter`
does here.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from decimal import Decimal, InvalidOperation

from qti_migration import text_of

DEFAULT_CORRECT_WEIGHT, DEFAULT_INCORRECT_WEIGHT = 100, 0
#: get_feedback_id: an answer's feedback id matching this is taken for general feedback, not the answer's.
GENERAL_FEEDBACK = re.compile(r"general_|_all|wrong|incorrect|correct|(_IC$)|(_C$)", re.I)


@dataclass
class Answer:
    migration_id: str = ""
    text: str = ""
    weight: float = DEFAULT_INCORRECT_WEIGHT
    comments: str = ""
    feedback_id: str | None = None
    kind: str = ""                 # numerical: exact_answer, range_answer, precision_answer
    exact: float | None = None
    margin: float | None = None
    start: float | None = None
    end: float | None = None


@dataclass
class Question:
    answers: list = field(default_factory=list)
    import_error: str = ""
    comments: dict = field(default_factory=dict)  # question-level feedback: neutral, correct, incorrect


def _first(element, tag, **attrs):
    return next((e for e in element.iter(tag) if all(e.get(k) == v for k, v in attrs.items())), None)


def _has(element, path: str) -> bool:
    """A descendant chain "match variable[identifier=X]" (the selectors process_response_conditions tests)."""
    outer, inner = path.split(" ")
    tag, _, rest = inner.partition("[")
    name, _, value = rest.rstrip("]").partition("=")
    for node in element.iter(outer):
        for child in node.iter(tag):
            got = child.get(name, "")
            if (value.startswith("^") and got.startswith(value[1:])) or got == value:
                return True
    return False


# ---- choice questions ------------------------------------------------------------------------------

def read_choice(doc) -> Question:
    """ChoiceInteraction#parse_question_data: answers, weights from the response conditions, feedback."""
    question = Question()
    answers = {}
    for interaction in doc.iter("choiceInteraction"):  # get_answers
        for choice in interaction.iter("simpleChoice"):
            answer = Answer(migration_id=choice.get("identifier"))
            answer.text = " ".join(text_of(choice.find("div")).split()) if choice.find("div") is not None else ""
            question.answers.append(answer)
            answers[answer.migration_id] = answer
    for condition in doc.iter("responseCondition"):  # process_response_conditions
        if _has(condition, "match variable[identifier=RESP_MC]") or _has(condition, "match variable[identifier=response]"):
            migration_id = _first(_first(condition, "match"), "baseValue", baseType="identifier").text.strip()
            answer = answers.get(migration_id) or next((a for a in answers.values() if a.text == migration_id), None)
            if answer is None:  # canvas-lms would raise on nil here and record an error for the question
                question.import_error = "There was an error exporting an assessment question"
                continue
            answer.weight = response_weight(condition)
            answer.feedback_id = answer.feedback_id or feedback_id(condition)
        elif _has(condition, "member variable[identifier=RESP_MC]") or _has(condition, "match variable[identifier=^TF]"):
            raise NotImplementedError("a response condition canvas-lms reads as RESP_MC or true/false")
        else:
            for branch in (e for e in condition.iter() if e.tag in ("responseIf", "responseElseIf")):
                match = _first(branch, "match")
                value = _first(match, "baseValue", baseType="identifier") if match is not None else None
                if value is None:
                    continue
                migration_id = value.text.strip()
                answer = answers.get(migration_id) or next((a for a in answers.values() if a.text == migration_id), None)
                if answer is not None:
                    answer.weight = response_weight(branch)
                    answer.feedback_id = answer.feedback_id or feedback_id(branch)
    for correct in doc.iter("correctResponse"):
        for value in correct.iter("value"):
            if value.text in answers:
                answers[value.text].weight = DEFAULT_CORRECT_WEIGHT
    attach_feedback_values(doc, question.answers)
    if not any(a.weight and a.weight > 0 for a in question.answers):  # set_question_type
        question.import_error = "The importer couldn't determine the correct answers for this question."
    question.comments = question_feedback(doc)
    return question


def response_weight(condition) -> float:
    """get_response_weight with get_base_value: 100 when SCORE is set (or summed) to a positive value."""
    node = None
    for rule in condition.iter("setOutcomeValue"):
        if rule.get("identifier") == "SCORE":
            node = _first(rule, "baseValue")
            break
    if node is None or node.get("baseType") not in ("float", "integer", "boolean"):
        return DEFAULT_INCORRECT_WEIGHT
    text = node.text or ""
    if node.get("baseType") == "float":
        positive = re.search(r"score\.max", text, re.I) or _to_f(text) > 0
    elif node.get("baseType") == "integer":
        positive = _to_f(text) > 0
    else:
        positive = text.lower() == "true"
    return DEFAULT_CORRECT_WEIGHT if positive else DEFAULT_INCORRECT_WEIGHT


def feedback_id(condition) -> str | None:
    """get_feedback_id: the identifier a condition adds to FEEDBACK, unless it reads as general feedback."""
    rule = _first(condition, "setOutcomeValue", identifier="FEEDBACK")
    if rule is None or _first(rule, "variable", identifier="FEEDBACK") is None:
        return None
    value = _first(rule, "baseValue", baseType="identifier")
    found = value.text.strip() if value is not None else None
    return None if found is None or GENERAL_FEEDBACK.search(found) else found


def attach_feedback_values(doc, answers) -> None:
    """attach_feedback_values: each answer's feedback is the first p or div of the modalFeedback its id names."""
    by_id = {}
    for modal in doc.iter("modalFeedback"):
        node = modal.find(".//p") if modal.find(".//p") is not None else modal.find(".//div")
        if node is not None:
            by_id[modal.get("identifier")] = node
    for answer in answers:
        if answer.feedback_id in by_id:
            answer.comments = text_of(by_id[answer.feedback_id])


def question_feedback(doc) -> dict[str, str]:
    """get_feedback: modalFeedback identifiers that read as the question's own feedback (wrong, correct,
    solution, general), by the order of get_feedback's tests."""
    out = {}
    for modal in doc.iter("modalFeedback"):
        ident = modal.get("identifier") or ""
        if re.search(r"wrong|incorrect|(_IC$)", ident, re.I):
            kind = "incorrect"
        elif re.search(r"correct|(_C$)", ident, re.I):
            kind = "correct"
        elif re.search(r"solution", ident, re.I):
            kind = "example_solution"
        elif re.search(r"general_|_all", ident, re.I):
            kind = "neutral"
        else:
            continue
        out[kind] = text_of(modal.find("div")) if modal.find("div") is not None else ""
    return out


def mark_choice(question: Question, chosen: str) -> tuple[bool, str]:
    """MultipleChoiceQuestion#correct_answer_parts for the answer whose text is `chosen`: right when its
    weight is 100; and the comments Canvas shows for it."""
    answer = next((a for a in question.answers if a.text == chosen), None)
    if answer is None:
        return False, ""
    return answer.weight == 100, answer.comments


# ---- numerical questions ---------------------------------------------------------------------------

def read_numeric(doc) -> Question:
    """NumericInteraction#parse_question_data."""
    question = Question()
    answer = Answer(weight=100)  # get_answer_values: gte/lte or equal base values
    gte, lte = _under(doc, "gte"), _under(doc, "lte")
    if gte is not None and lte is not None:
        answer.kind, answer.start, answer.end = "range_answer", _to_f(gte.text), _to_f(lte.text)
        question.answers.append(answer)
    elif _under(doc, "equal") is not None:
        answer.kind, answer.exact = "exact_answer", _to_f(_under(doc, "equal").text)
        question.answers.append(answer)
    for branch in (e for e in doc.iter() if e.tag in ("responseIf", "responseElseIf")):  # get_canvas_answers
        answer = Answer(weight=100, text="answer_text", feedback_id=feedback_id(branch))
        either, both = branch.find("or"), branch.find("and")
        if either is not None:
            match = _first(either, "stringMatch")
            exact_node = _first(match, "baseValue") if match is not None else None
            if exact_node is None:
                continue
            exact = exact_node.text
            lower, upper = _custom(either, "vargt"), _custom(either, "varlte")
            if (lower is not None and upper is not None and re.sub(r"[0.]", "", lower.text).endswith("5")
                    and re.sub(r"[0.]", "", upper.text).endswith("5")):
                raise NotImplementedError("canvas-lms's precision_answer detection (vargt with varlte)")
            answer.kind, answer.exact = "exact_answer", _to_f(exact)
            if upper is not None:
                answer.margin = float(Decimal(upper.text) - Decimal(exact))
            question.answers.append(answer)
        elif both is not None:
            answer.kind = "range_answer"
            lower, upper = _custom(both, "vargte"), _custom(both, "varlte")
            answer.start = _to_f(lower.text) if lower is not None else None
            answer.end = _to_f(upper.text) if upper is not None else None
            if lower is not None or upper is not None:
                question.answers.append(answer)
    attach_feedback_values(doc, question.answers)
    return question


def mark_numeric(question: Question, typed: str) -> bool:
    """NumericalQuestion#correct_answer_parts: the typed number as a BigDecimal within some answer's
    exact ± margin (both floats written as Ruby's Float#to_s, read as BigDecimal) or its range."""
    if not typed.strip():
        return False
    try:
        number = Decimal(typed.strip())
    except InvalidOperation:
        number = Decimal("0.0")
    for answer in sorted(question.answers, key=lambda a: a.weight):
        if answer.kind == "exact_answer":
            value, margin = Decimal(repr(answer.exact)), Decimal(repr(answer.margin or 0.0))
            if value - margin <= number <= value + margin:
                return True
        elif answer.kind == "range_answer":
            low, high = sorted((Decimal(repr(answer.start)), Decimal(repr(answer.end))))
            if low <= number <= high:
                return True
    return False


def _under(doc, tag):
    """`@doc.at_css('responseCondition TAG baseValue')`."""
    for condition in doc.iter("responseCondition"):
        for node in condition.iter(tag):
            value = _first(node, "baseValue")
            if value is not None:
                return value
    return None


def _custom(element, kind):
    for node in element.iter("customOperator"):
        if node.get("class") == kind:
            return _first(node, "baseValue")
    return None


def _to_f(text) -> float:
    """Ruby's String#to_f: the leading number, 0.0 when there is none."""
    match = re.match(r"\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?", text or "")
    return float(match.group(0)) if match else 0.0
