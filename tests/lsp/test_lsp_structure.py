"""Document and workspace symbols, folding ranges and semantic tokens, end to end."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from cncmacro.debugging.stepping import end_text, last_line_run
from cncmacro.dialects import get_dialect
from cncmacro.dialects.tables import FUNCTION, FUNCTION_KINDS, OPERATOR, STATEMENT
from cncmacro.library.machine_file import MachineSettings
from cncmacro.library.programs import ProgramLibrary
from cncmacro.machine import Machine

from .lsp_session import FANUC, GSK, close_file, edit, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")


def _tree(symbols: list[types.DocumentSymbol]) -> list[object]:
    return [(s.name, s.range.start.line, _tree(list(s.children or []))) for s in symbols]


async def test_document_symbols_nest_labels_inside_loops(fanuc_en: LanguageClient) -> None:
    text = "O0001 (MAIN)\nN1 #1=0\nWHILE[#1 LT 3] DO1\nN2 #1=#1+1\nWHILE[#2 LT 2] DO2\nN3 #2=#2+1\nEND2\nEND1\nM30\n"
    text += "O0002 (SUB)\nN5 M99\n"
    uri = open_file(fanuc_en, FANUC / "symbols.nc", text)
    result = await fanuc_en.text_document_document_symbol_async(
        types.DocumentSymbolParams(types.TextDocumentIdentifier(uri))
    )
    close_file(fanuc_en, uri)
    assert _tree(result) == [
        ("O0001", 0, [("N1", 1, []), ("DO1 … END1", 2, [("N2", 3, []), ("DO2 … END2", 4, [("N3", 5, [])])])]),
        ("O0002", 9, [("N5", 10, [])]),
    ]
    assert result[0].detail == "MAIN"


async def test_document_symbols_of_a_generated_file_with_thousands_of_loops_leave_the_loops_out(
    fanuc_en: LanguageClient,
) -> None:
    """A CAM-generated file with 6,000 loops: its outline names its programs (and its few labels),
    not 6,000 loops no one could read, and it comes at once."""
    loop = ["#1=0", "WHILE[#1 LT 2] DO1", "G01 X1. Y1.", "#1=#1+1", "END1"]
    text = "\n".join(["O0001 (CAM)", "N1 G00 X0", *loop * 6_000, "N2 M30", "O0002", "N5 M99"])
    uri = open_file(fanuc_en, FANUC / "many_loops.nc", text)
    result = await fanuc_en.text_document_document_symbol_async(
        types.DocumentSymbolParams(types.TextDocumentIdentifier(uri))
    )
    close_file(fanuc_en, uri)
    assert _tree(result) == [("O0001", 0, [("N1", 1, []), ("N2", 30_002, [])]), ("O0002", 30_003, [("N5", 30_004, [])])]


async def test_workspace_symbols_are_the_programs(fanuc_en: LanguageClient, gsk_zh: LanguageClient) -> None:
    found = await fanuc_en.workspace_symbol_async(types.WorkspaceSymbolParams(query="drill"))
    assert [(s.name, s.location.uri.rsplit("/", 1)[-1]) for s in found] == [("O9100", "O9100.nc")]
    every = await gsk_zh.workspace_symbol_async(types.WorkspaceSymbolParams(query=""))
    assert sorted(s.name for s in every) == ["CUT", "O0002"]


LATHE_PART = (
    "%\n(cncmacro: dialect=gsk980tdi)\nO0001 (LATHE PART)\nN10 G00 X100. Z100.\nN20 G01 X20. W-5. F0.2\nM30\n%\n"
)


async def test_a_gsk_program_after_a_dialect_comment_is_named_by_its_o_number(gsk_en: LanguageClient) -> None:
    uri = open_file(gsk_en, GSK / "lathe_part.nc", LATHE_PART)
    try:
        result = await gsk_en.text_document_document_symbol_async(
            types.DocumentSymbolParams(types.TextDocumentIdentifier(uri))
        )
        found = await gsk_en.workspace_symbol_async(types.WorkspaceSymbolParams(query="lathe"))
    finally:
        close_file(gsk_en, uri)
    # one program, named as its O line says; on the '%' and the dialect comment above it the
    # breadcrumbs already show O0001, its name is still picked out on the O line
    assert _tree(result) == [("O0001", 0, [("N10", 3, []), ("N20", 4, [])])]
    assert result[0].detail == "LATHE PART" and result[0].selection_range.start.line == 2
    assert result[0].range.end.line == 6
    assert [(s.name, s.location.range.start.line) for s in found] == [("O0001", 2)]
    # without an O line, the file's name is all there is to name the program by
    uri = open_file(gsk_en, GSK / "facing.nc", "(cncmacro: dialect=gsk980tdi)\nG00 X50. Z2.\nM30\n")
    try:
        result = await gsk_en.text_document_document_symbol_async(
            types.DocumentSymbolParams(types.TextDocumentIdentifier(uri))
        )
        found = await gsk_en.workspace_symbol_async(types.WorkspaceSymbolParams(query="facing"))
    finally:
        close_file(gsk_en, uri)
    assert _tree(result) == [("facing", 0, [])] and [s.name for s in found] == ["facing"]


async def test_folding_covers_loops_programs_and_comment_blocks(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "O9100.nc")
    ranges = await fanuc_en.text_document_folding_range_async(
        types.FoldingRangeParams(types.TextDocumentIdentifier(uri))
    )
    close_file(fanuc_en, uri)
    got = sorted((r.start_line, r.end_line, r.kind) for r in ranges)
    assert got == [(0, 6, None), (1, 2, types.FoldingRangeKind.Comment)]
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    ranges = await fanuc_en.text_document_folding_range_async(
        types.FoldingRangeParams(types.TextDocumentIdentifier(uri))
    )
    close_file(fanuc_en, uri)
    assert sorted((r.start_line, r.end_line) for r in ranges) == [(0, 14), (5, 10), (6, 8)]


async def test_folding_of_a_program_whose_m99_is_inside_a_loop_nests_the_loop(fanuc_en: LanguageClient) -> None:
    text = "O0001 (LOOP RETURN)\n#1=0\nWHILE[#1 LT 3] DO1\n#1=#1+1\nM99\nEND1\nG00 X0\n"
    uri = open_file(fanuc_en, FANUC / "loop_m99.nc", text)
    ranges = await fanuc_en.text_document_folding_range_async(
        types.FoldingRangeParams(types.TextDocumentIdentifier(uri))
    )
    close_file(fanuc_en, uri)
    got = sorted((r.start_line, r.end_line) for r in ranges)
    assert got == [(0, 5), (2, 5)]  # the program's range holds the loop's, up to END1
    for a, b in got:  # no two ranges cross
        assert all(not (a < c <= b < d) for c, d in got)


def _decode(data: list[int], legend: types.SemanticTokensLegend, lines: list[str]) -> list[tuple[str, str, list[str]]]:
    out = []
    line = col = 0
    for k in range(0, len(data), 5):
        dl, dc, length, typ, mods = data[k : k + 5]
        line += dl
        col = dc if dl else col + dc
        names = [m for i, m in enumerate(legend.token_modifiers) if mods & (1 << i)]
        out.append((lines[line][col : col + length], legend.token_types[typ], names))
    return out


async def test_semantic_tokens_classify_variables_keywords_and_labels(fanuc_en: LanguageClient) -> None:
    text = "O0001 (MAIN)\nN10 #1=#100+#500+#5001\nIF[#1 GT 2] GOTO10\nG65 P9100 X1.\n#50=#0\n"
    uri = open_file(fanuc_en, FANUC / "tokens.nc", text)
    caps = await _legend(fanuc_en)
    full = await fanuc_en.text_document_semantic_tokens_full_async(
        types.SemanticTokensParams(types.TextDocumentIdentifier(uri))
    )
    part = await fanuc_en.text_document_semantic_tokens_range_async(
        types.SemanticTokensRangeParams(
            types.TextDocumentIdentifier(uri), types.Range(types.Position(2, 0), types.Position(2, 30))
        )
    )
    close_file(fanuc_en, uri)
    lines = text.split("\n")
    tokens = _decode(list(full.data), caps, lines)
    assert ("O0001", "namespace", []) in tokens and ("N10", "label", []) in tokens
    assert ("#1", "variable", ["local"]) in tokens
    assert ("#100", "variable", ["common"]) in tokens
    assert ("#500", "variable", ["persistent"]) in tokens
    assert ("#5001", "variable", ["system", "readonly"]) in tokens
    assert ("#50", "variable", ["undefined"]) in tokens and ("#0", "variable", ["vacant"]) in tokens
    assert ("IF", "keyword", []) in tokens and ("GT", "operator", []) in tokens and ("GOTO", "keyword", []) in tokens
    assert [t for t in tokens if t[0] in ("(MAIN)", "G", "65", "P", "9100", "X", "1.")] == []  # the grammar's
    ranged = _decode(list(part.data), caps, lines)
    assert [t[0] for t in ranged] == ["IF", "#1", "GT", "GOTO"]


async def test_semantic_tokens_leave_codes_addresses_and_alarm_texts_to_the_grammar(fanuc_en: LanguageClient) -> None:
    """A token can only recolour what it covers: over ``G`` alone it tears ``G90`` in two colours,
    over ``X`` as over ``#32`` it glues ``X#32`` into one word, over an alarm text as a comment it
    takes away the text's string colour; and ``THEN`` must be the keyword ``IF`` is."""
    text = "G90 G81 X#32 Y#33 R2. F100\nIF[#30 EQ 7] THEN #3000=1(TOOL BROKEN)\n#3006=2(STOP HERE)\n"
    uri = open_file(fanuc_en, FANUC / "grammar_words.nc", text)
    full = await fanuc_en.text_document_semantic_tokens_full_async(
        types.SemanticTokensParams(types.TextDocumentIdentifier(uri))
    )
    close_file(fanuc_en, uri)
    lines = text.split("\n")
    tokens = _decode(list(full.data), await _legend(fanuc_en), lines)
    assert [t[0] for t in tokens if t[0] in lines[0]] == ["#32", "#33"]  # nothing over G90, G81, X, Y, R2., F100
    assert ("#32", "variable", ["local"]) in tokens
    assert ("THEN", "keyword", []) in tokens and ("IF", "keyword", []) in tokens
    assert [t for t in tokens if "(" in t[0] or "BROKEN" in t[0] or "STOP" in t[0]] == []
    assert ("#3000", "variable", ["system"]) in tokens and ("#3006", "variable", ["system"]) in tokens


