"""The language server on a workspace that anybody may have filled (docs/design.md "Untrusted
folders and files"), over stdio as an editor starts it: ``initialize`` is answered (a failed one is
fatal to VS Code) and the server goes on working, whatever the folders hold. What it could not
read is named in a warning; a broken machine file is an error diagnostic on that file."""

from __future__ import annotations

import asyncio
import os
import sys
import time
from pathlib import Path
from typing import Any

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import ClientServerConfig, LanguageClient

from hardening.unprivileged import command
from hardening.untrusted import (
    FINDING,
    HOSTILE_MACHINE_FILES,
    make_deep,
    remove_deep,
    shut_folders,
    sparse_file,
    write_gbk_named,
)
from lsp.lsp_session import diagnostics_for, open_file, start

pytestmark = pytest.mark.asyncio
TIMEOUT = 20.0  # seconds: a server that waits this long is stuck
WHOLE_DISK_SECONDS = 60.0  # an index of "/" stopped by its caps, on a busy machine
fifo_only = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs FIFOs")
linux_only = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="Linux file names and /proc")


@pytest_lsp.fixture(config=ClientServerConfig(server_command=command(sys.executable, "-m", "cncmacro", "lsp")))
async def client(lsp_client: LanguageClient):  # type: ignore[no-untyped-def]
    """A server not yet initialised (each test makes its workspace first), meeting file
    permissions as any user does, also when the tests run as root."""
    yield
    try:
        await asyncio.wait_for(lsp_client.shutdown_session(), TIMEOUT)
    except Exception:  # a stuck server is stopped by the fixture
        pass


async def initialize(client: LanguageClient, root: Path, locale: str = "en", timeout: float = TIMEOUT) -> float:
    """``initialize`` and ``initialized`` on ``root``; the seconds ``initialize`` took."""
    t0 = time.perf_counter()
    await asyncio.wait_for(start(client, root, locale), timeout)
    return time.perf_counter() - t0


async def shown_warning(client: LanguageClient) -> str:
    """The text of the first ``window/showMessage`` warning."""

    async def wait() -> str:
        while not client.messages:
            await asyncio.sleep(0.02)
        [message] = client.messages
        assert message.type == types.MessageType.Warning
        return message.message

    return await asyncio.wait_for(wait(), TIMEOUT)


async def symbols(client: LanguageClient, query: str = "") -> list[str]:
    found = await asyncio.wait_for(client.workspace_symbol_async(types.WorkspaceSymbolParams(query=query)), TIMEOUT)
    return sorted(s.name for s in found or [])


async def still_works(client: LanguageClient, root: Path) -> None:
    """A program opened now gets its diagnostics."""
    uri = open_file(client, root / "O0001.nc", FINDING)
    diags = (await asyncio.wait_for(diagnostics_for(client, uri, 1), TIMEOUT)).diagnostics
    assert [(d.range.start.line, d.code) for d in diags if d.code != "not-executed"] == [(1, "variable-number")]


async def published(client: LanguageClient, uri: str, accept: Any) -> list[types.Diagnostic]:
    """The diagnostics last published for ``uri``, once ``accept`` takes them."""

    async def wait() -> list[types.Diagnostic]:
        while uri not in client.diagnostics or not accept(client.diagnostics[uri]):
            await asyncio.sleep(0.02)
        return list(client.diagnostics[uri])

    return await asyncio.wait_for(wait(), TIMEOUT)


async def test_folders_that_cannot_be_entered_are_named_and_the_server_starts(
    client: LanguageClient, tmp_path: Path
) -> None:
    with shut_folders(tmp_path) as root:
        await initialize(client, root)
        said = await shown_warning(client)
        assert said.startswith("cncmacro: 3 folders or files in the workspace were not read: ")
        assert f"{root / 'listed' / 'O0002.nc'}: cannot read (Permission denied)" in said
        assert f"{root / 'listed' / 'inner'}: cannot read the folder (Permission denied)" in said
        assert f"{root / 'shut'}: cannot read the folder (Permission denied)" in said
        logged = [m.message for m in client.log_messages if m.type == types.MessageType.Warning]
        assert len(logged) == 3
        assert await symbols(client) == ["O0001"]
        await still_works(client, root)


async def test_a_workspace_folder_of_the_whole_disk_is_searched_within_bounds(
    client: LanguageClient, tmp_path: Path
) -> None:
    # a hang guard, not a timing: the index stops at its caps in about 5 s on a quiet machine (a
    # disk full of program files, under make test's three lanes, took over 20 s), where a walk of
    # the whole disk takes many minutes
    took = await initialize(client, Path("/"), timeout=WHOLE_DISK_SECONDS)
    assert took < WHOLE_DISK_SECONDS, f"initialize took {took:.1f} s"
    await symbols(client, "O9999")  # answered
    await still_works(client, tmp_path)


