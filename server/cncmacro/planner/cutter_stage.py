"""Cutter radius compensation on a mill: G41/G42 with D, cancelled by G40 (docs/semantics.md,
"Cutter radius compensation").

The planner's stage between a block's programmed move and its time: while ``Planner.cutter`` is
set, ``Planner.record`` hands each move here. The tool centre's end point of a block is known only
when the next block in the plane is (where the two offsets meet: offset_geometry.py), so the stage
runs one move behind: a move is recorded at once with a provisional centre path (ending on the
perpendicular of its end, as if nothing followed), and when the next move in the plane arrives
the corner between them is worked out and the earlier move's path, time and length are put right
in place (``Planner.moves``, the clock, the cut and rapid lengths). Moves off the plane in between
(a Z move) are made at the corner. Start-up is the first move in the plane after G41/G42 with a
D whose offset is not zero, cancel the first after G40; both are of type A or B as the machine
file's ``cutter_startup`` says. The radius is offset D's geometry plus wear, as the macro machine
keeps them (``Dialect.tool_offset_bases``; G10 L12/L13 write them). The control's answers: an arc
at start-up or cancel (PS0034), a corner whose offsets do not meet (PS0033), an offset path that
reverses a block or a cutter too large for an inside arc (PS0041), a plane change in G41/G42
(PS0037); where the profile has no such alarms (``Dialect.cutter_alarms``) the last three are
notes the run goes past.
"""

from __future__ import annotations

from collections.abc import Callable
from math import dist, hypot, sqrt
from typing import TYPE_CHECKING, NamedTuple, TypeVar

from ..bilingual import detail
from ..dialects.alarms import CUTTER_ARC_START, CUTTER_INTERFERENCE, CUTTER_NO_INTERSECTION, CUTTER_PLANE
from .alarms import MacroAlarm
from .arcs import ARC_MODES
from .cycle_time import INCH
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

if TYPE_CHECKING:
    from .planner import Planner

LEFT, RIGHT, CANCEL = 41.0, 42.0, 40.0
_T = TypeVar("_T")
_MOVE_MODES = frozenset((0.0, 1.0, 2.0, 3.0))
_Point = tuple[float, ...]


class Pending(NamedTuple):
    """The last move in the plane, whose centre path waits for the next one: its place in
    ``Planner.moves`` (-1 when moves are not recorded), its line, mode, feed, unit (25.4 under
    G20) and plane, its programmed start and end, its programmed element in the plane and signed
    offset (left positive), its provisional centre path and time, whether it is the start-up
    block, the places of the moves off the plane recorded since, the seconds per program unit of
    its path (0 for a rapid), its provisional path's length and the square of its move along the
    axes off the plane."""

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


class CutterStage:
    """The compensation state of one run: the modal code (41, 42, or 40 with a cancel to come),
    whether the offset is established, the plane it was started in, the start-up type, the move
    waiting for the next, the offsets already noted as having no value, and the indexes of the
    plane's two axes and where offset D's geometry and wear are kept."""

    __slots__ = ("axes", "bases", "code", "noted", "on", "pending", "plane", "type_b")

    def __init__(
        self, code: float, plane: float, type_b: bool, axes: tuple[int, int] = (0, 1),
        bases: tuple[int, int] = (13000, 12000),
    ) -> None:  # fmt: skip
        self.code = code
        self.on = False
        self.plane = plane
        self.axes = axes  # the plane's two axes (indexes)
        self.bases = bases  # where offset D's geometry and wear are kept (#base + D)
        self.type_b = type_b
        self.pending: Pending | None = None
        self.noted: frozenset[int] = frozenset()

    def copy(self) -> CutterStage:
        c = CutterStage(self.code, self.plane, self.type_b, self.axes, self.bases)
        c.on, c.pending, c.noted = self.on, self.pending, self.noted
        return c


