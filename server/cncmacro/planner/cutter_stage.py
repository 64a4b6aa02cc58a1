"""Cutter radius compensation: G41/G42 with D on a mill, with the T offset's tool nose radius on a
lathe, cancelled by G40 (docs/semantics.md, "Cutter radius compensation").

The planner's stage between a block's programmed move and its time: while ``Planner.cutter`` is
set, ``Planner.record`` hands each move here. The tool centre's end point of a block is known only
when the next block in the plane is (where the two offsets meet: offset_geometry.py), so the stage
runs one move behind: a move is recorded at once with a provisional centre path (ending on the
perpendicular of its end, as if nothing followed), and when the next move in the plane arrives
the corner between them is worked out and the earlier move's path, time and length are put right
in place (``Planner.moves``, the clock, the cut and rapid lengths). Straight cuts one after
another (a CAM contour) are joined by ``StraightCuts``, which in a run of plain lines also holds
the last move's record until its corner is known, and hands it back before anything else reads
the run. Moves off the plane in between
(a Z move) are made at the corner. Start-up is the first move in the plane after G41/G42 with a
D whose offset is not zero, cancel the first after G40; both are of type A or B as the machine
file's ``cutter_startup`` says. The radius is offset D's geometry plus wear, as the macro machine
keeps them (``Dialect.tool_offset_bases``; G10 L12/L13 write them). The control's answers: an arc
at start-up or cancel (PS0034), a corner whose offsets do not meet (PS0033), an offset path that
reverses a block or a cutter too large for an inside arc (PS0041), a plane change in G41/G42
(PS0037), a skip G31 in G41/G42 (PS0035, ``Dialect.skip_compensation_alarm``); where the
profile has no such alarms (``Dialect.cutter_alarms``) the interference and plane alarms are
notes the run goes past, and so is the skip without its switch.

On a lathe (tool nose radius compensation) the geometry is the same in the Z-X plane, X taken as a
radius (the plane's scale, ``MoveTimes.planes``: halved in, doubled back out), the radius and
the imaginary tool nose direction come from the offset the T code selects
(``Dialect.lathe_offsets``), and the programmed path is the imaginary tool nose's: outside offset
mode the nose centre is the tip's direction away from the programmed point, so a start-up starts
and a cancel ends there. The one-pass straight-cut join (``StraightCuts``) is the mill's only.
"""

from __future__ import annotations

from collections.abc import Callable, Generator
from math import dist, hypot, sqrt
from typing import TYPE_CHECKING, NamedTuple, TypeVar

from ..bilingual import detail
from ..dialects.alarms import (
    CUTTER_ARC_START,
    CUTTER_CORNER,
    CUTTER_INTERFERENCE,
    CUTTER_NO_INTERSECTION,
    CUTTER_PLANE,
    CUTTER_SKIP,
)
from .alarms import AlarmBeforeMove, MacroAlarm
from .arcs import ARC_MODES
from .cycle_time import INCH
from .machine_limits import Bounds, path_leaves_travel, program_bounds
from .moves import CentrePath, CentrePiece, Move
from .offset_geometry import (
    EPSILON,
    MEET,
    PERPENDICULAR_AFTER,
    PERPENDICULAR_BEFORE,
    Corner,
    NoIntersection,
    PathElement,
    centre_segment,
    join,
    offset_element,
    perpendicular_end,
    reverses,
)
from .tool_offsets import lathe_offset_number

if TYPE_CHECKING:
    from .planner import Planner

LEFT, RIGHT, CANCEL = 41.0, 42.0, 40.0
SAME, SWITCH = "same", "switch"  # ``CutterStage.written``
_T = TypeVar("_T")
_MOVE_MODES = frozenset((0.0, 1.0, 2.0, 3.0))
_Point = tuple[float, ...]
_Scale = tuple[float, float] | None  # a lathe plane's units per program unit (X a diameter), None on a mill
_Cut = tuple[int, float, float, _Point, _Point]  # a straight cut joined: its line, mode, feed, start and end
_Joined = tuple[float, float, float]  # the last move's seconds put right, this one's, the change in cut length
# ``StraightCuts``' state while its joins are under way: the last move (line, mode, feed, start, end),
# its end in the plane (px, py), direction and length (tx, ty, l), the centre path's start
# (cx, cy, s0), its seconds a unit of length, move off the plane, length and seconds, and
# where its record is (place, hold, held, fresh)
_State = tuple[int, float, float, _Point, _Point, float, float, float, float, float, float, float,
               _Point | None, float, float, float, float, int, bool, bool, bool]  # fmt: skip


class Pending(NamedTuple):
    """The last move in the plane, whose centre path waits for the next one: its place in
    ``Planner.moves`` (-1 when moves are not recorded), its line, mode, feed, unit (25.4 under
    G20) and plane, its programmed start and end, its programmed element in the plane and signed
    offset (left positive), its provisional centre path and time, whether it is the start-up
    block, the places of the moves off the plane recorded since, the seconds per program unit of
    its path (0 for a rapid), its provisional path's length and the square of its move along the
    axes off the plane, and its file (the over-travel alarm found when its path is settled stands on it)."""

    place: int
    line: int
    mode: float
    feed: float
    unit: float
    plane: float
    start: _Point
    end: _Point
    element: PathElement
    d: float
    path: CentrePath
    seconds: float
    startup: bool
    between: tuple[int, ...]
    per_length: float
    length: float
    off_plane: float
    file: str


class CutterStage:
    """The compensation state of one run: the modal code (41, 42, or 40 with a cancel to come),
    whether the offset is established, the plane it was started in, the start-up type, the move
    waiting for the next, the offsets already noted as having no value, and the indexes of the
    plane's two axes and where offset D's geometry and wear are kept."""

    __slots__ = (
        "axes", "bases", "code", "lathe", "moved", "noted", "on", "pending", "plane", "resume", "type_b", "written",
    )  # fmt: skip

    def __init__(
        self, code: float, plane: float, type_b: bool, axes: tuple[int, int] = (0, 1),
        bases: tuple[int, int] = (13000, 12000), lathe: bool = False,
    ) -> None:  # fmt: skip
        self.code = code
        self.on = False
        self.plane = plane
        self.axes = axes  # the plane's two axes (indexes)
        self.bases = bases  # where offset D's geometry and wear are kept (#base + D)
        self.type_b = type_b
        self.lathe = lathe  # tool nose radius compensation: the T offset's radius and tip, X a diameter
        self.pending: Pending | None = None
        self.noted: frozenset[int] = frozenset()
        # G41/G42 written again in offset mode, for the next move in the plane: SAME side (the
        # previous block ends on its perpendicular) or a SWITCH of side; "" when not
        self.written = ""
        # the coordinate system moved since the pending move (``frame_moved``): that move and how
        # far its points go to be in the coordinates now in force (the plane's units)
        self.moved: tuple[Pending, float, float] | None = None
        # where the tool centre is after a shift set the compensation aside (GSK980TDi): the next
        # start-up starts there
        self.resume: _Point | None = None

    def copy(self) -> CutterStage:
        c = CutterStage(self.code, self.plane, self.type_b, self.axes, self.bases, self.lathe)
        c.on, c.pending, c.noted, c.written = self.on, self.pending, self.noted, self.written
        c.moved, c.resume = self.moved, self.resume
        return c