async def _legend(client: LanguageClient) -> types.SemanticTokensLegend:
    caps: types.ServerCapabilities = client.server_capabilities  # type: ignore[attr-defined]
    provider = caps.semantic_tokens_provider
    assert isinstance(provider, types.SemanticTokensOptions | types.SemanticTokensRegistrationOptions)
    return provider.legend


# a row's kind -> the token type and the completion item kind the editor shows its name with
SHOWN_AS = {
    FUNCTION: ("function", types.CompletionItemKind.Function),
    OPERATOR: ("operator", types.CompletionItemKind.Operator),
    STATEMENT: ("keyword", types.CompletionItemKind.Keyword),
}


async def test_a_function_tables_name_is_coloured_and_completed_as_its_row_kind(fanuc_en: LanguageClient) -> None:
    """The kind the profile's function table gives a name decides both its semantic token and its
    completion item: SQRT and POPEN functions, GT and AND operators, IF and THEN statement words."""
    text = "IF[SQRT[#1] GT 2 AND #2 EQ 0] THEN POPEN\n#3=\n"
    uri = open_file(fanuc_en, FANUC / "kinds.nc", text)
    full = await fanuc_en.text_document_semantic_tokens_full_async(
        types.SemanticTokensParams(types.TextDocumentIdentifier(uri))
    )
    completion = await fanuc_en.text_document_completion_async(
        types.CompletionParams(types.TextDocumentIdentifier(uri), types.Position(1, 3))
    )
    close_file(fanuc_en, uri)
    tokens = {t[0]: t[1] for t in _decode(list(full.data), await _legend(fanuc_en), text.split("\n"))}
    assert isinstance(completion, types.CompletionList)
    items = {i.label: i for i in completion.items}
    rows = {f.name: f.kind for f in get_dialect("fanuc").functions()}
    names = ("SQRT", "POPEN", "GT", "AND", "IF", "THEN")
    assert {rows[n] for n in names} == set(FUNCTION_KINDS)
    assert {n: (tokens[n], items[n].kind) for n in names} == {n: SHOWN_AS[rows[n]] for n in names}
    assert items["SQRT"].insert_text == "SQRT[$1]" and items["POPEN"].insert_text is None  # POPEN has no brackets


