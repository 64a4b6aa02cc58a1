"""Diagnostics for the editor: the workspace analysis on a worker thread, cancelled by newer
edits, its newest result pushed per file.

``DiagnosticsEngine.analyses`` holds one ``analysis.workspace.WorkspaceAnalysis`` per machine file
in use, as ``cncmacro check`` makes one per group of files: each open document is in the analysis
of its own machine file (``OpenDocument.machine_file``, the nearest ``.cncmacro.toml`` above it;
None for the defaults), which holds it (the server's ``Documents`` show its ``ParsedDocument``,
so each document is parsed once), and every edit goes through it. With one machine file there
is one analysis, and nothing is merged. A machine file created, changed or deleted moves
the documents whose nearest one changed to the analysis of their new one (``regroup``) and gives
each analysis its file's settings again (``configure``). An analysis analyses its own documents;
their results are merged, each open file's findings and values taken from its own analysis (a
program of another machine's folder is read there as saved), those of a file that is not open
from every analysis that reached it. The analysis runs on one worker
thread, so hovers and completion are answered meanwhile; the editor's thread only reads the
documents, and changes them (open, change, close, settings) inside ``editing()``, which first
tells a running analysis to stop (it checks between chunks of blocks) and then takes the
lock that the analysis holds. Each change starts a new generation; a result is published only
when no change came after the generation it was computed from, each open file with the
version it was analysed at. A finding in a file that is not open (a macro called from an open
file) is published without a version, and cleared when a later result no longer has it. The
first analysis of a huge file reports work-done progress. Diagnostics are pushed only: a server
that also answers ``textDocument/diagnostic`` has each finding shown twice by a client that
pulls and takes pushes too (Neovim 0.10 and later keep the two apart).

Files changed on disk that no editor event reports (``disk_watch.py``) are looked for when an
analysis starts, on the worker thread, and every ``DISK_CHECK_SECONDS`` while documents are
open: what changed goes through the server's ``disk_changed``, as a file event does, and the
analysis starts again with it.
"""

from __future__ import annotations

import asyncio
import gc
import json
import logging
import threading
import time
from collections.abc import Callable, Iterator
from concurrent.futures import ThreadPoolExecutor
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, cast

from lsprotocol import types

from ..analysis import Diagnostic
from ..analysis.cycle_lenses import FileTiming
from ..analysis.first_screen import FIRST_SCREEN_LINES
from ..analysis.workspace import AnalysisResult, WorkspaceAnalysis
from ..analysis.workspace_result import Value
from ..bilingual import pick
from ..syntax.document import ParsedDocument, head_lines
from .collector import Collector
from .cycle_lenses import refresh_code_lenses
from .disk_watch import DiskStamps
from .documents import Edit, OpenDocument, uri_to_path
from .editor_steps import between_steps, one_step
from .protocol_diagnostics import to_lsp
from .settings import Settings, merged_severities, valid_severities
from .site_steps import index_soon

if TYPE_CHECKING:
    from pathlib import Path

    from .server import CncMacroProtocol, CncMacroServer

log = logging.getLogger(__name__)

DEBOUNCE_SECONDS = 0.0  # edits are coalesced by cancelling: a newer one stops the older analysis
# Documents opened or closed in a burst (an editor restoring a session, a client opening a whole
# folder, "close all") are analysed once the burst pauses for this long: each analysis looks at every open document,
# so analysing after each of 2,000 opens would cost the square of the count.
BURST_SECONDS = 0.05
PROGRESS_LINES = 20_000  # a first analysis of a file this long reports progress
PROGRESS_SECONDS = 0.25  # how often it reports
FIRST_SCREEN_FROM = 100_000  # a file this long shows its first screen's findings before it is parsed in full
READ_PIECE_LINES = 250  # and is parsed in steps (``editor_steps.py``) of pieces of this many lines
PROVISIONAL_LINES = 1_000  # edited lines (besides the first screen) whose findings show before its first analysis
DISK_CHECK_SECONDS = 2.0  # between looks at the files the analysis read, while documents are open

LineValues = dict[int, list[tuple[int, Value]]]


