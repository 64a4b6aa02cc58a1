"""Navigation: go to definition, find references, and rename N labels.

A jump (``GOTO 10``, ``IF .. GOTO``, ``M99 P``, ``M98 Q``, and Haas ``M97 P`` where the
dialect has that local subprogram call) leads to the N label it lands on
(``machine.jumps`` says which of duplicate labels); the ``P`` of ``G65``/``G66``/``M98`` leads
to the called program's file and line, found by the program library. References cover N
labels (within their program), O programs (every call across the workspace) and variables
(locals within their program, the others across the files of the same machine: the same
machine file and profile). Renaming a label rewrites the
label and every jump to it.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from lsprotocol import types
from pygls.exceptions import JsonRpcException

from ..analysis.indexes.call_sites import call_site
from ..analysis.indexes.return_labels import callers, return_landings, returns_onto
from ..analysis.indexes.site_index import FileSites
from ..analysis.indexes.sites import label_jumps, starts_from_the_top
from ..dialects import describe
from ..ide.under_cursor import label_under, program_under
from ..library.machine_file import CallCode
from ..machine.jump_words import RETURN_LABEL
from ..machine.jumps import first_line, goto_line
from ..syntax.nodes import Var
from ..syntax.walk import nodes_at
from .cursor import Cursor, cursor_at, doc_range
from .positions import Encoding

if TYPE_CHECKING:
    from .server import CncMacroServer


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_DEFINITION)
    def definition(ls: CncMacroServer, params: types.DefinitionParams) -> list[types.Location] | None:
        cur = cursor_at(ls, params.text_document.uri, params.position)
        return None if cur is None else find_definition(ls, cur)

    @server.feature(types.TEXT_DOCUMENT_REFERENCES)
    def references(ls: CncMacroServer, params: types.ReferenceParams) -> list[types.Location] | None:
        cur = cursor_at(ls, params.text_document.uri, params.position)
        if cur is None:
            return None
        return find_references(ls, cur, params.context.include_declaration)

    @server.feature(types.TEXT_DOCUMENT_PREPARE_RENAME)
    def prepare_rename(ls: CncMacroServer, params: types.PrepareRenameParams) -> types.Range | None:
        cur = cursor_at(ls, params.text_document.uri, params.position)
        target = None if cur is None else label_under(cur.doc, cur.block, cur.column)
        if cur is None or target is None:
            return None
        return cur.range(target[1], target[2])

    @server.feature(types.TEXT_DOCUMENT_RENAME)
    def rename(ls: CncMacroServer, params: types.RenameParams) -> types.WorkspaceEdit | None:
        cur = cursor_at(ls, params.text_document.uri, params.position)
        if cur is None:
            return None
        return rename_label(ls, cur, params.new_name)


def _loc(uri: str, line: int, start: int, end: int, text: str, encoding: Encoding) -> types.Location:
    return types.Location(uri, encoding.range(line, text, start, end))


def find_definition(ls: CncMacroServer, cur: Cursor) -> list[types.Location] | None:
    encoding = ls.documents.encoding
    hit = label_under(cur.doc, cur.block, cur.column)
    if hit is not None and hit[3] == RETURN_LABEL:
        return return_locations(ls, cur, hit[0]) or None
    if hit is not None and hit[3] != "N":
        label, _, _, kind = hit
        program = cur.doc.parsed.program
        unit = program.unit_at(cur.line)
        lines = program.label_lines(label, unit)
        target = first_line(lines) if starts_from_the_top(kind) else goto_line(lines, cur.line)
        if target is None:
            return None
        b = cur.doc.block(target)
        span = b.label_span if b is not None and b.label_span else (0, 0)
        return [_loc(cur.doc.uri, target, span[0], span[1], cur.doc.line(target), encoding)]
    site = call_site(cur.block, cur.doc.dialect, machine_calls(ls, cur.doc.path))
    if site is not None and site.target.start <= cur.column <= site.target.end:
        found = ls.index.find_program(cur.doc, site.number, site.name)
        if found is None:
            return None
        line = found.unit.start
        text = found.file.lines[line] if line < len(found.file.lines) else ""
        return [_loc(ls.uri_for_path(found.file.path), line, 0, len(text), text, encoding)]
    return None


def return_locations(ls: CncMacroServer, cur: Cursor, label: int) -> list[types.Location]:
    """The ``Nn`` labels the ``M99 P n`` under the cursor returns to: one in each caller
    (``analysis/indexes/return_labels.py``), or a main program's own."""
    encoding = ls.documents.encoding
    found = return_landings(ls.index, cur.doc, cur.line, label)
    here = cur.doc.as_loaded()
    places = [(here, found.own)] if found.main else []
    places += [(x.caller.file, x.line) for x in found.landings]
    out: list[types.Location] = []
    for f, line in places:
        if line is None or line >= len(f.lines):
            continue
        span = f.program.blocks[line].label_span or (0, 0)
        loc = _loc(ls.uri_for_path(f.path), line, span[0], span[1], f.lines[line], encoding)
        if loc not in out:
            out.append(loc)
    return out


