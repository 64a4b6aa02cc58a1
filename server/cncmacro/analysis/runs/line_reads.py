"""The variables a line of a program reads and writes, told from its text.

Two judgements of a run's findings ask where the values that decided the run came from: is a
loop one the control never leaves (``endless_loops.py``), is an alarm one every run of the
program reaches (``sure_alarms.py``). Both read the lines the run went through as text,
comments left out: a ``#n`` that is the target of an assignment (``#n=`` at the start of a
statement, after an optional block delete and N number, or after ``THEN``) is written; every
other ``#n`` is read.
A read through ``#[...]`` or of a ``#_`` name (a 30i system variable or a named common) has no
number: it is ``INDIRECT``, a value the text cannot place. A line that draws a random number
(``RAND[..]``, ``SRAND[..]``: ``draws``) reads a value no run can foresee.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from ...machine.expressions import RANDOM_FUNCTIONS

INDIRECT = -1

_COMMENT = re.compile(r"\([^)]*\)?")
_TARGET = re.compile(r"^\s*(?:/\d?\s*)?(?:N\d+\s*)?(?P<hash>#)\s*(\d+|\[.*?\])\s*=(?!=)", re.I)
_THEN_TARGET = re.compile(r"(?<![A-Z])THEN\s*(?P<hash>#)\s*(\d+|\[.*?\])\s*=(?!=)", re.I)
_REFERENCE = re.compile(r"#\s*(\d+|\[|_)")
# a random number drawn: RAND[..], SRAND[..] (GSK980TDi, machine/expressions.py's RANDOM_FUNCTIONS)
_DRAW = re.compile(rf"(?:{'|'.join(sorted(RANDOM_FUNCTIONS, key=len, reverse=True))})\s*\[", re.IGNORECASE)


def code_of(text: str) -> str:
    """``text`` without its comments."""
    return _COMMENT.sub("", text)


def _target(code: str) -> re.Match[str] | None:
    """The assignment's target of ``code``: at its start, or after ``THEN``."""
    target = _TARGET.match(code)
    if target is None:
        target = _THEN_TARGET.search(code)
    return target


def draws(code: str) -> bool:
    """Whether ``code`` (comments left out) draws a random number (``RAND[..]``, ``SRAND[..]``)."""
    return _DRAW.search(code) is not None


def written(code: str) -> int | None:
    """The variable the statement ``code`` (comments left out) assigns, ``INDIRECT`` for
    ``#[..]=``; None when it assigns none."""
    target = _target(code)
    if target is None:
        return None
    return int(target.group(2)) if target.group(2).isdigit() else INDIRECT


def reads(code: str, written_at: int | None = None) -> Iterator[int]:
    """The numbers of the variables ``code`` (comments left out) reads, ``INDIRECT`` for a
    read through ``#[..]`` or a ``#_`` name. ``written_at``: the column of another ``#`` that is
    written, not read (a macro A block's ``P#n``)."""
    target = _target(code)
    for ref in _REFERENCE.finditer(code):
        if target is not None and ref.start() == target.start("hash"):
            continue  # the assignment's own target (the index of a #[..]= is read)
        if ref.start() == written_at:
            continue
        number = ref.group(1)
        yield int(number) if number.isdigit() else INDIRECT
