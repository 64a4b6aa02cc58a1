"""What the analysis runs find reaches the editor: division by zero and macro alarms found by
running, blocks no run reaches (tagged ``Unnecessary``), findings in a macro that come through
its caller in another file (open or on disk, with the call site as related information in
UTF-16 columns, cleared when the caller is fixed), in both dialects and both locales."""

from __future__ import annotations

from pathlib import Path

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, GSK, Accept, close_file, diagnostics_for, edit, open_file, published_where

pytestmark = pytest.mark.asyncio(loop_scope="session")


def codes(found: types.PublishDiagnosticsParams | list[types.Diagnostic]) -> list[tuple[int, str]]:
    items = found.diagnostics if isinstance(found, types.PublishDiagnosticsParams) else found
    return [(d.range.start.line, str(d.code)) for d in items]


def has(code: str) -> Accept:
    return lambda items: any(d.code == code for d in items)


def empty(items: list[types.Diagnostic]) -> bool:
    return not items


def open_saved(client: LanguageClient, path: Path, text: str) -> str:
    """Save ``text`` as ``path`` and open it (a called program is looked up on disk)."""
    path.write_text(text, "utf-8")
    return open_file(client, path)


def utf16_len(text: str) -> int:
    return len(text.encode("utf-16-le")) // 2


async def test_a_division_by_zero_found_by_running_is_an_error(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "run_div.nc", "O0100\n#1=0\n#2=10/#1\nM30\n")
    got = await diagnostics_for(fanuc_en, uri, 1)
    div = [d for d in got.diagnostics if d.code == "division-by-zero"]
    assert [d.range.start.line for d in div] == [2]
    assert div[0].severity == types.DiagnosticSeverity.Error and "112" in div[0].message
    edit(fanuc_en, uri, 2, 1, 3, 4, "4")  # #1=4: the division is fine now
    got = await diagnostics_for(fanuc_en, uri, 2)
    assert codes(got) == []


async def test_blocks_no_run_reaches_are_hints_tagged_unnecessary(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "run_skip.nc", "O0100\nGOTO 10\n#1=1\n#2=2\nN10 M30\n")
    got = await diagnostics_for(fanuc_en, uri, 1)
    assert codes(got) == [(2, "not-executed")]
    (hint,) = got.diagnostics
    assert hint.range.end.line == 3 and hint.severity == types.DiagnosticSeverity.Hint
    assert list(hint.tags or []) == [types.DiagnosticTag.Unnecessary]
    assert "2 lines" in hint.message


async def test_a_macro_alarm_every_run_reaches_is_an_error_with_its_number_and_text(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "run_alarm.nc", "O0100\n#1=6\n#3000=12(SPINDLE NOT READY)\nM30\n")
    got = await diagnostics_for(fanuc_en, uri, 1)
    (alarm,) = [d for d in got.diagnostics if d.code == "macro-alarm"]
    assert alarm.range.start.line == 2 and alarm.severity == types.DiagnosticSeverity.Error
    assert "3012" in alarm.message and "SPINDLE NOT READY" in alarm.message


async def test_a_finding_in_an_open_macro_comes_through_its_caller_with_the_call_site_related(
    fanuc_en: LanguageClient, tmp_path: Path
) -> None:
    macro = open_saved(fanuc_en, tmp_path / "O9200.nc", "O9200 (DIVIDE)\n#3=#2/#1\nM99\n")
    got = await diagnostics_for(fanuc_en, macro, 1)
    assert codes(got) == []  # run on its own, its arguments are unknown (no caller): #2/#1 is no alarm
    call_line = "(𝑥 CALL) G65 P9200 A0 B2."  # an astral character: UTF-16 columns differ
    main = open_file(fanuc_en, tmp_path / "MAIN.nc", f"O0001\n{call_line}\nM30\n")
    got = (await published_where(fanuc_en, {macro: lambda items: any(d.related_information for d in items)}))[macro]
    assert codes(got) == [(1, "division-by-zero"), (2, "not-executed")]
    div = got[0]
    assert "O0001" in div.message
    (rel,) = div.related_information or []
    assert rel.location.uri == main and rel.location.range.start.line == 1
    assert rel.location.range.end.character == utf16_len(call_line)
    edit(fanuc_en, main, 2, 1, 22, 23, "5")  # A5: no division by zero any more
    await published_where(fanuc_en, {macro: empty, main: empty})
    close_file(fanuc_en, main)
    close_file(fanuc_en, macro)


async def test_a_finding_in_a_macro_on_disk_is_published_and_cleared(fanuc_zh: LanguageClient, tmp_path: Path) -> None:
    (tmp_path / "O9300.nc").write_text("O9300 (DIVIDE)\n#3=#2/#1\nM99\n", "utf-8")
    macro = (tmp_path / "O9300.nc").as_uri()
    main = open_file(fanuc_zh, tmp_path / "MAIN.nc", "O0001\nG65 P9300 A0 B2.\nM30\n")
    got = (await published_where(fanuc_zh, {macro: has("division-by-zero")}))[macro]
    assert codes(got) == [(1, "division-by-zero"), (2, "not-executed")]
    assert "除数为零" in got[0].message  # the Chinese locale
    assert got[0].related_information[0].location.uri == main  # type: ignore[index]
    edit(fanuc_zh, main, 2, 1, 11, 12, "3")  # A3
    await published_where(fanuc_zh, {macro: empty})
    close_file(fanuc_zh, main)


