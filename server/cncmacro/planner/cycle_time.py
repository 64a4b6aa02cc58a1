"""Cycle time and path length: the one place that decides how long a move, a dwell, a tool
change and an M code take (docs/semantics.md §9 "Cycle time").

The model, plainly: no acceleration or deceleration, every move at its rate from its first
point to its last; exact stop (G09, G61) and cutting mode (G64) change nothing, because
without acceleration a corner costs no time; feed and rapid overrides at 100 %.

- A rapid (G00, and the moves of G28/G30) moves each axis at its own rapid traverse rate
  (``Timing.rapid``): the move takes as long as its slowest axis, max over the axes of
  distance / rate. That is FANUC's non-linear interpolation positioning, each axis on its
  own, and also the time of linear-interpolation positioning, whose rate is held so that no
  axis passes its own.
- A feed move (G01, G02, G03, G31, a lathe cycle's recorded move) takes its length divided
  by the feed rate; a G31 never faster than the profile's ``Dialect.skip_feed_clamp`` (the
  GSK980TDi's 200 mm/min). The length of an arc is the length of the arc (its sweep times its
  radius, with a helix's third axis added as the other side of a right triangle), not of the
  chord; a full circle is one turn. Feed per minute (G94; G98 on a lathe) is F in mm/min (in/min
  under G20); feed per revolution (G95; G99 on a lathe) is F per turn of the spindle at S
  rev/min. Under G96 (constant surface speed, lathes) the spindle turns at S·1000 / (π·D) at
  each point of the move, D the diameter there, never above the G50 S clamp nor
  ``Timing.max_spindle_speed``: the time is integrated along the move in closed form
  (``per_rev_minutes``). A lathe's thread (``LatheCycles.thread_codes``: G32, G34) moves its
  long axis by the lead F per revolution whatever G98/G99 says; G34's lead grows by its change
  per revolution. A feed move without a feed (F0, or per revolution with S0) takes no time.
- Under G93 (inverse time feed, where the profile's table has it in the feed group) a cut (G01,
  G02, G03) takes 1/F minutes whatever its length (``inverse_time_seconds``), never faster than
  ``top_feed``; F belongs in every such block, and one without is timed at the last F and noted
  (missing_feed.py).
- Lengths are in mm (a G20 program's inches times 25.4; a rotary axis's rapid is timed in degrees
  in either unit, ``inch_scale``); on a lathe X is a diameter, so the tool moves half of an X
  difference. A rotary axis's degrees count as millimetres, as in a FANUC
  feed of a move with rotary axes.
- A mill's drilling cycle (G73, G74, G76, G81–G89) takes the time of its steps
  (``planner/drill_cycles.py`` lists them): the positioning as a rapid, then each rapid and
  feed along the drilling axis and each shift across it (``cycle_seconds``), plus the dwell P.
  Its feed steps count as cut, its rapids as rapid path.
- G04 dwells for X or U seconds, or P times ``Timing.dwell_p_unit`` (milliseconds on FANUC, GSK
  and Haas; a Haas P written with a decimal point counts seconds, which the machine turns into
  P's unit where it compiles the block: ``Timing.dwell_p_point_seconds``).
- A tool change (``Timing.tool_change_code``: M06 on a mill, a lathe's T word) takes
  ``Timing.tool_change_seconds``; any other M code ``Timing.m_code_seconds`` for it, if listed.

``MoveTimes`` holds these rules with the machine's rates worked out once; the machine's clock
(#3001, #3002), ``cncmacro run``'s totals and the editor's code lenses all come from it.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from itertools import pairwise
from math import atan2, dist, hypot, sqrt
from operator import mul, sub
from typing import TYPE_CHECKING

from ..dialects.describe import ROTARY_AXES

if TYPE_CHECKING:
    from ..dialects import Dialect

INCH = 25.4
# the planner's ``codes`` key of the spindle's top speed a lathe's ``G50 S`` sets (G96's clamp)
SPEED_CLAMP = "S-clamp"
# the kinds of a drilling cycle's steps (``cycle_seconds``): a rapid and a feed along the drilling
# axis, and a rapid shift across it (G76, G87)
RAPID_STEP, FEED_STEP, SHIFT_STEP = 0, 1, 2
_TWO_PI = 2.0 * math.pi
# the mode a G31's move is recorded in (probing.py), whose feed the profile may clamp
SKIP_MODE = 31.0
# G93 inverse time feed (a feed-group code): a cut (G01, G02, G03) takes 1/F minutes
INVERSE_TIME = 93.0
INVERSE_TIME_MODES = (1.0, 2.0, 3.0)
# plane code -> (first axis, second axis): the plane an arc turns in (arcs.PLANES)
_PLANE_AXES = {17.0: ("X", "Y"), 18.0: ("Z", "X"), 19.0: ("Y", "Z")}


class MoveTimes:
    """The cycle-time rules (module docstring) for one machine's profile and timing data."""

    def __init__(self, dialect: Dialect) -> None:
        timing = dialect.timing
        self.timing = timing
        axes = dialect.axes
        diameter = axes.index("X") if dialect.lathe and "X" in axes else -1
        self.diameter = diameter
        # how far the tool goes per unit of each axis: half a diameter's change on a lathe's X
        self.scale: tuple[float, ...] | None = (
            tuple(0.5 if i == diameter else 1.0 for i in range(len(axes))) if diameter >= 0 else None
        )
        # seconds per unit moved, per axis, at rapid traverse (in mm)
        self.rapid_seconds_per_mm = tuple(
            60.0 * (0.5 if i == diameter else 1.0) / max(timing.rapid_rate(a), 1e-9) for i, a in enumerate(axes)
        )
        # mm (degrees) per program unit of each axis under G20: a rotary axis stays in degrees
        self.inch_scale = tuple(1.0 if a in ROTARY_AXES else INCH for a in axes)
        # the same seconds per program unit under G20 (``rapid_seconds``)
        self.rapid_seconds_per_inch = tuple(map(mul, self.rapid_seconds_per_mm, self.inch_scale))
        # plane code -> its two axes (indexes) and how far the tool goes per unit of each
        self.planes: dict[float, tuple[int, int, float, float]] = {}
        for code, (a, b) in _PLANE_AXES.items():
            if a in axes and b in axes:
                i, j = axes.index(a), axes.index(b)
                self.planes[code] = (i, j, 0.5 if i == diameter else 1.0, 0.5 if j == diameter else 1.0)
        cycles = dialect.lathe_cycles
        self.thread_modes = cycles.thread_codes
        self.variable_lead = cycles.variable_lead
        self.tool_change_m = float(timing.tool_change_code[1:]) if timing.tool_change_code.startswith("M") else None
        self.tool_change_t = timing.tool_change_code == "T"
        # the machine file's [limits]: the highest cutting feed (mm/min) and, where it gives the
        # spindle's top speed, that speed for every S (not only G96's); infinite without them
        self.top_feed = math.inf
        self.top_speed = math.inf
        # the fastest a skip move goes (mm/min; Dialect.skip_feed_clamp), infinite where it is not clamped
        self.skip_feed = math.inf if dialect.skip_feed_clamp is None else dialect.skip_feed_clamp
        self.helix_on_arc = timing.helix_fed_on_arc  # a helix's length is its arc's (``arc_length``)

    def distance(self, start: Sequence[float], end: Sequence[float]) -> float:
        """The straight distance from ``start`` to ``end``, in program units: on a lathe X moves
        by half its difference (a diameter), so three quarters of its square come off."""
        d = self.diameter
        if d < 0:
            return dist(start, end)
        full = dist(start, end)
        dx = end[d] - start[d]
        return sqrt(max(full * full - 0.75 * dx * dx, 0.0))

    def rapid_seconds(self, start: Sequence[float], end: Sequence[float], unit: float) -> float:
        """Seconds a rapid takes: its slowest axis's (``unit`` is 25.4 under G20, else 1; a
        rotary axis's degrees are degrees in either unit, ``inch_scale``). A machine has an axis
        at least, so ``max`` always has a value to take."""
        per_unit = self.rapid_seconds_per_mm if unit == 1.0 else self.rapid_seconds_per_inch
        slowest: float = max(map(mul, map(abs, map(sub, end, start)), per_unit))
        return slowest

    def arc_length(
        self, mode: float, plane: float, start: Sequence[float], end: Sequence[float], centre: Sequence[float]
    ) -> float:
        """The length of a G02 (``mode`` 2) or G03 arc from ``start`` to ``end`` about ``centre``
        in ``plane`` (17, 18, 19), a helix's third axis included (but where the profile feeds a
        helix along its arc in the plane, ``Timing.helix_fed_on_arc``: the arc's); program units."""
        axes = self.planes.get(plane)
        if axes is None:
            return self.distance(start, end)
        a, b, ka, kb = axes
        sa, sb = (start[a] - centre[a]) * ka, (start[b] - centre[b]) * kb
        ea, eb = (end[a] - centre[a]) * ka, (end[b] - centre[b]) * kb
        r = 0.5 * (hypot(sa, sb) + hypot(ea, eb))
        if r == 0.0:
            return self.distance(start, end)
        sweep = (atan2(eb, ea) - atan2(sb, sa)) % _TWO_PI  # counterclockwise
        if mode == 2.0:
            sweep = (_TWO_PI - sweep) % _TWO_PI
        if sweep == 0.0 and start[a] == end[a] and start[b] == end[b]:
            sweep = _TWO_PI  # I, J, K back to the start: a full circle
        arc = r * sweep
        if self.helix_on_arc:
            return arc
        # a helix: the move off the plane is the other side of a right triangle
        da, db = (end[a] - start[a]) * ka, (end[b] - start[b]) * kb
        off = (dist(start, end) if self.scale is None else self.distance(start, end)) ** 2 - da * da - db * db
        return sqrt(arc * arc + off) if off > 1e-12 else arc

    def long_axis(self, start: Sequence[float], end: Sequence[float]) -> float:
        """How far a thread's long axis moves from ``start`` to ``end`` (X by its radius): the
        axis its lead is measured along."""
        scale = self.scale
        if scale is None:
            return max(map(abs, map(sub, end, start)), default=0.0)
        return max(map(mul, map(abs, map(sub, end, start)), scale), default=0.0)

    def feed_seconds(self, mode: float, length: float, feed: float, per_rev: bool, speed: float, css: bool,
                     clamp: float | None, start: Sequence[float], end: Sequence[float], unit: float,
                     lead_change: float = 0.0) -> float:  # fmt: skip
        """Seconds of a cutting move in ``mode`` of ``length`` (program units) at ``feed``: per
        minute, or per revolution at spindle ``speed`` (S; under ``css`` a surface speed, the
        spindle clamped at ``clamp``, ``G50 S``). A thread's (``thread_modes``) is per revolution,
        along its long axis, its lead growing by ``lead_change`` per revolution (G34). A skip
        move (``SKIP_MODE``) goes at ``skip_feed`` at most, where its rate is the same all along."""
        thread = mode in self.thread_modes
        if thread:
            length = self.long_axis(start, end)
            if lead_change and length > 0.0 and feed > 0.0:
                feed = _mean_lead(length, feed, lead_change)
        else:
            top = self.top_feed
            if mode == SKIP_MODE and self.skip_feed < top:
                top = self.skip_feed
            rate = self.straight_rate(feed, per_rev, speed, css, unit, top)
            if rate is not None:
                return length / rate * 60.0 if rate > 0.0 and length > 0.0 else 0.0
        return self.per_rev_minutes(length, feed, speed, css, clamp, start, end, unit, not thread) * 60.0

    def inverse_time_seconds(self, feed: float, length: float = 0.0) -> float:
        """A cut's seconds under G93 (inverse time feed): 1/F minutes whatever its length, an
        arc's too (Haas: "60 (seconds) divided by the F value"); none at F0. A cut ``length`` mm
        long that 1/F minutes would move faster than ``top_feed`` goes at ``top_feed``: the control
        clamps the feed it works out as any other."""
        if feed <= 0.0:
            return 0.0
        return max(60.0 / feed, length / self.top_feed * 60.0)

    def straight_rate(
        self, feed: float, per_rev: bool, speed: float, css: bool, unit: float = 1.0, top: float | None = None
    ) -> float | None:
        """How fast a cutting move that is not a thread goes, in program units per minute, where
        that is the same all along it: F per minute, or F per revolution times S (S never above
        ``top_speed``), never above ``top`` (mm/min; ``top_feed`` unless given; ``unit`` is 25.4
        under G20, else 1): the control clamps both. 0 where it does not move (no feed, or per revolution at S0);
        None under G96 on a lathe, where the rate follows the diameter (``per_rev_minutes``)."""
        if not per_rev:
            rate = feed if feed > 0.0 else 0.0
        elif css and self.diameter >= 0:
            return None
        else:
            rate = feed * min(speed, self.top_speed) if feed > 0.0 and speed > 0.0 else 0.0
        if top is None:
            top = self.top_feed
        if rate * unit > top:  # the control clamps the feed at its highest
            rate = top / unit
        return rate

    def per_rev_minutes(self, length: float, feed: float, speed: float, css: bool, clamp: float | None,
                        start: Sequence[float], end: Sequence[float], unit: float,
                        feed_clamp: bool = True) -> float:  # fmt: skip
        """Minutes to move ``length`` at ``feed`` per revolution. At a constant ``speed``,
        length / (F·S), S never above ``top_speed`` and F·S never above ``top_feed`` (a thread's,
        without ``feed_clamp``, follows the spindle whatever its rate).
        Under G96 (``css``) the spindle turns at 1000·V / (π·D) (V = S in m/min; in ft/min
        under G20, 304.8·V), D the
        diameter where the tool is, never above ``clamp`` and the spindle's top speed: over a
        straight move D changes linearly, so dt = dl·π·D / (1000·V·F) integrates to the piece's
        length times its mean diameter where the spindle is not clamped, and to length / (F·top)
        where it is; the move is cut where |D| passes 0 or the clamp's diameter. Where F × rpm
        would pass ``top_feed`` (not a thread's, without ``feed_clamp``) the tool moves at
        ``top_feed``: the same as a spindle clamped at ``top_feed`` / F, so that speed is the clamp
        where it is the lower."""
        if feed <= 0.0 or length <= 0.0:
            return 0.0
        d = self.diameter
        if not css or d < 0:
            if speed <= 0.0:
                return 0.0
            rate = feed * min(speed, self.top_speed)  # the spindle at its top speed at most
            if feed_clamp and rate * unit > self.top_feed:  # the control clamps the feed at its highest
                rate = self.top_feed / unit
            return length / rate
        top = self.timing.max_spindle_speed if clamp is None else min(clamp, self.timing.max_spindle_speed)
        if feed_clamp and feed * top * unit > self.top_feed:
            # F x rpm never above the highest cutting feed: where it would be, the tool moves as if
            # the spindle turned at top_feed / F (the control clamps the feed, not the spindle)
            top = self.top_feed / (feed * unit)
        if speed <= 0.0 or top <= 0.0:
            return 0.0
        x0, x1 = start[d] * unit, end[d] * unit  # diameters, mm
        # rev/min times the diameter (mm) at surface speed S: m/min, ft/min under G20 (304.8 mm)
        surface = (304.8 if unit != 1.0 else 1000.0) * speed / math.pi
        knee = surface / top  # below this diameter the spindle turns at its top speed
        cuts = sorted({0.0, 1.0, *(t for v in (0.0, knee, -knee) if (t := _crossing(x0, x1, v)) is not None)})
        minutes = 0.0
        for a, b in pairwise(cuts):
            mean = 0.5 * (abs(x0 + (x1 - x0) * a) + abs(x0 + (x1 - x0) * b))
            piece = length * (b - a)
            minutes += piece / (feed * top) if mean <= knee else piece * mean / (feed * surface)
        return minutes

    def cycle_seconds(
        self, steps: Sequence[tuple[int, float]], drill_axis: int, shift_axis: int, rate: float, unit: float
    ) -> tuple[float, float, float]:
        """The seconds, cut (mm) and rapid path (mm) of a drilling cycle's ``steps`` (kind, length
        in program units): a feed step at ``rate`` (program units per minute; none when 0), a
        rapid along ``drill_axis`` or a shift along ``shift_axis`` at that axis's rapid rate."""
        seconds = cut = rapid = 0.0
        per_mm = self.rapid_seconds_per_mm
        for kind, length in steps:
            if kind == FEED_STEP:
                cut += length
                if rate > 0:
                    seconds += length / rate * 60.0
            else:
                rapid += length
                seconds += length * unit * per_mm[drill_axis if kind == RAPID_STEP else shift_axis]
        return seconds, cut * unit, rapid * unit

    def dwell_seconds(self, words: dict[str, float], axis_value: float | None) -> float:
        """G04's time: P in the profile's unit, else X (or U) in seconds."""
        p = words.get("P")
        if p is not None:
            return max(0.0, p * self.timing.dwell_p_unit)
        return max(0.0, axis_value or 0.0)

    def m_seconds(self, m: float) -> float:
        """The time of M code ``m`` (a tool change's when it is the tool change code)."""
        if m == self.tool_change_m:
            return self.timing.tool_change_seconds
        return self.timing.m_code_seconds.get(m, 0.0)


def _crossing(x0: float, x1: float, v: float) -> float | None:
    """Where (0 to 1) a straight move from ``x0`` to ``x1`` passes ``v``, if strictly inside."""
    if (x0 - v) * (x1 - v) < 0.0:
        return (v - x0) / (x1 - x0)
    return None


def _mean_lead(length: float, lead: float, change: float) -> float:
    """The mean lead of a variable-lead thread ``length`` long that starts at ``lead`` and grows
    by ``change`` per revolution: after N turns it has gone F·N + K·N²/2, so N = (√(F² + 2·K·L)
    − F) / K; a lead that would shrink below zero first keeps ``lead``."""
    root = lead * lead + 2.0 * change * length
    if root < 0.0:
        return lead
    turns = (math.sqrt(root) - lead) / change
    return length / turns if turns > 0.0 else lead
