"""LaTeX math -> plain Unicode for the terminal and plain files: θ = π − 2α, T₁/T₂ = e^(μθ), sin⁻¹((r₂ − r₁)/X);
text with $...$ math spans -> the same text with its math so written (text_to_plain).

Covers what templates and solvers write (fractions, roots, sub- and superscripts, Greek, integrals,
accents, \\mathrm, \\text, \\operatorname, \\left/\\right, spacing). A fraction's denominator that is
more than one factor is bracketed, a/(2π), and so is a fraction a factor follows, (1/2)mv²: plain text
has no bar to show where a fraction ends. An unknown command keeps its backslash, so that a gap in
this table shows (and a test over every template's text finds it) instead of passing as a word.
"""
from __future__ import annotations

import re
import unicodedata
from functools import lru_cache

GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "varepsilon": "ε", "zeta": "ζ",
    "eta": "η", "theta": "θ", "vartheta": "ϑ", "iota": "ι", "kappa": "κ", "lambda": "λ", "mu": "μ", "nu": "ν",
    "xi": "ξ", "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ", "upsilon": "υ", "phi": "φ", "varphi": "φ",
    "chi": "χ", "psi": "ψ", "omega": "ω", "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ", "Xi": "Ξ",
    "Pi": "Π", "Sigma": "Σ", "Phi": "Φ", "Psi": "Ψ", "Omega": "Ω",
}
SYMBOLS = {
    "times": "×", "cdot": "·", "pm": "±", "mp": "∓", "le": "≤", "leq": "≤", "ge": "≥", "geq": "≥", "ne": "≠",
    "neq": "≠", "approx": "≈", "infty": "∞", "circ": "°", "degree": "°", "to": "→", "rightarrow": "→",
    "lceil": "⌈", "rceil": "⌉", "lfloor": "⌊", "rfloor": "⌋", "%": "%", "$": "$", "{": "{", "}": "}",
    "_": "_", "#": "#", "&": "&", "ldots": "…", "dots": "…", "cdots": "⋯", "partial": "∂", "sum": "Σ",
    "int": "∫", "iint": "∬", "oint": "∮", "prod": "Π", "angle": "∠", "div": "÷", "propto": "∝", "sim": "∼",
    "equiv": "≡", "ll": "≪", "gg": "≫", "Rightarrow": "⇒", "leftarrow": "←", "perp": "⊥", "parallel": "∥",
    "nabla": "∇", "ell": "ℓ", "hbar": "ħ", "prime": "′", "vert": "|", "lvert": "|", "rvert": "|", "|": "‖",
    "langle": "⟨", "rangle": "⟩", "cap": "∩", "cup": "∪", "in": "∈", "forall": "∀", "exists": "∃",
}
#: A fraction of small whole numbers written as one character where a factor follows it: ½I, not 1/2I.
VULGAR = {("1", "2"): "½", ("1", "3"): "⅓", ("2", "3"): "⅔", ("1", "4"): "¼", ("3", "4"): "¾"}
#: Relations and binary operators set with a space each side.
SPACED = {"times", "le", "leq", "ge", "geq", "ne", "neq", "approx", "pm", "mp", "to", "rightarrow", "Rightarrow",
          "leftarrow", "div", "propto", "sim", "equiv", "ll", "gg", "in"}
#: Accents as combining marks after their argument (ω⃗, θ̈, ẋ).
ACCENTS = {"vec": "\u20d7", "dot": "\u0307", "ddot": "\u0308", "hat": "\u0302", "bar": "\u0304",
           "overline": "\u0305", "tilde": "\u0303"}
SPACES = {",": "", ":": " ", ";": " ", " ": " ", "!": "", "quad": "  ", "qquad": "   "}
FUNCTIONS = {"sin", "cos", "tan", "cot", "sec", "csc", "cosec", "arcsin", "arccos", "arctan", "sinh",
             "cosh", "tanh", "ln", "log", "exp", "max", "min", "lim", "det"}
TEXT_COMMANDS = {"mathrm", "text", "textrm", "operatorname", "mathit", "mathbf", "boldsymbol", "mathsf",
                 "textit", "textbf", "mbox"}
