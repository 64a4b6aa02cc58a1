"""A huge file in the editor, end to end: its first screen's findings come at once, before the
whole analysis; the analysis reports how far it got, and the user can stop it."""

from __future__ import annotations

import asyncio
from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, config, diagnostics_for, edit, hover_text, open_file, start

pytestmark = pytest.mark.asyncio(loop_scope="module")

LINES = 120_000  # above the size from which a file shows its first screen first
BAD_LINE = 5  # a syntax error near the top: what the user sees first
MISSING_LABEL_LINE = 90_000  # a jump to a missing label far down: a finding that needs the whole file


def huge_program() -> str:
    lines = ["O0300 (CAM)", "#100=1"] + [f"G01 X{i % 100}.5 Y{i % 37}.25 F800" for i in range(LINES)] + ["M30"]
    lines[BAD_LINE] = "#1=[2+3"
    lines[MISSING_LABEL_LINE] = "IF [#100 EQ 2] GOTO 99991"
    return "\n".join(lines)


@pytest_lsp.fixture(config=config(), scope="module")
async def client(lsp_client: LanguageClient):  # type: ignore[no-untyped-def]
    await start(lsp_client, FANUC, "en")
    yield
    await lsp_client.shutdown_session()


async def analysed(client: LanguageClient, uri: str, version: int) -> list[tuple[int, str]]:
    """The findings of ``uri`` once the analysis of its ``version`` ended (its progress ends
    after they are published; the ones before are the first screen's and the edited lines')."""
    name = uri.rsplit("/", 1)[-1]
    for _ in range(6000):
        for token, rs in client.progress_reports.items():
            t = str(token)
            if "analysis" in t and name in t and t.endswith(f"-{version}") and rs:
                if isinstance(rs[-1], types.WorkDoneProgressEnd):
                    return [(d.range.start.line, str(d.code)) for d in client.diagnostics[uri]]
        await asyncio.sleep(0.01)
    raise AssertionError(f"the analysis of {name} version {version} did not end")


def codes(published: types.PublishDiagnosticsParams) -> list[tuple[int, str]]:
    return [(d.range.start.line, str(d.code)) for d in published.diagnostics]


def reports_of(client: LanguageClient, name: str, kind: str = "analysis") -> list[object]:
    """The progress reported on the file ``name``: its reading, or its analysis."""
    return [r for token, rs in client.progress_reports.items() if name in str(token) and kind in str(token) for r in rs]


async def test_a_huge_file_shows_its_first_screen_findings_before_the_whole_analysis(client: LanguageClient) -> None:
    uri = open_file(client, FANUC / "huge_first.nc", huge_program(), version=1)
    first = await diagnostics_for(client, uri, 1)
    assert codes(first) == [(BAD_LINE, "syntax")]  # only what the top lines earn by themselves
    found = await analysed(client, uri, 1)
    assert (BAD_LINE, "syntax") in found
    assert (MISSING_LABEL_LINE, "undefined-label") in found


