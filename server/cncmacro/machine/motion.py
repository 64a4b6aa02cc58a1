"""The simulated machine's NC side: modal G codes, F/S/T/M, positions, offsets (docs/semantics.md §8).

``execute_nc`` takes the evaluated words of one block and does what the control would: it
updates the modal groups and the last F, S, T, M, D, H values; moves the axes (G00–G03 end
points, G90/G91, and on a lathe U/V/W as incremental X/Y/Z); applies work offsets
(G54–G59, G54.1 Pn and Haas G154 Pn / G110–G129, external), tool offsets (lathe T codes, G43/G44 H) and coordinate
setting (G92, or G50 on a lathe); handles G04, G10, G28, G31, G53 and canned cycles; and
records every move, a G02/G03 arc with its centre (arcs.py). Which modal group a G code
belongs to comes from the dialect's table.
Values arrive already rounded to their address's increment.
"""

from __future__ import annotations

from collections.abc import Sequence
from string import ascii_letters
from typing import TYPE_CHECKING, cast

from ..bilingual import detail
from ..dialects.alarms import ARGUMENT_RANGE
from .alarms import MacroAlarm
from .arcs import ARC_MODES, arc_centre, arc_planes
from .calls import g_code_groups
from .cycle_time import INCH, MoveTimes
from .drill_cycles import drill_block
from .frames import Move, ToolChange
from .probing import Probe, SkipState, skip_block
from .words import extra_offset_codes

if TYPE_CHECKING:
    from ..dialects import Dialect
    from ..library.machine_file import MachineSettings
    from .machine import Machine
    from .observer import RunObserver

Value = float | None

WORK_BASE = 5201  # external offset of axis 1; G54 is +20, G55 +40 ... (both dialects)
G54_1_BASE = 7001  # G54.1 P1 axis 1; each P adds 20 (fanuc; ``Dialect.extra_offset_variables``)
LATHE_CYCLES_WITH_PROFILE = (71.0, 72.0, 73.0)
_new_move = tuple.__new__  # a Move without the NamedTuple constructor's keyword handling
_Words = tuple[tuple[str, float], ...]  # (letter or group, value)
_Axes = tuple[tuple[int, float], ...]  # (axis index, value)
# a block of plain motion decided once (``Motion.plain_plan``): modal settings (group, G), F and S,
# absolute axes (index, value), incremental axes, and the arc words R I J K
PlainPlan = tuple[_Words, _Words, _Axes, _Axes, _Words]
# a plan with the file and the next line appended, as a plain line's runner holds it
PlainRun = tuple[_Words, _Words, _Axes, _Axes, _Words, str, int]
_NOT_PLAIN_GROUPS = frozenset(("macro", "canned", "wcs", "length"))
_CANCEL_CYCLE = ("canned", 80.0)  # on a mill, G00-G03 cancel a drilling cycle (group 01 over group 09)
_CENTRE_LETTERS = frozenset("RIJK")  # arc radius and centre: kept for a canned cycle's R level
_G_WORDS_KEPT = 1000  # spellings of G words ``plain_g_word`` keeps
# ``plain_kinds``'s codes: an absolute axis's is its index (below PLAIN_INCREMENTAL), so that
# the common word, an axis, is told by one comparison; the others come after
PLAIN_INCREMENTAL = 32  # plus the axis index: an incremental letter (U, V, W on a lathe)
PLAIN_G = 64
PLAIN_F = 65
PLAIN_S = 66
PLAIN_ARC_LETTERS = {67: "R", 68: "I", 69: "J", 70: "K"}  # the arc's radius and centre words
NOT_PLAIN = 99  # a letter a plain motion line cannot hold


