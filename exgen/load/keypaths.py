"""A key path of a template file as its author reads it, for error messages: ("parts", 1, "tol", "rel")
is "part (b), tol.rel" (a part by its id, where it has one), list items are counted from 1."""
from __future__ import annotations

#: A list's items, as an author names them ("part (b)", "mistake 2"), and whether the list's key is said too
#: ("require, condition 1").
_ITEMS = {"parts": ("part", False), "mistakes": ("mistake", False), "hints": ("hint", False),
          "require": ("condition", True), "report": ("entry", True), "key_figures": ("figure", True)}


def key_words(keypath: tuple, data=None) -> str:
    """A key path as an author reads it: ("parts", 1, "tol", "rel") -> "part (b), tol.rel" (a part by its
    id where it has one), ("params", "N1", "step") -> "parameter N1, step"; items are counted from 1."""
    words, pending, node, i = [], [], data, 0
    while i < len(keypath):
        key = keypath[i]
        if key == "params" and not pending and i + 1 < len(keypath):
            words.append(f"parameter {keypath[i + 1]}")
            node, i = _child(_child(node, key), keypath[i + 1]), i + 2
            continue
        node = _child(node, key)
        if isinstance(key, int):
            label, said = _ITEMS.get(pending[-1] if pending else "", ("item", True))
            if pending and not said:
                pending.pop()
            if pending:
                words.append(".".join(pending))
                pending = []
            part_id = node.get("id") if label == "part" and isinstance(node, dict) else None
            words.append(f"{label} ({part_id})" if part_id else f"{label} {key + 1}")
        else:
            pending.append(str(key))
        i += 1
    if pending:
        words.append(".".join(pending))
    return ", ".join(words)


def _child(node, key):
    if isinstance(node, dict):
        return node.get(key)
    if isinstance(node, list) and isinstance(key, int) and 0 <= key < len(node):
        return node[key]
    return None