@linux_only
async def test_a_file_name_that_is_not_utf8_leaves_the_workspace_working(
    client: LanguageClient, tmp_path: Path
) -> None:
    write_gbk_named(tmp_path, b"O9100\n#2=1/#0\nM99\n")  # found by its O9100 header
    write_gbk_named(tmp_path, b"#3=1\nM99\n", b"\xb3\xcc.nc")  # no header: named after its file
    (tmp_path / "O0001.nc").write_text("O0001\nG65 P9100\nM30\n", encoding="utf-8")
    await initialize(client, tmp_path)
    assert await symbols(client) == ["O0001", "O9100", "程"]
    uri = open_file(client, tmp_path / "O0001.nc")
    called = f"{tmp_path.as_uri()}/%B3%CC%D0%F2.nc"  # the name's own bytes
    found = await published(client, called, lambda d: bool(d))
    assert [(d.range.start.line, d.code) for d in found if d.code != "not-executed"] == [(1, "division-by-zero")]
    mine = await published(client, uri, lambda d: True)  # published with the called file's
    assert [d.code for d in mine if d.code != "not-executed"] == []
    definition = await client.text_document_definition_async(
        types.DefinitionParams(types.TextDocumentIdentifier(uri), types.Position(1, 6))
    )
    assert [loc.target_uri if isinstance(loc, types.LocationLink) else loc.uri for loc in definition or []] == [called]


async def test_a_thousand_nested_folders_are_indexed(client: LanguageClient, tmp_path: Path) -> None:
    deep = make_deep(tmp_path)
    (deep / "O0002.nc").write_text("O0002\nM30\n", encoding="utf-8")
    try:
        await initialize(client, tmp_path)
        assert await symbols(client) == ["O0002"]
        await still_works(client, tmp_path)
    finally:
        remove_deep(tmp_path / "d")


@linux_only
async def test_a_2_gb_program_file_is_named_and_never_read(client: LanguageClient, tmp_path: Path) -> None:
    sparse_file(tmp_path / "O8100.nc")
    (tmp_path / "O0002.nc").write_text("O0002\nG65 P8100\nM30\n", encoding="utf-8")
    await initialize(client, tmp_path)
    said = await shown_warning(client)
    assert said.startswith("cncmacro: 1 folder or file in the workspace was not read: ")
    assert (
        f"{tmp_path / 'O8100.nc'}: 2,147,483,648 bytes, over the limit of 8,000,000: not read for the programs" in said
    )
    assert await symbols(client) == ["O0002"]
    uri = open_file(client, tmp_path / "O0002.nc")  # its call looks for O8100 on disk
    diags = (await asyncio.wait_for(diagnostics_for(client, uri, 1), TIMEOUT)).diagnostics
    assert [d.code for d in diags if d.code != "not-executed"] == ["program-not-found"]
    pid = client._server.pid  # type: ignore[attr-defined]  # the server's process
    peak = next(line for line in Path(f"/proc/{pid}/status").read_text().splitlines() if line.startswith("VmHWM"))
    assert int(peak.split()[1]) < 300 * 1024, peak  # kB: reading the file would take 2 GB


@fifo_only
async def test_a_fifo_in_a_file_event_never_blocks_the_server(client: LanguageClient, tmp_path: Path) -> None:
    (tmp_path / "O0001.nc").write_text(FINDING, encoding="utf-8")
    await initialize(client, tmp_path)
    fifo = tmp_path / "O1234.nc"
    os.mkfifo(fifo)
    try:
        client.workspace_did_change_watched_files(types.DidChangeWatchedFilesParams(
            [types.FileEvent(fifo.as_uri(), types.FileChangeType.Created)]))  # fmt: skip
        assert await symbols(client) == ["O0001"]
        logged = [m.message for m in client.log_messages if m.type == types.MessageType.Warning]
        assert logged == [f"{fifo}: a FIFO (named pipe), not a file: not read"]
        await still_works(client, tmp_path)
    finally:
        try:  # a server that opened it to read waits for a writer: this one lets it go
            os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))
        except OSError:
            pass


@pytest.mark.parametrize("name", [*HOSTILE_MACHINE_FILES, "a FIFO"])
async def test_a_hostile_machine_file_is_a_diagnostic_on_it_and_the_server_starts(
    client: LanguageClient, tmp_path: Path, name: str
) -> None:
    machine = tmp_path / ".cncmacro.toml"
    if name == "a FIFO":
        if not hasattr(os, "mkfifo"):
            pytest.skip("needs FIFOs")
        os.mkfifo(machine)
        said = "a FIFO (named pipe), not a file: not read (the machine file)"
    else:
        content, said = HOSTILE_MACHINE_FILES[name]
        machine.write_bytes(content if isinstance(content, bytes) else content.encode("utf-8"))
    await initialize(client, tmp_path)
    [problem] = await published(client, machine.as_uri(), lambda d: bool(d))
    assert (problem.code, problem.severity) == ("machine-file", types.DiagnosticSeverity.Error)
    assert problem.message.startswith(f"{machine}: ") and said in problem.message, problem.message
    await still_works(client, tmp_path)
    machine.unlink()  # made right again
    machine.write_text('base = "fanuc-0i"\n', encoding="utf-8")
    client.workspace_did_change_watched_files(types.DidChangeWatchedFilesParams(
        [types.FileEvent(machine.as_uri(), types.FileChangeType.Changed)]))  # fmt: skip
    assert await published(client, machine.as_uri(), lambda d: not d) == []


async def test_a_machine_file_problem_is_on_its_line(client: LanguageClient, tmp_path: Path) -> None:
    machine = tmp_path / ".cncmacro.toml"
    machine.write_text('base = "fanuc-0i"\n\n[calls]\nG100 = 9010\n"G²" = 9000\n', encoding="utf-8")
    await initialize(client, tmp_path, "zh-CN")
    [problem] = await published(client, machine.as_uri(), lambda d: bool(d))
    assert (problem.range.start.line, problem.range.start.character) == (4, 0)
    assert problem.message == f"{machine}：'calls.G²' 必须是 G 或 M 代码（G100、M50）或 T"