def cutter_code(p: Planner, group: str, g: float, line: int) -> None:
    """A block's G code of the ``cutter`` group (G40, G41, G42) or, while the offset is on, of the
    ``plane`` group: start, keep or cancel the stage (before the modal code is set)."""
    stage = p.cutter
    shape = p.shape
    if shape is not None and (_outside_first_block(p, group, g, line) or shape.reading):
        return  # a roughing cycle's shape is read, not cut: its passes are drawn as programmed (§12)
    if group == "plane":
        if stage is not None and stage.on and g != stage.plane:
            _finding(p, CUTTER_PLANE, "cutter-plane", line,
                     detail(f"G{g:g} changes the plane while cutter radius compensation (G41/G42) is on: cancel it "
                            "with G40 first",
                            f"刀具半径补偿（G41/G42）有效时用 G{g:g} 变更了平面：请先用 G40 取消补偿"))  # fmt: skip
        elif stage is not None and not stage.on:  # before the start-up: the plane it starts in
            ij = p.times.planes.get(g)
            stage.plane, stage.axes = g, (ij[0], ij[1]) if ij else (0, 1)
        return
    if g in (LEFT, RIGHT):
        if stage is None:
            plane = p.modal.get("plane", 17.0)
            ij = p.times.planes.get(plane)
            bases = p.dialect.lathe_offsets.radius if p.lathe else p.dialect.tool_offset_bases[2:4]
            p.cutter = CutterStage(g, plane, p.settings.cutter_startup == "B", (ij[0], ij[1]) if ij else (0, 1),
                                   (bases[0], bases[1]), p.lathe)  # fmt: skip
        else:
            if stage.on and g != stage.code:  # a change of side: the next move in the plane reads it
                stage.written = SWITCH
            elif stage.on and p.dialect.repeated_side_perpendicular:  # FANUC: the previous block ends
                stage.written = SAME  # on its perpendicular (``cutter_move``)
            stage.code = g
    elif stage is not None:
        stage.code = CANCEL
        stage.written = ""
        if not stage.on:
            p.cutter = None


def _outside_first_block(p: Planner, group: str, g: float, line: int) -> bool:
    """Whether a G41/G42 of a G70 shape's block is to be passed over: on a profile that compensates
    a shape only from its first block N(ns) (``Dialect.shape_compensation_first_block``: GSK980TDi
    §3.23.1), one on a later block does not compensate the cycle, which the run notes (a warning:
    the manual gives no alarm). One on the first block marks the shape compensated."""
    shape = p.shape
    if shape is None or group != "cutter" or g not in (LEFT, RIGHT) or not p.dialect.shape_compensation_first_block:
        return False
    if shape.first_axes is None:  # the first block: it names the shape's first axes after its G codes
        shape.compensated = True
        return False
    p.host.note("cycle", detail(
        f"G{g:g} on a block after the shape's first: this control compensates a G70-G73 shape only when G41/G42 "
        "is on its first block N(ns); the shape is cut as programmed",
        f"G{g:g} 不在精车形状的第一段：本系统仅当 G41/G42 在形状的第一段 N(ns) 时才对 G70-G73 形状进行刀尖半径补偿；"
        "形状按编程轨迹切削"), line, "cycle-shape")  # fmt: skip
    return True


# the one-shot codes whose moves are made as programmed, the offset taken up again from the
# programmed point at the next move in the plane (FANUC: G28 "cancels the offset vector at the
# intermediate position"; G30, G53 and the skip G31 likewise here)
UNCOMPENSATED_CODES = frozenset((28.0, 30.0, 31.0, 53.0))


def skip_in_offset(p: Planner, code: float, line: int) -> None:
    """A skip (``Dialect.skip_codes``: G31) commanded while G41/G42 is in force: the control's
    alarm where the profile has one (``Dialect.skip_compensation_alarm``: FANUC PS0035, Mitsubishi
    P608), else a warning the run goes past (GSK980TDi §3.16 and Haas ask for G40 first and name
    no alarm), the skip then made as programmed (``uncompensated``)."""
    stage = p.cutter
    if stage is None or stage.code not in (LEFT, RIGHT):
        return
    message = detail(
        f"G{code:g} (skip) while cutter radius compensation (G{stage.code:g}) is in force: the control takes a "
        "skip only with the compensation cancelled; cancel it with G40 before the skip",
        f"刀具半径补偿（G{stage.code:g}）有效时指令了 G{code:g}（跳转）：系统只在取消补偿后执行跳转；"
        "请在跳转前用 G40 取消补偿",
    )
    if p.dialect.skip_compensation_alarm:
        raise MacroAlarm(CUTTER_SKIP, message, "cutter-skip")
    p.host.note("cutter", message, line, "cutter-skip")


def uncompensated(p: Planner, run: Callable[[], _T]) -> _T:
    """``run`` (a one-shot code's moves) with compensation set aside: the pending move keeps its
    path to the perpendicular of its end, the moves of ``run`` are drawn as programmed, and the
    next move in the plane starts the offset again (a start-up from where the tool is)."""
    stage = p.cutter
    if stage is not None and stage.on and stage.pending is not None and p.travel is not None:
        pending = stage.pending  # its path to its end's perpendicular is the one made
        if stage.moved is None or stage.moved[0] is not pending:
            _pending_travel(p, pending, pending.path, stage.axes[0], stage.axes[1], _lathe_scale(p, stage))
    p.cutter = None
    try:
        return run()
    finally:
        if stage is not None:
            stage.on = False
            stage.pending = None
            stage.written = ""
            stage.resume = None
            p.cutter = stage if stage.code != CANCEL else None


def cutter_radius(p: Planner, line: int) -> float:
    """The radius offset D in force holds: its geometry plus its wear (half of it where the machine
    file's ``cutter_offset`` says the offsets hold diameters), 0 for D0 (no D yet) or an offset
    the run has no value for (noted once per offset number)."""
    if p.lathe:
        return nose_radius(p, line)
    d = p.codes.get("D")
    n = int(d) if d is not None else 0
    if n <= 0:
        return 0.0
    geometry, wear = p.dialect.tool_offset_bases[2:4]
    value = stored_radius(p, (geometry, wear), n)
    if value is None:
        stage = p.cutter
        if stage is not None and n not in stage.noted:
            stage.noted = stage.noted | {n}
            p.host.note("cutter", detail(
                f"D{n} has no value in this run (#{geometry + n}, #{wear + n}): the tool centre is drawn on the "
                "programmed path; give the offset in the machine file's [variables] or with G10 L12",
                f"本次运行中 D{n} 没有数值（#{geometry + n}、#{wear + n}）：刀具中心按编程轨迹绘制；"
                "请在机床文件的 [variables] 中或用 G10 L12 给出该补偿值"), line, "cutter-offset")  # fmt: skip
        return 0.0
    return value


def nose_radius(p: Planner, line: int) -> float:
    """On a lathe: the tool nose radius of the offset the T code selects (T0101: offset 1), its
    geometry plus its wear (``Dialect.lathe_offsets``; ``G10 P.. R..`` writes them), 0 for offset 0
    or one the run has no value for (noted once per offset number, as ``cutter_radius`` does)."""
    n = lathe_offset_number(p.codes.get("T") or 0.0)
    if n <= 0:
        return 0.0
    geometry, wear = p.dialect.lathe_offsets.radius
    stored = p.host.stored
    g, w = stored(geometry + n), stored(wear + n)
    if g is not None or w is not None:
        return (g or 0.0) + (w or 0.0)
    stage = p.cutter
    if stage is not None and n not in stage.noted:
        stage.noted = stage.noted | {n}
        p.host.note("cutter", detail(
            f"tool offset {n:02d} has no tool nose radius in this run (#{geometry + n}, #{wear + n}): the tool nose "
            f"is drawn on the programmed path; give it in the machine file's [variables] or with G10 P{n} R..",
            f"本次运行中刀补 {n:02d} 没有刀尖半径（#{geometry + n}、#{wear + n}）：刀尖按编程轨迹绘制；"
            f"请在机床文件的 [variables] 中或用 G10 P{n} R.. 给出该值"), line, "cutter-offset")  # fmt: skip
    return 0.0


def _tip(p: Planner, radius: float, i: int, j: int) -> tuple[float, float]:
    """Where the imaginary tool nose of the offset the T code selects lies from the nose centre,
    in the plane's axes ``i`` and ``j`` (a radius along X): its direction (``Dialect.lathe_offsets``'s
    tip, 0-9; another number, or none, is 0) times ``radius``. (0, 0) off a lathe."""
    if not p.lathe or not radius:
        return (0.0, 0.0)
    offsets = p.dialect.lathe_offsets
    n = lathe_offset_number(p.codes.get("T") or 0.0)
    tip = p.host.stored(offsets.tip + n) if n > 0 else None
    k = int(tip) if tip is not None and tip == int(tip) and 0 <= tip < len(offsets.tips) else 0
    sx, sz = offsets.tips[k]
    names = p.dialect.axes
    signs = {"X": sx, "Z": sz}
    return signs.get(names[i], 0) * radius, signs.get(names[j], 0) * radius


