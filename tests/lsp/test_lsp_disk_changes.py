"""Programs changed on disk reach the diagnostics, whatever the editor watches: an editor that
registers watchers at run time is asked for one on the program files and the machine file; one
that cannot (Neovim on Linux) gets the called programs and the machine file read again when
their time or size changes (at the next edit, or on its own a moment later); a FIFO named like
a program never stops the server."""

from __future__ import annotations

import asyncio
import contextlib
import fnmatch
import os
from pathlib import Path, PurePosixPath

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient, client_capabilities

from .lsp_session import close_file, config, diagnostics_for, edit, open_file, published_where, start

pytestmark = pytest.mark.asyncio(loop_scope="module")

MAIN = "O0001 (MAIN)\nG65 P1234 A2.\nM30\n"
MACRO = "O1234 (RING)\n#10=360/[#1-2]\nM99\n"  # A2.: a division by zero on line 1


@pytest_lsp.fixture(config=config(), scope="module")
async def watching(lsp_client: LanguageClient, tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    """A client that registers watchers at run time (VS Code's capabilities)."""
    lsp_client.root = root = tmp_path_factory.mktemp("watched")  # type: ignore[attr-defined]
    await start(lsp_client, root, "en")
    yield
    await lsp_client.shutdown_session()


@pytest_lsp.fixture(config=config(), scope="module")
async def not_watching(lsp_client: LanguageClient, tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    """A client that sends no file events (VS Code's capabilities without file watching)."""
    caps = client_capabilities("visual-studio-code")
    assert caps.workspace is not None
    caps.workspace.did_change_watched_files = None
    lsp_client.root = root = tmp_path_factory.mktemp("not_watched")  # type: ignore[attr-defined]
    await start(lsp_client, root, "en", capabilities=caps)
    yield
    await lsp_client.shutdown_session()


def findings(found: types.PublishDiagnosticsParams) -> list[tuple[int, str]]:
    return [(d.range.start.line, str(d.code)) for d in found.diagnostics if d.code != "not-executed"]


def division_lines(items: list[types.Diagnostic]) -> list[int]:
    return [d.range.start.line for d in items if d.code == "division-by-zero"]


def rewrite(path: Path, text: str) -> None:
    """Write ``text`` over ``path`` in place, its modification time moved on by a second."""
    before = path.stat()
    path.write_text(text, "utf-8")
    os.utime(path, ns=(before.st_atime_ns, before.st_mtime_ns + 1_000_000_000))


def release(fifo: Path) -> None:
    """Let a reader that waits on ``fifo`` go on (a writer comes and goes)."""
    with contextlib.suppress(OSError):
        os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))


def matches(glob: str, path: str) -> bool:
    assert glob.startswith("**/") and "/" not in glob[3:], glob
    return fnmatch.fnmatchcase(PurePosixPath(path).name, glob[3:])


async def test_a_client_that_registers_watchers_is_asked_to_watch_the_program_files(watching: LanguageClient) -> None:
    async def registered() -> list[types.Registration]:
        while not watching.registrations:  # type: ignore[attr-defined]
            await asyncio.sleep(0.01)
        return watching.registrations  # type: ignore[attr-defined]

    got = await asyncio.wait_for(registered(), 10)
    assert [r.method for r in got] == [types.WORKSPACE_DID_CHANGE_WATCHED_FILES]
    options = got[0].register_options
    watchers = options["watchers"] if isinstance(options, dict) else options.watchers  # type: ignore[union-attr]
    globs = [w["globPattern"] if isinstance(w, dict) else w.glob_pattern for w in watchers]
    assert all(isinstance(g, str) for g in globs)
    watched = [
        "O1234.nc", "sub/O1234.NC", "PART.CNC", "deep/a/b/Wheel.Cnc", "lib/MACRO.mac", "x.PRG", "tape.Tap",
        "old.eia", "O9100", "o9100", ".cncmacro.toml", "sub/.cncmacro.toml",
    ]  # fmt: skip
    for path in watched:
        assert any(matches(g, path) for g in globs), f"{path} is not watched by {globs}"
    for path in ["notes.txt", "README.md", "build/out.json", "cncmacro.toml"]:
        assert not any(matches(g, path) for g in globs), f"{path} is watched by {globs}"


async def test_a_called_program_changed_on_disk_is_read_again_without_file_events(
    not_watching: LanguageClient,
) -> None:
    root: Path = not_watching.root  # type: ignore[attr-defined]
    macro = root / "O1234.nc"
    macro.write_text(MACRO, "utf-8")
    macro_uri = macro.as_uri()
    uri = open_file(not_watching, root / "MAIN.nc", MAIN)
    try:
        await diagnostics_for(not_watching, uri, 1)
        got = await published_where(not_watching, {macro_uri: lambda d: division_lines(d) == [1]}, timeout=10)
        assert division_lines(got[macro_uri]) == [1]
        assert not_watching.registrations == []  # type: ignore[attr-defined]

        # fixed on disk (and broken on the next line), no file event: the next edit reads it again
        rewrite(macro, "O1234 (RING)\n#10=360/[#1+2]\n#11=1/[#1-2]\nM99\n")
        edit(not_watching, uri, 2, 1, 10, 13, "A2.0")
        await diagnostics_for(not_watching, uri, 2)
        got = await published_where(not_watching, {macro_uri: lambda d: division_lines(d) == [2]}, timeout=10)
        assert division_lines(got[macro_uri]) == [2]

        # changed again, and no edit comes: it is read again all the same, a moment later
        rewrite(macro, "O1234 (RING)\n#10=360/[#1+2]\n#11=1/[#1+2]\n#12=1/[#1-2]\nM99\n")
        got = await published_where(not_watching, {macro_uri: lambda d: division_lines(d) == [3]}, timeout=10)
        assert division_lines(got[macro_uri]) == [3]
    finally:
        close_file(not_watching, uri)


