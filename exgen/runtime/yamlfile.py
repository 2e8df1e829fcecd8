"""An instructor's YAML file (an assignment, a template), read with the caps answer files are read with,
and its mistakes said in plain words at file:line:column.

The file is read as answer files are (exgen.runtime.safefile: a regular file, at most MAX_BYTES, by a deadline),
parsed into a node tree (libyaml bounds nesting; aliases stay references), and checked before any value
is built: at most MAX_DEPTH levels and MAX_ENTRIES entries with every alias counted as the copy it
stands for (the "billion laughs" file, a few hundred bytes that expand a billion times, is refused
at once), and no key twice in one mapping (YAML would keep the last without a word). A syntax error is
explained as a lecturer would want it: an unclosed quote, a tab, a line indented differently, a colon in a
value, with where it is and what to do.
"""
from __future__ import annotations

import re
from pathlib import Path

import yaml

from ..errors import ExgenError
from .safefile import NotText, Unreadable, read_text

#: As for answer files (graders.formats): an instructor's file is a few kilobytes.
MAX_BYTES = 256 * 1024
MAX_DEPTH = 16
MAX_ENTRIES = 2000
READ_SECONDS = 2.0

_Loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


class YamlFileError(ExgenError):
    """A file that cannot be read as YAML data; names the file, the line and column, and what to do."""

    def __init__(self, path, detail: str, line: int | None = None, column: int | None = None):
        self.path, self.detail, self.line, self.column = str(path), detail, line, column
        super().__init__(f"{where(path, line, column)}: {detail}")


def where(path, line: int | None, column: int | None = None) -> str:
    """'file', 'file:12' or 'file:12:5', as editors and compilers write a place."""
    if not line:
        return str(path)
    return f"{path}:{line}:{column}" if column else f"{path}:{line}"


def read_yaml(path: Path, what: str = "the file", *, max_bytes: int = MAX_BYTES, max_entries: int = MAX_ENTRIES):
    """(node tree, data) of a YAML file, or YamlFileError. `what` names the file in messages ("an
    assignment file"); a file that grows with the class (review decisions) is read with larger caps."""
    path = Path(path)
    text = _text(path, max_bytes)
    loader = _Loader(text)
    try:
        root = loader.get_single_node()
        if root is not None:
            _check(path, root, what, max_entries)
        data = loader.construct_document(root) if root is not None else None
    except yaml.YAMLError as exc:
        raise YamlFileError(path, *_explained(exc, text, what)) from None
    finally:
        loader.dispose()
    return root, data


def _text(path: Path, max_bytes: int = MAX_BYTES) -> str:
    try:
        return read_text(path, max_bytes, READ_SECONDS)
    except NotText as exc:
        raise YamlFileError(path, f"{exc.reason}: save the file as UTF-8", exc.line, exc.column) from None
    except Unreadable as exc:
        raise YamlFileError(path, exc.reason if exc.missing else f"cannot be read: {exc.reason}") from None


def _check(path: Path, root: yaml.Node, what: str, max_entries: int = MAX_ENTRIES) -> None:
    """Depth, entries and duplicate keys, over the node tree, before any value is built. A tree without
    aliases is walked once, counting; one with aliases is measured as expanded (`_check_aliased`)."""
    seen: set[int] = set()
    stack = [(root, 1)]
    while stack:
        node, level = stack.pop()
        if id(node) in seen:  # an alias: sizes must count it as the copy it stands for
            return _check_aliased(path, root, what, max_entries)
        seen.add(id(node))
        if len(seen) > max_entries:
            raise YamlFileError(path, f"more than {max_entries:,} entries: far more than {what} holds", *_mark(node))
        if isinstance(node, yaml.MappingNode):
            _no_duplicate_keys(path, node)
        if isinstance(node, (yaml.MappingNode, yaml.SequenceNode)):
            if level > MAX_DEPTH:
                raise YamlFileError(path, f"nested more than {MAX_DEPTH} levels deep here: far deeper than {what} "
                                          "needs", *_mark(node))
            stack.extend((child, level + 1) for child in _children(node))
    return None


def _check_aliased(path: Path, root: yaml.Node, what: str, max_entries: int = MAX_ENTRIES) -> None:
    """As _check, for a tree with aliases: each node is visited once, and an alias counts its node's
    entries and depth again where it is used, so a few hundred bytes that expand a billion times are
    refused at once (and an alias inside what it names, a loop, too)."""
    sizes: dict[int, tuple[int, int]] = {}  # id(node) -> (entries, depth), once known
    open_nodes: set[int] = set()
    stack = [(root, False)]
    while stack:
        node, done = stack.pop()
        key = id(node)
        if key in sizes and not done:
            continue
        children = _children(node)
        if not done:
            if key in open_nodes:
                raise YamlFileError(path, "an alias (*name) refers to the value it is inside: a loop", *_mark(node))
            open_nodes.add(key)
            if isinstance(node, yaml.MappingNode):
                _no_duplicate_keys(path, node)
            stack.append((node, True))
            stack.extend((child, False) for child in children if id(child) not in sizes)
            continue
        open_nodes.discard(key)
        entries = 1 + sum(sizes[id(child)][0] for child in children)
        container = isinstance(node, (yaml.MappingNode, yaml.SequenceNode))
        depth = 1 + max((sizes[id(child)][1] for child in children), default=0) if container else 0
        if entries > max_entries:
            raise YamlFileError(path, f"more than {max_entries:,} entries from here down (aliases counted as the "
                                      f"copies they stand for): far more than {what} holds", *_mark(node))
        if depth > MAX_DEPTH:
            raise YamlFileError(path, f"nested more than {MAX_DEPTH} levels deep from here: far deeper than "
                                      f"{what} needs", *_mark(node))
        sizes[key] = (entries, depth)