def machine_calls(ls: CncMacroServer, path: str) -> dict[str, CallCode] | None:
    """The call codes of the machine file that the file at ``path`` is read with, if any."""
    return ls.documents.calls_for(path)


def find_references(ls: CncMacroServer, cur: Cursor, include_declaration: bool) -> list[types.Location] | None:
    encoding = ls.documents.encoding
    hit = label_under(cur.doc, cur.block, cur.column)
    if hit is not None and hit[3] == RETURN_LABEL:  # M99 P n: the labels it returns to, and itself
        landed = return_locations(ls, cur, hit[0]) if include_declaration else []
        return [*landed, _loc(cur.doc.uri, cur.line, hit[1], hit[2], cur.doc.line(cur.line), encoding)]
    if hit is not None:
        return label_references(ls, cur, hit[0], include_declaration, encoding)
    program = program_under(cur.doc, cur.block, cur.column, machine_calls(ls, cur.doc.path))
    if program is not None:
        number, called = program
        if not called:
            return program_references(ls, cur.doc.path, number, include_declaration, cur)
        found = ls.index.find_program(cur.doc, number, None)
        return program_references(ls, found.file.path if found else None, number, include_declaration, cur)
    for node in reversed(nodes_at(cur.block, cur.column)):
        if isinstance(node, Var):
            return variable_references(ls, cur, node.number, include_declaration)
    return None


def label_references(
    ls: CncMacroServer, cur: Cursor, label: int, include_declaration: bool, encoding: Encoding
) -> list[types.Location]:
    """The N label's lines and the jumps that land on them: those of its program (an ``M99 P``
    there only when nothing calls the program: called, it returns to the caller) and the
    ``M99 P`` of the programs it calls that return to it (``analysis/indexes/return_labels.py``)."""
    doc = cur.doc
    program = doc.parsed.program
    unit = program.unit_at(cur.line)
    out: list[types.Location] = []
    defined = program.label_lines(label, unit)
    if include_declaration:
        for i in defined:
            b = doc.block(i)
            if b is not None and b.label_span:
                out.append(_loc(doc.uri, i, b.label_span[0], b.label_span[1], doc.line(i), encoding))
    jumps = list(label_jumps(doc, unit.start, unit.end, label))
    if any(j.kind == RETURN_LABEL for _, j in jumps) and callers(ls.index, doc, unit):
        jumps = [(i, j) for i, j in jumps if j.kind != RETURN_LABEL]
    for i, j in jumps:
        out.append(_loc(doc.uri, i, j.start, j.end, doc.line(i), encoding))
    for r in (r for at in defined for r in returns_onto(ls.index, doc, at, label)):
        uri = ls.uri_for_path(r.file.path)
        out.append(_loc(uri, r.line, r.site.start, r.site.end, r.file.lines[r.line], encoding))
    out.sort(key=lambda x: (x.uri != doc.uri, x.uri, x.range.start.line, x.range.start.character))
    return out


