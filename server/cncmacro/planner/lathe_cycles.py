"""A lathe's multiple repetitive cycles in the planner (docs/semantics.md, "Lathe cycles"):
what each block of G70–G76 means and the moves it makes.

- **The first block** of G71, G72, G73, G74, G75 and G76 (the one without P and Q, or without an
  end point) only sets the cycle's parameters, kept until the next such block: its U and W are
  not moves (``params``).
- **G71, G72, G73 with P and Q** name the finishing shape, the blocks from N(P) to N(Q). The
  planner answers with a ``ShapeCall``; the macro machine runs those blocks while the planner
  *reads* them (``begin_shape``: every move of theirs is kept as a shape segment instead of
  being made, their F, S and T are ignored), and when the block N(Q) is done it calls
  ``end_shape``, which turns the shape into the passes (stock_removal.py) and records them as
  the cycle block's moves. The tool is back at the start point.
  Where the profile takes the first block's words in that block (``LatheCycles.one_block``,
  Haas's ``G71 P Q U W D``), its D is the depth (G73: I and K the relief, D the passes) and no
  first block is needed.
- **G70 P Q** runs the shape blocks as they are written, with their own F, S and T, then
  returns to the start point at rapid.
- **G74, G75, G76** (GSK's G78) and the single cycles G90, G92, G94 are planned by their own modules
  (``MULTIPLE_CYCLES``: groove_cycles.py, thread_cycles.py; turning_cycles.py); a code no
  module plans is recorded as one cut.

Every move of a cycle is recorded with the cycle block's line and ``pass_of`` (its code), so
the toolpath view draws each pass and the debugger knows which pass it is on.

Under tool nose radius compensation (cutter_stage.py; docs/semantics.md §12) G70's shape blocks
are cut compensated, as any block; the roughing passes of G71–G73 and the moves of the other
cycles are drawn as programmed, the compensation set aside for them and taken up again after.
Where the profile compensates a shape only from its first block
(``Dialect.shape_compensation_first_block``: GSK980TDi), a compensation in force before the
cycle is set aside for it, a G41/G42 on the shape's first block compensates G70's pass, and the
return to the start point cancels it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, NamedTuple

from ..bilingual import detail
from .cutter_stage import CANCEL, CutterStage, uncompensated
from .cycle_passes import Pass, record_passes
from .cycle_rules import check_cycle_block, check_shape
from .groove_cycles import diameter_grooving, face_grooving
from .stock_removal import Point, Segment, Step, pattern_passes, rough_passes, translate
from .thread_cycles import enhanced_thread, multiple_thread

if TYPE_CHECKING:
    from .planner import Planner

ROUGHING = frozenset({71.0, 72.0, 73.0})
FINISHING = 70.0
SHAPE_CODES = ROUGHING | {FINISHING}
# the cycles whose blocks the control checks (cycle_rules.py), planned or not
CHECKED_CYCLES = SHAPE_CODES | {74.0, 75.0, 76.0}
# G71–G73's own words: in their blocks U and W are parameters (depths, allowances), never moves
_PARAMETER_UW = SHAPE_CODES


class ShapeCall(NamedTuple):
    """A cycle that names a finishing shape: its code and the labels P (first block) and Q
    (last). The planner has begun the shape (``begin_shape``) when it answers one."""

    code: float
    first: float
    last: float


@dataclass(slots=True)
class ShapeReading:
    """A shape cycle under way: its code, block (file, line), words, where the tool started,
    whether the shape is being read (G71–G73) rather than run (G70), the codes its reading set
    aside, the segments read so far (mode, start, end, centre), in work coordinates, the axes
    (by index) its first block with an axis word names (both X and Z: a type II shape), and under
    tool nose radius compensation (cutter_stage.py) whether its first block has G41/G42, the
    compensation set aside for the cycle and the G40/G41/G42 code in force before it."""

    code: float
    file: str
    line: int
    words: dict[str, float]
    start: tuple[float, ...]
    reading: bool
    kept_codes: dict[str, float | None]
    segments: list[tuple[float, tuple[float, ...], tuple[float, ...], tuple[float, ...] | None]] = field(
        default_factory=list
    )
    first_axes: frozenset[int] | None = None
    compensated: bool = False
    kept_cutter: CutterStage | None = None
    cutter_code: float = CANCEL

    def copy(self) -> ShapeReading:
        return ShapeReading(self.code, self.file, self.line, dict(self.words), self.start, self.reading,
                            dict(self.kept_codes), list(self.segments), self.first_axes, self.compensated,
                            None if self.kept_cutter is None else self.kept_cutter.copy(),
                            self.cutter_code)  # fmt: skip


# code -> the planner of a cycle's second block: (planner, block words with U/W, file, line, end point)
MultipleCycle = Callable[["Planner", dict[str, float], str, int, list[float]], None]
MULTIPLE_CYCLES: dict[float, MultipleCycle] = {
    74.0: face_grooving,  # groove_cycles.py
    75.0: diameter_grooving,
    76.0: multiple_thread,  # thread_cycles.py
    78.0: enhanced_thread,  # GSK980TDi's G78 (a code only a profile with it in ``cycle_codes`` reaches)
}


def block_words(p: Planner, axes: dict[int, float], inc: dict[int, float], other: dict[str, float]) -> dict[str, float]:
    """The block's words by letter again (X, Z as given; U, W as written)."""
    words = dict(other)
    names = p.dialect.axes
    back = {v: k for k, v in p.dialect.incremental_letters.items()}
    for i, v in axes.items():
        words[names[i]] = v
    for i, v in inc.items():
        words[back[names[i]]] = v
    return words


