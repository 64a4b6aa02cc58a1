"""A huge document is parsed in steps on the editor's thread before it is analysed.

A document of ``FIRST_SCREEN_FROM`` lines or more is opened with its first screen parsed
(``ParsedDocument(in_steps=…)``) and then parsed ``READ_PIECE_LINES`` lines at a time in steps
of about 2 ms (``editor_steps.py``), answering the editor between them (hovers, tokens and the
like parse the lines they need on their own meanwhile), with work-done progress where the
editor shows it. Its first screen's findings are published as soon as the editor's settings
are known (``published.py``). Edits that come meanwhile change its text and the lines parsed
already; once read, the document is handed to its analysis. Python's cycle collector is kept
out of the way while it is read, and what was read is frozen afterwards, so that later
collections pass it over.
"""

from __future__ import annotations

import asyncio
import gc
from collections.abc import Callable
from typing import TYPE_CHECKING

from lsprotocol import types

from .analysis_groups import AnalysisGroups
from .analysis_progress import begin_progress
from .collector import Collector
from .documents import OpenDocument
from .editor_steps import between_steps, one_step
from .published import Published
from .texts import t

if TYPE_CHECKING:
    from .server import CncMacroServer

FIRST_SCREEN_FROM = 100_000  # a file this long shows its first screen's findings before it is parsed in full
READ_PIECE_LINES = 250  # and is parsed in steps (``editor_steps.py``) of pieces of this many lines


class HugeReading:
    """The huge documents being read: ``uri in reading`` while one is."""

    def __init__(self, server: CncMacroServer, groups: AnalysisGroups, published: Published,
                 collector: Collector) -> None:  # fmt: skip
        self.server = server
        self.groups = groups
        self.published = published
        self.collector = collector
        self._loading: set[str] = set()  # the URIs being read
        self._loads: dict[str, asyncio.Future[None]] = {}  # and their reading

    def __contains__(self, uri: object) -> bool:
        return uri in self._loading

    def __bool__(self) -> bool:
        return bool(self._loading)

    def add(self, uri: str) -> None:
        """``uri`` was opened with its first screen parsed: it is being read."""
        self._loading.add(uri)

    def discard(self, uri: str) -> None:
        """``uri`` was closed: its reading stops at the next step."""
        self._loading.discard(uri)

    def read(self, doc: OpenDocument, then: Callable[[OpenDocument], None]) -> None:
        """Read ``doc`` in steps; ``then(doc)`` once it is read to its end (not if closed meanwhile)."""
        self._loads[doc.uri] = asyncio.ensure_future(self._read(doc, then))

    async def _read(self, doc: OpenDocument, then: Callable[[OpenDocument], None]) -> None:
        token = await begin_progress(self.server, doc, "reading", False, self.groups.locale)
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
        then(doc)

    async def _read_steps(self, doc: OpenDocument, token: str | None) -> None:
        """The steps of ``_read``, until the document is read or closed."""
        parsed = doc.parsed
        shown = -1  # the percentage last reported
        while not one_step(lambda: parsed.parse_more(READ_PIECE_LINES)):
            if doc.uri not in self._loading:
                return  # closed meanwhile
            if doc.uri not in self.published.first_shown and self.server.settings_ready.is_set():  # opened before them
                analysis = self.groups.of(doc.machine_file)
                self.published.first_screen(analysis, doc.uri, doc.path, doc.lines, doc.version)
            done = int(100 * len(parsed.blocks) / len(parsed.lines))
            if token is not None and done != shown:  # the message again: an editor may show only the latest
                shown = done
                message = t("reading_lines", self.groups.locale, lines=len(parsed.lines))
                self.server.work_done_progress.report(
                    token, types.WorkDoneProgressReport(message=message, percentage=done)
                )
            await between_steps()
