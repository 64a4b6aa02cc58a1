"""Sets of NC words a rule looks at, and the quick search for the lines of plain words
(``Block.plain``) that may hold one.

Nearly every line of a CAM program is plain words that no rule looks at (``G01 X12.5 Y-3.``):
the static checks pass over such a line without building its words. Which lines they look at is
not written here: each rule says which words it looks at (``recognise_call``'s call words in
``calls.py``, the words a control may refuse in ``words.py``, the checks' own in
``analysis/checks/call_checks.py``) as ``WordSet``s, and ``plain_search`` makes the search from them, so
that a rule that looks at a word is never passed over on a plain line.

A set names its words by address and code as the interpreter reads them, rounded (``M97.6`` is
M98, ``G1.04`` is G01): its pattern takes in every way of writing such a word, and some more
(a search may look at a line for nothing, never pass one over that it should look at).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass

_END = r"(?=[ \t]|$)"  # a word of a plain line ends at a blank or the line's end
_MOST_G = (0.0, 1.0, 2.0, 3.0)  # G00-G03: most G words of a CAM program


@dataclass(frozen=True, slots=True)
class WordSet:
    """The words with address ``letter`` that a rule looks at: those whose code is one of
    ``codes``; with ``outside``, every word not written as one of those codes (the G codes a
    control lacks); with ``point``, every word written with a decimal point; with none of them,
    every word of the address (a ``T`` that the machine file makes a call)."""

    letter: str
    codes: frozenset[float] | None = None
    outside: frozenset[float] | None = None
    point: bool = False

    def pattern(self) -> str:
        """A pattern of the words of the set as a plain line writes them (the letter in either
        case, then the number), to be searched at a word's start."""
        head = f"[{self.letter.upper()}{self.letter.lower()}]"
        if self.point:
            return rf"{head}[+-]?\d*\."
        if self.codes is not None:
            return rf"{head}[+-]?0*(?:{'|'.join(_near(c) for c in sorted(self.codes))}){_END}"
        return rf"{head}[+-]?[\d.]"  # ``outside`` sets are looked for by ``_outside_search``

    def misses(self, code: float) -> bool:
        """Whether no word of the set is ``code`` written plainly (``G1``, ``G01``, ``G1.``,
        ``G1.0``), so that a search may pass such a word over at once."""
        if self.point:
            return False
        if self.codes is not None:
            return all(int(c) not in (int(code), int(code) + 1) for c in self.codes)
        if self.outside is not None:
            return code in self.outside
        return False


def _near(code: float) -> str:
    """The numbers that round to ``code`` and some more, after leading zeros: its whole part
    with any fraction, or the whole number below it with a fraction (``97.6`` for M98, ``.5``
    for M01)."""
    whole = int(code)
    below = rf"|{whole - 1 or ''}\.\d*" if whole >= 1 else ""
    return rf"{whole or ''}(?:\.\d*)?{below}"


_PLAIN_NUMBER = re.compile(r"(\d+)(?:\.(\d*))?")


def _written(code: float) -> tuple[int, str]:
    """``code`` as a whole number and the digits of its fraction (``54.1``: 54, "1")."""
    whole, _, frac = f"{code:g}".partition(".")
    return int(whole), frac


def _outside_search(sets: list[WordSet]) -> Callable[[str], bool]:
    """Whether a plain line holds a word of one of the ``outside`` sets: a word of its letter
    with a minus sign, or with a number not written exactly as one of its codes (leading zeros
    and trailing zeros of a fraction aside: ``G054.0`` is G54, ``G.5``, ``G-1`` and ``G1..2`` are
    not written as any code). A set of hundreds of codes made into a pattern took milliseconds
    to compile; looking its words up takes none."""
    written: dict[str, set[tuple[int, str]]] = {}
    for s in sets:  # a word is passed over only when no set of its letter looks at it
        codes = {_written(c) for c in s.outside or ()}
        letter = s.letter.upper()
        written[letter] = written[letter] & codes if letter in written else codes
    heads = "".join(sorted(x + x.lower() for x in written))
    # each word of those letters at the line's start or after a blank: its letter, sign, digits and points
    words = re.compile(rf"(?:^|(?<=[ \t]))([{heads}])([+-]?)([\d.]*)").findall

    def search(line: str) -> bool:
        for letter, sign, number in words(line):
            codes = written[letter.upper()]
            if not number:
                continue
            if sign == "-":
                return True
            m = _PLAIN_NUMBER.fullmatch(number)
            if m is None or (int(m[1]), (m[2] or "").rstrip("0")) not in codes:
                return True
        return False

    return search


def plain_search(sets: Iterable[WordSet]) -> Callable[[str], bool]:
    """Whether a plain line holds a word of one of ``sets``, at worst a word that only looks like
    one. A line without the letter of any set, G00 to G03 aside where no set holds them (nearly
    every line of a CAM program: axis words and straight or circular moves), is passed over
    before the full pattern is tried."""
    sets = tuple(sets)
    if not sets:
        return lambda line: False
    letters = {s.letter.upper() for s in sets}
    quick = f"[{''.join(sorted(x + x.lower() for x in letters))}]"
    g_sets = [s for s in sets if s.letter.upper() == "G"]
    if g_sets and all(s.misses(code) for s in g_sets for code in _MOST_G):
        # not a G00-G03: one class of letters, then the G words that are one of those looked
        # behind (a pattern that starts with one class is searched twice as fast as a choice)
        quick += rf"(?!(?<=[Gg])\+?0*[0-3](?:\.0*)?{_END})"
    first = re.compile(quick).search
    outside = [s for s in sets if s.outside is not None and not s.point]
    rest = [s for s in sets if s not in outside]
    full = re.compile(rf"(?:^|[ \t])(?:{'|'.join(s.pattern() for s in rest)})").search if rest else None
    other = _outside_search(outside) if outside else None

    def search(line: str) -> bool:
        if first(line) is None:
            return False
        return (full is not None and full(line) is not None) or (other is not None and other(line))

    return search
