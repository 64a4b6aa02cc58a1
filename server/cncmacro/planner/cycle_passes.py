"""A cycle's passes recorded together: the moves a lathe cycle makes from one block (G71–G73's
roughing, G74/G75's pecks, G76's thread passes).

While moves are kept (a ``run``, the debugger, the toolpath) each pass goes through
``Planner.record`` and becomes a ``Move``; so it does where the machine file's ``[limits]`` gives
a travel, which ``record`` checks. A run for diagnostics keeps no moves
(``Planner.record_moves`` is False): there the passes only advance the clock and the path
lengths, and ``record_passes`` does that in one loop with the planner's state read once, by
the same rules of cycle_time.py, so that a program of thousands of cycles (each of a hundred
passes) checks as fast as a mill program of as many blocks. The two ways give the same clock
and lengths (tests/test_lathe_cycle_passes.py).
"""

from __future__ import annotations

from collections.abc import Iterable
from operator import mul, sub
from typing import TYPE_CHECKING

from .arcs import ARC_MODES
from .cycle_time import INCH

if TYPE_CHECKING:
    from .planner import Planner

# a pass: (motion mode, start, end, arc centre or None), positions in program units
Pass = tuple[float, tuple[float, ...], tuple[float, ...], "tuple[float, ...] | None"]


def record_passes(p: Planner, file: str, line: int, passes: Iterable[Pass], pass_of: str) -> None:
    """Record the passes of lathe cycle ``pass_of`` (e.g. "G75") of block ``line`` of ``file``."""
    shape = p.shape
    if p.record_moves or (shape is not None and shape.reading) or p.travel is not None:  # record checks the travel
        record = p.record
        for mode, start, end, centre in passes:
            record(file, line, mode, start, end, centre, pass_of=pass_of)
        return
    times = p.times
    distance = times.distance
    rapid_rates = times.rapid_seconds_per_mm
    feed = p.codes.get("F") or 0.0
    modal = p.modal
    unit = INCH if modal.get("units") == 20.0 else 1.0
    plane = modal.get("plane", 17.0)
    feed_seconds = p.feed_seconds
    seconds = cut = rapid = 0.0
    hint = p.feed_hint and 0.0 < feed < 1.0
    for mode, start, end, centre in passes:
        if mode == 0.0:
            seconds += max(map(mul, map(abs, map(sub, end, start)), rapid_rates)) * unit
            rapid += distance(start, end)
            continue
        if centre is not None and mode in ARC_MODES:
            length = times.arc_length(mode, plane, start, end, centre)
        else:
            length = distance(start, end)
        seconds += feed_seconds(mode, length, feed, start, end, unit)
        cut += length
        if hint:
            p.feed_per_minute_hint(mode, feed, line)
            hint = False
    p.clock += seconds
    p.cut_length += cut * unit
    p.rapid_length += rapid * unit
