"""Work-done progress of the long work on a huge document: its reading and its first analysis.

The editor is asked for a progress token only where it shows progress
(``window.workDoneProgress``); a client that refuses one gets none and the work goes on. The
reading reports its percentage itself (``diagnostics.py``); an analysis reports what its
analyses say they do (``WorkspaceAnalysis.progress``) every ``PROGRESS_SECONDS``, and may be
stopped by the user (the editor's cancel button: ``stop_asked``) until the next edit.
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any

from lsprotocol import types

from ..analysis.workspace import WorkspaceAnalysis
from .documents import OpenDocument
from .texts import t

if TYPE_CHECKING:
    from .server import CncMacroServer

PROGRESS_SECONDS = 0.25  # how often an analysis reports


async def begin_progress(server: CncMacroServer, doc: OpenDocument, kind: str, cancellable: bool,
                         locale: str) -> str | None:  # fmt: skip
    """Begin reporting the ``kind`` ("reading" or "analysis") of ``doc``, if the editor shows
    progress; the user may stop it when ``cancellable``. The token, or None."""
    caps = server.client_capabilities.window
    if caps is None or not caps.work_done_progress:
        return None
    token = f"cncmacro-{kind}-{doc.uri}-{doc.version}"
    try:
        await server.work_done_progress.create_async(token)
    except Exception:  # the client refused: analyse without progress
        return None
    server.work_done_progress.begin(
        token,
        types.WorkDoneProgressBegin(
            title="cncmacro",
            message=t("reading_lines" if kind == "reading" else "analysing_lines", locale, lines=len(doc.lines)),
            cancellable=cancellable,
            percentage=0,
        ),
    )
    return token


def stop_asked(server: CncMacroServer, token: str | None) -> Callable[[], bool]:
    """Whether the user stopped the analysis that reports progress with ``token`` (the
    editor's cancel button; the analysis starts again at the next edit)."""
    if token is None:
        return lambda: False
    future = server.work_done_progress.tokens.get(token)
    return (lambda: False) if future is None else future.cancelled


async def report_progress(server: CncMacroServer, token: str, work: asyncio.Future[Any],
                          analyses: Callable[[], Iterable[WorkspaceAnalysis]]) -> None:  # fmt: skip
    """Report how far the ``analyses`` got (``WorkspaceAnalysis.progress``) until ``work`` ends."""
    last: tuple[str, int] | None = None
    while not work.done():
        await asyncio.wait([work], timeout=PROGRESS_SECONDS)
        progress = [a.progress for a in analyses() if a.docs]
        if not progress or work.done():
            continue
        now = max(progress, key=lambda p: p.done)
        shown = (now.what, min(99, int(now.done * 100)))
        if shown != last:
            last = shown
            server.work_done_progress.report(token, types.WorkDoneProgressReport(message=shown[0], percentage=shown[1]))
