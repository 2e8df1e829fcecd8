"""A corpus of hostile answers and answer files, for tests and benchmarks.

`strings.json` holds short hostile answers (code, injections, unicode look-alikes and invisible marks,
huge exponents, broken formulas); `files/` holds small hostile answer files (YAML tags and bombs, deep
nesting, other encodings, binaries under an answer file's name). What would be too big to keep in the
repository (megabyte answers, files at the 256 KiB limit) is made by `long_strings()` and `big_files()`.
"""
from __future__ import annotations

import json
from functools import lru_cache
from pathlib import Path

HERE = Path(__file__).parent
LIMIT = 256 * 1024


def strings() -> list[str]:
    return json.loads((HERE / "strings.json").read_text(encoding="ascii")) + long_strings()


def long_strings() -> list[str]:
    return ["x" * 10_000, "9" * 1_000_000, " " * 200_000, "5" + " " * 200_000 + "N", "\u202e" * 100_000,
            "(" * 100_000, "sqrt(" * 50_000, "Z" + "\u0301" * 100_000, "5 at " + "9" * 200_000]


@lru_cache(maxsize=1)
def files() -> dict[str, bytes]:
    """Every hostile file by name: the stored ones and the generated ones."""
    stored = {p.name: p.read_bytes() for p in sorted((HERE / "files").iterdir()) if p.is_file()}
    return {**stored, **big_files()}


def _fill(line, head: str = "", tail: str = "", size: int = LIMIT - 64) -> str:
    parts, total, i = [head], len(head) + len(tail), 0
    while True:
        piece = line(i)
        if total + len(piece.encode()) > size:
            break
        parts.append(piece)
        total += len(piece.encode())
        i += 1
    return "".join(parts) + tail


def big_files() -> dict[str, bytes]:
    """Files just under the size limit, each built to cost a reader as much as possible."""
    texts = {
        "big_many_keys.yaml": _fill(lambda i: f"    k{i}: \"1\"\n", "answers:\n  q1:\n"),
        "big_flow_list.yaml": _fill(lambda i: "1,", "answers: [", "1]\n"),
        "big_flow_maps.yaml": _fill(lambda i: "{a: 1},", "answers: [", "{}]\n"),
        "big_block_list.yaml": _fill(lambda i: "  - x\n", "answers:\n"),
        "big_anchors.yaml": _fill(lambda i: f"  k{i}: &a{i} x\n", "answers:\n"),
        "big_scalar.yaml": _fill(lambda i: "9", "answers:\n  q1:\n    a: \"", "\"\n"),
        "big_spaces.yaml": _fill(lambda i: " ", "answers:\n  q1:\n    a: \"5", "N\"\n"),
        "big_comment.yaml": _fill(lambda i: "#" * 80 + "\n", "answers: {q1: {a: 5 N}}\n"),
        "big_folded.yaml": _fill(lambda i: "    9 9 9 9 9 9 9 9\n", "answers:\n  q1:\n    a: >\n"),
        "big_keys.json": _fill(lambda i: f'"k{i}": "1",', '{"answers": {', '"z": "1"}}'),
        "big_long_key.json": _fill(lambda i: "k", '{"answers": {"', '": {"a": "1"}}}'),
        "big_strings.json": _fill(lambda i: '"\\u202e\\u0000",', '{"answers": {"q1": [', '""]}}'),
        "big_rows.csv": _fill(lambda i: f"q{i % 50},a{i},1\n"),
        "big_junk_rows.csv": _fill(lambda i: "junk\n"),
        "big_quoted_field.csv": _fill(lambda i: "\"\"", "q1,a,\"", "\"\n"),
    }
    return {name: text.encode("utf-8") for name, text in texts.items()}
