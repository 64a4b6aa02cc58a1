"""The path of a lathe's single fixed cycles (G90, G92, G94): the control's data for the planner
(docs/semantics.md §9).

Each goes in along one axis at rapid, cuts along the other to the end point, comes back out
along the first (at the feed; a thread's G92 pulls out at rapid) and returns along the second
at rapid to where it started (the GSK980TDi programming manual's G90 axial cutting cycle, G92
thread cutting cycle and G94 radial cutting cycle). G90 and G92 go in along X first and cut
along Z; G94 goes in along Z first and faces along X. ``planner/turning_cycles.py`` turns one into its legs.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class SingleCycle:
    """A single fixed cycle: the axis it goes in along first, whether it comes out along it at
    rapid (a thread's pull-out) rather than at the feed, and whether it cuts a thread (its F is
    the lead, per revolution)."""

    first: str
    rapid_out: bool = False
    thread: bool = False


LATHE_SINGLE_CYCLES: dict[float, SingleCycle] = {
    90.0: SingleCycle("X"),
    92.0: SingleCycle("X", rapid_out=True, thread=True),
    94.0: SingleCycle("Z"),
}
