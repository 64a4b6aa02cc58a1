"""Plain-words messages for lines the grammar rejects.

Lark reports an unexpected character or token with the names of the terminals it expected.
A CNC programmer wants to read "expected ']' to close the '[' at column 5" or "expected a
value after 'X'", so this module turns lark's exceptions into a ``Problem`` with a range.
"""

from __future__ import annotations

from lark.exceptions import UnexpectedCharacters, UnexpectedInput, UnexpectedToken

from .nodes import Problem

_NAMES = {
    "NUMBER": "a number",
    "VARNUM": "a variable such as #1",
    "HASH": "'#'",
    "LSQB": "'['",
    "RSQB": "']'",
    "LETTER": "an address such as X or G",
    "P_LETTER": "an address such as X or G",
    "BRACKET_NAME": "a program name in brackets",
    "SIGN": "'+' or '-'",
    "ADDOP": "OR or XOR",
    "MULOP": "'*', '/', AND or MOD",
    "RELOP": "a comparison (EQ NE GT GE LT LE)",
    "EQUALS": "'='",
    "FUNC": "a function such as SIN",
    "ATAN": "ATAN",
    "ATAN_SEP": "'/'",
    "IF": "IF",
    "THEN": "THEN",
    "GOTO": "GOTO",
    "WHILE": "WHILE",
    "DO": "DO",
    "END": "END",
    "POPEN": "POPEN",
    "PCLOS": "PCLOS",
    "DPRNT": "DPRNT",
    "BPRNT": "BPRNT",
    "DPRNT_ARGS": "'[' with the text to print",
    "$END": "the end of the block",
}

# What a bare value looks like, to say "expected a value" instead of listing six terminals.
_VALUE_START = {"NUMBER", "VARNUM", "HASH", "LSQB", "SIGN"}
# What may start a word or a statement, to say "another word or statement" likewise.
_ITEM_START = {
    "LETTER", "P_LETTER", "VARNUM", "HASH", "IF", "WHILE", "DO", "END", "GOTO",
    "POPEN", "PCLOS", "DPRNT", "BPRNT",
}


def describe_error(code: str, err: UnexpectedInput) -> Problem:
    """A problem with a message and a range for a line that does not parse."""
    unclosed = _unclosed_bracket(code)
    if isinstance(err, UnexpectedCharacters):
        pos = err.pos_in_stream
        ch = code[pos] if pos < len(code) else ""
        if ch == "]" and unclosed is None:
            return Problem("']' without a matching '['", pos, pos + 1)
        if unclosed is not None and ch not in "[]":
            return _unclosed_problem(code, unclosed, pos)
        expected = _expected_text(set(err.allowed or ()))
        what = f"'{ch}'" if ch.isprintable() else f"character U+{ord(ch):04X}"
        return Problem(f"unexpected {what}{expected}", pos, pos + 1)
    if isinstance(err, UnexpectedToken):
        tok = err.token
        expected_set = set(err.expected or ())
        if tok.type == "$END":
            end = len(code.rstrip())
            if unclosed is not None:
                return _unclosed_problem(code, unclosed, end)
            start = max(0, end - 1)
            return Problem(f"the block ends too early{_expected_text(expected_set)}", start, end)
        start = tok.start_pos if tok.start_pos is not None else 0
        end = tok.end_pos if tok.end_pos is not None else start + 1
        if tok.type == "RSQB" and unclosed is None and "RSQB" not in expected_set:
            return Problem("']' without a matching '['", start, end)
        if tok.type == "RELOP" and "RELOP" not in expected_set:
            if _open_bracket_before(code, start):
                msg = f"unexpected comparison '{tok}': join conditions as [[a EQ b] AND [c EQ d]]"
            else:
                msg = f"the comparison '{tok}' is allowed only inside the [ ] of an IF or WHILE condition"
            return Problem(msg, start, end)
        if tok.type == "NUMBER" and "NUMBER" not in expected_set:
            return Problem(
                f"unexpected number '{tok}': an address letter such as X must come before a value",
                start,
                end,
            )
        if unclosed is not None and "RSQB" in expected_set and tok.type not in ("LSQB",):
            return _unclosed_problem(code, unclosed, start)
        return Problem(f"unexpected '{tok}'{_expected_text(expected_set)}", start, end)
    pos = getattr(err, "pos_in_stream", 0) or 0
    return Problem("the block does not parse", pos, pos + 1)


def _unclosed_problem(code: str, bracket: int, at: int) -> Problem:
    at = min(at, len(code))
    end = max(at, len(code.rstrip()))
    return Problem(f"expected ']' to close the '[' at column {bracket + 1}", at, max(end, at + 1))


def _open_bracket_before(code: str, pos: int) -> bool:
    """True when a '[' opened before ``pos`` is still open there."""
    return _unclosed_bracket(code[:pos]) is not None


def _unclosed_bracket(code: str) -> int | None:
    """Column of the innermost '[' that is never closed, if any."""
    stack: list[int] = []
    for i, ch in enumerate(code):
        if ch == "[":
            stack.append(i)
        elif ch == "]" and stack:
            stack.pop()
    return stack[-1] if stack else None


def _expected_text(expected: set[str]) -> str:
    if not expected:
        return ""
    names: list[str] = []
    if len(expected & _ITEM_START) >= 5:
        names.append("another word or statement")
        expected = expected - _ITEM_START
    if {"NUMBER", "VARNUM", "LSQB"} <= expected:
        names.append("a value (a number, #variable or [expression])")
        expected = expected - _VALUE_START - {"FUNC", "ATAN"}
    names += _names(expected)
    if len(names) > 5:
        names = [*names[:5], "..."]
    return "; expected " + ", ".join(names)


def _names(terms: set[str]) -> list[str]:
    seen: list[str] = []
    for t in sorted(terms):
        name = _NAMES.get(t, t)
        if name not in seen:
            seen.append(name)
    return seen
