"""What the planner asks of the macro machine that runs it: the one narrow interface downward.

The planner keeps no variables. The offset tables it reads (work offsets, tool offsets) and
writes (``G10``) are the macro machine's stored system variables, reached by number through
``stored``, ``store`` and ``store_added``; it tells the machine of a tool change (``tool_changed``, for whoever
watches the run), of a remark about a block (``note``: where a ``G31`` stopped) and of where a
``G31`` stopped on a control that stores it in common variables (``probed``: the GSK980TDi's
#995…). The macro machine (``machine/machine.py``'s ``Machine``) is the host; a test may give any
object with these six methods.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol


class PlannerHost(Protocol):
    """The macro machine as the planner sees it."""

    def stored(self, n: int) -> float | None:
        """The value of stored system variable ``#n`` (an offset), None when vacant."""
        ...

    def store(self, n: int, value: float) -> None:
        """Write stored system variable ``#n`` (a ``G10`` offset), as a program's write would."""
        ...

    def store_added(self, n: int, amount: float) -> None:
        """Add ``amount`` to stored system variable ``#n`` (a ``G10`` increment: G91, a lathe's
        U, W, C), as ``#n=#n+amount`` would: an offset the run does not know stays unknown."""
        ...

    def tool_changed(self, file: str, line: int) -> None:
        """A tool change on ``line`` of ``file`` (0-based), before its time is added."""
        ...

    def note(self, kind: str, message: str, line: int | None = None, subject: str | None = None) -> None:
        """A remark about the block on ``line`` of the program running (its current line when None)."""
        ...

    def probed(self, stored: Sequence[tuple[int, float]], touched: bool) -> None:
        """A G31 ended on a control that stores where the skip signal came on in common
        variables (``Dialect.skip_commons``): ``stored`` are those variables with where the move
        stopped, which they take where the signal came on (``touched``)."""
        ...
