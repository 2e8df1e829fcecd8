"""What Canvas's QTI 1.2 converter makes of a Canvas export, for the QTI 1.2 that exgen writes.

Canvas imports a QTI 1.2 package by running instructure/QTIMigrationTool over it (canvas-lms,
gems/plugins/qti_exporter/lib/qti/converter.rb, `run_qti_converter`, with `--ucvars`), which writes QTI
2.1; canvas-lms then reads that (tests/canvas_rules.py). This is a faithful port of the tool's steps for
the elements exgen writes, from lib/imsqtiv1.py, lib/imscp.py and lib/xmlutils.py at commit
7847455bb7fb4ca223cecf7e576ca81f7d0bda47; each function names the class or method it follows. The tool
itself is not on the package index, so the tests carry this port; `test_export_canvas_import.py` checks
the port against the tool where a checkout is named by $EXGEN_QTI_MIGRATION_TOOL.

The output is QTI 2.1 as plain (namespace-free) elements: canvas-lms reads it with CSS selectors that
ignore the default namespace.
"""
from __future__ import annotations

import html
import re
import string

from lxml import etree

Q = "{http://www.imsglobal.org/xsd/ims_qtiasiv1p2}"

# lib/xmlutils.py
NMTOKEN_CHARS = string.ascii_letters + string.digits + "_-.:"
NMSTART_CHARS = string.ascii_letters + "_"
# lib/imsqtiv1.py
RESPONSE_PREFIX, OUTCOME_PREFIX, FEEDBACK_PREFIX = "RESPONSE_", "OUTCOME_", "FEEDBACK_"
D2L_IDENTIFIER_REPLACER = re.compile(r"_(?:ans|str)$", flags=re.I)


def check_nmtoken(token: str, prefix: str) -> str:
    """QTIObjectV1.CheckNMTOKEN: an ASCII character outside NMTOKEN_CHARS becomes '-', and a token not
    starting with a letter or '_' gets `prefix` in front."""
    new = ""
    for c in token.strip():
        if c not in NMTOKEN_CHARS and ord(c) < 128:
            c = "-"
        if not new and c not in NMSTART_CHARS:
            new = prefix
        new += c
    return new


def read_identifier(value: str, prefix: str = "ID-") -> str:
    """QTIObjectV1.ReadIdentifier: CheckNMTOKEN, then every ':' and '.' becomes '_'."""
    return check_nmtoken(value.strip(), prefix).replace(":", "_").replace(".", "_")


def d2l(value: str) -> str:
    """D2L_IDENTIFIER_REPLACER, applied to response and label idents before ReadIdentifier."""
    return D2L_IDENTIFIER_REPLACER.sub("", value)


def fix_identifier(value: str) -> str:
    """imscp.CPResource.FixIdentifier: a character outside NMTOKEN_CHARS becomes '_'; 'ID_' in front of
    one not starting with a letter or '_'."""
    new = ""
    for c in value:
        if c not in NMTOKEN_CHARS:
            c = "_"
        if not new and c not in NMSTART_CHARS:
            new = "ID_"
        new += c
    return new


def item_identifier(value: str) -> str:
    """QTIItem.SetAttribute_ident: ':' becomes '-', then CPResource.SetIdentifier (FixIdentifier)."""
    return fix_identifier("-".join(value.split(":")))


def convert(questestinterop: bytes) -> list[etree._Element]:
    """Every item of a QTI 1.2 quiz as the tool writes it in QTI 2.1."""
    root = etree.fromstring(questestinterop)
    return [_item(item) for item in root.iter(f"{Q}item")]


def _sub(parent, tag: str, text: str | None = None, **attrs) -> etree._Element:
    element = etree.SubElement(parent, tag, {k.rstrip("_"): v for k, v in attrs.items()})
    if text is not None:
        element.text = text
    return element


def _item(item) -> etree._Element:
    out = etree.Element("assessmentItem", identifier=item_identifier(item.get("ident")), title=item.get("title", ""))
    meta = _sub(out, "instructureMetadata")
    for field in item.iter(f"{Q}qtimetadatafield"):  # InstructureHelperContainer: Canvas's own fields
        _sub(meta, "instructureField", name=field.findtext(f"{Q}fieldlabel"), value=field.findtext(f"{Q}fieldentry"))
    responses = {}
    body = _sub(out, "itemBody")
    for material in item.findall(f"{Q}presentation/{Q}material"):
        _sub(body, "div", _mattext(material), class_="html")
    for lid in item.iter(f"{Q}response_lid"):  # ResponseLID: a choiceInteraction of identifiers
        rid = read_identifier(d2l(lid.get("ident")), RESPONSE_PREFIX)
        responses[rid] = "identifier"
        interaction = _sub(body, "choiceInteraction", responseIdentifier=rid)
        for label in lid.iter(f"{Q}response_label"):  # ResponseLabel.SetAttribute_ident
            choice = _sub(interaction, "simpleChoice", identifier=read_identifier(d2l(label.get("ident")), RESPONSE_PREFIX))
            _sub(choice, "div", _mattext(label.find(f"{Q}material")), class_="html")
    for text in item.iter(f"{Q}response_str"):  # ResponseStr with render_fib: "assuming string"
        rid = read_identifier(d2l(text.get("ident")), RESPONSE_PREFIX)
        responses[rid] = "string"
        _sub(body, "extendedTextInteraction", responseIdentifier=rid)
    for rid, base in responses.items():
        out.insert(1, etree.Element("responseDeclaration", identifier=rid, cardinality="single", baseType=base))
    processing = _sub(out, "responseProcessing")
    _conditions(item, processing, responses)
    for feedback in item.findall(f"{Q}itemfeedback"):  # ItemFeedback.SetAttribute_ident
        modal = _sub(out, "modalFeedback", outcomeIdentifier="FEEDBACK", showHide="show",
                     identifier=read_identifier(feedback.get("ident"), FEEDBACK_PREFIX))
        _sub(modal, "div", _mattext(feedback.find(f".//{Q}material")), class_="html")
    return out


