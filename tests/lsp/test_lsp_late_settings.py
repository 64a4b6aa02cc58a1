"""The editor's settings answered late (a busy editor at start answers ``workspace/configuration``
after the server stopped waiting, 2 s): the server analyses with the initialization options
meanwhile, and applies the settings when they come. A late answer used to arrive for a request
the server had given up on: the settings were lost, and the server logged an error."""

from __future__ import annotations

import asyncio
from collections.abc import AsyncIterator

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import ClientServerConfig, LanguageClient

from .lsp_session import FANUC, SERVER, close_file, hover_text, open_file, start

pytestmark = pytest.mark.asyncio(loop_scope="module")

LATE_SECONDS = 3.0  # beyond the 2 s the server waits for the settings at start


@pytest_lsp.fixture(config=ClientServerConfig(server_command=SERVER), loop_scope="module")
async def late(lsp_client: LanguageClient) -> AsyncIterator[LanguageClient]:
    lsp_client.protocol.fm._features.pop(types.WORKSPACE_CONFIGURATION)  # pytest-lsp's answers at once

    @lsp_client.feature(types.WORKSPACE_CONFIGURATION)
    async def configuration(params: types.ConfigurationParams) -> list[object]:
        await asyncio.sleep(LATE_SECONDS)
        return [{"dialect": "gsk980tdi"}]

    await start(lsp_client, FANUC, "en")
    yield lsp_client
    await lsp_client.shutdown_session()


async def test_settings_answered_after_the_wait_still_apply(late: LanguageClient) -> None:
    uri = open_file(late, FANUC / "late.nc", "O0001\nG00 X10.\nM30\n")
    early = await hover_text(late, uri, 1, 1)
    await asyncio.sleep(LATE_SECONDS + 0.5)
    after = await hover_text(late, uri, 1, 1)
    close_file(late, uri)
    assert "FANUC" in early and "GSK" not in early
    assert "GSK" in after, after
