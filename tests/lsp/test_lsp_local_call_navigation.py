"""Navigation of a local subprogram call (Haas ``M97 P n``, docs/semantics.md §5 "M97 local
subprogram call"): definition of its P is the N line, the references of that N include it,
renaming the N rewrites it, and hover on its P describes the label.

These run the language server's navigation and hover on an open document whose dialect is
``fanuc`` with the switch on (``running.haas_switched``), without a client, so that the switch is
what they test; the same requests through a client, on the ``haas`` profile, are in
``test_lsp_haas.py``.
"""

from __future__ import annotations

from types import SimpleNamespace
from typing import Any

from lsprotocol import types

from cncmacro.analysis.indexes.workspace_index import WorkspaceIndex
from cncmacro.dialects import Dialect, get_dialect
from cncmacro.library.machine_file import CallCode
from cncmacro.lsp.cursor import cursor_at
from cncmacro.lsp.documents import Documents
from cncmacro.lsp.hover import hover_text
from cncmacro.lsp.navigation import find_definition, find_references, rename_label
from running import haas_switched

TEXT = "O0011\nM97 P100 L2\nM30\nN100 G01 X1. F100\nM99\n"
URI = "file:///programs/O0011.nc"


class _Documents(Documents):
    """Open documents all read in one given dialect."""

    def __init__(self, dialect: Dialect) -> None:
        super().__init__()
        self.fixed = dialect

    def dialect_for(self, lines: list[str], path: str) -> Dialect:
        return self.fixed


class _MacroM97(_Documents):
    """Open documents all read in one given dialect, with a machine file whose ``[calls]`` makes
    M97 a macro call of O9097."""

    def calls_for(self, path: str) -> dict[str, CallCode] | None:
        return {"M97": CallCode(9097)}


def _server(dialect: Dialect, documents: type[_Documents] = _Documents) -> Any:
    docs = documents(dialect)
    docs.open(types.TextDocumentItem(URI, "cncmacro", 1, TEXT))
    index = WorkspaceIndex(lambda: docs.by_uri.values(), docs.dialect_for, calls_for=docs.calls_for)
    return SimpleNamespace(documents=docs, locale="en", index=index)


def _at(ls: Any, line: int, ch: int) -> Any:
    cur = cursor_at(ls, URI, types.Position(line, ch))
    assert cur is not None
    return cur


def test_5_definition_of_m97_p_is_its_n_line() -> None:
    ls = _server(haas_switched())
    [loc] = find_definition(ls, _at(ls, 1, 6)) or []  # the 100 of M97 P100
    assert loc.uri == URI and (loc.range.start.line, loc.range.start.character, loc.range.end.character) == (3, 0, 4)
    assert find_definition(_server(get_dialect("fanuc")), _at(_server(get_dialect("fanuc")), 1, 6)) is None


def test_5_references_of_n100_include_m97_p100() -> None:
    ls = _server(haas_switched())
    found = find_references(ls, _at(ls, 3, 1), True) or []
    assert [(r.range.start.line, r.range.start.character) for r in found] == [(1, 5), (3, 0)]
    plain = _server(get_dialect("fanuc"))
    assert [r.range.start.line for r in find_references(plain, _at(plain, 3, 1), True) or []] == [3]


def test_5_an_m97_the_machine_file_makes_a_call_is_no_jump_to_its_p() -> None:
    ls = _server(haas_switched(), _MacroM97)
    assert [r.range.start.line for r in find_references(ls, _at(ls, 3, 1), True) or []] == [3]
    assert find_definition(ls, _at(ls, 1, 6)) is None  # P100 is an argument of the call of O9097


def test_5_renaming_n100_rewrites_m97_p100() -> None:
    ls = _server(haas_switched())
    edit = rename_label(ls, _at(ls, 3, 1), "N200")
    assert edit is not None and edit.changes is not None
    changes = sorted((e.range.start.line, e.range.start.character, e.new_text) for e in edit.changes[URI])
    assert changes == [(1, 5, "200"), (3, 0, "N200")]


def test_5_an_m97_typed_in_is_a_reference_at_once() -> None:
    ls = _server(haas_switched())
    change = types.TextDocumentContentChangePartial(
        range=types.Range(types.Position(2, 0), types.Position(2, 0)), text="M97 P100\n"
    )
    ls.documents.change(
        types.DidChangeTextDocumentParams(
            text_document=types.VersionedTextDocumentIdentifier(uri=URI, version=2), content_changes=[change]
        )
    )
    found = find_references(ls, _at(ls, 4, 1), True) or []
    assert [(r.range.start.line, r.range.start.character) for r in found] == [(1, 5), (2, 5), (4, 0)]


def test_5_hover_on_m97_p_describes_the_label_and_its_calls() -> None:
    ls = _server(haas_switched())
    found = hover_text(ls, _at(ls, 1, 6))
    assert found is not None
    text, start, end = found
    assert (start, end) == (5, 8) and text.startswith("**N100**") and "line 2 (M97 P)" in text
