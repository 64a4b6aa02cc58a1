"""Whoever watches a run from outside the interpreter: the analysis, through one ``RunObserver``.

A ``Machine`` made with ``observer=`` tells it what a plain run keeps to itself, and a machine
made without one runs the plain loop (``Machine._run``) and compiles plain blocks, paying
nothing for any of this. With an observer:

- every block is compiled watched (``CompiledFile.compile``): a read that finds a local vacant
  which the macro's caller did not pass is reported (``vacant_argument``), an assignment to a
  local or common variable reports the value it left (``wrote``), and a loop head each pass
  (``loop_pass``);
- ``Machine.run`` runs ``tracking.run_tracked``, which stamps each line it runs with
  ``track_serial`` in ``last_run`` (file path -> one slot per line, -1 for never) and tells
  ``first_run`` of a line whose stamp was below ``track_floor``: a line not run since the
  observer last raised the floor, and asks ``came_back`` at each jump back within a frame and
  each change of frame, pausing the run when it answers True (the state is then whole: a
  ``Snapshot`` can be taken).

The methods here do nothing: a subclass overrides what it needs. The analysis's ``EntryRun``
(``analysis/runs/run_checks.py``) is one; it sets ``track_serial`` before each chunk it runs,
raises ``track_floor`` when it goes back to a checkpoint, and reads ``last_run`` to decide whether an edited
line runs again after a given point of an earlier run.
"""

from __future__ import annotations

from .alarms import CallLevel

Value = float | None


class RunObserver:
    """Hears of a machine's run; every method is a no-op (see the module docstring)."""

    def __init__(self) -> None:
        self.last_run: dict[str, list[int]] = {}  # file path -> per line, the serial that last ran it
        self.track_serial = 0  # what the lines run from now on are stamped with
        self.track_floor = 0  # a line stamped below this is heard of (``first_run``) when it next runs
        # (as they stand here, each line is heard of the first time it runs)

    def first_run(self, file: str, line: int, step: int) -> None:
        """``line`` of ``file`` runs, as block ``step`` of the run, for the first time since the
        floor was last raised."""

    def vacant_argument(self, number: int, file: str, line: int, chain: tuple[CallLevel, ...]) -> None:
        """A macro read its local ``#number`` on ``line`` vacant, and its caller did not pass it."""

    def wrote(self, file: str, line: int, number: int, value: Value) -> None:
        """The assignment on ``line`` left ``value`` in local or common ``#number``."""

    def loop_pass(self, level: int, do_line: int, again: bool) -> None:
        """The loop head on ``do_line`` of call level ``level`` runs (``again``: the loop was
        already running, else it starts)."""

    def tool_changed(self, file: str, line: int) -> None:
        """A tool change on ``line`` of ``file`` (cycle_time.py); the machine's clock and path
        lengths are those before it."""

    def came_back(self, line: int, to: int) -> bool:
        """The block on ``line`` jumped back to ``to``, at or before it, in the same frame; or
        (``line`` -1) the run went on in another frame (a call or a return) at ``to``. True
        pauses the run before the block on ``to``."""
        return False