class Motion:
    """The NC part of the machine (a mixin of ``Machine``)."""

    dialect: Dialect
    settings: MachineSettings
    S: dict[int, Value]
    clock: float
    written_system: set[int]
    observer: RunObserver | None

    def init_motion(self) -> None:
        axes = self.dialect.axes
        self.axis_index = {a: i for i, a in enumerate(axes)}
        self.pos: list[float] = [0.0] * len(axes)
        self.shift: list[float] = [0.0] * len(axes)
        self.skip_pos: list[float] = [0.0] * len(axes)
        self.skip_state = SkipState()  # the contact points used (probing.py)
        self.probes: list[Probe] = []
        self.tool_vector: list[float] = [0.0] * len(axes)
        self.modal: dict[str, float] = {"motion": 0.0, "distance": 90.0, "units": 21.0, "cutter": 40.0,
                                        "length": 49.0, "canned": 80.0, "return": 98.0, "macro": 67.0,
                                        "spindle": 97.0, "wcs": 54.0, "cutting": 64.0, "rotation": 69.0,
                                        "mirror": 50.1, "scaling": 50.0, "polar": 15.0, "stroke": 22.0}  # fmt: skip
        self.modal.update(self.dialect.modal_defaults)
        self.codes: dict[str, Value] = {}
        self.extra_wcs = 0  # G54.1 Pn (G154 Pn, G110-G129)
        self.cycle_start_z: float | None = None
        self.moves: list[Move] = []
        self.record_moves = True
        # the cycle time's rules (cycle_time.py), the path so far (mm) and, while moves are
        # recorded, the tool changes (``cncmacro run``'s totals per tool)
        self.times = MoveTimes(self.dialect)
        self.cut_length = 0.0
        self.rapid_length = 0.0
        self.tool_changes: list[ToolChange] = []
        self.g_groups = g_code_groups(self.dialect)
        self._extra_codes = extra_offset_codes(self.dialect)
        if self._extra_codes:  # the switch makes them work offset codes, whatever the table says
            self.g_groups = {**self.g_groups, **dict.fromkeys(self._extra_codes, "wcs")}
        self._cycle_codes = self.dialect.cycle_codes
        self._lathe = self.dialect.lathe
        self._call_needs_distance = self.dialect.modal_call_needs_distance
        self._plain_kinds: dict[str, int] | None = None
        self._plain_groups: dict[float, str] | None = None
        self._plain_g_words: dict[str, tuple[str, float]] = {}
        self._arc_planes = arc_planes(self.axis_index)
        self._diameter = self.axis_index.get("X", -1) if self._lathe else -1

    # ---------------------------------------------------------------- positions
    def work_offset(self, axis: int) -> float:
        """The work offset of ``axis`` in force: the coordinate system's plus the external."""
        wcs = self.modal.get("wcs", 54.0)
        if self.extra_wcs and (wcs == 54.1 or wcs in self._extra_codes):
            n = self.dialect.extra_offset_variables + 20 * (self.extra_wcs - 1) + axis
        else:
            n = WORK_BASE + 20 * (int(wcs) - 53) + axis
        return (self.S.get(n) or 0.0) + (self.S.get(WORK_BASE + axis) or 0.0)

    def machine_position(self, axis: int) -> float:
        return self.pos[axis] + self.work_offset(axis) + self.shift[axis] + self.tool_vector[axis]

    def position_value(self, which: str, axis: int) -> Value:
        if axis >= len(self.pos):
            return 0.0
        if which in ("end", "current"):
            return self.pos[axis]
        if which == "machine":
            return self.machine_position(axis)
        if which == "skip":
            return self.skip_pos[axis]
        if which == "tool":
            return self.tool_vector[axis]
        return 0.0

    # ---------------------------------------------------------------- plain motion
    def plain_text_plan(self, text: str) -> PlainPlan | None:
        """``plain_plan`` read straight from a ``Block.plain`` line: whitespace-separated
        address-number words with at most three decimals, so that a literal axis value is
        already on the grid (docs/semantics.md §2). None when the line is not plain motion or its
        values need the general rounding (increment input mode, S with a fraction)."""
        kinds = self.plain_kinds()
        if not kinds:
            return None
        modal: list[tuple[str, float]] = []
        codes: list[tuple[str, float]] = []
        axes: list[tuple[int, float]] = []
        inc: list[tuple[int, float]] = []
        extra: list[tuple[str, float]] = []
        groups = self.plain_g_groups()
        for word in text.split():
            kind = kinds[word[0]]
            if kind == NOT_PLAIN:
                return None
            v = float(word[1:])
            if kind < PLAIN_INCREMENTAL:
                axes.append((kind, v))
            elif kind < PLAIN_G:
                inc.append((kind - PLAIN_INCREMENTAL, v))
            elif kind == PLAIN_G:
                group = groups.get(v)
                if group is None:
                    return None
                modal.append((group, v))
                if group == "motion" and not self._lathe:
                    modal.append(_CANCEL_CYCLE)
            elif kind == PLAIN_F:
                codes.append(("F", v))
            elif kind == PLAIN_S:
                if v % 1:
                    return None
                codes.append(("S", v))
            else:
                extra.append((PLAIN_ARC_LETTERS[kind], v))
        return tuple(modal), tuple(codes), tuple(axes), tuple(inc), tuple(extra)

    def plain_g_groups(self) -> dict[float, str]:
        """G code -> modal group, for the G codes a plain line may carry: those of a modal
        group without side effects beyond the group, and not configured to call a program."""
        groups = self._plain_groups
        if groups is None:
            calls = self.settings.calls
            groups = self._plain_groups = {
                g: group
                for g, group in self.g_groups.items()
                if group and group not in _NOT_PLAIN_GROUPS and f"G{g:g}" not in calls
            }
        return groups

    def plain_g_words(self) -> dict[str, tuple[str, float]]:
        """G word as written (``G01``, ``g1``) -> its ``plain_g_groups`` group ("" for none)
        and its value, for each one ``plain_g_word`` has read: a plain line's G word is
        looked up, not read again (reading a number costs more than the rest of the word)."""
        return self._plain_g_words

    def plain_g_word(self, word: str) -> tuple[str, float]:
        """Read G word ``word`` for ``plain_g_words``, and keep it there (while it holds fewer
        than ``_G_WORDS_KEPT``: a program can spell one code many ways)."""
        v = float(word[1:])
        read = (self.plain_g_groups().get(v, ""), v)
        if len(self._plain_g_words) < _G_WORDS_KEPT:
            self._plain_g_words[word] = read
        return read

    def plain_kinds(self) -> dict[str, int]:
        """Every ASCII letter (either case) -> its code: an axis's index, ``PLAIN_INCREMENTAL``
        plus the index for an incremental letter, ``PLAIN_G``, ``PLAIN_F``, ``PLAIN_S``, a key
        of ``PLAIN_ARC_LETTERS`` for R, I, J, K, and ``NOT_PLAIN`` for the others (a
        ``Block.plain`` word starts with an ASCII letter, so looking it up never misses). Empty
        in increment input mode, where a value without a point counts least increments, and
        for a machine of more axes than the codes leave room for."""
        kinds = self._plain_kinds
        if kinds is not None:
            return kinds
        if self.settings.decimal_point == "increment" or len(self.axis_index) > PLAIN_INCREMENTAL:
            kinds = self._plain_kinds = {}
            return kinds
        kinds = dict.fromkeys(ascii_letters, NOT_PLAIN)
        codes = {"G": PLAIN_G, "F": PLAIN_F, "S": PLAIN_S, **{c: k for k, c in PLAIN_ARC_LETTERS.items()}}
        codes.update(self.axis_index)
        for letter, axis in self.dialect.incremental_letters.items():
            if axis in self.axis_index:
                codes[letter] = PLAIN_INCREMENTAL + self.axis_index[axis]
        for letter, code in codes.items():
            kinds[letter] = kinds[letter.lower()] = code
        self._plain_kinds = kinds
        return kinds

    def plain_plan(self, words: list[tuple[str, float]]) -> PlainPlan | None:
        """For a block of literal words that only sets modal codes, F or S and moves axes:
        (modal settings, codes, absolute axes, incremental axes, arc words R I J K), decided
        once; None for anything else (one-shot G codes, canned cycles, tools), which
        ``execute_nc`` does."""
        modal: list[tuple[str, float]] = []
        codes: list[tuple[str, float]] = []
        axes: list[tuple[int, float]] = []
        inc: list[tuple[int, float]] = []
        extra: list[tuple[str, float]] = []
        axis_index = self.axis_index
        inc_letters = self.dialect.incremental_letters
        for letter, v in words:
            if letter == "G":
                group = self.g_groups.get(v)
                if not group or group in _NOT_PLAIN_GROUPS:
                    return None
                modal.append((group, v))
                if group == "motion" and not self._lathe:
                    modal.append(_CANCEL_CYCLE)
            elif letter in axis_index:
                axes.append((axis_index[letter], v))
            elif letter in inc_letters and inc_letters[letter] in axis_index:
                inc.append((axis_index[inc_letters[letter]], v))
            elif letter in ("F", "S"):
                codes.append((letter, v))
            elif letter in _CENTRE_LETTERS:
                extra.append((letter, v))
            else:
                return None
        return tuple(modal), tuple(codes), tuple(axes), tuple(inc), tuple(extra)

    def run_plain(self, plan: PlainRun, line: int) -> bool:
        """Carry out a ``plain_plan`` with its file and next line appended; returns whether
        the block counts as a move for a G66 call (``execute_nc``)."""
        modal_sets, code_sets, axes, inc, _, file, _ = plan
        modal = self.modal
        for group, g in modal_sets:
            modal[group] = g
        if code_sets:
            codes = self.codes
            for letter, v in code_sets:
                codes[letter] = v
        if not axes and not inc:
            if plan[4] and modal["motion"] in ARC_MODES:  # I, J, K alone may be a full circle
                return self._cycle_fallback(plan, file, line)
            return False
        mode = modal["motion"]
        if mode in self._cycle_codes or (modal["canned"] != 80.0 and not self._lathe):
            return self._cycle_fallback(plan, file, line)
        start = self.pos
        target = start[:]
        if self._lathe or modal["distance"] == 90.0:
            for i, v in axes:
                target[i] = v
        else:
            for i, v in axes:
                target[i] += v
        for i, v in inc:
            target[i] += v
        self.pos = target
        extra = plan[4]
        centre = self.arc_centre(mode, start, target, dict(extra)) if extra and mode in ARC_MODES else None
        self._record(file, line, mode, tuple(start), tuple(target), centre)
        return not self._call_needs_distance or target != start or centre is not None

    def _cycle_fallback(self, plan: PlainRun, file: str, line: int) -> bool:
        inverse = {v: k for k, v in self.dialect.incremental_letters.items()}
        words = [(self.dialect.axes[i], v) for i, v in plan[2]]
        words += [(inverse[self.dialect.axes[i]], v) for i, v in plan[3]]
        words += plan[4]
        return self.execute_nc(words, file, line)[0]

    # ---------------------------------------------------------------- one block
    def execute_nc(self, words: list[tuple[str, float]], file: str, line: int) -> tuple[bool, float | None]:
        """Carry out the NC words of a block. Returns (moved, skip_label): whether the block
        counts as a move for G66 modal calls (a move command; on a dialect whose
        ``modal_call_needs_distance`` is set, one that goes somewhere or draws an arc) and, for a
        lathe roughing cycle with Q, the label after which the program continues."""
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
        one_shot: float | None = None
        groups = [self.g_groups.get(g) for g in gs]
        if "motion" in groups and "canned" not in groups and not self.dialect.lathe:
            self.modal["canned"] = 80.0  # G00-G03 cancel a drilling cycle, as G80 does
        for g, group in zip(gs, groups, strict=True):
            if group:
                if group == "macro":
                    continue  # G66/G67 are handled by the call layer
                self.modal[group] = g
                if group == "canned" and g != 80.0:
                    self.cycle_start_z = None
                if group == "wcs" and g == 54.1:
                    self.extra_wcs = int(other.get("P", 1))
                elif group == "wcs" and g in self._extra_codes:
                    self.extra_wcs = self._extra_offset(g, other)
            else:
                one_shot = g
        for letter in ("F", "S", "D", "H", "B"):
            if letter in other:
                self.codes[letter] = other[letter]
        if "T" in other:
            self.select_tool(other["T"])
            if self.times.tool_change_t:
                self.tool_change(file, line)
        if "M" in other:
            self.codes["M"] = other["M"]
            self.m_code_time(other["M"], file, line)  # after T: T1 M06 changes to T1
        if "H" in other and self.modal.get("length") in (43.0, 44.0):
            self.apply_length_offset(other["H"])
        elif not self.dialect.lathe and self.modal.get("length") == 49.0 and "Z" in self.axis_index:
            self.tool_vector[self.axis_index["Z"]] = 0.0

        if one_shot is not None:
            return self._one_shot(one_shot, axes, incremental, other, file, line)
        mode = self.modal.get("motion", 0.0)
        canned = self.modal.get("canned", 80.0)
        if not axes and not incremental:
            return self._full_circle(mode, canned, other, file, line), None
        target = self._target(axes, incremental)
        if not self.dialect.lathe and canned != 80.0:
            drill_block(self, canned, axes, incremental, other, file, line)  # drill_cycles.py
            return True, None
        if mode in self.dialect.cycle_codes:
            self._record(file, line, mode, tuple(self.pos), tuple(target))
            return True, None  # a turning cycle ends where it started
        centre = self._block_arc(mode, target, other)
        moved = not self._call_needs_distance or target != self.pos or centre is not None
        self._move(file, line, mode, target, centre)
        return moved, None

    def _extra_offset(self, g: float, other: dict[str, float]) -> int:
        """The extra work offset a Haas ``G154 Pn`` (P1 when P is left out) or ``G110``–``G129``
        selects; a P outside the offsets the control has is alarm 119."""
        if g != self.dialect.extra_offset_code:
            return self.dialect.extra_offset_aliases.index(g) + 1
        p = int(other.get("P", 1.0))
        count = self.dialect.extra_offset_count
        if not 1 <= p <= count:
            raise MacroAlarm(
                ARGUMENT_RANGE,
                detail(f"G{g:g} P{p}: P must be 1 to {count}", f"G{g:g} P{p}：P 必须在 1～{count} 之间"),
            )
        return p

    def arc_centre(
        self, mode: float, start: Sequence[float], end: Sequence[float], words: dict[str, float]
    ) -> tuple[float, ...] | None:
        """The centre of a G02 (``mode`` 2) or G03 arc from ``start`` to ``end`` in the plane in
        force, from the block's R, I, J, K ``words`` (arcs.py); None when they name none."""
        plane = self._arc_planes.get(self.modal.get("plane", 17.0))
        if plane is None:
            return None
        return arc_centre(mode == 2.0, plane, self._diameter, start, end, words)

    def _block_arc(self, mode: float, target: list[float], other: dict[str, float]) -> tuple[float, ...] | None:
        """The centre of the move to ``target`` when ``mode`` is an arc, else None."""
        if mode not in ARC_MODES:
            return None
        return self.arc_centre(mode, self.pos, target, other)

    def _full_circle(self, mode: float, canned: float, other: dict[str, float], file: str, line: int) -> bool:
        """A G02/G03 block with I, J or K but no axis word: a full circle back to the start
        (with R instead, an arc of 0° that moves nothing). Returns whether it moved."""
        if mode not in ARC_MODES or "R" in other or (canned != 80.0 and not self._lathe):
            return False
        centre = self.arc_centre(mode, self.pos, self.pos, other)
        if centre is None:
            return False
        here = tuple(self.pos)
        self._record(file, line, mode, here, here, centre)
        return True

    def _target(self, axes: dict[int, float], incremental: dict[int, float]) -> list[float]:
        target = list(self.pos)
        absolute = self.dialect.lathe or self.modal.get("distance", 90.0) == 90.0
        for i, v in axes.items():
            target[i] = v if absolute else target[i] + v
        for i, v in incremental.items():
            target[i] = target[i] + v
        return target

    def _move(
        self, file: str, line: int, mode: float, target: list[float], centre: tuple[float, ...] | None = None
    ) -> None:
        self._record(file, line, mode, tuple(self.pos), tuple(target), centre)
        self.pos[:] = target

    def _record(
        self,
        file: str,
        line: int,
        mode: float,
        start: tuple[float, ...],
        end: tuple[float, ...],
        centre: tuple[float, ...] | None = None,
    ) -> None:
        """Advance the simulated clock by the move's time, add its length to the path and
        record the move (with an arc's centre and its time), by the rules of cycle_time.py."""
        feed = self.codes.get("F") or 0.0
        times = self.times
        modal = self.modal
        unit = INCH if modal.get("units") == 20.0 else 1.0
        if mode == 0.0:
            seconds = times.rapid_seconds(start, end, unit)
            self.rapid_length += times.distance(start, end) * unit
        else:
            if centre is not None and mode in ARC_MODES:
                length = times.arc_length(mode, modal.get("plane", 17.0), start, end, centre)
            else:
                length = times.distance(start, end)
            rate = self.cutting_rate(feed, start, end, unit)
            seconds = length / rate * 60.0 if rate > 0 else 0.0
            self.cut_length += length * unit
        self.clock += seconds
        if self.record_moves:
            self.moves.append(_new_move(Move, (file, line, mode, start, end, float(feed), centre, seconds)))

    def cutting_rate(self, feed: float, start: Sequence[float], end: Sequence[float], unit: float) -> float:
        """The feed of a cutting move from ``start`` to ``end`` in program units per minute:
        F, or per revolution F times the spindle speed (``MoveTimes.feed_rate``)."""
        modal = self.modal
        per_rev = modal.get("feed")
        if per_rev == 95.0 or (per_rev == 99.0 and self._lathe):
            return self.times.feed_rate(feed, True, self.codes.get("S") or 0.0, modal.get("spindle") == 96.0,
                                        start, end, unit)  # fmt: skip
        return feed  # per minute (``feed_rate``)

    def m_code_time(self, m: float, file: str, line: int) -> None:
        """The time of M code ``m``: a tool change (``tool_change``) or the machine file's."""
        if m == self.times.tool_change_m:
            self.tool_change(file, line)
        else:
            self.clock += self.times.m_seconds(m)

    def tool_change(self, file: str, line: int) -> None:
        """A tool change on ``line``: where a tool's part of the run starts (kept while moves
        are recorded, told to the observer), then its time."""
        if self.record_moves:
            tool = self.codes.get("T")
            self.tool_changes.append(ToolChange(file, line, tool, self.clock, self.cut_length, self.rapid_length))
        if self.observer is not None:
            self.observer.tool_changed(file, line)
        self.clock += self.times.timing.tool_change_seconds

    # ---------------------------------------------------------------- tools
    def select_tool(self, t: float) -> None:
        self.codes["T"] = t
        if not self.dialect.lathe:
            return
        n = int(t)
        offset = n % 100 if n >= 100 else n % 10
        ix = self.axis_index
        vec = [0.0] * len(self.pos)
        if offset:
            for axis, geometry, wear in (("X", 2700, 2000), ("Z", 2800, 2100), ("Y", 2450, 2400)):
                if axis in ix:
                    vec[ix[axis]] = (self.S.get(geometry + offset) or 0.0) + (self.S.get(wear + offset) or 0.0)
        self.tool_vector = vec

    def apply_length_offset(self, h: float) -> None:
        n = int(h)
        value = 0.0
        if n:
            geometry, wear = self.dialect.tool_offset_bases[:2]
            value = (self.S.get(geometry + n) or 0.0) + (self.S.get(wear + n) or 0.0)
        if self.modal.get("length") == 44.0:
            value = -value
        if "Z" in self.axis_index:
            self.tool_vector[self.axis_index["Z"]] = value

    # ---------------------------------------------------------------- one-shot codes
    def _one_shot(
        self, g: float, axes: dict[int, float], inc: dict[int, float], other: dict[str, float], file: str, line: int
    ) -> tuple[bool, float | None]:
        lathe = self.dialect.lathe
        if g == 4.0:  # dwell: P in the profile's unit, X or U in seconds (cycle_time.py)
            self.clock += self.times.dwell_seconds(other, next(iter({**axes, **inc}.values()), None))
            return False, None
        if g == 10.0:
            self._g10(axes, inc, other)
            return False, None
        if g in (28.0, 30.0):  # through the intermediate point to the reference point
            if axes or inc:
                middle = self._target(axes, inc)
                self._move(file, line, 0.0, middle)
                home = list(self.pos)
                for i in set(axes) | set(inc):
                    home[i] = 0.0 - (self.work_offset(i) + self.shift[i] + self.tool_vector[i]) + 0.0
                self._move(file, line, 0.0, home)
                return True, None
            return False, None
        if g == 31.0:  # skip: probing.py
            skip_block(cast("Machine", self), self._target(axes, inc), file, line)
            return True, None
        if g == 53.0:
            target = list(self.pos)
            for i, v in axes.items():
                target[i] = v - (self.work_offset(i) + self.shift[i] + self.tool_vector[i])
            self._move(file, line, self.modal.get("motion", 0.0), target)
            return bool(axes), None
        if g == self.dialect.coordinate_setting_code:
            for i, v in axes.items():
                self.shift[i] += self.pos[i] - v
                self.pos[i] = v
            return False, None
        if lathe and g in self.dialect.cycle_codes:
            target = self._target(axes, inc)
            self._record(file, line, g, tuple(self.pos), tuple(target))
            if g in LATHE_CYCLES_WITH_PROFILE and "P" in other and "Q" in other:
                return True, other["Q"]
            return bool(axes or inc), None
        if axes or inc:  # any other one-shot code with axis words: move in the modal mode
            mode = self.modal.get("motion", 0.0)
            target = self._target(axes, inc)
            self._move(file, line, mode, target, self._block_arc(mode, target, other))
            return True, None
        return False, None

    def _g10(self, axes: dict[int, float], inc: dict[int, float], other: dict[str, float]) -> None:
        l_value = other.get("L")
        p = int(other.get("P", 0.0))
        absolute = self.dialect.lathe or self.modal.get("distance", 90.0) == 90.0
        if l_value in (2.0, 20.0):
            if l_value == 2.0:
                if not 0 <= p <= 6:
                    raise MacroAlarm(
                        ARGUMENT_RANGE,
                        detail(
                            f"G10 L2 P{p}: P must be 0 (external) to 6 (G59)",
                            f"G10 L2 P{p}：P 必须为 0（外部偏置）～6（G59）",
                        ),
                    )
                base = WORK_BASE + 20 * p
            else:
                count = self.dialect.extra_offset_count
                if not 1 <= p <= count:
                    raise MacroAlarm(
                        ARGUMENT_RANGE,
                        detail(f"G10 L20 P{p}: P must be 1 to {count}", f"G10 L20 P{p}：P 必须在 1～{count} 之间"),
                    )
                base = self.dialect.extra_offset_variables + 20 * (p - 1)
            for i, v in axes.items():
                n = base + i
                self.S[n] = v if absolute else (self.S.get(n) or 0.0) + v
                self.written_system.add(n)
            for i, v in inc.items():
                n = base + i
                self.S[n] = (self.S.get(n) or 0.0) + v
                self.written_system.add(n)
            return
        if self.dialect.lathe:  # G10 P.. X.. Z.. R.. Q..: P < 10000 wear, P 10000+n geometry
            geometry = p >= 10000
            n = p % 10000
            ix = self.axis_index
            rows = {"X": (2700, 2000), "Z": (2800, 2100), "Y": (2450, 2400)}
            for letter, (g_base, w_base) in rows.items():
                if letter not in ix:
                    continue
                i = ix[letter]
                num = (g_base if geometry else w_base) + n
                if i in axes:
                    self.S[num] = axes[i]
                    self.written_system.add(num)
                if i in inc:
                    self.S[num] = (self.S.get(num) or 0.0) + inc[i]
                    self.written_system.add(num)
            if "R" in other:
                num = (2900 if geometry else 2200) + n
                self.S[num] = other["R"]
                self.written_system.add(num)
            if "Q" in other:
                self.S[2300 + n] = other["Q"]
                self.written_system.add(2300 + n)
            return
        bases = dict(zip((10.0, 11.0, 12.0, 13.0), self.dialect.tool_offset_bases, strict=True))
        if l_value in bases and "R" in other:
            num = bases[l_value] + p
            self.S[num] = other["R"] if absolute else (self.S.get(num) or 0.0) + other["R"]
            self.written_system.add(num)
