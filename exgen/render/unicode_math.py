"""LaTeX math -> plain Unicode for the terminal and plain files: θ = π − 2α, T₁/T₂ = e^(μθ), sin⁻¹((r₂ − r₁)/X);
text with $...$ math spans -> the same text with its math so written (text_to_plain).

Covers what templates and solvers write (fractions, roots, sub- and superscripts, Greek,
\\mathrm, \\text, \\operatorname, \\left/\\right, spacing); an unknown command prints its name.
"""
from __future__ import annotations

import re
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
    "angle": "∠",
}
#: A fraction of small whole numbers written as one character where a factor follows it: ½I, not 1/2I.
VULGAR = {("1", "2"): "½", ("1", "3"): "⅓", ("2", "3"): "⅔", ("1", "4"): "¼", ("3", "4"): "¾"}
SPACES = {",": "", ":": " ", ";": " ", " ": " ", "!": "", "quad": "  ", "qquad": "   "}
FUNCTIONS = {"sin", "cos", "tan", "cot", "sec", "csc", "cosec", "arcsin", "arccos", "arctan", "sinh",
             "cosh", "tanh", "ln", "log", "exp", "max", "min", "lim", "det"}
TEXT_COMMANDS = {"mathrm", "text", "textrm", "operatorname", "mathit", "mathbf", "boldsymbol", "mathsf",
                 "textit", "textbf", "mbox"}
DROPPED = {"left", "right", "big", "Big", "bigl", "bigr", "Bigl", "Bigr", "displaystyle", "textstyle", "limits"}
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
        """The argument of \\text and friends, keeping its spaces ("spring in tension")."""
        if self.peek() != "{":
            return self.argument()
        self.take()
        parts = []
        while self.peek() is not None and self.peek() != "}":
            parts.append(" " if self.peek() == " " else self.item())
            if parts[-1] == " ":
                self.take()
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

    def _factor_follows(self) -> str | None:
        """What follows, if it multiplies what came before ("digit" or "term"); None if an operator or nothing."""
        at = self.at
        while at < len(self.tokens) and self.tokens[at] in (" ", "\\,", "\\!", "\\;", "\\:", "\\ "):
            at += 1
        token = self.tokens[at] if at < len(self.tokens) else None
        if token is None:
            return None
        if token[0].isdigit():
            return "digit"
        if token.startswith("\\"):
            name = token[1:]
            multiplies = name in GREEK or name in FUNCTIONS or name in TEXT_COMMANDS or name in (
                "frac", "dfrac", "tfrac", "sqrt", "left", "vec")
            return "term" if multiplies else None
        return "term" if token.isalpha() or token in ("(", "[", "{") else None

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
        if name == "frac" or name in ("dfrac", "tfrac"):
            top, bottom = self.argument(), self.argument()
            text = f"{_grouped(top)}/{_grouped(bottom)}"
            factor = self._factor_follows()
            if not factor:
                return text
            if factor != "digit" and (top, bottom) in VULGAR:
                return VULGAR[top, bottom]
            return f"({text})"  # "1/2I" would read 1/(2I)
        if name == "sqrt":
            return "√" + _grouped(self.argument())
        if name == "operatorname":
            return self.function(self.argument())
        if name in TEXT_COMMANDS:
            return self.text_argument()
        if name == "vec":  # a vector: the symbol with a combining arrow above (ω⃗)
            return self.argument() + "\u20d7"
        if name in DROPPED:
            return ""
        if name in SPACES:
            return SPACES[name]
        if name in GREEK:
            return GREEK[name]
        if name in SYMBOLS:
            return f" {SYMBOLS[name]} " if name in ("times", "le", "leq", "ge", "geq", "ne", "neq", "approx",
                                                     "pm", "to", "rightarrow") else SYMBOLS[name]
        if name in FUNCTIONS:
            return " " + self.function(name)
        return name

    def function(self, name: str) -> str:
        """sin, cosec, ...: scripts attach to the name (sin⁻¹), then a space before the argument."""
        while self.peek() in ("^", "_"):
            name += self.item()
        while self.peek() == " ":
            self.take()
        if self.peek() in ("\\frac", "\\dfrac", "\\tfrac"):  # sin⁻¹((r₂ − r₁)/X), not sin⁻¹ (r₂ − r₁)/X
            return f"{name}({self.item()})"
        return name + " "


def _grouped(text: str) -> str:
    """Parenthesise a fraction part or root argument unless it is a single term."""
    text = text.strip()
    return text if re.fullmatch(r"[\w.′°⁰¹²³⁴⁵⁶⁷⁸⁹₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ]+", text) else f"({text})"


def _script(text: str, table: dict, mark: str) -> str:
    if text.strip() == "°":
        return "°"
    compact = text.replace(" ", "").replace("−", "-")
    if compact and all(ch in table for ch in compact):
        return "".join(table[ch] for ch in compact)
    text = text.strip()
    return f"{mark}{text}" if len(text) == 1 else f"{mark}({text})"


@lru_cache(maxsize=4096)
def latex_to_unicode(latex: str) -> str:
    text = _Parser(_tokens(latex)).sequence()
    text = re.sub(r" {2,}", " ", text).strip()
    return text.replace("( ", "(").replace(" )", ")")


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


def text_to_plain(text: str) -> str:
    """A statement or ask for the terminal: math spans as Unicode."""
    return "".join(latex_to_unicode(chunk) if is_math else unescape_dollars(chunk)
                   for is_math, chunk in split_math(text))