def program_references(
    ls: CncMacroServer, path: str | None, number: int, include_declaration: bool, cur: Cursor
) -> list[types.Location]:
    """The calls of O``number`` across the workspace (and its header when asked)."""
    encoding = ls.documents.encoding
    out: list[types.Location] = []
    for f in ls.index.loaded_files():
        uri = ls.uri_for_path(f.path)
        dialect = cur.doc.dialect if f.path == cur.doc.path else ls.documents.dialect_for(f.lines, f.path)
        calls = machine_calls(ls, f.path)
        for i, b in enumerate(f.program.blocks):
            if include_declaration and b.program == number and b.program_span and (path is None or f.path == path):
                out.append(_loc(uri, i, b.program_span[0], b.program_span[1], f.lines[i], encoding))
            if b.plain is not None and not calls and "P" not in b.plain.upper():
                continue
            site = call_site(b, dialect, calls)
            if site is not None and site.number == number:
                out.append(_loc(uri, i, site.target.start, site.target.end, f.lines[i], encoding))
    return out


def variable_references(
    ls: CncMacroServer, cur: Cursor, number: int, include_declaration: bool
) -> list[types.Location]:
    """Where ``#number`` is mentioned: a local within its program, the others in every file of
    the cursor's machine (``WorkspaceIndex.machine_sites``: not in a file of another control)."""
    encoding = ls.documents.encoding
    out: list[types.Location] = []
    kind = describe.variable_class(number, cur.doc.dialect)
    if kind == describe.LOCAL:
        unit = cur.doc.parsed.program.unit_at(cur.line)
        files: list[tuple[FileSites, int, int | None]] = [
            (FileSites(cur.doc.path, cur.doc.lines, cur.doc.sites), unit.start, unit.end)
        ]
    else:
        files = [(f, 0, None) for f in ls.index.machine_sites(cur.doc.path, cur.doc.dialect)]
    for f, start, end in files:
        uri = ls.uri_for_path(f.path)
        for i, s in f.sites.variable_uses(number, start, end):
            if include_declaration or not s.write:
                out.append(_loc(uri, i, s.start, s.end, f.lines[i], encoding))
    return out


def refused(message: str) -> JsonRpcException:
    """The answer to a request the server will not do: LSP's RequestFailed, with the reason the
    editor shows."""
    return JsonRpcException(message=message, code=int(types.LSPErrorCodes.RequestFailed))


def rename_label(ls: CncMacroServer, cur: Cursor, new_name: str) -> types.WorkspaceEdit | None:
    hit = label_under(cur.doc, cur.block, cur.column)
    if hit is None:
        return None
    text = new_name.strip().upper().lstrip("N")
    if not text.isdigit() or not 1 <= int(text) <= 99999:
        raise refused(f"'{new_name}' is not a sequence number (N1 to N99999)")
    new = int(text)
    doc = cur.doc
    encoding = ls.documents.encoding
    program = doc.parsed.program
    unit = program.unit_at(cur.line)
    if new != hit[0] and program.label_lines(new, unit):
        # two N20 in one program: every jump to N20 would land on the first, wherever it was
        raise refused(f"N{new} is already a label in this program: renaming onto it would change where jumps land")
    returns = [r for at in program.label_lines(hit[0], unit) for r in returns_onto(ls.index, doc, at, hit[0])]
    if returns:  # rewriting that M99 P would move the returns of its other callers
        r = returns[0]
        raise refused(
            f"N{hit[0]} is where M99 P{hit[0]} of {Path(r.file.path).name} (line {r.line + 1}) returns: "
            "rename the label there and here together"
        )
    edits: list[types.TextEdit] = []
    for i in program.label_lines(hit[0], unit):
        b = doc.block(i)
        if b is not None and b.label_span:
            edits.append(types.TextEdit(doc_range(doc, i, b.label_span[0], b.label_span[1], encoding), f"N{new}"))
    for i, j in label_jumps(doc, unit.start, unit.end, hit[0]):
        edits.append(types.TextEdit(doc_range(doc, i, j.start, j.end, encoding), str(new)))
    return types.WorkspaceEdit(changes={doc.uri: edits})
