"""The site index of a document (``analysis/indexes/site_index.py``), made in steps on the editor's
thread once its first analysis is published, or when a question needs it sooner.

Made at once, the index of a million-line file takes seconds, and the editor's messages would
wait that long. So a question that finds an index not ``ready`` answers with what it has and
says the rest is being found, and the index is made here a step at a time (``editor_steps.py``),
the editor's messages answered between the steps, as a huge file is read (``diagnostics.py``).
A shorter document's index would be made at the first question that needs it, which the user
then waits for (30-50 ms for 20,000 lines, at the first hover on a variable): it is made here
too, in the same steps, after its first analysis.
"""

from __future__ import annotations

import asyncio
import logging
import weakref
from functools import partial

from ..analysis.indexes.site_index import SiteIndex
from .editor_steps import between_steps, one_step

log = logging.getLogger(__name__)
INDEX_PIECE_LINES = 200  # lines looked at between two looks at the clock (``editor_steps.py``)

_building: weakref.WeakSet[SiteIndex] = weakref.WeakSet()
_tasks: set[asyncio.Task[None]] = set()


def index_soon(sites: SiteIndex) -> None:
    """Begin making ``sites`` in steps, unless it is made, being made, or of a document still read."""
    if sites.made or sites.partial or sites in _building:
        return
    _building.add(sites)
    task = asyncio.ensure_future(_steps(weakref.ref(sites)))
    _tasks.add(task)
    task.add_done_callback(_tasks.discard)


async def _steps(ref: weakref.ref[SiteIndex]) -> None:
    """The steps, holding the index only during each: one whose document was closed or edited
    into another index meanwhile is gone, and its steps end."""
    while True:
        sites = ref()
        if sites is None:
            return
        try:
            done = one_step(partial(sites.build, INDEX_PIECE_LINES))
        except Exception:  # a fault here must not stop the server: the next question begins it again
            log.exception("indexing a document in steps failed")
            done = True
        if done:
            _building.discard(sites)
            return
        del sites
        await between_steps()
