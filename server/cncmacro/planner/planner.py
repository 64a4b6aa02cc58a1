"""The motion planner: the NC side of the control (docs/semantics.md §8, §9; ARCHITECTURE.md,
"The motion planner").

The macro machine (machine/) hands the planner each NC block with its words evaluated:
``execute_nc`` for any block, ``run_plain`` for a plain motion line decided once
(plain_words.py). The planner owns the modal state (groups, units, plane, distance and feed
mode), F, S, T, M, D, H, positions, work and tool offsets and coordinate setting, the cycles
(drilling: drill_cycles.py; turning: turning_cycles.py), the skip function (probing.py), the
one-shot codes (one_shot.py) and the time model (cycle_time.py). It emits the one stream of
moves every front end reads (``moves``, moves.py): rapid, feed, arc (with its plane and
centre), probe and cycle moves, each with its source block, feed and time, and the tool
changes (``tool_changes``). The system variables that read its state (#4001…, #4101…, #5001…,
#5021…, #3001) ask ``read``. It imports nothing of the macro machine: what it needs of it (the
offset tables, a tool change, a remark) goes through ``PlannerHost`` (host.py).
Values arrive already rounded to their address's increment.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

from ..bilingual import Detail, detail
from .angled_moves import (
    DRAWING_ANGLE,
    PENDING_ANGLE,
    PENDING_LINE,
    angled_end,
    corner_point,
    one_axis_fault,
    two_line_fault,
)
from .arc_checks import arc_finding, no_centre
from .arcs import ARC_MODES, arc_centre, arc_fault, arc_planes
from .block_words import set_codes, set_modal
from .conic_moves import CURVE_FAULT, conic_points
from .corner_stage import HeldCorner, corner_without_move, corner_word, hold_corner, restore_corner, take_corner
from .cutter_stage import (
    UNCOMPENSATED_CODES,
    CutterStage,
    centre_travel,
    cutter_move,
    restore_pending,
    skip_in_offset,
    uncompensated,
)
from .cycle_time import INCH, INVERSE_TIME, INVERSE_TIME_MODES, SPEED_CLAMP, MoveTimes
from .drill_cycles import drill_block
from .lathe_cycles import ShapeCall, ShapeReading
from .lathe_drilling import lathe_drill_block
from .machine_limits import leaves_travel, program_bounds, spindle_speed
from .missing_feed import inverse_time_cut, note_missing_feed
from .modal_groups import extra_offset_codes, g_code_groups
from .moves import TURNING, Leg, Move, ToolChange
from .offset_travel import travel_start
from .one_shot import one_shot
from .plain_words import VALUE_GROUPS, PlainRun, shared_plain_words
from .positions import position_value
from .probing import Probe, SkipState
from .state import MODAL_DEFAULTS, PlannerState
from .three_point_arcs import three_point_arc
from .turning_cycles import forget_single_cycle, in_increments, single_cycle, single_cycle_target, turning_legs
from .variable_leads import lead_alarm
from .virtual_planes import CYLINDER, VIRTUAL_PLANE, surface_length
from .whereabouts import START, Whereabouts, astray, placed, unknown_ends

if TYPE_CHECKING:
    from ..dialects import Dialect
    from ..library.machine_file import MachineSettings
    from .host import PlannerHost

_new_move = tuple.__new__  # a Move without the NamedTuple constructor's keyword handling
# The moves a run keeps for its toolpath (about 200 bytes each): a drilling cycle's K repeat makes
# 9,999 moves of one block, so a short program can make millions. Beyond it the run, its clock and
# its path go on to the end; only the toolpath stops growing (``moves_full``).
MOVE_BUDGET = 1_000_000
# the ``codes`` key set once a run has been told that its per-minute feed looks per revolution
FEED_HINT_GIVEN = "G99-hint"


class Planner:
    """The NC side of one simulated control (module docstring)."""

    at_line: int = 0  # the line of the block being carried out (a cut with no feed is said there)
    cycle_passes: int = 0  # passes the lathe cycles made (``cycle_passes.record_passes``): the work they cost
    # the tool vector before a change the machine has not travelled yet (offset_travel.py), else None
    vector_before: list[float] | None = None
    block_feed: bool = False  # whether that block writes F (G93 takes one in every cut: missing_feed.py)
    whereabouts: Whereabouts = START  # what the run knows of where the machine is (whereabouts.py)
    # the drawn axes astray when the block began, and where the tool was then (whereabouts.py, ``astray``):
    # a move of the block that travels one from there starts at an unknown place (``Move.unknown``)
    block_astray: frozenset[int] = frozenset()
    block_start: tuple[float, ...] = ()
    drawn_axes: frozenset[int] | None = None  # the axes the toolpath view draws (whereabouts.py, ``drawn_axes``)
    block_corner: str | None = None  # a block's ,C or ,R (its letter) while it runs (machine/corners.py)
    block_corner_value: float | None = None  # and its value (None: vacant)
    corner: HeldCorner | None = None  # a move whose chamfer or rounding waits for the next (corner_stage.py)
    # where the last chamfer or rounding cut ended, and the seconds and cut length it added (the same)
    corner_end: tuple[float, ...] | None = None
    corner_cost: tuple[float, float] = (0.0, 0.0)
    # the moves an alarm found reading ahead took back (cutter_stage.py, ``_withdraw``): from which
    # place, how many moves were left, and those taken: a snapshot taken before the alarm and
    # restored gets them again
    withdrawn: tuple[int, int, list[Move]] | None = None

    def __init__(self, dialect: Dialect, settings: MachineSettings, host: PlannerHost) -> None:
        self.dialect = dialect
        self.settings = settings
        self.host = host
        axes = dialect.axes
        self.axis_index = {a: i for i, a in enumerate(axes)}
        self.pos: list[float] = [0.0] * len(axes)
        self.shift: list[float] = [0.0] * len(axes)
        self.skip_pos: list[float] = [0.0] * len(axes)
        self.skip_state = SkipState()  # the contact points used (probing.py)
        self.probes: list[Probe] = []
        self.tool_vector: list[float] = [0.0] * len(axes)
        self.modal: dict[str, float] = {**MODAL_DEFAULTS, **dialect.modal_defaults}
        self.codes: dict[str, float | None] = {}
        self.extra_wcs = 0  # G54.1 Pn (G154 Pn, G110-G129)
        self.cycle_start_z: float | None = None
        self.cycle_params: dict[float, dict[str, float]] = {}  # a lathe cycle's first block (lathe_cycles.py)
        self.shape: ShapeReading | None = None  # the shape cycle under way
        self.cutter: CutterStage | None = None  # cutter radius compensation under way (cutter_stage.py)
        self.moves: list[Move] = []
        self.record_moves = True
        # whether a recorded move carries its tool centre path under cutter radius compensation
        # (``Move.tool_path``): a view that shows only the programmed moves and the totals
        # (``cncmacro run``'s text) leaves them out; the clock, the lengths and the findings are
        # the same either way
        self.centre_paths = True
        self.move_budget = MOVE_BUDGET
        self.moves_cut = False  # the toolpath reached ``move_budget`` and keeps no more moves
        # the cycle time's rules (cycle_time.py), the clock (#3001), the path so far (mm) and,
        # while moves are recorded, the tool changes (``cncmacro run``'s totals per tool)
        self.times = MoveTimes(dialect)
        self.clock = 0.0
        self.cut_length = 0.0
        self.rapid_length = 0.0
        self.tool_changes: list[ToolChange] = []
        self.g_groups = g_code_groups(dialect)
        self.extra_codes = extra_offset_codes(dialect)
        if self.extra_codes:  # the switch makes them work offset codes, whatever the table says
            self.g_groups = {**self.g_groups, **dict.fromkeys(self.extra_codes, "wcs")}
        self.plain = shared_plain_words(dialect, settings, self.g_groups, self.axis_index)
        self.cycle_codes = dialect.cycle_codes
        self.block_angle: float | None = None  # a block's ,A, while it runs (machine/corners.py)
        # the G codes whose blocks' axis words are values (G22's limits, G68's centre: VALUE_GROUPS)
        self._value_codes = frozenset(g for g, group in self.g_groups.items() if group in VALUE_GROUPS)
        tpi = dialect.lathe_cycles.threads_per_inch is not None
        self._values_in_block = bool(dialect.motion_value_letters) or tpi
        self._three_points = dialect.three_point_arcs
        self._curves = frozenset((*dialect.three_point_arcs, *dialect.conic_moves))  # ``_curve``'s
        # the motion modes whose moves a plain line cannot make: a variable-lead thread (its own
        # word), a three-point arc, an ellipse or a parabola (their own words), a thread where I
        # may give its threads per inch: ``execute_nc``'s
        self.own_path_modes = frozenset(
            (*self.times.variable_lead, *dialect.three_point_arcs, *dialect.motion_value_letters,
             *(self.times.thread_modes if tpi else ()))
        )  # fmt: skip
        self.lathe = dialect.lathe
        self.drills = dialect.drills  # a canned drilling cycle in force decides a move (Dialect.drills)
        self._call_needs_distance = dialect.modal_call_needs_distance
        self._call_codes = dialect.modal_call_codes  # None: any move command calls (G66)
        self._motion_numbers = dialect.motion_numbers
        self._arc_planes = arc_planes(self.axis_index)
        self._diameter = self.axis_index.get("X", -1) if self.lathe else -1
        # the arc radius tolerance in mm (FANUC parameter 3410; the machine file's ``arc_tolerance``)
        self.arc_tolerance = settings.arc_tolerance
        self._incremental_names = {v: k for k, v in dialect.incremental_letters.items()}  # X -> U on a lathe
        # a lathe that powers on in G98 (per minute): a cutting F below 1 there lacks a G99
        self.feed_hint = self.lathe and dialect.modal_defaults.get("feed") == 98.0
        # the machine file's [limits] (machine_limits.py): the travel of each limited axis of this
        # machine by index (mm, machine coordinates), the spindle's top speed where it is the
        # machine's own, and the feed and speed clamps of the time; None and infinite without them
        limits = settings.limits
        self.travel: tuple[tuple[int, float, float], ...] | None = None
        self.spindle_top: float | None = None
        if limits is not None:
            travel = tuple(
                (self.axis_index[a], lo, hi) for a, (lo, hi) in limits.travel.items() if a in self.axis_index
            )
            self.travel = travel or None
            self.spindle_top = limits.spindle
            self.times.top_feed = limits.feed or math.inf
            self.times.top_speed = limits.spindle or math.inf

    # ---------------------------------------------------------------- state for the macro machine
    def read(self, source: str, param: str, default: float | None, index: int) -> float | None:
        """A system variable of the planner's state (the profile's row ``source`` and ``param``):
        a modal group's code, a code's last value, or axis ``index``'s position of a kind."""
        if source == "modal":
            code = self.modal.get(param, default)
            if param == "motion" and code in self._motion_numbers:  # G6.2 reads 124 (Dialect.motion_numbers)
                return self._motion_numbers[code]
            return code
        if source == "code":
            if param == "P":  # #4130: the extra work offset in force (G54.1 Pn reads n), else the default
                wcs = self.modal.get("wcs")
                return float(self.extra_wcs) if self.extra_wcs and (wcs == 54.1 or wcs in self.extra_codes) else default
            return self.codes.get(param, default)
        value = position_value(self, param, index)
        # a position summed from offsets (machine 0 after G28 read back through the work offset and the
        # tool's) carries the last bits of the sums: 8.9e-16 where the control reads 0, which made a
        # shop's home check `IF [#5023 NE 0]` reach its alarm. Positions are whole increments on the
        # control: rounded to 1e-9 of the unit, the noise goes and no increment is touched
        return None if value is None else round(value, 9) + 0.0

    def snapshot(self) -> PlannerState:
        return PlannerState(
            dict(self.modal), dict(self.codes),
            (list(self.pos), list(self.shift), list(self.skip_pos), list(self.tool_vector)), self.extra_wcs,
            self.cycle_start_z, self.clock, (self.cut_length, self.rapid_length), len(self.moves),
            len(self.tool_changes), self.skip_state, len(self.probes),
            {k: dict(v) for k, v in self.cycle_params.items()}, None if self.shape is None else self.shape.copy(),
            None if self.cutter is None else self.cutter.copy(),
            None if self.vector_before is None else list(self.vector_before), self.whereabouts, self.corner,
        )  # fmt: skip

    def restore(self, state: PlannerState) -> None:
        self.modal = dict(state.modal)
        self.codes = dict(state.codes)
        pos, shift, skip, tool = state.positions
        self.pos, self.shift, self.skip_pos, self.tool_vector = list(pos), list(shift), list(skip), list(tool)
        self.extra_wcs = state.extra_wcs
        self.cycle_start_z = state.cycle_start_z
        self.clock = state.clock
        self.cut_length, self.rapid_length = state.lengths
        withdrawn, self.withdrawn = self.withdrawn, None
        if withdrawn is not None and withdrawn[1] == len(self.moves) and withdrawn[0] < state.moves:
            del self.moves[withdrawn[0] :]  # back to before an alarm took them (or cut the last one short)
            self.moves.extend(withdrawn[2])
        del self.moves[state.moves :]
        if self.moves_cut and len(self.moves) < self.move_budget:  # taken back to before the toolpath filled
            self.moves_cut = False
            self.record_moves = True
        del self.tool_changes[state.tool_count :]
        self.skip_state = state.skip_state
        del self.probes[state.probes :]
        self.cycle_params = {k: dict(v) for k, v in state.cycle_params.items()}
        self.shape = None if state.shape is None else state.shape.copy()
        self.cutter = None if state.cutter is None else state.cutter.copy()
        self.vector_before = None if state.vector_before is None else list(state.vector_before)
        self.whereabouts = state.whereabouts
        self.corner = state.corner
        restore_pending(self)
        restore_corner(self)

    # ---------------------------------------------------------------- plain motion
    def run_plain(self, plan: PlainRun, line: int) -> bool:
        """Carry out a ``PlainWords`` plan with its file and next line appended; returns whether
        the block counts as a move for a G66 call (``execute_nc``)."""
        held = self.corner
        moved = self._run_plain(plan, line)
        if held is not None and self.corner is held:  # a chamfer still waits: this block moved nothing
            corner_without_move(self, moved, False)
        return moved

    def _run_plain(self, plan: PlainRun, line: int) -> bool:
        modal_sets, code_sets, axes, inc, _, file, _ = plan
        self.at_line = line
        self.block_began()
        self.block_feed = any(letter == "F" for letter, _ in code_sets)
        if PENDING_ANGLE in self.codes and self.block_angle is None:  # the two-block form's second block
            del self.codes[PENDING_ANGLE], self.codes[PENDING_LINE]  # without its angle: no corner
        if self.cutter is not None and any(g == "plane" for g, _ in modal_sets):  # under compensation: the
            # plane change's alarm (cutter_stage.py)
            words = [("G", g) for group, g in modal_sets if group != "canned"]
            words += [(k, v) for k, v in code_sets if k in ("F", "S")]
            return self._cycle_fallback(plan, file, line, words)
        modal = self.modal
        for group, g in modal_sets:
            modal[group] = g
            if group == "motion" and self.cycle_params and g not in self.dialect.single_cycles:
                forget_single_cycle(self)
        if code_sets:
            codes = self.codes
            for letter, v in code_sets:
                codes[letter] = v
            if self.spindle_top is not None:
                for letter, v in code_sets:
                    if letter == "S":
                        spindle_speed(self, v, line, file)
        if not axes and not inc:
            if plan[4] and modal["motion"] in ARC_MODES:  # I, J, K alone may be a full circle
                return self._cycle_fallback(plan, file, line)
            return False
        mode = modal["motion"]
        if (mode in self.cycle_codes or mode in self.own_path_modes or (modal["canned"] != 80.0 and self.drills)
                or self.block_angle is not None or self.block_corner is not None):  # fmt: skip
            return self._cycle_fallback(plan, file, line)
        if self.shape is not None:
            self._shape_axes(frozenset(i for i, _ in axes) | frozenset(i for i, _ in inc))
        start = self.pos
        target = start[:]
        if self.lathe or modal["distance"] == 90.0:
            for i, v in axes:
                target[i] = v
            if axes:
                placed(self, (i for i, _ in axes))  # whereabouts.py
        else:
            for i, v in axes:
                target[i] += v
        for i, v in inc:
            target[i] += v
        self.pos = target
        extra = plan[4]
        centre = self.checked_arc(mode, start, target, dict(extra), line) if mode in ARC_MODES else None
        self.record(file, line, mode, tuple(start), tuple(target), centre)
        if self._no_call_after(mode):
            return False
        return not self._call_needs_distance or target != start or centre is not None

    def block_began(self) -> None:
        """Note which drawn axes are astray as a block begins, and where the tool is (whereabouts.py)."""
        self.block_astray = astray(self)
        if self.block_astray:
            self.block_start = tuple(self.pos)

    def _shape_axes(self, named: frozenset[int]) -> None:
        """A block of a lathe cycle's shape names the axes ``named`` (by index): the first such
        block says whether the shape is type I or II (lathe_cycles.py)."""
        shape = self.shape
        if shape is not None and shape.first_axes is None:
            shape.first_axes = named

    def _cycle_fallback(
        self, plan: PlainRun, file: str, line: int, words: list[tuple[str, float]] | None = None
    ) -> bool:
        """Run a plain line's plan through ``execute_nc`` (after ``words``, its G codes, F and S,
        when they have not been carried out yet)."""
        names, inverse = self.dialect.axes, self._incremental_names
        words = (words or []) + [(names[i], v) for i, v in plan[2]]
        words += [(inverse[names[i]], v) for i, v in plan[3]]
        words += plan[4]
        return self.execute_nc(words, file, line)[0]

    # ---------------------------------------------------------------- one block
    def execute_nc(self, words: list[tuple[str, float]], file: str, line: int) -> tuple[bool, ShapeCall | None]:
        """Carry out the NC words of a block. Returns (moved, shape): whether the block
        counts as a move for G66 modal calls (a move command; on a dialect whose
        ``modal_call_needs_distance`` is set, one that goes somewhere or draws an arc; on one with
        ``modal_call_codes``, one of those codes: the block's one-shot code, else the motion mode
        in force) and, for a lathe cycle that names a finishing shape (G70–G73 P Q), the shape the
        macro machine is to run (lathe_cycles.py)."""
        held = self.corner
        done = self._execute_nc(words, file, line)
        if held is not None and self.corner is held:  # a chamfer still waits: this block moved nothing
            corner_without_move(self, done[0], ("G", 4.0) in words)
        return done

    def _execute_nc(self, words: list[tuple[str, float]], file: str, line: int) -> tuple[bool, ShapeCall | None]:
        self.at_line = line
        self.block_began()
        gs: list[float] = []
        axes: dict[int, float] = {}
        incremental: dict[int, float] = {}
        other: dict[str, float] = {}
        axis_index = self.axis_index
        inc_letters = self.dialect.incremental_letters
        for letter, v in words:
            if letter == "G":
                gs.append(v)
            elif letter in axis_index:
                axes[axis_index[letter]] = v
            elif letter in inc_letters and inc_letters[letter] in axis_index:
                incremental[axis_index[inc_letters[letter]]] = v
            else:
                other[letter] = v
        self.block_feed = "F" in other
        last_keys = self.plain.last_keys
        if last_keys:  # the profile's address variables read every letter's last value
            codes = self.codes
            for letter, v in words:
                key = last_keys.get(letter)
                if key is not None:
                    codes[key] = v
        one = set_modal(self, gs, other, line)
        if self._values_in_block:  # an ellipse's letters, a thread's threads per inch (GSK)
            self._block_values(one, axes, other)
        if (
            self.lathe
            and one == self.dialect.coordinate_setting_code
            and "S" in other
            and not self._g50_speed(axes, incremental)
        ):
            # G50 S is the spindle speed clamp (docs/semantics.md §10.4), not a spindle speed
            self.codes[SPEED_CLAMP] = other["S"]
            set_codes(self, {k: v for k, v in other.items() if k != "S"}, file, line)
        else:
            set_codes(self, other, file, line)
        if gs and (axes or incremental) and not self._value_codes.isdisjoint(gs):
            # G22 X_ Z_ I_ K_: the stored stroke check's limits (FANUC 0i-TF and GSK980TDi manuals,
            # "stored stroke check"); G68 X_ Y_ R_, G51 X_ Y_ P_, G51.1 X_: the centre of the
            # rotation, scaling, mirror image. Not a move; none of them is simulated (§8)
            return False, None
        moved, shape = self._carry_out(one, axes, incremental, other, file, line)
        if moved and self._no_call_after(self.modal.get("motion", 0.0) if one is None else one):
            return False, shape
        return moved, shape

    def _no_call_after(self, code: float) -> bool:
        """Whether a move in ``code`` (a block's one-shot code, else the motion mode in force) is
        one after which no G66 call is made (``Dialect.modal_call_codes``)."""
        calls = self._call_codes
        return calls is not None and code not in calls

    def _carry_out(
        self, one: float | None, axes: dict[int, float], incremental: dict[int, float], other: dict[str, float],
        file: str, line: int,
    ) -> tuple[bool, ShapeCall | None]:  # fmt: skip
        """The move of a block whose modal codes and F, S, T, M are set (``execute_nc``): its
        one-shot code ``one``, else the motion mode in force, with its axis words."""
        if one is not None:
            if one != 4.0 and self.cycle_params:
                forget_single_cycle(self)
            if self.cutter is not None and (one in UNCOMPENSATED_CODES or one in self.dialect.skip_codes):
                if one in self.dialect.skip_codes:  # G31 in G41/G42: PS0035 (cutter_stage.py)
                    skip_in_offset(self, one, line)
                return uncompensated(self, lambda: one_shot(self, one, axes, incremental, other, file, line))
            return one_shot(self, one, axes, incremental, other, file, line)
        mode = self.modal.get("motion", 0.0)
        drawing = self.dialect.drawing_angle
        if drawing is not None and self.block_angle is None and drawing[0] in other and mode in (0.0, 1.0):
            # GSK980TDi's G01 X_ Q_: the angle as a word of its own (angled_moves.py)
            self.block_angle = other[drawing[0]] * drawing[1]
            try:
                return self._carry_out(one, axes, incremental, other, file, line)
            finally:
                self.block_angle = None
        canned = self.modal.get("canned", 80.0)
        if not axes and not incremental:
            if self.block_angle is not None:  # G01 ,A1 F0.1: FANUC's two-block form (angle_alone)
                self.angle_alone(line)
                return False, None
            return self._full_circle(mode, canned, other, file, line), None
        if self.shape is not None:
            self._shape_axes(frozenset(axes) | frozenset(incremental))
        target = self.target(axes, incremental)
        if PENDING_ANGLE in self.codes:  # the second block of the two-block form (angled_moves.py)
            self._two_block_corner(file, mode, target, {*axes, *incremental})
        if self.block_angle is not None and mode in (0.0, 1.0):  # G01 X30. ,A135. (angled_moves.py)
            self._angled(target, {*axes, *incremental}, self.block_angle, line)
        if canned != 80.0 and self.drills:
            drilling = self.dialect.lathe_drilling
            if drilling is None:
                drill_block(self, canned, axes, incremental, other, file, line)  # drill_cycles.py
            elif canned in drilling.cycles:
                lathe_drill_block(self, drilling, canned, axes, incremental, other, file, line)  # lathe_drilling.py
            return True, None
        if mode in self.cycle_codes:
            if self.cutter is not None:  # drawn as programmed under tool nose radius compensation (§12)
                uncompensated(self, lambda: self.turning_cycle(file, line, mode, axes, incremental, other))
            else:
                self.turning_cycle(file, line, mode, axes, incremental, other)
            return True, None  # a turning cycle ends where it started
        if self.lathe or self.modal.get("distance", 90.0) == 90.0:
            placed(self, axes)  # the axes named are where the program says (whereabouts.py)
        if mode in self._curves and self._curve(file, line, mode, target, other):
            return True, None
        centre = self.block_arc(mode, target, other, line)
        moved = not self._call_needs_distance or target != self.pos or centre is not None
        lead = self.times.variable_lead.get(mode)
        change = other.get(lead, 0.0) if lead else 0.0
        if lead:  # the control's alarm for a lead below zero (variable_leads.py)
            alarm = lead_alarm(mode, self.codes.get("F") or 0.0, change, self.times.long_axis(self.pos, target))
            if alarm is not None:
                raise alarm
        if self.block_corner is None and self.dialect.chamfer_words is None:
            self.move(file, line, mode, target, centre, change)
            return moved, None
        word = corner_word(self, mode, other)  # a chamfer or rounding after the move (corner_stage.py)
        clock, cut, start = self.clock, self.cut_length, tuple(self.pos)
        self.corner_end, self.corner_cost = None, (0.0, 0.0)
        self.move(file, line, mode, target, centre, change)
        if word is not None:
            start = self.corner_end or start  # the move starts where a chamfer before it ended
            unit = INCH if self.modal.get("units") == 20.0 else 1.0
            seconds, length = self.clock - clock - self.corner_cost[0], self.cut_length - cut - self.corner_cost[1]
            hold_corner(self, word, line, mode, start, tuple(target), centre, seconds, length / unit)
        return moved, None

    # ---------------------------------------------------------------- arcs
    def arc_centre(
        self, mode: float, start: Sequence[float], end: Sequence[float], words: dict[str, float],
        plane_code: float | None = None,
    ) -> tuple[float, ...] | None:  # fmt: skip
        """The centre of a G02 (``mode`` 2) or G03 arc from ``start`` to ``end`` in the plane in
        force (or ``plane_code``'s), from the block's R, I, J, K ``words`` (arcs.py); None when
        they name none."""
        plane = self._arc_planes.get(self.modal.get("plane", 17.0) if plane_code is None else plane_code)
        if plane is None:
            return None
        return arc_centre(mode == 2.0, plane, self._diameter, start, end, words)

    def arc_fault(
        self, start: Sequence[float], end: Sequence[float], centre: Sequence[float], words: dict[str, float],
        plane_code: float | None = None,
    ) -> tuple[str, float, float] | None:  # fmt: skip
        """What the control finds wrong with an arc about ``centre`` (``arcs.arc_fault``) in the
        plane in force (or ``plane_code``'s), with the machine's tolerance in the program's unit."""
        plane = self._arc_planes.get(self.modal.get("plane", 17.0) if plane_code is None else plane_code)
        if plane is None:
            return None
        tolerance = self.arc_tolerance / 25.4 if self.modal.get("units") == 20.0 else self.arc_tolerance
        return arc_fault(plane, self._diameter, start, end, centre, words, tolerance)

    def checked_arc(
        self, mode: float, start: Sequence[float], end: Sequence[float], words: dict[str, float], line: int
    ) -> tuple[float, ...] | None:
        """``arc_centre``, and the control's finding on the arc of ``line`` (arc_checks.py); None in
        polar or cylindrical interpolation, whose plane is not simulated: the arc is drawn as its
        chord (virtual_planes.py)."""
        if VIRTUAL_PLANE in self.modal:
            return None
        centre = self.arc_centre(mode, start, end, words)
        if centre is not None:
            fault = self.arc_fault(start, end, centre, words)
            if fault is not None:
                arc_finding(self, fault, line)
        else:
            plane = self._arc_planes.get(self.modal.get("plane", 17.0))
            if plane is not None:
                no_centre(self, mode, plane, start, end)  # PS0022 (arc_checks.py)
        return centre

    def block_arc(
        self, mode: float, target: list[float], other: dict[str, float], line: int
    ) -> tuple[float, ...] | None:
        """The centre of the move to ``target`` on ``line`` when ``mode`` is an arc, else None."""
        if mode not in ARC_MODES:
            return None
        return self.checked_arc(mode, self.pos, target, other, line)

    def _angled(self, target: list[float], named: set[int], angle: float, line: int) -> None:
        """The coordinate of the plane a block with ``,A`` leaves out, from the one it names; on a
        control that alarms on a line too near parallel to its axis, the finding, and the move
        as written (``Dialect.drawing_angle``)."""
        plane = self._arc_planes.get(self.modal.get("plane", 17.0))
        if plane is None:
            return
        drawing = self.dialect.drawing_angle
        if drawing is not None and drawing[2] is not None:
            letters = self.dialect.axes
            fault = one_axis_fault(plane, letters[plane[0]] + letters[plane[1]], named, angle, drawing[2])
            if fault is not None:
                self.host.note("arc", fault, line, DRAWING_ANGLE)
                return
        angled_end(plane, self._diameter, self.pos, target, named, angle)

    def angle_alone(self, line: int) -> None:
        """A block with an angle ``,A1`` and no coordinate (``block_angle``) under G00/G01: the first
        block of FANUC's two-block form, whose move waits for the next block (angled_moves.py)."""
        if self.block_angle is not None and self.modal.get("motion", 0.0) in (0.0, 1.0):
            self.codes[PENDING_ANGLE], self.codes[PENDING_LINE] = self.block_angle, float(line)

    def _two_block_corner(self, file: str, mode: float, target: list[float], named: set[int]) -> None:
        """The move of the first block of FANUC's two-block form (``,A1`` alone), to the corner
        where its line meets this block's (``X3 Z3 ,A2``), recorded on the first block's line."""
        first = self.codes.pop(PENDING_ANGLE) or 0.0
        first_line = int(self.codes.pop(PENDING_LINE) or 0.0)
        plane = self._arc_planes.get(self.modal.get("plane", 17.0))
        second = self.block_angle
        if plane is None or second is None or mode not in (0.0, 1.0) or not {plane[0], plane[1]} <= named:
            return
        drawing = self.dialect.drawing_angle
        fault = two_line_fault(first, second, drawing[2]) if drawing is not None and drawing[2] is not None else None
        if fault is not None:
            self.host.note("arc", fault, first_line, DRAWING_ANGLE)
            return
        corner = corner_point(plane, self._diameter, self.pos, target, first, second)
        if corner is not None:
            self.move(file, first_line, mode, corner)

    def _g50_speed(self, axes: dict[int, float], incremental: dict[int, float]) -> bool:
        """Whether the S of a lathe's coordinate setting block (G50) is the spindle speed rather
        than the clamp: where the profile says so (``Dialect.coordinate_setting_speed``) for a
        block that sets coordinates too, under G97 (docs/semantics.md §10.4)."""
        return self.dialect.coordinate_setting_speed and bool(axes or incremental) and self.modal.get("spindle") != 96.0

    def _block_values(self, one: float | None, axes: dict[int, float], other: dict[str, float]) -> None:
        """Words that are values in this block's mode: an ellipse's A, B, Q and a parabola's P, Q
        are never an axis word (``Dialect.motion_value_letters``: moved from ``axes`` to
        ``other``), and a thread's pitch in threads per inch (GSK980TDi I) gives its F, the lead:
        25.4 / I mm, 1 / I inch under G20."""
        values = self.dialect.motion_value_letters.get(self.modal.get("motion", 0.0)) if one is None else None
        if values:
            for letter in values:
                i = self.axis_index.get(letter)
                if i is not None and i in axes:
                    other[letter] = axes.pop(i)
        tpi = self.dialect.lathe_cycles.threads_per_inch
        if tpi is not None and tpi in other and "F" not in other and self._cuts_thread(one):
            per_inch = other[tpi]
            code = self.modal.get("motion", 0.0) if one is None else one
            if per_inch > 0.0 or (per_inch < 0.0 and code in self.dialect.lathe_cycles.left_hand):
                other["F"] = (1.0 if self.modal.get("units") == 20.0 else 25.4) / per_inch

    def _cuts_thread(self, one: float | None) -> bool:
        """Whether a block with one-shot code ``one`` (None: none) cuts a thread: G76 (GSK's G78), or a
        thread's motion mode or single cycle in force."""
        if one is not None:
            return one in (76.0, 78.0) and one in self.cycle_codes
        mode = self.modal.get("motion", 0.0)
        single = self.dialect.single_cycles.get(mode)
        drilling = self.dialect.lathe_drilling
        tap = drilling.cycles.get(mode) if drilling is not None else None
        return (
            mode in self.times.thread_modes or (single is not None and single.thread) or (tap is not None and tap.lead)
        )

    def _curve(self, file: str, line: int, mode: float, target: list[float], other: dict[str, float]) -> bool:
        """A move in a curve's ``mode``: a G05/G05.1 three-point arc (three_point_arcs.py), a G6.2/G6.3
        ellipse or a G7.2/G7.3 parabola (conic_moves.py). Whether it was made here (else it is
        the general move's: a three-point arc the control alarms on, drawn straight)."""
        if mode in self._three_points:
            three_point = self._three_point(mode, target, other)
            if isinstance(three_point, tuple):
                self.move(file, line, three_point[0], target, three_point[1])
                return True
            if three_point is not None:  # the control alarms: the move is drawn straight
                self.host.note("arc", three_point, line, CURVE_FAULT)
        conic = self.dialect.conic_moves.get(mode)
        if conic is None:
            return False
        self._conic(file, line, mode, conic, target, other)
        return True

    def _conic(
        self, file: str, line: int, mode: float, conic: tuple[bool, bool], target: list[float], other: dict[str, float]
    ) -> None:
        """The ellipse or parabola (``conic``: ``Dialect.conic_moves``) to ``target``, cut as its
        short pieces; where the control alarms, the finding, and the move straight."""
        plane = self._arc_planes.get(self.modal.get("plane", 17.0))
        if plane is None:
            self.move(file, line, mode, target)
            return
        increment = in_increments(self, 1.0)
        points = conic_points(conic[0], conic[1], plane, self._diameter, self.pos, target, other, increment)
        if isinstance(points, str):
            self.host.note("arc", points, line, CURVE_FAULT)
            self.move(file, line, mode, target)
            return
        for point in points:
            self.move(file, line, mode, list(point))

    def _three_point(
        self, mode: float, target: list[float], other: dict[str, float]
    ) -> tuple[float, tuple[float, ...]] | Detail | None:
        """The mode (2 or 3) and centre of a three-point arc to ``target`` in the plane in force,
        when ``mode`` is one (``Dialect.three_point_arcs``); why not, where the circle does not
        exist."""
        absolute = self.dialect.three_point_arcs.get(mode)
        code = self.modal.get("plane", 17.0)
        plane = self._arc_planes.get(code)
        if absolute is None or plane is None:
            return None

        def length(mode: float, start: Sequence[float], end: Sequence[float], centre: Sequence[float]) -> float:
            return self.times.arc_length(mode, code, start, end, centre)

        return three_point_arc(absolute, plane, self._diameter, self.pos, target, other, length)

    def _full_circle(self, mode: float, canned: float, other: dict[str, float], file: str, line: int) -> bool:
        """A G02/G03 block with I, J or K but no axis word: a full circle back to the start
        (with R instead, an arc of 0° that moves nothing). Returns whether it moved."""
        if mode not in ARC_MODES or (canned != 80.0 and self.drills):
            return False
        if "R" in other:
            self.checked_arc(mode, self.pos, self.pos, other, line)  # an arc of 0°: a finding, no move
            return False
        centre = self.arc_centre(mode, self.pos, self.pos, other)
        if centre is None:
            return False
        here = tuple(self.pos)
        self.record(file, line, mode, here, here, centre)
        return True

    # ---------------------------------------------------------------- moves
    def target(self, axes: dict[int, float], incremental: dict[int, float]) -> list[float]:
        """Where the block's axis words send the tool (G90/G91; a lathe's U, V, W add)."""
        target = list(self.pos)
        absolute = self.lathe or self.modal.get("distance", 90.0) == 90.0
        for i, v in axes.items():
            target[i] = v if absolute else target[i] + v
        for i, v in incremental.items():
            target[i] = target[i] + v
        return target

    def move(
        self,
        file: str,
        line: int,
        mode: float,
        target: list[float],
        centre: tuple[float, ...] | None = None,
        lead_change: float = 0.0,
        end_unknown: bool = False,
    ) -> None:
        """Move to ``target`` in ``mode`` (an arc about ``centre``; a variable-lead thread whose
        lead changes by ``lead_change`` per revolution; to a place the run does not know: a
        reference point, ``end_unknown``) and record it."""
        self.record(file, line, mode, tuple(self.pos), tuple(target), centre, lead_change=lead_change,
                    end_unknown=end_unknown)  # fmt: skip
        self.pos[:] = target

    def turning_cycle(
        self, file: str, line: int, code: float, axes: dict[int, float], inc: dict[int, float], other: dict[str, float]
    ) -> None:
        """A lathe's turning cycle to the block's end point, recorded with its legs
        (turning_cycles.py; a single cycle's words are modal); the tool ends where it started."""
        single = self.dialect.single_cycles.get(code)
        if single is not None:
            target, taper = single_cycle_target(self, code, axes, inc, other)
            single_cycle(self, file, line, code, single, target, taper)
        elif self.dialect.lathe_drilling is not None and code in self.dialect.lathe_drilling.cycles:
            # gsk980tdi's drilling cycles are of the motion group (lathe_drilling.py)
            lathe_drill_block(self, self.dialect.lathe_drilling, code, axes, inc, other, file, line)
        else:  # a cycle no module plans: timed as the one cut it is drawn as
            target = self.target(axes, inc)
            start = tuple(self.pos)
            legs = turning_legs(None, self.axis_index, start, target)
            self.record(file, line, code, start, tuple(target), None, legs, TURNING)

    def record(
        self,
        file: str,
        line: int,
        mode: float,
        start: tuple[float, ...],
        end: tuple[float, ...],
        centre: tuple[float, ...] | None = None,
        legs: tuple[Leg, ...] | None = None,
        cycle: str | None = None,
        pass_of: str | None = None,
        lead_change: float = 0.0,
        end_unknown: bool = False,
    ) -> None:
        """Advance the clock by the move's time, add its length to the path and record the move
        (with an arc's centre and plane, a cycle's legs, its time, the lathe cycle it is a pass
        of), by cycle_time.py's rules. While a roughing cycle reads its shape, the move is kept as
        a segment of the shape instead (lathe_cycles.py). A move from or to a place the run does
        not know is marked so (``Move.unknown``: whereabouts.py)."""
        if self.corner is not None:  # the corner a chamfer or rounding cuts first (corner_stage.py)
            plain = legs is None and cycle is None and pass_of is None
            start = self.corner_end = take_corner(self, mode, self.modal.get("plane", 17.0), start, end, centre, plain)
        shape = self.shape
        if shape is not None and shape.reading:
            shape.segments.append((mode, start, end, centre))
            return
        unknown = unknown_ends(self, start, end, end_unknown) if self.block_astray or end_unknown else None
        feed = self.codes.get("F") or 0.0
        times = self.times
        modal = self.modal
        unit = INCH if modal.get("units") == 20.0 else 1.0
        plane = modal.get("plane", 17.0)
        stop = None
        tool_path = None
        compensated = None
        if self.cutter is not None and legs is None:  # cutter radius compensation (cutter_stage.py)
            compensated = cutter_move(self, file, line, mode, plane, start, end, centre, feed, unit)
        if self.travel is None:
            pass
        elif compensated is None:  # the machine's soft limits: the move stops where it leaves them
            stop = leaves_travel(self, program_bounds(self), mode, plane, start, end, centre, legs)
            if stop is not None:
                end = stop[0]
        else:  # the machine follows the tool centre
            short = centre_travel(self, line, mode, plane, start, end, centre, compensated[0], feed, unit)
            if short is not None:
                compensated, end, stop = (short[0], short[1]), short[2], (short[2], short[3])
        travelled = start if self.vector_before is None else travel_start(self, start)  # offset_travel.py
        if compensated is not None:
            tool_path, seconds = compensated
        elif mode == 0.0:
            seconds = times.rapid_seconds(travelled, end, unit)
            self.rapid_length += times.distance(travelled, end) * unit
        else:
            if centre is not None and mode in ARC_MODES:
                length = times.arc_length(mode, plane, start, end, centre)
            else:
                length = times.distance(travelled, end)
                if CYLINDER in modal:  # C's degrees on the cylinder's surface (virtual_planes.py)
                    length = surface_length(self, start, end, length)
            if modal.get("feed") == INVERSE_TIME and mode in INVERSE_TIME_MODES and legs is None and cycle is None:
                seconds = inverse_time_cut(self, feed, line, length * unit)  # G93: 1/F minutes (missing_feed.py)
            else:
                seconds = self.feed_seconds(mode, length, feed, start, end, unit, lead_change, line)
            self.cut_length += length * unit
            if self.feed_hint and 0.0 < feed < 1.0:
                self.feed_per_minute_hint(mode, feed, line)
        self.clock += seconds
        if self.record_moves:
            self.moves.append(_new_move(Move, (file, line, mode, start, end, float(feed), centre, seconds, plane, legs,
                                              cycle, pass_of, tool_path if self.centre_paths else None,
                                              unknown)))  # fmt: skip
            if len(self.moves) >= self.move_budget:
                self.moves_full(line)
        if stop is not None:
            raise stop[1]

    def moves_full(self, line: int | None = None) -> None:
        """The toolpath has ``move_budget`` moves: keep no more (the clock and the path go on),
        and say so once, on the block that filled it."""
        if not self.record_moves or len(self.moves) < self.move_budget:
            return
        self.record_moves = False
        self.moves_cut = True
        n = f"{self.move_budget:,}"
        self.host.note("limits", detail(
            f"the toolpath keeps the first {n} moves, which this block reached; the run goes on, and its "
            "time and path count every move",
            f"刀具路径只保留前 {n} 个移动（本程序段达到该数目）；"
            "运行继续，加工时间和路径长度计入全部移动"), line)  # fmt: skip

    def feed_per_minute_hint(self, mode: float, feed: float, line: int) -> None:
        """On a lathe that powers on in G98 (``feed_hint``: gsk980tdi), a cut at F below 1 under
        G98 is a feed per revolution without its G99 (0.2 mm/min cuts nothing): a note, once a
        run, that the analysis shows as a ``feed-per-minute`` hint (docs/semantics.md §10.4)."""
        if self.modal.get("feed") != 98.0 or mode in self.times.thread_modes or FEED_HINT_GIVEN in self.codes:
            return
        self.codes[FEED_HINT_GIVEN] = 1.0
        f = f"F{feed:g}"
        self.host.note(
            "feed",
            detail(f"{f} under G98 is {feed:g} mm/min: a cutting feed below 1 per minute almost surely means per "
                   "revolution, and this control powers on in G98 (feed per minute); add G99 before the cut",
                   f"G98（每分钟进给）下 {f} 即 {feed:g} mm/min：每分钟进给小于 1 几乎肯定是每转进给，"
                   "本系统上电默认为 G98，请在切削前加 G99"),
            line,
            "feed-per-minute",
        )  # fmt: skip

    def feed_seconds(self, mode: float, length: float, feed: float, start: Sequence[float], end: Sequence[float],
                     unit: float, lead_change: float = 0.0, line: int | None = None) -> float:  # fmt: skip
        """The seconds of a cutting move in ``mode`` from ``start`` to ``end``, ``length`` long, by
        the feed mode, spindle speed, G96 and G50 S clamp in force (``MoveTimes.feed_seconds``); a
        negative F of a left-hand thread is its lead |F|. A cut that cannot be timed (no feed, or per
        revolution at S0) is noted on ``line``, the block's by default (missing_feed.py)."""
        modal = self.modal
        feed_mode = modal.get("feed")
        codes = self.codes
        if feed < 0.0 and modal.get("motion") in self.dialect.lathe_cycles.left_hand:
            feed = -feed  # a left-hand thread of lead |F| (``LatheCycles.left_hand``)
        per_rev = feed_mode == 95.0 or (feed_mode == 99.0 and self.lathe)
        speed = codes.get("S") or 0.0
        thread = mode in self.times.thread_modes
        if feed <= 0.0 or ((per_rev or thread) and speed <= 0.0):
            note_missing_feed(self, feed, per_rev or thread, speed, self.at_line if line is None else line, thread)
        return self.times.feed_seconds(mode, length, feed, per_rev, speed, modal.get("spindle") == 96.0,
                                       codes.get(SPEED_CLAMP), start, end, unit, lead_change)  # fmt: skip

    def cutting_rate(self, feed: float, start: Sequence[float], end: Sequence[float], unit: float) -> float:
        """The feed of a G01 from ``start`` to ``end`` in program units per minute, as
        ``feed_seconds`` times it (a mill's drilling cycle, drill_cycles.py)."""
        length = self.times.distance(start, end)
        seconds = self.feed_seconds(1.0, length, feed, start, end, unit)
        return length / seconds * 60.0 if seconds > 0.0 else 0.0
