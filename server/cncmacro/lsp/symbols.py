"""Document symbols (O programs, with their N labels and nested loops) and workspace symbols
(every program in the workspace index), read from the ``Program`` structure of the parser.

A program is named by its O number, and by its file only when it has no O line: the lines
before a file's first O line that hold no program text (a ``%``, the dialect comment) belong
to that program (``Program.named_units``)."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from lsprotocol import types

from ..syntax.program import LoopPair
from .cursor import doc_range
from .documents import OpenDocument
from .positions import Encoding

if TYPE_CHECKING:
    from .server import CncMacroServer

MAX_LABELS = 5000  # a CAM file numbers every block; past this many, labels are left out
MAX_LOOPS = 5000  # and a generated file may hold thousands of loops: past this many, they are left out too


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
    def document_symbol(ls: CncMacroServer, params: types.DocumentSymbolParams) -> list[types.DocumentSymbol]:
        return document_symbols(ls.documents.get(params.text_document.uri), ls.documents.encoding)

    @server.feature(types.WORKSPACE_SYMBOL)
    def workspace_symbol(ls: CncMacroServer, params: types.WorkspaceSymbolParams) -> list[types.WorkspaceSymbol]:
        query = params.query.strip().lower()
        out = []
        for p in ls.index.programs():
            text = f"{p.name} {p.title or ''}".lower()
            if query and query not in text:
                continue
            uri = ls.uri_for_path(p.path)
            out.append(
                types.WorkspaceSymbol(
                    name=p.name,
                    kind=types.SymbolKind.Module,
                    location=types.Location(uri, types.Range(types.Position(p.line, 0), types.Position(p.line, 0))),
                    container_name=(p.title or "") + f" — {Path(p.path).name}",
                )
            )
        return out


def document_symbols(doc: OpenDocument, encoding: Encoding) -> list[types.DocumentSymbol]:
    program = doc.parsed.program
    labelled = sum(len(lines) for lines in program.labels.values())
    labels = (
        sorted((line, n) for n, lines in program.labels.items() for line in lines) if labelled <= MAX_LABELS else []
    )
    loops = sorted(program.loops, key=lambda p: p.do_line) if len(program.loops) <= MAX_LOOPS else []
    out: list[types.DocumentSymbol] = []
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
        inside: list[types.DocumentSymbol] = []
        sym = types.DocumentSymbol(
            name=name,
            detail=unit.title or "",
            kind=types.SymbolKind.Module,
            range=types.Range(types.Position(first, 0), _line_end(doc, last, encoding)),
            selection_range=doc_range(doc, unit.start, 0, len(doc.line(unit.start)), encoding),
            children=inside,
        )
        # loops nest by their ranges; labels go into the innermost loop that holds them: the
        # stack holds each open symbol's last line and its children
        stack: list[tuple[int, list[types.DocumentSymbol]]] = [(last, inside)]
        events = sorted(
            [(p.do_line, 0, p) for p in loops if unit.start <= p.do_line < unit.end]
            + [(line, 1, n) for line, n in labels if unit.start <= line < unit.end],
            key=lambda e: (e[0], e[1]),
        )
        for line, _, item in events:
            while len(stack) > 1 and stack[-1][0] < line:
                stack.pop()
            parent = stack[-1][1]
            if isinstance(item, LoopPair):
                in_loop: list[types.DocumentSymbol] = []
                parent.append(
                    types.DocumentSymbol(
                        name=f"DO{item.number} … END{item.number}",
                        kind=types.SymbolKind.Namespace,
                        range=types.Range(types.Position(line, 0), _line_end(doc, item.end_line, encoding)),
                        selection_range=doc_range(doc, line, 0, len(doc.line(line)), encoding),
                        children=in_loop,
                    )
                )
                stack.append((item.end_line, in_loop))
            else:
                b = doc.block(line)
                span = b.label_span if b is not None and b.label_span else (0, 0)
                r = doc_range(doc, line, span[0], span[1], encoding)
                parent.append(
                    types.DocumentSymbol(name=f"N{item}", kind=types.SymbolKind.Key, range=r, selection_range=r)
                )
        out.append(sym)
    return out


def _line_end(doc: OpenDocument, line: int, encoding: Encoding) -> types.Position:
    text = doc.line(line)
    return types.Position(line, encoding.to_client(text, len(text)))
