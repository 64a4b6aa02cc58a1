"""Signature help without a server: on a G65 call, the locals the called macro reads in number
order with the letter that fills each, the argument being typed active; a documented program on
the control gives its own letters; a line without a macro call has no signature."""

from __future__ import annotations

from cncmacro.analysis.indexes.workspace_index import WorkspaceIndex
from cncmacro.dialects import get_dialect
from cncmacro.ide.signature_help import DocumentedSignature, MacroArgument, MacroSignature, signature_help
from cncmacro.lsp.documents import OpenDocument

from .documents import document


def _index(doc: OpenDocument) -> WorkspaceIndex:
    return WorkspaceIndex(lambda: [doc], lambda lines, path: doc.dialect)


CALLER = document(
    "O0001",
    "G65 P9100 R1. X2. Z-2.",  # 1
    "M30",
    "O9100 (BORE)",
    "#100=#24+#26*#18+#4",
    "M99",
)
BORE = (
    MacroArgument(4, "I", "I1"),
    MacroArgument(18, "R", "K5"),
    MacroArgument(24, "X", "K7"),
    MacroArgument(26, "Z", "J8"),
)


def test_a_g65_call_shows_the_locals_the_macro_reads_and_the_argument_being_typed() -> None:
    assert signature_help(CALLER, _index(CALLER), 1, 20) == MacroSignature("O9100", "BORE", BORE, 3)  # on Z-2.
    assert signature_help(CALLER, _index(CALLER), 1, 15) == MacroSignature("O9100", "BORE", BORE, 2)  # on X2.


def test_before_the_first_argument_no_argument_is_active() -> None:
    assert signature_help(CALLER, _index(CALLER), 1, 5) == MacroSignature("O9100", "BORE", BORE, None)


def test_a_line_that_calls_no_macro_has_no_signature() -> None:
    assert signature_help(CALLER, _index(CALLER), 0, 2) is None
    assert signature_help(CALLER, _index(CALLER), 9, 0) is None  # past the end


def test_a_call_of_a_macro_nowhere_to_be_found_has_no_signature() -> None:
    doc = document("O0001", "G65 P8123 X1.", "M30")
    assert signature_help(doc, _index(doc), 1, 12) is None


def test_a_documented_program_on_the_control_gives_its_own_letters() -> None:
    doc = document("O0001", "G65 P9023 A12. T5", "M30", profile="haas")
    found = signature_help(doc, _index(doc), 1, 17)  # on T5
    assert isinstance(found, DocumentedSignature)
    assert found.doc == get_dialect("haas").program_doc(9023)
    assert [letter for letter, _, _ in found.doc.arguments][found.active or 0] == "T" and found.active == 1