def cutter_code(p: Planner, group: str, g: float, line: int) -> None:
    """A block's G code of the ``cutter`` group (G40, G41, G42) or, while the offset is on, of the
    ``plane`` group: start, keep or cancel the stage (before the modal code is set)."""
    stage = p.cutter
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
    if g in (LEFT, RIGHT) and not p.lathe:
        if stage is None:
            plane = p.modal.get("plane", 17.0)
            ij = p.times.planes.get(plane)
            bases = p.dialect.tool_offset_bases
            p.cutter = CutterStage(g, plane, p.settings.cutter_startup == "B", (ij[0], ij[1]) if ij else (0, 1),
                                   (bases[2], bases[3]))  # fmt: skip
        else:
            stage.code = g
    elif stage is not None:
        stage.code = CANCEL
        if not stage.on:
            p.cutter = None


# the one-shot codes whose moves are made as programmed, the offset taken up again from the
# programmed point at the next move in the plane (FANUC: G28 "cancels the offset vector at the
# intermediate position"; G30, G53 and the skip G31 likewise here)
UNCOMPENSATED_CODES = frozenset((28.0, 30.0, 31.0, 53.0))


def uncompensated(p: Planner, run: Callable[[], _T]) -> _T:
    """``run`` (a one-shot code's moves) with compensation set aside: the pending move keeps its
    path to the perpendicular of its end, the moves of ``run`` are drawn as programmed, and the
    next move in the plane starts the offset again (a start-up from where the tool is)."""
    stage = p.cutter
    p.cutter = None
    try:
        return run()
    finally:
        if stage is not None:
            stage.on = False
            stage.pending = None
            p.cutter = stage if stage.code != CANCEL else None


def cutter_radius(p: Planner, line: int) -> float:
    """The radius offset D in force holds: its geometry plus its wear (half of it where the machine
    file's ``cutter_offset`` says the offsets hold diameters), 0 for D0 (no D yet) or an offset
    the run has no value for (noted once per offset number)."""
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


def _full(plane_point: tuple[float, float], like: _Point, i: int, j: int) -> _Point:
    out = list(like)
    out[i], out[j] = plane_point
    return tuple(out)


