"""The run's past, for step back and reverse continue: checkpoints plus replay.

The interpreter is deterministic and its snapshots are cheap, so the history keeps a
snapshot every ``interval`` blocks (and one after each change a person makes to a variable),
at most ``keep`` of them: with the defaults, the last 1,000,000 blocks at about 10 kB each.
Going back to block count *b* restores the last checkpoint at or before *b* and runs forward
to *b*; at most ``interval`` blocks are replayed. Checkpoints after *b* are dropped, because
the run may now take another path (a person may change a variable before going on).
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable

from ..machine import Machine, Snapshot

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
        """Called after blocks ran: keep a checkpoint when ``interval`` blocks have passed."""
        if not self.checkpoints or m.blocks - self.checkpoints[-1].blocks >= self.interval:
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

    def back_to_stop(self, m: Machine, stops_here: Callable[[Machine], bool]) -> bool:
        """Go back to the latest earlier block where ``stops_here`` holds; False (and at the
        earliest point kept) when there is none."""
        current = m.blocks
        cps = [c for c in self.checkpoints if c.blocks < current]
        for i in range(len(cps) - 1, -1, -1):
            end = cps[i + 1].blocks if i + 1 < len(cps) else current
            m.restore(cps[i])
            found = None
            while True:
                if m.blocks >= end:
                    break
                if stops_here(m):
                    found = m.blocks
                m.step()
                if m.finished:
                    break
            if found is not None:
                return self.go_to(m, found)
        self.go_to(m, self.earliest)
        return False


def _replay(m: Machine, target: int) -> None:
    while m.blocks < target and not m.finished:
        m.run(target - m.blocks, is_limit=False)