async def test_semantic_tokens_on_gsk_mark_the_c_relation(gsk_en: LanguageClient) -> None:
    uri = open_file(gsk_en, GSK / "MAIN.CNC")
    full = await gsk_en.text_document_semantic_tokens_full_async(
        types.SemanticTokensParams(types.TextDocumentIdentifier(uri))
    )
    close_file(gsk_en, uri)
    lines = (GSK / "MAIN.CNC").read_text("utf-8").split("\n")
    tokens = _decode(list(full.data), await _legend(gsk_en), lines)
    assert [t for t in tokens if "螺纹" in t[0]] == []  # a comment is the grammar's to colour
    assert ("#100", "variable", ["common"]) in tokens and ("GOTO", "keyword", []) in tokens


async def test_an_o_program_folds_exactly_to_its_m99(gsk_en: LanguageClient) -> None:
    text = "O0100 (A)\n#1=1\nM99\n(NOTES AFTER THE END)\n(MORE NOTES)\nO0200 (B)\n#2=2\nM30\n"
    uri = open_file(gsk_en, GSK / "folds.CNC", text)
    ranges = await gsk_en.text_document_folding_range_async(types.FoldingRangeParams(types.TextDocumentIdentifier(uri)))
    close_file(gsk_en, uri)
    programs = sorted((r.start_line, r.end_line) for r in ranges if r.kind is None)
    assert programs == [(0, 2), (5, 7)]