async def test_gsk_a_division_by_zero_in_a_named_macro_comes_through_its_caller(
    gsk_en: LanguageClient, tmp_path: Path
) -> None:
    macro = open_saved(gsk_en, tmp_path / "DIVI.CNC", "(INDEX)\n#2=360/#1\nM99\n")
    await diagnostics_for(gsk_en, macro, 1)
    main = open_file(gsk_en, tmp_path / "M.CNC", "O0002\n#100=0\nG65 P[DIVI] A#100\nM30\n")
    both = await published_where(gsk_en, {macro: has("division-by-zero"), main: has("not-executed")})
    assert codes(both[macro]) == [(1, "division-by-zero"), (2, "not-executed")]
    assert "O0002" in both[macro][0].message
    assert codes(both[main]) == [(3, "not-executed")]
    close_file(gsk_en, main)
    close_file(gsk_en, macro)


async def test_gsk_h99_alarm_and_division_found_by_running_in_chinese(gsk_zh: LanguageClient) -> None:
    text = "O0002\n#1=0\nG65 H04 P#2 Q5 R2\nIF[#2==10]GOTO 9\n#3=1\nN9 G65 H99 P5\nM30\n"
    uri = open_file(gsk_zh, GSK / "run_h99.CNC", text)
    got = await diagnostics_for(gsk_zh, uri, 1)
    assert codes(got) == [(4, "not-executed"), (5, "macro-alarm"), (6, "not-executed")]
    # #2 = 5 x 2 = 10 on every run: the main program always reaches the alarm, an error; H99 P5 is
    # alarm 5900 + 5 (GSK980TDi §3.28.2: "G65 H99 Pi … i：报警号+5900", 5900-5999)
    assert got.diagnostics[1].severity == types.DiagnosticSeverity.Error and "5905" in got.diagnostics[1].message
    edit(gsk_zh, uri, 2, 5, 3, 13, "#3=#2/#1")  # the division by zero comes first now
    got = await diagnostics_for(gsk_zh, uri, 2)
    assert codes(got) == [(4, "not-executed"), (5, "division-by-zero"), (6, "not-executed")]
    assert "除数为零" in got.diagnostics[1].message


async def test_run_findings_follow_the_severity_setting(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "run_sev.nc", "O0100\n#3000=1(STOP)\nM30\n")
    got = await diagnostics_for(fanuc_en, uri, 1)
    assert [(str(d.code), d.severity) for d in got.diagnostics] == [
        ("macro-alarm", types.DiagnosticSeverity.Error),
        ("not-executed", types.DiagnosticSeverity.Hint),
    ]
    fanuc_en.set_configuration({"severity": {"macro-alarm": "warning", "not-executed": "off"}}, section="cncMacro")
    fanuc_en.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings=None))
    items = (await published_where(fanuc_en, {uri: lambda items: len(items) == 1}))[uri]
    assert [(str(d.code), d.severity) for d in items] == [("macro-alarm", types.DiagnosticSeverity.Warning)]
    fanuc_en.set_configuration({}, section="cncMacro")
    fanuc_en.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings=None))
    await published_where(fanuc_en, {uri: lambda items: len(items) == 2})


async def test_5_calls_a_macro_opened_alone_is_analysed_through_its_caller_on_disk(fanuc_en: LanguageClient) -> None:
    """Only the macro is open; its caller is a file of the workspace folder. The macro's own
    argument check does not fire (the caller passes H), and what only the caller's arguments
    cause (H6: a division by zero) is reported in the macro, with the call site related."""
    caller = FANUC / "ring_caller.nc"
    macro = FANUC / "O9277.nc"
    caller.write_text("O0277 (RING OF HOLES)\nG65 P9277 H6 R40.\nM30\n", "utf-8")
    created = types.FileEvent(uri=caller.as_uri(), type=types.FileChangeType.Created)
    fanuc_en.workspace_did_change_watched_files(types.DidChangeWatchedFilesParams(changes=[created]))
    try:
        uri = open_saved(fanuc_en, macro, "O9277 (RING)\nIF[#11 EQ #0] THEN #3000=1(H MISSING)\n#10=360/[#11-6]\nM99\n")
        got = (await published_where(fanuc_en, {uri: has("division-by-zero")}))[uri]
        assert [c for c in codes(got) if c[1] != "not-executed"] == [(2, "division-by-zero")]
        related = next(d for d in got if d.code == "division-by-zero").related_information or []
        assert [Path(r.location.uri).name for r in related] == ["ring_caller.nc"]
        close_file(fanuc_en, uri)
    finally:
        caller.unlink()
        macro.unlink()


async def test_a_kept_common_is_unknown_a_branch_on_it_is_a_note_and_nothing_is_faded(fanuc_zh: LanguageClient) -> None:
    # #706 is kept on the machine: 10/#706 is no alarm; IF on the result stops the run with a
    # note naming #706, and the alarm block after it is not faded as unreached
    text = "O0100\n#641=10/#706\nIF [#641 GT 2] GOTO 10\n#3000=1 (WORN)\nN10 M30\n"
    uri = open_file(fanuc_zh, FANUC / "run_unknown.nc", text)
    got = await diagnostics_for(fanuc_zh, uri, 1)
    assert codes(got) == [(2, "unknown-value")]
    (note,) = got.diagnostics
    assert note.severity == types.DiagnosticSeverity.Hint  # a finding on an unknown is at most a hint
    assert "#706（第 2 行）" in note.message and "[variables]" in note.message
    edit(fanuc_zh, uri, 2, 1, 8, 12, "4")  # #641=10/4: known again, the branch jumps over the alarm
    got = await diagnostics_for(fanuc_zh, uri, 2)
    assert codes(got) == [(3, "not-executed")]
