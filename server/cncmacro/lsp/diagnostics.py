"""Diagnostics for the editor: the workspace analysis on a worker thread, cancelled by newer
edits, its newest result pushed per file.

``DiagnosticsEngine`` schedules the analysis of the open documents and hands its outcome to
the editor. Its parts, each in its own module: the analyses, one per machine file in use
(``analysis_groups.py``); the outcome of an analysis made ready to publish on the worker
thread (``outcomes.py``); what the editor has been shown, with a huge document's first screen
(``published.py``); the reading of a huge document (``huge_reading.py``); and the progress of
long work (``analysis_progress.py``).

The analysis runs on one worker thread, so hovers and completion are answered meanwhile; the
editor's thread only reads the documents, and changes them (open, change, close, settings)
inside ``editing()``, which first tells a running analysis to stop (it checks between chunks
of blocks) and then takes the lock that the analysis holds. Each change starts a new
generation; a result is published only when no change came after the generation it was
computed from, each open file with the version it was analysed at. A huge document is parsed
in steps on the editor's thread first (``huge_reading.py``), its first screen's findings
published at once; the first analysis of a large one reports work-done progress.

Files changed on disk that no editor event reports (``disk_watch.py``) are looked for when an
analysis starts, on the worker thread, and every ``DISK_CHECK_SECONDS`` while documents are
open: what changed goes through the server's ``disk_changed``, as a file event does, and the
analysis starts again with it.
"""

from __future__ import annotations

import asyncio
import logging
import threading
import time
from collections.abc import Callable, Iterator
from concurrent.futures import ThreadPoolExecutor
from contextlib import contextmanager
from typing import TYPE_CHECKING, cast

from lsprotocol import types

from ..analysis.first_screen import FIRST_SCREEN_LINES
from ..analysis.runs.cycle_lenses import FileTiming
from ..analysis.workspace import WorkspaceAnalysis
from ..analysis.workspace_result import AnalysisResult
from ..syntax.document import ParsedDocument, head_lines
from .analysis_groups import AnalysisGroups
from .analysis_progress import begin_progress, report_progress, stop_asked
from .collector import Collector
from .disk_watch import DiskStamps
from .documents import Edit, OpenDocument, uri_to_path
from .huge_reading import FIRST_SCREEN_FROM, HugeReading
from .outcomes import LineValues, Outcome, ProtocolForms
from .published import Published
from .settings import Settings
from .texts import t

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
DISK_CHECK_SECONDS = 2.0  # between looks at the files the analysis read, while documents are open
# With several documents open, each run of an analysis goes on for this long at a time, then the
# next run takes its turn, and what is complete is published: a small file is not kept waiting
# behind a run that goes on to its 30 s. Each further round of the same analysis gives twice as
# long, up to ``MAX_SLICE_SECONDS``, so that the rounds cost little next to the runs.
SLICE_SECONDS = 0.25
MAX_SLICE_SECONDS = 4.0


