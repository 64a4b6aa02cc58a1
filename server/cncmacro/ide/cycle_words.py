"""Cycle words under the cursor: what a letter of a cycle block means in the block it is in
(hover), and the letters of the block being typed with the one under the cursor (signature help,
completion), from the profile's table (``Dialect.cycle_words``, ``dialects/cycle_words.py``).

A block belongs to the cycle whose G code it names (the last such G word). Which of a two-block
cycle's blocks it is follows the run's rule (``CycleWords.is_second``: G71's second block has P
and Q). A block still being typed may not show it yet: one with a letter only the first block
has is the first; one with neither is the second when the nearest block above it in its program
that names the same code is a first block (``G71 U2. R1.`` then ``G71 `` on the next line), else
the first.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ..dialects.cycle_words import CycleForm, CycleWord, CycleWords
from ..dialects.dialect import Dialect
from ..syntax.block_parser import parse_block
from ..syntax.nodes import Block, Number, Word
from .source import EditorDocument

LOOK_BACK = 200  # the lines above a block searched for the same cycle's first block
_PARTIAL = re.compile(r"[A-Za-z]\s*$")  # a letter typed without its value yet


@dataclass(frozen=True, slots=True)
class CycleWordAt:
    """A letter of a cycle block: the code (``G71``), the form of the block it is in, what the
    letter means there, and its columns."""

    code: str
    form: CycleForm
    word: CycleWord
    start: int
    end: int


@dataclass(frozen=True, slots=True)
class CycleSignature:
    """The block being typed: its code, its form, the index of the letter under the cursor in the
    form's words (None when the cursor is on no letter of the form) and the letters it has."""

    code: str
    form: CycleForm
    active: int | None
    given: frozenset[str]


def cycle_of(dialect: Dialect, words: tuple[Word, ...] | list[Word]) -> tuple[CycleWords, Word] | None:
    """The cycle a block names (the last G word the profile's table has) and that G word."""
    found = None
    for w in words:
        if w.letter == "G" and isinstance(w.value, Number):
            cycle = dialect.cycle_words_of(w.value.value)  # P as the cycle dwells on this profile
            if cycle is not None:
                found = (cycle, w)
    return found


def cycle_word_at(dialect: Dialect, block: Block, column: int) -> CycleWordAt | None:
    """The meaning of the letter at code-point ``column`` of ``block`` in the cycle block it is
    (the run's rule), or None when it is no letter of one."""
    found = cycle_of(dialect, block.words)
    if found is None:
        return None
    cycle, g = found
    form = cycle.form_of([w.letter for w in block.words])
    under = [w for w in block.words if w.start <= column <= w.end]  # two where words touch: the right one
    if not under or under[-1] is g:
        return None
    w = under[-1]
    meaning = form.word(w.letter)
    return None if meaning is None else CycleWordAt(cycle.code, form, meaning, w.start, w.end)


def cycle_form_of(dialect: Dialect, block: Block) -> tuple[str, CycleForm] | None:
    """The code and form of a cycle block (the run's rule), or None when it names no cycle."""
    found = cycle_of(dialect, block.words)
    if found is None:
        return None
    return found[0].code, found[0].form_of([w.letter for w in block.words])


def cycle_signature(doc: EditorDocument, line: int, column: int) -> CycleSignature | None:
    """The cycle block being typed on ``line`` and the letter at or before ``column``, or None
    when the line names no cycle before the cursor."""
    words = _typed_words(doc, line, column)
    found = cycle_of(doc.dialect, words)
    if found is None or column <= found[1].end:  # none before the code, nor on it
        return None
    cycle, g = found
    letters = frozenset(w.letter for w in words if w is not g)
    before = [w for w in words if w is not g and g.start < w.start < column]
    text = doc.line(line)[:column]
    typed = _PARTIAL.search(text)  # a letter typed just now, without its value yet
    letter = typed.group(0)[0].upper() if typed and not text.endswith(" ") else None
    form = _typed_form(doc, line, cycle, letters | {letter} if letter else letters)
    if letter is None and before and column <= before[-1].end:
        letter = before[-1].letter
    letters_in_form = [w.letter for w in form.words]
    active = letters_in_form.index(letter) if letter in letters_in_form else None
    return CycleSignature(cycle.code, form, active, letters)


def _typed_words(doc: EditorDocument, line: int, column: int) -> tuple[Word, ...]:
    """The words of ``line``: its block's, or, while a word is half typed (the line does not
    parse), those of the text before the cursor without the letter being typed."""
    block = doc.block(line)
    if block is not None and block.words:
        return tuple(block.words)
    text = _PARTIAL.sub("", doc.line(line)[:column])
    return tuple(parse_block(text).words)


def _typed_form(doc: EditorDocument, line: int, cycle: CycleWords, letters: frozenset[str]) -> CycleForm:
    """The form of a block being typed (module docstring)."""
    if len(cycle.forms) < 2 or cycle.is_second(letters):
        return cycle.form_of(letters)
    first, second = cycle.forms
    if letters & ({w.letter for w in first.words} - {w.letter for w in second.words}):
        return first
    above = _block_above(doc, line, cycle)
    return second if above is not None and not cycle.is_second(above) else first


def _block_above(doc: EditorDocument, line: int, cycle: CycleWords) -> list[str] | None:
    """The letters of the nearest block above ``line`` in its program that names ``cycle``'s code."""
    top = max(doc.parsed.program.unit_at(line).start, line - LOOK_BACK, 0)
    for i in range(line - 1, top - 1, -1):
        block = doc.block(i)
        if block is None:
            continue
        found = cycle_of(doc.dialect, block.words)
        if found is not None and found[0] is cycle:
            return [w.letter for w in block.words]
    return None
