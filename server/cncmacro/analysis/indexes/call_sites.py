"""A call on one block that names what it calls (``CallSite``), for the static checks and the
editor features alike, and the program calls the editor navigates (``call_site``, ``calls_on``,
``calls_of_program``): ``G65``/``G66``, ``M98``/``M198``, or a code that the machine file's
``[calls]`` makes a call, with the word that names its program.

What a block calls is ``machine.calls.recognise_call``'s (``M98 P30040`` is O0040 three times;
``G65 P`` has at most the dialect's digits); ``call_site`` keeps the calls that name a program
by a literal word. A local call (Haas ``M97 P n``) names a label of the program itself and is
navigated as a jump; the static checks (``call_checks.py``) make a ``CallSite`` of it, and of an
``M98 Q`` on the current program, to look for the label, and read a target's constant value
where the editor reads only a literal.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass

from ...dialects.dialect import Dialect
from ...library.machine_file import CallCode
from ...machine.calls import call_word_pattern, recognise_call
from ...syntax.nodes import Block, Word


@dataclass(frozen=True, slots=True)
class CallSite:
    """A call on one block: ``kind`` is ``G65``, ``G66``, ``M98``, ``M198``, the profile's local call
    (Haas ``M97``) or the machine file's code (``G100``); the program is named by ``number`` or
    (gsk980tdi ``P[CUT]``) ``name``, neither for ``M98 Q`` or ``M97 P`` on the current program.
    ``target`` is the word that names it (P, the configured code itself; the M word of an
    ``M98 Q`` without P), ``code`` the word that makes the call, ``arguments`` the words that fill
    locals (a macro call's). ``label`` is the literal label the call starts at (``M98 Q``,
    ``M97 P``), ``label_span`` its columns and ``label_letter`` the address that names it."""

    kind: str
    number: int | None
    name: str | None
    target: Word
    code: Word
    arguments: tuple[Word, ...] = ()
    label: int | None = None
    label_span: tuple[int, int] = (0, 0)
    label_letter: str = "Q"

    @property
    def start(self) -> int:
        """The first column of the word that names what is called."""
        return self.target.start

    @property
    def end(self) -> int:
        """The column after the word that names what is called."""
        return self.target.end


def call_site(block: Block, dialect: Dialect, calls: Mapping[str, CallCode] | None = None) -> CallSite | None:
    """The program call this block makes, if it names its program (``calls``: the machine
    file's call codes)."""
    if block.plain is not None and not calls and "P" not in block.plain.upper():
        return None  # a line of plain words without P: no word of it is read
    call = recognise_call(block.words, dialect, calls)
    if call is None or call.arithmetic or call.local or call.target is None:
        return None  # G65 Hm P Q R is macro arithmetic and branches (docs/semantics.md §7), not a call
    return CallSite(call.kind, call.number, call.name, call.target, call.code, call.arguments)


def calls_on(blocks: list[Block], lines: Iterable[int], dialect: Dialect,
             calls: Mapping[str, CallCode] | None = None) -> Iterator[tuple[int, Block, CallSite]]:  # fmt: skip
    """(line, block, call) for each of ``lines`` whose block calls a program it names."""
    for i in lines:
        b = blocks[i]
        site = call_site(b, dialect, calls)
        if site is not None:
            yield i, b, site


def calls_of_program(
    texts: Sequence[str],
    block_at: Callable[[int], Block | None],
    number: int,
    dialect: Dialect,
    calls: Mapping[str, CallCode] | None = None,
) -> Iterator[tuple[int, CallSite]]:
    """(line, call) for each line of a document (``texts``, its blocks by ``block_at``) that calls
    program ``number``; only the lines with a call word (``call_word_pattern``) are parsed."""
    word = re.compile(call_word_pattern(calls or {})).search
    for i, text in enumerate(texts):
        if word(text) is None:
            continue
        b = block_at(i)
        site = None if b is None else call_site(b, dialect, calls)
        if site is not None and site.number == number:
            yield i, site
