"""The words of a cycle block, letter by letter: the record a profile's table of cycle words is
made of (``Dialect.cycle_words``: ``lathe_cycle_words.py``, ``drill_cycle_words.py``), read by
the editor's hover, signature help and completion (docs/editor.md, "Cycle words").

A code may be written in one block (``G90 X Z R F``) or in two that give its letters different
meanings: a lathe's multiple repetitive cycles have a first block (``G71 U(Δd) R(e)``) that sets
parameters and a second (``G71 P(ns) Q(nf) U(Δu) W(Δw) F``) that runs the cycle. Which one a
block is follows the rule the run follows (docs/semantics.md §10.2, ``planner/lathe_cycles.py``):
G70–G73's second block is the one with both P and Q, G74–G76's the one with an end point (any of
X, Z, U, W).
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass

# the names of the two blocks of a two-block cycle, and of a one-block code's only block
FIRST_BLOCK = ("first block", "第一程序段")
SECOND_BLOCK = ("second block", "第二程序段")
ONLY_BLOCK = ("", "")


@dataclass(frozen=True, slots=True)
class CycleWord:
    """One letter of a block form: the symbol the manuals give its value (``Δd``; empty when
    they give none) and what it means there, in English and Chinese."""

    letter: str
    symbol: str
    en: str
    zh: str

    @property
    def piece(self) -> str:
        """How the form writes it: ``U(Δd)``, or the letter alone."""
        return f"{self.letter}({self.symbol})" if self.symbol else self.letter


@dataclass(frozen=True, slots=True)
class CycleForm:
    """One block form of a code: its name (``FIRST_BLOCK``, ``SECOND_BLOCK`` or ``ONLY_BLOCK``)
    and its letters in the manual's order."""

    name: tuple[str, str]
    words: tuple[CycleWord, ...]

    def word(self, letter: str) -> CycleWord | None:
        """The meaning of ``letter`` in this form, or None when the form has no such letter."""
        return next((w for w in self.words if w.letter == letter), None)

    def text(self, code: str) -> str:
        """The form as the manuals write it: ``G71 U(Δd) R(e)``."""
        return " ".join([code, *(w.piece for w in self.words)])


@dataclass(frozen=True, slots=True)
class CycleWords:
    """The block forms of one G code (``code`` as the tables spell it, ``G71``): one form, or a
    first and a second. A block is the second when it has every letter of ``second_marks``
    (``all_marks``) or any of them."""

    code: str
    forms: tuple[CycleForm, ...]
    second_marks: frozenset[str] = frozenset()
    all_marks: bool = False

    def is_second(self, letters: Collection[str]) -> bool:
        """Whether a block with ``letters`` is this code's second block (the run's rule)."""
        if len(self.forms) < 2:
            return False
        if self.all_marks:
            return self.second_marks <= set(letters)
        return any(letter in self.second_marks for letter in letters)

    def form_of(self, letters: Collection[str]) -> CycleForm:
        """The form a block with ``letters`` is."""
        return self.forms[1] if self.is_second(letters) else self.forms[0]


def one_block(code: str, *words: CycleWord) -> CycleWords:
    """A code written in one block."""
    return CycleWords(code, (CycleForm(ONLY_BLOCK, words),))


def two_blocks(
    code: str, first: tuple[CycleWord, ...], second: tuple[CycleWord, ...], marks: str, all_marks: bool
) -> CycleWords:
    """A code written in a first and a second block; ``marks`` are the letters that make a block
    the second (all of them with ``all_marks``, else any)."""
    forms = (CycleForm(FIRST_BLOCK, first), CycleForm(SECOND_BLOCK, second))
    return CycleWords(code, forms, frozenset(marks), all_marks)


def by_code(*rows: CycleWords) -> dict[float, CycleWords]:
    """A profile's table: each code's words by its number (``G71`` -> 71.0)."""
    return {float(r.code[1:]): r for r in rows}
