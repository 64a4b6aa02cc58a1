"""Semantic tokens: what the server knows better than a grammar can, and nothing else.

A TextMate grammar already colours comments, alarm texts, numbers, address letters and G/M
codes well; a token over any of them could only take a colour away (a ``G`` coloured apart from
its ``90``, an alarm text coloured as a comment). So the tokens are the words whose meaning
hangs on the dialect or the parse: variables by class as the dialect has them (``local``,
``common``, ``persistent``, ``system`` with ``readonly`` where the table says so, ``vacant`` #0
and ``undefined`` numbers), the keywords, functions and operators of the dialect's table
(``WH`` as WHILE where the control reads abbreviations), labels and program numbers. Every
statement word, ``THEN`` as much as ``IF``, is a keyword. The VS Code extension maps each
token to the grammar's own scope (``semanticTokenScopes`` in package.json), so a theme gives
both the same colour.

Tokens are found per line by a small scanner that also works on lines that do not parse, with
the label and program spans taken from the parsed block; a line's tokens are cached by its
text, so after an edit only new lines are scanned. ``full``, ``full/delta`` (one edit: what changed
between the common start and end of the previous answer and this one) and ``range`` requests
are served; a whole document is encoded in steps of a few milliseconds (``editor_steps.py``),
the other requests answered between the steps. A line of address words only (``Block.plain``:
most of a CAM file) has no token and is passed over without a look at its text.
"""

from __future__ import annotations

import itertools
import re
import time
from functools import cache
from typing import TYPE_CHECKING

from lsprotocol import types

from ..dialects import describe, tables
from ..dialects.dialect import Dialect
from ..syntax.block_parser import MAX_BLOCK_CHARS
from ..syntax.nodes import Block
from .documents import OpenDocument
from .editor_steps import STEP_SECONDS, between_steps
from .positions import Encoding

PIECE_LINES = 500  # lines of a whole document's tokens encoded between two looks at the clock

if TYPE_CHECKING:
    from .server import CncMacroServer

TOKEN_TYPES = ["keyword", "function", "operator", "variable", "label", "namespace"]
TOKEN_MODIFIERS = ["local", "common", "persistent", "system", "readonly", "vacant", "undefined"]
LEGEND = types.SemanticTokensLegend(token_types=TOKEN_TYPES, token_modifiers=TOKEN_MODIFIERS)
_T = {name: i for i, name in enumerate(TOKEN_TYPES)}
_M = {name: 1 << i for i, name in enumerate(TOKEN_MODIFIERS)}
_CLASS_MODIFIER = {describe.NULL: "vacant"}  # a variable class -> its modifier, where the names differ

_SCAN = re.compile(
    r"(?P<comment>\([^)]*\)?)|(?P<end>[;\uff1b].*)|(?P<var>#\d+)|(?P<named>#_[A-Za-z0-9_]+)|(?P<word>[A-Za-z]+)"
)

Token = tuple[int, int, int, int]  # start, end (code points), type, modifiers


# a row's kind in the dialect's function table -> the token type of its name
_TOKEN_TYPE = {tables.FUNCTION: "function", tables.OPERATOR: "operator", tables.STATEMENT: "keyword"}


@cache
def _token_types(dialect_name: str) -> dict[str, str]:
    """The token type of each name in the dialect's function table, by its row's ``kind``: a
    function, an operator, or a statement word, coloured as a keyword (``IF``, ``THEN``, ``DO``)."""
    from ..dialects import get_dialect

    out: dict[str, str] = {}
    for f in get_dialect(dialect_name).functions():
        out.setdefault(f.name, _TOKEN_TYPE[f.kind])
    return out


@cache
def _letter_names(dialect_name: str) -> bool:
    """Whether a name of the dialect's table is one letter, which a line of address words
    (``Block.plain``) could hold."""
    return any(len(name) == 1 for name in _token_types(dialect_name))


def line_tokens(text: str, block: Block, dialect: Dialect) -> list[Token]:
    """The tokens of one line. Comments (alarm texts too) and ``;`` tails are read only to be
    passed over; numbers, address letters and G/M codes get none."""
    kinds = _token_types(dialect.name)
    shortened = {a.start: a for a in block.abbreviations}  # ``WH`` is coloured as WHILE
    label = block.label_span
    prog = block.program_span
    out: list[Token] = []
    for m in _SCAN.finditer(text):
        kind = m.lastgroup
        s, e = m.start(), m.end()
        if label and label[0] <= s < label[1]:
            if s == label[0]:
                out.append((label[0], label[1], _T["label"], 0))
            continue
        if prog and prog[0] <= s < prog[1]:
            if s == prog[0]:
                out.append((prog[0], prog[1], _T["namespace"], 0))
            continue
        if kind == "var":
            n = int(m.group(0)[1:])
            cls = describe.variable_class(n, dialect)
            mods = _M[_CLASS_MODIFIER.get(cls, cls)]
            if cls == describe.SYSTEM:
                row = dialect.system_variable(n)
                if row is not None and row.access == "r":
                    mods |= _M["readonly"]
            out.append((s, e, _T["variable"], mods))
        elif kind == "named":  # a FANUC 30i system variable name
            out.append((s, e, _T["variable"], _M["system"]))
        elif kind == "word":
            word = m.group(0).upper()
            a = shortened.get(s)
            if a is not None and a.end == e:
                word = a.word
            k = kinds.get(word)
            if k is not None:
                out.append((s, e, _T[k], 0))
    return out


class _TokenCache:
    def __init__(self, limit: int = 200_000) -> None:
        self.limit = limit
        self.data: dict[tuple[object, ...], list[Token]] = {}

    def get(self, text: str, block: Block, dialect: Dialect) -> list[Token]:
        key = (text, dialect.name, dialect.common_ranges, dialect.extra_rows)
        hit = self.data.get(key)
        if hit is None:
            if len(self.data) >= self.limit:
                self.data.clear()
            hit = self.data[key] = line_tokens(text, block, dialect)
        return hit


