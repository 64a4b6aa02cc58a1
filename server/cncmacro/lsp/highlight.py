"""Document highlight: the cursor on a variable, a label or a program marks each of its uses in
the file.

On ``#105`` every read and write of ``#105`` in the document is marked, writes (``#105=...``) as
Write and the others as Read; a local (``#1``–``#33``) only within its O program, where it
lives. On an N label, or on a jump's number (``GOTO 100``, ``M99 P100``, ``M98 Q100``, the P of
a Haas ``M97``), the labels N100 of its program are marked as Write and each jump to it as Read.
On an O header's number, or on the word of a call that names a program (``G65 P9100``,
``G66 P9100``, ``M98 P9100``, with the profile's count digits: ``M98 P30040`` names O0040; a
machine file's call code), the headers of that program in the file are marked as Write and each
call to it as Read; what a call names is ``analysis/indexes/call_sites.py``'s, as for go to definition.
Where things are comes from the document's site index (``analysis/indexes/site_index.py``); in a huge
file whose index is still being made in steps (``site_steps.py``) nothing is marked meanwhile,
rather than the editor waiting seconds at each move of the cursor.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from lsprotocol import types

from ..analysis.indexes.call_sites import calls_of_program
from ..analysis.indexes.sites import label_jumps
from ..dialects import describe
from ..library.machine_file import CallCode
from ..syntax.nodes import Var
from ..syntax.walk import nodes_at
from .cursor import Cursor, cursor_at
from .navigation import label_under, machine_calls, program_under
from .site_steps import index_soon

if TYPE_CHECKING:
    from .server import CncMacroServer

READ = types.DocumentHighlightKind.Read
WRITE = types.DocumentHighlightKind.Write


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_HIGHLIGHT)
    def document_highlight(
        ls: CncMacroServer, params: types.DocumentHighlightParams
    ) -> list[types.DocumentHighlight] | None:
        cur = cursor_at(ls, params.text_document.uri, params.position)
        if cur is None:
            return None
        if not cur.doc.sites.ready:  # a huge file not indexed yet: nothing marked until it is
            index_soon(cur.doc.sites)
            return None
        return highlights(cur, machine_calls(ls, cur.doc.path))


def highlights(cur: Cursor, calls: Mapping[str, CallCode] | None = None) -> list[types.DocumentHighlight] | None:
    """The uses of the label, program or variable under the cursor, in document order, or None
    (``calls``: the machine file's call codes)."""
    label = label_under(cur)
    if label is not None:
        return label_highlights(cur, label[0])
    program = program_under(cur, calls)
    if program is not None:
        return program_highlights(cur, program[0], calls)
    for node in reversed(nodes_at(cur.block, cur.column)):
        if isinstance(node, Var):
            return variable_highlights(cur, node.number)
    return None


def label_highlights(cur: Cursor, label: int) -> list[types.DocumentHighlight]:
    doc = cur.doc
    program = doc.parsed.program
    unit = program.unit_at(cur.line)
    out: list[tuple[int, int, int, types.DocumentHighlightKind]] = []
    for i in program.label_lines(label, unit):
        b = doc.block(i)
        if b is not None and b.label_span:
            out.append((i, b.label_span[0], b.label_span[1], WRITE))
    out.extend((i, j.start, j.end, READ) for i, j in label_jumps(doc, unit.start, unit.end, label))
    return _marks(cur, sorted(out))


def program_highlights(cur: Cursor, number: int, calls: Mapping[str, CallCode] | None) -> list[types.DocumentHighlight]:
    """The O``number`` headers of the document (Write) and its calls of that program (Read)."""
    doc = cur.doc
    out: list[tuple[int, int, int, types.DocumentHighlightKind]] = []
    for unit in doc.parsed.program.units:
        b = doc.block(unit.start)
        if unit.number == number and b is not None and b.program == number and b.program_span:
            out.append((unit.start, b.program_span[0], b.program_span[1], WRITE))
    for i, site in calls_of_program(doc.lines, doc.block, number, doc.dialect, calls):
        out.append((i, site.target.start, site.target.end, READ))
    return _marks(cur, sorted(out))


def variable_highlights(cur: Cursor, number: int) -> list[types.DocumentHighlight]:
    doc = cur.doc
    start, end = 0, None
    if describe.variable_class(number, doc.dialect) == describe.LOCAL:
        unit = doc.parsed.program.unit_at(cur.line)
        start, end = unit.start, unit.end
    uses = doc.sites.variable_uses(number, start, end)
    return _marks(cur, [(i, s.start, s.end, WRITE if s.write else READ) for i, s in uses])


def _marks(
    cur: Cursor, found: list[tuple[int, int, int, types.DocumentHighlightKind]]
) -> list[types.DocumentHighlight]:
    return [types.DocumentHighlight(cur.range(start, end, line), kind) for line, start, end, kind in found]
