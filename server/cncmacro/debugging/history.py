"""The run's past, for step back and reverse continue: checkpoints plus replay.

The interpreter is deterministic and its snapshots are cheap, so the history keeps a
snapshot every ``interval`` blocks (and one after each change a person makes to a variable),
at most ``keep`` of them: with the defaults, the last 1,000,000 blocks at about 10 kB each.
Going back to block count *b* restores the last checkpoint at or before *b* and runs forward
to *b*; at most ``interval`` blocks are replayed. Checkpoints after *b* are dropped, because
the run may now take another path (a person may change a variable before going on).
Reverse continue walks the past latest first (``past``), replaying one stretch between two
checkpoints at a time, until the breakpoints say the forward run stopped there.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Iterator
from typing import TypeVar

from ..machine import Machine, Snapshot
from .stop_points import can_stop

T = TypeVar("T")
INTERVAL = 500
KEEP = 2000


class History:
    def __init__(self, interval: int = INTERVAL, keep: int = KEEP) -> None:
        self.interval = interval
        self.checkpoints: deque[Snapshot] = deque(maxlen=keep)

    def reset(self, m: Machine) -> None:
        self.checkpoints.clear()
        self.checkpoints.append(m.snapshot())

    def record(self, m: Machine) -> None:
        """Called after blocks ran: keep a checkpoint when ``interval`` blocks have passed, at a
        point a run may stop at (``can_stop``: not inside a shape being read)."""
        if not self.checkpoints or (m.blocks - self.checkpoints[-1].blocks >= self.interval and can_stop(m)):
            self.checkpoints.append(m.snapshot())

    def mark(self, m: Machine) -> None:
        """Called after a person changed the state: replays from here must see the change."""
        self.checkpoints.append(m.snapshot())

    @property
    def earliest(self) -> int:
        return self.checkpoints[0].blocks if self.checkpoints else 0

    def go_to(self, m: Machine, target: int) -> bool:
        """Put the machine at block count ``target``; False (and at the earliest point kept)
        when the history does not reach back that far."""
        if not self.checkpoints:
            return False
        while len(self.checkpoints) > 1 and self.checkpoints[-1].blocks > target:
            self.checkpoints.pop()
        cp = self.checkpoints[-1]
        m.restore(cp)
        if cp.blocks > target:
            return False
        _replay(m, target)
        return True

    def past(self, m: Machine, look: Callable[[Machine, bool, bool, bool, bool], T]) -> Iterator[tuple[int, T]]:
        """The run's earlier points, latest first, each as its block count and what ``look``
        says there: from now back to the earliest checkpoint kept. Each stretch between two
        checkpoints is replayed block by block (the machine is left somewhere in the past: put
        it where it should be with ``go_to``). ``look(machine, first, arrival, change,
        entered)`` is asked at every point: ``first`` at the start of a stretch, ``arrival``
        for each point but a stretch's last (which is the next stretch's first), and the
        present, and ``change`` for each point but a stretch's first (the block that led there
        was replayed; ``entered`` when it opened a program level)."""
        now = m.blocks
        cps = [c for c in self.checkpoints if c.blocks < now]
        for i in range(len(cps) - 1, -1, -1):
            end = cps[i + 1].blocks if i + 1 < len(cps) else now
            m.restore(cps[i])
            start = m.blocks
            seen: list[tuple[int, T]] = []
            entered = start == 0
            while True:
                b = m.blocks
                seen.append((b, look(m, b == start, b < end or b == now, b > start, entered)))
                if b >= end or m.finished:
                    break
                depth = len(m.frames)
                m.step()
                entered = len(m.frames) > depth
            yield from reversed(seen)


def _replay(m: Machine, target: int) -> None:
    while m.blocks < target and not m.finished:
        m.run(target - m.blocks, is_limit=False)
