"""The language server object: state (documents, workspace index, settings) and wiring.

``CncMacroServer`` holds everything the features read. Document sync is handled here rather
than by pygls's own text store, so that an edit goes straight to the cached parser and the
text is never copied. Each LSP method is answered by a function in its own module (hover,
navigation, symbols, ...), named in ``FEATURES`` and registered by ``build_server``. pygls answers an exception in a
handler with an error response and keeps serving; the error is also logged here.
"""

from __future__ import annotations

import asyncio
import importlib
import inspect
import json
import logging
import os
import sys
import threading
import time
from collections.abc import Callable, Generator, Iterable, Iterator
from pathlib import Path
from typing import Any, cast

from lsprotocol import types
from pygls.lsp.server import LanguageServer
from pygls.protocol import JsonRPCProtocol, LanguageServerProtocol
from pygls.protocol.language_server import lsp_method
from pygls.workspace import Workspace

from .. import __version__
from ..analysis.indexes.workspace_index import WorkspaceIndex
from ..dialects.registry import profile_facts
from ..library.machine_file import MACHINE_FILE_NAME
from ..syntax.block_parser import warm_up
from .diagnostics import DiagnosticsEngine
from .disk_watch import watch_registration
from .documents import Documents, path_to_uri, uri_to_path
from .positions import negotiate
from .protocol_warm_up import warm_up_protocol
from .reports import log_skipped, publish_machine_file, report_skipped
from .settings import SECTION, Settings
from .stdio import serve_stdio
from .texts import t

log = logging.getLogger(__name__)
CONFIGURATION_TIMEOUT = 2.0  # seconds to wait for the editor's settings before analysing
DOCUMENT_DIALECT = "cncmacro/documentDialect"  # {"uri"} -> {"dialect", "title", "lathe", "source"} or null
PROFILES = "cncmacro/profiles"  # {} -> [{"name", "title", "titleZh", "summary", "summaryZh", "aliases", "lathe", ...}]
_Handler = tuple[Callable[..., Any], tuple[Any, ...], None]  # what an lsp_method yields to pygls: handler, arguments


