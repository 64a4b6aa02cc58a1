"""Document highlight: the cursor on a variable, a label or a program marks each of its uses in
the file.

On ``#105`` every read and write of ``#105`` in the document is marked, writes (``#105=...``) as
written and the others as read; a local (``#1``–``#33``) only within its O program, where it
lives. On an N label, or on a jump's number (``GOTO 100``, ``M99 P100``, ``M98 Q100``, the P of
a Haas ``M97``), the labels N100 of its program are marked as written and each jump to it as
read. On an O header's number, or on the word of a call that names a program (``G65 P9100``,
``G66 P9100``, ``M98 P9100``, with the profile's count digits: ``M98 P30040`` names O0040; a
machine file's call code), the headers of that program in the file are marked as written and
each call to it as read; what a call names is ``analysis/indexes/call_sites.py``'s, as for go to
definition. Where things are comes from the document's site index
(``analysis/indexes/site_index.py``), which must be ready (``SiteIndex.ready``).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from ..analysis.indexes.call_sites import calls_of_program
from ..analysis.indexes.sites import label_jumps
from ..dialects import describe
from ..library.machine_file import CallCode
from ..syntax.nodes import Var
from ..syntax.walk import nodes_at
from .source import EditorDocument
from .spans import Span
from .under_cursor import label_under, program_under


@dataclass(frozen=True, slots=True)
class Highlight:
    """One use of the name under the cursor; ``write``: a definition or an assignment."""

    span: Span
    write: bool


def highlights(
    doc: EditorDocument, line: int, column: int, calls: Mapping[str, CallCode] | None = None
) -> list[Highlight] | None:
    """The uses of the label, program or variable at code-point ``column`` of ``line``, in
    document order, or None when there is none there (``calls``: the machine file's call codes)."""
    block = doc.block(line)
    if block is None:
        return None
    label = label_under(doc, block, column)
    if label is not None:
        return label_highlights(doc, line, label[0])
    program = program_under(doc, block, column, calls)
    if program is not None:
        return program_highlights(doc, program[0], calls)
    for node in reversed(nodes_at(block, column)):
        if isinstance(node, Var):
            return variable_highlights(doc, line, node.number)
    return None


def label_highlights(doc: EditorDocument, line: int, label: int) -> list[Highlight]:
    """The N``label`` lines of the program holding ``line`` (written) and its jumps to it (read)."""
    program = doc.parsed.program
    unit = program.unit_at(line)
    out: list[Highlight] = []
    for i in program.label_lines(label, unit):
        b = doc.block(i)
        if b is not None and b.label_span:
            out.append(Highlight(Span(i, b.label_span[0], b.label_span[1]), True))
    out.extend(Highlight(Span(i, j.start, j.end), False) for i, j in label_jumps(doc, unit.start, unit.end, label))
    return sorted(out, key=_order)


def program_highlights(doc: EditorDocument, number: int, calls: Mapping[str, CallCode] | None) -> list[Highlight]:
    """The O``number`` headers of the document (written) and its calls of that program (read)."""
    out: list[Highlight] = []
    for unit in doc.parsed.program.units:
        b = doc.block(unit.start)
        if unit.number == number and b is not None and b.program == number and b.program_span:
            out.append(Highlight(Span(unit.start, b.program_span[0], b.program_span[1]), True))
    for i, site in calls_of_program(doc.lines, doc.block, number, doc.dialect, calls):
        out.append(Highlight(Span(i, site.target.start, site.target.end), False))
    return sorted(out, key=_order)


def variable_highlights(doc: EditorDocument, line: int, number: int) -> list[Highlight]:
    """The reads and writes of ``#number``: a local's within the program holding ``line``."""
    start, end = 0, None
    if describe.variable_class(number, doc.dialect) == describe.LOCAL:
        unit = doc.parsed.program.unit_at(line)
        start, end = unit.start, unit.end
    return [Highlight(Span(i, s.start, s.end), s.write) for i, s in doc.sites.variable_uses(number, start, end)]


def _order(h: Highlight) -> tuple[int, int, int, bool]:
    return h.span.line, h.span.start, h.span.end, h.write
