"""The passes of a lathe's stock removal cycles G71, G72 and G73, as plain geometry
(docs/semantics.md, "Lathe cycles").

Everything here works in a plane of two coordinates ``(a, b)``: ``a`` the axis the cycle steps
its depth along, ``b`` the axis it cuts along, both in radius terms (a lathe's X diameter is
halved before and doubled after, by ``lathe_cycles.py``). G71 steps along X and cuts along Z;
G72 steps along Z and cuts along X. A ``Segment`` of the finishing shape is a line or an arc in
the same plane; a ``Step`` of the tool path is a rapid, a feed or (on the final pass along the
shape) an arc.

G71/G72 (FANUC 0i-TF and GSK980TDi manuals, "stock removal in turning/facing"): from the start
point A the tool steps in by the depth Δd, cuts along ``b`` until it meets the finishing shape
(offset by the allowances), pulls back by e at 45°, returns along ``b`` at rapid and steps in
again, until the next level would pass the shape's first point (a type II shape, whose first
block names both axes: its deepest point, since its first cut need not be vertical and the shape
may go deeper after it, GSK980TDi §3.23.1 type II item 3). Where the shape dips below a
level again further along (a pocket, type II), the level is cut there too: out to A's depth, over
to where the shape goes below the level, down at rapid to the level above and in at the feed,
along to where the shape comes back up, pulled back by e; and back to A's depth and along ``b``
before the next level; then it cuts once along the
shape offset by the allowances and returns to A at rapid: out along ``a`` to A's depth (or stays
where it is when the shape ended beyond it), back along ``b``, and in to A. The GSK980TDi's steps
(§3.23.1, §3.23.2 ①–⑧) differ: the tool first goes at rapid to A′ (A moved by the allowances),
the levels count from A′ and each cut returns along ``b`` to A′'s, the 45° pull-back is made at
the feed, and from the shape's end C′ the tool goes straight to A at rapid.

G73 (pattern repeating): the shape offset by the relief (Δi, Δk) and the allowances, ``count``
times, the relief shrinking evenly to none on the last pass; each pass goes from A to the offset
shape's first point at rapid, follows it at the feed and returns to A at rapid, or (GSK980TDi
§3.23.3) goes at rapid to the start point offset as the pass, from there in the mode of the
shape's first block to its first point and along it, on to the next pass's start at rapid, and
from the last pass's end to A at rapid.
"""

from __future__ import annotations

import math
from itertools import pairwise
from typing import NamedTuple

Point = tuple[float, float]
MAX_LEVELS = 200_000  # a depth of cut so small that more levels than this are planned stops there
_ARC_STEP = math.radians(2.0)  # arcs are followed in chords of at most 2° to find where a level meets them


class Segment(NamedTuple):
    """One block of the finishing shape: ``mode`` 0 or 1 (a line) or 2 or 3 (an arc about
    ``centre``, G02 or G03 as programmed), from ``start`` to ``end``."""

    mode: float
    start: Point
    end: Point
    centre: Point | None = None


class Step(NamedTuple):
    """One move of a cycle's path: ``mode`` 0 (rapid), 1 (feed) or an arc's 2 or 3 about
    ``centre``, to ``end``."""

    mode: float
    end: Point
    centre: Point | None = None


def _chords(seg: Segment, ccw_mode: float) -> list[Point]:
    """The points of a segment from its start to its end: a line's two, an arc's chords (an arc
    of mode ``ccw_mode`` turns counterclockwise in the ``(a, b)`` plane)."""
    if seg.centre is None or seg.mode not in (2.0, 3.0):
        return [seg.start, seg.end]
    ca, cb = seg.centre
    r = math.hypot(seg.start[0] - ca, seg.start[1] - cb)
    t0 = math.atan2(seg.start[1] - cb, seg.start[0] - ca)
    t1 = math.atan2(seg.end[1] - cb, seg.end[0] - ca)
    sweep = t1 - t0
    ccw = seg.mode == ccw_mode
    if ccw and sweep <= 0:
        sweep += 2 * math.pi
    elif not ccw and sweep >= 0:
        sweep -= 2 * math.pi
    n = max(1, math.ceil(abs(sweep) / _ARC_STEP))
    pts = [(ca + r * math.cos(t0 + sweep * k / n), cb + r * math.sin(t0 + sweep * k / n)) for k in range(n)]
    return [*pts, seg.end]


def shape_polyline(shape: list[Segment], ccw_mode: float) -> list[Point]:
    """The finishing shape as one chain of points, from its first segment's start."""
    if not shape:
        return []
    pts = [shape[0].start]
    for seg in shape:
        pts.extend(_chords(seg, ccw_mode)[1:])
    return pts


def deeper_runs(pts: list[Point], level: float, side: float, b_start: float, end_b: float) -> list[Point]:
    """The stretches along ``b``, in cutting order, where the chain ``pts`` lies deeper than
    ``level`` (``side``: the sign of the way the depth grows into the part): each (where the cut
    at that level starts, where it meets the shape). The first starts at ``b_start`` when the
    chain starts deeper; one still deeper at the chain's end runs to ``end_b``."""
    runs: list[Point] = []
    inside = bool(pts) and side * (pts[0][0] - level) > 0
    b_in = b_start
    for (a0, b0), (a1, b1) in pairwise(pts):
        d0 = side * (a0 - level)
        d1 = side * (a1 - level)
        if inside and d0 > 0 >= d1:
            runs.append((b_in, b0 + (b1 - b0) * d0 / (d0 - d1)))
            inside = False
        elif not inside and d0 <= 0 < d1:
            b_in = b0 + (b1 - b0) * d0 / (d0 - d1)
            inside = True
    if inside:
        runs.append((b_in, end_b))
    return runs