def stored_radius(p: Planner, bases: tuple[int, int], n: int) -> float | None:
    """Offset ``n``'s radius from its geometry and wear at ``bases`` (``#base + n``), halved where
    the machine file's ``cutter_offset`` says they hold diameters; None when neither has a value."""
    stored = p.host.stored
    g, w = stored(bases[0] + n), stored(bases[1] + n)
    if g is None and w is None:
        return None
    value = (g or 0.0) + (w or 0.0)
    return value * 0.5 if p.settings.cutter_offset == "diameter" else value


def _finding(p: Planner, number: int, subject: str, line: int, message: str) -> None:
    """The control's alarm ``number`` where the profile has the cutter alarms, else a note."""
    if p.dialect.cutter_alarms:
        raise MacroAlarm(number, message, subject)
    p.host.note("cutter", message, line, subject)


def _full(plane_point: tuple[float, float], like: _Point, i: int, j: int, scale: _Scale = None) -> _Point:
    """``like`` with its plane axes ``i`` and ``j`` at ``plane_point`` (a lathe's X doubled back to a
    diameter: ``scale``, the plane's units per program unit, ``MoveTimes.planes``)."""
    out = list(like)
    if scale is None:
        out[i], out[j] = plane_point
    else:
        out[i], out[j] = plane_point[0] / scale[0], plane_point[1] / scale[1]
    return tuple(out)


def cutter_move(
    p: Planner, file: str, line: int, mode: float, plane: float, start: _Point, end: _Point, centre: _Point | None,
    feed: float, unit: float,
) -> tuple[CentrePath, float] | None:  # fmt: skip
    """The centre path of a move (and its seconds, its length added to the run's) while the stage
    is set; None when the move is not compensated (no offset on, a move of another kind)."""
    stage = p.cutter
    assert stage is not None
    axes = p.times.planes.get(stage.plane)
    if axes is None or mode not in _MOVE_MODES:
        return None
    i, j = axes[0], axes[1]
    scale = _lathe_scale(p, stage) if stage.lathe else None
    in_plane = centre is not None or start[i] != end[i] or start[j] != end[j]
    if not stage.on:
        if not in_plane:
            return None
        d = cutter_radius(p, line)
        if d == 0.0:
            return None
        if mode in ARC_MODES:
            _arc_finding(p, _arc_message("G41/G42", "start-up", "建立"), line)
            return None
        _rounded_corner(p, "start-up", "建立")
        stage.on = True
        first = _plane_point(start, i, j, scale)
        element = PathElement(first, _plane_point(end, i, j, scale))
        tip = _tip(p, abs(d), i, j)  # outside offset mode the programmed point is the imaginary tool nose's
        begin = _full((first[0] - tip[0], first[1] - tip[1]), start, i, j, scale) if tip != (0.0, 0.0) else start
        if stage.resume is not None:  # the compensation set aside by a shift: from where the centre is
            begin, stage.resume = _full(_plane_point(stage.resume, i, j, scale), start, i, j, scale), None
        d = d if stage.code == LEFT else -d
        return _provisional(p, (file, line), mode, plane, element, d, begin, start, end, None, feed, unit, True, i, j)
    written = stage.written if in_plane else ""
    if centre is None and in_plane and mode != 0.0 and not written:  # a straight cut after one: joined in one pass
        joined = _straight_after_straight(p, file, line, mode, plane, start, end, feed)
        if joined is not None:
            return joined
    pending = stage.pending
    if not in_plane:  # a move off the plane: made where the tool centre is
        at = _plane_point(start if pending is None else pending.path.pieces[-1].end, i, j, scale)
        moved = stage.moved
        if moved is not None and moved[0] is pending:
            at = (at[0] + moved[1], at[1] + moved[2])
        path = CentrePath(_full(at, start, i, j, scale), (CentrePiece(_full(at, end, i, j, scale)),))
        if pending is not None and p.record_moves:
            stage.pending = pending._replace(between=(*pending.between, len(p.moves)))
        return path, _cost(p, mode, path, feed, unit, plane, start, end)
    if stage.code == CANCEL:
        return _cancel_move(p, stage, line, mode, plane, start, end, feed, unit, scale)
    d = cutter_radius(p, line)
    d = d if stage.code == LEFT else -d
    element = _element(mode, start, end, centre, i, j, scale)
    if centre is not None and offset_element(element, d) is None:
        radius = _arc_radius(element)
        _finding(p, CUTTER_INTERFERENCE, "cutter-interference", line, detail(
            f"the cutter (radius {abs(d):g}) is too large for this arc of radius {radius:g}: its centre cannot "
            "follow it on the inside",
            f"刀具（半径 {abs(d):g}）大于此圆弧（半径 {radius:g}）：刀具中心无法在内侧沿其移动"))  # fmt: skip
        d = 0.0
    begin = _plane_point(start, i, j, scale)
    stage.written = ""
    if written == SWITCH:
        _rounded_corner(p, "change of side", "切换")
    if pending is not None:
        outer = PERPENDICULAR_AFTER if pending.startup and not stage.type_b else MEET
        here, mx, my = _in_frame(stage, pending)
        if written == SAME:  # FANUC: "a right angle to the moving direction in the previous block"
            q = perpendicular_end(here.element, here.d)
            corner = Corner(q, (), q)
        else:
            corner = _corner(p, here, element, d, outer, line)
        _settle(p, pending, _moved_corner(corner, -mx, -my), line, i, j, scale, not mx and not my)
        begin = corner.after_start
    return _provisional(p, (file, line), mode, plane, element, d, _full(begin, start, i, j, scale), start, end, centre,
                        feed, unit, False, i, j)  # fmt: skip


def _cancel_move(
    p: Planner, stage: CutterStage, line: int, mode: float, plane: float, start: _Point, end: _Point, feed: float,
    unit: float, scale: _Scale,
) -> tuple[CentrePath, float] | None:  # fmt: skip
    """The cancel: the first move in the plane after G40 (``cutter_move``), from the corner with
    the pending move to the programmed end (on a lathe the tip's vector away from it)."""
    i, j = p.times.planes[stage.plane][:2]
    pending = stage.pending
    arc = mode in ARC_MODES
    if arc:
        _arc_finding(p, _arc_message("G40", "cancel", "取消"), line)
    _rounded_corner(p, "cancel", "取消")
    begin = _plane_point(start, i, j, scale)
    last = _plane_point(end, i, j, scale)
    if pending is not None:
        outer = PERPENDICULAR_BEFORE if arc or not stage.type_b else MEET
        here, mx, my = _in_frame(stage, pending)
        corner = _corner(p, here, PathElement(begin, last), pending.d, outer, line)
        _settle(p, pending, _moved_corner(corner, -mx, -my), line, i, j, scale, not mx and not my)
        begin = corner.after_start
    stage.on = False
    stage.pending = None
    p.cutter = None
    if arc:  # a profile without the alarm: the arc as programmed
        return None
    tip = _tip(p, abs(nose_radius(p, line)), i, j) if stage.lathe else (0.0, 0.0)  # its tip ends on the end
    finish = _full((last[0] - tip[0], last[1] - tip[1]), end, i, j, scale) if tip != (0.0, 0.0) else end
    path = CentrePath(_full(begin, start, i, j, scale), (CentrePiece(finish),))
    return path, _cost(p, mode, path, feed, unit, plane, start, end)


_tuple_new = tuple.__new__  # a named tuple without its constructor's keyword handling


