"""A Haas NGC mill workspace (``workspace_haas``, whose ``.cncmacro.toml`` has ``base = "haas"``)
through a real client: hover, completion, navigation of ``M97 P n`` and the diagnostics speak of
the Haas control, in English and in Chinese; the same text read as ``fanuc-0i`` (the FANUC
workspace, which names no profile) gets none of it, and a ``profile-suggestion`` naming Haas."""

from __future__ import annotations

import re
from collections.abc import AsyncIterator
from pathlib import Path

import pytest
import pytest_asyncio
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, HERE, close_file, described, diagnostics_for, hover_text
from .lsp_session import open_file as open_in

pytestmark = pytest.mark.asyncio(loop_scope="session")

HAAS = HERE / "workspace_haas"
PROGRAM = HAAS / "O01000.nc"

# where things are in O01000.nc (0-based lines and columns)
G154_P5, M97_P100, G65_P9832, G187, N100 = (3, 1), (8, 5), (9, 5), (10, 1), (12, 1)
T3026, T14001, T7001 = (6, 8), (7, 4), (7, 11)


_opened: list[tuple[LanguageClient, str]] = []


def open_file(client: LanguageClient, path: Path, text: str | None = None) -> str:
    """Open ``path`` in ``client`` until the end of the test (each test opens its documents anew)."""
    uri = open_in(client, path, text)
    _opened.append((client, uri))
    return uri


@pytest_asyncio.fixture(autouse=True, loop_scope="session")
async def close_the_documents() -> AsyncIterator[None]:
    yield
    for client, uri in _opened:
        close_file(client, uri)
    _opened.clear()


def as_fanuc(client: LanguageClient) -> str:
    """The text of O01000.nc opened in the FANUC workspace, where it is read as fanuc-0i."""
    return open_file(client, FANUC / "O01000.nc", PROGRAM.read_text("utf-8"))


async def maybe_hover(client: LanguageClient, uri: str, at: tuple[int, int]) -> str | None:
    got = await client.text_document_hover_async(
        types.HoverParams(types.TextDocumentIdentifier(uri), types.Position(*at))
    )
    return (None if got is None else described(str(got.contents.value))) or None  # type: ignore[union-attr]


async def test_the_workspace_reads_it_as_haas_with_its_title(haas_en: LanguageClient) -> None:
    uri = open_file(haas_en, PROGRAM)
    answer = await haas_en.protocol.send_request_async("cncmacro/documentDialect", {"uri": uri})
    assert (answer.dialect, answer.title, answer.source) == ("haas", "Haas NGC mill", "workspace")


async def test_hover_3026_is_the_tool_in_the_spindle_in_english_and_chinese(
    haas_en: LanguageClient, haas_zh: LanguageClient, fanuc_en: LanguageClient
) -> None:
    text = await hover_text(haas_en, open_file(haas_en, PROGRAM), *T3026)
    assert text.startswith("**#3026** — System variable")
    assert "Tool in the spindle: the number of the tool now loaded" in text and "*Haas NGC mill*" in text
    text = await hover_text(haas_zh, open_file(haas_zh, PROGRAM), *T3026)
    assert "系统变量" in text and "主轴上的刀具：当前装在主轴上的刀具号" in text and "只读" in text
    fanuc = await hover_text(fanuc_en, as_fanuc(fanuc_en), *T3026)
    assert "No such variable in this dialect (alarm 115)" in fanuc


async def test_hover_14001_and_7001_are_the_g154_p1_offset(haas_en: LanguageClient, fanuc_en: LanguageClient) -> None:
    uri = open_file(haas_en, PROGRAM)
    text = await hover_text(haas_en, uri, *T14001)
    assert "**#14001**" in text and "X axis work offset of G154 P1 (G110); G10 L20 P1 sets it too" in text
    text = await hover_text(haas_en, uri, *T7001)
    assert "**#7001**" in text and "X axis work offset of G110 (G154 P1); another number for #14001" in text
    fanuc = as_fanuc(fanuc_en)
    assert "No such variable" in await hover_text(fanuc_en, fanuc, *T14001)
    assert "G54.1 P1" in await hover_text(fanuc_en, fanuc, *T7001)  # FANUC's additional offsets


