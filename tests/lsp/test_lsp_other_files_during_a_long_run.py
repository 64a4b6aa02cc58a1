"""While one file's analysis runs to its bound (a program that counts for ever under a machine
file's huge ``max_blocks``, which only the run's 30 s end), another file opened meanwhile gets
its diagnostics within about a second: with several documents open, the runs take turns and
what is complete is published (docs/editor.md, "Diagnostics")."""

from __future__ import annotations

import asyncio
import time
from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import close_file, config, open_file, published_where, start

pytestmark = pytest.mark.asyncio

# counts to 10**8 before it ends: far beyond the 30 s a run may take, under max_blocks = 10**12
COUNTS_LONG = "O0001\n#1=0\nWHILE[#1 LT 1]DO1\n#2=#2+1\nIF[#2 GT 100000000]THEN#1=1\nEND1\nM30\n"
DIVIDES = "O0002\n#1=1/0\nM30\n"  # alarm 112 on line 2


@pytest_lsp.fixture(config=config())
async def client(lsp_client: LanguageClient):  # type: ignore[no-untyped-def]
    """A server not yet initialised: the test makes its workspace first."""
    yield
    await lsp_client.shutdown_session()


async def test_a_small_file_gets_its_diagnostics_while_a_long_run_goes_on(client: LanguageClient,
                                                                          tmp_path: Path) -> None:  # fmt: skip
    (tmp_path / ".cncmacro.toml").write_text("max_blocks = 1000000000000\n", "utf-8")
    (tmp_path / "long.nc").write_text(COUNTS_LONG, "utf-8")
    (tmp_path / "small.nc").write_text(DIVIDES, "utf-8")
    await start(client, tmp_path, "en")
    long_uri = open_file(client, tmp_path / "long.nc")
    await asyncio.sleep(1.0)  # its run is under way
    opened = time.monotonic()
    small_uri = open_file(client, tmp_path / "small.nc")

    def divides(found: list[types.Diagnostic]) -> bool:
        return any(d.code == "division-by-zero" and d.range.start.line == 1 for d in found)

    await published_where(client, {small_uri: divides}, timeout=10.0)
    waited = time.monotonic() - opened
    still_running = long_uri not in client.diagnostics  # its run goes on to its 30 s
    close_file(client, long_uri)  # stops it
    assert waited < 2.0, f"small.nc's diagnostics came {waited:.1f} s after it was opened"
    assert still_running