def _straight_after_straight(
    p: Planner, file: str, line: int, mode: float, plane: float, start: _Point, end: _Point, feed: float
) -> tuple[CentrePath, float] | None:
    """A compiled line's straight cut after a straight cut, joined by ``StraightCuts`` as a run
    of plain lines joins it: its provisional path and seconds (``Planner.record`` records it),
    None for a case the general way takes."""
    cuts = StraightCuts(p, file, False)
    if not cuts.take_over(plane):
        return None
    joined = cuts.cut((line, mode, feed, start, end))
    if joined is None:
        return None
    correction, seconds, change = joined
    p.clock += correction
    p.cut_length += change
    cuts.flush()
    return cuts.stage.pending.path, seconds  # type: ignore[union-attr]


class StraightCuts:
    """Straight cuts one after another under compensation, the common case of a CAM contour: a
    cut after a cut, both straight, at the same offset, in the same unit and plane, each corner
    worked out as ``offset_geometry.join`` works it out (a tangent needs no corner, an inside or
    obtuse corner ends at the intersection, P + d (n1 + n2) / (1 + t1·t2) for offsets of one
    distance d, an acute outside one goes through the two extension points), the earlier move's
    path, time and length put right in place.

    ``take_over`` takes the stage's pending move when it is such a cut. From then on the last
    move's state is kept here (in the locals of ``_joins`` while cuts come, in the slots when
    they stop), its direction and length carried to the next corner, and ``stage.pending`` is
    out of date until ``flush`` writes it back (a ``Pending`` with the provisional path, as the
    general way keeps it). The radius, unit and plane are read once: no plain motion line
    changes them. With ``hold`` (a run of plain lines that records its
    own moves: machine/straight_runs.py) the last move's record waits here too and is made once,
    with its path put right, when the next cut comes, or with its provisional path at ``flush``:
    whoever else records a move or reads the run (``Planner.record``, the end of the run of
    plain lines) has it flushed first."""

    __slots__ = (
        "active", "ax", "ay", "cx", "cy", "d", "end", "feed", "file", "fresh", "held", "hold", "i", "j",
        "l", "length", "line", "mode", "off", "p", "per", "place", "plane", "px", "py", "s0", "seconds", "send",
        "stage", "start", "tx", "ty", "unit", "xy",
    )  # fmt: skip

    def __init__(self, p: Planner, file: str, hold: bool) -> None:
        self.s0: _Point | None = None
        self.p = p
        self.file = file
        self.hold = hold
        self.active = False  # the last move's state is here (``stage.pending`` out of date)
        self.held = False  # and its record too, not yet in ``Planner.moves``
        self.send: Callable[[_Cut | None], _Joined | None] | None = None  # the joins' own, while they are under way

    def take_over(self, plane: float | None = None) -> bool:
        """Take the stage's pending move if it is a straight cut the next one can join here
        (``plane``: the one the next move is in, which must be the pending one's; None for a
        plain line, which cannot change it)."""
        p = self.p
        stage = p.cutter
        if stage is None or stage.lathe or stage.code == CANCEL or stage.written or stage.moved is not None:
            return False
        pending = stage.pending
        if (pending is None or not pending.per_length or pending.element[2] is not None or pending.startup
                or pending.between or (plane is not None and plane != pending.plane)):  # fmt: skip
            return False
        if (INCH if p.modal["units"] == 20.0 else 1.0) != pending.unit or _signed_radius(p, stage) != pending.d:
            return False
        self.stage = stage
        self.i, self.j = stage.axes
        self.xy = stage.axes == (0, 1)
        self.d, self.unit, self.plane = pending.d, pending.unit, pending.plane
        (ax, ay), (px, py) = pending.element[0], pending.element[1]
        length = self.l = hypot(px - ax, py - ay)
        self.ax, self.ay, self.px, self.py = ax, ay, px, py
        self.tx, self.ty = (px - ax) / length, (py - ay) / length
        s0 = self.s0 = pending.path[0]
        self.cx, self.cy = s0[self.i], s0[self.j]
        self.line, self.mode, self.feed, self.start, self.end = (pending.line, pending.mode, pending.feed,
                                                                 pending.start, pending.end)  # fmt: skip
        self.per, self.off, self.length, self.seconds = (pending.per_length, pending.off_plane, pending.length,
                                                         pending.seconds)  # fmt: skip
        self.place = pending.place
        self.hold = self.hold and p.record_moves  # none once the toolpath is full
        self.held = False
        self.fresh = True
        self.active = True
        return True

    def begin(self, cut: _Cut) -> _Joined | None:
        """``cut`` while no join is under way: take the stage's pending move over, if it is a
        straight cut this one can join, and start the joins with this one."""
        if not self.active and not self.take_over():
            return None
        joins = self._joins()
        next(joins)
        self.send = joins.send
        return joins.send(cut)

    def _joins(self) -> Generator[_Joined | None, _Cut | None, None]:  # noqa: C901, PLR0912, PLR0915 (one loop on purpose, as straight_runs.py)
        """The joins of one take-over, one cut sent at a time, the last move's state held in this
        frame's locals (a CAM contour sends a hundred thousand: slots read and written a move
        were a third of its cost). Each straight cut ``(line, mode, feed, start, end)`` after the
        last one gets the corner between them: the last move put right (its record made, with
        ``hold``), this one the last in its turn, and ``(correction, seconds, change)`` back: the
        caller adds ``correction`` (the last move's seconds put right) and then ``seconds`` (this
        one's provisional seconds) to the clock, and ``change`` to the cut length. A case left to
        the general way gets None, and a None sent (``flush``) ends the joins: either way the
        state goes back to the slots and ``stage.pending`` is written back."""
        p = self.p
        moves = p.moves
        record = p.record_moves
        budget = p.move_budget
        file, i, j, xy, d, unit, plane = self.file, self.i, self.j, self.xy, self.d, self.unit, self.plane
        line, mode, feed, start, end = self.line, self.mode, self.feed, self.start, self.end
        px, py, tx, ty, l1 = self.px, self.py, self.tx, self.ty, self.l
        # the axes off the plane, when there are at most two (X, Y, Z and A: Z and A), looked at
        # one by one to see a move stay in the plane; -1 for more, whose moves ``dist`` measures
        others = [k for k in range(len(end)) if k not in (i, j)] or [i]
        k1, k2 = (others[0], others[-1]) if len(others) <= 2 else (-1, -1)
        cx, cy, s0 = self.cx, self.cy, self.s0
        per, off, length, seconds = self.per, self.off, self.length, self.seconds
        place, hold, held, fresh = self.place, self.hold, self.held, self.fresh
        least = -EPSILON  # the reversal a move of 1 may show before it is one (more in proportion to a longer move)
        keeps = hold or record or place >= 0  # moves are recorded
        points = keeps and p.centre_paths  # with their centre paths (the corners' points with them)
        # the machine's travel in the plane (machine_limits.py), which the corners are held to: a
        # corner inside it keeps the path to it inside (a straight piece leaves only where it ends out)
        limits = _plane_limits(p, i, j)
        corners = points or limits is not None
        # what a record reads that changes less often than moves come: the feed as a record holds
        # it, the room left in the toolpath, the axes after X and Y of the last move's end (on a
        # mill in G17: the rest of a centre point), kept while the moves stay in the plane
        kept_feed = float(feed)
        room = budget - len(moves) - 1
        tail = end[2:]  # (made again from the first cut's start: a move off the plane may have come between)
        tails = points and xy  # a tail is read (a centre point on a mill in G17)
        retail = tails and not (k1 == 2 and k2 == len(end) - 1)  # made again each move: more axes than Z and A
        # The last move's reach: how far its provisional centre path goes along its direction,
        # from the corner it starts at to its end's perpendicular. Every corner is on the lines of
        # both moves' offsets (or, at an acute outside corner, one extension point on each), so
        # a path's length in the plane is its reach, and the corner after it moves its end along
        # the line by a share of the offset that the corner's kind gives (``back``), and the
        # next path's start (``ahead``); no point need be made where no path is. Not yet known
        # for the move taken over (``fresh``), whose start an interference may have put off its line.
        reach = 0.0
        joined: _Joined | None = None
        while True:
            cut = yield joined
            if cut is None:
                break
            new_line, new_mode, new_feed, new_start, new_end = cut
            ex, ey = new_end[i], new_end[j]
            if (ex == px and ey == py) or new_mode != mode:
                break
            dx, dy = ex - px, ey - py
            l2 = hypot(dx, dy)
            t2x, t2y = dx / l2, dy / l2
            cross, dot = tx * t2y - ty * t2x, tx * t2x + ty * t2y
            link = False
            if -1e-12 <= cross <= 1e-12 and dot > 0.0:  # straight on
                back, ahead = 0.0, -d * cross
                if corners or fresh:
                    bx, by = px - ty * d, py + tx * d
                    nx, ny = bx, by
            elif cross * d > 0.0 or dot >= 0.0:  # inside or obtuse: where the two offsets cross
                if dot <= -1.0 + 1e-9:
                    break
                k = d / (1.0 + dot)
                back = ahead = -k * cross
                if corners or fresh:
                    bx, by = px - k * (ty + t2y), py + k * (tx + t2x)
                    nx, ny = bx, by
            else:  # acute outside: through the two extension points
                r = back = ahead = -d if d < 0.0 else d
                bx, by = px - ty * d + tx * r, py + tx * d + ty * r
                nx, ny = px - t2y * d - t2x * r, py + t2x * d - t2y * r
                link = True
            # the last move's centre path in the plane, from its start to the corner
            along = (bx - cx) * tx + (by - cy) * ty if fresh else reach + back
            if along < least and along < least * (l1 if l1 > 1.0 else 1.0):
                # the control's alarm leaves the joins (nothing changed yet); a note goes on here
                if not fresh:
                    cx, cy = px - ty * d - reach * tx, py + tx * d - reach * ty
                self._keep((line, mode, feed, start, end, px, py, tx, ty, l1, cx, cy, s0, per, off,
                           length, seconds, place, hold, held, fresh))  # fmt: skip
                own, self.send = self.send, None
                _reversal(p, new_line, line, place, start, mode, plane, unit, seconds, length)
                self.send, own = own, None
            if limits is not None and (
                not (limits[0] <= bx <= limits[1] and limits[2] <= by <= limits[3])
                or (link and not (limits[0] <= nx <= limits[1] and limits[2] <= ny <= limits[3]))
            ):  # a corner out of the travel: the last move stops where its path leaves it
                if not fresh:
                    cx, cy = px - ty * d - reach * tx, py + tx * d - reach * ty
                self._keep((line, mode, feed, start, end, px, py, tx, ty, l1, cx, cy, s0, per, off,
                           length, seconds, place, hold, held, fresh))  # fmt: skip
                own, self.send = self.send, None
                ends = ((bx, by), (nx, ny)) if link else ((bx, by),)
                made = CentrePath(_full((cx, cy), start, i, j), tuple(CentrePiece(_full(q, new_start, i, j))
                                                                      for q in ends))  # fmt: skip
                _pending_travel(p, Pending(place, line, mode, feed, unit, plane, start, end, PathElement(
                    (start[i], start[j]), (px, py)), d, made, seconds, False, (), per, length, off, self.file),
                    made, i, j, None)  # fmt: skip
                self.send, own = own, None
            # the last move, now that its corner is known: its length and time put right
            if fresh:
                ux, uy = bx - cx, by - cy
                settled = sqrt(ux * ux + uy * uy + off)
                tail = new_start[2:]
            elif off == 0.0:
                settled = along if along >= 0.0 else -along
            else:
                settled = sqrt(along * along + off)
            if link:
                settled += hypot(nx - bx, ny - by)
            settled_seconds = settled * per
            correction = settled_seconds - seconds
            if keeps:  # its record: made (held) or put right, with its centre path to the corner
                path: CentrePath | None = None  # none kept (``Planner.centre_paths``)
                if points and (held or place >= 0):
                    first = (bx, by) + tail if xy else _full((bx, by), new_start, i, j)  # noqa: RUF005 (half the time)
                    piece = _tuple_new(CentrePiece, (first, None, False))
                    if link:
                        second = _full((nx, ny), new_start, i, j)
                        pieces: tuple[CentrePiece, ...] = (piece, _tuple_new(CentrePiece, (second, None, False)))
                    else:
                        second, pieces = first, (piece,)
                    if s0 is None:
                        if not fresh:
                            cx, cy = px - ty * d - reach * tx, py + tx * d - reach * ty
                        s0 = _full((cx, cy), start, i, j)
                    path = _tuple_new(CentrePath, (s0, pieces))
                if held:
                    moves.append(_tuple_new(Move, (file, line, mode, start, end, kept_feed, None, settled_seconds,
                                                   plane, None, None, None, path, None)))  # fmt: skip
                    room -= 1
                elif 0 <= place < len(moves) and moves[place][1] == line:
                    old = moves[place]
                    moves[place] = _tuple_new(Move, (*old[:7], settled_seconds, *old[8:12], path, *old[13:]))
                s0 = second if path is not None else None
            else:  # an analysis: no record, and the next path's start made only if asked for
                s0 = None
            # this move, the last in its turn: from the corner to its end's perpendicular
            # (the state is set in place, each name once its old value is used: a move's worth of
            # names packed and unpacked at once was a sixth of the join's time)
            if k1 >= 0 and new_start[k1] == new_end[k1] and new_start[k2] == new_end[k2]:
                off = 0.0
                if retail:
                    tail = new_end[2:]
            else:
                if tails:
                    tail = new_end[2:]
                whole = dist(new_start, new_end)
                off = whole * whole - l2 * l2
                if off < 1e-9:  # in the plane (but for the rounding of the squares)
                    off = 0.0
            reach = l2 + ahead
            change = settled - length
            if off == 0.0:
                length = reach if reach >= 0.0 else -reach
            else:
                length = sqrt(reach * reach + off)
            if new_feed != feed:
                per = p.feed_seconds(new_mode, 1.0, new_feed, new_start, new_end, unit)
                feed = new_feed
                kept_feed = float(feed)
            seconds = length * per
            joined = (correction, seconds, (change + length) * unit)
            line, start, end = new_line, new_start, new_end
            px, py = ex, ey
            tx, ty = t2x, t2y
            l1 = l2
            fresh = False
            if not keeps:
                continue
            if not hold:
                place = len(moves) if record else -1
            elif room > 0:
                held = True
            else:  # this move fills the toolpath: recorded now, and no move after it
                cx, cy = px - ty * d - reach * tx, py + tx * d - reach * ty
                self._keep((line, mode, feed, start, end, px, py, tx, ty, l1, cx, cy, s0, per, off,
                           length, seconds, place, hold, True, fresh))  # fmt: skip
                self._end()
                self.hold = False
                p.moves_full(line)
                yield joined
                return
        if not fresh:  # the last corner, on the last move's line at its reach before the end's perpendicular
            cx, cy = px - ty * d - reach * tx, py + tx * d - reach * ty
        self._keep((line, mode, feed, start, end, px, py, tx, ty, l1, cx, cy, s0, per, off, length,
                   seconds, place, hold, held, fresh))  # fmt: skip
        self._end()
        yield None

    def _keep(self, state: _State) -> None:
        """The joins' state back in the slots, where ``flush`` and the next take-over read it."""
        (line, mode, feed, start, end, px, py, tx, ty, l1, cx, cy, s0, per, off, length, seconds,
         place, hold, held, fresh) = state  # fmt: skip
        self.line, self.mode, self.feed, self.start, self.end = line, mode, feed, start, end
        self.ax, self.ay, self.px, self.py, self.tx, self.ty, self.l = start[self.i], start[self.j], px, py, tx, ty, l1
        self.cx, self.cy, self.s0 = cx, cy, s0
        self.per, self.off, self.length, self.seconds = per, off, length, seconds
        self.place, self.hold, self.held, self.fresh = place, hold, held, fresh

    def _end(self) -> None:
        """The joins are over (their state kept): the last move back to the stage."""
        self.send = None
        self._flush()

    def _path_start(self) -> _Point:
        """Where the last move's centre path starts: its corner with the move before."""
        s0 = self.s0
        if s0 is None:
            s0 = self.s0 = _full((self.cx, self.cy), self.start, self.i, self.j)
        return s0

    def cut(self, cut: _Cut) -> _Joined | None:
        """One straight cut ``(line, mode, feed, start, end)`` after the last one, joined
        (``_joins``): ``(correction, seconds, change)``, or None for a case left to the general
        way, with nothing changed but ``stage.pending`` written back. A run of plain lines calls
        ``send`` itself while it is not None, ``begin`` when it is."""
        send = self.send
        return send(cut) if send is not None else self.begin(cut)

    def flush(self) -> None:
        """Hand the last move back to the stage as the general way keeps it, with its path to
        its end's perpendicular: ``stage.pending`` and (``hold``) its record."""
        send = self.send
        if send is None:
            self._flush()
            return
        try:
            send(None)
        except StopIteration:  # the joins ended on an error of their own: what the slots hold
            self.send = None
            self._flush()

    def _flush(self) -> None:
        """``flush`` from the slots."""
        if not self.active:
            return
        self.active = False
        if self.fresh:  # taken over, nothing cut since: the stage's pending is as it was
            return
        p = self.p
        end = self.end
        fx, fy = self.px - self.ty * self.d, self.py + self.tx * self.d  # the end's perpendicular
        finish = (fx, fy, *end[2:]) if self.xy else _full((fx, fy), end, self.i, self.j)
        path = _tuple_new(CentrePath, (self._path_start(), (_tuple_new(CentrePiece, (finish, None, False)),)))
        place = self.place
        if self.held:
            self.held = False
            place = len(p.moves)
            p.moves.append(_tuple_new(Move, (self.file, self.line, self.mode, self.start, end, float(self.feed), None,
                                             self.seconds, self.plane, None, None, None,
                                             path if p.centre_paths else None, None)))  # fmt: skip
        element = _tuple_new(PathElement, ((self.ax, self.ay), (self.px, self.py), None, False))
        self.stage.pending = _tuple_new(Pending, (place, self.line, self.mode, self.feed, self.unit, self.plane,
                                                  self.start, end, element, self.d, path, self.seconds, False, (),
                                                  self.per, self.length, self.off, self.file))  # fmt: skip


