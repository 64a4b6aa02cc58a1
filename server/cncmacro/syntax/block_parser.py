"""Parsing one line into a ``Block``: the fast path first, then the lark grammar.

``parse_block`` never raises: a line that does not parse gives a block whose ``problems`` say
why, with a range. Blocks are cached by line text (``BlockCache``), so re-parsing a document
after an edit only parses the lines whose text is new.
"""

from __future__ import annotations

import gc
import re
import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING, cast

from ..bilingual import detail
from .assemble import Items, assemble, assemble_words
from .conditions import BlockError
from .fastpath import plain_words, read_items
from .lines import Prepared, has_special, prepare
from .nodes import Block, Problem

if TYPE_CHECKING:
    from .grammar import GrammarParser

# A line of whitespace-separated address-number words with at most three decimals, not
# starting with N or O and with no O after the first word (``M99 O0810`` ends one program and
# starts the next, assemble.py): the CAM norm (``G01 X12.5 Y-3.``). Its ``split()`` gives exactly its
# words, its axis values are on the 0.001 grid already, and ``assemble_words`` would give it
# neither a label nor a header; the interpreter compiles it straight from its text.
# From Python 3.11 the quantifiers are possessive: a word that fails can never match with
# fewer characters (what would be left is a digit or a point, where a blank or the end must
# follow), so not backtracking into it matches the same lines, a fifth faster. Python 3.10's
# ``re`` has no possessive quantifiers and gets the same pattern without them.
_POSSESSIVE = "+" if sys.version_info >= (3, 11) else ""


def _plain_line_pattern(possessive: str) -> str:
    """The plain-line pattern, with ``possessive`` ("+" or "") after each quantifier (``@``)."""
    number = r"[+-]?@(?:\d{1,15}@(?:\.\d{0,3}@)?@|\.\d{1,3}@)"
    template = r"[ \t]*@[A-MP-Za-mp-z]" + number + r"(?:[ \t]+@[A-NP-Za-np-z]" + number + r")*@[ \t]*@"
    return template.replace("@", possessive)


_PLAIN_LINE = re.compile(_plain_line_pattern(_POSSESSIVE)).fullmatch
# The same pattern with ``\d`` only 0-9, a tenth quicker: opening a file tries it first, and a
# line it does not take goes to ``parse_block``, which tries ``_PLAIN_LINE`` (a line of
# other digits, such as full-width ones, is plain all the same: it is then cached).
_PLAIN_ASCII_LINE = re.compile(_plain_line_pattern(_POSSESSIVE), re.ASCII).fullmatch
# A sequence number at the start of a line: when a plain line follows it (``N10 G01 X5.``,
# a line in ten of a CAM program), the block is made without reading its words.
_LABEL_THEN = re.compile(r"[ \t]*[Nn](\d{1,9})").match


def labelled_plain(line: str) -> Block | None:
    """The block of a sequence number followed by plain words (``N10 G01 X5.``), its words
    read only when asked for (``Block.plain_tail``); None for any other line. It is the block
    the general path builds: the label must be a whole number without a sign or a point, and
    the words after it those of a plain line (not an ``N`` or an ``O`` first, no ``O`` after)."""
    m = _LABEL_THEN(line)
    if m is None:
        return None
    end = m.end()
    if _PLAIN_LINE(line, end) is None:
        return None
    return Block.of_labelled(line[end:], int(m[1]), (m.start(1) - 1, end))


# Real controls read blocks of at most a few hundred characters; a longer line is reported,
# not parsed, so that a huge line costs nothing and cannot stall the editor.
MAX_BLOCK_CHARS = 4096

_idle: list[GrammarParser] = []  # built parsers (lark, node builder) no thread is using
_idle_lock = threading.Lock()


@contextmanager
def _parser() -> Iterator[GrammarParser]:
    """A grammar parser for this thread's use: an idle one, or a new one (building one takes
    a few hundred milliseconds, so they are kept and shared between threads, one at a time)."""
    with _idle_lock:
        p = _idle.pop() if _idle else None
    if p is None:
        p = _new_parser()
    try:
        yield p
    finally:
        with _idle_lock:
            _idle.append(p)


