"""A lathe program read under a mill profile, through the language server (docs/editor.md
"A lathe program under a mill profile"): one ``profile-suggestion`` (information) names the lathe
profile, its quick fixes write ``(cncmacro: dialect=fanuc-0i-lathe)`` or the machine file's
``base``, after which the file is read as the lathe and the finding is gone; a lathe profile and
the mill corpora get none."""

from __future__ import annotations

from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import actions_for, config, diagnostics_for, open_file, published_where, start

pytestmark = pytest.mark.asyncio(loop_scope="module")

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
LATHE = (
    "%\nO0100 (SHAFT)\nG21 G40 G99\nT0101\nG50 S2500\nG96 S180 M03\nG00 X52. Z2. M08\nG71 U2. R0.5\n"
    "G71 P10 Q20 U0.5 W0.1 F0.25\nN10 G00 X20.\nG01 Z-20. F0.1\nX30. W-10.\nZ-45.\nN20 X52.\nG70 P10 Q20\n"
    "G00 X100. Z100.\nT0303\nG97 S600\nG00 X32. Z5.\nG92 X29.2 Z-30. F1.5\nX28.6\nG00 X100. Z100.\nM30\n%\n"
)


@pytest_lsp.fixture(config=config(), scope="module")
async def shop(lsp_client: LanguageClient, tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    """A workspace of its own (the quick fixes write its machine file), no machine file at first."""
    lsp_client.root = root = tmp_path_factory.mktemp("lathe_shop")  # type: ignore[attr-defined]
    await start(lsp_client, root, "en")
    yield
    await lsp_client.shutdown_session()


@pytest_lsp.fixture(config=config(), scope="module")
async def corpus(lsp_client: LanguageClient):  # type: ignore[no-untyped-def]
    await start(lsp_client, CORPUS, "en")
    yield
    await lsp_client.shutdown_session()


def hints(diags: list[types.Diagnostic]) -> list[types.Diagnostic]:
    return [d for d in diags if d.code == "profile-suggestion"]


def applied(text: str, edits: list[types.TextEdit]) -> str:
    """``text`` with ``edits`` (of whole lines' starts and ends, ASCII) applied, last first."""
    lines = text.split("\n")
    for e in sorted(edits, key=lambda e: (e.range.start.line, e.range.start.character), reverse=True):
        start, end = e.range.start, e.range.end
        head = "\n".join([*lines[: start.line], lines[start.line][: start.character]])
        tail = "\n".join([lines[end.line][end.character :], *lines[end.line + 1 :]])
        lines = (head + e.new_text + tail).split("\n")
    return "\n".join(lines)


async def dialect_of(client: LanguageClient, uri: str) -> object:
    return await client.protocol.send_request_async("cncmacro/documentDialect", {"uri": uri})


async def test_a_lathe_program_under_fanuc_0i_gets_one_information_on_its_roughing_cycle(shop: LanguageClient) -> None:
    root: Path = shop.root  # type: ignore[attr-defined]
    uri = open_file(shop, root / "shaft.nc", LATHE)
    diags = (await diagnostics_for(shop, uri, 1)).diagnostics
    [hint] = hints(diags)
    assert hint.severity == types.DiagnosticSeverity.Information
    # line 9 (0-based 8) holds G71 P10 Q20 U0.5 W0.1 F0.25: the span of G71 P10 Q20
    assert (hint.range.start.line, hint.range.start.character, hint.range.end.character) == (8, 0, 11)
    assert hint.message.startswith("This looks like a lathe program (G71 P10 Q20 on line 9, T0101 on line 4")
    assert "Choose the lathe profile fanuc-0i-lathe" in hint.message
    assert [d.code for d in diags if d.severity is not None and d.severity <= 2] == []  # it is nothing else


async def test_the_comment_quick_fix_makes_the_file_a_fanuc_0i_lathe_program_without_the_finding(
    shop: LanguageClient,
) -> None:
    root: Path = shop.root  # type: ignore[attr-defined]
    uri = open_file(shop, root / "shaft_comment.nc", LATHE)
    [hint] = hints((await diagnostics_for(shop, uri, 1)).diagnostics)
    actions = await actions_for(shop, uri, hint)
    comment = next(a for a in actions if "(cncmacro: dialect=fanuc-0i-lathe)" in a.title)
    assert list(comment.diagnostics or []) == [hint]
    assert comment.edit is not None and comment.edit.changes is not None
    fixed = applied(LATHE, comment.edit.changes[uri])
    assert fixed.startswith("%\n(cncmacro: dialect=fanuc-0i-lathe)\nO0100 (SHAFT)\n")  # after the %, in line 2
    marked = open_file(shop, root / "shaft_marked.nc", fixed)
    diags = (await diagnostics_for(shop, marked, 1)).diagnostics
    assert hints(diags) == [] and [d.code for d in diags if d.severity is not None and d.severity <= 2] == []
    answer = await dialect_of(shop, marked)
    assert (answer.dialect, answer.lathe, answer.source) == ("fanuc-0i-lathe", True, "file")  # type: ignore[attr-defined]


async def test_the_machine_file_quick_fix_creates_it_with_base_fanuc_0i_lathe(shop: LanguageClient) -> None:
    root: Path = shop.root  # type: ignore[attr-defined]
    folder = root / "lathe_cell"
    folder.mkdir()
    uri = open_file(shop, folder / "shaft.nc", LATHE)
    [hint] = hints((await diagnostics_for(shop, uri, 1)).diagnostics)
    action = next(a for a in await actions_for(shop, uri, hint) if 'base = "fanuc-0i-lathe"' in a.title)
    assert action.edit is not None and action.edit.document_changes is not None
    create, write = action.edit.document_changes
    assert isinstance(create, types.CreateFile) and isinstance(write, types.TextDocumentEdit)
    machine = root / ".cncmacro.toml"  # the workspace's machine file, beside its first folder
    assert create.uri == write.text_document.uri == machine.as_uri()
    [edit] = write.edits
    machine.write_text(applied("", [edit]), "utf-8")  # as the editor applies it
    try:
        assert machine.read_text("utf-8") == 'base = "fanuc-0i-lathe"\n'
        created = types.FileEvent(uri=machine.as_uri(), type=types.FileChangeType.Created)
        shop.workspace_did_change_watched_files(types.DidChangeWatchedFilesParams(changes=[created]))
        await published_where(shop, {uri: lambda d: not hints(d)}, timeout=30)
        answer = await dialect_of(shop, uri)
        assert (answer.dialect, answer.source) == ("fanuc-0i-lathe", "workspace")  # type: ignore[attr-defined]
    finally:
        machine.unlink()
        changed = types.FileEvent(uri=machine.as_uri(), type=types.FileChangeType.Deleted)
        shop.workspace_did_change_watched_files(types.DidChangeWatchedFilesParams(changes=[changed]))


async def test_the_machine_file_quick_fix_changes_the_base_of_one_that_exists(shop: LanguageClient) -> None:
    root: Path = shop.root  # type: ignore[attr-defined]
    folder = root / "mill_named"
    folder.mkdir()
    machine = folder / ".cncmacro.toml"
    machine.write_text('# cell 4\nbase = "fanuc-0i"\ncommon = [[100, 199], [500, 999]]\n', "utf-8")
    uri = open_file(shop, folder / "shaft.nc", LATHE)
    # the other documents are published again meanwhile (the last test's machine file went): wait for this one
    got = await published_where(shop, {uri: lambda d: bool(hints(d))}, timeout=30)
    [hint] = hints(got[uri])
    assert "mill profile fanuc-0i" in hint.message  # the machine file names the mill
    action = next(a for a in await actions_for(shop, uri, hint) if 'base = "fanuc-0i-lathe"' in a.title)
    assert action.edit is not None and action.edit.changes is not None
    fixed = applied(machine.read_text("utf-8"), action.edit.changes[machine.as_uri()])
    assert fixed == '# cell 4\nbase = "fanuc-0i-lathe"\ncommon = [[100, 199], [500, 999]]\n'
    machine.write_text(fixed, "utf-8")
    changed = types.FileEvent(uri=machine.as_uri(), type=types.FileChangeType.Changed)
    shop.workspace_did_change_watched_files(types.DidChangeWatchedFilesParams(changes=[changed]))
    await published_where(shop, {uri: lambda d: not hints(d)}, timeout=30)
    answer = await dialect_of(shop, uri)
    assert (answer.dialect, answer.lathe) == ("fanuc-0i-lathe", True)  # type: ignore[attr-defined]


async def test_under_fanuc_30i_the_quick_fix_sets_lathe_true_its_own_lathe_form(shop: LanguageClient) -> None:
    root: Path = shop.root  # type: ignore[attr-defined]
    folder = root / "cell_30i"
    folder.mkdir()
    machine = folder / ".cncmacro.toml"
    machine.write_text('base = "fanuc-30i"\nlathe = false\n[severity]\nsyntax = "error"\n', "utf-8")
    uri = open_file(shop, folder / "shaft.nc", LATHE)
    [hint] = hints((await published_where(shop, {uri: lambda d: bool(hints(d))}, timeout=30))[uri])
    actions = await actions_for(shop, uri, hint)
    assert [a.title for a in actions] == [
        "Set lathe = true in .cncmacro.toml: a FANUC 30i-B lathe (G-code system A) (every file of the workspace)"
    ]  # no comment names the lathe form
    assert actions[0].edit is not None and actions[0].edit.changes is not None
    fixed = applied(machine.read_text("utf-8"), actions[0].edit.changes[machine.as_uri()])
    assert fixed == 'base = "fanuc-30i"\nlathe = true\n[severity]\nsyntax = "error"\n'
    machine.write_text(fixed, "utf-8")
    changed = types.FileEvent(uri=machine.as_uri(), type=types.FileChangeType.Changed)
    shop.workspace_did_change_watched_files(types.DidChangeWatchedFilesParams(changes=[changed]))
    await published_where(shop, {uri: lambda d: not hints(d)}, timeout=30)
    answer = await dialect_of(shop, uri)
    assert (answer.dialect, answer.lathe) == ("fanuc-30i", True)  # type: ignore[attr-defined]


async def test_a_lathe_program_under_a_lathe_profile_gets_no_suggestion(shop: LanguageClient) -> None:
    root: Path = shop.root  # type: ignore[attr-defined]
    for lathe in ("fanuc-0i-lathe", "gsk980tdi"):
        folder = root / lathe
        folder.mkdir()
        (folder / ".cncmacro.toml").write_text(f'base = "{lathe}"\n', "utf-8")
        uri = open_file(shop, folder / "shaft.nc", LATHE)
        diags = (await published_where(shop, {uri: lambda d: True}, timeout=30))[uri]
        assert hints(diags) == [], lathe
        assert (await dialect_of(shop, uri)).dialect == lathe  # type: ignore[attr-defined]


async def test_no_file_of_the_mill_corpora_gets_a_suggestion(corpus: LanguageClient) -> None:
    files = sorted(f for mill in ("fanuc-0i", "fanuc-30i", "haas") for f in (CORPUS / mill).glob("*.nc"))
    assert len(files) > 60
    uris = [f.as_uri() for f in files]
    for f in files:
        open_file(corpus, f, f.read_bytes().decode("utf-8", errors="replace"))
    got = await published_where(corpus, {uri: lambda d: True for uri in uris}, timeout=120)
    assert {uri: hints(d) for uri, d in got.items() if hints(d)} == {}