def _mattext(material) -> str:
    return "".join(m.text or "" for m in material.iter(f"{Q}mattext")) if material is not None else ""


def _conditions(item, processing, responses) -> None:
    """ResProcessing.AddRespCondition: a condition with continue="Yes" stands alone (in the else of the
    chain before it, if that chain did not continue); one with continue="No" opens a chain that the next
    continue="No" condition extends as a responseElseIf."""
    add_point, continuing = processing, True
    for condition in item.iter(f"{Q}respcondition"):
        flag = condition.get("continue", "No").lower() == "yes"
        expression = _expression(condition.find(f"{Q}conditionvar")[0], responses)
        rules = _rules(condition)
        if flag or continuing:
            wrapper = etree.Element("responseCondition")
            branch = _sub(wrapper, "responseIf")
            if flag and not continuing:
                add_point = _else(add_point)
            add_point.append(wrapper)
            if not flag:
                add_point = wrapper
        else:
            branch = etree.Element("responseElseIf")
            else_ = add_point.find("responseElse")
            (add_point.insert(add_point.index(else_), branch) if else_ is not None else add_point.append(branch))
        branch.append(expression)
        for rule in rules:
            branch.append(rule)
        continuing = flag
    # QTIItem.CloseObject: a decvar's maxvalue (minvalue 0 is falsy, so none for it) becomes a clamp
    for decvar in item.iter(f"{Q}decvar"):
        if float(decvar.get("maxvalue") or 0):
            clamp = _sub(_sub(processing, "responseCondition"), "responseIf")
            gt = _sub(clamp, "gt")
            _sub(gt, "variable", identifier="SCORE")
            _sub(gt, "baseValue", str(float(decvar.get("maxvalue"))), baseType="float")
            _sub(_sub(clamp, "setOutcomeValue", identifier="SCORE"), "baseValue", str(float(decvar.get("maxvalue"))),
                 baseType="float")


def _else(condition):
    found = condition.find("responseElse")
    return found if found is not None else _sub(condition, "responseElse")


def _expression(element, responses) -> etree._Element:
    """ConditionVar's operators: OtherOperatorV1, AndOperatorV1, OrOperatorV1, VarEqual, VarGTE, VarLTE."""
    tag = etree.QName(element).localname
    if tag == "other":
        return _value("boolean", "true")
    if tag in ("and", "or"):
        out = etree.Element(tag)
        for child in element:
            out.append(_expression(child, responses))
        return out
    rid = read_identifier(d2l(element.get("respident")), RESPONSE_PREFIX)  # VarThing.SetAttribute_respident
    base = responses[rid]
    value = element.text or ""
    if base == "identifier":
        value = check_nmtoken(value, RESPONSE_PREFIX)  # VarThing.MakeSingleValue: CheckNMTOKEN only
    if tag == "varequal":
        out = etree.Element("match" if base == "identifier" else "stringMatch")
        if base == "string":
            out.set("caseSensitive", "false")
            out.set("substring", "false")
    else:  # vargte, varlte on a string: "not supported on String in QTI v2"
        out = etree.Element("customOperator", {"class": tag})
    _sub(out, "variable", identifier=rid)
    out.append(_value(base, value, identifier=rid))
    return out


def _value(base: str, text: str, **attrs) -> etree._Element:
    element = etree.Element("baseValue", baseType=base, **attrs)
    element.text = text
    return element


def _rules(condition) -> list[etree._Element]:
    """SetVar (action Set) and DisplayFeedback (SetAttribute_linkrefid: ReadIdentifier)."""
    rules = []
    for setvar in condition.findall(f"{Q}setvar"):
        rule = etree.Element("setOutcomeValue", identifier=read_identifier(setvar.get("varname", "SCORE"), OUTCOME_PREFIX).upper())
        rule.append(_value("float", setvar.text or ""))
        rules.append(rule)
    for shown in condition.findall(f"{Q}displayfeedback"):
        rule = etree.Element("setOutcomeValue", identifier="FEEDBACK")
        multiple = _sub(rule, "multiple")
        _sub(multiple, "variable", identifier="FEEDBACK")
        multiple.append(_value("identifier", read_identifier(shown.get("linkrefid"), FEEDBACK_PREFIX)))
        rules.append(rule)
    return rules


def strip_namespaces(element) -> etree._Element:
    """A QTI 2.1 document as the tool writes it, namespaces dropped, to read as the port's output is."""
    for node in element.iter():
        if isinstance(node.tag, str):
            node.tag = etree.QName(node).localname
    etree.cleanup_namespaces(element)
    return element


def text_of(div) -> str:
    """The HTML a `<div class="html">` carries, as text (the tool escapes it; canvas-lms reads it back)."""
    return html_text(div.text or "")


def html_text(markup: str) -> str:
    """HTML as the text it shows."""
    return html.unescape(re.sub(r"<[^>]+>", "", str(markup)))