async def test_hover_g154_m97_and_g187_show_the_haas_texts(
    haas_en: LanguageClient, haas_zh: LanguageClient, fanuc_en: LanguageClient
) -> None:
    uri = open_file(haas_en, PROGRAM)
    g154 = await hover_text(haas_en, uri, *G154_P5)
    assert g154.startswith("**G154** — Select work coordinates G154 P1-P99") and "*Haas NGC mill*" in g154
    m97 = await hover_text(haas_en, uri, 8, 1)
    assert m97.startswith("**M97** — Local subprogram call: M97 P(sequence number in this program) L(repeat count)")
    g187 = await hover_text(haas_en, uri, *G187)
    assert g187.startswith("**G187** — Accuracy control: G187 P1 (rough), P2 (medium), P3 (finish)")
    zh = await hover_text(haas_zh, open_file(haas_zh, PROGRAM), 8, 1)
    assert zh.startswith("**M97** — 本地子程序调用") and "非模态" in zh
    fanuc = as_fanuc(fanuc_en)
    assert [await maybe_hover(fanuc_en, fanuc, at) for at in (G154_P5, (8, 1), G187)] == [None, None, None]


async def test_completion_after_30_offers_3026_with_its_haas_text(
    haas_en: LanguageClient, haas_zh: LanguageClient, fanuc_en: LanguageClient
) -> None:
    async def items(client: LanguageClient, uri: str) -> dict[str, types.CompletionItem]:
        got = await client.text_document_completion_async(
            types.CompletionParams(types.TextDocumentIdentifier(uri), types.Position(2, 6))
        )
        assert isinstance(got, types.CompletionList)
        return {i.label: i for i in got.items}

    text = "%\nO01001\n#1=#30\n"
    offered = (await items(haas_en, open_file(haas_en, HAAS / "typing.nc", text)))["#3026"]
    assert offered.detail == "read-only" and offered.text_edit is not None
    assert str(offered.documentation.value).startswith("Tool in the spindle")  # type: ignore[union-attr]
    offered = (await items(haas_zh, open_file(haas_zh, HAAS / "typing.nc", text)))["#3026"]
    assert str(offered.documentation.value).startswith("主轴上的刀具")  # type: ignore[union-attr]
    assert "#3026" not in await items(fanuc_en, open_file(fanuc_en, FANUC / "typing.nc", text))


async def test_definition_of_m97_p100_is_the_n100_line(haas_en: LanguageClient, fanuc_en: LanguageClient) -> None:
    uri = open_file(haas_en, PROGRAM)
    for column in (5, 8):  # on the number 100, as on the number of M99 P10 or GOTO 10
        got = await haas_en.text_document_definition_async(
            types.DefinitionParams(types.TextDocumentIdentifier(uri), types.Position(8, column))
        )
        assert isinstance(got, list) and len(got) == 1, column
        assert (got[0].uri, got[0].range.start.line, got[0].range.end.character) == (uri, 12, 4)
    fanuc = await fanuc_en.text_document_definition_async(
        types.DefinitionParams(types.TextDocumentIdentifier(as_fanuc(fanuc_en)), types.Position(*M97_P100))
    )
    assert not fanuc  # on FANUC, M97 is a plain M code and its P names nothing


async def test_references_of_n100_include_the_m97_and_rename_rewrites_it(
    haas_en: LanguageClient, fanuc_en: LanguageClient
) -> None:
    uri = open_file(haas_en, PROGRAM)

    async def references(client: LanguageClient, of: str) -> list[tuple[int, int]]:
        got = await client.text_document_references_async(
            types.ReferenceParams(
                text_document=types.TextDocumentIdentifier(of),
                position=types.Position(*N100),
                context=types.ReferenceContext(include_declaration=True),
            )
        )
        return sorted((r.range.start.line, r.range.start.character) for r in got or [])

    assert await references(haas_en, uri) == [(8, 5), (12, 0)]
    edit = await haas_en.text_document_rename_async(
        types.RenameParams(types.TextDocumentIdentifier(uri), types.Position(*N100), "N200")
    )
    assert edit is not None and edit.changes is not None
    assert sorted((e.range.start.line, e.range.start.character, e.new_text) for e in edit.changes[uri]) == [
        (8, 5, "200"),
        (12, 0, "N200"),
    ]
    hover = await hover_text(haas_en, uri, *N100)
    assert "jumps to it:\n- line 9 (M97 P)" in hover
    assert await references(fanuc_en, as_fanuc(fanuc_en)) == [(12, 0)]


async def test_highlight_on_m97_p100_marks_the_label_not_a_program(haas_en: LanguageClient) -> None:
    """``M97 P100`` enters the label N100 of its own program: the label and the call are marked,
    as for a jump; ``G65 P9832`` names a program, marked alone (no O9832 in the file)."""
    uri = open_file(haas_en, PROGRAM)

    async def marks(at: tuple[int, int]) -> list[tuple[int, int, int, types.DocumentHighlightKind | None]]:
        got = await haas_en.text_document_document_highlight_async(
            types.DocumentHighlightParams(types.TextDocumentIdentifier(uri), types.Position(*at))
        )
        return [(h.range.start.line, h.range.start.character, h.range.end.character, h.kind) for h in got or []]

    read, write = types.DocumentHighlightKind.Read, types.DocumentHighlightKind.Write
    assert await marks(M97_P100) == [(8, 5, 8, read), (12, 0, 4, write)]
    assert await marks(G65_P9832) == [(9, 4, 9, read)]


