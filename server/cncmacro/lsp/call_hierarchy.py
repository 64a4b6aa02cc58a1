"""Call hierarchy (``textDocument/prepareCallHierarchy``, ``callHierarchy/incomingCalls``,
``callHierarchy/outgoingCalls``): the programs that call a program and the ones it calls, across
the workspace, as ``analysis/editing/call_hierarchy.py`` finds them. The cursor on a call's ``P`` (or a
call code) names the called program, on ``M97 P`` the label it enters; anywhere else the program
the cursor is in. An item carries its file and first line in ``data``.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from lsprotocol import types

from ..analysis.editing.call_hierarchy import CallTarget, incoming, label_item, outgoing, program_item
from ..analysis.indexes.call_sites import call_site
from ..library.file_cache import LoadedFile
from ..machine.jump_words import local_call_kind
from .cursor import cursor_at
from .navigation import machine_calls

if TYPE_CHECKING:
    from .server import CncMacroServer


def _loaded(ls: CncMacroServer, path: str) -> LoadedFile | None:
    return next((f for f in ls.index.loaded_files() if f.path == path), None)


def _line(f: LoadedFile, i: int) -> str:
    return f.lines[i] if i < len(f.lines) else ""


def _item(ls: CncMacroServer, f: LoadedFile, t: CallTarget) -> types.CallHierarchyItem:
    encoding = ls.documents.encoding
    last = max(t.start, min(t.end, len(f.lines)) - 1)
    whole = types.Range(
        encoding.range(t.start, _line(f, t.start), 0, 0).start,
        encoding.range(last, _line(f, last), len(_line(f, last)), len(_line(f, last))).end,
    )
    return types.CallHierarchyItem(
        name=t.name,
        kind=types.SymbolKind.Function if t.label is None else types.SymbolKind.Method,
        uri=ls.uri_for_path(f.path),
        range=whole,
        selection_range=encoding.range(t.start, _line(f, t.start), *t.span),
        detail=t.title or Path(f.path).name,
        data={"path": f.path, "start": t.start, "label": t.label},
    )


def _target(ls: CncMacroServer, item: types.CallHierarchyItem) -> tuple[LoadedFile, CallTarget] | None:
    data: Any = item.data
    if not isinstance(data, dict) or not isinstance(data.get("path"), str) or not isinstance(data.get("start"), int):
        return None
    f = _loaded(ls, data["path"])
    if f is None or data["start"] >= len(f.program.blocks):
        return None
    unit = f.program.unit_at(data["start"])
    label = data.get("label")
    t = label_item(f, unit, label) if isinstance(label, int) else program_item(f, unit)
    return None if t is None else (f, t)


def prepare(ls: CncMacroServer, params: types.CallHierarchyPrepareParams) -> list[types.CallHierarchyItem] | None:
    cur = cursor_at(ls, params.text_document.uri, params.position)
    if cur is None:
        return None
    doc = cur.doc
    here = doc.as_loaded()
    unit = here.program.unit_at(cur.line)
    site = call_site(cur.block, doc.dialect, machine_calls(ls, doc.path))
    if site is not None and site.target.start <= cur.column <= site.target.end:
        found = ls.index.find_program(doc, site.number, site.name)
        if found is None or found.file.on_control:
            return None
        return [_item(ls, found.file, program_item(found.file, found.unit))]
    code = doc.dialect.local_subprogram_code
    if code is not None:
        for j in doc.sites.jumps_of(cur.block):
            if j.kind == local_call_kind(code) and j.start <= cur.column <= j.end:
                t = label_item(here, unit, j.label)
                return None if t is None else [_item(ls, here, t)]
    return [_item(ls, here, program_item(here, unit))]


def _ranges(ls: CncMacroServer, f: LoadedFile, spans: list[tuple[int, int, int]]) -> list[types.Range]:
    encoding = ls.documents.encoding
    return [encoding.range(i, _line(f, i), start, end) for i, start, end in spans]


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_PREPARE_CALL_HIERARCHY)
    def prepare_call_hierarchy(
        ls: CncMacroServer, params: types.CallHierarchyPrepareParams
    ) -> list[types.CallHierarchyItem] | None:
        return prepare(ls, params)

    @server.feature(types.CALL_HIERARCHY_INCOMING_CALLS)
    def incoming_calls(
        ls: CncMacroServer, params: types.CallHierarchyIncomingCallsParams
    ) -> list[types.CallHierarchyIncomingCall] | None:
        hit = _target(ls, params.item)
        if hit is None:
            return None
        files = list(ls.index.loaded_files())
        by_path = {f.path: f for f in files}
        found = incoming(
            ls.index.library(None), files, hit[1], ls.documents.dialect_for, lambda p: machine_calls(ls, p)
        )
        return [
            types.CallHierarchyIncomingCall(_item(ls, by_path[c.path], c), _ranges(ls, by_path[c.path], spans))
            for c, spans in found
        ]

    @server.feature(types.CALL_HIERARCHY_OUTGOING_CALLS)
    def outgoing_calls(
        ls: CncMacroServer, params: types.CallHierarchyOutgoingCallsParams
    ) -> list[types.CallHierarchyOutgoingCall] | None:
        hit = _target(ls, params.item)
        if hit is None:
            return None
        f, t = hit
        library = ls.index.library(None)
        found = outgoing(library, f, t, ls.documents.dialect_for(f.lines, f.path), machine_calls(ls, f.path))
        out = []
        for callee, spans in found:
            g = _loaded(ls, callee.path) or library.load(callee.path)
            if g is not None:
                out.append(types.CallHierarchyOutgoingCall(_item(ls, g, callee), _ranges(ls, f, spans)))
        return out
