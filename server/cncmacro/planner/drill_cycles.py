"""A mill's drilling canned cycle (G73, G74, G76, G81–G89) hole by hole: where the tool goes, which
of its moves are rapids and which cut, and so how long a hole takes (docs/semantics.md §9
"Canned cycles").

A block in a drilling cycle with an axis word drills one hole, or K holes (L on Haas: the
profile's ``cycle_repeat_letter``), each in five phases, as FANUC's operator's manuals describe
them:

1. position X and Y (and any other axis but Z) at rapid, at the level the tool is at;
2. rapid to the R point;
3. cut from R to Z at F: in one feed, or for G83 and G73 in pecks of Q (``_cut``);
4. dwell P at the bottom where the cycle does (``DrillCycle.dwell``), and, for FANUC's taps, again
   at R on the way out (``DrillCycle.dwell_at_r``);
5. come back: G98 to the initial level, G99 to R; at rapid, or for tapping and feed-out boring
   at F up to R (then at rapid to the initial level under G98). Fine boring shifts by Q at the
   bottom before it rapids out and back after; back boring (G87) has its own order.

The hole data Z, R, Q and P stay in force from the cycle block that last gave them (the
control keeps them while the cycle is in force; a program names them again after G80, but for
FANUC's Q and, where the control resets it, P: block_words.py ``cycle_named``). Under
G90 R and Z are levels; under G91 R is the distance from the initial level to R and Z the
distance from R to the bottom. The initial level is the Z where the tool was when the canned
cycle mode began, after G80 or a G00-G03 (``Planner.cycle_start_z``; another cycle named with
no G80 between keeps it: block_words.py ``cycle_named``). Each repetition of K under G91 moves on
by the block's X and Y; under G90 it drills the same hole again; K0 keeps the data and drills
nothing. The drilling axis is Z. On FANUC (``Dialect.peck_q_alarm``) a G73/G83 hole with no Q in
force, or Q0, is alarm PS0045, and a cycle named after G80 starts with no Q (block_words.py).

The recorded move is one per hole, from where the tool was to the hole's bottom, its time the
sum of the phases' (``MoveTimes.cycle_seconds``), its feed steps added to the cut path and its
rapids to the rapid path, and its legs the path drawn (``hole_legs``); the tool ends at the
return level.
"""

from __future__ import annotations

from math import ceil, floor
from typing import TYPE_CHECKING

from ..bilingual import detail
from ..dialects.alarms import ARGUMENT_RANGE, PECK_Q_MISSING
from ..dialects.drill_cycles import PECK, PLAIN_DRILLING, SHORT_PECK, DrillCycle
from .alarms import MacroAlarm
from .cycle_time import FEED_STEP, INCH, RAPID_STEP, SHIFT_STEP
from .machine_limits import leaves_travel, program_bounds
from .moves import DRILLING, Leg, Move
from .whereabouts import placed

if TYPE_CHECKING:
    from .planner import Planner

# the hole data a drilling cycle keeps in ``Planner.codes`` (R under "R")
CYCLE_Z = "cycle Z"
CYCLE_Q = "cycle Q"
CYCLE_P = "cycle P"
# set where Z, R were given in the canned cycle mode in force (block_words.py ``cycle_named``)
Z_GIVEN = "cycle Z given"
R_GIVEN = "cycle R given"
MAX_REPEATS = 9999

Steps = list[tuple[int, float]]


