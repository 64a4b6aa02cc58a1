"""Whether a program read under a mill profile was written for a lathe (docs/profiles.md,
"How a lathe program is recognised").

A FANUC lathe program read as a mill runs without an error and wrongly: ``G92 X29.2 Z-30. F1.5``
(a thread) shifts the coordinates, U and W move nothing and ``G99 F0.2`` is no feed per
revolution. Nothing in one block proves a lathe, so the signs are counted:

- **strong** (one is enough): a multiple repetitive cycle ``G70``–``G73`` with P and Q naming N
  labels of the program (the finishing shape N(P)..N(Q)) and no X, Y, Z or R word (a mill's
  ``G73`` peck drilling has them); ``G76`` in two blocks, the first with P and no axis word, the
  next one with the thread's end point (a mill's ``G76`` fine boring is one block with its hole);
- **ordinary** (two different ones are needed): a 4-digit tool word, tool and offset
  (``T0101``); ``G50`` with S (the spindle clamp; a mill's G50 cancels scaling); ``G96``
  (constant surface speed); U or W written as a move where the profile has no such axis; ``G99``
  with F below 1 (a feed per revolution; a mill's G99 is the R level of a drilling cycle);
  ``G92`` with F and an X and a Z (a thread; a mill's G92 sets coordinates); a ``G70``–``G73``
  P Q block whose labels the program lacks.

X written as a diameter is no sign: on a mill's X the text alone cannot tell it. ``block_signs``
reads one block (kept per line with its ``LineFacts``), ``lathe_evidence`` weighs the signs of
a program.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from ...dialects import Dialect
from ...machine.calls import code_value, g_code_name
from ...machine.word_sets import WordSet
from ...syntax.nodes import Number, Word
from ...syntax.program import Program

ROUGHING = "roughing"  # G70-G73 P Q, no X Y Z R
THREAD_FIRST = "thread-first"  # G76 P.. without an axis word
THREAD_SECOND = "thread-second"  # G76 with the thread's end point
TOOL_OFFSET = "tool-offset"
SPINDLE_CLAMP = "spindle-clamp"
SURFACE_SPEED = "surface-speed"
INCREMENTAL = "incremental"
FEED_PER_REV = "feed-per-revolution"
THREAD_G92 = "thread-g92"

_SHAPE_CYCLES = (70.0, 71.0, 72.0, 73.0)
_LATHE_CYCLES = frozenset((*_SHAPE_CYCLES, 74.0, 75.0, 76.0))
_NOT_MOVES = frozenset((4.0, 10.0, 65.0, 66.0))  # dwell, data setting, macro calls: U and W are no moves
_SIGN_CODES = frozenset((50.0, *_LATHE_CYCLES, 92.0, 96.0, 99.0))
_INCREMENTAL = ("U", "W")
_OTHER_LETTERS = frozenset(("T", *_INCREMENTAL))  # the signs that need no G code
_SIGN_WHOLE = frozenset(int(c) for c in _SIGN_CODES)
ORDINARY_NEEDED = 2


@dataclass(frozen=True, slots=True)
class LatheSign:
    """One sign in one block: its kind, the columns of its words, the words as written
    (``G71 P10 Q20``) and, for a ``ROUGHING`` sign, the labels P and Q name."""

    kind: str
    start: int
    end: int
    shown: str
    labels: tuple[int, int] | None = None


def sign_words(dialect: Dialect) -> tuple[WordSet, ...]:
    """The words ``block_signs`` looks at under ``dialect`` (none on a lathe profile), so that a
    plain line holding one is looked at (``call_checks.words_looked_at``)."""
    if dialect.lathe:
        return ()
    return (
        WordSet("G", _SIGN_CODES),
        WordSet("T"),
        *(WordSet(a) for a in _INCREMENTAL if a not in dialect.axes),
    )


def _written(w: Word) -> str:
    """A literal word as written (``T0101``, ``W-10.``); another as its address and ``…``."""
    v = w.value
    return f"{w.letter}{v.text}" if isinstance(v, Number) else f"{w.letter}…"


def block_signs(words: Sequence[Word], dialect: Dialect) -> list[LatheSign]:
    """The lathe signs of a block of NC words (no macro call) read under ``dialect``; none on a
    lathe profile. A sign is in the text: the G codes and the T and F values that make one are
    literal, the other words are counted whatever their value."""
    if dialect.lathe or not _may_sign(words):
        return []
    codes = [(c, w) for w in words if w.letter == "G" and (c := code_value(w)) is not None]
    g = {c for c, _ in codes}
    by: dict[str, Word] = {}  # the first word of each other address, whatever its value
    for w in words:
        if w.letter != "G":
            by.setdefault(w.letter, w)
    out: list[LatheSign] = []

    def add(kind: str, first: Word, *rest: Word, labels: tuple[int, int] | None = None) -> None:
        shown = " ".join([g_code_name(code_value(first)) if first.letter == "G" else _written(first),
                          *(_written(w) for w in rest)])  # fmt: skip
        out.append(LatheSign(kind, first.start, max(w.end for w in (first, *rest)), shown, labels))

    for code, w in codes:
        if code in _SHAPE_CYCLES and "P" in by and "Q" in by and not {"X", "Y", "Z", "R"} & by.keys():
            add(ROUGHING, w, by["P"], by["Q"], labels=_labels(by["P"], by["Q"]))
        elif code == 76.0 and "P" in by and not {"X", "Y", "Z", "U", "W"} & by.keys():
            add(THREAD_FIRST, w, by["P"])
        elif code == 76.0 and ("X" in by or "U" in by) and ("Z" in by or "W" in by):
            add(THREAD_SECOND, w)
        elif code == 50.0 and "S" in by:
            add(SPINDLE_CLAMP, w, by["S"])
        elif code == 96.0:
            add(SURFACE_SPEED, w)
        elif code == 99.0 and "F" in by and 0 < _value(by["F"]) < 1 and not g & dialect.drill_cycles.keys():
            add(FEED_PER_REV, w, by["F"])
        elif code == 92.0 and "F" in by and ("X" in by or "U" in by) and ("Z" in by or "W" in by):
            add(THREAD_G92, w, by.get("X") or by["U"], by.get("Z") or by["W"], by["F"])
    tool = by.get("T")
    if tool is not None and isinstance(tool.value, Number) and len(tool.value.text) == 4 and tool.value.text.isdigit():
        add(TOOL_OFFSET, tool)
    if not g & (_LATHE_CYCLES | _NOT_MOVES):
        moved = next((by[a] for a in _INCREMENTAL if a in by and a not in dialect.axes), None)
        if moved is not None:
            add(INCREMENTAL, moved)
    return out


def _may_sign(words: Sequence[Word]) -> bool:
    """Whether a block may hold a sign: a T, U or W word, or a G code whose whole part (or the
    next whole number, for ``G69.99``) is one of the signs'. Most blocks (moves, arcs) do not,
    and are passed over at this cost only."""
    for w in words:
        letter = w.letter
        if letter == "G":
            v = w.value
            if v.__class__ is not Number:
                continue
            x = v.value
            if int(x) in _SIGN_WHOLE or int(x) + 1 in _SIGN_WHOLE:
                return True
        elif letter in _OTHER_LETTERS:
            return True
    return False


def _value(w: Word) -> float:
    """A literal word's value; 0 for any other (no feed below 1 that a text shows)."""
    v = w.value
    return v.value if isinstance(v, Number) else 0.0


