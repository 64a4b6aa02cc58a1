"""A lathe's single turning cycle as the legs it is drawn and timed by (docs/semantics.md §9,
§10.3).

A single fixed cycle (G90, G92, G94: ``Dialect.single_cycles``, dialects/turning_cycles.py) goes
in along its first axis at rapid, cuts along the other to the end point, comes back out along
the first (at the feed, or at rapid for a thread's pull-out) and returns at rapid to where it
started. R tapers the cut: it is where the cut starts less where it ends, along the first axis
(G90, G92: a radius, so the cut starts at X + 2R; G94: along Z, at Z + R).

X (U), Z (W) and R are modal (``single_cycle_target``): a following block of the cycle that
gives only X (or only Z) cuts again to the other coordinate of the last cycle block, with its R
(and F), until a G code of the motion group other than these cycles or a one-shot code other
than G04 clears them (``forget_single_cycle``; FANUC 0i-TF and GSK980TDi: the single cycles'
examples that step X alone, then Z alone with R).

A single cycle is timed leg by leg (``time_legs``, by cycle_time.py's rules): a rapid leg at the
axes' rapid rates, a cutting leg at the feed in force, except a thread's (G92), whose F is the
lead: per revolution of the spindle, whatever G98/G99 says, as every thread on a lathe is cut.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

from .cycle_time import INCH
from .machine_limits import leaves_travel, program_bounds
from .moves import TURNING, Leg, Move

if TYPE_CHECKING:
    from ..dialects.turning_cycles import SingleCycle
    from .planner import Planner

# the ``Planner.cycle_params`` key of the modal words of the single cycle in force
SINGLE_CYCLE_WORDS = -1.0
# the mode a cycle's thread cut is timed and drawn as (G32 on both lathe profiles; cycle_time.py)
THREAD_MODE = 32.0
STARTS = "starts"  # the key of a thread's number of starts among the single cycle's kept words


def turning_legs(
    cycle: SingleCycle | None,
    axis_index: Mapping[str, int],
    start: Sequence[float],
    end: Sequence[float],
    taper: float = 0.0,
) -> tuple[Leg, ...]:
    """The legs of a turning cycle from ``start`` to its end point ``end`` (module docstring),
    ``taper`` the cut's start less its end along the first axis, in that axis's units."""
    if cycle is not None and cycle.tap:  # in to the end point and back out to the start
        return (Leg(False, tuple(end)), Leg(False, tuple(start)))
    first = None if cycle is None else axis_index.get(cycle.first)
    if cycle is None or first is None:
        return (Leg(False, tuple(end)),)
    inside = list(start)
    inside[first] = end[first] + taper
    out = list(end)
    out[first] = start[first]
    return (
        Leg(True, tuple(inside)),
        Leg(False, tuple(end)),
        Leg(cycle.rapid_out, tuple(out)),
        Leg(True, tuple(start)),
    )


def time_legs(p: Planner, start: tuple[float, ...], legs: tuple[Leg, ...], thread: bool, tap: bool = False) -> float:
    """The seconds of a single cycle's ``legs`` from ``start`` (module docstring), added to the
    planner's clock and its cut and rapid path; a tapping cycle's (``tap``) both legs threaded."""
    times = p.times
    unit = INCH if p.modal.get("units") == 20.0 else 1.0
    feed = p.codes.get("F") or 0.0
    mode = THREAD_MODE if thread else 1.0
    seconds = 0.0
    at: tuple[float, ...] = start
    for leg in legs:
        length = times.distance(at, leg.end)
        if leg.rapid:
            seconds += times.rapid_seconds(at, leg.end, unit)
            p.rapid_length += length * unit
        else:
            cut_mode = mode if tap or leg is legs[1] else 1.0  # only the cut along the thread is threaded
            seconds += p.feed_seconds(cut_mode, length, feed, at, leg.end, unit)
            p.cut_length += length * unit
        at = leg.end
    p.clock += seconds
    return seconds


def single_cycle_target(
    p: Planner, code: float, axes: dict[int, float], inc: dict[int, float], other: dict[str, float]
) -> tuple[list[float], float]:
    """The end point and taper R of single cycle ``code``'s block: its X (U), Z (W) and R, and
    for those it leaves out the last cycle block's (module docstring). Kept for the next block."""
    kept = p.cycle_params.get(SINGLE_CYCLE_WORDS, {})
    same = kept.get("G") == code
    names = p.dialect.axes
    target = list(p.pos)
    for i, name in enumerate(names):
        if i in axes:
            target[i] = axes[i]
        elif i in inc:
            target[i] += inc[i]
        elif same and name in kept:
            target[i] = kept[name]
    letter = p.dialect.lathe_cycles.taper_letters.get(code, "R")  # Haas: I (G90, G92), K (G94)
    taper = other.get(letter, kept.get("R", 0.0) if same else 0.0)
    words = {"G": code, "R": taper, **dict(zip(names, target, strict=True))}
    single = p.dialect.single_cycles.get(code)
    if single is not None and single.starts is not None:  # a thread's starts (L), modal with the rest
        kept_starts = kept.get(STARTS, 1.0) if same and single.starts_modal else 1.0
        words[STARTS] = other.get(single.starts, kept_starts)
    if single is not None and single.widening is not None:  # G92.3's E, A, Q: modal with the rest
        for letter in single.widening:
            if letter in other or (same and letter in kept):
                words[letter] = other.get(letter, kept.get(letter, 0.0))
    p.cycle_params[SINGLE_CYCLE_WORDS] = words
    return target, taper


