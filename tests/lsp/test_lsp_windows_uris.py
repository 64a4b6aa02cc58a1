"""Documents as VS Code on Windows names them: ``file:///c%3A/...``, the drive letter in lower case
and its colon escaped. The server reads that as the drive's path, so a program in the folder is
found by its callers, and publishes its findings under the very URI the editor sent (a URI
written another way would be a second document the editor never shows); and a program on a
share (``file://server/share/...``) finds its callees on the share. Windows only: the
drive letters are the system's; runs on the Windows runner."""

from __future__ import annotations

import sys
from pathlib import Path
from urllib.parse import quote

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import config, diagnostics_for, start

pytestmark = [
    pytest.mark.asyncio(loop_scope="module"),
    pytest.mark.skipif(sys.platform != "win32", reason="Windows only: drive letters (runs on the Windows runner)"),
]


def vscode_uri(path: Path) -> str:
    """The URI VS Code sends for ``path`` on Windows: ``file:///c%3A/folder/O0001.nc``."""
    text = str(path.resolve())
    drive, rest = text[0].lower(), text[2:].replace("\\", "/")
    return f"file:///{drive}%3A{quote(rest)}"


@pytest_lsp.fixture(config=config(), scope="module")
async def client(lsp_client: LanguageClient, tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    root = tmp_path_factory.mktemp("drive_letters").resolve()  # the long names, as the editor has them
    (root / "O1234.nc").write_text("O1234\nG01 X1. F100\nM99\n", encoding="utf-8")
    lsp_client.root = root  # type: ignore[attr-defined]
    await start(lsp_client, root, "en")
    yield
    await lsp_client.shutdown_session()


async def test_a_document_named_with_an_escaped_drive_colon_finds_its_callee_and_keeps_its_uri(
    client: LanguageClient,
) -> None:
    root: Path = client.root  # type: ignore[attr-defined]
    uri = vscode_uri(root / "O0001.nc")
    assert "%3A" in uri
    text = "O0001\nM98 P1234\n#1=1/0\nM30\n"
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(types.TextDocumentItem(uri=uri, language_id="cncmacro", version=1, text=text))
    )
    got = await diagnostics_for(client, uri, 1)  # published under the URI as the editor wrote it
    # the callee on the drive is found (no program-not-found); the run reaches the division
    assert [(d.range.start.line, d.code) for d in got.diagnostics if d.code != "not-executed"] == [
        (2, "division-by-zero")
    ]


async def test_a_document_on_a_unc_share_finds_its_callee_on_the_share(client: LanguageClient) -> None:
    root: Path = client.root  # type: ignore[attr-defined]
    # the runner's drive through its administrative share: \\localhost\C$\...
    share = Path(f"\\\\localhost\\{str(root)[0]}$" + str(root)[2:])
    if not (share / "O1234.nc").exists():
        pytest.skip(f"no administrative share here: {share}")
    uri = "file://localhost/" + quote(str(share / "O0002.nc")[len("\\\\localhost\\") :].replace("\\", "/"))
    text = "O0002\nM98 P1234\n#1=1/0\nM30\n"
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(types.TextDocumentItem(uri=uri, language_id="cncmacro", version=1, text=text))
    )
    got = await diagnostics_for(client, uri, 1)
    assert [(d.range.start.line, d.code) for d in got.diagnostics if d.code != "not-executed"] == [
        (2, "division-by-zero")
    ]