async def test_a_huge_file_reports_how_far_its_analysis_got_and_can_be_stopped(client: LanguageClient) -> None:
    uri = open_file(client, FANUC / "huge_progress.nc", huge_program(), version=1)
    await diagnostics_for(client, uri, 1)
    assert (MISSING_LABEL_LINE, "undefined-label") in await analysed(client, uri, 1)
    reports = reports_of(client, "huge_progress.nc")
    begin, end = reports[0], reports[-1]
    assert isinstance(begin, types.WorkDoneProgressBegin) and begin.cancellable and begin.percentage == 0
    assert isinstance(end, types.WorkDoneProgressEnd) and end.message == "done"
    shown = [r.percentage for r in reports[1:-1] if isinstance(r, types.WorkDoneProgressReport)]
    assert shown == sorted(shown) and all(0 <= p < 100 for p in shown if p is not None)

    # stopped by the user: the first screen's findings stay, the rest waits for the next edit
    uri = open_file(client, FANUC / "huge_stopped.nc", huge_program(), version=1)
    first = await diagnostics_for(client, uri, 1)
    for _ in range(1000):
        tokens = [
            t for t, rs in client.progress_reports.items() if "huge_stopped.nc" in str(t) and "analysis" in str(t)
        ]
        if tokens:
            break
        await asyncio.sleep(0.01)
    client.window_work_done_progress_cancel(types.WorkDoneProgressCancelParams(token=tokens[0]))
    last: object = None
    for _ in range(3000):
        reports = reports_of(client, "huge_stopped.nc")
        last = reports[-1] if reports else None
        if isinstance(last, types.WorkDoneProgressEnd):
            break
        await asyncio.sleep(0.01)
    assert isinstance(last, types.WorkDoneProgressEnd) and last.message == "stopped"
    assert codes(first) == [(BAD_LINE, "syntax")]
    assert [(d.range.start.line, str(d.code)) for d in client.diagnostics[uri]] == [(BAD_LINE, "syntax")]
    assert "#100" in await hover_text(client, uri, 1, 1)  # the editor still answers

    edit(client, uri, 2, BAD_LINE, 0, 7, "#1=[2+3]")
    fixed = await diagnostics_for(client, uri, 2)  # at once: the edited lines, by themselves
    assert codes(fixed) == []
    found = await analysed(client, uri, 2)  # then everything
    assert (BAD_LINE, "syntax") not in found
    assert (MISSING_LABEL_LINE, "undefined-label") in found


async def test_a_huge_file_answers_hovers_and_keeps_edits_while_it_is_read(client: LanguageClient) -> None:
    uri = open_file(client, FANUC / "huge_reading.nc", huge_program(), version=1)
    # at once, far below the first screen: the line is read on its own
    assert "#100" in await hover_text(client, uri, MISSING_LABEL_LINE, 5)
    edit(client, uri, 2, BAD_LINE, 0, 7, "#1=[2+3]")  # typed before the file is read in full
    assert codes(await diagnostics_for(client, uri, 2)) == []  # at once, by itself
    edit(client, uri, 3, MISSING_LABEL_LINE + 1, 0, 0, "#1=[")  # a new syntax error far down
    assert codes(await diagnostics_for(client, uri, 3)) == [(MISSING_LABEL_LINE + 1, "syntax")]
    edit(client, uri, 4, MISSING_LABEL_LINE, 20, 25, "2")  # GOTO 99991 -> GOTO 2: still no N2
    found = await analysed(client, uri, 4)
    assert (BAD_LINE, "syntax") not in found and (MISSING_LABEL_LINE + 1, "syntax") in found
    missing = [d for d in client.diagnostics[uri] if d.range.start.line == MISSING_LABEL_LINE]
    assert [str(d.code) for d in missing] == ["undefined-label"] and "GOTO 2" in missing[0].message
    reading = reports_of(client, "huge_reading.nc", "reading")
    assert isinstance(reading[0], types.WorkDoneProgressBegin) and not reading[0].cancellable
    assert isinstance(reading[-1], types.WorkDoneProgressEnd)


async def test_a_huge_file_says_where_a_variable_is_written_and_what_jumps_to_a_label_once_indexed(
    client: LanguageClient,
) -> None:
    """Finding every write of #100, or every jump to N77, in a huge file takes seconds: meanwhile
    a hover answers at once and says the places are still being found; once the file is indexed
    (in steps, between the editor's messages) the same hovers list them, the ones far down too.
    Document highlight marks nothing until then, and then the write far down too."""
    text = huge_program().split("\n")
    text[80_000] = "#100=2"
    text[80_001] = "N77 G00 X0"
    text[80_002] = "IF [#100 EQ 5] GOTO 77"
    uri = open_file(client, FANUC / "huge_where.nc", "\n".join(text), version=1)
    early = await hover_text(client, uri, 1, 1)  # while the file is read
    assert "#100" in early and "huge_where.nc" in early.partition("still being found in")[2]
    label = await hover_text(client, uri, 80_001, 1)
    assert "N77" in label and "jumps to it: still being found in huge_where.nc" in label
    assert not await marks(client, uri, 1, 1)  # the cursor moves on at once: nothing marked yet
    await analysed(client, uri, 1)
    for _ in range(3000):
        later = await hover_text(client, uri, 1, 1)
        if "still being found" not in later:
            break
        await asyncio.sleep(0.01)
    assert "huge_where.nc:2" in later and "huge_where.nc:80001" in later
    label = await hover_text(client, uri, 80_001, 1)
    assert "still being found" not in label and "80003" in label
    assert (80_000, types.DocumentHighlightKind.Write) in await marks(client, uri, 1, 1)


