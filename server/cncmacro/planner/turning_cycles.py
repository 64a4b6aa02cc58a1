"""A lathe's turning cycle as the legs it is drawn and timed by (docs/semantics.md §9).

A single fixed cycle (G90, G92, G94: ``Dialect.single_cycles``, dialects/turning_cycles.py) goes
in along its first axis at rapid, cuts along the other to the end point, comes back out along
the first (at the feed, or at rapid for a thread's pull-out) and returns at rapid to where it
started. Any other turning cycle (G70–G76 so far) is one cut from where it starts to its end
point, until its passes are planned.

A single cycle is timed leg by leg (``time_legs``, by cycle_time.py's rules): a rapid leg at the
axes' rapid rates, a cutting leg at the feed in force, except a thread's (G92), whose F is the
lead: per revolution of the spindle, whatever G98/G99 says, as every thread on a lathe is cut.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

from .cycle_time import INCH
from .moves import TURNING, Leg, Move

if TYPE_CHECKING:
    from ..dialects.turning_cycles import SingleCycle
    from .planner import Planner


def turning_legs(
    cycle: SingleCycle | None, axis_index: Mapping[str, int], start: Sequence[float], end: Sequence[float]
) -> tuple[Leg, ...]:
    """The legs of a turning cycle from ``start`` to its end point ``end`` (module docstring)."""
    first = None if cycle is None else axis_index.get(cycle.first)
    if cycle is None or first is None:
        return (Leg(False, tuple(end)),)
    inside = list(start)
    inside[first] = end[first]
    out = list(end)
    out[first] = start[first]
    return (
        Leg(True, tuple(inside)),
        Leg(False, tuple(end)),
        Leg(cycle.rapid_out, tuple(out)),
        Leg(True, tuple(start)),
    )


def time_legs(p: Planner, start: tuple[float, ...], legs: tuple[Leg, ...], thread: bool) -> float:
    """The seconds of a single cycle's ``legs`` from ``start`` (module docstring), added to the
    planner's clock and its cut and rapid path."""
    times = p.times
    unit = INCH if p.modal.get("units") == 20.0 else 1.0
    feed = p.codes.get("F") or 0.0
    seconds = 0.0
    at: tuple[float, ...] = start
    for leg in legs:
        length = times.distance(at, leg.end)
        if leg.rapid:
            seconds += times.rapid_seconds(at, leg.end, unit)
            p.rapid_length += length * unit
        else:
            speed = p.codes.get("S") or 0.0
            rate = (
                times.feed_rate(feed, True, speed, False, at, leg.end, unit)
                if thread
                else p.cutting_rate(feed, at, leg.end, unit)
            )
            seconds += length / rate * 60.0 if rate > 0 else 0.0
            p.cut_length += length * unit
        at = leg.end
    p.clock += seconds
    return seconds


def single_cycle(p: Planner, file: str, line: int, code: float, cycle: SingleCycle, target: list[float]) -> None:
    """Run single cycle ``code`` from where the tool is to ``target`` and back: time its legs and
    record it as one move with them."""
    start = tuple(p.pos)
    legs = turning_legs(cycle, p.axis_index, start, target)
    seconds = time_legs(p, start, legs, cycle.thread)
    if p.record_moves:
        feed = float(p.codes.get("F") or 0.0)
        p.moves.append(Move(file, line, code, start, tuple(target), feed, None, seconds,
                            p.modal.get("plane", 17.0), legs, TURNING))  # fmt: skip
