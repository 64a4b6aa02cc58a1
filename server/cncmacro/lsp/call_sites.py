"""Recognising the call words of a block for editor features: ``G65``/``G66``/``M98`` with ``P``.

Which program a ``P`` names comes from ``machine.calls`` (``M98 P30040`` is O0040 three times;
``G65 P`` has at most the dialect's digits); this module only finds the words.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..dialects.dialect import Dialect
from ..machine.alarms import MacroAlarm
from ..machine.calls import macro_program_number, program_and_count
from ..syntax.nodes import Block, Number, Word


@dataclass(frozen=True, slots=True)
class CallSite:
    """A call on one block: ``kind`` is ``G65``, ``G66`` or ``M98``; the program is named by
    ``number`` or (gsk980tdi ``P[CUT]``) ``name``; ``p`` is the P word; ``arguments`` are the
    words after the call code that are macro arguments (G65/G66 only)."""

    kind: str
    number: int | None
    name: str | None
    p: Word
    arguments: tuple[Word, ...]
    code: Word


def _is(word: Word, letter: str, value: float) -> bool:
    return word.letter == letter and isinstance(word.value, Number) and word.value.value == value


def call_site(block: Block, dialect: Dialect) -> CallSite | None:
    """The call this block makes, if it names its program with a literal P."""
    if block.plain is not None and "P" not in block.plain.upper():
        return None
    words = block.words
    for i, w in enumerate(words):
        kind = "G65" if _is(w, "G", 65) else "G66" if _is(w, "G", 66) else "M98" if _is(w, "M", 98) else None
        if kind is None:
            continue
        if kind == "G65" and dialect.h_codes and any(x.letter == "H" for x in words):
            return None  # G65 Hm P Q R: macro arithmetic and branches (docs/semantics.md §7), not a call
        p = next((x for x in words if x.letter == "P"), None)
        if p is None:
            return None
        args = tuple(x for x in words[i + 1 :] if x.letter not in ("P", "L")) if kind != "M98" else ()
        if p.name is not None:
            return CallSite(kind, None, p.name, p, args, w)
        if not isinstance(p.value, Number):
            return CallSite(kind, None, None, p, args, w)
        try:
            if kind == "M98":
                number, _ = program_and_count(p.value.text, p.value.value, None, dialect, [])
            else:
                number = macro_program_number(p.value.value, dialect)
        except MacroAlarm:
            number = None
        return CallSite(kind, number, None, p, args, w)
    return None
