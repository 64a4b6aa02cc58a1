"""A cycle's passes recorded together: the moves a lathe cycle makes from one block (G71–G73's
roughing, G74/G75's pecks, G76's thread passes).

While moves are kept (a ``run``, the debugger, the toolpath) each pass goes through
``Planner.record`` and becomes a ``Move``; so it does where the machine file's ``[limits]`` gives
a travel, which ``record`` checks. A run for diagnostics keeps no moves
(``Planner.record_moves`` is False): there the passes only advance the clock and the path
lengths, and ``record_passes`` does that in one loop with the planner's state read once, by
the same rules of cycle_time.py. A pass moves X and Z alone (each cycle builds it from the one
before with those two changed), so a straight one's length and rapid time are read from them.
The two ways give the same clock and lengths (tests/test_lathe_cycle_passes.py).
"""

from __future__ import annotations

from collections.abc import Sequence
from math import sqrt
from typing import TYPE_CHECKING

from .arcs import ARC_MODES
from .cycle_time import INCH
from .missing_feed import note_missing_feed

if TYPE_CHECKING:
    from .planner import Planner

# a pass: (motion mode, start, end, arc centre or None), positions in program units
Pass = tuple[float, tuple[float, ...], tuple[float, ...], "tuple[float, ...] | None"]


def record_passes(p: Planner, file: str, line: int, passes: Sequence[Pass], pass_of: str) -> None:
    """Record the passes of lathe cycle ``pass_of`` (e.g. "G75") of block ``line`` of ``file``,
    and count them (``Planner.cycle_passes``: the analysis runs checkpoint by the work done)."""
    p.cycle_passes += len(passes)
    shape = p.shape
    if p.record_moves or (shape is not None and shape.reading) or p.travel is not None:  # record checks the travel
        record = p.record
        for mode, start, end, centre in passes:
            record(file, line, mode, start, end, centre, pass_of=pass_of)
        return
    times = p.times
    feed = p.codes.get("F") or 0.0
    modal = p.modal
    unit = INCH if modal.get("units") == 20.0 else 1.0
    plane = modal.get("plane", 17.0)
    hint = p.feed_hint and 0.0 < feed < 1.0
    per_rev = modal.get("feed") == 95.0 or (modal.get("feed") == 99.0 and p.lathe)
    # a straight cut's rate, the same all along it (None under G96: the general rule)
    rate = times.straight_rate(feed, per_rev, p.codes.get("S") or 0.0, modal.get("spindle") == 96.0, unit)
    xi, zi = times.diameter, p.axis_index.get("Z", -1)
    if xi < 0 or zi < 0:
        rate = None  # not a lathe's X (a diameter) and Z
    else:
        rx, rz = times.rapid_seconds_per_mm[xi], times.rapid_seconds_per_mm[zi]
    threads = times.thread_modes
    seconds = cut = rapid = 0.0
    for mode, start, end, centre in passes:
        if rate is not None and centre is None and mode not in threads:
            # a lathe cycle's pass moves X (a diameter: the tool goes half of it) and Z only
            dx, dz = end[xi] - start[xi], end[zi] - start[zi]
            length = sqrt(0.25 * dx * dx + dz * dz)
            if mode == 0.0:
                seconds += max(abs(dx) * rx, abs(dz) * rz) * unit
                rapid += length
                continue
            if rate > 0.0 and length > 0.0:
                seconds += length / rate * 60.0
            elif rate <= 0.0:  # no feed, or per revolution at S0 (missing_feed.py)
                note_missing_feed(p, feed, per_rev, p.codes.get("S") or 0.0, line)
        elif mode == 0.0:
            seconds += times.rapid_seconds(start, end, unit)
            rapid += times.distance(start, end)
            continue
        else:
            if centre is not None and mode in ARC_MODES:
                length = times.arc_length(mode, plane, start, end, centre)
            else:
                length = times.distance(start, end)
            seconds += p.feed_seconds(mode, length, feed, start, end, unit, line=line)
        cut += length
        if hint:
            p.feed_per_minute_hint(mode, feed, line)
            hint = False
    p.clock += seconds
    p.cut_length += cut * unit
    p.rapid_length += rapid * unit
