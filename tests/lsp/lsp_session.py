"""Helpers for the language-server tests: a real ``cncmacro lsp`` process per workspace and
locale, driven over stdio by pytest-lsp; opening the workspace's files; waiting for diagnostics.

The servers of the shared workspaces (``conftest.py``: FANUC, GSK, Haas and the calls' workspace,
in English and Chinese) start once for the whole run, which saves most of the suite's start-ups
(each pays the server's import, about 0.8 s of CPU); each module sees a server as a fresh one
would show it: what a module left open is closed when it ends (``open_file`` keeps count), and
the diagnostics the client kept for those documents are forgotten. A module's own workspace or
settings get a server for that module (``session_fixture``). Every one of these clients lives on
the session's event loop, so a module that uses them marks its tests
``pytest.mark.asyncio(loop_scope="session")``."""

from __future__ import annotations

import asyncio
import sys
from collections.abc import AsyncIterator, Callable
from pathlib import Path
from typing import Any, Literal

import pytest
import pytest_asyncio
from lsprotocol import types
from pytest_lsp import ClientServerConfig, LanguageClient, client_capabilities

HERE = Path(__file__).resolve().parent
FANUC = HERE / "workspace_fanuc"
GSK = HERE / "workspace_gsk"
HAAS = HERE / "workspace_haas"
CALLS = HERE / "workspace_calls"
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
    left_open(client).add(uri)
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(
            types.TextDocumentItem(
                uri=uri, language_id="cncmacro", version=version, text=path.read_text("utf-8") if text is None else text
            )
        )
    )
    return uri


def close_file(client: LanguageClient, uri: str) -> None:
    left_open(client).discard(uri)
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


class Publishes:
    """Every ``publishDiagnostics`` a client received, counted, the last few versions of each URI
    kept: waiting for the next notification instead misses one that arrives in the same read as
    the one before it (pytest-lsp wakes one waiter per notification), which a busy server's
    bunched publishes made happen."""

    def __init__(self) -> None:
        self.count = 0
        self.by_uri: dict[str, dict[int | None, tuple[int, types.PublishDiagnosticsParams]]] = {}

    def add(self, params: types.PublishDiagnosticsParams) -> None:
        self.count += 1
        versions = self.by_uri.setdefault(params.uri, {})
        versions.pop(params.version, None)
        versions[params.version] = (self.count, params)
        while len(versions) > 16:
            del versions[next(iter(versions))]

    def since(self, count: int, uri: str, version: int | None) -> types.PublishDiagnosticsParams | None:
        """The publish of ``uri`` for ``version`` received after the ``count``th, if there is one."""
        got = self.by_uri.get(uri, {}).get(version)
        return got[1] if got is not None and got[0] > count else None


def publishes(client: LanguageClient) -> Publishes:
    """What ``client`` is sent, kept from the first call on (pytest-lsp's own handler, which keeps
    each URI's latest diagnostics in ``client.diagnostics``, still runs)."""
    kept: Publishes | None = getattr(client, "publishes", None)
    if kept is None:
        kept = client.publishes = Publishes()  # type: ignore[attr-defined]
        features = client.protocol.fm.features
        keep_latest = features[types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS]

        def publish(params: types.PublishDiagnosticsParams) -> Any:
            kept.add(params)
            return keep_latest(params)

        features[types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS] = publish
    return kept


async def diagnostics_for(client: LanguageClient, uri: str, version: int) -> types.PublishDiagnosticsParams:
    """Wait for the diagnostics of ``uri`` computed from ``version`` that are published after
    this call."""
    kept = publishes(client)
    after = kept.count
    while (got := kept.since(after, uri, version)) is None:
        await asyncio.sleep(0.01)
    return got


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


def described(hover: str) -> str:
    """A hover's text without the cycle time the server adds below it once the document's run
    is timed (a hover answered before that has none; a warm server's run is often done first);
    empty where the cycle time is all the hover says."""
    cycle_time = ("Cycle time:", "加工时间：")
    if hover.startswith(cycle_time):
        return ""
    head, sep, tail = hover.rpartition("\n\n---\n\n")
    return head if sep and tail.startswith(cycle_time) else hover


def config(**kw: Any) -> ClientServerConfig:
    return ClientServerConfig(server_command=SERVER, **kw)


def left_open(client: LanguageClient) -> set[str]:
    """The documents ``open_file`` opened in ``client`` and ``close_file`` has not closed."""
    if not hasattr(client, "left_open"):
        client.left_open = set()  # type: ignore[attr-defined]
    return client.left_open  # type: ignore[attr-defined,no-any-return]


async def close_what_is_left_open(client: LanguageClient) -> None:
    """Close what a module left open in a shared server, wait for a request's answer (what the
    server published before it has arrived) and forget the diagnostics kept for those documents:
    the next module opens its documents in a server holding only the workspace on disk."""
    uris = sorted(left_open(client))
    for uri in uris:
        close_file(client, uri)
    await client.workspace_symbol_async(types.WorkspaceSymbolParams(query="no such program"))
    for uri in uris:
        client.diagnostics.pop(uri, None)


def _client_fixture(root: Path, locale: str, settings: dict[str, Any] | None, scope: Literal["module", "session"]):  # type: ignore[no-untyped-def]
    """A fixture: a client on a server started in ``root`` and ``locale``, for ``scope``."""

    @pytest_asyncio.fixture(scope=scope, loop_scope="session")
    async def the_client(request: pytest.FixtureRequest) -> AsyncIterator[LanguageClient]:
        client = await config().start(devtools=request.config.getoption("devtools"))
        assert isinstance(client, LanguageClient)
        await start(client, root, locale, settings)
        yield client
        await client.shutdown_session()
        await client.stop()

    return the_client


def session_fixture(root: Path, locale: str, settings: dict[str, Any] | None = None):  # type: ignore[no-untyped-def]
    """A module-wide client for one workspace, locale and settings."""
    return _client_fixture(root, locale, settings, "module")


def shared_server(root: Path, locale: str):  # type: ignore[no-untyped-def]
    """A client on a server for ``root`` in ``locale`` that the whole run shares; the tests use
    it through ``module_view`` (``conftest.py``)."""
    return _client_fixture(root, locale, None, "session")


async def module_view(client: LanguageClient) -> AsyncIterator[LanguageClient]:
    """A module's view of a shared server's ``client``: what the module left open is closed when
    it ends."""
    yield client
    await close_what_is_left_open(client)


async def actions_for(client: LanguageClient, uri: str, diag: types.Diagnostic) -> list[types.CodeAction]:
    """The code actions the server offers for ``diag`` (commands left out)."""
    got = await client.text_document_code_action_async(
        types.CodeActionParams(types.TextDocumentIdentifier(uri), diag.range, types.CodeActionContext([diag]))
    )
    return [a for a in got or [] if isinstance(a, types.CodeAction)]