class CncMacroProtocol(LanguageServerProtocol):
    """The protocol without pygls's own copy of open documents: the server's ``Documents``
    keeps them parsed instead."""

    def __init__(self, server: Any, converter: Any) -> None:
        super().__init__(server, converter)
        self._writing: set[asyncio.Future[Any]] = set()  # writes to a socket not yet done

    def _execute_handler(self, msg_id: Any, handler: Any, callback: Any, args: Any = None, kwargs: Any = None) -> None:
        """pygls keeps the future of a notification handled by a generator (didOpen, didChange,
        didClose, ...) among the requests' futures, where nothing ever removes it: one per
        message, for good. Nothing answers a notification, so its future goes when it is done."""
        if callback == self._check_handler_result:
            report = callback

            def callback(future: Any) -> None:
                if not future.cancelled():  # cancelled by ``shutdown``, while it walks the futures
                    self._request_futures.pop(msg_id, None)
                report(future)

        super()._execute_handler(msg_id, handler, callback, args, kwargs)

    def send_diagnostics(self, uri: str, version: int | None, encoded: list[str]) -> None:
        """Publish diagnostics already encoded as JSON text, one string per finding (encoded
        once per finding on the analysis thread: a file with a thousand findings is not
        encoded all again on each publish)."""
        listed = ", ".join(encoded)
        version_part = "" if version is None else f', "version": {version}'
        params = f'{{"uri": {json.dumps(uri)}, "diagnostics": [{listed}]{version_part}}}'
        method = json.dumps(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
        self._send_text(f'{{"jsonrpc": "{JsonRPCProtocol.VERSION}", "method": {method}, "params": {params}}}')

    def _send_text(self, body: str) -> None:
        """Send one message's JSON text, framed as pygls frames its own."""
        if self.writer is None:
            return
        data = body.encode(self.CHARSET)
        if self._include_headers:
            header = f"Content-Length: {len(data)}\r\nContent-Type: {self.CONTENT_TYPE}; charset={self.CHARSET}\r\n\r\n"
            data = header.encode("ascii") + data
        try:
            res = self.writer.write(data)
            if inspect.isawaitable(res):  # a socket's writer
                task = asyncio.ensure_future(res)
                self._writing.add(task)
                task.add_done_callback(self._writing.discard)
        except BrokenPipeError:
            raise
        except Exception:
            log.exception("sending a message failed")

    def to_json(self, value: Any) -> Any:
        """``value`` (a protocol type) in its JSON form, as this protocol sends it."""
        return self._converter.unstructure(value)

    @lsp_method(types.INITIALIZE)
    def lsp_initialize(self, params: types.InitializeParams) -> Generator[Any, Any, types.InitializeResult]:
        """pygls answers with the first encoding the client lists (``utf-8`` for Neovim and
        Helix); this server picks the one it converts cheapest (``positions.negotiate``), reads
        and writes every column in it, and says so. pygls's own workspace (it holds no document
        of this server) is made again with the same encoding."""
        general = params.capabilities.general
        encoding = negotiate(general.position_encodings if general is not None else None)
        server = self._server
        assert isinstance(server, CncMacroServer)  # this protocol is made by CncMacroServer only
        server.documents.encoding = encoding
        result = yield from super().lsp_initialize(params)
        result.capabilities.position_encoding = encoding.kind
        workspace = self.workspace
        self._workspace = Workspace(
            workspace.root_uri, workspace._sync_kind, params.workspace_folders or [], encoding.kind
        )
        return result

    @lsp_method(types.TEXT_DOCUMENT_DID_OPEN)
    def lsp_text_document__did_open(self, params: types.DidOpenTextDocumentParams) -> Iterator[_Handler]:
        if (handler := self.fm.features.get(types.TEXT_DOCUMENT_DID_OPEN)) is not None:
            yield handler, (params,), None

    @lsp_method(types.TEXT_DOCUMENT_DID_CHANGE)
    def lsp_text_document__did_change(self, params: types.DidChangeTextDocumentParams) -> Iterator[_Handler]:
        if (handler := self.fm.features.get(types.TEXT_DOCUMENT_DID_CHANGE)) is not None:
            yield handler, (params,), None

    @lsp_method(types.TEXT_DOCUMENT_DID_CLOSE)
    def lsp_text_document__did_close(self, params: types.DidCloseTextDocumentParams) -> Iterator[_Handler]:
        if (handler := self.fm.features.get(types.TEXT_DOCUMENT_DID_CLOSE)) is not None:
            yield handler, (params,), None


class CncMacroServer(LanguageServer):
    """The cncmacro language server and its state."""

    def __init__(self) -> None:
        super().__init__("cncmacro", __version__, protocol_cls=CncMacroProtocol)
        self.documents = Documents()
        documents = self.documents
        self.index = WorkspaceIndex(
            documents.by_uri.values, documents.dialect_for, documents.block_memo, calls_for=documents.calls_for,
            extensions_for=documents.extensions_for, machine_of=documents.machine_file_of,
            reading_rule=documents.reading_rule,
        )  # fmt: skip
        self.settings = Settings()
        self.locale: str = "en"
        self.diagnostics = DiagnosticsEngine(self)
        self.settings_ready = asyncio.Event()  # set once the editor's settings were asked for
        self.roots: list[str] = []
        self.watching: asyncio.Future[None] | None = None  # the request for the editor's file watcher
        self.pulling: asyncio.Future[None] | None = None  # the request for the editor's settings at start
        self.machine_file_uris: set[str] = set()  # the machine files whose problem is shown
        self.machine_files_shown: set[Path] = set()  # the machine files in use when they were last shown
        self.last_message_at = time.monotonic()  # when the editor last sent anything (the collector waits for quiet)
        self.setting_problems_shown: set[str] = set()  # the settings' problems already shown
        self.initialize_accepted = False  # an initialize request was understood (before it: LSP's -32002)

    # ---- the workspace
    def machine_files_in_use(self) -> list[Path]:
        """The machine files of the workspace folders and of the open documents."""
        machines = self.documents.machines
        found = [machines.path_in(str(root)) for root in machines.roots]
        found += [doc.machine_file for doc in self.documents.by_uri.values()]
        return [p for p in dict.fromkeys(found) if p is not None]

    def show_machine_files(self) -> None:
        """Show the problem of each machine file in use on it, or clear the one shown before."""
        machines = self.documents.machines
        in_use = self.machine_files_in_use()
        self.machine_files_shown = set(in_use)
        shown = {publish_machine_file(self, machines.state(path)) for path in in_use}
        shown.discard(None)
        for uri in self.machine_file_uris - shown:  # right again, gone, or no longer in use
            self.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=[]))
        self.machine_file_uris = cast("set[str]", shown)

    def scan_folders(self) -> None:
        """Index the program files of the workspace folders. A fault of the checker there must
        not stop the server (a failed ``initialize`` is fatal to the editor): it is logged and
        the index stays as far as it got."""
        try:
            self.index.scan(self.roots)
        except Exception:
            log.exception("indexing the workspace folders failed")
        self.diagnostics.collector.indexed()

    def list_folders_ahead(self) -> None:
        """The folders a call looks in, listed on a thread of their own ahead of the first hover
        on a call (``WorkspaceIndex.folders_to_list``); a fault there is logged, nothing more."""
        library = self.index.folders_to_list()
        if library is None:
            return

        def list_them() -> None:
            try:
                library.list_folders()
            except Exception:
                log.exception("listing the folders of the workspace's programs failed")

        threading.Thread(target=list_them, name="cncmacro-listings", daemon=True).start()

    # ---- settings
    def apply_settings(self, settings: Settings) -> None:
        """The editor's settings (or a machine file) changed: analyse again with them."""
        self.settings = settings
        self.documents.setting_dialect = settings.dialect
        self.documents.rechoose_dialects()
        self.diagnostics.configure(settings)
        if self.settings_ready.is_set():  # before, nothing may be published yet
            self.show_machine_files()
            self.show_setting_problems()

    def show_setting_problems(self) -> None:
        """Tell the person, once each, what in the editor's settings names nothing (an unknown
        profile, a severity for no code): the setting is passed over, which would be silent."""
        for key, values in self.settings.problems:
            text = t(key, self.locale, **values)
            if text not in self.setting_problems_shown:
                self.setting_problems_shown.add(text)
                self.window_show_message(types.ShowMessageParams(type=types.MessageType.Warning, message=text))

    def uri_for_path(self, path: str) -> str:
        for doc in self.documents.by_uri.values():
            if doc.path == path:
                return doc.uri
        return path_to_uri(path)

    def disk_changed(self, paths: Iterable[str]) -> None:
        """Files or folders changed on disk (the editor's file events, or what ``disk_watch``
        found): what is there now is read again (a regular file only), the machine file too,
        and the open documents are analysed again. A path named twice (two watchers of one
        editor) is read once."""
        unique = list(dict.fromkeys(paths))
        self.diagnostics.disk.seen(unique)
        for path in unique:
            if os.path.isdir(path):
                self.index.refresh_folder(path)
            else:
                problem = self.index.reload(path)
                if problem is not None:
                    log_skipped(self, problem)
        if any(Path(p).name == MACHINE_FILE_NAME for p in unique):  # settings, dialects, which file each is read with
            self.diagnostics.regroup()
            self.apply_settings(self.settings)  # and shows their problems, or clears them
        self.diagnostics.files_changed(unique)

    def report_server_error(self, error: Exception, source: Any) -> None:
        log.error("cncmacro language server: %s: %s", type(error).__name__, error)