DROPPED = {"left", "right", "big", "Big", "bigl", "bigr", "Bigl", "Bigr", "bigg", "Bigg", "displaystyle", "textstyle",
           "limits", "nolimits"}
SUPER = dict(zip("0123456789+-=()nix", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁼⁽⁾ⁿⁱˣ"))
SUB = dict(zip("0123456789+-=()aehijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ"))
# A math span: an unescaped $ ... unescaped $ (a literal dollar is written \$).
MATH_SPAN = re.compile(r"(?<!\\)\$(.+?)(?<!\\)\$", re.DOTALL)
_TOKEN = re.compile(r"\\([A-Za-z]+|.)|([{}^_])|(\s+)|(.)", re.DOTALL)


def _tokens(latex: str) -> list[str]:
    out = []
    for match in _TOKEN.finditer(latex):
        command, special, space, char = match.groups()
        if command is not None:
            out.append("\\" + command)
        elif special is not None:
            out.append(special)
        elif space is not None:
            out.append(" ")
        else:
            out.append(char)
    return out


class _Parser:
    def __init__(self, tokens: list[str]):
        self.tokens, self.at = tokens, 0

    def peek(self) -> str | None:
        return self.tokens[self.at] if self.at < len(self.tokens) else None

    def take(self) -> str | None:
        token = self.peek()
        self.at += 1
        return token

    def sequence(self, stop: str | None = None) -> str:
        parts = []
        while self.peek() is not None and self.peek() != stop:
            parts.append(self.item())
        if stop is not None:
            self.take()
        return "".join(parts)

    def argument(self) -> str:
        """A braced group or a single token, as text."""
        while self.peek() == " ":
            self.take()
        if self.peek() == "{":
            self.take()
            return self.sequence("}")
        return self.item() if self.peek() is not None else ""

    def text_argument(self) -> str:
        """The argument of \\text and friends as text: its spaces, hyphens and apostrophes as written
        ("spring in tension", "counter-clockwise"), groups inside it included."""
        if self.peek() != "{":
            return self.argument()
        self.take()
        parts = []
        while self.peek() is not None and self.peek() != "}":
            token = self.take()
            if token == "{":
                self.at -= 1
                parts.append(self.text_argument())
            elif token == "~":
                parts.append(" ")
            elif token.startswith("\\") and len(token) > 1:
                name = token[1:]
                parts.append(" " if name in SPACES else self.command(name).strip() if name in SYMBOLS
                             else self.command(name))
            else:
                parts.append(token)
        self.take()
        return "".join(parts)

    def item(self) -> str:
        token = self.take()
        if token == "{":
            return self.sequence("}")
        if token in ("^", "_"):
            return _script(self.argument(), SUPER if token == "^" else SUB, token)
        if token == " ":
            return ""
        if token == "-":
            return "−" if self._unary() else " − "
        if token in ("+", "="):
            return f" {token} "
        if token == "'":
            return "′"
        if not token.startswith("\\"):
            return token
        return self.command(token[1:])

    def _unary(self) -> bool:
        """A minus with no operand before it (at the start, after a bracket or an operator) is a sign."""
        at = self.at - 2
        while at >= 0 and self.tokens[at] == " ":
            at -= 1
        if at < 0:
            return True
        before = self.tokens[at]
        return before in ("(", "{", "[", "=", "+", "-", "^", "_", ",", "\\times", "\\cdot", "\\left", "\\frac")

    def command(self, name: str) -> str:
        if name in ("frac", "dfrac", "tfrac", "cfrac"):
            (top, top_factors), (bottom, bottom_factors) = self.measured_argument(), self.measured_argument()
            top = top.strip() if top_factors else f"({top.strip()})"  # 2πN/60, (d₁ + t)/2
            bottom = bottom.strip() if bottom_factors == 1 else f"({bottom.strip()})"  # a/2, a/(2π)
            fraction = f"{top}/{bottom}"
            factor = self._factor_follows()
            if not factor:
                return fraction
            if factor != "digit" and (top, bottom) in VULGAR:
                return VULGAR[top, bottom]  # ½I(ω₁² − ω₂²)
            return f"({fraction})"  # "1/2I" would read 1/(2I)
        if name == "sqrt":
            root = ROOTS.get(self.optional_argument(), "√")
            radicand, factors = self.measured_argument()
            return root + (radicand.strip() if factors == 1 else f"({radicand.strip()})")
        if name == "operatorname":
            return self.function(self.argument())
        if name in TEXT_COMMANDS:
            return self.text_argument()
        if name in ACCENTS:  # a combining mark after its symbol: ω⃗, θ̈
            return self.argument() + ACCENTS[name]
        if name in DROPPED:
            if name in ("left", "right") and self.peek() == ".":  # \\left. opens nothing
                self.take()
            return ""
        if name in SPACES:
            return SPACES[name]
        if name in GREEK:
            return GREEK[name]
        if name in SYMBOLS:
            return f" {SYMBOLS[name]} " if name in SPACED else SYMBOLS[name]
        if name in FUNCTIONS:
            return " " + self.function(name)
        return "\\" + name

    def optional_argument(self) -> str:
        """[3] after \\sqrt, as its text ("" when there is none)."""
        if self.peek() != "[":
            return ""
        self.take()
        return self.sequence("]")

    def measured_argument(self) -> tuple[str, int | None]:
        """An argument and how many factors it multiplies (see _factors; None when it is no product)."""
        start = self.at
        text = self.argument()
        return text, _factors(self.tokens[start:self.at])

    def _factor_follows(self) -> str | None:
        """What comes straight after, if it multiplies (1/2 then m v², which would read as part of a
        denominator): "digit" or "term"; None for an operator or nothing."""
        at = self.at
        while at < len(self.tokens) and (self.tokens[at] == " " or self.tokens[at][1:] in SPACES):
            at += 1
        if at >= len(self.tokens):
            return None
        token = self.tokens[at]
        if token[0].isdigit():
            return "digit"
        if not token.startswith("\\") or len(token) == 1:
            return "term" if token.isalnum() or token in ("(", "[", "{") else None
        name = token[1:]
        multiplies = name in GREEK or name in ACCENTS or name in TEXT_COMMANDS or name in FUNCTIONS or \
            name in ("frac", "dfrac", "tfrac", "cfrac", "sqrt", "left", "operatorname", "infty", "partial")
        return "term" if multiplies else None

    def function(self, name: str) -> str:
        """sin, cosec, ...: scripts attach to the name (sin⁻¹), then a space before the argument."""
        while self.peek() in ("^", "_"):
            name += self.item()
        while self.peek() == " ":
            self.take()
        if self.peek() in ("\\frac", "\\dfrac", "\\tfrac"):  # sin⁻¹((r₂ − r₁)/X), not sin⁻¹ (r₂ − r₁)/X
            return f"{name}({self.item()})"
        return name + " "


ROOTS = {"": "√", "2": "√", "3": "∛", "4": "∜"}
_ONE_SYMBOL = set(GREEK) | {"infty", "ell", "hbar", "partial", "nabla", "prime"}
_CLOSE = {"(": ")", "[": "]", "{": "}"}


def _factors(tokens: list[str]) -> int | None:
    """How many factors LaTeX tokens multiply (2π: 2), each a number, a symbol with its scripts, accents
    and primes, a text, a root or a bracketed group; None for anything else (a sum, a fraction)."""
    tokens = [t for t in tokens if t[1:] not in SPACES]
    while tokens and tokens[0] == " ":
        tokens = tokens[1:]
    while tokens and tokens[0] == "{" and _past_group(tokens, 0) == len(tokens):  # an argument's own braces
        tokens = tokens[1:-1]
    factors, at = 0, 0
    while at < len(tokens):
        token = tokens[at]
        if token in ("^", "_"):  # a script belongs to the factor before it
            at = _past_argument(tokens, at + 1)
            continue
        if token in ("'", " "):
            at += 1
            continue
        factors += 1
        if token in _CLOSE or token == "\\left":
            at = _past_group(tokens, at)
        elif token[0].isdigit() or token == ".":
            while at < len(tokens) and (tokens[at].isdigit() or tokens[at] == "."):
                at += 1
        elif token.isalpha() and len(token) == 1:
            at += 1
        elif token[1:] in _ONE_SYMBOL:
            at += 1
        elif token[1:] in TEXT_COMMANDS or token[1:] in ACCENTS or token[1:] in ("sqrt", "operatorname"):
            end = _past_argument(tokens, at + 1)
            if token[1:] in TEXT_COMMANDS and " " in tokens[at + 2:end - 1]:
                return None  # words: "time taken" is no one factor in plain text
            at = end
        else:
            return None
    return factors


def _past_argument(tokens: list[str], at: int) -> int:
    """The index after the argument that starts at `at` (a group or one token)."""
    if at < len(tokens) and tokens[at] == "[":  # \\sqrt[3]
        at = _past_group(tokens, at)
    if at < len(tokens) and tokens[at] == "{":
        return _past_group(tokens, at)
    return at + 1


def _past_group(tokens: list[str], at: int) -> int:
    """The index after the bracket (or \\left ... \\right pair) that opens at `at` is closed."""
    opening = tokens[at]
    pairs = ("\\left", "\\right") if opening == "\\left" else (opening, _CLOSE[opening])
    depth = 0
    while at < len(tokens):
        depth += (tokens[at] == pairs[0]) - (tokens[at] == pairs[1])
        at += 1
        if depth == 0:
            return at + 1 if opening == "\\left" else at  # past \\right's bracket too
    return at


def _script(text: str, table: dict, mark: str) -> str:
    if text.strip() == "°":
        return "°"
    compact = re.sub(r"\s*([−+=])\s*", r"\1", text.strip()).replace("−", "-")  # ⁻¹, not ^(−1); a space is kept
    if compact and all(ch in table for ch in compact):
        return "".join(table[ch] for ch in compact)
    text = text.strip()
    return f"{mark}{text}" if len(text) == 1 else f"{mark}({text})"


#: A one-letter script with no Unicode form, run into the symbol after it, is set off by a space: m_B b², not
#: m_Bb² (m with the subscript Bb); a bracket would read as a part's label (F_(c)h).
_RUN_IN_SCRIPT = re.compile(r"(?<=[_^])([A-Za-z0-9])(?=[A-Za-z0-9\u0370-\u03ff(√])")


@lru_cache(maxsize=4096)
def latex_to_unicode(latex: str) -> str:
    text = _Parser(_tokens(latex)).sequence()
    text = re.sub(r" {2,}", " ", text).strip()
    text = _RUN_IN_SCRIPT.sub(r"\1 ", text)
    return unicodedata.normalize("NFC", text.replace("( ", "(").replace(" )", ")"))  # x and a dot: ẋ


def split_math(text: str) -> list[tuple[bool, str]]:
    """[(is_math, chunk), ...] in order; prose chunks keep their \\$ escapes."""
    out, at = [], 0
    for match in MATH_SPAN.finditer(text):
        if match.start() > at:
            out.append((False, text[at:match.start()]))
        out.append((True, match.group(1).strip()))
        at = match.end()
    if at < len(text):
        out.append((False, text[at:]))
    return out


def unescape_dollars(prose: str) -> str:
    return prose.replace("\\$", "$")


#: A hyphen before a digit that follows no word, number or closing bracket is a negative sign, set as the
#: minus sign U+2212 in typeset text, so "-1512" never stands beside "(−1512.5)".
NEGATIVE_NUMBER = re.compile(r"(?<![\w.)\]\-\u2080-\u2089\u2070-\u2079])-(?=\.?\d)")


def typeset_minus(text: str) -> str:
    """Every negative sign of a number in `text` as U+2212 ("x = -3" -> "x = −3"; "x-1", "2-3" kept)."""
    return NEGATIVE_NUMBER.sub("\u2212", text) if "-" in text else text


def text_to_plain(text: str) -> str:
    """A statement or ask for the terminal: math spans as Unicode, negative numbers with the minus sign."""
    if "$" not in text:  # no math and no escaped dollar: most messages and asks
        return typeset_minus(text)
    return "".join(latex_to_unicode(chunk) if is_math else typeset_minus(unescape_dollars(chunk))
                   for is_math, chunk in split_math(text))
