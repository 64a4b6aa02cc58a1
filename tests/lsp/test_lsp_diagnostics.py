"""Document sync and diagnostics, end to end: incremental edits, versions, pushed only,
progress on a huge file, severities from settings, and errors answered without dying."""

from __future__ import annotations

import asyncio

import pytest
import pytest_lsp
from lsprotocol import types
from pygls.exceptions import JsonRpcException
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, GSK, config, diagnostics_for, edit, open_file, publishes, start

pytestmark = pytest.mark.asyncio(loop_scope="module")


@pytest_lsp.fixture(config=config(), scope="module")
async def client(lsp_client: LanguageClient):  # type: ignore[no-untyped-def]
    await start(lsp_client, FANUC, "en", {"severity": {"duplicate-label": "off"}, "dialect": "gsk980tdi"})
    yield
    await lsp_client.shutdown_session()


@pytest_lsp.fixture(config=config(), scope="module")
async def client_zh(lsp_client: LanguageClient):  # type: ignore[no-untyped-def]
    await start(lsp_client, GSK, "zh-CN", {"severity": {"syntax": "warning"}, "dialect": "fanuc"})
    yield
    await lsp_client.shutdown_session()


async def test_open_publishes_syntax_errors_with_the_version(client: LanguageClient) -> None:
    uri = open_file(client, FANUC / "broken_1.nc", "O0100\n#1=[2+3\nM30\n", version=7)
    got = await diagnostics_for(client, uri, 7)
    assert [(d.range.start.line, d.code, d.severity) for d in got.diagnostics] == [
        (1, "syntax", types.DiagnosticSeverity.Error),
        (2, "not-executed", types.DiagnosticSeverity.Hint),  # the run stops at the error
    ]
    assert "]" in got.diagnostics[0].message


async def test_incremental_edits_fix_the_error_and_only_the_newest_version_counts(client: LanguageClient) -> None:
    uri = open_file(client, FANUC / "broken_2.nc", "O0100\n#1=[2+3\nM30\n", version=1)
    await diagnostics_for(client, uri, 1)
    kept = publishes(client)  # every publish, not the next notification: two may come in one read
    after = kept.count
    edit(client, uri, 2, 1, 7, 7, "]")  # fixed: #1=[2+3]
    edit(client, uri, 3, 2, 0, 0, "#2=[")  # broken again on line 3
    edit(client, uri, 4, 2, 4, 4, "1]")  # fixed again: #2=[1]M30 ... is not valid either
    edit(client, uri, 5, 2, 0, 6, "M30")  # line 3 is M30 again
    while (got := kept.since(after, uri, 5)) is None:
        await asyncio.sleep(0.01)
    arrived = sorted((count, version or 0) for version, (count, _) in kept.by_uri[uri].items() if count > after)
    seen = [version for _, version in arrived]
    assert seen == sorted(seen)  # never an older version after a newer one (a later one is kept last)
    assert list(got.diagnostics) == []


async def test_diagnostics_are_pushed_only_so_a_client_that_also_pulls_shows_each_once(client: LanguageClient) -> None:
    """A client that pulls ``textDocument/diagnostic`` and takes pushes too (Neovim 0.10 and
    later) keeps the two apart and showed every finding twice: the server offers no pulling."""
    assert client.server_capabilities.diagnostic_provider is None  # type: ignore[attr-defined]
    with pytest.raises(JsonRpcException):
        await client.text_document_diagnostic_async(
            types.DocumentDiagnosticParams(types.TextDocumentIdentifier((FANUC / "broken_3.nc").as_uri()))
        )


async def test_severity_setting_switches_a_code_off(client: LanguageClient) -> None:
    text = "O0100\nN5 G00 X0\nN5 G00 X1\nGOTO 5\nM30\n"
    uri = open_file(client, FANUC / "dup.nc", text, version=1)
    got = await diagnostics_for(client, uri, 1)
    assert "duplicate-label" not in [d.code for d in got.diagnostics]


async def test_1_duplicate_program_is_a_warning_on_the_ignored_header(client: LanguageClient) -> None:
    text = "O0100\nM30\nO0100 (OLD COPY)\n#100=1/0\nM30\n"
    uri = open_file(client, FANUC / "twice.nc", text, version=1)
    got = await diagnostics_for(client, uri, 1)
    found = [(d.range.start.line, d.range.start.character, d.range.end.character, d.code) for d in got.diagnostics]
    assert found == [(2, 0, 5, "duplicate-program")]
    assert got.diagnostics[0].severity == types.DiagnosticSeverity.Warning
    [d] = got.diagnostics
    assert d.related_information is not None
    assert [(r.location.uri, r.location.range.start.line) for r in d.related_information] == [(uri, 0)]