def _labels(p: Word, q: Word) -> tuple[int, int] | None:
    """The N labels that literal whole P and Q words name, else None."""
    a, b = p.value, q.value
    if not isinstance(a, Number) or not isinstance(b, Number) or a.has_point or b.has_point:
        return None
    return int(a.value), int(b.value)


@dataclass(frozen=True, slots=True)
class LatheEvidence:
    """The signs that make a program a lathe's: (line, sign), the strong ones first, each part in
    line order; the finding goes on the first."""

    signs: tuple[tuple[int, LatheSign], ...]


def lathe_evidence(signs: Mapping[int, Sequence[LatheSign]], program: Program) -> LatheEvidence | None:
    """Whether the signs of ``program`` (line -> that line's signs, from ``block_signs``) make
    it a lathe program: a strong sign, or ordinary signs of ``ORDINARY_NEEDED`` different
    kinds. The first sign of each kind is kept for the message; None when the evidence is
    short."""
    strong: list[tuple[int, LatheSign]] = []
    ordinary: dict[str, tuple[int, LatheSign]] = {}
    lines = sorted(k for k in signs if k < program.read_end)
    for i, k in enumerate(lines):
        for s in signs[k]:
            if s.kind == ROUGHING:
                if s.labels is not None and _shape_labelled(program, *s.labels):
                    strong.append((k, s))
                else:
                    ordinary.setdefault(ROUGHING, (k, s))
            elif s.kind == THREAD_FIRST:
                after = _next_thread_block(program, signs, lines[i + 1 :], k)
                if after is not None:
                    strong.append((k, LatheSign(s.kind, s.start, s.end, f"{s.shown} + {after.shown}")))
            elif s.kind != THREAD_SECOND:
                ordinary.setdefault(s.kind, (k, s))
    if not strong and len(ordinary) < ORDINARY_NEEDED:
        return None
    return LatheEvidence((*sorted(_first_of_each(strong), key=_by_line), *sorted(ordinary.values(), key=_by_line)))


def _by_line(found: tuple[int, LatheSign]) -> tuple[int, int]:
    return found[0], found[1].start


def _first_of_each(strong: list[tuple[int, LatheSign]]) -> list[tuple[int, LatheSign]]:
    seen: dict[str, tuple[int, LatheSign]] = {}
    for k, s in strong:
        seen.setdefault(s.kind, (k, s))
    return list(seen.values())


def _shape_labelled(program: Program, p: int, q: int) -> bool:
    """Whether N(P) and N(Q) are labels of the program, N(P) not after N(Q)."""
    first, last = program.labels.get(p), program.labels.get(q)
    return bool(first) and bool(last) and first[0] <= last[0]  # type: ignore[index]


def _next_thread_block(
    program: Program, signs: Mapping[int, Sequence[LatheSign]], later: Sequence[int], k: int
) -> LatheSign | None:
    """The second block of a two-block G76 that starts on line ``k``: the next block with words,
    if it is a G76 with the thread's end point."""
    for j in range(k + 1, program.read_end):
        block = program.blocks[j]
        if block.statements or block.words:
            if later and later[0] == j:
                return next((s for s in signs[j] if s.kind == THREAD_SECOND), None)
            return None
    return None
