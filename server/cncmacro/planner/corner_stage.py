"""Chamfers and corner roundings cut between two moves (docs/semantics.md §8, "Chamfer and corner
words"; the GSK980TDi's L and D, §10.1).

FANUC's and Haas's ``,C`` (a chamfer ``,C`` from the virtual corner along each move) and ``,R`` (an
arc of that radius tangent to both), and the GSK980TDi's ``L`` (a chamfer of that length, type I of
its state parameter №181.0, the default; type II, the distance to the intersection, is cut as
``,C``: the machine file's ``chamfer_type``) and ``D`` (a rounding arc; ``Dialect.chamfer_words``),
written on a G01, G02 or G03 block, shape the corner between that block's move and the next. The
chamfer needs the next move, which the planner meets a block later: as the cutter compensation
stage does (cutter_stage.py), the block's move is recorded at once as written, to the corner, and
held (``Planner.corner``, a ``HeldCorner``); when the next move in the plane arrives
(``Planner.record`` calls ``take_corner`` first) the held move is shortened in place (its record,
the clock, the cut length), the chamfer or arc is recorded after it on the same block's line (a
single block stop comes after it), and the next move starts where it ends. The program position
(#5001…) stays the programmed corner: the point the program wrote, from which the next block's
increments count.

Nothing is inserted (the corner stays sharp, as before) when the block's own move leaves the
plane, between two lines on one line or, for a rounding, two moves already tangent (GSK980TDi
§3.11.3). When the next block is not a G01, G02 or G03 move in the plane (it moves nothing, moves
off the plane, or is a G00, a cycle, a return) the corner is the control's alarm where the profile
has it (``Dialect.corner_next_alarm``: FANUC's PS0051, PS0052; a G04 block between is let stand),
else it stays sharp. A chamfer or rounding that does not fit
its moves is the control's alarm where the profile has it (``Dialect.corner_fit_alarm``: FANUC's
PS0055, the GSK980TDi's unnumbered ones), else a note. Under cutter radius compensation the corner
is not inserted (a note says so): the two stages are not composed.

Inside a roughing cycle's shape (G71–G73 reading its blocks: ``ShapeReading.segments``) the same
rule shapes the segments, so the cycle's passes follow the chamfered shape.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

from ..bilingual import Detail, detail
from ..dialects.alarms import CORNER_FIT, CORNER_NO_MOVE, CORNER_NOT_CUT
from .alarms import MacroAlarm
from .arcs import ARC_MODES
from .corner_geometry import LONG, RADIUS, Inserted, NoFit, chamfer, chamfer_of_length, rounding
from .cycle_time import INCH
from .moves import Move
from .offset_geometry import PathElement

if TYPE_CHECKING:
    from .planner import Planner

CUTTING_MODES = (1.0, 2.0, 3.0)  # "倒角必须在 G01、G02 或 G03 代码段中使用"; FANUC's on G01/G02/G03
CHAMFER, LENGTH, ROUND = "C", "L", "R"  # ``HeldCorner.kind``: ,C; GSK's L (type I); ,R and GSK's D
_NAMES = {
    CHAMFER: ("the chamfer", "倒角"),
    LENGTH: ("the chamfer", "直线倒角"),
    ROUND: ("the corner rounding", "圆弧倒角"),
}
_LIMIT = 1000.0  # the GSK980TDi's range of L and D: "取值范围 0～1000 mm，如果…超过范围，则忽略"
_Point = tuple[float, ...]


class HeldCorner(NamedTuple):
    """A move whose corner waits for the next move: the chamfer or rounding (``kind``, ``value``),
    where its record is (``place`` in ``Planner.moves``, or in the shape's segments when
    ``in_shape``; -1 when moves are not kept) and the record as made, its line, mode, feed, unit
    (25.4 under G20), plane, start, end, arc centre, seconds and length (program units)."""

    kind: str
    value: float
    place: int
    record: Move | None
    in_shape: bool
    line: int
    mode: float
    feed: float
    unit: float
    plane: float
    start: _Point
    end: _Point
    centre: _Point | None
    seconds: float
    length: float


def corner_word(p: Planner, mode: float, other: dict[str, float]) -> tuple[str, float] | None:
    """The chamfer or rounding a G01/G02/G03 block asks for, as (kind, value): its ``,C`` or ``,R``
    (``Planner.block_corner``, ``Planner.block_corner_value``), else the profile's own words
    (``Dialect.chamfer_words``: GSK's L and D, ignored outside 0–1000 mm; L of type II, the machine
    file's ``chamfer_type``, is a chamfer as ``,C``)."""
    if mode not in CUTTING_MODES:
        return None
    letter = p.block_corner
    if letter is not None:
        value = p.block_corner_value
        if value is None or value <= 0.0:
            return None
        return (CHAMFER if letter == "C" else ROUND), value
    words = p.dialect.chamfer_words
    if words is None:
        return None
    length = CHAMFER if p.settings.chamfer_type == "II" else LENGTH  # type II: L to the intersection, as ,C
    for kind, word in ((length, words[0]), (ROUND, words[1])):
        value = other.get(word)
        if value is not None:
            return (kind, value) if 0.0 < value <= _LIMIT else None
    return None


def hold_corner(
    p: Planner, word: tuple[str, float], line: int, mode: float, start: _Point, end: _Point,
    centre: _Point | None, seconds: float, length: float,
) -> None:  # fmt: skip
    """Hold the move just recorded from ``start`` to ``end`` (``seconds``, ``length`` in program
    units) for the corner ``word`` after it."""
    if p.cutter is not None:  # not composed with cutter radius compensation (module docstring)
        _note(p, word, line, detail(
            "under cutter radius compensation (G41/G42) it is not inserted: the toolpath keeps the sharp corner "
            "and the time counts none",
            "刀具半径补偿（G41/G42）方式中不插入：刀具轨迹保留尖角，时间中不计入"))  # fmt: skip
        return
    plane = p.modal.get("plane", 17.0)
    if plane not in p.times.planes:
        return
    shape = p.shape
    in_shape = shape is not None and shape.reading
    if in_shape:
        assert shape is not None
        place, record = len(shape.segments) - 1, None
    elif p.record_moves and p.moves and p.moves[-1].line == line:
        place, record = len(p.moves) - 1, p.moves[-1]
    else:
        place, record = -1, None
    unit = INCH if p.modal.get("units") == 20.0 else 1.0
    p.corner = HeldCorner(word[0], word[1], place, record, in_shape, line, mode, float(p.codes.get("F") or 0.0),
                          unit, plane, start, end, centre, seconds, length)  # fmt: skip


def _note(p: Planner, word: tuple[str, float], line: int, why: Detail) -> None:
    """Note on ``line`` why the corner ``word`` after its move is not cut."""
    en, zh = _NAMES[word[0]]
    p.host.note(
        "simulation",
        detail(
            f"{en} {word[1]:g} between this move and the next: {why}",
            f"本段与下一段之间的{zh} {word[1]:g}：{why.zh}",
        ),
        line,
        "not-simulated",
    )


def _element(mode: float, start: _Point, end: _Point, centre: _Point | None, axes: tuple[int, int, float, float]
             ) -> PathElement:  # fmt: skip
    i, j, si, sj = axes
    a, b = (start[i] * si, start[j] * sj), (end[i] * si, end[j] * sj)
    if centre is None or mode not in ARC_MODES:
        return PathElement(a, b)
    return PathElement(a, b, (centre[i] * si, centre[j] * sj), mode == 3.0)


def _full(q: tuple[float, float], like: _Point, axes: tuple[int, int, float, float]) -> _Point:
    i, j, si, sj = axes
    point = list(like)
    point[i], point[j] = q[0] / si, q[1] / sj
    return tuple(point)


def _in_plane(start: _Point, end: _Point, axes: tuple[int, int, float, float]) -> bool:
    """Whether a move from ``start`` to ``end`` moves no axis but the plane's two."""
    i, j = axes[0], axes[1]
    return all(a == b for k, (a, b) in enumerate(zip(start, end, strict=True)) if k not in (i, j))


def take_corner(
    p: Planner, mode: float, plane: float, start: _Point, end: _Point, centre: _Point | None, plain: bool
) -> _Point:
    """The held corner (if any) cut before the move from ``start`` to ``end`` (``plain``: a move of a
    block, not a cycle's leg or pass): the held move shortened, the chamfer or arc recorded, and
    where this move now starts."""
    held = p.corner
    p.corner = None
    assert held is not None
    shape = p.shape
    in_shape = shape is not None and shape.reading
    axes = p.times.planes.get(plane)
    if in_shape != held.in_shape or start != held.end:
        return start
    if not plain or mode not in CUTTING_MODES:  # a G00, a cycle, a return: PS0052 on FANUC
        _next_alarm(p, held, CORNER_NOT_CUT, detail("the next block is not a G01, G02 or G03 move",
                                                    "下一程序段不是 G01、G02 或 G03 的移动"))  # fmt: skip
        return start
    if plane != held.plane or axes is None or not _in_plane(start, end, axes):  # PS0051 on FANUC
        _next_alarm(p, held, CORNER_NO_MOVE, detail("the next block moves off the plane of the corner",
                                                   "下一程序段的移动不在该拐角所在的平面内"))  # fmt: skip
        return start
    if not _in_plane(held.start, held.end, axes):
        return start
    before = _element(held.mode, held.start, held.end, held.centre, axes)
    after = _element(mode, start, end, centre, axes)
    try:
        if held.kind == CHAMFER:
            inserted = chamfer(before, after, held.value)
        elif held.kind == LENGTH:
            inserted = chamfer_of_length(before, after, held.value)
        else:
            inserted = rounding(before, after, held.value)
    except NoFit as fault:
        _no_fit(p, held, fault.reason)
        return start
    if inserted is None:
        return start
    if in_shape:
        assert shape is not None
        _shape_corner(shape.segments, held, inserted, axes)
    else:
        _cut_corner(p, held, inserted, axes)
    return _full(inserted.end, start, axes)


def _next_alarm(p: Planner, held: HeldCorner, number: int, why: Detail) -> None:
    """The block after the corner ``held`` does not go on with a G01, G02 or G03 move in its
    plane (``why``): alarm ``number`` (FANUC's PS0051 or PS0052) where the profile has it
    (``Dialect.corner_next_alarm``); elsewhere the corner is left sharp."""
    if not p.dialect.corner_next_alarm:
        return
    en, zh = _NAMES[held.kind]
    raise MacroAlarm(number, detail(
        f"{en} {held.value:g} of the block on line {held.line + 1} needs a G01, G02 or G03 move in its plane "
        f"in the next block: {why}",
        f"第 {held.line + 1} 行程序段的{zh} {held.value:g} 需要下一程序段为该平面内的 G01、G02 或 G03 移动：{why.zh}",
    ), "corner-next")  # fmt: skip


def corner_without_move(p: Planner, moved: bool, dwell: bool) -> None:
    """A block that left the held corner waiting: one that ``moved`` by a way of its own (a
    drilling cycle's holes) is FANUC's PS0052, one that moved nothing PS0051, but for a dwell
    (``dwell``: a G04 block, which the control lets stand between the two moves) and inside a
    roughing cycle's shape, where the cycle's own rules speak (PS0069)."""
    held = p.corner
    if held is None or held.in_shape or dwell:
        return
    if moved:
        _next_alarm(p, held, CORNER_NOT_CUT, detail("the next block is not a G01, G02 or G03 move",
                                                    "下一程序段不是 G01、G02 或 G03 的移动"))  # fmt: skip
    _next_alarm(p, held, CORNER_NO_MOVE, detail("the next block moves nothing", "下一程序段没有移动"))


def _shape_corner(segments: list[tuple[float, _Point, _Point, _Point | None]], held: HeldCorner, inserted: Inserted,
                  axes: tuple[int, int, float, float]) -> None:  # fmt: skip
    """The held shape segment shortened and the chamfer or arc put after it."""
    k = held.place
    if not 0 <= k < len(segments):
        return
    mode, a, _, c = segments[k]
    corner_start = _full(inserted.start, held.end, axes)
    segments[k] = (mode, a, corner_start, c)
    segments.insert(k + 1, _inserted_segment(inserted, corner_start, held.end, axes))


def _inserted_segment(inserted: Inserted, corner_start: _Point, like: _Point, axes: tuple[int, int, float, float]
                      ) -> tuple[float, _Point, _Point, _Point | None]:  # fmt: skip
    end = _full(inserted.end, like, axes)
    if inserted.centre is None:
        return 1.0, corner_start, end, None
    return (3.0 if inserted.ccw else 2.0), corner_start, end, _full(inserted.centre, like, axes)


def _cut_corner(p: Planner, held: HeldCorner, inserted: Inserted, axes: tuple[int, int, float, float]) -> None:
    """The held move shortened in place and the chamfer or arc recorded after it: the clock and the
    cut length take the difference."""
    times = p.times
    corner_start = _full(inserted.start, held.end, axes)
    if held.centre is not None and held.mode in ARC_MODES:
        length = times.arc_length(held.mode, held.plane, held.start, corner_start, held.centre)
    else:
        length = times.distance(held.start, corner_start)
    seconds = p.feed_seconds(held.mode, length, held.feed, held.start, corner_start, held.unit, line=held.line)
    mode, start, end, centre = _inserted_segment(inserted, corner_start, held.end, axes)
    if centre is not None:
        extra = times.arc_length(mode, held.plane, start, end, centre)
    else:
        extra = times.distance(start, end)
    extra_seconds = p.feed_seconds(mode, extra, held.feed, start, end, held.unit, line=held.line)
    cost = (seconds + extra_seconds - held.seconds, (length + extra - held.length) * held.unit)
    p.clock += cost[0]
    p.cut_length += cost[1]
    p.corner_cost = cost
    moves = p.moves
    k = held.place
    if held.record is not None and 0 <= k < len(moves) and moves[k] is held.record:
        moves[k] = held.record._replace(end=corner_start, seconds=seconds)
        moves.insert(k + 1, held.record._replace(mode=mode, start=start, end=end, centre=centre,
                                                 seconds=extra_seconds, tool_path=None))  # fmt: skip
        p.moves_full(held.line)


def _no_fit(p: Planner, held: HeldCorner, reason: str) -> None:
    """A chamfer or rounding that does not fit its moves: the control's alarm, else a note."""
    v = f"{held.value:g}"
    if reason == LONG:
        en, zh = (f"the chamfer {v} is longer than the third side of the triangle the two moves make",
                  f"倒角直线长度 {v} 大于两段插补直线形成的三角形的第三边")  # fmt: skip
    elif reason == RADIUS:
        en, zh = (f"no arc of radius {v} tangent to both moves fits on them: the radius is too large or a move "
                  "too short",
                  f"半径 {v} 的圆弧无法与两段移动均相切：倒角圆弧半径过大或某段移动过短")  # fmt: skip
    else:
        en, zh = (f"a move is too short for the chamfer {v}: its end would be off the move, on its extension",
                  f"某段移动过短，不足以插入 {v} 的倒角，其端点将不在插补线上（而在其延长线上）")  # fmt: skip
    message = detail(f"{en} (the block on line {held.line + 1} and the next)",
                     f"{zh}（第 {held.line + 1} 行程序段与下一段）")  # fmt: skip
    if p.dialect.corner_fit_alarm:
        raise MacroAlarm(CORNER_FIT, message, "corner-fit")
    p.host.note("simulation", detail(f"{message}; the corner is left sharp", f"{message.zh}；保留尖角"),
                held.line, "not-simulated")  # fmt: skip


def restore_corner(p: Planner) -> None:
    """After a snapshot is restored: the held move's record as it was while it was held (a later
    move may have shortened it before the run was taken back)."""
    held = p.corner
    if held is None or held.record is None or held.in_shape:
        return
    moves = p.moves
    if 0 <= held.place < len(moves) and moves[held.place].line == held.line:
        moves[held.place] = held.record