def drill_block(
    m: Planner, cycle: float, axes: dict[int, float], incremental: dict[int, float], other: dict[str, float],
    file: str, line: int,
) -> None:  # fmt: skip
    """Drill the holes of one block in canned cycle ``cycle`` (module docstring)."""
    codes = m.codes
    for letter, key in (("R", "R"), ("Q", CYCLE_Q), ("P", CYCLE_P)):
        if letter in other:
            codes[key] = other[letter]
    z = m.axis_index.get("Z")
    plane = {i: v for i, v in axes.items() if i != z}
    if z is not None and z in axes:
        codes[CYCLE_Z] = axes[z]
    if m.dialect.peck_q_alarm:  # FANUC clears the hole data at G80 and G00-G03
        _cleared_data(m, cycle, "R" in other, z is not None and z in axes, line)
    repeats = repeat_count(other.get(m.dialect.cycle_repeat_letter), m.dialect.cycle_repeat_letter)
    absolute = m.modal.get("distance", 90.0) == 90.0
    if z is None:  # no drilling axis: the holes are only positioned
        for _ in range(repeats):
            m.move(file, line, 0.0, m.target(plane, incremental))
        if repeats and absolute:
            placed(m, plane)  # whereabouts.py
        return
    if m.cycle_start_z is None:
        m.cycle_start_z = m.pos[z]
    initial = m.cycle_start_z
    r_word, z_word = codes.get("R"), codes.get(CYCLE_Z)
    r_level = initial if r_word is None else r_word if absolute else initial + r_word
    bottom = r_level if z_word is None else z_word if absolute else r_level + z_word
    spec = m.dialect.drill_cycles.get(cycle, PLAIN_DRILLING)
    if spec.cut in (PECK, SHORT_PECK) and m.dialect.peck_q_alarm and not codes.get(CYCLE_Q):
        raise _no_peck(cycle, codes.get(CYCLE_Q))
    to_initial = spec.back or m.modal.get("return") == 98.0
    back_to = initial if to_initial else r_level
    times = m.times
    unit = INCH if m.modal.get("units") == 20.0 else 1.0
    q = abs(codes.get(CYCLE_Q) or 0.0)
    p = codes.get(CYCLE_P) or 0.0
    dwell = times.dwell_seconds({"P": p}, None) * spec.dwells if p else 0.0  # at the bottom, a tap's at R
    retract, clearance = times.timing.peck_retract / unit, times.timing.peck_clearance / unit
    shift_axis = m.axis_index.get("X", 0)
    feed = m.codes.get("F") or 0.0
    for _ in range(repeats):
        start = tuple(m.pos)
        hole = m.target(plane, incremental)  # positioned at the level the tool is at
        at_r, at_bottom = list(hole), list(hole)
        at_r[z], at_bottom[z] = r_level, bottom
        steps = hole_steps(spec, hole[z], r_level, bottom, back_to, q, retract, clearance)
        rate = m.cutting_rate(feed, at_r, at_bottom, unit)
        seconds, cut, rapid = times.cycle_seconds(steps, z, shift_axis, rate, unit)
        seconds += times.rapid_seconds(start, hole, unit) + dwell
        m.clock += seconds
        m.cut_length += cut
        m.rapid_length += rapid + times.distance(start, hole) * unit
        hole_at = tuple(hole)
        hole[z] = back_to
        record_hole(m, file, line, cycle, start, (hole_at, tuple(at_r), tuple(at_bottom), tuple(hole)),
                    spec.feed_out, feed, seconds, m.modal.get("plane", 17.0))  # fmt: skip
        m.pos = hole
    if repeats and absolute:  # the holes' absolute X, Y, and the R level it stops at (whereabouts.py)
        placed(m, [*plane, z] if r_word is not None and not to_initial else plane)


def _cleared_data(m: Planner, cycle: float, r_given: bool, z_given: bool, line: int) -> None:
    """A ``cycle-block`` warning, once a canned cycle mode, where a hole drills to a Z or from an R
    given before the G80 or G00-G03 that began the mode: FANUC clears the hole data there (the
    operator's manuals, "canned cycle for drilling"), so the control does not use them, while the
    run keeps them (docs/semantics.md §9, "Hole data")."""
    codes = m.codes
    if r_given:
        codes[R_GIVEN] = 1.0
    if z_given:
        codes[Z_GIVEN] = 1.0
    old = [letter for letter, key, given in (("Z", CYCLE_Z, Z_GIVEN), ("R", "R", R_GIVEN))
           if key in codes and given not in codes]  # fmt: skip
    if not old:
        return
    codes[Z_GIVEN] = codes[R_GIVEN] = 1.0
    words, was, it = (" and ".join(old), "were", "them") if len(old) > 1 else (old[0], "was", "it")
    g = f"G{cycle:g}"
    m.host.note("cycle", detail(
        f"{g}: the {words} in force {was} given before the G80 or G00-G03 that ended the last canned cycle mode; "
        f"FANUC clears the hole data there, so the control does not drill by {it} as the run does (the cycle "
        f"time uses {it}): give {words} again in this canned cycle mode",
        f"{g}：当前的 {'、'.join(old)} 是在结束上一个固定循环方式的 G80 或 G00-G03 之前指令的；FANUC 在此清除孔加工"
        f"数据，控制器不会像本次运行这样按它钻孔（加工时间按它计算）：请在本固定循环方式中重新指令 {'、'.join(old)}"),
        line, "cycle-block")  # fmt: skip


def _no_peck(cycle: float, q: float | None) -> MacroAlarm:
    """FANUC's PS0045 "ADDRESS Q NOT FOUND (G73/G83)": "the amount of each-time cutting is not
    specified by address Q, or Q0 is specified" (``Dialect.peck_q_alarm``)."""
    g = f"G{cycle:g}"
    if q is None:
        return MacroAlarm(PECK_Q_MISSING, detail(
            f"{g}: no Q, the depth of each peck, in force in this canned cycle mode",
            f"{g}：本固定循环方式中没有指令每次切深 Q"))  # fmt: skip
    return MacroAlarm(PECK_Q_MISSING, detail(f"{g}: Q0, a peck of no depth", f"{g}：Q0，每次切深为零"))