def _plane_limits(p: Planner, i: int, j: int) -> tuple[float, float, float, float] | None:
    """The machine's travel on the plane's axes ``i`` and ``j`` in program coordinates (lowest and
    highest of each, unbounded where not limited: ``program_bounds``); None where neither is."""
    if p.travel is None:
        return None
    inf = float("inf")
    out = [-inf, inf, -inf, inf]
    found = False
    for k, low, high, _ in program_bounds(p):
        if k in (i, j):
            n = 0 if k == i else 2
            out[n], out[n + 1] = low - 1e-9, high + 1e-9
            found = True
    return (out[0], out[1], out[2], out[3]) if found else None


def _signed_radius(p: Planner, stage: CutterStage) -> float | None:
    """The radius of the D in force, signed for the side (left positive), read as
    ``cutter_radius`` reads it; None for a D without a value (``cutter_radius`` notes it)."""
    n = p.codes.get("D")
    if not n or n <= 0:
        return None
    d = stored_radius(p, stage.bases, int(n))
    if d is None:
        return None
    return d if stage.code == LEFT else -d


def _reversal_message(line: int) -> str:
    """The interference of the block on (0-based) ``line`` cut backwards."""
    return detail(
        f"interference: with the cutter's offset the block on line {line + 1} would be cut backwards (the tool "
        "centre's path runs against the programmed one): the cutter is too large for this step or groove",
        f"干涉：按刀具偏置，第 {line + 1} 行的程序段将反向切削（刀具中心轨迹与编程轨迹方向相反）："
        "刀具对该台阶或槽来说太大",
    )