@dataclass(slots=True)
class Outcome:
    """One finished analysis, made ready on the worker thread: per file URI the version it
    was analysed at (None for a file that is not open), its diagnostics, their protocol form,
    and the values the runs left on its lines."""

    generation: int
    versions: dict[str, int | None]
    found: dict[str, list[Diagnostic]]
    items: dict[str, list[types.Diagnostic]]
    values: dict[str, LineValues]
    payloads: dict[str, list[str]]  # the items encoded as JSON text, as published
    on_disk: list[str] = field(default_factory=list)  # files changed on disk: nothing analysed, read them first
    timing: dict[str, FileTiming] = field(default_factory=dict)  # per URI, the cycle time (cycle_lenses.py)


class DiagnosticsEngine:
    """Schedules, cancels and publishes the analysis of the open documents."""

    def __init__(self, server: CncMacroServer, delay: float = DEBOUNCE_SECONDS) -> None:
        self.server = server
        # per machine file; every one reads the files on disk through the workspace index's cache
        first = WorkspaceAnalysis(files=server.index.disk, memo=server.documents.block_memo)
        self.analyses: dict[Path | None, WorkspaceAnalysis] = {None: first}
        self._search_paths: list[str] = []
        self._folders: list[str] = []
        self._locale = "en"
        self._editor = Settings()  # the editor's settings in force
        self.delay = delay
        self.lock = threading.Lock()  # held by the analysis, and by the editor's thread to change anything
        self.generation = 0
        self._executor = ThreadPoolExecutor(max_workers=1, thread_name_prefix="cncmacro-analysis")
        self._task: asyncio.Task[None] | None = None
        self._published: dict[str, tuple[int | None, list[Diagnostic], list[types.Diagnostic], int]] = {}
        self._values: dict[str, tuple[int | None, LineValues]] = {}
        self._timing: dict[str, tuple[int | None, FileTiming | None]] = {}
        self._analysed_once: set[str] = set()
        self._first_shown: set[str] = set()  # huge documents whose first screen was published
        # per huge document not analysed yet: its first screen's lines, the analysis that
        # checked them and their findings
        self._first_screens: dict[str, tuple[tuple[str, ...], WorkspaceAnalysis, list[Diagnostic]]] = {}
        self._loading: set[str] = set()  # huge documents being read (``_read``)
        self._touched: dict[str, set[int]] = {}  # per huge document not analysed yet, the lines edited
        self._loads: dict[str, asyncio.Future[None]] = {}  # and their reading
        # the worker's caches: per file the diagnostics last converted, and per diagnostic (with
        # the text of its lines) its protocol form and JSON form
        self._converted: dict[str, tuple[list[Diagnostic], list[types.Diagnostic], list[str]]] = {}
        self._forms: dict[tuple[object, ...], tuple[types.Diagnostic, str]] = {}
        self.collector = Collector()
        self._cleaning = False
        self._opened_at = (0.0, 0.0)  # when the last two documents were opened or closed (monotonic)
        self.disk = DiskStamps()  # the files the analysis read, for the changes no editor event reports
        self._disk_checks: asyncio.Task[None] | None = None

    # ---- setting up
    def start(self, machine_file: Path | None, folders: list[str], locale: str) -> None:
        """A fresh analysis for the session (at ``initialize``, before any document opens), for
        ``machine_file`` (the first workspace folder's)."""
        with self.editing():
            self._search_paths, self._folders, self._locale = list(folders), list(folders), locale
            self.analyses = {}
            self._analysis(machine_file)

    def configure(self, editor: Settings) -> None:
        """The editor's settings, or a machine file, changed: each analysis gets its machine
        file's settings and the editor's again; the open documents are analysed again."""
        with self.editing():
            self._editor = editor
            for machine_file, analysis in self.analyses.items():
                analysis.configure(**self._options(machine_file))
        self.schedule()

    def _options(self, machine_file: Path | None) -> dict[str, Any]:
        """The settings of the analysis of ``machine_file``: the file's, and the editor's over them."""
        machine = self.server.documents.machines.settings(machine_file)
        editor = self._editor
        severities = valid_severities(merged_severities(machine, editor))
        return {
            "settings": machine,
            "dialect": editor.dialect,
            "max_blocks": editor.run_budget,
            "severities": severities,
        }

    def _analysis(self, machine_file: Path | None) -> WorkspaceAnalysis:
        """The analysis of the documents read with ``machine_file`` (made at the first one)."""
        analysis = self.analyses.get(machine_file)
        if analysis is None:
            for unused in [k for k, a in self.analyses.items() if not a.docs]:
                del self.analyses[unused]  # the one kept when its last document left, say
            analysis = self.analyses[machine_file] = WorkspaceAnalysis(
                search_paths=self._search_paths,
                workspace_folders=self._folders,
                locale=self._locale,
                files=self.server.index.disk,
                memo=self.server.documents.block_memo,
            )
            analysis.configure(**self._options(machine_file))
        return analysis

    def _left(self, machine_file: Path | None) -> None:
        """A document left the analysis of ``machine_file``: without documents, it goes (but the
        last one, which keeps what it knows of the workspace for the next document)."""
        analysis = self.analyses.get(machine_file)
        if analysis is not None and not analysis.docs and len(self.analyses) > 1:
            del self.analyses[machine_file]

    def regroup(self) -> None:
        """A machine file changed on disk: each open document whose nearest one is another now
        moves to that one's analysis, with its text and version."""
        documents = self.server.documents
        with self.editing():
            documents.machines.forget()
            for doc in documents.by_uri.values():
                machine_file = documents.machines.path_for(doc.path)
                if doc.uri in self._loading:  # read with the machine file it has once read in full
                    doc.machine_file = machine_file
                    continue
                if machine_file == doc.machine_file:
                    continue
                before = doc.machine_file
                self.analyses[before].close(doc.path)
                analysis = self._analysis(machine_file)
                analysis.open(doc.path, doc.parsed.text, doc.version)
                parsed = analysis.document(doc.path)
                assert parsed is not None
                documents.moved(doc, parsed, machine_file)
                self._left(before)
                self.disk.watch_machine_files(doc.path)

    # ---- document events
    @contextmanager
    def editing(self) -> Iterator[None]:
        """Stop a running analysis, then hold the lock while the caller changes documents or
        settings; a new generation starts."""
        self.generation += 1
        with self.lock:
            yield

    def opened(self, item: types.TextDocumentItem) -> OpenDocument:
        path = uri_to_path(item.uri)
        documents = self.server.documents
        huge = item.text.count("\n") >= FIRST_SCREEN_FROM
        with self.editing():
            analysis = self._analysis(documents.machines.path_for(path))
            if huge:
                if self.server.settings_ready.is_set():
                    top = head_lines(item.text, FIRST_SCREEN_LINES)
                    self._publish_first_screen(analysis, item.uri, path, top, item.version)
                doc = documents.open(item, ParsedDocument(item.text, in_steps=FIRST_SCREEN_LINES))
                self._loading.add(item.uri)
            else:
                analysis.open(path, item.text, item.version)
                parsed = analysis.document(path)
                assert parsed is not None
                doc = documents.open(item, parsed)
        self.disk.watch_machine_files(path)
        self._opened_at = (self._opened_at[1], time.monotonic())
        if huge:
            self._loads[item.uri] = asyncio.ensure_future(self._read(doc))
        else:
            self.schedule()
        return doc

    async def _read(self, doc: OpenDocument) -> None:
        """Parse a huge document in steps, answering the editor between them (hovers, tokens and
        the like parse the lines they need on their own meanwhile), then hand it to its analysis
        (the edits that came meanwhile changed its text, and the lines parsed already)."""
        token = await self._begin_progress(doc, "reading", cancellable=False)
        parsed = doc.parsed
        try:
            with self.collector.paused():  # a collection between steps would walk all read so far
                await self._read_steps(doc, token)
        finally:
            if token is not None:
                self.server.work_done_progress.end(token, types.WorkDoneProgressEnd())
            self._loads.pop(doc.uri, None)
        gc.freeze()  # what was read stays: later collections pass it over
        if doc.uri not in self._loading or self.server.documents.by_uri.get(doc.uri) is not doc:
            return
        self._loading.discard(doc.uri)
        with self.editing():
            analysis = self._analysis(doc.machine_file)
            analysis.open(doc.path, parsed, doc.version)
            self.server.documents.moved(doc, parsed, doc.machine_file)
        self.schedule()

    async def _read_steps(self, doc: OpenDocument, token: str | None) -> None:
        """The steps of ``_read``, until the document is read or closed."""
        parsed = doc.parsed
        shown = -1  # the percentage last reported
        while not one_step(lambda: parsed.parse_more(READ_PIECE_LINES)):
            if doc.uri not in self._loading:
                return  # closed meanwhile
            if doc.uri not in self._first_shown and self.server.settings_ready.is_set():  # opened before them
                self._publish_first_screen(self._analysis(doc.machine_file), doc.uri, doc.path, doc.lines, doc.version)
            done = int(100 * len(parsed.blocks) / len(parsed.lines))
            if token is not None and done != shown:  # the message again: an editor may show only the latest
                shown = done
                lines = f"{len(parsed.lines):,}"
                message = pick(self._locale, f"reading {lines} lines", f"读取 {lines} 行")
                self.server.work_done_progress.report(
                    token, types.WorkDoneProgressReport(message=message, percentage=done)
                )
            await between_steps()

    def _ready(self) -> list[OpenDocument]:
        """The open documents, but those still being read (``_read``)."""
        return [d for d in self.server.documents.by_uri.values() if d.uri not in self._loading]

    def _publish_first_screen(self, analysis: WorkspaceAnalysis, uri: str, path: str, lines: list[str], version: int,
                              extra: list[int] | None = None) -> None:  # fmt: skip
        """Publish the findings that the first lines of a huge document (and the lines of
        ``extra``) earn by themselves (``WorkspaceAnalysis.first_screen``), before the document
        is parsed in full and analysed: the top of the file is what the editor shows first."""
        self._first_shown.add(uri)
        top = tuple(lines[:FIRST_SCREEN_LINES])
        kept = self._first_screens.get(uri)
        try:
            if kept is not None and kept[0] == top and kept[1] is analysis:  # the first screen is as it was
                diags = kept[2] + analysis.first_screen(path, lines, extra or (), head=False)
            else:
                diags = analysis.first_screen(path, lines)
                self._first_screens[uri] = (top, analysis, diags)
                diags = diags + analysis.first_screen(path, lines, extra or (), head=False)
        except Exception:  # the whole analysis will say it
            log.exception("the first screen's findings failed")
            return

        def line_text(_file: str, line: int) -> str:
            return lines[line] if 0 <= line < len(lines) else ""

        encoding = self.server.documents.encoding
        uri_of = self.server.uri_for_path
        converted = [to_lsp(x, line_text, encoding, uri_of) for x in diags]
        self._published[uri] = (version, diags, converted, 1)
        self.server.text_document_publish_diagnostics(
            types.PublishDiagnosticsParams(uri=uri, diagnostics=converted, version=version)
        )

    def changed(self, params: types.DidChangeTextDocumentParams) -> OpenDocument | None:
        uri = params.text_document.uri
        version = params.text_document.version
        if uri in self._loading:  # being read: the text changes now, the analysis comes once it is read
            doc = self.server.documents.change(params)
            if doc is not None:
                self._publish_provisional(doc, params)
            return doc

        def apply(doc: OpenDocument, edit: Edit) -> None:
            self.analyses[doc.machine_file].change(doc.path, *edit, version)

        with self.editing():
            doc = self.server.documents.change(params, apply)
        if doc is not None:
            if doc.uri in self._first_shown and doc.uri not in self._analysed_once:
                self._publish_provisional(doc, params)
            self.schedule()
        return doc

    def _publish_provisional(self, doc: OpenDocument, params: types.DidChangeTextDocumentParams) -> None:
        """An edit in a huge document whose first analysis has not ended: what the first screen
        and the lines edited so far earn by themselves, for the new version at once (the whole
        analysis publishes the rest)."""
        touched = self._touched.setdefault(doc.uri, set())
        for change in params.content_changes:
            if isinstance(change, types.TextDocumentContentChangePartial):
                first, last = change.range.start.line, change.range.end.line
                added = change.text.count("\n") - (last - first)
                if added:  # the lines below move
                    moved = {x + added if x > last else x for x in touched if not first < x <= last}
                    touched.clear()
                    touched.update(moved)
                touched.update(range(first, first + change.text.count("\n") + 1))
        lines = [x for x in sorted(touched) if FIRST_SCREEN_LINES <= x < len(doc.lines)][:PROVISIONAL_LINES]
        analysis = self._analysis(doc.machine_file)
        self._publish_first_screen(analysis, doc.uri, doc.path, doc.lines, doc.version, lines)

    def closed(self, uri: str) -> None:
        reading = uri in self._loading  # its reading stops
        self._loading.discard(uri)
        self._touched.pop(uri, None)
        self._first_screens.pop(uri, None)
        with self.editing():
            doc = self.server.documents.close(uri)
            if doc is not None and not reading:
                self.analyses[doc.machine_file].close(doc.path)
                self._left(doc.machine_file)
                self.collector.closed()
        self._published.pop(uri, None)
        self._values.pop(uri, None)
        self._timing.pop(uri, None)
        self._analysed_once.discard(uri)
        self._first_shown.discard(uri)
        self.server.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=[]))
        self._opened_at = (self._opened_at[1], time.monotonic())
        self.schedule()

    def files_changed(self, paths: list[str]) -> None:
        """Files changed on disk (created, changed, deleted)."""
        with self.editing():
            for analysis in self.analyses.values():
                for path in paths:
                    analysis.file_changed(path)
        self.schedule()

    def folders_changed(self, folders: list[str]) -> None:
        """The editor's workspace folders changed: callers are looked for in the new ones."""
        with self.editing():
            self._folders = list(folders)
            for analysis in self.analyses.values():
                analysis.set_workspace_folders(folders)
        self.schedule()

    # ---- running
    def schedule(self) -> None:
        """Analyse the current state (after the pause), on the worker thread."""
        loop = asyncio.get_event_loop()
        self._task = loop.create_task(self._run(self.generation))

    async def _run(self, generation: int) -> None:
        await asyncio.sleep(self.delay)
        while self._in_burst():
            await asyncio.sleep(BURST_SECONDS)
            if generation != self.generation:
                return  # the burst went on: the run after its last document analyses them all
        if not self.server.settings_ready.is_set():  # the first analyses wait for the settings
            await self.server.settings_ready.wait()
        if generation != self.generation:
            return  # a newer change scheduled its own run
        big = [d for d in self._ready() if d.uri not in self._analysed_once and len(d.lines) >= PROGRESS_LINES]
        for d in big:
            if len(d.lines) >= FIRST_SCREEN_FROM and d.uri not in self._first_shown:
                self._publish_first_screen(self.analyses[d.machine_file], d.uri, d.path, d.lines, d.version)
        token = await self._begin_progress(big[0], "analysis", cancellable=True) if big else None
        stopped = self._stop_asked(token)
        work = asyncio.get_running_loop().run_in_executor(self._executor, self._analyse, generation, stopped)
        try:
            if token is not None:
                await self._report_progress(token, work)
            outcome = await work
            if outcome is not None and outcome.on_disk:
                self.server.disk_changed(outcome.on_disk)  # read them, and analyse again
                return
            if outcome is None or outcome.generation != self.generation:
                return  # cancelled, or a newer change came: its own run publishes
            self._publish(outcome)
        finally:
            if token is not None:  # it ends once its findings are shown
                done = pick(self._locale, "stopped", "已停止") if stopped() else pick(self._locale, "done", "完成")
                self.server.work_done_progress.end(token, types.WorkDoneProgressEnd(message=done))
        if self.collector.due() and not self._cleaning and not self._loading:  # not while a huge file is read
            self._cleaning = True
            try:
                await self._clean_when_quiet()
            finally:
                self._cleaning = False

    def _in_burst(self) -> bool:
        """Whether documents are being opened or closed in a burst: the last two came close
        together, and the last one just now."""
        before, last = self._opened_at
        now = time.monotonic()
        return last - before < BURST_SECONDS and now - last < BURST_SECONDS

    async def _clean_when_quiet(self) -> None:
        """Collect the frozen heap once the editor sent nothing for a while (``Collector.quiet_seconds``;
        at once when urgent)."""
        while not self.collector.urgent():
            quiet = time.monotonic() - self.server.last_message_at
            wanted = self.collector.quiet_seconds()
            if quiet >= wanted:
                break
            await asyncio.sleep(wanted - quiet)
        if self._loading:
            return  # a huge file began to be read: after its first analysis
        await asyncio.get_running_loop().run_in_executor(self._executor, self.collector.clean)

    def _analyse(self, generation: int, stopped: Callable[[], bool] = lambda: False) -> Outcome | None:
        """On the worker thread: analyse and convert, or None when a newer change came or the
        user stopped it (``stopped``)."""

        def cancelled() -> bool:
            return self.generation != generation or stopped()

        on_disk = self.disk.changed() if self.server.documents.by_uri else []
        if on_disk:
            return Outcome(generation, {}, {}, {}, {}, {}, on_disk)
        with self.lock:
            if cancelled():
                return None
            docs = self._ready()
            if not docs:
                return Outcome(generation, {}, {}, {}, {}, {})
            new_documents = any(d.uri not in self._analysed_once for d in docs)
            started = time.time_ns()
            with self.collector.paused():
                results: list[tuple[Path | None, WorkspaceAnalysis, AnalysisResult]] = []
                complete = True  # every machine file's analysis ran to its end
                groups: dict[Path | None, str] = {}  # per machine file, the path of its first document
                for d in docs:
                    groups.setdefault(d.machine_file, d.path)
                try:
                    for machine_file, first in groups.items():
                        analysis = self.analyses[machine_file]
                        result = analysis.analyze(first, cancelled)
                        if result is None:
                            complete = False
                            break
                        results.append((machine_file, analysis, result))
                except Exception:  # a fault in the analysis must not stop the server
                    log.exception("the analysis failed")
                    complete = False
                try:
                    outcome = self._outcome(generation, docs, results) if complete else None
                finally:
                    self._record_reads(started)
                self.collector.settle(new_documents and outcome is not None)  # before the collector runs again
        return outcome

    def _record_reads(self, started: int) -> None:
        """Keep the stamps of the files the analyses have read from disk (not their open ones)."""
        libraries: list[object] = []
        paths: list[str] = []
        for analysis in self.analyses.values():
            files, folders = analysis.library.read_from_disk()
            own = analysis.docs
            paths += [*(f for f in files if f not in own), *folders]
            libraries.append(analysis.library)
        self.disk.record(libraries, list(dict.fromkeys(paths)), started)

    # ---- files changed on disk that no event reports
    def check_disk_now_and_then(self) -> None:
        """Look at the files the analysis read every ``DISK_CHECK_SECONDS`` from now on."""
        if self._disk_checks is None:
            self._disk_checks = asyncio.get_event_loop().create_task(self._check_disk())

    async def _check_disk(self) -> None:
        loop = asyncio.get_running_loop()
        while True:
            await asyncio.sleep(DISK_CHECK_SECONDS)
            if not self.server.documents.by_uri:
                continue
            try:
                changed = await loop.run_in_executor(self._executor, self.disk.changed)
                if changed:
                    self.server.disk_changed(changed)
            except Exception:  # a fault here must not end the checks
                log.exception("looking at the files on disk failed")

    def _outcome(self, generation: int, docs: list[OpenDocument],
                 results: list[tuple[Path | None, WorkspaceAnalysis, AnalysisResult]]) -> Outcome:  # fmt: skip
        by_path = {d.path: d for d in docs}
        result, owner = _merged(by_path, results)
        versions: dict[str, int | None] = {}
        found: dict[str, list[Diagnostic]] = {}
        for path, diags in result.diagnostics.items():
            uri = by_path[path].uri if path in by_path else self.server.uri_for_path(path)
            versions[uri] = by_path[path].version if path in by_path else None
            found[uri] = diags
        for d in docs:
            versions.setdefault(d.uri, d.version)
            found.setdefault(d.uri, [])

        def line_text(file: str, line: int) -> str:
            ws = owner.get(file) or next((a for _, a, _ in results if a.document(file) is not None), results[0][1])
            parsed = ws.document(file)
            lines = parsed.lines if parsed is not None else _disk_lines(ws, file)
            return lines[line] if 0 <= line < len(lines) else ""

        encoding = self.server.documents.encoding
        protocol = cast("CncMacroProtocol", self.server.protocol)
        unstructure = protocol.to_json
        uri_of = self.server.uri_for_path
        forms = self._forms
        used: dict[tuple[object, ...], tuple[types.Diagnostic, str]] = {}
        items: dict[str, list[types.Diagnostic]] = {}
        payloads: dict[str, list[str]] = {}
        for uri, diags in found.items():
            cached = self._converted.get(uri)
            if cached is not None and cached[0] == diags:
                items[uri], payloads[uri] = cached[1], cached[2]
                continue
            converted, payload = [], []
            for x in diags:
                # an edit changes a few findings: the others keep their converted forms
                key = (x, encoding, line_text(x.file, x.line), line_text(x.file, x.end_line),
                       *(line_text(r.file, r.line) for r in x.related))  # fmt: skip
                form = used.get(key) or forms.get(key)
                if form is None:
                    item = to_lsp(x, line_text, encoding, uri_of)
                    form = (item, json.dumps(unstructure(item)))
                used[key] = form
                converted.append(form[0])
                payload.append(form[1])
            items[uri], payloads[uri] = converted, payload
            self._converted[uri] = (diags, converted, payload)
        if used:  # only the forms of the findings of now are kept
            self._forms = used
        for uri in [u for u in self._converted if u not in found]:
            del self._converted[uri]  # a closed document, or a file without findings now
        values = {by_path[p].uri: v for p, v in result.values.items() if p in by_path}
        timing = {by_path[p].uri: t for p, t in result.timing.items() if p in by_path}
        return Outcome(generation, versions, found, items, values, payloads, timing=timing)

    def _publish(self, outcome: Outcome) -> None:
        documents = self.server.documents.by_uri
        for uri, version in outcome.versions.items():
            doc = documents.get(uri)
            if doc is not None and doc.version != version:
                continue
            if version is not None or doc is not None:
                self._values[uri] = (version, outcome.values.get(uri, {}))
                self._timing[uri] = (version, outcome.timing.get(uri))
            self._analysed_once.add(uri)
            if doc is not None:
                index_soon(doc.sites)  # a huge document's variable index, in steps, before a hover asks
            self._touched.pop(uri, None)
            self._first_screens.pop(uri, None)
            diags = outcome.found[uri]
            old = self._published.get(uri)
            if old is not None and old[0] == version and old[1] == diags:
                continue
            self._published[uri] = (version, diags, outcome.items[uri], old[3] + 1 if old else 1)
            cast("CncMacroProtocol", self.server.protocol).send_diagnostics(uri, version, outcome.payloads[uri])
        for uri in [u for u, p in self._published.items() if u not in outcome.versions and u not in documents]:
            del self._published[uri]  # a file that is not open, no longer with findings
            self.server.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=[]))
        if self.server.settings.inlay_values:
            self._refresh_inlay_hints()
        refresh_code_lenses(self.server)

    def _refresh_inlay_hints(self) -> None:
        caps = self.server.client_capabilities.workspace
        hints = caps.inlay_hint if caps is not None else None
        if hints is not None and hints.refresh_support:
            self.server.workspace_inlay_hint_refresh(None)

    def _stop_asked(self, token: str | None) -> Callable[[], bool]:
        """Whether the user stopped the analysis that reports progress with ``token`` (the
        editor's cancel button; the analysis starts again at the next edit)."""
        if token is None:
            return lambda: False
        future = self.server.work_done_progress.tokens.get(token)
        return (lambda: False) if future is None else future.cancelled

    async def _report_progress(self, token: str, work: asyncio.Future[Outcome | None]) -> None:
        """Report how far the analyses got (``WorkspaceAnalysis.progress``) until ``work`` ends."""
        last: tuple[str, int] | None = None
        while not work.done():
            await asyncio.wait([work], timeout=PROGRESS_SECONDS)
            progress = [a.progress for a in self.analyses.values() if a.docs]
            if not progress or work.done():
                continue
            now = max(progress, key=lambda p: p.done)
            shown = (now.what, min(99, int(now.done * 100)))
            if shown != last:
                last = shown
                self.server.work_done_progress.report(
                    token, types.WorkDoneProgressReport(message=shown[0], percentage=shown[1])
                )

    async def _begin_progress(self, doc: OpenDocument, kind: str, cancellable: bool) -> str | None:
        """Begin reporting the ``kind`` ("reading" or "analysis") of ``doc``, if the editor shows
        progress; the user may stop it when ``cancellable``."""
        caps = self.server.client_capabilities.window
        if caps is None or not caps.work_done_progress:
            return None
        token = f"cncmacro-{kind}-{doc.uri}-{doc.version}"
        try:
            await self.server.work_done_progress.create_async(token)
        except Exception:  # the client refused: analyse without progress
            return None
        self.server.work_done_progress.begin(
            token,
            types.WorkDoneProgressBegin(
                title="cncmacro",
                message=pick(
                    self._locale,
                    f"{'reading' if kind == 'reading' else 'analysing'} {len(doc.lines):,} lines",
                    f"{'读取' if kind == 'reading' else '分析'} {len(doc.lines):,} 行",
                ),
                cancellable=cancellable,
                percentage=0,
            ),
        )
        return token

    # ---- reading results
    def timing(self, doc: OpenDocument) -> FileTiming | None:
        """The cycle time's facts of ``doc`` from the newest analysis, if it analysed this version."""
        got = self._timing.get(doc.uri)
        return got[1] if got is not None and got[0] == doc.version else None

    def values(self, doc: OpenDocument) -> LineValues:
        """The values the newest run left on the lines of ``doc``, if it analysed this version."""
        got = self._values.get(doc.uri)
        return got[1] if got is not None and got[0] == doc.version else {}


