"""What can be practised: the course's chapters, their topics and templates, and a student's choice
among them (everything, a chapter, a topic or one template), limited to an assignment's templates
when an instructor hands out a practice set."""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import yaml

from exgen.errors import ExgenError
from exgen.load.template import Template

UNKNOWN_TOPIC = "{what!r} is neither a topic nor a template{within}; the topics are {topics}"
UNKNOWN_CHAPTER = "chapter {number} has no templates{within} (chapters with templates: {chapters})"
BAD_SCOPE = "cannot practise {key!r}"


@lru_cache(maxsize=1)
def chapter_titles() -> dict[int, str]:
    """The course's chapters by number, from exgen/data/chapters.yaml."""
    text = resources.files("exgen").joinpath("data/chapters.yaml").read_text("utf-8")
    return {int(k): str(v) for k, v in yaml.safe_load(text).items()}


def topic_of(template: Template) -> str:
    return template.topic or template.id.split(".")[0]


@dataclass(frozen=True)
class Chapter:
    number: int
    title: str
    topics: dict[str, tuple[Template, ...]]  # in the bank's order; empty: not in the bank yet


@dataclass(frozen=True)
class Scope:
    """`kind` is all, chapter, topic or template; `value` the chapter number, topic or template id."""

    kind: str = "all"
    value: str = ""

    @property
    def key(self) -> str:
        return self.kind if self.kind == "all" else f"{self.kind}:{self.value}"

    @classmethod
    def parse(cls, key: str) -> "Scope":
        kind, _, value = str(key).partition(":")
        if kind == "all" and not value:
            return cls()
        if kind in ("chapter", "topic", "template") and value:
            return cls(kind, value)
        raise ExgenError(BAD_SCOPE.format(key=str(key)[:60]))


class Catalogue:
    """The templates a student may practise: the bank's, or only an assignment's."""

    def __init__(self, bank, assignment=None):
        self.bank, self.assignment = bank, assignment
        if assignment is not None:
            ids = dict.fromkeys(q.template for q in assignment.questions)
            self.templates = tuple(bank.get(i) for i in ids)
        else:
            self.templates = tuple(bank)
        self.by_id = {t.id: t for t in self.templates}

    @property
    def absent(self) -> str:
        """What a chapter with no templates here is."""
        return f"not in {self.assignment.title}" if self.assignment is not None else "not in the bank yet"

    @property
    def within(self) -> str:
        return f" in {self.assignment.title}" if self.assignment is not None else ""

    def chapters(self) -> list[Chapter]:
        """The course's seven chapters (and any other a template names), each with its topics."""
        titles = chapter_titles()
        numbers = sorted(set(titles) | {t.chapter for t in self.templates})
        out = []
        for number in numbers:
            topics: dict[str, list[Template]] = {}
            for template in self.templates:
                if template.chapter == number:
                    topics.setdefault(topic_of(template), []).append(template)
            out.append(Chapter(number, titles.get(number, f"Chapter {number}"),
                               {k: tuple(v) for k, v in topics.items()}))
        return out

    def topics(self) -> list[str]:
        return list(dict.fromkeys(topic_of(t) for t in self.templates))

    def choose(self, chapter: int | None = None, topic: str | None = None) -> Scope:
        """The scope for `--chapter N` or `--topic NAME_OR_TEMPLATE_ID` (neither: everything)."""
        if chapter is not None:
            scope = Scope("chapter", str(chapter))
        elif topic:
            scope = Scope("template" if topic in self.by_id else "topic", topic)
        else:
            scope = Scope()
        self.templates_in(scope)  # raises for a scope with nothing in it
        return scope

    def templates_in(self, scope: Scope) -> tuple[Template, ...]:
        if scope.kind == "all":
            found = self.templates
        elif scope.kind == "chapter":
            found = tuple(t for t in self.templates if str(t.chapter) == scope.value)
            if not found:
                chapters = ", ".join(str(c) for c in sorted({t.chapter for t in self.templates}))
                raise ExgenError(UNKNOWN_CHAPTER.format(number=scope.value[:20], within=self.within, chapters=chapters))
        elif scope.kind == "template" and scope.value in self.by_id:
            found = (self.by_id[scope.value],)
        else:
            found = tuple(t for t in self.templates if topic_of(t) == scope.value)
        if not found:
            raise ExgenError(UNKNOWN_TOPIC.format(what=scope.value[:60], within=self.within,
                                                  topics=", ".join(self.topics())))
        return found

    def label(self, scope: Scope) -> str:
        """How a page or prompt names the scope."""
        if scope.kind == "chapter":
            number = int(scope.value)
            return f"Chapter {number}: {chapter_titles().get(number, '')}".rstrip(": ")
        if scope.kind == "topic":
            return scope.value.replace("_", " ").capitalize()
        if scope.kind == "template":
            return self.by_id[scope.value].title if scope.value in self.by_id else scope.value
        return self.assignment.title if self.assignment is not None else "All topics"
