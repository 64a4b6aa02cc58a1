"""The sequence-number commands, end to end: the server renumbers, adds or removes N labels and
applies the edit itself (``workspace/applyEdit``); a jump whose label is computed makes it ask,
naming the line, whether to keep the labels it could reach (``window/showMessageRequest``)."""

from __future__ import annotations

from typing import Any

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, GSK, HERE, close_file, open_file, session_fixture

pytestmark = pytest.mark.asyncio(loop_scope="session")

RENUMBER = "cncmacro.server.renumberSequenceNumbers"
LABELS = HERE / "workspace_labels"
labels_en = session_fixture(LABELS, "en")


def _editor(client: LanguageClient, answer: str | None = None) -> dict[str, list[Any]]:
    """Accept every edit the server applies and answer its questions with ``answer``, as an
    editor would; what came is kept in the returned lists."""
    seen: dict[str, list[Any]] = getattr(client, "seen_by_editor", None) or {"edits": [], "questions": []}
    seen["answer"] = [answer]
    if not hasattr(client, "seen_by_editor"):
        client.seen_by_editor = seen  # type: ignore[attr-defined]

        @client.feature(types.WORKSPACE_APPLY_EDIT)
        def apply_edit(params: types.ApplyWorkspaceEditParams) -> types.ApplyWorkspaceEditResult:
            seen["edits"].append(params)
            return types.ApplyWorkspaceEditResult(applied=True)

        @client.feature(types.WINDOW_SHOW_MESSAGE_REQUEST)
        def question(params: types.ShowMessageRequestParams) -> types.MessageActionItem | None:
            seen["questions"].append(params)
            wanted = seen["answer"][0]
            return next((a for a in params.actions or [] if a.title == wanted), None)

    seen["edits"].clear()
    seen["questions"].clear()
    return seen


def _applied(text: str, edit: types.ApplyWorkspaceEditParams) -> str:
    rows = text.split("\n")
    change = edit.edit.document_changes[0]  # type: ignore[index]
    assert isinstance(change, types.TextDocumentEdit)
    for e in sorted(change.edits, key=lambda e: (e.range.start.line, -e.range.start.character)):
        assert isinstance(e, types.TextEdit)
        r = e.range
        row = rows[r.start.line]
        rows[r.start.line] = row[: r.start.character] + e.new_text + row[r.end.character :]
    return "\n".join(rows)


async def _run(client: LanguageClient, command: str, **arg: Any) -> Any:
    return await client.workspace_execute_command_async(types.ExecuteCommandParams(command, [arg]))


LOOP = "O0001\n#1=0\nN3 #1=#1+1\nIF[#1 LT 3] GOTO3\nM98 P0002 Q7\nM30\nO0002\nN7 #2=1\nM99\n"


async def test_renumbering_applies_an_edit_that_rewrites_the_jumps(fanuc_en: LanguageClient) -> None:
    assert RENUMBER in fanuc_en.server_capabilities.execute_command_provider.commands  # type: ignore[attr-defined]
    seen = _editor(fanuc_en)
    uri = open_file(fanuc_en, FANUC / "renumber.nc", LOOP)
    result = await _run(fanuc_en, RENUMBER, uri=uri, step=10)
    close_file(fanuc_en, uri)
    assert result["applied"] and result["changes"] == 4
    assert _applied(LOOP, seen["edits"][0]).split("\n")[2:8] == [
        "N10 #1=#1+1", "IF[#1 LT 3] GOTO10", "M98 P0002 Q10", "M30", "O0002", "N10 #2=1",
    ]  # fmt: skip
    assert seen["edits"][0].label == "Renumber sequence numbers"


async def test_a_selection_is_renumbered_alone(fanuc_en: LanguageClient) -> None:
    seen = _editor(fanuc_en)
    text = "O0001\nN1 #1=1\nN2 #2=2\nN3 #3=3\nM30\n"
    uri = open_file(fanuc_en, FANUC / "selection.nc", text)
    selection = {"start": {"line": 2, "character": 0}, "end": {"line": 4, "character": 0}}
    await _run(fanuc_en, RENUMBER, uri=uri, step=5, range=selection)
    close_file(fanuc_en, uri)
    assert _applied(text, seen["edits"][0]).split("\n")[1:4] == ["N1 #1=1", "N5 #2=2", "N10 #3=3"]


async def test_a_computed_goto_asks_and_keeping_leaves_its_program_alone(fanuc_en: LanguageClient) -> None:
    text = "O0001\nN1 M98 P0002\nN2 M30\nO0002\n#1=20\nGOTO #1\nN20 #2=1\nM99\n"
    uri = open_file(fanuc_en, FANUC / "computed.nc", text)
    seen = _editor(fanuc_en, answer=None)
    refused = await _run(fanuc_en, RENUMBER, uri=uri, step=10)
    assert not refused["applied"] and refused["refused"][0]["line"] == 6 and not seen["edits"]
    assert "line 6" in seen["questions"][0].message and "computed" in seen["questions"][0].message
    seen = _editor(fanuc_en, answer="Keep those labels unchanged")
    kept = await _run(fanuc_en, RENUMBER, uri=uri, step=10)
    close_file(fanuc_en, uri)
    assert kept["applied"] and kept["kept"] == [7]
    assert _applied(text, seen["edits"][0]).split("\n")[1:7] == [
        "N10 M98 P0002", "N20 M30", "O0002", "#1=20", "GOTO #1", "N20 #2=1",
    ]  # fmt: skip