def _reversal(
    p: Planner, line: int, reversed_line: int, place: int, start: _Point, mode: float, plane: float, unit: float,
    seconds: float, length: float,
) -> None:  # fmt: skip
    """The block on ``reversed_line`` would be cut backwards, found when the block on ``line`` is
    read: PS0041 where the profile has the cutter alarms, else a note. FANUC's control finds it
    reading ahead and stops before that block moves ("the tool stops and an alarm is displayed",
    the tool "Stopped" at the end of the block before it): when the run ends on the alarm, the
    block's move (recorded at ``place``, with its provisional ``seconds`` and ``length``) and any
    made after it are taken back, and the tool is at its ``start``."""
    message = _reversal_message(reversed_line)
    if not p.dialect.cutter_alarms:
        p.host.note("cutter", message, line, "cutter-interference")
        return

    def take_back() -> None:
        _withdraw(p, place, reversed_line, mode, unit, seconds, length, None)
        p.pos = list(start)

    raise AlarmBeforeMove(CUTTER_INTERFERENCE, message, "cutter-interference", take_back)


def _withdraw(
    p: Planner, place: int, line: int, mode: float, unit: float, seconds: float, length: float, made: Move | None
) -> None:
    """Take back the move of ``line`` recorded at ``place`` (its provisional ``seconds`` and
    ``length``) and the moves made after it, which the control never made: from the clock, the
    lengths and the toolpath (``made``, what the control did make of that move, in its place;
    ``Planner.withdrawn`` keeps what was taken for a snapshot restored)."""
    moves = p.moves
    if 0 <= place < len(moves) and moves[place].line == line:
        after = moves[place + 1 :]
        taken = moves[place:]
        del moves[place:]
        if made is not None:
            moves.append(made)
        p.withdrawn = (place, len(moves), taken)
    else:
        after = []
    p.clock -= seconds + sum(mv.seconds for mv in after)
    if mode == 0.0:
        p.rapid_length -= length * unit
    else:
        p.cut_length -= length * unit
    for mv in after:  # the moves off the plane made at the block's corner
        if mv.mode == 0.0:
            p.rapid_length -= p.times.distance(mv.start, mv.end) * unit
        else:
            p.cut_length -= p.times.distance(mv.start, mv.end) * unit


def _machine_path(
    p: Planner, path: CentrePath, radius: float, i: int, j: int, scale: _Scale, back: bool = False
) -> CentrePath:
    """The path the machine position follows along the tool centre's ``path``: the path itself on a
    mill; on a lathe the imaginary tool nose's, the tip's vector (``_tip``) from the nose centre of
    ``radius``, whose position the T offset carries to the machine (``back``: from that path to the
    centre's)."""
    tx, ty = _tip(p, abs(radius), i, j)
    if not tx and not ty:
        return path
    if back:
        tx, ty = -tx, -ty

    def moved(q: _Point) -> _Point:
        x, y = _plane_point(q, i, j, scale)
        return _full((x + tx, y + ty), q, i, j, scale)

    pieces = tuple(
        CentrePiece(moved(pc.end), None if pc.centre is None else moved(pc.centre), pc.clockwise) for pc in path.pieces
    )
    return CentrePath(moved(path.start), pieces)


def _programmed_at(element: PathElement, q: tuple[float, float], first: bool) -> tuple[float, float]:
    """Where the programmed ``element`` is when the tool centre stops at ``q`` (the plane's
    units): its point nearest ``q`` when the centre stopped on the path along it (``first``), its
    end when on a corner's piece after it."""
    if not first:
        return element.end
    (ax, ay), (bx, by) = element.start, element.end
    c = element.centre
    if c is not None:
        r = hypot(ax - c[0], ay - c[1])
        dx, dy = q[0] - c[0], q[1] - c[1]
        h = hypot(dx, dy)
        return element.end if h == 0.0 else (c[0] + dx * r / h, c[1] + dy * r / h)
    ux, uy = bx - ax, by - ay
    ll = ux * ux + uy * uy
    t = 0.0 if ll == 0.0 else min(1.0, max(0.0, ((q[0] - ax) * ux + (q[1] - ay) * uy) / ll))
    return ax + t * ux, ay + t * uy