def cutter_move(
    p: Planner, line: int, mode: float, plane: float, start: _Point, end: _Point, centre: _Point | None,
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
    in_plane = centre is not None or start[i] != end[i] or start[j] != end[j]
    if not stage.on:
        if not in_plane:
            return None
        d = cutter_radius(p, line)
        if d == 0.0:
            return None
        if mode in ARC_MODES:
            raise MacroAlarm(CUTTER_ARC_START, _arc_message("G41/G42", "start-up", "建立"), "cutter-arc")
        stage.on = True
        d = d if stage.code == LEFT else -d
        element = PathElement((start[i], start[j]), (end[i], end[j]))
        return _provisional(p, line, mode, plane, element, d, start, start, end, None, feed, unit, True, i, j)
    pending = stage.pending
    if (centre is None and in_plane and mode != 0.0 and pending is not None and stage.code != CANCEL
            and pending.per_length and pending.element[2] is None and not pending.startup
            and not pending.between and plane == pending.plane):  # fmt: skip
        seconds = _line_after_line(p, stage, pending, line, mode, start, end, feed)
        if seconds is not None:
            return stage.pending.path, seconds  # type: ignore[union-attr]
    if not in_plane:  # a move off the plane: made where the tool centre is
        at = (start[i], start[j]) if pending is None else _plane_point(pending.path.pieces[-1].end, i, j)
        path = CentrePath(_full(at, start, i, j), (CentrePiece(_full(at, end, i, j)),))
        if pending is not None and p.record_moves:
            stage.pending = pending._replace(between=(*pending.between, len(p.moves)))
        return path, _cost(p, mode, path, feed, unit, plane, start, end)
    if stage.code == CANCEL:
        if mode in ARC_MODES:
            raise MacroAlarm(CUTTER_ARC_START, _arc_message("G40", "cancel", "取消"), "cutter-arc")
        cancel = PathElement((start[i], start[j]), (end[i], end[j]))
        begin = (start[i], start[j])
        if pending is not None:
            outer = MEET if stage.type_b else PERPENDICULAR_BEFORE
            corner = _corner(p, pending, cancel, pending.d, outer, line)
            _settle(p, pending, corner, line, i, j)
            begin = corner.after_start
        stage.on = False
        stage.pending = None
        p.cutter = None
        path = CentrePath(_full(begin, start, i, j), (CentrePiece(end),))
        return path, _cost(p, mode, path, feed, unit, plane, start, end)
    d = cutter_radius(p, line)
    d = d if stage.code == LEFT else -d
    element = _element(mode, start, end, centre, i, j)
    if centre is not None and offset_element(element, d) is None:
        radius = _arc_radius(element)
        _finding(p, CUTTER_INTERFERENCE, "cutter-interference", line, detail(
            f"the cutter (radius {abs(d):g}) is too large for this arc of radius {radius:g}: its centre cannot "
            "follow it on the inside",
            f"刀具（半径 {abs(d):g}）大于此圆弧（半径 {radius:g}）：刀具中心无法在内侧沿其移动"))  # fmt: skip
        d = 0.0
    begin = (start[i], start[j])
    if pending is not None:
        outer = PERPENDICULAR_AFTER if pending.startup and not stage.type_b else MEET
        corner = _corner(p, pending, element, d, outer, line)
        _settle(p, pending, corner, line, i, j)
        begin = corner.after_start
    return _provisional(p, line, mode, plane, element, d, _full(begin, start, i, j), start, end, centre, feed, unit,
                        False, i, j)  # fmt: skip


_tuple_new = tuple.__new__  # a named tuple without its constructor's keyword handling


def straight_cut(p: Planner, file: str, line: int, mode: float, start: _Point, end: _Point) -> bool:
    """Record a straight cut of a run of plain lines (machine/straight_runs.py) after a straight
    cut under compensation, its centre path and time included, as ``Planner.record`` would;
    False, recording nothing, for any other case, which ``Planner.record`` then takes."""
    stage = p.cutter
    if stage is None or mode == 0.0:
        return False
    pending = stage.pending
    if (pending is None or stage.code == CANCEL or not pending.per_length or pending.element[2] is not None
            or pending.startup or pending.between):  # fmt: skip
        return False
    feed = p.codes.get("F") or 0.0
    done = _line_after_line(p, stage, pending, line, mode, start, end, feed)
    if done is None:
        return False
    if p.record_moves:
        p.moves.append(_tuple_new(Move, (file, line, mode, start, end, float(feed), None, done, pending.plane,
                                         None, None, None, stage.pending.path)))  # type: ignore[union-attr]  # fmt: skip
        if len(p.moves) >= p.move_budget:
            p.moves_full(line)
    p.clock += done
    return True


def _line_after_line(
    p: Planner, stage: CutterStage, pending: Pending, line: int, mode: float, start: _Point, end: _Point, feed: float
) -> float | None:
    """The common case of a CAM contour, a cut after a cut, both straight, at the same offset, in
    the same unit and plane: ``offset_geometry.join``'s corner worked out in place, the pending
    move put right, the new one pending in its turn; returns the new move's seconds (its path is
    the new ``stage.pending.path``), None for a case it leaves to the general way. The same rules:
    a tangent needs no corner, an inside or obtuse corner ends at the intersection,
    P + d (n1 + n2) / (1 + t1·t2) for offsets of one distance d, an acute outside one goes
    through the two extension points."""
    i, j = stage.axes
    element = pending.element
    p_point = element[1]
    (ax, ay), (px, py) = element[0], p_point
    ex, ey = end[i], end[j]
    if (ex == px and ey == py) or mode != pending.mode or (INCH if p.modal["units"] == 20.0 else 1.0) != pending.unit:
        return None
    d = _signed_radius(p, stage)
    if d != pending.d:
        return None
    l1, l2 = hypot(px - ax, py - ay), hypot(ex - px, ey - py)
    t1x, t1y, t2x, t2y = (px - ax) / l1, (py - ay) / l1, (ex - px) / l2, (ey - py) / l2
    cross, dot = t1x * t2y - t1y * t2x, t1x * t2x + t1y * t2y
    link = False
    if -1e-12 <= cross <= 1e-12 and dot > 0.0:
        bx, by = px - t1y * d, py + t1x * d
        cx, cy = bx, by
    elif cross * d > 0.0 or dot >= 0.0:
        if dot <= -1.0 + 1e-9:
            return None
        k = d / (1.0 + dot)
        bx, by = px - k * (t1y + t2y), py + k * (t1x + t2x)
        cx, cy = bx, by
    else:
        r = -d if d < 0.0 else d
        bx, by = px - t1y * d + t1x * r, py + t1x * d + t1y * r
        cx, cy = px - t2y * d - t2x * r, py + t2x * d - t2y * r
        link = True
    s0 = pending.path[0]
    sx, sy = s0[i], s0[j]
    if (bx - sx) * t1x + (by - sy) * t1y < -EPSILON * (l1 if l1 > 1.0 else 1.0):
        _finding(p, CUTTER_INTERFERENCE, "cutter-interference", line, _reversal_message(pending.line))
    xy = i == 0 and j == 1
    first = (bx, by, *start[2:]) if xy else _full((bx, by), start, i, j)
    length = sqrt((bx - sx) ** 2 + (by - sy) ** 2 + pending.off_plane)
    pieces: tuple[CentrePiece, ...] = (_tuple_new(CentrePiece, (first, None, False)),)
    second = first
    if link:
        second = _full((cx, cy), start, i, j)
        pieces += (_tuple_new(CentrePiece, (second, None, False)),)
        length += hypot(cx - bx, cy - by)
    unit = pending.unit
    per = pending.per_length
    seconds = length * per
    p.clock += seconds - pending.seconds
    moves = p.moves
    place = pending.place
    if 0 <= place < len(moves) and moves[place][1] == pending.line:
        old = moves[place]
        moves[place] = _tuple_new(Move, (*old[:7], seconds, *old[8:12], _tuple_new(CentrePath, (s0, pieces))))
    # the new move, pending in its turn: from the corner to its end's perpendicular
    qx, qy = ex - t2y * d, ey + t2x * d
    finish = (qx, qy, *end[2:]) if xy else _full((qx, qy), end, i, j)
    off_plane = dist(start, end) ** 2 - l2 * l2
    if off_plane < 1e-9:  # in the plane (but for the rounding of the squares)
        off_plane = 0.0
    length_b = sqrt((qx - cx) ** 2 + (qy - cy) ** 2 + off_plane)
    if feed != pending.feed:
        per = p.feed_seconds(mode, 1.0, feed, start, end, unit)
    seconds_b = length_b * per
    p.cut_length += (length - pending.length + length_b) * unit
    path = _tuple_new(CentrePath, (second, (_tuple_new(CentrePiece, (finish, None, False)),)))
    stage.pending = _tuple_new(Pending, (len(moves) if p.record_moves else -1, line, mode, feed, unit, pending.plane,
                                         start, end, _tuple_new(PathElement, (p_point, (ex, ey), None, False)), d,
                                         path, seconds_b, False, (), per, length_b, off_plane))  # fmt: skip
    return seconds_b


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


def _arc_message(code: str, what: str, what_zh: str) -> str:
    return detail(
        f"the {what} of cutter radius compensation ({code}) is on a G02/G03 arc: the control starts and cancels "
        "it only on a G00 or G01 move",
        f"刀具半径补偿的{what_zh}（{code}）在 G02/G03 圆弧上：系统只能在 G00 或 G01 移动中建立和取消补偿",
    )


def _arc_radius(s: PathElement) -> float:
    assert s.centre is not None
    return round(hypot(s.start[0] - s.centre[0], s.start[1] - s.centre[1]), 4)


def _plane_point(q: _Point, i: int, j: int) -> tuple[float, float]:
    return q[i], q[j]


def _element(mode: float, start: _Point, end: _Point, centre: _Point | None, i: int, j: int) -> PathElement:
    if centre is None or mode not in ARC_MODES:
        return PathElement((start[i], start[j]), (end[i], end[j]))
    return PathElement((start[i], start[j]), (end[i], end[j]), (centre[i], centre[j]), mode == 3.0)


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
    p: Planner, line: int, mode: float, plane: float, element: PathElement, d: float, begin: _Point, start: _Point,
    end: _Point, centre: _Point | None, feed: float, unit: float, startup: bool, i: int, j: int,
) -> tuple[CentrePath, float]:  # fmt: skip
    """The path of a new move in the plane from ``begin``, ending on its end's perpendicular as
    if nothing followed, kept pending for the next move to put right."""
    q = perpendicular_end(element, d)
    piece = CentrePiece(_full(q, end, i, j), None if startup or element.centre is None else centre, mode == 2.0)
    path = CentrePath(begin, (piece,))
    seconds = _cost(p, mode, path, feed, unit, plane, start, end)
    stage = p.cutter
    assert stage is not None
    index = len(p.moves) if p.record_moves else -1
    per_length = 0.0 if mode == 0.0 else p.feed_seconds(mode, 1.0, feed, start, end, unit)
    (ax, ay), (bx, by) = element.start, element.end
    off_plane = max(dist(start, end) ** 2 - (bx - ax) ** 2 - (by - ay) ** 2, 0.0)
    stage.pending = Pending(index, line, mode, feed, unit, plane, start, end, element, d, path, seconds, startup, (),
                            per_length, _length(p, path, plane), off_plane)  # fmt: skip
    return path, seconds