def forget_single_cycle(p: Planner) -> None:
    """A G code of the motion group other than a single cycle, or a one-shot code other than
    G04: the single cycle's modal words are cleared (module docstring)."""
    p.cycle_params.pop(SINGLE_CYCLE_WORDS, None)


def single_cycle(
    p: Planner, file: str, line: int, code: float, cycle: SingleCycle, target: list[float], taper: float = 0.0
) -> None:
    """Run single cycle ``code`` from where the tool is to ``target`` and back, its cut tapered by
    ``taper`` (R): time its legs and record it as one move with them."""
    start = tuple(p.pos)
    first = p.axis_index.get(cycle.first)
    scale = 2.0 if first is not None and first == p.times.diameter else 1.0  # R is a radius on X
    legs = turning_legs(cycle, p.axis_index, start, target, taper * scale)
    seconds = 0.0
    # a thread of L starts: each start cut in turn; a widened root (G92.3): each pass across it
    for _ in range(thread_starts(p, cycle) * widening_passes(p, cycle)):
        seconds += time_legs(p, start, legs, cycle.thread, cycle.tap)
    feed = p.codes.get("F") or 0.0
    if p.feed_hint and 0.0 < feed < 1.0 and not cycle.thread:
        p.feed_per_minute_hint(1.0, feed, line)
    stop = None
    if p.travel is not None:  # the machine's soft limits (machine_limits.py): the cycle is drawn whole
        stop = leaves_travel(p, program_bounds(p), code, p.modal.get("plane", 17.0), start, start, None, legs)
    if p.record_moves:
        p.moves.append(Move(file, line, code, start, tuple(target), float(feed), None, seconds,
                            p.modal.get("plane", 17.0), legs, TURNING))  # fmt: skip
        if len(p.moves) >= p.move_budget:
            p.moves_full(line)
    if stop is not None:
        raise stop[1]


def thread_starts(p: Planner, cycle: SingleCycle) -> int:
    """How many times a single cycle is cut: its thread's starts (``SingleCycle.starts``, modal:
    kept with the cycle's words by ``single_cycle_target``), 1 for one or none."""
    if cycle.starts is None:
        return 1
    kept = p.cycle_params.get(SINGLE_CYCLE_WORDS, {})
    return max(1, int(kept.get(STARTS, 1.0)))


def widening_passes(p: Planner, cycle: SingleCycle) -> int:
    """How many passes a thread whose root is widened along its long axis takes
    (``SingleCycle.widening``; GSK980TDi G92.3, §3.24.14: "余量加工循环切削的次数＝(F－E－A)/Q ＋ 1"):
    the tool of width A steps Q (least input increments) across the root the lead F leaves beside
    the crest E, from one side to the other, the last step the rest; 1 where the words are missing
    or leave nothing to widen. Each pass goes along the same path (the control shifts the spindle's
    phase, not the start point: the manual draws one cycle start point and says its path is G92's)."""
    if cycle.widening is None:
        return 1
    kept = p.cycle_params.get(SINGLE_CYCLE_WORDS, {})
    crest, tool, step = cycle.widening
    rest = abs(p.codes.get("F") or 0.0) - kept.get(crest, 0.0) - kept.get(tool, 0.0)
    step_mm = in_increments(p, kept.get(step, 0.0))
    if rest <= 0.0 or step_mm <= 0.0:
        return 1
    return math.ceil(rest / step_mm - 1e-9) + 1


def in_increments(p: Planner, value: float) -> float:
    """A lathe cycle's P or Q amount written without a decimal point, in program units: ``value``
    least input increments (``LatheCycles.increment``: 0.001 mm, 0.0001 inch under G20)."""
    step = p.dialect.lathe_cycles.increment
    return value * (step / 10.0 if p.modal.get("units") == 20.0 else step)