def _merged(
    by_path: dict[str, OpenDocument], results: list[tuple[Path | None, WorkspaceAnalysis, AnalysisResult]]
) -> tuple[AnalysisResult, dict[str, WorkspaceAnalysis]]:
    """The results of the analyses as one, and per file the analysis whose findings it shows:
    an open file's own (its machine file's), a file that is not open the first that reached it
    (the findings of the others added, each once)."""
    if len(results) == 1:
        _, analysis, result = results[0]
        return result, dict.fromkeys(result.diagnostics, analysis)
    owner: dict[str, WorkspaceAnalysis] = {}
    diagnostics: dict[str, list[Diagnostic]] = {}
    values: dict[str, dict[int, list[tuple[int, Value]]]] = {}
    timing: dict[str, FileTiming] = {}
    for machine_file, analysis, result in results:
        for path, diags in result.diagnostics.items():
            doc = by_path.get(path)
            if doc is not None and doc.machine_file != machine_file:
                continue  # an open file of another machine, read here as saved
            if path not in diagnostics:
                owner[path], diagnostics[path] = analysis, list(diags)
            elif doc is None:
                kept = diagnostics[path]
                kept += [x for x in diags if x not in kept]
                kept.sort(key=Diagnostic.sort_key)
        for path, lines in result.values.items():
            doc = by_path.get(path)
            if doc is not None and doc.machine_file == machine_file:
                values[path] = lines
        for path, t in result.timing.items():
            doc = by_path.get(path)
            if doc is not None and doc.machine_file == machine_file:
                timing[path] = t
    return AnalysisResult(results[0][2].version, diagnostics, values, timing), owner


def _disk_lines(ws: WorkspaceAnalysis, path: str) -> list[str]:
    loaded = ws.library.load(path)
    return loaded.lines if loaded is not None else []
