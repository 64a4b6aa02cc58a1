"""Where a run may stop: the one rule that stepping, going back and "run to here" share.

A lathe roughing cycle (G71–G73 P Q) is one step with its shape (docs/semantics.md §10.2): while
the planner reads the shape, the tool stays where the cycle began and none of the shape's blocks
is run, so no stop is made there: not by a step, a breakpoint, a pause, reverse continue, step
back or "run to here", and no history checkpoint is kept there (going back starts and ends at a
point a forward run could have stopped at). A G70 runs its shape, and stops in it are made.
"""

from __future__ import annotations

from ..machine import Machine


def can_stop(m: Machine) -> bool:
    """Whether a run may stop at the machine's present point (not while a roughing cycle
    reads its shape)."""
    shape = m.planner.shape
    return shape is None or not shape.reading