def warm_up() -> None:
    """Build a grammar parser now (on a background thread, say) so that the first line that
    needs the grammar, often the first keystroke that leaves a line unfinished, does not wait
    for it."""
    with _idle_lock:
        if _idle:
            return
    p = _new_parser()
    with _idle_lock:
        _idle.append(p)


def _new_parser() -> GrammarParser:
    """A new grammar parser. The grammar and lark are loaded with the first one: a CAM file
    that the fast path reads whole never needs them (lark alone takes 25 ms to load)."""
    from .grammar import make_parser

    return make_parser()


def parse_with_grammar(code: str, prep: Prepared) -> Block:
    """Parse prepared code with the lark grammar only (no fast path)."""
    from lark.exceptions import UnexpectedInput  # loaded by the parser's making (``_new_parser``)

    from .messages import describe_error

    with _parser() as (lark, builder):
        builder.reset()
        try:
            items = cast(Items, lark.parse(code))  # the builder makes the tree as lark parses
        except UnexpectedInput as err:
            return _failed(prep, describe_error(code, err))
        except BlockError as err:
            problem = Problem(err.message, err.start, err.end, alarm=err.alarm, without_block_if=err.without_block_if)
            return _failed(prep, problem)
        except RecursionError:
            too_deep = detail("the block is nested too deeply to read", "程序段嵌套过深，无法读取")
            return _failed(prep, Problem(too_deep, 0, len(code)))
        return assemble(items, prep)


def parse_block(line: str) -> Block:
    """The block of one line of program text (without its line break)."""
    if len(line) > MAX_BLOCK_CHARS:
        return Block(
            problems=(
                Problem(
                    detail(
                        f"block of {len(line)} characters is too long to be a program line "
                        f"(at most {MAX_BLOCK_CHARS}); not read",
                        f"程序段长 {len(line)} 个字符，超出一行程序的上限（最多 {MAX_BLOCK_CHARS} 个字符），未读取",
                    ),
                    0,
                    len(line),
                ),
            )
        )
    if _PLAIN_LINE(line) is not None:  # the common case
        return Block.of_plain(line)
    labelled = labelled_plain(line)
    if labelled is not None:
        return labelled
    special = has_special(line)  # a comment, ';', '/' or '%'
    statement = "#" in line or "[" in line  # never a line of address-number words alone
    if not special and not statement:
        words = plain_words(line)
        if words is not None:
            if words[0].letter not in ("O", "N") and words[-1].letter != "O":
                return Block(words=tuple(words))
            return assemble_words(words, Prepared(line))  # a label or header: read once, not again
    prep = prepare(line) if special else Prepared(line)
    code = prep.code
    if not code or code.isspace():
        return assemble((), prep)
    if special and not statement:  # else the code is the line, which is not plain words
        words = plain_words(code)
        if words is not None:
            return assemble_words(words, prep)
    items = read_items(code)
    if items is None:
        return parse_with_grammar(code, prep)
    return assemble(items, prep)


# A sequence number at the start of a line, ended by a blank, a letter, '#' or '[' (not by a
# digit or a point): it stays the line's label when the rest of the line does not parse.
_LEADING_LABEL = re.compile(r"[ \t]*[Nn](\d{1,9})(?![\d.])")


def _failed(prep: Prepared, problem: Problem) -> Block:
    """The block of a line that does not parse: only its comments, the problem and a leading
    sequence number before the problem remain. A control searching for ``N2387`` finds it on
    such a line and stops there with the syntax alarm, so a ``GOTO2387`` still lands on it
    (and typing into the coordinates of a label line leaves the program's labels alone)."""
    label = label_span = None
    m = _LEADING_LABEL.match(prep.code)
    if m is not None and m.end() <= problem.start:
        label, label_span = int(m.group(1)), (m.start(1) - 1, m.end())
    return Block(
        label=label,
        label_span=label_span,
        block_delete=prep.block_delete,
        tape=prep.tape,
        comments=prep.comments,
        problems=(*prep.problems, problem),
        structural=prep.tape or label is not None,
    )


