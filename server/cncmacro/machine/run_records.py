"""What a run gives back: its result (``RunResult``, what ``cncmacro run --json`` prints) and a copy
of its state at one moment (``Snapshot``, for the debugger's step back and the incremental
analysis).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..planner.moves import Move
from ..planner.probing import Probe
from ..planner.state import PlannerState
from .alarms import Alarm
from .frames import Frame, ModalCall, Note
from .status import RunStatus

Value = float | None


@dataclass(slots=True)
class RunResult:
    """What a run ended with, in docs/design.md's terms (``cncmacro run --json``)."""

    status: RunStatus
    alarm: Alarm | None
    blocks: int
    variables: dict[int, float]
    moves: list[Move]
    output: list[str]
    notes: list[Note]
    message: str | None = None
    probes: list[Probe] = field(default_factory=list)  # the G31 blocks (probing.py)


@dataclass(slots=True)
class Snapshot:
    """A copy of a machine's state at one moment; restore it any number of times."""

    frames: list[Frame]
    C: list[Value]
    S: dict[int, Value]
    motion: PlannerState  # the planner's (planner/planner.py)
    modal_calls: list[ModalCall]
    counts: tuple[int, int]  # output lines and notes
    blocks: int
    status: RunStatus
    alarm: Alarm | None
    message: str | None
    written_system: set[int] = field(default_factory=set)
    timer_marks: dict[int, float] = field(default_factory=dict)
    ended_with: float | None = None  # the end code a completed run stopped at (``Machine.ended_with``)