def lathe_cycle(
    p: Planner, g: float, axes: dict[int, float], inc: dict[int, float], other: dict[str, float], file: str, line: int
) -> tuple[bool, ShapeCall | None]:
    """Carry out a block of lathe cycle ``g`` (module docstring): (moved, the shape to read or run)."""
    if g in SHAPE_CODES:
        words = block_words(p, axes, inc, other)
        check_cycle_block(p, g, words, line)
        if ("P" in words and "Q" in words) if g == FINISHING else second_block(p, g, words):
            call = ShapeCall(g, words["P"], words["Q"])
            begin_shape(p, call, words, file, line)
            return True, call
        if g != FINISHING:
            p.cycle_params[g] = words
        return False, None
    if p.cutter is not None:  # drawn as programmed under tool nose radius compensation (module docstring)
        return uncompensated(p, lambda: _other_cycle(p, g, axes, inc, other, file, line))
    return _other_cycle(p, g, axes, inc, other, file, line)


def _other_cycle(
    p: Planner, g: float, axes: dict[int, float], inc: dict[int, float], other: dict[str, float], file: str, line: int
) -> tuple[bool, ShapeCall | None]:
    """A block of a lathe cycle other than G70–G73 (``lathe_cycle``)."""
    plan = MULTIPLE_CYCLES.get(g)
    if plan is not None or g in CHECKED_CYCLES:
        words = block_words(p, axes, inc, other)
        if not second_block(p, g, words):  # the first block: its parameters
            check_cycle_block(p, g, dict(other), line)
            p.cycle_params[g] = dict(other)
            return False, None
        check_cycle_block(p, g, words, line)
        if plan is not None:
            plan(p, words, file, line, p.target(axes, inc))
            return True, None
    p.turning_cycle(file, line, g, axes, inc, other)
    return bool(axes or inc), None


def second_block(p: Planner, g: float, words: dict[str, float]) -> bool:
    """Whether a block of two-block cycle ``g`` with ``words`` is its second, the one that cuts:
    the profile's rule (``Dialect.cycle_words``, dialects/cycle_words.py: G71–G73 with P and Q,
    G74–G76 with an end point), which the editor's hover follows too."""
    described = p.dialect.cycle_words.get(g)
    return described is not None and described.is_second(words)


def begin_shape(p: Planner, call: ShapeCall, words: dict[str, float], file: str, line: int) -> None:
    """The machine is about to run the blocks of ``call``'s shape: read them (G71–G73) or run
    them (G70) from where the tool is."""
    reading = call.code in ROUGHING
    kept = {k: p.codes.get(k) for k in ("F", "S", "T")} if reading else {}
    shape = ShapeReading(call.code, file, line, words, tuple(p.pos), reading, kept)
    shape.cutter_code = p.modal.get("cutter", CANCEL)
    stage = p.cutter
    if stage is not None and (reading or p.dialect.shape_compensation_first_block):  # set aside for the cycle
        shape.kept_cutter = stage
        p.cutter = None
    p.shape = shape


def end_shape(p: Planner) -> None:
    """The block N(Q) is done: plan and record the roughing passes (G71–G73) or return to the
    start point (G70). The tool ends where the cycle started."""
    shape = p.shape
    if shape is None:
        return
    p.shape = None
    start = list(shape.start)
    if not shape.reading:
        # under compensation the last block ends on its end's perpendicular and the return is made
        # as programmed (as G28's moves, cutter_stage.py); where the shape's G41/G42 is the cycle's
        # own (GSK), the return cancels it
        if p.cutter is not None:
            uncompensated(p, lambda: p.move(shape.file, shape.line, 0.0, start))
            if p.dialect.shape_compensation_first_block:
                p.cutter = None
        else:
            p.move(shape.file, shape.line, 0.0, start)
        _after_shape(p, shape)
        return
    for k, v in shape.kept_codes.items():
        p.codes[k] = v
    check_shape(p, shape)
    p.pos[:] = start
    xi, zi = p.axis_index["X"], p.axis_index["Z"]
    facing = shape.code == 72.0
    passes: list[Pass] = []
    at = tuple(start)
    for step in _roughing_steps(p, shape, xi, zi, facing):
        end = list(at)
        a, b = step.end
        end[xi], end[zi] = (b * 2.0, a) if facing else (a * 2.0, b)
        centre = None
        if step.centre is not None:
            c = list(end)
            a, b = step.centre
            c[xi], c[zi] = (b * 2.0, a) if facing else (a * 2.0, b)
            centre = tuple(c)
        passes.append((step.mode, at, tuple(end), centre))
        at = passes[-1][2]
    record_passes(p, shape.file, shape.line, passes, f"G{shape.code:g}")
    p.pos[:] = start
    _after_shape(p, shape)


