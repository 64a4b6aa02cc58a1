"""Helpers for the language-server tests: a real ``cncmacro lsp`` process per test module and
workspace, driven over stdio by pytest-lsp; opening the workspace's files; waiting for
diagnostics. The session fixtures are made available to the tests by ``conftest.py``."""

from __future__ import annotations

import asyncio
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest_lsp
from lsprotocol import types
from pytest_lsp import ClientServerConfig, LanguageClient, client_capabilities

HERE = Path(__file__).resolve().parent
FANUC = HERE / "workspace_fanuc"
GSK = HERE / "workspace_gsk"
SERVER = [sys.executable, "-m", "cncmacro", "lsp"]


async def start(
    client: LanguageClient,
    root: Path,
    locale: str,
    settings: dict[str, Any] | None = None,
    capabilities: types.ClientCapabilities | None = None,
) -> None:
    """Initialise a session on ``root`` in ``locale`` with VS Code's capabilities (or
    ``capabilities``); the server's capabilities are kept as ``client.server_capabilities``,
    the registrations it asks for (``client/registerCapability``, accepted as VS Code does) as
    ``client.registrations``."""
    if settings is not None:
        client.set_configuration(settings, section="cncMacro")
    accept_registrations(client)
    result = await client.initialize_session(
        types.InitializeParams(
            capabilities=capabilities or client_capabilities("visual-studio-code"),
            root_uri=root.as_uri(),
            workspace_folders=[types.WorkspaceFolder(uri=root.as_uri(), name=root.name)],
            locale=locale,
        )
    )
    client.server_capabilities = result.capabilities  # type: ignore[attr-defined]


def accept_registrations(client: LanguageClient) -> None:
    """Accept what the server asks to register, as VS Code does; kept as ``client.registrations``;
    and answer a code lens refresh."""
    registrations: list[types.Registration] = []
    client.registrations = registrations  # type: ignore[attr-defined]

    @client.feature(types.CLIENT_REGISTER_CAPABILITY)
    def register_capability(params: types.RegistrationParams) -> None:
        registrations.extend(params.registrations)

    @client.feature(types.WORKSPACE_CODE_LENS_REFRESH)
    def code_lens_refresh(params: None) -> None:
        """The lenses changed (a new analysis): VS Code asks for them again, here nothing does."""


def open_file(client: LanguageClient, path: Path, text: str | None = None, version: int = 1) -> str:
    """Open ``path`` in the server (with its text on disk unless ``text`` is given)."""
    uri = path.as_uri()
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(
            types.TextDocumentItem(
                uri=uri, language_id="cncmacro", version=version, text=path.read_text("utf-8") if text is None else text
            )
        )
    )
    return uri


def close_file(client: LanguageClient, uri: str) -> None:
    client.text_document_did_close(types.DidCloseTextDocumentParams(types.TextDocumentIdentifier(uri)))


def edit(client: LanguageClient, uri: str, version: int, line: int, start: int, end: int, text: str) -> None:
    """Replace columns ``start``..``end`` of ``line`` by ``text`` (an incremental change)."""
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            types.VersionedTextDocumentIdentifier(uri=uri, version=version),
            [
                types.TextDocumentContentChangePartial(
                    range=types.Range(types.Position(line, start), types.Position(line, end)), text=text
                )
            ],
        )
    )


async def diagnostics_for(client: LanguageClient, uri: str, version: int) -> types.PublishDiagnosticsParams:
    """Wait for the diagnostics of ``uri`` computed from ``version``; every publish on the way
    must be for that document's current or an older, not yet superseded, version."""
    while True:
        params = await client.wait_for_notification(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
        if params.uri == uri and params.version == version:
            return params


Accept = Callable[[list[types.Diagnostic]], bool]


async def published_where(
    client: LanguageClient, wanted: dict[str, Accept], timeout: float = 60.0
) -> dict[str, list[types.Diagnostic]]:
    """Wait (at most ``timeout`` seconds) until the diagnostics last published for each URI of
    ``wanted`` are ones its function accepts (for several files published at once, where
    waiting for one notification after another could miss one)."""

    async def wait() -> dict[str, list[types.Diagnostic]]:
        while True:
            got = {uri: list(client.diagnostics.get(uri, [])) for uri in wanted}
            if all(uri in client.diagnostics and accept(got[uri]) for uri, accept in wanted.items()):
                return got
            await asyncio.sleep(0.01)

    return await asyncio.wait_for(wait(), timeout)


async def hover_text(client: LanguageClient, uri: str, line: int, character: int) -> str:
    result = await client.text_document_hover_async(
        types.HoverParams(types.TextDocumentIdentifier(uri), types.Position(line, character))
    )
    assert result is not None, f"no hover at {line}:{character}"
    assert isinstance(result.contents, types.MarkupContent)
    return result.contents.value


def config(**kw: Any) -> ClientServerConfig:
    return ClientServerConfig(server_command=SERVER, **kw)


def session_fixture(root: Path, locale: str, settings: dict[str, Any] | None = None):  # type: ignore[no-untyped-def]
    """A module-wide client for one workspace and locale."""

    @pytest_lsp.fixture(config=config(), scope="module")
    async def the_client(lsp_client: LanguageClient):  # type: ignore[no-untyped-def]
        await start(lsp_client, root, locale, settings)
        yield
        await lsp_client.shutdown_session()

    return the_client


fanuc_en = session_fixture(FANUC, "en")
fanuc_zh = session_fixture(FANUC, "zh-CN")
gsk_en = session_fixture(GSK, "en")
gsk_zh = session_fixture(GSK, "zh-CN")
