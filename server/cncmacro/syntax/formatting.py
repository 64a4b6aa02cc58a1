"""Formatting program text: words in upper case, one space between words or none, comments
aligned if asked; nothing else changes (docs/editor.md "Formatting").

A line is rewritten from the grammar's own tokens (``tokens.code_tokens``) and the block it
parses to: comments ``( )``, the text of ``DPRNT[...]``/``BPRNT[...]`` and bracketed program
names (``P[cut]``) keep their case and text; a keyword written shortened (``WH``) stays
shortened; the indentation before the block, a block delete ``/n`` and whatever follows an
end-of-block ``;`` stay as written. ``spaced`` puts one space between the words of a block (the
NC words, the label, each macro statement, and around the macro keywords ``IF THEN GOTO WHILE DO
END ELSE ENDIF`` and the word operators ``EQ``…``AND``…``MOD``), nothing inside a word or expression;
``compact`` puts none. Each formatted line is parsed again and must give the same block, columns
aside, or it is left as it was; a line with a syntax error, a ``%`` line and the lines after the
tape's end are never touched. Formatting formatted text changes nothing.
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from .block_parser import MAX_BLOCK_CHARS, parse_block
from .lines import prepare
from .nodes import LOGICAL_SYMBOLS, Block, If
from .tokens import CodeToken, code_tokens

SPACED = "spaced"
COMPACT = "compact"
SPACINGS = (SPACED, COMPACT)
ALIGN_LIMIT = 48  # comments are aligned at most at this column; a longer block keeps one space

_KEYWORDS = frozenset({"IF", "THEN", "GOTO", "WHILE", "DO", "END", "ELSE", "ENDIF"})
_OPERATORS = frozenset({"RELOP", "ADDOP", "MULOP"})
_VERBATIM = frozenset({"BRACKET_NAME", "DPRNT_ARGS"})
_DELETE = re.compile(r"[ \t]*/[ \t]*(?:[1-9](?![0-9.]))?")
_BLANKS = re.compile(r"[ \t]+")


@dataclass(frozen=True, slots=True)
class FormatOptions:
    spacing: str = SPACED
    align_comments: bool = False


@dataclass(frozen=True, slots=True)
class _Line:
    head: str  # indentation, block delete, code with the comments inside it
    comments: str  # the comments after the last word, joined
    end: str  # ';' and what follows it, as written


def _word_operator(t: CodeToken) -> bool:
    """An operator that is a word (``AND``, ``GT``), or ``&&`` / ``||`` that stand for one: spaced."""
    return t.kind in _OPERATORS and (t.text.strip().isalpha() or t.text.strip() in LOGICAL_SYMBOLS)


def _item_starts(block: Block) -> set[int]:
    starts: set[int] = set()
    if block.label_span:
        starts.add(block.label_span[0])
    if block.program_span:
        starts.add(block.program_span[0])
    starts.update(w.start for w in block.words)
    for s in block.statements:
        starts.add(s.start)
        if isinstance(s, If) and s.then is not None:
            starts.add(s.then.start)
        if isinstance(s, If) and s.m99 is not None:  # [cond] M99 P n: M99 and P are words
            starts.update(w.start for w in s.m99)
    return starts


def _token_text(t: CodeToken) -> str:
    return t.text if t.kind in _VERBATIM else _BLANKS.sub("", t.text).upper()


def _spaced_between(a: tuple[int, str, Any], b: tuple[int, str, Any], starts: set[int]) -> bool:
    if a[1] == "comment" or b[1] == "comment":
        return True
    ta, tb = a[2], b[2]
    if tb.start in starts:
        return True
    if ta.kind in _KEYWORDS or tb.kind in _KEYWORDS:
        return True
    return _word_operator(ta) or _word_operator(tb)


def _shape(node: Any) -> Any:
    """A node as nested tuples without its columns, for comparing two parses of a block."""
    if isinstance(node, Block):
        return (
            node.label, node.program, node.title, node.block_delete, node.tape, _shape(node.words),
            _shape(node.corners), _shape(node.statements), tuple((c.text, c.closed) for c in node.comments),
            tuple((str(p.message), p.severity) for p in node.problems), tuple((a.text.upper(), a.word)
                                                                              for a in node.abbreviations),
        )  # fmt: skip
    if isinstance(node, tuple | list):
        return tuple(_shape(x) for x in node)
    if dataclasses.is_dataclass(node) and not isinstance(node, type):
        fields = [_shape(getattr(node, f.name)) for f in dataclasses.fields(node) if f.name not in ("start", "end")]
        return (type(node).__name__, *fields)
    return node


@lru_cache(maxsize=1 << 16)
def _format(line: str, spacing: str) -> _Line | None:
    """The pieces of ``line`` formatted, or None to leave it as it is (kept per line text: a
    CAM program repeats its lines)."""
    if len(line) > MAX_BLOCK_CHARS or not line.strip():
        return None
    block = parse_block(line)
    if block.tape or any(p.severity == "error" for p in block.problems):
        return None
    if block.plain is not None:  # address-number words and blanks only: no tokens needed
        indent = line[: len(line) - len(line.lstrip(" \t"))]
        plain = _Line(indent + (" " if spacing == SPACED else "").join(block.plain.upper().split()), "", "")
        return plain if spacing == SPACED or _shape(parse_block(plain.head)) == _shape(block) else None
    prep = prepare(line)
    code = prep.code
    semi = len(line)
    for i, ch in enumerate(line):
        if ch in ";\uff1b" and not any(c.start <= i < c.end for c in prep.comments):
            semi = i
            break
    tokens = code_tokens(code[:semi]) if code[:semi].strip() else []
    if tokens is None:
        return None
    indent = line[: len(line) - len(line.lstrip(" \t"))]
    head = indent
    if block.block_delete is not None:
        m = _DELETE.match(line)
        if m is None:
            return None
        head += _BLANKS.sub("", m.group(0)) + (" " if spacing == SPACED and tokens else "")
    pieces: list[tuple[int, str, Any]] = [(t.start, "token", t) for t in tokens]
    pieces += [(c.start, "comment", line[c.start : c.end]) for c in prep.comments if c.start < semi]
    pieces.sort(key=lambda p: p[0])
    last_code = max((i for i, p in enumerate(pieces) if p[1] == "token"), default=-1)
    starts = _item_starts(block)
    out: list[str] = []
    for i, p in enumerate(pieces[: last_code + 1] if last_code >= 0 else pieces):
        if i and spacing == SPACED and _spaced_between(pieces[i - 1], p, starts):
            out.append(" ")
        out.append(_token_text(p[2]) if p[1] == "token" else p[2])
    trailing = [p[2] for p in pieces[last_code + 1 :]] if last_code >= 0 else []
    end = line[semi:].rstrip(" \t")
    formatted = _Line(head + "".join(out), (" " if spacing == SPACED else "").join(trailing), end)
    again = parse_block(_join(formatted, spacing, None))
    try:
        if _shape(again) != _shape(block):
            return None
    except RecursionError:  # an expression nested too deeply to compare (600 chained operators): as it is
        return None
    return formatted


def _join(f: _Line, spacing: str, column: int | None) -> str:
    if not f.comments:
        return f.head + f.end
    gap = ""
    if f.head.strip():
        if column is not None and len(f.head) < column:
            gap = " " * (column - len(f.head))
        elif spacing == SPACED or column is not None:
            gap = " "
    return f.head + gap + f.comments + f.end


class FormattingStopped(Exception):
    """``format_lines`` was told to stop (``stopped``) before it ended: nothing is changed."""


STOP_EVERY = 1000  # lines formatted between two looks at ``stopped``


def format_lines(
    lines: Sequence[str],
    first: int,
    last: int,
    options: FormatOptions,
    read_end: int | None = None,
    stopped: Callable[[], bool] | None = None,
) -> dict[int, str]:
    """The new text of each line from ``first`` to ``last`` (inclusive) that formatting changes;
    ``read_end`` is the line of the tape's closing ``%`` (the lines from it on are not touched).
    Comments after a block are aligned over these lines when ``options.align_comments``.
    ``stopped`` is asked every ``STOP_EVERY`` lines: when it says so, ``FormattingStopped``."""
    stop = min(last + 1, len(lines), len(lines) if read_end is None else read_end)
    formatted: dict[int, _Line] = {}
    for i in range(max(0, first), stop):
        if stopped is not None and i % STOP_EVERY == 0 and stopped():
            raise FormattingStopped
        f = _format(lines[i], options.spacing)
        if f is not None:
            formatted[i] = f
    column = None
    if options.align_comments:
        widths = [len(f.head) for f in formatted.values() if f.comments and f.head.strip()]
        fitting = [w for w in widths if w < ALIGN_LIMIT]
        column = max(fitting) + 1 if fitting else None
    out: dict[int, str] = {}
    for i, f in formatted.items():
        text = _join(f, options.spacing, column)
        if text != lines[i]:
            out[i] = text
    return out