def _initialize(server: CncMacroServer, params: types.InitializeParams) -> None:
    server.locale = params.locale or "en"
    server.settings = Settings.from_mapping(params.initialization_options)
    server.documents.setting_dialect = server.settings.dialect
    roots = [uri_to_path(f.uri) for f in params.workspace_folders or []]
    if not roots and params.root_uri:
        roots = [uri_to_path(params.root_uri)]
    elif not roots and params.root_path:
        roots = [params.root_path]
    server.roots = roots
    server.documents.machines.set_roots(roots)
    server.diagnostics.disk.set_roots(roots)
    server.scan_folders()
    # the grammar parser is built meanwhile, so the first unfinished line typed does not wait for it
    threading.Thread(target=warm_up, name="cncmacro-grammar", daemon=True).start()
    server.list_folders_ahead()
    server.diagnostics.start(server.documents.machines.first(), roots, server.locale)
    server.apply_settings(server.settings)
    # before any document opens: what the first open would otherwise make (analysis/warm_up.py)
    server.diagnostics.warm_up()
    warm_up_protocol(server.protocol)  # the messages of the first open, read and written sooner


async def _initialized(server: CncMacroServer, params: types.InitializedParams) -> None:
    server.watching = asyncio.ensure_future(_register_file_watchers(server))
    server.diagnostics.check_disk_now_and_then()
    report_skipped(server, server.index.skipped)  # notifications may go out only now that initialize is answered
    # the editor's settings are waited for a while, not cancelled: an answer that comes later (a
    # busy editor at start) still applies, instead of arriving for a request given up on
    server.pulling = asyncio.ensure_future(_pull_configuration(server))
    try:
        done, _ = await asyncio.wait({server.pulling}, timeout=CONFIGURATION_TIMEOUT)
        if not done:
            log.info("workspace/configuration: no answer yet; the initialization options apply until it comes")
    finally:
        server.settings_ready.set()
        server.show_machine_files()  # with the editor's severities
        server.show_setting_problems()


