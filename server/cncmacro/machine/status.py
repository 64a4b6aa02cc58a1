"""How a run stands: ``RunStatus``, the value ``Machine.run`` returns and ``RunResult`` carries.

A ``str`` enum, so that each member is its text everywhere a status is shown or compared: in
``cncmacro run --json``, the debugger's output and exit code, ``==`` with the plain text, and as
a dictionary key. ``str()`` and format give the value on every Python the package supports (3.10
formats a ``str`` mixin differently from 3.12, so both are spelled out here).
"""

from __future__ import annotations

from enum import Enum


class RunStatus(str, Enum):
    READY = "ready"  # started, no block run yet (or resumed after a pause)
    RUNNING = "running"  # inside ``Machine.run``
    PAUSED = "paused"  # M00, #3006, one step, a pause request, or a chunk's end (``is_limit=False``)
    COMPLETED = "completed"  # M30/M02, or the main program ran off its end
    ALARM = "alarm"  # a macro alarm; ``Machine.alarm`` says which
    LIMIT = "limit"  # the block budget ran out
    STOPPED = "stopped"  # ``Machine.cancel`` from another thread

    def __str__(self) -> str:
        return self.value

    def __format__(self, spec: str) -> str:
        return format(self.value, spec)


FINISHED = frozenset({RunStatus.COMPLETED, RunStatus.ALARM, RunStatus.LIMIT, RunStatus.STOPPED})
# how often (in blocks) a run loop looks whether another thread asked it to stop or pause
CANCEL_CHECK = 4096
