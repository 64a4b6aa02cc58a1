"""Function breakpoints on codes: ``M06``, ``T``, ``T5``, ``M00``, ``M01``, ``G81``.

A name is a G, M or T address with a number (``M6`` and ``M06`` are the same code, ``G5.1``
keeps its decimal) or the letter alone (``T``: any tool call, "run to the next tool change").
The name is read with the block grammar (``syntax.block_parser``) and rounded as the
interpreter rounds a code (``machine.calls.code_value``: G to 0.1, M and T to a whole number);
a G code the dialect's table and the machine file's ``[calls]`` lack is refused with the
interpreter's own words (``machine.words``), as is an M code with a decimal point.

The run stops before a block whose words hold the code: a literal word as written, a word
with an expression (``T#1``, ``M[#2+4]``) by its value at that moment. The words of a macro
call (``G65 P9100 T5``: ``T`` is the argument ``#20``) are arguments, not codes
(``machine.calls.recognise_call``), so they never match.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ..bilingual import Detail, detail
from ..dialects import DEFAULT_DIALECT, get_dialect
from ..machine import Machine, MacroAlarm
from ..machine.calls import code_value, recognise_call
from ..machine.expressions import ExpressionCompiler
from ..machine.variables import StopRequest
from ..machine.words import g_code_known, m_decimal_point, unknown_g_code
from ..syntax.block_parser import parse_block
from ..syntax.nodes import Block, Number, Word

CODE_LETTERS = ("G", "M", "T")
_LETTER_ALONE = re.compile(r"^\s*([GgMmTt])\s*$")
_CODE_NAME = re.compile(r"^\s*[GgMmTt]\s*\d{1,8}(\.\d*)?\s*$")


@dataclass(frozen=True, slots=True)
class CodeName:
    """A code to stop at: its letter and value, or None for any code of the letter."""

    letter: str
    value: float | None

    def __str__(self) -> str:
        if self.value is None:
            return self.letter
        return f"{self.letter}{self.value:g}"


def looks_like_code(name: str) -> bool:
    """Whether ``name`` is written as a G, M or T code (and is to be read as one)."""
    return bool(_LETTER_ALONE.match(name) or _CODE_NAME.match(name))


def read_code_name(name: str, machine: Machine | None) -> CodeName | Detail:
    """The code ``name`` asks for, or what is wrong with it. Without a machine (before a
    launch) a G code is not checked against the dialect."""
    alone = _LETTER_ALONE.match(name)
    if alone:
        return CodeName(alone.group(1).upper(), None)
    block = parse_block(name.strip())
    words = block.words
    if block.problems or len(words) != 1 or words[0].letter not in CODE_LETTERS:
        return detail(
            f"'{name}' is no code: name a G, M or T code (M06, T, M00, G81)",
            f"'{name}' 不是代码：请写 G、M 或 T 代码（M06、T、M00、G81）",
        )
    word = words[0]
    if word.letter == "M":
        # before a launch the default profile says it (its alarm number)
        problem = m_decimal_point(word, machine.dialect if machine is not None else get_dialect(DEFAULT_DIALECT))
        if problem is not None:
            return problem
    value = code_value(word)
    assert value is not None  # a literal: the pattern allows nothing else
    if word.letter == "G" and machine is not None:
        if not g_code_known(value, machine.dialect, machine.settings.calls):
            return unknown_g_code(f"{value:g}", machine.dialect)
    return CodeName(word.letter, value)


def _rounded(letter: str, value: float) -> float | None:
    """A computed value rounded as the interpreter rounds a code of ``letter``."""
    return code_value(Word(letter, Number(value, f"{value!r}", 0, 0), None, 0, 0))


def codes_of(machine: Machine, block: Block) -> list[tuple[str, float]]:
    """The G, M and T codes ``block`` gives, as the run stands before it (not a call's
    arguments); a word whose expression cannot be evaluated now is left out."""
    words = block.words
    if not any(w.letter in CODE_LETTERS for w in words):
        return []
    call = recognise_call(words, machine.dialect, machine.settings.calls)
    arguments = {id(w) for w in call.arguments} if call is not None else set()
    out: list[tuple[str, float]] = []
    for w in words:
        if w.letter not in CODE_LETTERS or id(w) in arguments:
            continue
        value = code_value(w)
        if value is None and w.value is not None:
            try:
                computed = ExpressionCompiler(machine.kinds, in_address=True).value(w.value)(machine)
            except (MacroAlarm, StopRequest):
                continue
            value = None if computed is None else _rounded(w.letter, computed)
        if value is not None:
            out.append((w.letter, value))
    return out


def matches(name: CodeName, codes: list[tuple[str, float]]) -> bool:
    """Whether the block's ``codes`` hold the code ``name`` asks for."""
    return any(letter == name.letter and (name.value is None or value == name.value) for letter, value in codes)