def _after_shape(p: Planner, shape: ShapeReading) -> None:
    """Take up again the compensation set aside for the cycle: the next move in the plane starts
    it from where the tool is (cutter_stage.py). Where only the shape's first block compensates
    (GSK980TDi §3.23.1), the cycle leaves the G40/G41/G42 code as it found it, and a compensation in
    force before the cycle without a G41/G42 on that block leaves the shape uncompensated: a
    warning on the cycle block, since the control gives no alarm."""
    kept = shape.kept_cutter
    if kept is not None and kept.code != CANCEL:
        kept.on = False
        kept.pending = None
        p.cutter = kept
    if not p.dialect.shape_compensation_first_block:
        return
    p.modal["cutter"] = shape.cutter_code
    if kept is not None and kept.code != CANCEL and not shape.compensated:
        c = f"G{shape.code:g}"
        p.host.note("cycle", detail(
            f"{c}: the tool nose radius compensation in force is set aside for the cycle, and the shape's first block "
            "N(P) has no G41/G42: this control cuts the shape without compensation",
            f"{c}：已有的刀尖半径补偿在循环中暂时取消，而精车形状的第一段 N(P) 没有 G41/G42：本系统不带补偿切削该形状"),
            shape.line, "cycle-shape")  # fmt: skip


def _roughing_steps(p: Planner, shape: ShapeReading, xi: int, zi: int, facing: bool) -> list[Step]:
    """The passes of a roughing cycle in its own plane: (X radius, Z) for G71 and G73, (Z, X
    radius) for G72 (``facing``); ``xi`` and ``zi`` are the X and Z axes' indexes."""

    def to_plane(q: tuple[float, ...]) -> Point:
        return (q[zi], q[xi] / 2.0) if facing else (q[xi] / 2.0, q[zi])

    segments = [Segment(m, to_plane(a), to_plane(b), None if c is None else to_plane(c))
                for m, a, b, c in shape.segments]  # fmt: skip
    if not segments:
        return []
    words = shape.words
    first = p.cycle_params.get(shape.code, {})
    du, dw = words.get("U", 0.0) / 2.0, words.get("W", 0.0)
    allowance = (dw, du) if facing else (du, dw)
    cycles = p.dialect.lathe_cycles
    moved = translate(segments, *allowance)
    offset_start = moved[0].start  # A moved by the allowances (A′; G73's last pass's An)
    moved[0] = Segment(moved[0].mode, to_plane(shape.start), moved[0].end, moved[0].centre)
    start = to_plane(shape.start)
    approach = 0.0 if segments[0].mode == 0.0 else 1.0
    if shape.code == 73.0:
        relief = (first.get("U", 0.0), first.get("W", 0.0))
        count = round(first.get("R", 1.0))
        if cycles.one_block and "D" in words:  # Haas: G73 P Q I K U W D, D the passes
            relief, count = (words.get("I", 0.0), words.get("K", 0.0)), round(words["D"])
        if not cycles.pattern_through_offset_starts:
            return pattern_passes(start, moved, relief, count)
        moved[0] = Segment(moved[0].mode, offset_start, moved[0].end, moved[0].centre)
        return pattern_passes(start, moved, relief, max(count, cycles.pattern_min_passes), approach)
    depth = first.get("W" if facing else "U", 0.0)
    if p.dialect.lathe_cycles.one_block and "D" in words:  # Haas: G71 P Q U W D, D the depth of cut
        depth = words["D"]
    retract = first.get("R", 0.0)
    # G18: G03 turns from Z toward X, so counterclockwise in (z, x) (G72's plane), clockwise in (x, z)
    ccw_mode = 3.0 if facing else 2.0
    via = offset_start if cycles.roughing_from_offset_start else None
    retract_mode = 1.0 if cycles.roughing_retract_at_feed else 0.0
    type_two = shape.first_axes is not None and {xi, zi} <= shape.first_axes  # its first block names both axes
    return rough_passes(start, moved, depth, retract, approach, ccw_mode, via, retract_mode, type_two)
