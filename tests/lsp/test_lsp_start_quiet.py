"""A server that starts analyses a short program of its own before any document opens
(analysis/warm_up.py), so that the first program the user opens is checked sooner. Nothing of it
reaches the editor: no diagnostics, no message and no error before the first document opens, and
the first program opened is checked as any other."""

from __future__ import annotations

import asyncio
from collections.abc import AsyncIterator

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, config, diagnostics_for, open_file, publishes, start

pytestmark = pytest.mark.asyncio(loop_scope="module")


@pytest_lsp.fixture(config=config(), loop_scope="module")
async def started(lsp_client: LanguageClient) -> AsyncIterator[LanguageClient]:
    publishes(lsp_client)  # every publish kept from the start
    await start(lsp_client, FANUC, "en")
    yield lsp_client
    await lsp_client.shutdown_session()


async def test_a_started_server_says_nothing_until_a_program_opens_then_checks_it(started: LanguageClient) -> None:
    await asyncio.sleep(1.0)  # the server settles after ``initialized``
    assert publishes(started).count == 0
    assert started.messages == []
    assert [m.message for m in started.log_messages if m.type == types.MessageType.Error] == []
    uri = open_file(started, FANUC / "first_opened.nc", "O0001\nG00 X0 Y0\n#1=10/[#2-#2]\nM30\n")
    got = await diagnostics_for(started, uri, 1)
    # #2 is vacant: 10/[vacant - vacant] = 10/0, FANUC alarm 112 on line 3; M30 is never reached
    assert [(d.range.start.line, d.code) for d in got.diagnostics] == [(2, "division-by-zero"), (3, "not-executed")]
    assert set(publishes(started).by_uri) == {uri}
