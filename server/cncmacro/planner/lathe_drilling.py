"""A lathe's drilling cycles hole by hole (docs/semantics.md §10.3): the face cycles drill along
Z (G83 drilling, G84 tapping, G85 boring), the side cycles along X (G87, G88, G89), positioned by
the other axes (X and C on the face, Z and C on the side). The profile's ``Dialect.lathe_drilling``
(dialects/drill_cycles.py) says which codes there are and how R is read.

FANUC 0i-TF (G-code system A), "canned cycle for drilling", ``G83 X(U) C(H) Z(W) R Q P F K``:

1. position at rapid, at the level the tool is at (the initial level, taken when the block that
   names the cycle begins);
2. rapid to the R point, R from the initial level (along X a radius value);
3. cut to the bottom (Z, or W from the R point): in one feed, or in pecks of Q (least input
   increments, as the lathe cycles' P and Q) with a retract of d (the machine file's
   ``peck_retract``, FANUC parameter 5114) after each;
4. dwell P at the bottom (G83, G84, G87, G88, G89), a tap (G84, G88) again at the R point on its
   way out (FANUC 16i/18i/21i-TA/TB: "Dwell time at the bottom of the hole and at point R when a
   return is made");
5. out to the initial level: at rapid, or for tapping and boring at F to the R point first.

GSK980TDi §3.23.9, ``G83 X(U) C(H) Z(W) P Q R F K J``: there is no R point. The cycle drills
from where the hole is positioned, in pecks of Q each followed by a rapid retract of R (J0, R 1 mm
when left out, a radius) or by a rapid back to the start and down again to R short of the depth
reached (J1), dwells P and rapids back to the start. Its rigid taps G84/G88 (§3.24.6) go in and
out at the lead F (I threads per inch) per revolution.

Q, P, R (and J) stay in force with the cycle, each axis's bottom too; K drills the block's hole K times
(under U, H each time on by them). Each hole is recorded as one move with its legs and time, as a
mill's (drill_cycles.py); the tool ends at the return level over the hole.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..dialects.drill_cycles import PECK, SHORT_PECK, DrillCycle, LatheDrill
from .cycle_time import INCH, RAPID_STEP
from .drill_cycles import CYCLE_P, CYCLE_Q, hole_steps, record_hole, repeat_count
from .turning_cycles import THREAD_MODE, in_increments
from .whereabouts import placed

if TYPE_CHECKING:
    from ..dialects.drill_cycles import LatheDrilling
    from .planner import Planner

# the hole data kept in ``Planner.codes`` while the cycle is in force
LATHE_R = "lathe drill R"
LATHE_J = "lathe drill J"
LATHE_BOTTOM = "lathe drill bottom"  # the bottom as an absolute level
LATHE_DEPTH = "lathe drill depth"  # the bottom as W (U) from where the cut starts


def lathe_drill_block(
    p: Planner, data: LatheDrilling, code: float, axes: dict[int, float], inc: dict[int, float],
    other: dict[str, float], file: str, line: int,
) -> None:  # fmt: skip
    """Drill the holes of one block in the lathe drilling cycle ``code`` (module docstring)."""
    spec = data.cycles[code]
    axis = p.axis_index.get(spec.axis)
    codes = p.codes
    for letter, key in (("R", LATHE_R), ("Q", CYCLE_Q), ("P", CYCLE_P), ("J", LATHE_J)):
        if letter in other:
            codes[key] = other[letter]
    place = {i: v for i, v in axes.items() if i != axis}
    place_inc = {i: v for i, v in inc.items() if i != axis}
    bottom, depth = f"{LATHE_BOTTOM} {spec.axis}", f"{LATHE_DEPTH} {spec.axis}"  # each axis its own
    if axis is not None and axis in axes:
        codes[bottom], codes[depth] = axes[axis], None
    elif axis is not None and axis in inc:
        codes[bottom], codes[depth] = None, inc[axis]
    repeats = repeat_count(other.get("K"), "K")
    if axis is None:  # no drilling axis on this machine: the holes are only positioned
        for _ in range(repeats):
            p.move(file, line, 0.0, p.target(place, place_inc))
        if repeats:
            placed(p, place)  # whereabouts.py
        return
    scale = 2.0 if axis == p.times.diameter else 1.0  # X levels are diameters, R a radius value
    for _ in range(repeats):
        _hole(p, data, spec, axis, scale, p.target(place, place_inc), file, line, code)
    if repeats:
        placed(p, place)  # the holes' X, C are where the program says (whereabouts.py)


def _hole(
    p: Planner, data: LatheDrilling, spec: LatheDrill, axis: int, scale: float, hole: list[float], file: str,
    line: int, code: float,
) -> None:  # fmt: skip
    """One hole at ``hole`` (positioned, at the tool's level along ``axis``)."""
    codes = p.codes
    start = tuple(p.pos)
    if data.r_point:  # FANUC: the initial level from the block that named the cycle
        if p.cycle_start_z is None:
            p.cycle_start_z = p.pos[axis]
        initial = p.cycle_start_z
        r_level = initial + scale * (codes.get(LATHE_R) or 0.0)
    else:  # GSK: from where the hole is positioned
        initial = r_level = hole[axis]
    absolute, depth = codes.get(f"{LATHE_BOTTOM} {spec.axis}"), codes.get(f"{LATHE_DEPTH} {spec.axis}")
    bottom = absolute if absolute is not None else r_level + depth if depth is not None else r_level
    cycle, retract, clearance = _cut_of(p, data, spec.cycle)
    q = in_increments(p, abs(codes.get(CYCLE_Q) or 0.0))
    hole[axis] = initial
    # the steps along the drilling axis in travel (a radius along X), as the clock counts them
    steps = hole_steps(cycle, initial / scale, r_level / scale, bottom / scale, initial / scale, q, retract, clearance)
    at_r, at_bottom = list(hole), list(hole)
    at_r[axis], at_bottom[axis] = r_level, bottom
    unit = INCH if p.modal.get("units") == 20.0 else 1.0
    times = p.times
    feed = codes.get("F") or 0.0
    if spec.lead:  # a tap's F is its lead: per revolution whatever G98/G99 says
        length = times.distance(at_r, at_bottom)
        took = p.feed_seconds(THREAD_MODE, length, feed, at_r, at_bottom, unit)
        rate = length / took * 60.0 if took > 0.0 else 0.0
    else:
        rate = p.cutting_rate(feed, at_r, at_bottom, unit)
    # a rapid's time per program unit along the axis (a diameter along X), the feed's per travel
    steps = [(kind, length * scale if kind == RAPID_STEP else length) for kind, length in steps]
    seconds, cut, rapid = times.cycle_seconds(steps, axis, axis, rate, unit)
    rapid /= scale
    p_word = codes.get(CYCLE_P) or 0.0
    seconds += times.rapid_seconds(start, hole, unit) + (
        times.dwell_seconds({"P": p_word}, None) * cycle.dwells  # at the bottom, a FANUC tap's at R too
    )
    p.clock += seconds
    p.cut_length += cut
    p.rapid_length += rapid + times.distance(start, hole) * unit
    p.pos = list(hole)  # back at the initial level over the hole
    back = tuple(hole)
    record_hole(p, file, line, code, start, (back, tuple(at_r), tuple(at_bottom), back), cycle.feed_out, feed,
                seconds, p.modal.get("plane", 18.0))  # fmt: skip


def _cut_of(p: Planner, data: LatheDrilling, cycle: DrillCycle) -> tuple[DrillCycle, float, float]:
    """How the cycle pecks, and its retract d and clearance (program units): FANUC's from the
    machine file's timing, GSK's from R (J0: a retract of R after each peck; J1: back to the start
    and down to R short of the depth reached)."""
    unit = INCH if p.modal.get("units") == 20.0 else 1.0
    if data.r_point or cycle.cut != SHORT_PECK:
        return cycle, p.times.timing.peck_retract / unit, p.times.timing.peck_clearance / unit
    given = p.codes.get(LATHE_R)
    r = abs(given) if given is not None else data.default_retract / unit
    if p.codes.get(LATHE_J) == 1.0:
        return DrillCycle(cut=PECK, dwell=cycle.dwell), 0.0, r
    return cycle, r, 0.0