async def _register_file_watchers(server: CncMacroServer) -> None:
    """Ask an editor that can register watchers at run time for one on the program files and
    the machine file (``disk_watch.py``); once it agreed, its events are trusted for the files
    under the workspace folders."""
    caps = server.client_capabilities.workspace
    watched = caps.did_change_watched_files if caps is not None else None
    if watched is None or not watched.dynamic_registration:
        return
    try:
        await server.client_register_capability_async(watch_registration())
    except Exception as e:  # refused: the files the analysis reads are looked at instead
        log.info("client/registerCapability for file watching failed: %s", e)
        return
    server.diagnostics.disk.evented = True


async def _pull_configuration(server: CncMacroServer) -> None:
    caps = server.client_capabilities.workspace
    if caps is None or not caps.configuration:
        return
    try:
        result = await server.workspace_configuration_async(
            types.ConfigurationParams(items=[types.ConfigurationItem(section=SECTION)])
        )
    except Exception as e:  # a client that cannot answer keeps the settings it gave at start
        log.info("workspace/configuration failed: %s", e)
        return
    if result and isinstance(result[0], dict):
        server.apply_settings(Settings.from_mapping(result[0]))


# The modules of lsp/ that answer the editor's requests, each adding its handlers with its
# ``register(server)``, in the order ``build_server`` registers them: a new feature is one line here.
FEATURES = (
    "hover",
    "navigation",
    "highlight",
    "symbols",
    "folding",
    "semantic_tokens",
    "completion",
    "signature_help",
    "code_actions",
    "inlay_hints",
    "sequence_numbers",
    "formatting",
    "call_hierarchy",
    "inline_values",
    "cycle_lenses",
)