# (a line as written, the code that ends a program there as the debugger names it, or None):
# the codes that end a program spelled as programs spell them, and codes that do not; M29.6 is
# M30 as the control rounds an M word (a warning on gsk980tdi, which runs on)
_END_CASES = [
    ("M30", "M30"), ("M02", "M02"), ("M2", "M02"), ("m030", "M30"), ("M29.6", "M30"), ("G0 X1. M30", "M30"),
    ("N5 M99", "M99"), ("M20", None), ("M300", None), ("M3", None), ("M05 S0", None),
]  # fmt: skip


async def test_5_program_end_a_program_folds_where_its_run_ends_and_the_debugger_names_that_code(
    gsk_en: LanguageClient,
) -> None:
    """One rule says which M codes end a program (machine/program_end.py): where a run of the
    program ends, where the editor folds it and the code the debugger names all follow it."""
    for line, code in _END_CASES:
        text = f"O0100 (A)\n#1=1\n{line}\n#2=2\nG0 X0\n"
        m = Machine("gsk980tdi", MachineSettings(max_blocks=1000), ProgramLibrary(), m99_ends_main=True)
        m.start_file(str(GSK / "ends.CNC"), text)
        m.run()
        ends = code is not None
        assert (m.status, 2 not in m.variables()) == ("completed", ends), line
        assert end_text(m, "en") == (f"program end ({code})" if ends else "program end"), line
        assert last_line_run(m) == (2 if ends else 4), line
        uri = open_file(gsk_en, GSK / "ends.CNC", text)
        ranges = await gsk_en.text_document_folding_range_async(
            types.FoldingRangeParams(types.TextDocumentIdentifier(uri))
        )
        close_file(gsk_en, uri)
        assert [(r.start_line, r.end_line) for r in ranges if r.kind is None] == [(0, 2 if ends else 4)], line


