"""A Haas lathe program read under the Haas mill profile, through the language server
(docs/profiles.md "How a lathe program is recognised", "haas-lathe"): its ``profile-suggestion``
names ``haas-lathe``, the mill's own lathe, not a FANUC lathe; the comment quick fix writes
``(cncmacro: dialect=haas-lathe)`` and the file is then read as a Haas lathe with no finding.
The same text under ``fanuc-0i`` still names ``fanuc-0i-lathe``."""

from __future__ import annotations

from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import config, diagnostics_for, open_file, published_where, start
from .test_lsp_lathe_program import actions_for, applied, dialect_of, hints

pytestmark = pytest.mark.asyncio(loop_scope="module")

# a shaft roughed with Haas's one-block G71 and threaded with its one-block G76
SHAFT = (
    "%\nO01200 (SHAFT)\nG21 G40 G99\nT0101\nG50 S2500\nG96 S180 M03\nG00 X52. Z2. M08\n"
    "G71 P10 Q20 U0.5 W0.1 D1.5 F0.25\nN10 G00 X20.\nG01 Z-20. F0.1\nX30. W-10.\nZ-45.\nN20 X52.\n"
    "G70 P10 Q20\nG00 X100. Z100.\nT0303\nG97 S600\nG00 X32. Z5.\nG76 X28.16 Z-30. K0.92 D0.3 A60 F1.5\n"
    "G00 X100. Z100.\nM30\n%\n"
)


@pytest_lsp.fixture(config=config(), scope="module")
async def shop(lsp_client: LanguageClient, tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    lsp_client.root = root = tmp_path_factory.mktemp("haas_lathe_shop")  # type: ignore[attr-defined]
    await start(lsp_client, root, "en")
    yield
    await lsp_client.shutdown_session()


async def test_under_haas_a_lathe_program_is_offered_haas_lathe_not_a_fanuc_lathe(shop: LanguageClient) -> None:
    root: Path = shop.root  # type: ignore[attr-defined]
    folder = root / "haas_cell"
    folder.mkdir()
    (folder / ".cncmacro.toml").write_text('base = "haas"\n', "utf-8")
    uri = open_file(shop, folder / "shaft.nc", SHAFT)
    [hint] = hints((await published_where(shop, {uri: lambda d: bool(hints(d))}, timeout=30))[uri])
    assert hint.severity == types.DiagnosticSeverity.Information
    # line 8 (0-based 7) holds G71 P10 Q20 U0.5 W0.1 D1.5 F0.25: the span of G71 P10 Q20
    assert (hint.range.start.line, hint.range.start.character, hint.range.end.character) == (7, 0, 11)
    assert "mill profile haas" in hint.message
    assert "Choose the lathe profile haas-lathe (Haas lathe)" in hint.message
    assert "fanuc-0i-lathe" not in hint.message
    titles = [a.title for a in await actions_for(shop, uri, hint)]
    assert any("(cncmacro: dialect=haas-lathe)" in t for t in titles)
    assert any('base = "haas-lathe"' in t for t in titles)
    assert not any("fanuc-0i-lathe" in t for t in titles)


async def test_the_comment_quick_fix_makes_it_a_haas_lathe_program_without_findings(shop: LanguageClient) -> None:
    root: Path = shop.root  # type: ignore[attr-defined]
    folder = root / "haas_cell_2"
    folder.mkdir()
    (folder / ".cncmacro.toml").write_text('base = "haas"\n', "utf-8")
    uri = open_file(shop, folder / "shaft.nc", SHAFT)
    [hint] = hints((await published_where(shop, {uri: lambda d: bool(hints(d))}, timeout=30))[uri])
    comment = next(a for a in await actions_for(shop, uri, hint) if "(cncmacro: dialect=haas-lathe)" in a.title)
    assert comment.edit is not None and comment.edit.changes is not None
    fixed = applied(SHAFT, comment.edit.changes[uri])
    assert fixed.startswith("%\n(cncmacro: dialect=haas-lathe)\nO01200 (SHAFT)\n")
    marked = open_file(shop, folder / "shaft_marked.nc", fixed)
    diags = (await published_where(shop, {marked: lambda d: True}, timeout=30))[marked]
    assert hints(diags) == [] and [d.code for d in diags if d.severity is not None and d.severity <= 2] == []
    answer = await dialect_of(shop, marked)
    assert (answer.dialect, answer.lathe, answer.source) == ("haas-lathe", True, "file")  # type: ignore[attr-defined]


async def test_under_fanuc_0i_the_same_program_is_offered_the_fanuc_lathe(shop: LanguageClient) -> None:
    root: Path = shop.root  # type: ignore[attr-defined]
    uri = open_file(shop, root / "shaft_fanuc.nc", SHAFT)
    [hint] = hints((await diagnostics_for(shop, uri, 1)).diagnostics)
    assert "Choose the lathe profile fanuc-0i-lathe" in hint.message
    assert "haas-lathe" not in hint.message