class DiagnosticsEngine:
    """Schedules, cancels and publishes the analysis of the open documents."""

    def __init__(self, server: CncMacroServer, delay: float = DEBOUNCE_SECONDS) -> None:
        self.server = server
        # one analysis per machine file
        self.groups = AnalysisGroups(server.documents, server.index.disk, server.index.callee_folders)
        self.published = Published(server)
        self.delay = delay
        self.lock = threading.Lock()  # held by the analysis, and by the editor's thread to change anything
        self.generation = 0
        self._executor = ThreadPoolExecutor(max_workers=1, thread_name_prefix="cncmacro-analysis")
        self._task: asyncio.Task[None] | None = None
        self._forms = ProtocolForms()  # the worker's: the findings' protocol and JSON forms
        self.collector = Collector()
        self.reading = HugeReading(server, self.groups, self.published, self.collector)  # huge documents
        self._cleaning = False
        self._opened_at = (0.0, 0.0)  # when the last two documents were opened or closed (monotonic)
        self.disk = DiskStamps()  # the files the analysis read, for the changes no editor event reports
        self._disk_checks: asyncio.Task[None] | None = None

    # ---- setting up
    def start(self, machine_file: Path | None, folders: list[str], locale: str) -> None:
        """A fresh analysis for the session (at ``initialize``, before any document opens), for
        ``machine_file`` (the first workspace folder's)."""
        with self.editing():
            self.groups.start(machine_file, folders, locale)

    def warm_up(self) -> None:
        """Before any document opens: a short program analysed, so that the first one the user
        opens finds the process's caches ready (``AnalysisGroups.warm_up``)."""
        self.groups.warm_up()

    def configure(self, editor: Settings) -> None:
        """The editor's settings, or a machine file, changed: each analysis gets its machine
        file's settings and the editor's again; the open documents are analysed again."""
        with self.editing():
            self.groups.configure(editor)
        self.schedule()

    def regroup(self) -> None:
        """A machine file changed on disk: each open document whose nearest one is another now
        moves to that one's analysis (``AnalysisGroups.regroup``)."""
        with self.editing():
            for path in self.groups.regroup(self.reading):
                self.disk.watch_machine_files(path)

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
            analysis = self.groups.of(documents.machines.path_for(path))
            if huge:
                if self.server.settings_ready.is_set():
                    top = head_lines(item.text, FIRST_SCREEN_LINES)
                    self.published.first_screen(analysis, item.uri, path, top, item.version)
                doc = documents.open(item, ParsedDocument(item.text, in_steps=FIRST_SCREEN_LINES))
                self.reading.add(item.uri)
            else:
                analysis.open(path, item.text, item.version)
                parsed = analysis.document(path)
                assert parsed is not None
                doc = documents.open(item, parsed)
        self.disk.watch_machine_files(path)
        self._opened_at = (self._opened_at[1], time.monotonic())
        if huge:
            self.reading.read(doc, self._read_in_full)
        else:
            self.schedule()
        return doc

    def _read_in_full(self, doc: OpenDocument) -> None:
        """A huge document read to its end (``huge_reading.py``) is handed to its analysis (the
        edits that came meanwhile changed its text, and the lines parsed already)."""
        with self.editing():
            self.groups.opened(doc)
        self.schedule()

    def _ready(self) -> list[OpenDocument]:
        """The open documents, but those still being read (``huge_reading.py``)."""
        return [d for d in self.server.documents.by_uri.values() if d.uri not in self.reading]

    def changed(self, params: types.DidChangeTextDocumentParams) -> OpenDocument | None:
        uri = params.text_document.uri
        version = params.text_document.version
        if uri in self.reading:  # being read: the text changes now, the analysis comes once it is read
            doc = self.server.documents.change(params)
            if doc is not None:
                self.published.provisional(self.groups.of(doc.machine_file), doc, params)
            return doc

        def apply(doc: OpenDocument, edit: Edit) -> None:
            self.groups[doc.machine_file].change(doc.path, *edit, version)

        with self.editing():
            doc = self.server.documents.change(params, apply)
        if doc is not None:
            if doc.uri in self.published.first_shown and doc.uri not in self.published.analysed_once:
                self.published.provisional(self.groups.of(doc.machine_file), doc, params)
            self.schedule()
        return doc

    def closed(self, uri: str) -> None:
        reading = uri in self.reading  # its reading stops
        self.reading.discard(uri)
        with self.editing():
            doc = self.server.documents.close(uri)
            if doc is not None and not reading:
                self.groups[doc.machine_file].close(doc.path)
                self.groups.left(doc.machine_file)
                self.collector.closed()
        self.published.closed(uri)
        self._opened_at = (self._opened_at[1], time.monotonic())
        self.schedule()

    def files_changed(self, paths: list[str]) -> None:
        """Files changed on disk (created, changed, deleted)."""
        with self.editing():
            self.groups.files_changed(paths)
        self.schedule()

    def folders_changed(self, folders: list[str]) -> None:
        """The editor's workspace folders changed: callers are looked for in the new ones."""
        with self.editing():
            self.groups.folders_changed(folders)
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
        published = self.published
        big = [d for d in self._ready() if d.uri not in published.analysed_once and len(d.lines) >= PROGRESS_LINES]
        for d in big:
            if len(d.lines) >= FIRST_SCREEN_FROM and d.uri not in published.first_shown:
                published.first_screen(self.groups[d.machine_file], d.uri, d.path, d.lines, d.version)
        token = await begin_progress(self.server, big[0], "analysis", True, self.groups.locale) if big else None
        stopped = stop_asked(self.server, token)
        try:
            turn = SLICE_SECONDS
            while True:  # rounds: each publishes what is complete, until all is
                loop = asyncio.get_running_loop()
                work = loop.run_in_executor(self._executor, self._analyse, generation, stopped, turn)
                if token is not None:
                    await report_progress(self.server, token, work, lambda: self.groups)
                outcome = await work
                if outcome is not None and outcome.on_disk:
                    self.server.disk_changed(outcome.on_disk)  # read them, and analyse again
                    return
                if outcome is None or outcome.generation != self.generation:
                    return  # cancelled, or a newer change came: its own run publishes
                published.outcome(outcome)
                if not outcome.partial:
                    break
                turn = min(2 * turn, MAX_SLICE_SECONDS)
        finally:
            if token is not None:  # it ends once its findings are shown
                done = t("stopped" if stopped() else "done", self.groups.locale)
                self.server.work_done_progress.end(token, types.WorkDoneProgressEnd(message=done))
        if self.collector.due() and not self._cleaning and not self.reading:  # not while a huge file is read
            self._cleaning = True
            try:
                await self._clean_when_quiet(generation)
            finally:
                self._cleaning = False

    def _in_burst(self) -> bool:
        """Whether documents are being opened or closed in a burst: the last two came close
        together, and the last one just now."""
        before, last = self._opened_at
        now = time.monotonic()
        return last - before < BURST_SECONDS and now - last < BURST_SECONDS

    async def _clean_when_quiet(self, generation: int) -> None:
        """Collect the frozen heap once the editor sent nothing for a while (``Collector.quiet_seconds``;
        at once when urgent), unless a newer change came meanwhile: its run cleans up after it
        publishes (a clean-up queued behind that run's analysis would hold up its publishing)."""
        while not self.collector.urgent():
            quiet = time.monotonic() - self.server.last_message_at
            wanted = self.collector.quiet_seconds()
            if quiet >= wanted:
                break
            await asyncio.sleep(wanted - quiet)
        if self.reading or generation != self.generation:
            return  # a huge file began to be read (after its first analysis), or a newer run comes
        await asyncio.get_running_loop().run_in_executor(self._executor, self._clean_unless_newer, generation)

    def _clean_unless_newer(self, generation: int) -> None:
        """On the worker thread: the clean-up, unless a newer change came while it waited its turn."""
        if generation == self.generation:
            self.collector.clean()

    def _analyse(self, generation: int, stopped: Callable[[], bool] = lambda: False,
                 turn: float | None = None) -> Outcome | None:  # fmt: skip
        """On the worker thread: analyse and convert, or None when a newer change came or the
        user stopped it (``stopped``). With several documents open each run goes on for at
        most ``turn`` seconds; the outcome then leaves out the files of the runs that did not
        end (``Outcome.partial``), which the next call takes further."""

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
            new_documents = any(d.uri not in self.published.analysed_once for d in docs)
            started = time.time_ns()
            with self.collector.paused():
                results: list[tuple[Path | None, WorkspaceAnalysis, AnalysisResult]] = []
                complete = True  # every machine file's analysis ran to its end
                groups: dict[Path | None, str] = {}  # per machine file, the path of its first document
                for d in docs:
                    groups.setdefault(d.machine_file, d.path)
                turn = turn if len(docs) > 1 else None  # alone, a document waits for nothing else
                try:
                    for machine_file, first in groups.items():
                        analysis = self.groups[machine_file]
                        result = analysis.analyze(first, cancelled, turn)
                        if result is None:
                            complete = False
                            break
                        results.append((machine_file, analysis, result))
                except Exception:  # a fault in the analysis must not stop the server
                    log.exception("the analysis failed")
                    complete = False
                try:
                    outcome = self._outcome(generation, docs, results) if complete else None
                    unfinished = {path for _, _, result in results for path in result.unfinished}
                    if outcome is not None and unfinished:
                        by_path = {d.path: d.uri for d in docs}
                        outcome.without({by_path.get(p) or self.server.uri_for_path(p) for p in unfinished})
                finally:
                    self.groups.record_reads(self.disk, started)
                self.collector.settle(new_documents and outcome is not None)  # before the collector runs again
        return outcome

    def _outcome(self, generation: int, docs: list[OpenDocument],
                 results: list[tuple[Path | None, WorkspaceAnalysis, AnalysisResult]]) -> Outcome:  # fmt: skip
        server = self.server
        protocol = cast("CncMacroProtocol", server.protocol)
        return self._forms.outcome(generation, docs, results, server.documents.encoding, server.uri_for_path,
                                   protocol.to_json)  # fmt: skip

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

    # ---- reading results
    def timing(self, doc: OpenDocument) -> FileTiming | None:
        """The cycle time's facts of ``doc`` from the newest analysis, if it analysed this version."""
        return self.published.timing(doc)

    def values(self, doc: OpenDocument) -> LineValues:
        """The values the newest run left on the lines of ``doc``, if it analysed this version."""
        return self.published.values(doc)