def _cut_short(
    p: Planner, bounds: Bounds, plane: float, path: CentrePath, element: PathElement, radius: float, i: int, j: int,
    scale: _Scale,
) -> tuple[CentrePath, _Point, MacroAlarm] | None:  # fmt: skip
    """Where the machine, following the centre's ``path``, first leaves ``bounds``: the centre's
    path up to there, the programmed point there (``_programmed_at``) and the over-travel alarm;
    None when it stays inside."""
    found = path_leaves_travel(p, bounds, plane, _machine_path(p, path, radius, i, j, scale))
    if found is None:
        return None
    machine, alarm = found
    cut = _machine_path(p, machine, radius, i, j, scale, back=True)
    last = cut.pieces[-1].end
    q = _programmed_at(element, _plane_point(last, i, j, scale), len(cut.pieces) == 1)
    return cut, _full(q, last, i, j, scale), alarm


def _pending_travel(p: Planner, pending: Pending, path: CentrePath, i: int, j: int, scale: _Scale) -> None:
    """The pending move's centre ``path``, now settled (its axes off the plane were checked as it
    was made, ``centre_travel``): where it leaves the machine's travel in the plane, the control's
    over-travel alarm on that block (FANUC OT0500/OT0501: the axis stops at the limit), raised
    while the next move is read; the move is cut short there and the moves after it taken back
    when the run ends on it."""
    bounds = tuple(b for b in program_bounds(p) if b[0] == i or b[0] == j)
    found = _cut_short(p, bounds, pending.plane, path, pending.element, pending.d, i, j, scale) if bounds else None
    if found is None:
        return
    cut, stop, alarm = found
    place, line, mode, feed, unit, plane, start = pending[:7]

    def take_back() -> None:
        moves = p.moves
        made = None
        if 0 <= place < len(moves) and moves[place].line == line:
            made = moves[place]._replace(end=stop, tool_path=cut if p.centre_paths else None)
        _withdraw(p, place, line, mode, unit, pending.seconds, pending.length, made)
        taken = _cost(p, mode, cut, feed, unit, plane, start, stop)
        p.clock += taken
        if made is not None:
            moves[-1] = made._replace(seconds=taken)
        p.pos = list(stop)

    raise AlarmBeforeMove(alarm.number, alarm.message, alarm.subject, take_back, (pending.file, line))


def centre_travel(
    p: Planner, line: int, mode: float, plane: float, start: _Point, end: _Point, centre: _Point | None,
    path: CentrePath, feed: float, unit: float,
) -> tuple[CentrePath, float, _Point, MacroAlarm] | None:  # fmt: skip
    """The travel check of a move ``Planner.record`` makes with its centre ``path`` (the machine
    follows the centre, not the programmed point): the whole path where it is final (a cancel, a
    move off the plane), only its axes off the plane where the next move settles its corner
    (``_pending_travel`` checks the plane then). Where it leaves: the path up to there, its
    seconds (the run's lengths put right), the programmed point there and the alarm."""
    axes = p.times.planes.get(plane)
    if axes is None:
        return None
    i, j = axes[0], axes[1]
    stage = p.cutter
    bounds = program_bounds(p)
    if stage is not None and stage.pending is not None and stage.pending.path is path:
        bounds = tuple(b for b in bounds if b[0] != i and b[0] != j)
    if not bounds:
        return None
    scale = (axes[2], axes[3]) if p.lathe else None
    radius = nose_radius(p, line) if p.lathe else 0.0
    element = _element(mode, start, end, centre, i, j, scale)
    found = _cut_short(p, bounds, plane, path, element, radius, i, j, scale)
    if found is None:
        return None
    cut, stop, alarm = found
    _count(p, mode, path, plane, -unit)
    return cut, _cost(p, mode, cut, feed, unit, plane, start, stop), stop, alarm


def _arc_finding(p: Planner, message: str, line: int) -> None:
    """A start-up or cancel on an arc: PS0034 on every mill and on a lathe with FANUC's cutter
    alarms; a note on a lathe without them (GSK980TDi: no source at hand gives its alarm)."""
    if p.lathe and not p.dialect.cutter_alarms:
        p.host.note("cutter", message, line, "cutter-arc")
        return
    raise MacroAlarm(CUTTER_ARC_START, message, "cutter-arc")


def frame_moved(p: Planner, change: dict[int, float]) -> None:
    """The program position took ``change`` (per axis, new minus old) while the machine stayed
    where it was: a work offset (G54-G59, G10 L2), a local coordinate system (G52) or a coordinate
    setting (G92/G50, its preset) in offset mode. The pending move's corner with the next one is
    then worked out in one frame, the coordinates now in force (``moved``, read by ``_in_frame``);
    where the profile sets the compensation aside at a shift (``Dialect.shift_cancels_compensation``:
    GSK980TDi §3.19, §3.21) the pending move keeps its end on its perpendicular and the next move in
    the plane is a start-up from there (``resume``)."""
    stage = p.cutter
    if stage is None or not stage.on:
        return
    i, j = stage.axes
    di, dj = change.get(i, 0.0), change.get(j, 0.0)
    if not di and not dj:
        return
    pending = stage.pending
    if p.dialect.shift_cancels_compensation:
        stage.on = False
        stage.pending = stage.moved = None
        stage.written = ""
        if pending is not None:
            end = pending.path.pieces[-1].end
            stage.resume = tuple(v + change.get(k, 0.0) for k, v in enumerate(end))
        return
    if pending is None:
        return
    mx, my = _plane_point(tuple(change.get(k, 0.0) for k in range(max(i, j) + 1)), i, j, _lathe_scale(p, stage))
    moved = stage.moved
    if moved is not None and moved[0] is pending:
        mx, my = mx + moved[1], my + moved[2]
    stage.moved = (pending, mx, my)


def _in_frame(stage: CutterStage, pending: Pending) -> tuple[Pending, float, float]:
    """``pending`` with its element in the coordinates now in force (``CutterStage.moved``) and
    how far it was moved; the move is read, the record of the shift is done with."""
    moved = stage.moved
    stage.moved = None
    if moved is None or moved[0] is not pending:
        return pending, 0.0, 0.0
    _, mx, my = moved
    e = pending.element
    c = None if e.centre is None else (e.centre[0] + mx, e.centre[1] + my)
    element = PathElement((e.start[0] + mx, e.start[1] + my), (e.end[0] + mx, e.end[1] + my), c, e.ccw)
    return pending._replace(element=element), mx, my


def _moved_corner(corner: Corner, mx: float, my: float) -> Corner:
    """``corner`` moved by (``mx``, ``my``) in the plane."""
    if not mx and not my:
        return corner
    links = tuple((x + mx, y + my) for x, y in corner.links)
    (bx, by), (ax, ay) = corner.before_end, corner.after_start
    return Corner((bx + mx, by + my), links, (ax + mx, ay + my))


def _rounded_corner(p: Planner, what: str, what_zh: str) -> None:
    """A chamfer or corner R (``,C``/``,R``: ``Planner.block_corner``) on a start-up, a cancel or a
    change of side: the control's alarm where the profile has it (``Dialect.corner_compensation_alarm``:
    FANUC PS0039), else nothing (the corner is not simulated)."""
    letter = p.block_corner
    if letter is None or not p.dialect.corner_compensation_alarm:
        return
    raise MacroAlarm(CUTTER_CORNER, detail(
        f",{letter} on the {what} of cutter radius compensation: the control does not chamfer or round the corner "
        "of a start-up, a cancel or a change between G41 and G42; move it to a block in offset mode",
        f"刀具半径补偿{what_zh}的程序段中指令了 ,{letter}：系统不能在补偿的建立、取消或 G41/G42 切换处倒角或倒圆角；"
        "请将其移到补偿方式中的程序段"), "cutter-corner")  # fmt: skip


