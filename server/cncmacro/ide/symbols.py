"""The outline of a document (its O programs, with their N labels and nested loops) and the
programs of the workspace, read from the ``Program`` structure of the parser and the workspace
index.

A program is named by its O number, and by its file only when it has no O line: the lines
before a file's first O line that hold no program text (a ``%``, the dialect comment) belong
to that program (``Program.named_units``)."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from enum import Enum
from pathlib import Path

from ..analysis.indexes.workspace_index import ProgramEntry
from ..syntax.program import LoopPair
from .source import EditorDocument
from .spans import Region, Span

MAX_LABELS = 5000  # a CAM file numbers every block; past this many, labels are left out
MAX_LOOPS = 5000  # and a generated file may hold thousands of loops: past this many, they are left out too


class OutlineKind(Enum):
    PROGRAM = "program"
    LOOP = "loop"
    LABEL = "label"


@dataclass(frozen=True, slots=True)
class OutlineSymbol:
    """One entry of the outline: ``region`` is all it covers, ``selection`` the part that names it."""

    name: str
    kind: OutlineKind
    region: Region
    selection: Span
    detail: str | None = None
    children: tuple[OutlineSymbol, ...] = ()


@dataclass(frozen=True, slots=True)
class ProgramSymbol:
    """One program of the workspace: its name, its title and file, and the line it starts on."""

    name: str
    detail: str
    path: str
    line: int


@dataclass(slots=True)
class _Open:
    """An outline entry while its children are gathered."""

    symbol: OutlineSymbol
    last: int  # its last line
    children: list[_Open] = field(default_factory=list)

    def closed(self) -> OutlineSymbol:
        s = self.symbol
        return OutlineSymbol(s.name, s.kind, s.region, s.selection, s.detail, tuple(c.closed() for c in self.children))


def document_symbols(doc: EditorDocument) -> list[OutlineSymbol]:
    """The programs of ``doc``, each holding its loops (nested by their lines) and its labels
    (each in the innermost loop that holds it)."""
    program = doc.parsed.program
    labelled = sum(len(lines) for lines in program.labels.values())
    labels = (
        sorted((line, n) for n, lines in program.labels.items() for line in lines) if labelled <= MAX_LABELS else []
    )
    loops = sorted(program.loops, key=lambda p: p.do_line) if len(program.loops) <= MAX_LOOPS else []
    out: list[OutlineSymbol] = []
    units = program.named_units()
    for unit in units:
        last = max(unit.start, unit.end - 1)
        if unit.number is None:
            if unit.end <= unit.start:
                continue
            name = Path(doc.path).stem
        else:
            name = f"O{unit.number:04d}"
        # the first program's symbol holds the lead-in before its O line ('%', the dialect
        # comment), so that the breadcrumbs there name it too
        first = program.units[0].start if unit is units[0] else unit.start
        top = _Open(
            OutlineSymbol(name, OutlineKind.PROGRAM, _to_line_end(doc, first, last), _whole_line(doc, unit.start),
                          unit.title or ""),
            last,
        )  # fmt: skip
        stack = [top]  # each open symbol, innermost last
        events = sorted(
            [(p.do_line, 0, p) for p in loops if unit.start <= p.do_line < unit.end]
            + [(line, 1, n) for line, n in labels if unit.start <= line < unit.end],
            key=lambda e: (e[0], e[1]),
        )
        for line, _, item in events:
            while len(stack) > 1 and stack[-1].last < line:
                stack.pop()
            parent = stack[-1]
            if isinstance(item, LoopPair):
                loop = _Open(
                    OutlineSymbol(f"DO{item.number} … END{item.number}", OutlineKind.LOOP,
                                  _to_line_end(doc, line, item.end_line), _whole_line(doc, line)),
                    item.end_line,
                )  # fmt: skip
                parent.children.append(loop)
                stack.append(loop)
            else:
                b = doc.block(line)
                start, end = b.label_span if b is not None and b.label_span else (0, 0)
                span = Span(line, start, end)
                region = Region(line, start, line, end)
                parent.children.append(_Open(OutlineSymbol(f"N{item}", OutlineKind.LABEL, region, span), line))
        out.append(top.closed())
    return out


def workspace_symbols(programs: Iterable[ProgramEntry], query: str) -> list[ProgramSymbol]:
    """The programs whose name or title holds ``query`` (ignoring case and the spaces around it);
    every program for an empty one."""
    query = query.strip().lower()
    return [
        ProgramSymbol(p.name, (p.title or "") + f" — {Path(p.path).name}", p.path, p.line)
        for p in programs
        if not query or query in f"{p.name} {p.title or ''}".lower()
    ]


def _whole_line(doc: EditorDocument, line: int) -> Span:
    return Span(line, 0, len(doc.line(line)))


def _to_line_end(doc: EditorDocument, first: int, last: int) -> Region:
    """From the start of line ``first`` to the end of line ``last``."""
    return Region(first, 0, last, len(doc.line(last)))