_cache = _TokenCache()


def encode(doc: OpenDocument, first: int, last: int, encoding: Encoding) -> list[int]:
    """The LSP integer encoding of the tokens on lines ``first`` to ``last`` (inclusive)."""
    data: list[int] = []
    prev_line = 0
    prev_start = 0
    lines = doc.parsed.lines
    block_at = doc.parsed.block_at  # a line of a huge file not parsed yet is parsed on its own
    dialect = doc.dialect
    pass_plain = not _letter_names(dialect.name)
    for i in range(max(first, 0), min(last, len(lines) - 1) + 1):
        text = lines[i]
        if not text or len(text) > MAX_BLOCK_CHARS:
            continue  # a line too long to be a block is not read, so not coloured either
        block = block_at(i)
        if block.plain is not None and pass_plain:
            continue  # address words only (most of a CAM file): nothing the grammar does not colour
        plain = encoding.plain(text)  # looked at once per line, not once per token
        for s, e, typ, mods in _cache.get(text, block, dialect):
            if plain:
                cs, length = s, e - s
            else:
                cs = encoding.to_client(text, s)
                length = encoding.to_client(text, e) - cs
            if i == prev_line:
                data += (0, cs - prev_start, length, typ, mods)
            else:
                data += (i - prev_line, cs, length, typ, mods)
            prev_line, prev_start = i, cs
    return data


async def encode_document(doc: OpenDocument, encoding: Encoding) -> list[int]:
    """The tokens of the whole of ``doc``, encoded ``PIECE_LINES`` lines at a time in steps
    (``editor_steps.py``), the editor's other requests answered between the steps (a CAM file of
    a million lines takes a good part of a second); an edit meanwhile starts the encoding again,
    a few times at most."""
    for _ in range(3):
        version = doc.version
        data: list[int] = []
        last_line = 0  # the line of the last token so far
        count = len(doc.lines)
        end = time.perf_counter() + STEP_SECONDS
        for first in range(0, count, PIECE_LINES):
            part = encode(doc, first, min(first + PIECE_LINES, count) - 1, encoding)
            if part:  # its first token's line counts from line 0: make it count from the last token
                line = part[0]
                part[0] = line - last_line
                last_line = line + sum(part[5::5])
                data += part
            if time.perf_counter() >= end:
                await between_steps()
                end = time.perf_counter() + STEP_SECONDS
                if doc.version != version:
                    break
        else:
            return data
    return data


def register(server: CncMacroServer) -> None:
    @server.feature(
        types.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL,
        types.SemanticTokensRegistrationOptions(
            legend=LEGEND, full=types.SemanticTokensFullDelta(delta=True), range=True
        ),
    )
    async def full(ls: CncMacroServer, params: types.SemanticTokensParams) -> types.SemanticTokens | None:
        doc = ls.documents.get(params.text_document.uri)
        if doc is None:  # not open: the empty answer (documents.py)
            return None
        data = await encode_document(doc, ls.documents.encoding)
        return types.SemanticTokens(data=data, result_id=_remember(doc.uri, data))

    @server.feature(types.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL_DELTA)
    async def full_delta(
        ls: CncMacroServer, params: types.SemanticTokensDeltaParams
    ) -> types.SemanticTokens | types.SemanticTokensDelta | None:
        doc = ls.documents.get(params.text_document.uri)
        if doc is None:  # not open: the empty answer (documents.py)
            return None
        data = await encode_document(doc, ls.documents.encoding)
        old = _previous.get(doc.uri)
        result_id = _remember(doc.uri, data)
        if old is None or old[0] != params.previous_result_id:
            return types.SemanticTokens(data=data, result_id=result_id)
        return types.SemanticTokensDelta(edits=delta_edits(old[1], data), result_id=result_id)

    @server.feature(types.TEXT_DOCUMENT_SEMANTIC_TOKENS_RANGE, LEGEND)
    def range_(ls: CncMacroServer, params: types.SemanticTokensRangeParams) -> types.SemanticTokens | None:
        doc = ls.documents.get(params.text_document.uri)
        if doc is None:  # not open: the empty answer (documents.py)
            return None
        r = params.range
        return types.SemanticTokens(data=encode(doc, r.start.line, r.end.line, ls.documents.encoding))


_previous: dict[str, tuple[str, list[int]]] = {}  # URI -> the last full answer's result id and data
_PREVIOUS_LIMIT = 32
_ids = itertools.count(1)


def _remember(uri: str, data: list[int]) -> str:
    if uri not in _previous and len(_previous) >= _PREVIOUS_LIMIT:
        del _previous[next(iter(_previous))]
    result_id = str(next(_ids))
    _previous[uri] = (result_id, data)
    return result_id


def delta_edits(old: list[int], new: list[int]) -> list[types.SemanticTokensEdit]:
    """One edit turning ``old`` into ``new``: what lies between their common start and end."""
    n = min(len(old), len(new))
    p = _common_start(old, new, n)
    q = _common_start(old[::-1], new[::-1], n - p)
    if p == len(old) == len(new):
        return []
    return [types.SemanticTokensEdit(start=p, delete_count=len(old) - p - q, data=new[p : len(new) - q])]


def _common_start(a: list[int], b: list[int], n: int) -> int:
    """How many of the first ``n`` items ``a`` and ``b`` share: compared a slice at a time, then
    one at a time in the slice that differs (a million-line file's tokens are millions of ints)."""
    p = 0
    step = 4096
    while step:
        while p + step <= n and a[p : p + step] == b[p : p + step]:
            p += step
        step //= 8
    return p
