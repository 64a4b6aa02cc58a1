"""``cncmacro check --jobs N``: the work of one check spread over N processes.

``Workers`` runs the steps of ``check_work.MachineWork`` (what files name and call, then the
analysis of batches of call groups) and gives their answers back in the order they were asked
for, so that the report is the same, byte for byte, whatever the number of processes. With one
job it runs them in this process and starts none. With more, a pool of worker processes works
on the next few batches (``WINDOW`` per process) while the answers are taken in order: the
findings of a group are written as soon as it and every group before it are done, and no more
answers wait in memory than the window holds.

The pool starts its processes as the platform does (``fork`` on Linux, ``spawn`` on Windows and
macOS); both are tested. Ctrl-C is for the checking process alone: a worker ignores it from its
start (the signal is blocked while a worker is started, and the worker ignores it before
unblocking it), the checking process stops the workers and ``cncmacro`` exits with 130 and no
traceback. A worker that dies (killed, out of memory) ends the check with ``WorkerLost``
instead of a wait that never ends.

``--shard K/N`` spreads a library over N machines instead: each check finds the same call
groups, and checks those whose first file falls to shard K by a hash of its path as found
(``in_shard``), so that a group's callers and callees are always checked together.
"""

from __future__ import annotations

import argparse
import os
import signal
import sys
import zlib
from collections import deque
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

from ..bilingual import pick
from .check_work import MachineWork, in_worker
from .locale_option import environment_locale

if TYPE_CHECKING:  # the pool's modules are loaded only when there are workers (10 ms)
    from concurrent.futures import Future, ProcessPoolExecutor

T = TypeVar("T")
R = TypeVar("R")

# batches asked of each process ahead of the one whose answer is awaited: enough that the
# others keep working while one checks a large group, few enough that the answers waiting
# (findings only) stay small
WINDOW = 16
MAX_WINDOWS_JOBS = 61  # the most processes a pool can wait on at once on Windows


class WorkerLost(Exception):
    """A worker process ended before it answered (killed, or out of memory)."""


def default_jobs() -> int:
    """The number of processors this process may run on (``--jobs``'s default)."""
    count = getattr(os, "process_cpu_count", None)  # Python 3.13
    if count is not None:
        n = count()
    elif hasattr(os, "sched_getaffinity"):
        n = len(os.sched_getaffinity(0))
    else:
        n = os.cpu_count()
    return usable_jobs(n or 1)


def usable_jobs(jobs: int) -> int:
    """``jobs`` within what the platform can run (Windows waits on at most 61 processes)."""
    return min(jobs, MAX_WINDOWS_JOBS) if sys.platform == "win32" else jobs


def jobs_argument(text: str) -> int:
    """argparse ``type`` for ``--jobs``: a whole number of processes, 1 or more."""
    try:
        jobs = int(text)
    except ValueError:
        jobs = 0
    if jobs < 1:
        raise argparse.ArgumentTypeError(
            pick(
                environment_locale(),
                f"{text!r} is not a number of processes: give a whole number, 1 or more "
                "(1 checks in this process alone)",
                f"{text!r} 不是进程数：请给出 1 或更大的整数（1 表示只在本进程中检查）",
            )
        )
    return jobs


Shard = tuple[int, int]  # (K, N): the Kth of N shards, counted from 1


def shard_argument(text: str) -> Shard:
    """argparse ``type`` for ``--shard``: ``K/N``, 1 <= K <= N."""
    k, _, n = text.partition("/")
    try:
        shard = int(k), int(n)
    except ValueError:
        shard = 0, 0
    if not 1 <= shard[0] <= shard[1]:
        raise argparse.ArgumentTypeError(
            pick(
                environment_locale(),
                f"{text!r} is not a shard: give K/N, the Kth of N shards, 1 <= K <= N (1/4 to 4/4)",
                f"{text!r} 不是分片：请写成 K/N，即 N 个分片中的第 K 个，1 <= K <= N（1/4 到 4/4）",
            )
        )
    return shard


def in_shard(first: Path, shard: Shard | None) -> bool:
    """Whether the call group whose first file is ``first`` is checked in ``shard`` (None: all
    are). The hash is CRC-32 of the path's bytes as found: the same on every machine and every
    Python, for the same paths given on the command line in the same folder."""
    if shard is None:
        return True
    return zlib.crc32(os.fsencode(first)) % shard[1] == shard[0] - 1


class Workers:
    """See the module docstring: ``jobs`` processes (none for 1) doing the steps of ``works``."""

    def __init__(self, works: list[MachineWork], jobs: int) -> None:
        self.works = works
        self.jobs = jobs
        self._pool: ProcessPoolExecutor | None = None
        if jobs > 1:
            from concurrent.futures import ProcessPoolExecutor

            self._pool = ProcessPoolExecutor(jobs, initializer=_start, initargs=(works,))

    def __enter__(self) -> Workers:
        return self

    def __exit__(self, kind: type[BaseException] | None, *_: object) -> None:
        pool, self._pool = self._pool, None
        if pool is None:
            return
        if kind is None:
            pool.shutdown(wait=True)
            return
        # interrupted, a pipe closed, a failure: the workers are stopped, not waited for
        stop = getattr(pool, "terminate_workers", None)  # Python 3.14
        if stop is not None:
            stop()
        else:
            for process in list((getattr(pool, "_processes", None) or {}).values()):
                process.terminate()
        pool.shutdown(wait=False, cancel_futures=True)

    def map(self, step: Callable[[MachineWork, T], R], machine: int, items: Iterable[T]) -> Iterator[R]:
        """``step(works[machine], item)`` of each of ``items``, in their order."""
        pool = self._pool
        if pool is None:
            work = self.works[machine]
            for item in items:
                yield step(work, item)
            return
        pending: deque[Future[Any]] = deque()
        for item in items:
            pending.append(self._submit(pool, step, machine, item))
            if len(pending) >= WINDOW * self.jobs:
                yield _answer(pending.popleft())
        while pending:
            yield _answer(pending.popleft())

    @staticmethod
    def _submit(pool: ProcessPoolExecutor, step: Callable[..., Any], machine: int, item: object) -> Future[Any]:
        """Ask the pool for ``step`` of ``item``, with Ctrl-C held back meanwhile (a worker
        started now starts with it blocked: ``_start``); it comes once the worker is asked."""
        block = getattr(signal, "pthread_sigmask", None)
        if block is None:  # Windows: a worker ignores Ctrl-C from its initialiser on
            return pool.submit(_step, step, machine, item)
        held = block(signal.SIG_BLOCK, {signal.SIGINT})
        try:
            return pool.submit(_step, step, machine, item)
        finally:
            block(signal.SIG_SETMASK, held)


def _answer(future: Future[R]) -> R:
    from concurrent.futures.process import BrokenProcessPool

    try:
        return future.result()
    except BrokenProcessPool:
        raise WorkerLost from None


_works: list[MachineWork] = []  # a worker process's copy of the checking process's ``works``


def _start(works: list[MachineWork]) -> None:
    """A worker process's start: Ctrl-C is the checking process's to handle."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    unblock = getattr(signal, "pthread_sigmask", None)
    if unblock is not None:
        unblock(signal.SIG_UNBLOCK, {signal.SIGINT})
    global _works
    _works = works
    in_worker()


def _step(step: Callable[[MachineWork, T], R], machine: int, item: T) -> R:
    return step(_works[machine], item)