def translate(shape: list[Segment], da: float, db: float) -> list[Segment]:
    """The shape moved by ``(da, db)``."""

    def at(p: Point) -> Point:
        return (p[0] + da, p[1] + db)

    return [Segment(s.mode, at(s.start), at(s.end), None if s.centre is None else at(s.centre)) for s in shape]


def along_shape(shape: list[Segment]) -> list[Step]:
    """The steps that follow ``shape`` at the feed (its arcs as arcs)."""
    return [Step(1.0 if s.mode in (0.0, 1.0) else s.mode, s.end, s.centre) for s in shape]


def rough_passes(
    start: Point,
    shape: list[Segment],
    depth: float,
    retract: float,
    approach: float,
    ccw_mode: float,
    offset_start: Point | None = None,
    retract_mode: float = 0.0,
    to_deepest: bool = False,
) -> list[Step]:
    """G71/G72: the path from ``start`` (A) that removes the stock down to ``shape`` (already
    offset by the finishing allowances) in levels ``depth`` apart, each pass pulled back by
    ``retract`` at 45° in ``retract_mode`` (0 rapid, 1 the feed), then the pass along the shape
    and the return to A (module docstring). ``approach`` is the mode (0 or 1) of the shape's
    first block, by which each level is stepped into; an arc of mode ``ccw_mode`` turns
    counterclockwise in the ``(a, b)`` plane. With ``offset_start`` (A′, A moved by the
    allowances: the GSK980TDi's steps ①–⑧) the tool first goes there at rapid, the levels count
    from it and each cut returns to its ``b``, and from the shape's end it goes straight to A
    at rapid. With ``to_deepest`` (a type II shape) the levels go on down to the shape's deepest
    point rather than stopping at its first point."""
    if not shape or depth <= 0:
        return []
    a_start, b_start = start if offset_start is None else offset_start
    first = shape[0].end
    side = math.copysign(1.0, first[0] - a_start) if first[0] != a_start else 0.0
    pts = shape_polyline(shape, ccw_mode)[1:]  # from the shape's first point on
    end_b = shape[-1].end[1]
    along = math.copysign(1.0, end_b - first[1]) if end_b != first[1] else -1.0
    steps: list[Step] = [] if offset_start in (None, start) else [Step(0.0, offset_start)]
    bottom = max(side * a for a, _ in [first, *pts]) if to_deepest else side * first[0]

    def rapid(to: Point) -> None:  # a rapid to where the tool already is is left out
        if to != (steps[-1].end if steps else (a_start, b_start)):
            steps.append(Step(0.0, to))

    k = 1
    while side and k <= MAX_LEVELS:
        level = a_start + side * depth * k
        if side * level >= bottom:
            break
        runs = deeper_runs(pts, level, side, b_start, end_b)
        out = level - side * retract
        for n, (b_in, b_out) in enumerate(runs):
            if n == 0 and b_in == b_start:  # in from the stock's end, at the level
                steps.append(Step(approach, (level, b_start)))
            else:  # a pocket: over the shape at A's depth, down to the level above, in at the feed
                rapid((a_start, steps[-1].end[1] if steps else b_start))
                rapid((a_start, b_in))
                rapid((level - side * depth, b_in))
                steps.append(Step(1.0, (level, b_in)))
            steps.append(Step(1.0, (level, b_out)))
            steps.append(Step(retract_mode, (out, b_out - along * retract)))
        if len(runs) > 1 or (runs and runs[0][0] != b_start):  # out of a pocket over the shape
            steps.append(Step(0.0, (a_start, steps[-1].end[1])))
            steps.append(Step(0.0, (a_start, b_start)))
        elif runs:
            steps.append(Step(0.0, (out, b_start)))
        k += 1
    steps.append(Step(approach, first))
    steps.extend(along_shape(shape[1:]))
    if offset_start is not None:
        steps.append(Step(0.0, start))
        return steps
    last = steps[-1].end
    out = a_start if side * (a_start - last[0]) <= 0 else last[0]  # never back into the stock
    steps.append(Step(0.0, (out, last[1])))
    steps.append(Step(0.0, (out, b_start)))
    if out != a_start:
        steps.append(Step(0.0, (a_start, b_start)))
    return steps


def pattern_passes(
    start: Point, shape: list[Segment], relief: Point, count: int, approach: float | None = None
) -> list[Step]:
    """G73: ``count`` passes along ``shape`` (already offset by the allowances), the first
    offset by ``relief`` and each later one by an even share less, the last by none.

    Without ``approach`` each pass goes from A to the offset shape's first point at rapid, along
    the shape at the feed, and back to A at rapid. With it (the GSK980TDi's steps, §3.23.3) each
    pass starts at the shape's start offset as the pass (An), reached at rapid from A or from the
    last pass's end, goes to the offset first point (Bn) in ``approach``'s mode (0 rapid, 1 the
    feed: the shape's first block's) and along the shape at the feed; the last ends at rapid at A."""
    steps: list[Step] = []
    if not shape or count < 1:
        return steps
    for k in range(1, count + 1):
        share = (count - k) / (count - 1) if count > 1 else 0.0
        moved = translate(shape, relief[0] * share, relief[1] * share)
        if approach is None:
            steps.append(Step(0.0, moved[0].end))
            steps.extend(along_shape(moved[1:]))
            steps.append(Step(0.0, start))
            continue
        steps.append(Step(0.0, moved[0].start))
        steps.append(Step(approach, moved[0].end))
        steps.extend(along_shape(moved[1:]))
    if approach is not None:
        steps.append(Step(0.0, start))
    return steps
