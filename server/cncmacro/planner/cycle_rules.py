"""The alarms of a lathe's cycles at run time (docs/semantics.md §10.5): what a control refuses
in a cycle block's words (``check_cycle_block``) and in a finishing shape once it is read
(``check_shape``). Each raises ``MacroAlarm`` with the control's number (dialects/alarms.py).
The static findings for literal words come from the same rules.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .lathe_cycles import ShapeReading
    from .planner import Planner


def check_cycle_block(p: Planner, g: float, words: dict[str, float]) -> None:
    """Refuse a block of lathe cycle ``g`` whose ``words`` (U and W by letter) the control
    alarms on; the first block's parameters are in ``p.cycle_params``."""


def check_shape(p: Planner, shape: ShapeReading) -> None:
    """Refuse a finishing shape, read in full, that the control alarms on."""