async def test_semantic_tokens_delta_turns_the_old_answer_into_the_new_one(fanuc_zh: LanguageClient) -> None:
    text = "O0100\n#1=5\n#100=#1*2\nM30\n"
    uri = open_file(fanuc_zh, FANUC / "delta.nc", text)
    first = await fanuc_zh.text_document_semantic_tokens_full_async(
        types.SemanticTokensParams(types.TextDocumentIdentifier(uri))
    )
    assert first is not None and first.result_id
    edit(fanuc_zh, uri, 2, 2, 0, 0, "#500=SIN[30]\n")  # a new line before #100=#1*2
    delta = await fanuc_zh.text_document_semantic_tokens_full_delta_async(
        types.SemanticTokensDeltaParams(types.TextDocumentIdentifier(uri), previous_result_id=first.result_id)
    )
    fresh = await fanuc_zh.text_document_semantic_tokens_full_async(
        types.SemanticTokensParams(types.TextDocumentIdentifier(uri))
    )
    close_file(fanuc_zh, uri)
    assert isinstance(delta, types.SemanticTokensDelta) and len(delta.edits) == 1
    data = list(first.data)
    e = delta.edits[0]
    data[e.start : e.start + e.delete_count] = list(e.data or [])
    assert data == list(fresh.data) and data != list(first.data)
    lines = text.split("\n")
    lines.insert(2, "#500=SIN[30]")
    assert ("#500", "variable", ["persistent"]) in _decode(data, await _legend(fanuc_zh), lines)
    provider = fanuc_zh.server_capabilities.semantic_tokens_provider  # type: ignore[attr-defined]
    assert provider.full.delta is True


async def test_semantic_tokens_of_a_long_file_are_those_of_its_lines_while_other_requests_are_answered(
    fanuc_en: LanguageClient,
) -> None:
    """A file longer than one encoding step (lines with and without tokens, a step ending on a
    line with tokens) gets, in one answer, the tokens its lines have one by one, and a hover sent
    meanwhile is answered."""
    lines = ["O0600"]
    for i in range(45_000):
        lines.append(f"#{100 + i % 50}=#{101 + i % 7}+1" if i % 3 == 0 else f"G01 X{i % 90}. Y{i % 13}.")
    text = "\n".join([*lines, "M30"])
    uri = open_file(fanuc_en, FANUC / "long_tokens.nc", text)
    doc = types.TextDocumentIdentifier(uri)
    full_request = fanuc_en.text_document_semantic_tokens_full_async(types.SemanticTokensParams(doc))
    hover = await fanuc_en.text_document_hover_async(types.HoverParams(doc, types.Position(1, 1)))
    full = await full_request
    whole = await fanuc_en.text_document_semantic_tokens_range_async(
        types.SemanticTokensRangeParams(doc, types.Range(types.Position(0, 0), types.Position(len(lines), 0)))
    )
    assert hover is not None
    assert full is not None and whole is not None
    assert len(full.data) == 5 * 2 * 15_000 + 5 and full.data == whole.data  # two variables a macro line
    close_file(fanuc_en, uri)


async def test_semantic_tokens_delta_of_a_long_file_edited_in_the_middle_is_the_one_change(
    fanuc_en: LanguageClient,
) -> None:
    """Tens of thousands of tokens, one variable retyped in the middle: the delta is one edit of
    that token, and applied to the old answer it gives the new one."""
    lines = ["O0610"]
    for i in range(30_000):
        lines.append(f"#{100 + i % 50}=#{101 + i % 7}+1" if i % 3 == 0 else f"G01 X{i % 90}. Y{i % 13}.")
    uri = open_file(fanuc_en, FANUC / "long_delta.nc", "\n".join([*lines, "M30"]))
    doc = types.TextDocumentIdentifier(uri)
    first = await fanuc_en.text_document_semantic_tokens_full_async(types.SemanticTokensParams(doc))
    assert first is not None and first.result_id
    middle = 15_004  # "#103=#101+1", a macro line: #103 becomes #1, a local variable
    assert lines[middle].startswith("#103=")
    edit(fanuc_en, uri, 2, middle, 1, 4, "1")
    delta = await fanuc_en.text_document_semantic_tokens_full_delta_async(
        types.SemanticTokensDeltaParams(doc, previous_result_id=first.result_id)
    )
    fresh = await fanuc_en.text_document_semantic_tokens_full_async(types.SemanticTokensParams(doc))
    close_file(fanuc_en, uri)
    assert isinstance(delta, types.SemanticTokensDelta) and len(delta.edits) == 1
    e = delta.edits[0]
    assert e.delete_count <= 5 and 0 < e.start < len(first.data) - 5  # the one token, far from either end
    data = list(first.data)
    data[e.start : e.start + e.delete_count] = list(e.data or [])
    assert fresh is not None and data == list(fresh.data) and data != list(first.data)