async def test_a_gsk_h_code_jump_to_a_variable_label_asks_before_renumbering(gsk_en: LanguageClient) -> None:
    """``G65 H81 P#1 Q#100 R5`` (gsk980tdi macro A) jumps to the label whose number #1 holds."""
    text = "O0001\n#1=20\n#100=5\nG65 H81 P#1 Q#100 R5\n#2=1\nN20 #3=3\nM30\n"
    uri = open_file(gsk_en, GSK / "computed_h.CNC", text)
    seen = _editor(gsk_en, answer=None)
    refused = await _run(gsk_en, RENUMBER, uri=uri, step=10)
    close_file(gsk_en, uri)
    assert not refused["applied"] and refused["refused"][0]["line"] == 4 and not seen["edits"]
    assert "line 4" in seen["questions"][0].message and "computed" in seen["questions"][0].message


async def test_a_label_an_m99_p_of_another_file_returns_to_is_kept(labels_en: LanguageClient) -> None:
    text = (LABELS / "MAIN.nc").read_text()
    uri = open_file(labels_en, LABELS / "MAIN.nc")
    seen = _editor(labels_en)
    result = await _run(labels_en, RENUMBER, uri=uri, step=10)
    close_file(labels_en, uri)
    assert result["kept"] == [4]
    assert _applied(text, seen["edits"][0]).split("\n")[1:4] == ["N10 M98 P7000", "#2=1", "N20 #3=2"]


async def test_adding_and_removing_sequence_numbers(fanuc_en: LanguageClient) -> None:
    text = "O0001\n#1=1\nN2 GOTO 4\n#3=3\nN4 M30\n"
    uri = open_file(fanuc_en, FANUC / "add.nc", text)
    seen = _editor(fanuc_en)
    await _run(fanuc_en, "cncmacro.server.addSequenceNumbers", uri=uri, step=10)
    added = _applied(text, seen["edits"][0])
    await _run(fanuc_en, "cncmacro.server.removeSequenceNumbers", uri=uri)
    removed = _applied(text, seen["edits"][1])
    close_file(fanuc_en, uri)
    assert added.split("\n")[1:5] == [
        "N10 #1=1", "N2 GOTO 4", "N20 #3=3", "N4 M30",
    ]  # fmt: skip
    assert removed.split("\n")[1:5] == ["#1=1", "GOTO 4", "#3=3", "N4 M30"]


async def test_the_question_is_in_chinese(fanuc_zh: LanguageClient) -> None:
    uri = open_file(fanuc_zh, FANUC / "computed_zh.nc", "O0001\n#1=20\nGOTO #1\nN20 #2=1\nM30\n")
    seen = _editor(fanuc_zh, answer=None)
    await _run(fanuc_zh, RENUMBER, uri=uri, step=10)
    close_file(fanuc_zh, uri)
    question = seen["questions"][0]
    assert "第 3 行" in question.message and [a.title for a in question.actions] == ["保留这些顺序号不变", "取消"]


async def test_the_labels_kept_are_listed_as_chinese_lists_them(fanuc_zh: LanguageClient) -> None:
    # GOTO #1 in O0002 may land on its N20 or N30 (lines 7 and 8): keeping both names two lines, with 、
    text = "O0001\nN1 M98 P0002\nN2 M30\nO0002\n#1=20\nGOTO #1\nN20 #2=1\nN30 #3=1\nM99\n"
    uri = open_file(fanuc_zh, FANUC / "kept_zh.nc", text)
    _editor(fanuc_zh, answer="保留这些顺序号不变")
    kept = await _run(fanuc_zh, RENUMBER, uri=uri, step=10)
    close_file(fanuc_zh, uri)
    assert kept["applied"] and kept["kept"] == [7, 8], kept
    assert "第 7、8 行的顺序号保持不变" in fanuc_zh.messages[-1].message


async def test_bad_arguments_get_a_message_not_a_crash(fanuc_en: LanguageClient) -> None:
    _editor(fanuc_en)
    uri = open_file(fanuc_en, FANUC / "bad_args.nc", "O0001\nN1 #1=1\nM30\n")
    bad_step = await _run(fanuc_en, RENUMBER, uri=uri, step="ten")
    bad_range = await _run(fanuc_en, RENUMBER, uri=uri, step=10, range={"start": "x", "end": {"line": "y"}})
    not_open = await _run(fanuc_en, RENUMBER, uri="file:///nowhere.nc", step=10)
    close_file(fanuc_en, uri)
    assert not bad_step["applied"] and "step" in bad_step["error"]
    assert bad_range["applied"] and bad_range["changes"] == 1  # a range it cannot read: the whole file
    assert not_open is None