def record_hole(
    m: Planner, file: str, line: int, cycle: float, start: tuple[float, ...],
    points: tuple[tuple[float, ...], tuple[float, ...], tuple[float, ...], tuple[float, ...]],
    feed_out: bool, feed: float, seconds: float, plane: float,
) -> None:  # fmt: skip
    """Record a hole of ``cycle`` as one move from ``start`` to its bottom, with its ``seconds``
    and the legs it is drawn by (``points``: positioned, at R, at the bottom, back: ``hole_legs``),
    a mill's or a lathe's (lathe_drilling.py); the machine's soft limits (machine_limits.py) stop
    the run on it, the hole drawn whole."""
    if not m.record_moves and m.travel is None:
        return
    positioned, at_r, bottom, back = points
    legs = hole_legs(positioned, at_r, bottom, back, feed_out)
    stop = None
    if m.travel is not None:
        stop = leaves_travel(m, program_bounds(m), cycle, plane, start, bottom, None, legs)
    if m.record_moves:
        m.moves.append(Move(file, line, cycle, start, bottom, float(feed), None, seconds, plane, legs, DRILLING))
        if len(m.moves) >= m.move_budget:
            m.moves_full(line)
    if stop is not None:
        raise stop[1]


def hole_legs(
    positioned: tuple[float, ...], at_r: tuple[float, ...], bottom: tuple[float, ...], back: tuple[float, ...],
    feed_out: bool,
) -> tuple[Leg, ...]:  # fmt: skip
    """The legs a hole is drawn by: positioning at rapid, rapid to R, the cut to the bottom (the
    pecks are not drawn one by one), and the way out to the return level: at rapid, or for
    tapping and feed-out boring at the feed to R and then at rapid. Back boring's R point lies
    below the work and its cut goes up, which the same legs draw."""
    out = (Leg(False, at_r), Leg(True, back)) if feed_out else (Leg(True, back),)
    return (Leg(True, positioned), Leg(True, at_r), Leg(False, bottom), *out)


def repeat_count(k: float | None, letter: str) -> int:
    """How many times a cycle block drills: its K (L), 1 when absent; 0 to 9999."""
    if k is None:
        return 1
    if not 0 <= k <= MAX_REPEATS:
        raise MacroAlarm(
            ARGUMENT_RANGE,
            detail(
                f"{letter}{k:g}: a canned cycle's repeat count must be 0 to {MAX_REPEATS}",
                f"{letter}{k:g}：固定循环的重复次数必须在 0～{MAX_REPEATS} 之间",
            ),
        )
    return int(k)


def hole_steps(
    spec: DrillCycle, level: float, r_level: float, bottom: float, back_to: float, q: float, retract: float,
    clearance: float,
) -> Steps:  # fmt: skip
    """The steps of one hole after positioning (``MoveTimes.cycle_seconds``'s kinds and lengths
    in program units), from ``level`` through ``r_level`` to ``bottom`` and back to ``back_to``;
    ``q`` is the peck depth or the shift, ``retract`` and ``clearance`` G73's and G83's d."""
    depth = abs(bottom - r_level)
    if spec.back:  # G87: shift, down to R below the work, shift back, bore up, shift, out, back
        return [(SHIFT_STEP, 2.0 * q), (RAPID_STEP, abs(level - r_level)), (FEED_STEP, depth),
                (SHIFT_STEP, 2.0 * q), (RAPID_STEP, abs(bottom - back_to))]  # fmt: skip
    steps: Steps = [(RAPID_STEP, abs(level - r_level)), *_cut(spec.cut, depth, q, retract, clearance)]
    if spec.shift:  # G76: shift off the wall at the bottom and back at the top
        steps.append((SHIFT_STEP, 2.0 * q))
    if spec.feed_out:
        steps += [(FEED_STEP, depth), (RAPID_STEP, abs(r_level - back_to))]
    else:
        steps.append((RAPID_STEP, abs(bottom - back_to)))
    return steps


def _cut(kind: str, depth: float, q: float, retract: float, clearance: float) -> Steps:
    """The cut from R to the bottom: one feed, or n = ⌈depth / Q⌉ pecks (the last one shorter).
    G73 after each peck but the last rapids up d and feeds d + Q; G83 rapids up to R, rapids
    down to d above the depth reached and feeds d + Q (d no more than the depth reached). The
    totals of each kind are summed here, without a loop over the pecks."""
    if kind not in (PECK, SHORT_PECK) or q <= 0.0 or depth <= q:
        return [(FEED_STEP, depth)]
    again = ceil(round(depth / q, 9)) - 1  # pecks after the first
    if kind == SHORT_PECK:
        return [(FEED_STEP, depth + again * retract), (RAPID_STEP, again * retract)]
    # the depths reached before each later peck: q, 2q, ... again·q; d caps at the depth reached
    reached = q * again * (again + 1) / 2.0
    under = min(again, floor(clearance / q))  # pecks whose depth reached is within d
    backs = q * under * (under + 1) / 2.0 + (again - under) * clearance  # Σ min(d, depth reached)
    return [(FEED_STEP, depth + backs), (RAPID_STEP, 2.0 * reached - backs)]
