"""The planner's state as a snapshot keeps it, and the modal groups a control starts with.

``PlannerState`` is a copy of the planner's state at one moment (``Planner.snapshot``, inside the
macro machine's ``Snapshot``); ``MODAL_DEFAULTS`` the modal code of each group at power-on, which
a profile's ``modal_defaults`` change (a lathe's G18 and G98).
"""

from __future__ import annotations

from dataclasses import dataclass

from .corner_stage import HeldCorner
from .cutter_stage import CutterStage
from .lathe_cycles import ShapeReading
from .probing import SkipState
from .whereabouts import START, Whereabouts

MODAL_DEFAULTS = {"motion": 0.0, "distance": 90.0, "units": 21.0, "cutter": 40.0, "length": 49.0, "canned": 80.0,
                  "return": 98.0, "macro": 67.0, "spindle": 97.0, "wcs": 54.0, "cutting": 64.0, "rotation": 69.0,
                  "mirror": 50.1, "scaling": 50.0, "polar": 15.0, "stroke": 22.0}  # fmt: skip


@dataclass(slots=True)
class PlannerState:
    """A copy of the planner's state at one moment (part of the macro machine's ``Snapshot``):
    modal groups, codes, positions (program, coordinate shift, skip, tool vector), the extra
    work offset, a drilling cycle's initial level, the clock, the cut and rapid path, and how
    many moves, tool changes and probes had been recorded, and a lathe's cycle parameters and
    the shape cycle under way (lathe_cycles.py), cutter radius compensation's stage
    (cutter_stage.py), the tool vector before a change the machine has not travelled yet
    (offset_travel.py), what the run knows of where the machine is (whereabouts.py), and the move
    held for its chamfer or rounding (corner_stage.py)."""

    modal: dict[str, float]
    codes: dict[str, float | None]
    positions: tuple[list[float], list[float], list[float], list[float]]
    extra_wcs: int
    cycle_start_z: float | None
    clock: float
    lengths: tuple[float, float]
    moves: int
    tool_count: int
    skip_state: SkipState
    probes: int
    cycle_params: dict[float, dict[str, float]]
    shape: ShapeReading | None
    cutter: CutterStage | None = None
    vector_before: list[float] | None = None  # a tool vector change not yet travelled (offset_travel.py)
    whereabouts: Whereabouts = START  # what the run knows of where the machine is (whereabouts.py)
    corner: HeldCorner | None = None  # a move whose chamfer or rounding waits for the next (corner_stage.py)