def _children(node: yaml.Node) -> list[yaml.Node]:
    if isinstance(node, yaml.MappingNode):
        return [n for pair in node.value for n in pair]
    if isinstance(node, yaml.SequenceNode):
        return list(node.value)
    return []


def _no_duplicate_keys(path: Path, node: yaml.MappingNode) -> None:
    seen: dict[str, yaml.Node] = {}
    for key, _ in node.value:
        if not isinstance(key, yaml.ScalarNode) or key.tag == "tag:yaml.org,2002:merge":
            continue
        first = seen.setdefault(key.value, key)
        if first is not key:
            raise YamlFileError(path, f"`{_short(key.value)}:` appears twice in one place (first on line "
                                      f"{first.start_mark.line + 1}): YAML would keep only the last; keep one",
                                *_mark(key))


def _mark(node) -> tuple[int, int]:
    return node.start_mark.line + 1, node.start_mark.column + 1


def place(root, keypath: tuple) -> tuple[int | None, int | None]:
    """Line and column of the deepest key (or list item) of `keypath` found in the node tree."""
    node, found = root, (None, None)
    for key in keypath:
        if isinstance(node, yaml.MappingNode):
            match = next(((k, v) for k, v in node.value if isinstance(k, yaml.ScalarNode) and k.value == str(key)), None)
            if match is None:
                break
            found, node = _mark(match[0]), match[1]
        elif isinstance(node, yaml.SequenceNode) and isinstance(key, int) and 0 <= key < len(node.value):
            node = node.value[key]
            found = _mark(node)
        else:
            break
    return found


def _short(text: str, limit: int = 40) -> str:
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[: limit - 1] + "\u2026"


# ---- syntax errors in plain words ---------------------------------------------------------------

_QUOTE_OPENS = re.compile(r"""(?:^\s*-\s+|:\s+|^\s*)(["'])""")


def _explained(exc: yaml.YAMLError, text: str, what: str) -> tuple[str, int | None, int | None]:
    """(what is wrong and what to do, line, column) for a YAML error, in plain words. The pure-Python
    parser says more than libyaml about where a construct began, so the text is parsed again with it."""
    if not isinstance(exc, yaml.MarkedYAMLError) or _Loader is not yaml.SafeLoader:
        try:
            yaml.compose(text, Loader=yaml.SafeLoader)
        except yaml.YAMLError as again:
            exc = again
        except RecursionError:
            pass
    problem = " ".join(str(getattr(exc, "problem", None) or exc).split())
    context = " ".join(str(getattr(exc, "context", None) or "").split())
    mark = getattr(exc, "problem_mark", None)
    start = getattr(exc, "context_mark", None)
    at = (mark.line + 1, mark.column + 1) if mark is not None else (None, None)
    began = (start.line + 1, start.column + 1) if start is not None else at
    message, line, column = _plain(problem, context, at, began, what)
    quote = _unclosed_quote_before(text, line)
    if quote and "quote" not in message:  # the likelier cause, lines above where the reading failed
        return (f"not valid YAML: a quote opened here is not closed on its line, so what follows is read as "
                f"its text until line {line} fails ({message}): close the quote", *quote)
    return f"not valid YAML: {message}", line, column


def _plain(problem: str, context: str, at, began, what: str) -> tuple[str, int | None, int | None]:
    if "quoted scalar" in context and "end of stream" in problem:
        return "a quote opened here is never closed: close it where its text ends", *began
    if "'\\t'" in problem:
        return "a tab character: YAML indents with spaces only; replace the tab with spaces", *at
    found = re.search(r"found character '(.)' that cannot start any token", problem)
    if found:
        return f"a value cannot start with {found.group(1)}: put the value in quotes", *at
    if "expected <block end>" in problem:
        return (f"this line is indented differently from the lines above it (from line {began[0]}): lines of "
                "one list or mapping start in the same column", *at)
    if "mapping values are not allowed here" in problem:
        return ("a `: ` where no key can start: a value holding a colon must be in quotes "
                "(title: \"Tutorial 1: Belts\"), or this line is indented too far", *at)
    if "could not find expected ':'" in problem:
        return "this line is not `key: value` (a colon missing after the key?)", *began
    if "flow sequence" in context:
        return "a list opened with [ here is not closed with ] (or a comma is missing)", *began
    if "flow mapping" in context:
        return "a mapping opened with { here is not closed with } (or a comma is missing)", *began
    if "undefined alias" in problem:
        return "a value starting with * is read as a reference to an &anchor: put the value in quotes", *at
    if "unknown escape character" in problem:
        return ("a backslash inside \"double quotes\" starts an escape: write \\\\ for a backslash, or use "
                "'single quotes'", *at)
    if "single document" in context:
        return f"a second document starts here (---): {what} holds one", *at
    if "directive" in context:
        return "a line starting with %: put the value in quotes", *began
    if "could not determine a constructor" in problem or "tag" in problem:
        return f"a tag (!name) that {what} cannot have: write plain values", *at
    words = f"{problem} ({context})" if context else problem
    return words or "cannot be read", *at


def _unclosed_quote_before(text: str, line: int | None) -> tuple[int, int] | None:
    """The last line before `line` where a value opens a quote the line does not close."""
    if not line:
        return None
    found = None
    for number, content in enumerate(text.splitlines()[: line - 1], start=1):
        opened = _QUOTE_OPENS.search(content)
        if not opened:
            continue
        quote, rest = opened.group(1), content[opened.end():]
        closed = re.search(r'(?<!\\)"' if quote == '"' else r"'(?!')", rest.replace("''", ""))
        if not closed:
            found = (number, opened.start(1) + 1)
    return found