def build_server() -> CncMacroServer:
    """A server with its own handlers (initialisation, document sync, the workspace, the client's
    custom requests) and every module of ``FEATURES`` registered."""
    server = CncMacroServer()

    server.feature(types.INITIALIZE)(_initialize)
    server.feature(types.INITIALIZED)(_initialized)

    @server.feature(types.TEXT_DOCUMENT_DID_OPEN)
    def did_open(ls: CncMacroServer, params: types.DidOpenTextDocumentParams) -> None:
        doc = ls.diagnostics.opened(params.text_document)
        if (
            doc.machine_file is not None
            and doc.machine_file not in ls.machine_files_shown
            and ls.settings_ready.is_set()
        ):
            ls.show_machine_files()  # a machine file newly in use: its problem, if it has one

    @server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
    def did_change(ls: CncMacroServer, params: types.DidChangeTextDocumentParams) -> None:
        ls.diagnostics.changed(params)

    @server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
    def did_close(ls: CncMacroServer, params: types.DidCloseTextDocumentParams) -> None:
        ls.diagnostics.closed(params.text_document.uri)

    @server.feature(types.WORKSPACE_DID_CHANGE_CONFIGURATION)
    async def did_change_configuration(ls: CncMacroServer, params: types.DidChangeConfigurationParams) -> None:
        if isinstance(params.settings, dict) and params.settings:
            ls.apply_settings(Settings.from_mapping(params.settings))
        await _pull_configuration(ls)

    @server.feature(types.WORKSPACE_DID_CHANGE_WATCHED_FILES)
    def did_change_watched_files(ls: CncMacroServer, params: types.DidChangeWatchedFilesParams) -> None:
        ls.disk_changed(uri_to_path(change.uri) for change in params.changes)

    @server.feature(types.WORKSPACE_DID_CHANGE_WORKSPACE_FOLDERS)
    def did_change_workspace_folders(ls: CncMacroServer, params: types.DidChangeWorkspaceFoldersParams) -> None:
        gone = {uri_to_path(f.uri) for f in params.event.removed}
        ls.roots = [r for r in ls.roots if r not in gone] + [uri_to_path(f.uri) for f in params.event.added]
        ls.documents.machines.set_roots(ls.roots)
        ls.diagnostics.disk.set_roots(ls.roots)
        ls.scan_folders()
        report_skipped(ls, ls.index.skipped)
        ls.diagnostics.folders_changed(ls.roots)
        ls.diagnostics.regroup()  # a document may now be in a folder, or no longer
        ls.apply_settings(ls.settings)

    @server.feature(DOCUMENT_DIALECT)
    def document_dialect(ls: CncMacroServer, params: Any) -> dict[str, Any] | None:
        """The dialect an open document is read in, its title in the editor's language (the
        status bar shows it), and what decided it."""
        uri = params.get("uri") if isinstance(params, dict) else getattr(params, "uri", None)
        doc = ls.documents.by_uri.get(uri) if isinstance(uri, str) else None
        if doc is None:
            return None
        source = ls.documents.dialect_source(doc)
        title = doc.dialect.shown_title(ls.locale)
        return {"dialect": doc.dialect.name, "title": title, "lathe": doc.dialect.lathe, "source": source}

    @server.feature(PROFILES)
    def profiles(ls: CncMacroServer, params: Any) -> list[dict[str, Any]]:
        """The control profiles this server knows (the client's picker and status bar)."""
        return profile_facts()

    for name in FEATURES:  # by name: its line in FEATURES is all a new feature needs here
        importlib.import_module(f"{__package__}.{name}").register(server)
    return server


def serve(tcp: bool = False, host: str = "127.0.0.1", port: int = 2087) -> int:
    """Run the server on stdio (or TCP) until the client says exit."""
    logging.basicConfig(level=logging.WARNING, format="%(levelname)s %(name)s: %(message)s")
    # The analysis thread and the thread that answers requests share the interpreter: hand
    # it over every millisecond (not every 5) so that a hover waits less behind an analysis.
    sys.setswitchinterval(0.001)
    server = build_server()
    if tcp:
        server.start_tcp(host, port)
        return 0
    return serve_stdio(server, sys.stdin.buffer, sys.stdout.buffer)
