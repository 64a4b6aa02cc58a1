"""A bad ``[skip]`` table in the editor (docs/machine-file.md "Probing: the [skip] table"): the
problem is a ``machine-file`` error on the line of the key, in the client's language, and the
message names the key without the line the editor already points at."""

from __future__ import annotations

from pathlib import Path

import pytest
import pytest_lsp
from pytest_lsp import LanguageClient

from .lsp_session import config, open_file, published_where, start

pytestmark = pytest.mark.asyncio
TIMEOUT = 30.0
MACHINE = '[skip]\nZ = -12.5\nbore = { X = 0, Y = 0, diameter = "50" }\n'


@pytest_lsp.fixture(config=config())
async def client(lsp_client: LanguageClient):  # type: ignore[no-untyped-def]
    """A server not yet initialised: each test makes its workspace first."""
    yield
    await lsp_client.shutdown_session()


@pytest.mark.parametrize(
    ("locale", "said"),
    [("en", "'skip.bore' has a 'diameter' that is not a number above 0"),
     ("zh-CN", "'skip.bore' 的 'diameter' 不是大于 0 的数值")],
)  # fmt: skip
async def test_a_bad_bore_is_an_error_on_its_line(
    client: LanguageClient, tmp_path: Path, locale: str, said: str
) -> None:
    machine = tmp_path / ".cncmacro.toml"
    machine.write_text(MACHINE, encoding="utf-8")
    (tmp_path / "O0001.nc").write_text("O0001\nG31 X10 F100\nM30\n", encoding="utf-8")
    await start(client, tmp_path, locale)
    open_file(client, tmp_path / "O0001.nc")
    got = await published_where(client, {machine.as_uri(): lambda d: bool(d)}, TIMEOUT)
    [problem] = got[machine.as_uri()]
    assert (problem.code, problem.range.start.line) == ("machine-file", 2)
    assert problem.message.endswith(said)