@contextmanager
def collector_paused() -> Iterator[None]:
    """Pause Python's cycle collector while many blocks are made at once, then freeze them.

    Blocks hold no reference cycles, yet the collector walks every live object each time a
    generation fills: a 100k-line file is over a million objects, and each full walk costs
    hundreds of milliseconds, during the parse and at any later moment (an edit, a hover).
    Frozen objects are skipped by the collector; they are still freed by reference
    counting when their document goes away.
    """
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        gc.freeze()
        if was_enabled:
            gc.enable()


class BlockCache:
    """Blocks by line text: identical lines share one block, and a line typed again is not
    parsed again. Now and then (before a file is opened, after half as many new entries as it
    held; at the editor's quiet moments) the blocks that nothing but the cache holds any more
    are dropped, so that what no document uses goes (an hour of
    typing leaves nothing behind) at a cost in proportion to what was added. A plain line of
    words (``Block.plain``, also after a label) costs no more to make than to look up, so opening a file makes those
    afresh and caches the lines that take parsing."""

    def __init__(self) -> None:
        self._blocks: dict[str, Block] = {}
        self._added = 0  # entries added since the last sweep
        self.parsed = 0  # lines actually parsed (cache misses), for tests and benchmarks

    def get(self, line: str) -> Block:
        b = self._blocks.get(line)
        if b is None:
            b = parse_block(line)
            self.parsed += 1
            self._add(line, b)
        return b

    def get_many(self, lines: list[str]) -> list[Block]:
        """The blocks of many lines at once (a file being opened)."""
        self._sweep_if_due()
        blocks = self._blocks
        out: list[Block] = []
        append = out.append
        plain = _PLAIN_ASCII_LINE
        of_plain = Block.of_plain
        added = 0
        short = max(map(len, lines), default=0) <= MAX_BLOCK_CHARS  # as good as always: no line to measure again
        for line in lines:
            if short or len(line) <= MAX_BLOCK_CHARS:
                if plain(line) is not None:
                    append(of_plain(line))  # as cheap as a lookup: not cached
                    continue
                labelled = labelled_plain(line)  # N10 G01 X5.: as cheap, and as rarely repeated
                if labelled is not None:
                    append(labelled)
                    continue
            b = blocks.get(line)
            if b is None:
                b = blocks[line] = parse_block(line)
                added += 1
            append(b)
        self.parsed += added
        self._added += added
        return out

    def _add(self, line: str, b: Block) -> None:
        if self._added >= max(SWEEP_LATEST, len(self._blocks)):  # a one-line edit rarely pays for a sweep
            self.sweep()
        self._blocks[line] = b
        self._added += 1

    def _sweep_if_due(self) -> None:
        if self._added >= max(SWEEP_MIN, len(self._blocks) // 2):
            self.sweep()

    def sweep(self) -> None:
        """Drop the blocks that only the cache holds (another thread may add meanwhile: it
        only loses the sharing of a block it took just now)."""
        blocks = self._blocks
        getrefcount = sys.getrefcount
        for line, b in list(blocks.items()):
            if getrefcount(b) <= _ONLY_CACHED:
                blocks.pop(line, None)
        self._added = 0

    def __len__(self) -> int:
        return len(self._blocks)


SWEEP_MIN = 20_000  # new entries before a file being opened sweeps first
SWEEP_LATEST = 200_000  # new entries before a line typed sweeps (the editor sweeps at quiet moments)
# references to a block that only the cache holds, as ``sweep`` counts them: the dict, the item
# tuple of its copy, the loop variable and ``getrefcount``'s argument
_ONLY_CACHED = 4


# The one cache of a process: the documents an editor opens and the files read from disk (the
# workspace index, the program library) share it, so a file already read from its folder costs
# lookups, not a second parse, when it is opened.
shared_cache = BlockCache()