async def test_g65_p9832_is_a_probing_macro_on_the_control(
    haas_en: LanguageClient, haas_zh: LanguageClient, fanuc_en: LanguageClient
) -> None:
    said = await hover_text(haas_en, open_file(haas_en, PROGRAM), *G65_P9832)
    assert said.startswith("**O9832** — Work probe on (Haas WIPS)")
    assert "Program: kept on the control (Haas NGC mill keeps O9000–O9999 there" in said  # no machine file names them
    said = await hover_text(haas_zh, open_file(haas_zh, PROGRAM), *G65_P9832)
    assert said.startswith("**O9832** — 工件测头开启（Haas WIPS）")
    assert "程序: 存放在数控系统内" in said and "Haas NGC 铣床 的 O9000–O9999" in said
    # FANUC keeps its 9000 series on the control too, with nothing said of what O9832 does there
    said = described(await hover_text(fanuc_en, as_fanuc(fanuc_en), *G65_P9832))
    assert said.startswith("**O9832** — Program: kept on the control (FANUC 0i Custom Macro B keeps O9000–O9999 there")


async def test_the_haas_program_is_clean_and_as_fanuc_0i_it_suggests_haas(
    haas_en: LanguageClient, fanuc_en: LanguageClient
) -> None:
    uri = open_file(haas_en, PROGRAM)
    assert list((await diagnostics_for(haas_en, uri, 1)).diagnostics) == []
    fanuc = as_fanuc(fanuc_en)
    found = (await diagnostics_for(fanuc_en, fanuc, 1)).diagnostics
    assert sorted((d.range.start.line, d.code) for d in found if d.severity == types.DiagnosticSeverity.Error) == [
        (3, "unknown-g-code"),  # G154 P5
        (4, "unknown-g-code"),
        (6, "variable-number"),  # #10500
        (6, "variable-number"),  # #3026
        (7, "variable-number"),  # #14001
        (10, "unknown-g-code"),  # G187
    ]
    [hint] = [d for d in found if d.code == "profile-suggestion"]
    assert hint.message.startswith("This file uses what Haas NGC mill has and FANUC 0i Custom Macro B lacks")
    assert "(cncmacro: dialect=haas)" in hint.message and 'base = "haas"' in hint.message


# §6: Haas documents none of FANUC's alarm numbers, so hover names an alarm without one
ALARM_WORDS = "O02000\n#1=#12000+SQRT[2]\n#2=#_ABC\nM30\n"
T12000, SQRT, NAME = (1, 4), (1, 11), (2, 4)
NUMBERED = re.compile(r"alarm\s*\d|报警\s*\d|\d\s*号报警", re.IGNORECASE)


async def test_hover_names_an_alarm_without_fanucs_number_on_haas(
    haas_en: LanguageClient, haas_zh: LanguageClient, fanuc_en: LanguageClient
) -> None:
    uri = open_file(haas_en, HAAS / "O02000.nc", ALARM_WORDS)
    undefined = await hover_text(haas_en, uri, *T12000)
    assert "No such variable in this dialect (alarm)" in undefined
    sqrt = await hover_text(haas_en, uri, *SQRT)
    assert "Square root of a; a negative is alarm" in sqrt
    names = await hover_text(haas_en, uri, *NAME)
    assert "This dialect has no system variable names (alarm)" in names
    assert [t for t in (undefined, sqrt, names) if NUMBERED.search(t)] == []
    zh_uri = open_file(haas_zh, HAAS / "O02000.nc", ALARM_WORDS)
    chinese = [await hover_text(haas_zh, zh_uri, *at) for at in (T12000, SQRT, NAME)]
    assert "该系统中不存在此变量（报警）" in chinese[0] and "平方根；a为负时为报警" in chinese[1]
    assert "该系统不支持系统变量名（报警）" in chinese[2]
    assert [t for t in chinese if NUMBERED.search(t)] == []
    # the same words on fanuc-0i keep FANUC's numbers: 115 no such variable, 119 argument out of range
    fanuc = open_file(fanuc_en, FANUC / "O02000.nc", ALARM_WORDS)
    assert "No such variable in this dialect (alarm 115)" in await hover_text(fanuc_en, fanuc, *T12000)
    assert "Square root of a; a negative is alarm 119" in await hover_text(fanuc_en, fanuc, *SQRT)
    assert "This dialect has no system variable names (alarm 114)" in await hover_text(fanuc_en, fanuc, *NAME)
