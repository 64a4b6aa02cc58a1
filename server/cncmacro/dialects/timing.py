"""What a control's machine takes time for, besides cutting: the data of the cycle-time model.

A ``Timing`` is one machine's: the rapid traverse rate of each axis (mm/min, degrees/min for a
rotary axis; FANUC parameter 1420, the machine builder's data sheet elsewhere), the seconds a
tool change takes and the code that makes it (``M6`` on a mill, where T only selects the next
tool; ``T`` on a lathe, whose turret indexes on the T word), the seconds other M codes take
(a coolant valve, a pallet change), the unit of a dwell's P (and whether a P written with a
decimal point counts seconds instead), the spindle's top speed (the
limit of G96 constant surface speed) and the peck drilling cycles' retract distances. Each
profile module carries typical values; a machine file's ``[timing]`` table gives the machine's
own (docs/machine-file.md, ``Timing.changed``). How the interpreter uses them is
``planner/cycle_time.py``.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import TypedDict


class TimingChanges(TypedDict, total=False):
    """A machine file's changes to a profile's ``Timing``: its fields, each optional."""

    rapid: dict[str, float]
    rapid_default: float
    tool_change_seconds: float
    tool_change_code: str
    m_code_seconds: dict[float, float]
    dwell_p_unit: float
    max_spindle_speed: float
    peck_retract: float
    peck_clearance: float


@dataclass(frozen=True)
class Timing:
    """One machine's timing data (see the module docstring)."""

    # axis letter -> rapid traverse rate, mm/min (degrees/min for a rotary axis)
    rapid: dict[str, float] = field(default_factory=dict)
    # an axis the table leaves out moves at this rate
    rapid_default: float = 10000.0
    tool_change_seconds: float = 0.0
    # "M6": M06 changes the tool (mills); "T": a T word indexes the turret (lathes)
    tool_change_code: str = "M6"
    # M code -> seconds it takes (M6 and a lathe's T are ``tool_change_seconds``)
    m_code_seconds: dict[float, float] = field(default_factory=dict)
    # seconds per unit of G04 P: 0.001 where P counts milliseconds, 1.0 where it counts seconds
    dwell_p_unit: float = 0.001
    # a dwell's P (G04's, a drilling cycle's) written with a decimal point counts seconds, one
    # without counts ``dwell_p_unit`` (Haas: "G04 P10. is a dwell of 10 seconds; G04 P10 is 10
    # milliseconds"); read from the word's text where the block is compiled (machine/blocks.py)
    dwell_p_point_seconds: bool = False
    # a helix (G02/G03 with the third axis moving) is fed along its arc in the plane, F the speed on
    # the circumference (FANUC: "The feedrate along the circumference of two circular interpolated
    # axes is the specified feedrate"); False: along the helix itself
    helix_fed_on_arc: bool = False
    # the spindle's top speed (rev/min): G96 never turns the spindle faster
    max_spindle_speed: float = 4000.0
    # mm: how far G73 retracts after each peck (FANUC parameter 5114) and how far above the last
    # depth G83 stops its rapid back in (parameter 5115); the machine builder sets both, 0 here
    peck_retract: float = 0.0
    peck_clearance: float = 0.0

    def rapid_rate(self, axis: str) -> float:
        """The rapid traverse rate of ``axis`` (mm/min or degrees/min)."""
        return self.rapid.get(axis, self.rapid_default)

    def changed(self, changes: TimingChanges) -> Timing:
        """This timing with a machine file's ``[timing]`` values over it: ``rapid`` and
        ``m_code_seconds`` are merged axis by axis and code by code, the others replace."""
        merged = changes.copy()
        if "rapid" in changes:
            merged["rapid"] = {**self.rapid, **changes["rapid"]}
        if "m_code_seconds" in changes:
            merged["m_code_seconds"] = {**self.m_code_seconds, **changes["m_code_seconds"]}
        return replace(self, **merged)