def _arc_message(code: str, what: str, what_zh: str) -> str:
    return detail(
        f"the {what} of cutter radius compensation ({code}) is on a G02/G03 arc: the control starts and cancels "
        "it only on a G00 or G01 move",
        f"刀具半径补偿的{what_zh}（{code}）在 G02/G03 圆弧上：系统只能在 G00 或 G01 移动中建立和取消补偿",
    )


def _arc_radius(s: PathElement) -> float:
    assert s.centre is not None
    return round(hypot(s.start[0] - s.centre[0], s.start[1] - s.centre[1]), 4)


def _lathe_scale(p: Planner, stage: CutterStage) -> _Scale:
    """The plane's units per program unit on a lathe (X a diameter: ``MoveTimes.planes``), None on
    a mill, whose points are taken as they are."""
    if not stage.lathe:
        return None
    axes = p.times.planes.get(stage.plane)
    return None if axes is None else (axes[2], axes[3])


def _plane_point(q: _Point, i: int, j: int, scale: _Scale = None) -> tuple[float, float]:
    """``q``'s point in the plane of axes ``i`` and ``j`` (a lathe's X halved: ``scale``)."""
    if scale is None:
        return q[i], q[j]
    return q[i] * scale[0], q[j] * scale[1]


def _element(
    mode: float, start: _Point, end: _Point, centre: _Point | None, i: int, j: int, scale: _Scale = None
) -> PathElement:
    a, b = _plane_point(start, i, j, scale), _plane_point(end, i, j, scale)
    if centre is None or mode not in ARC_MODES:
        return PathElement(a, b)
    return PathElement(a, b, _plane_point(centre, i, j, scale), mode == 3.0)


def _corner(p: Planner, pending: Pending, after: PathElement, d: float, outer: str, line: int) -> Corner:
    """How the pending move's offset meets the next element's (``NoIntersection``: PS0033)."""
    try:
        return join(pending.element, after, pending.d, d, outer)
    except NoIntersection:
        _finding(p, CUTTER_NO_INTERSECTION, "cutter-interference", line, detail(
            f"the offsets of this block and the one on line {pending.line + 1} do not meet on the inside corner: the "
            "cutter is too large for the shape there",
            f"本程序段与第 {pending.line + 1} 行程序段的偏置轨迹在内角处没有交点：刀具对该处形状来说太大"))  # fmt: skip
        q = perpendicular_end(pending.element, pending.d)
        return Corner(q, (), q)


def _provisional(
    p: Planner, where: tuple[str, int], mode: float, plane: float, element: PathElement, d: float, begin: _Point,
    start: _Point, end: _Point, centre: _Point | None, feed: float, unit: float, startup: bool, i: int, j: int,
) -> tuple[CentrePath, float]:  # fmt: skip
    """The path of a new move in the plane (of ``where``: its file and line) from ``begin``, ending
    on its end's perpendicular as if nothing followed, kept pending for the next move to put right."""
    file, line = where
    stage = p.cutter
    assert stage is not None
    q = perpendicular_end(element, d)
    scale = _lathe_scale(p, stage)
    piece = CentrePiece(_full(q, end, i, j, scale), None if startup or element.centre is None else centre,
                        mode == 2.0)  # fmt: skip
    path = CentrePath(begin, (piece,))
    seconds = _cost(p, mode, path, feed, unit, plane, start, end)
    index = len(p.moves) if p.record_moves else -1
    per_length = 0.0 if mode == 0.0 else p.feed_seconds(mode, 1.0, feed, start, end, unit)
    (ax, ay), (bx, by) = element.start, element.end
    off_plane = max(dist(start, end) ** 2 - (bx - ax) ** 2 - (by - ay) ** 2, 0.0)
    stage.pending = Pending(index, line, mode, feed, unit, plane, start, end, element, d, path, seconds, startup, (),
                            per_length, _length(p, path, plane), off_plane, file)  # fmt: skip
    return path, seconds


def _settle(
    p: Planner, pending: Pending, corner: Corner, line: int, i: int, j: int, scale: _Scale = None, checked: bool = True
) -> None:
    """Put the pending move's centre path right now that the corner after it is known: its time,
    its length, its record, and the moves off the plane made at its end. Where the path leaves the
    machine's travel the run stops on that move (``_pending_travel``; not ``checked`` when the
    coordinate system moved since it, the travel then being in other coordinates)."""
    provisional = pending.path
    last = provisional.pieces[-1]
    end_full = last.end
    element = pending.element
    pieces: list[CentrePiece] = []
    if pending.startup or element.centre is None:
        pieces.append(CentrePiece(_full(corner.before_end, end_full, i, j, scale)))
    else:
        pieces.append(CentrePiece(_full(corner.before_end, end_full, i, j, scale), last.centre, last.clockwise))
    if not pending.startup and pending.d:
        piece = centre_segment(element, _plane_point(provisional.start, i, j, scale), corner.before_end)
        if reverses(element, piece):
            _reversal(p, line, pending.line, pending.place, pending.start, pending.mode, pending.plane, pending.unit,
                      pending.seconds, pending.length)  # fmt: skip
    for link in corner.links:
        pieces.append(CentrePiece(_full(link, end_full, i, j, scale)))
    if corner.after_start != corner.before_end or corner.links:
        pieces.append(CentrePiece(_full(corner.after_start, end_full, i, j, scale)))
    path = CentrePath(provisional.start, tuple(pieces))
    if checked and p.travel is not None:
        _pending_travel(p, pending, path, i, j, scale)
    mode, unit, plane = pending.mode, pending.unit, pending.plane
    seconds = _cost(p, mode, path, pending.feed, unit, plane, pending.start, pending.end)
    _count(p, mode, provisional, plane, -unit)
    p.clock += seconds - pending.seconds
    moves = p.moves
    k = pending.place
    if 0 <= k < len(moves) and moves[k].line == pending.line:
        moves[k] = moves[k]._replace(tool_path=path if p.centre_paths else None, seconds=seconds)
    at = corner.after_start
    for k in pending.between:
        if 0 <= k < len(moves):
            mv = moves[k]
            if mv.tool_path is not None:
                off = CentrePath(
                    _full(at, mv.tool_path.start, i, j, scale), (CentrePiece(_full(at, mv.end, i, j, scale)),)
                )
                moves[k] = mv._replace(tool_path=off)


def restore_pending(p: Planner) -> None:
    """After a snapshot is restored: the pending move's record as it was when it was pending
    (a later move may have put it right before the run was taken back)."""
    stage = p.cutter
    pending = stage.pending if stage is not None else None
    if pending is None:
        return
    moves = p.moves
    k = pending.place
    if 0 <= k < len(moves) and moves[k].line == pending.line:
        moves[k] = moves[k]._replace(tool_path=pending.path if p.centre_paths else None, seconds=pending.seconds)


def _length(p: Planner, path: CentrePath, plane: float) -> float:
    """The length of a centre path in program units (arcs with a helix's third axis)."""
    times = p.times
    at = path.start
    total = 0.0
    for piece in path.pieces:
        if piece.centre is not None:
            total += times.arc_length(2.0 if piece.clockwise else 3.0, plane, at, piece.end, piece.centre)
        else:
            total += times.distance(at, piece.end)
        at = piece.end
    return total


def _count(p: Planner, mode: float, path: CentrePath, plane: float, unit: float) -> None:
    """Add the path's length (times ``unit``: negative to take it back) to the cut or rapid length."""
    length = _length(p, path, plane) * unit
    if mode == 0.0:
        p.rapid_length += length
    else:
        p.cut_length += length


def _cost(
    p: Planner, mode: float, path: CentrePath, feed: float, unit: float, plane: float, start: _Point, end: _Point
) -> float:
    """The seconds of ``path`` in ``mode`` (a rapid piece by piece at its slowest axis, a cut at
    the feed in force), its length added to the run's."""
    if mode == 0.0:
        seconds = 0.0
        at = path.start
        for piece in path.pieces:
            seconds += p.times.rapid_seconds(at, piece.end, unit)
            at = piece.end
    else:
        seconds = p.feed_seconds(mode, _length(p, path, plane), feed, start, end, unit)
    _count(p, mode, path, plane, unit)
    return seconds