async def test_the_quick_fixes_of_a_finding_that_spans_a_huge_file_are_those_of_the_findings_in_it(
    client: LanguageClient,
) -> None:
    """Hovering a finding that spans the file (the lines no run reaches, after the syntax error
    near the top) makes the editor ask for quick fixes over its whole range, with the findings
    it shows there: the clamp of the L0 far down is offered, once, with its finding; the blocks
    of the other lines are not looked at (the server answered nothing else for seconds while
    it looked at a million of them)."""
    text = huge_program().split("\n")
    text[100_000] = "G65 P9010 L0"
    text[110_000] = "G65 P9010 L0"  # its finding is not among those sent: not looked at
    uri = open_file(client, FANUC / "huge_fixes.nc", "\n".join(text), version=1)
    await analysed(client, uri, 1)
    shown = client.diagnostics[uri]
    spans = [d for d in shown if d.range.end.line - d.range.start.line > 100_000]
    assert [str(d.code) for d in spans] == ["not-executed"]
    within = [d for d in shown if spans[0].range.start.line <= d.range.start.line < 110_000]
    assert (100_000, "repeat-count-range") in [(d.range.start.line, str(d.code)) for d in within]
    got = await client.text_document_code_action_async(
        types.CodeActionParams(types.TextDocumentIdentifier(uri), spans[0].range, types.CodeActionContext(within))
    )
    fixes = [a for a in got or [] if isinstance(a, types.CodeAction)]
    assert [a.title for a in fixes] == ["Clamp the repeat count to 1"]
    assert fixes[0].diagnostics is not None and [str(d.code) for d in fixes[0].diagnostics] == ["repeat-count-range"]
    changes = fixes[0].edit.changes if fixes[0].edit is not None else None
    assert changes is not None and [e.range.start.line for e in changes[uri]] == [100_000]


async def marks(client: LanguageClient, uri: str, line: int, col: int) -> list[tuple[int, object]]:
    """The lines the editor marks for the word at ``line``:``col`` (document highlight), and how."""
    found = await client.text_document_document_highlight_async(
        types.DocumentHighlightParams(types.TextDocumentIdentifier(uri), types.Position(line, col))
    )
    return [(h.range.start.line, h.kind) for h in found or []]


@pytest_lsp.fixture(config=config(), scope="module")
async def big_folder(lsp_client: LanguageClient, tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    root = tmp_path_factory.mktemp("cam_folder")
    lines = ["O0400"] + [f"G01 X{i % 100}.5 Y{i % 37}.25 Z-{i % 7}.1 F800" for i in range(320_000)] + ["M30"]
    (root / "O0400.nc").write_text("\n".join(lines), encoding="utf-8")  # about 9 MB: over the search limit
    (root / "notes.nc").write_bytes(b"\x00\x01binary")
    lsp_client.root = root  # type: ignore[attr-defined]
    await start(lsp_client, root, "en")
    yield
    await lsp_client.shutdown_session()


async def test_a_cam_file_over_the_search_limit_is_named_as_not_searched_and_checked_in_full_when_opened(
    big_folder: LanguageClient,
) -> None:
    """A mould shop's folder holds CAM files of tens of megabytes: the workspace's search for
    called programs passes over them and says so, and says that opened, one is checked in full;
    opened, it is."""
    root: Path = big_folder.root  # type: ignore[attr-defined]
    path = root / "O0400.nc"
    assert path.stat().st_size > 8_000_000
    uri = open_file(big_folder, path, version=1)
    await diagnostics_for(big_folder, uri, 1)
    assert (320_001, "not-executed") not in await analysed(big_folder, uri, 1)  # the run reached the end
    said = [m.message for m in big_folder.messages if "O0400.nc" in m.message]
    assert len(said) == 1 and "not read for the programs that calls look for" in said[0]
    assert "opened in the editor, it is checked in full" in said[0]
