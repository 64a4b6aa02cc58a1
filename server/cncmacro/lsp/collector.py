"""Keeping Python's cycle collector out of the editor's way.

An analysis leaves hundreds of thousands of live objects (compiled blocks, checkpoints), and
a full collection walks them all: over 100 ms on a 100k-line file, seconds on a million
lines, at whatever moment the collector decides, such as in the middle of an edit's analysis
or a hover (the analysis thread holds the interpreter meanwhile). So the collector is paused
while an analysis runs (``paused``), what survived is frozen afterwards (the collector skips
frozen objects), and the frozen heap is collected for real only at a quiet moment: when the
process's memory has grown by ``GROWTH`` since the last clean-up or since a document was
first analysed (reference cycles the edits left behind are freed only then), once the editor
sent nothing for ``quiet_seconds`` (longer the larger the heap: a full collection of a
million-line file's working set holds the interpreter for over a second, and a hover then would
wait for it), or at once when it has grown by ``MAX_GROWTH``. Memory is read
from ``/proc/self/statm`` (counting frozen objects would walk them all); where that is
missing, every ``ANALYSES`` analyses count as due.

A closed document leaves its whole working set behind as garbage, and the runs of an analysis
hold reference cycles, so once frozen it would stay for good: a closed document makes a clean-up
due (a new document's baseline does not hide it), and ``CLOSES`` closed documents or
``URGENT_ANALYSES`` analyses without one make it urgent, quiet or not. An editor that opens and
closes thousands of files, or types for hours without a pause, so keeps its memory.
"""

from __future__ import annotations

import gc
import os
import threading
from collections.abc import Iterator
from contextlib import contextmanager

from ..syntax.block_parser import shared_cache

GROWTH = 1.15
MAX_GROWTH = 1.6
SLACK_BYTES = 32 << 20  # growth below this is never worth a collection
QUIET_SECONDS = 0.5
COLLECT_SECONDS_PER_MB = 0.002  # a full collection's time per MB of resident memory, about
QUIET_FACTOR = 3.0  # the quiet wanted before a clean-up, in times its expected length
ANALYSES = 200
URGENT_ANALYSES = 400
CLOSES = 32
_PAGE = os.sysconf("SC_PAGE_SIZE") if hasattr(os, "sysconf") else 4096


def resident_bytes() -> int | None:
    """The process's resident memory, or None where it cannot be read cheaply."""
    try:
        with open("/proc/self/statm", "rb") as f:
            return int(f.read().split()[1]) * _PAGE
    except (OSError, ValueError, IndexError):
        return None


class Collector:
    """When to freeze and when to collect (see the module docstring)."""

    def __init__(self) -> None:
        self._holds = 0  # how many ``paused`` are in force (an analysis, a huge file being read)
        self._was_enabled = True
        self._lock = threading.Lock()
        self.baseline = resident_bytes() or 0
        self.analyses = 0
        self.since_clean = 0  # analyses since the last real collection
        self.closes = 0  # documents closed since the last real collection

    @contextmanager
    def paused(self) -> Iterator[None]:
        """The collector does not run until the last of the pauses in force ends (an analysis on
        its thread and a huge file read on the editor's may overlap)."""
        with self._lock:
            if self._holds == 0:
                self._was_enabled = gc.isenabled()
                gc.disable()
            self._holds += 1
        try:
            yield
        finally:
            with self._lock:
                self._holds -= 1
                if self._holds == 0 and self._was_enabled:
                    gc.enable()

    def settle(self, new_documents: bool) -> None:
        """After an analysis: take its survivors out of the collector's walks. What the first
        analysis of a document leaves is its working set, not garbage: the growth that makes
        a clean-up worth it is counted from there."""
        gc.freeze()
        self.analyses += 1
        self.since_clean += 1
        if new_documents and not self.closes:
            self._rebase()

    def indexed(self) -> None:
        """The workspace's program files were indexed: what the index holds is working set, not
        garbage, so it is taken out of the collector's walks and the growth that makes a
        clean-up worth it is counted from here (a folder holding a 100k-line program grew the
        process past ``MAX_GROWTH``: the urgent clean-up that followed, 200 ms of a collection
        that freed nothing, held up the diagnostics of the first file opened)."""
        gc.freeze()
        if not self.closes:
            self._rebase()

    def closed(self) -> None:
        """A document was closed: what its analysis held is garbage now."""
        self.closes += 1

    def _grown(self, factor: float) -> bool:
        now = resident_bytes()
        if now is None:
            return self.analyses >= ANALYSES * factor
        return now > self.baseline * factor + SLACK_BYTES

    def due(self) -> bool:
        """Whether memory has grown enough to be worth a clean-up at a quiet moment, or
        ``ANALYSES`` analyses went by without one (each new document moves the baseline, so
        growth alone would never call for a clean-up while documents keep being opened)."""
        return self._grown(GROWTH) or self.since_clean >= ANALYSES or self.closes > 0

    def urgent(self) -> bool:
        """Whether it has grown so much that the clean-up cannot wait."""
        return self._grown(MAX_GROWTH) or self.closes >= CLOSES or self.since_clean >= URGENT_ANALYSES

    def quiet_seconds(self) -> float:
        """How long the editor must have sent nothing before a clean-up: ``QUIET_SECONDS``, or
        ``QUIET_FACTOR`` times what the clean-up is expected to take (``COLLECT_SECONDS_PER_MB``
        of resident memory), whichever is longer, so that the longer it holds the interpreter,
        the surer it is that nobody is waiting (a million-line file: about 1.3 s, after 4 s)."""
        now = resident_bytes()
        if now is None:
            return QUIET_SECONDS
        return max(QUIET_SECONDS, QUIET_FACTOR * COLLECT_SECONDS_PER_MB * now / (1 << 20))

    def clean(self) -> None:
        """Collect everything (frozen included), then freeze the survivors again."""
        gc.unfreeze()
        gc.collect()
        shared_cache.sweep()  # the blocks of lines no document has any more
        gc.freeze()
        self.since_clean = 0
        self.closes = 0
        self._rebase()

    def _rebase(self) -> None:
        self.baseline = resident_bytes() or 0
        self.analyses = 0
