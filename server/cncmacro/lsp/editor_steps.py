"""Long work done on the editor's thread (reading a huge file, indexing it) in short steps, the
editor's messages answered between them.

A step runs pieces of the work until ``STEP_SECONDS`` have passed, so a hover that comes in
the middle of one waits at most that long, however fast or slow the machine; then the event
loop turns ``YIELDS`` times, enough for a message to be read and reach its handler.
"""

from __future__ import annotations

import asyncio
import time
from collections.abc import Callable

STEP_SECONDS = 0.002  # the longest a message waits for a step to end
YIELDS = 8  # turns of the event loop given to the editor's messages between two steps


def one_step(piece: Callable[[], bool]) -> bool:
    """Run ``piece`` (a small part of the work; True once all is done) until the work is done or
    the step's time is up; whether it is done."""
    end = time.perf_counter() + STEP_SECONDS
    while not piece():
        if time.perf_counter() >= end:
            return False
    return True


async def between_steps() -> None:
    """Let the editor's messages through: a message takes a few turns of the loop to reach its handler."""
    for _ in range(YIELDS):
        await asyncio.sleep(0)