async def test_a_machine_file_created_in_a_document_s_folder_applies_to_it_without_file_events(
    not_watching: LanguageClient,
) -> None:
    root: Path = not_watching.root  # type: ignore[attr-defined]
    folder = root / "lathe"
    folder.mkdir(exist_ok=True)
    machine = folder / ".cncmacro.toml"
    uri = open_file(not_watching, folder / "MAIN4.nc", "O0004\n#150=1\nM30\n")
    try:
        assert findings(await diagnostics_for(not_watching, uri, 1)) == []
        machine.write_text("common = [[100, 149]]\n", "utf-8")  # the nearest machine file, below the root
        edit(not_watching, uri, 2, 1, 5, 6, "2")
        found = await asyncio.wait_for(diagnostics_for(not_watching, uri, 2), 10)
        assert findings(found) == [(1, "variable-number")]
    finally:
        machine.unlink(missing_ok=True)
        close_file(not_watching, uri)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs are a POSIX thing")
async def test_a_called_program_replaced_by_a_fifo_is_not_found_without_file_events(
    not_watching: LanguageClient,
) -> None:
    root: Path = not_watching.root  # type: ignore[attr-defined]
    macro = root / "O4321.nc"
    macro.write_text(MACRO.replace("O1234", "O4321"), "utf-8")
    macro_uri = macro.as_uri()
    uri = open_file(not_watching, root / "MAIN2.nc", MAIN.replace("P1234", "P4321"))
    try:
        await published_where(not_watching, {macro_uri: lambda d: division_lines(d) == [1]}, timeout=10)
        macro.unlink()
        os.mkfifo(macro)
        edit(not_watching, uri, 2, 1, 10, 13, "A2.0")
        found = await asyncio.wait_for(diagnostics_for(not_watching, uri, 2), 10)
        assert findings(found) == [(1, "program-not-found")]
        await published_where(not_watching, {macro_uri: lambda d: not d}, timeout=10)  # its finding is gone
    finally:
        release(macro)
        close_file(not_watching, uri)


async def test_a_machine_file_created_on_disk_applies_without_file_events(not_watching: LanguageClient) -> None:
    root: Path = not_watching.root  # type: ignore[attr-defined]
    machine = root / ".cncmacro.toml"
    uri = open_file(not_watching, root / "MAIN3.nc", "O0003\n#150=1\nM30\n")
    try:
        assert findings(await diagnostics_for(not_watching, uri, 1)) == []
        machine.write_text("common = [[100, 149]]\n", "utf-8")  # this machine has #100-#149 only
        edit(not_watching, uri, 2, 1, 5, 6, "2")
        found = await asyncio.wait_for(diagnostics_for(not_watching, uri, 2), 10)
        assert findings(found) == [(1, "variable-number")]
    finally:
        machine.unlink(missing_ok=True)
        close_file(not_watching, uri)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs are a POSIX thing")
async def test_a_fifo_named_like_a_program_is_never_opened(watching: LanguageClient) -> None:
    root: Path = watching.root  # type: ignore[attr-defined]
    fifo = root / "O5678.nc"
    os.mkfifo(fifo)
    uri = None
    try:
        created = types.FileEvent(uri=fifo.as_uri(), type=types.FileChangeType.Created)
        watching.workspace_did_change_watched_files(types.DidChangeWatchedFilesParams(changes=[created]))
        symbols = await asyncio.wait_for(watching.workspace_symbol_async(types.WorkspaceSymbolParams(query="")), 5)
        assert symbols == []  # answered, and the FIFO is no program
        uri = open_file(watching, root / "MAIN.nc", "O0001\nG65 P5678 A1.\nM30\n")
        found = await asyncio.wait_for(diagnostics_for(watching, uri, 1), 10)
        assert findings(found) == [(1, "program-not-found")]
    finally:
        release(fifo)
        if uri is not None:
            close_file(watching, uri)


async def test_a_txt_callee_no_watcher_covers_is_read_again_when_it_changes(watching: LanguageClient) -> None:
    """``1234.txt`` is a program by its first line (``O1234``), but neither its ending nor its name
    is one the editor's watcher reports: with the watcher in force it is still looked at."""
    root: Path = watching.root  # type: ignore[attr-defined]
    macro = root / "1234.txt"
    macro.write_text(MACRO, "utf-8")
    macro_uri = macro.as_uri()
    uri = open_file(watching, root / "MAIN5.nc", MAIN)
    try:
        await published_where(watching, {macro_uri: lambda d: division_lines(d) == [1]}, timeout=10)
        rewrite(macro, "O1234 (RING)\n#10=360/[#1+2]\n#11=1/[#1-2]\nM99\n")  # no file event comes
        got = await published_where(watching, {macro_uri: lambda d: division_lines(d) == [2]}, timeout=10)
        assert division_lines(got[macro_uri]) == [2]
    finally:
        close_file(watching, uri)
        macro.unlink()
