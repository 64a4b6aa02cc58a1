"""Macro words and the abbreviations a FANUC control reads for them (docs/semantics.md §1).

FANUC takes the first two or more letters of a custom macro word for the whole word (seed 003,
end of chapter 7; FANUC operator's manuals, "abbreviations of custom macro words"): ``WH`` for
``WHILE``, ``GO`` for ``GOTO``, ``AT[..]/[..]`` for ``ATAN``, ``RO`` for ``ROUND``. Only the words
below have abbreviations; the words of two letters (IF, DO, OR, LN and the relations EQ NE GT
GE LT LE) have none, and neither has MOD, which the manual's list leaves out.

Why none of them can be mistaken for NC words: a word's value never starts with a letter (it
is a number, a sign, ``#`` or ``[``), so two letters in a row are never an address and its
value (``GO10`` cannot be G with the value O10; ``EN1``, ``TH#1=2`` cannot be E or T words).
And every abbreviation's first two letters belong to one word only and to no word of two
letters (``EN`` is END's, ``EQ`` stays a relation, ``DO`` stays DO, ``DP`` is DPRNT's, ``TH``
THEN's, ``TA`` TAN's), so a prefix always names one word. The one reading a person may not
mean is a letter O typed for a zero (``GO1`` for ``G01``): the control reads it as ``GOTO 1``
too, and the editor shows the full word on hover and as a hint.

The grammar (``block.lark``) and the fast path (``fastpath.py``) both spell their keyword
patterns from ``pattern``; nodes carry the full word, and the block lists where an
abbreviation was written (``Block.abbreviations``) so that a dialect without them can report it.
"""

from __future__ import annotations

ABBREVIABLE = (
    "WHILE", "GOTO", "THEN", "END", "XOR", "AND", "SIN", "ASIN", "COS", "ACOS", "TAN", "ATAN", "SQRT", "ABS",
    "EXP", "ROUND", "FIX", "FUP", "BIN", "BCD", "POPEN", "PCLOS", "DPRNT", "BPRNT",
)  # fmt: skip

# every accepted shortening (two letters or more, short of the whole word) -> the whole word
FULL_WORD: dict[str, str] = {word[:k]: word for word in ABBREVIABLE for k in range(2, len(word))}


def pattern(word: str) -> str:
    """A regular expression for ``word`` or any of its abbreviations, longest first:
    ``WH(?:I(?:L(?:E)?)?)?`` for WHILE; a word without abbreviations stands for itself."""
    if word not in ABBREVIABLE:
        return word
    out = ""
    for ch in reversed(word[2:]):
        out = f"(?:{ch}{out})?"
    return word[:2] + out


def full_word(text: str) -> str:
    """The whole word for ``text`` (upper case): itself when it is not an abbreviation."""
    up = text.upper()
    return FULL_WORD.get(up, up)