async def test_5_argument_order_warning_reaches_the_editor_with_its_code(client: LanguageClient) -> None:
    text = "(cncmacro: dialect=fanuc)\nO0100\nG65 P9001 B1. A2. D3. J4. I5.\nG65 P9001 I5. J4.\nM30\nO9001\nM99\n"
    uri = open_file(client, FANUC / "order.nc", text, version=1)
    got = await diagnostics_for(client, uri, 1)
    found = [(d.range.start.line, d.range.start.character, d.code, d.severity) for d in got.diagnostics]
    assert found == [(2, 26, "argument-order", types.DiagnosticSeverity.Warning)]


async def test_severity_setting_changes_a_code_in_chinese_session(client_zh: LanguageClient) -> None:
    uri = open_file(client_zh, GSK / "broken.CNC", "O0100\n#1=[2+3\nM30\n", version=1)
    got = await diagnostics_for(client_zh, uri, 1)
    assert [(d.code, d.severity) for d in got.diagnostics] == [
        ("syntax", types.DiagnosticSeverity.Warning),
        ("not-executed", types.DiagnosticSeverity.Hint),
    ]


async def test_dialect_setting_applies_where_the_workspace_names_none(client: LanguageClient) -> None:
    uri = open_file(client, FANUC / "relations.nc", "O0100\nIF[#1>2]GOTO5\nN5 M30\n", version=1)
    got = await diagnostics_for(client, uri, 1)
    assert list(got.diagnostics) == []  # the setting says gsk980tdi, where '>' is a relation
    uri = open_file(client, FANUC / "relations_fanuc.nc", "(cncmacro: dialect=fanuc)\nIF[#1>2]GOTO5\nN5 M30\n")
    got = await diagnostics_for(client, uri, 1)
    assert [d.code for d in got.diagnostics] == ["dialect-feature", "not-executed"]  # the file's comment wins


async def test_gsk_dialect_from_the_workspace_wins_over_the_setting(client_zh: LanguageClient) -> None:
    uri = open_file(client_zh, GSK / "MAIN.CNC")
    got = await diagnostics_for(client_zh, uri, 1)
    assert [d for d in got.diagnostics if d.severity == types.DiagnosticSeverity.Error] == []


async def test_a_huge_file_reports_progress_on_its_first_analysis(client: LanguageClient) -> None:
    lines = ["O0200 (CAM)"] + [f"G01 X{i % 100}.5 Y{i % 37}.25" for i in range(25_000)] + ["M30"]
    uri = open_file(client, FANUC / "huge.nc", "\n".join(lines), version=1)
    await diagnostics_for(client, uri, 1)
    for _ in range(500):  # the progress ends right after the findings are published
        reports = [r for token, rs in client.progress_reports.items() if "huge.nc" in str(token) for r in rs]
        kinds = [r.kind for r in reports]
        if kinds and kinds[-1] == "end":
            break
        await asyncio.sleep(0.01)
    assert kinds[0] == "begin" and kinds[-1] == "end"


async def test_a_hover_on_a_document_not_open_is_null_and_the_server_keeps_serving(client: LanguageClient) -> None:
    missing = (FANUC / "never_opened.nc").as_uri()
    hover = await client.text_document_hover_async(
        types.HoverParams(types.TextDocumentIdentifier(missing), types.Position(0, 0))
    )
    assert hover is None
    uri = open_file(client, FANUC / "after_error.nc", "O0100\n#1=[2\n", version=3)
    got = await diagnostics_for(client, uri, 3)
    assert [d.code for d in got.diagnostics] == ["syntax"]


async def test_3_expressions_a_500_operator_line_keeps_the_server_answering(client: LanguageClient) -> None:
    text = "O0100\n#1=1" + "+1" * 500 + "\n#2=" + "-" * 1000 + "1\nGOTO 20\nM30\n"
    uri = open_file(client, FANUC / "long_chain.nc", text, version=1)
    got = await diagnostics_for(client, uri, 1)
    assert [(d.range.start.line, d.code) for d in got.diagnostics] == [(3, "undefined-label"), (4, "not-executed")]
    hover = await client.text_document_hover_async(
        types.HoverParams(types.TextDocumentIdentifier(uri), types.Position(1, 1))
    )
    assert hover is not None and "#1" in str(hover.contents)


async def test_1_text_and_blocks_text_after_the_closing_percent_is_only_a_hint(client: LanguageClient) -> None:
    text = "%\nO0100\n#1=1\nM30\n%\n\x1a\nJUNK [[[\n"
    uri = open_file(client, FANUC / "tape_end.nc", text, version=1)
    got = await diagnostics_for(client, uri, 1)
    assert [(d.range.start.line, d.code, d.severity) for d in got.diagnostics] == [
        (4, "after-tape-end", types.DiagnosticSeverity.Hint)
    ]
