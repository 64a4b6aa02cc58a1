"""The centre of a G02/G03 arc, as the control finds it from R or from I, J, K (docs/semantics.md §8).

The plane decides which two axes the arc turns in and which offset words give its centre:
G17 X,Y with I,J; G18 Z,X with K,I; G19 Y,Z with J,K. G02 turns clockwise and G03
counterclockwise as seen from the positive end of the third axis. I, J, K are incremental
from the start point whatever G90/G91 says. R names the radius instead: R > 0 the arc of at
most 180°, R < 0 the longer one; R wins over I, J, K in the same block. On a lathe X is a
diameter while I is a radius value (the GSK980 convention: I is the centre's X distance from
the start "用半径表示"), so the geometry is worked in radius terms and the centre's X is given
back as a diameter, like the end points. R with the end at the start is an arc of 0° (the tool
does not move; the centre is the start: FANUC's operator's manuals); a radius shorter than half
the chord puts the centre at the chord's midpoint (a half circle); I, J, K with the end at the
start (or no axis word at all) is a full circle; an arc without R or an offset word of its
plane has no centre (None). The axes off the plane (the helical axis too) keep their start
values.

``arc_fault`` is the one rule of an arc the control cannot cut as written (docs/semantics.md
§8, "Arcs"): I, J, K whose end point is farther from the centre or nearer to it than the start
by more than the tolerance (FANUC's alarm PS0020, parameter 3410), an R shorter than half the
chord by more than the tolerance, and R with the end at the start (no move at all).
``moves_in_plane`` says whether an arc with no centre (neither R nor an offset word of its plane)
goes anywhere in the plane: FANUC's alarm PS0022 (arc_checks.py).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

ARC_MODES = (2.0, 3.0)

# what ``arc_fault`` finds
RADIUS_MISMATCH = "arc-radius"  # I, J, K: the end is not on the start's circle
SHORT_RADIUS = "arc-short-radius"  # R shorter than half the chord
R_FULL_CIRCLE = "arc-r-full-circle"  # R with the end at the start: the tool does not move

# plane code -> (first axis, second axis, first offset word, second offset word)
PLANES: dict[float, tuple[str, str, str, str]] = {
    17.0: ("X", "Y", "I", "J"),
    18.0: ("Z", "X", "K", "I"),
    19.0: ("Y", "Z", "J", "K"),
}

Plane = tuple[int, int, str, str]


def arc_planes(axis_index: Mapping[str, int]) -> dict[float, Plane]:
    """The planes whose two axes this machine has, with the axes as indexes."""
    return {
        code: (axis_index[a], axis_index[b], off_a, off_b)
        for code, (a, b, off_a, off_b) in PLANES.items()
        if a in axis_index and b in axis_index
    }


def plane_scales(plane: Plane, diameter: int) -> tuple[float, float]:
    """What each of ``plane``'s two axes is multiplied by to be a length in the plane: 0.5 for
    the axis programmed as a diameter (``diameter``, a lathe's X), else 1."""
    return 0.5 if plane[0] == diameter else 1.0, 0.5 if plane[1] == diameter else 1.0


def arc_centre(
    clockwise: bool,
    plane: Plane,
    diameter: int,
    start: Sequence[float],
    end: Sequence[float],
    words: Mapping[str, float],
) -> tuple[float, ...] | None:
    """The centre of the arc from ``start`` to ``end`` in ``plane`` given the block's R, I,
    J, K ``words``; ``diameter`` is the index of the axis programmed as a diameter (-1 for
    none). None when the block names no centre for this plane."""
    a, b, off_a, off_b = plane
    scale_a, scale_b = plane_scales(plane, diameter)
    sa = start[a] * scale_a
    sb = start[b] * scale_b
    r = words.get("R")
    if r is not None:
        da = end[a] * scale_a - sa
        db = end[b] * scale_b - sb
        d2 = da * da + db * db
        if d2 == 0.0:
            return tuple(start)  # an arc of 0°: nothing moves
        # the centre is off the chord's midpoint by h along the chord's normal: h/d = k
        k2 = r * r / d2 - 0.25
        k = k2**0.5 if k2 > 0.0 else 0.0  # a radius shorter than half the chord: the midpoint
        if clockwise != (r > 0.0):  # G02 R+ and G03 R- lie right of the chord, the others left
            k = -k
        ca = sa + 0.5 * da + k * db
        cb = sb + 0.5 * db - k * da
    else:
        ia = words.get(off_a)
        ib = words.get(off_b)
        if ia is None and ib is None:
            return None
        ca = sa + ia if ia is not None else sa
        cb = sb + ib if ib is not None else sb
    centre = list(start)
    centre[a] = ca / scale_a
    centre[b] = cb / scale_b
    return tuple(centre)


def moves_in_plane(plane: Plane, start: Sequence[float], end: Sequence[float]) -> bool:
    """Whether the move from ``start`` to ``end`` changes either of ``plane``'s two axes (a move
    of the axis normal to the plane alone does not)."""
    return end[plane[0]] != start[plane[0]] or end[plane[1]] != start[plane[1]]


def arc_fault(
    plane: Plane,
    diameter: int,
    start: Sequence[float],
    end: Sequence[float],
    centre: Sequence[float],
    words: Mapping[str, float],
    tolerance: float,
) -> tuple[str, float, float] | None:
    """What is wrong with the arc from ``start`` to ``end`` about ``centre`` (``arc_centre``'s) in
    ``plane``, as the block's R, I, J, K ``words`` wrote it, with ``tolerance`` in the program's
    unit: ``(RADIUS_MISMATCH, start radius, end radius)`` when they differ by more than the
    tolerance, ``(SHORT_RADIUS, |R|, half the chord)`` when R falls short of half the chord by more
    than the tolerance, ``(R_FULL_CIRCLE, |R|, 0)`` for R with the end at the start; None for an
    arc the control cuts as written. A tolerance of 0 checks nothing (FANUC's parameter 3410 = 0)."""
    a, b = plane[0], plane[1]
    scale_a, scale_b = plane_scales(plane, diameter)
    r = words.get("R")
    if r is not None:
        da = (end[a] - start[a]) * scale_a
        db = (end[b] - start[b]) * scale_b
        chord2 = da * da + db * db
        if chord2 == 0.0:
            return (R_FULL_CIRCLE, abs(r), 0.0) if r != 0.0 else None
        if 4.0 * r * r >= chord2:
            return None  # R reaches half the chord: the arc is cut as written
        half = 0.5 * chord2**0.5
        if tolerance > 0.0 and half - abs(r) > tolerance:
            return SHORT_RADIUS, abs(r), half
        return None
    if tolerance <= 0.0:
        return None
    ca = centre[a] * scale_a
    cb = centre[b] * scale_b
    r0 = ((start[a] * scale_a - ca) ** 2 + (start[b] * scale_b - cb) ** 2) ** 0.5
    r1 = ((end[a] * scale_a - ca) ** 2 + (end[b] * scale_b - cb) ** 2) ** 0.5
    if abs(r1 - r0) > tolerance:
        return RADIUS_MISMATCH, r0, r1
    return None
