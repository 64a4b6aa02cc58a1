"""A file event for something that is not a program file on disk, through the real server
over stdio: a pipe created in the workspace under a program's name is refused at once (the
workspace index reads regular files only, without blocking), and the server goes on answering."""

from __future__ import annotations

import asyncio
import contextlib
import os
from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient

from lsp.lsp_session import config, start

pytestmark = [
    pytest.mark.asyncio(loop_scope="module"),
    pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs named pipes"),
]


@pytest_lsp.fixture(config=config(), scope="module")
async def client(lsp_client: LanguageClient, tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    root = tmp_path_factory.mktemp("events_workspace")
    (root / "O0001.nc").write_text("O0001 (MAIN)\nM30\n", encoding="utf-8")
    lsp_client.root = root  # type: ignore[attr-defined]
    await start(lsp_client, root, "en")
    yield
    await lsp_client.shutdown_session()


def _unblock(pipe: Path) -> None:
    """Open the pipe's writing end and close it, so that a reader waiting on it sees its end."""
    with contextlib.suppress(OSError):  # no reader: nobody waits on it
        os.close(os.open(pipe, os.O_WRONLY | os.O_NONBLOCK))


async def test_a_pipe_created_under_a_programs_name_is_refused_and_the_server_answers(client: LanguageClient) -> None:
    pipe = client.root / "O0005.nc"  # type: ignore[attr-defined]
    os.mkfifo(pipe)
    try:
        client.workspace_did_change_watched_files(
            types.DidChangeWatchedFilesParams([types.FileEvent(pipe.as_uri(), types.FileChangeType.Created)])
        )
        found = await asyncio.wait_for(client.workspace_symbol_async(types.WorkspaceSymbolParams(query="O")), 10)
        assert [s.name for s in found or []] == ["O0001"]
    finally:
        _unblock(pipe)
        pipe.unlink()