def _settle(p: Planner, pending: Pending, corner: Corner, line: int, i: int, j: int) -> None:
    """Put the pending move's centre path right now that the corner after it is known: its time,
    its length, its record, and the moves off the plane made at its end."""
    provisional = pending.path
    last = provisional.pieces[-1]
    end_full = last.end
    element = pending.element
    pieces: list[CentrePiece] = []
    if pending.startup or element.centre is None:
        pieces.append(CentrePiece(_full(corner.before_end, end_full, i, j)))
    else:
        pieces.append(CentrePiece(_full(corner.before_end, end_full, i, j), last.centre, last.clockwise))
    if not pending.startup and pending.d:
        piece = centre_segment(element, _plane_point(provisional.start, i, j), corner.before_end)
        if reverses(element, piece):
            _finding(p, CUTTER_INTERFERENCE, "cutter-interference", line, _reversal_message(pending.line))
    for link in corner.links:
        pieces.append(CentrePiece(_full(link, end_full, i, j)))
    if corner.after_start != corner.before_end or corner.links:
        pieces.append(CentrePiece(_full(corner.after_start, end_full, i, j)))
    path = CentrePath(provisional.start, tuple(pieces))
    mode, unit, plane = pending.mode, pending.unit, pending.plane
    seconds = _cost(p, mode, path, pending.feed, unit, plane, pending.start, pending.end)
    _count(p, mode, provisional, plane, -unit)
    p.clock += seconds - pending.seconds
    moves = p.moves
    k = pending.place
    if 0 <= k < len(moves) and moves[k].line == pending.line:
        moves[k] = moves[k]._replace(tool_path=path, seconds=seconds)
    at = corner.after_start
    for k in pending.between:
        if 0 <= k < len(moves):
            mv = moves[k]
            if mv.tool_path is not None:
                moves[k] = mv._replace(tool_path=CentrePath(_full(at, mv.tool_path.start, i, j),
                                                            (CentrePiece(_full(at, mv.end, i, j)),)))  # fmt: skip


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
        moves[k] = moves[k]._replace(tool_path=pending.path, seconds=pending.seconds)


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
