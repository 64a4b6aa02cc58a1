"""G74 and G75, a lathe's grooving cycles, planned into their pecks (docs/semantics.md §10.3).

The first block ``G74 R(e)`` (``G75 R(e)``) sets e, the retract after each peck. The second,
``G74 X(U) Z(W) P(Δi) Q(Δk) R(Δd) F``, pecks along Z (G74: face grooving, peck drilling when X
and P are left out) or along X (``G75``: grooving the diameter), in columns that shift across:

- G74 feeds along Z by Δk, retracts e at rapid, feeds Δk + e, … until Z, then at rapid moves
  off the wall by Δd along X (the other way than the columns go), back along Z to the start's
  Z, and across to the next column Δi further along X (the last at the end point's X).
- G75 is the same with X and Z swapped: pecks of Δi along X, columns Δk apart along Z, Δd off
  along Z at the bottom.

After the last column the tool returns at rapid along the shift axis to the start point. P and
Q are written without a decimal point, in least input increments (``in_increments``); e and
Δd are millimetres; e is a radius. Along X the GSK980TDi gives Δi (and G74's Δd) as diameters
(§3.23.5, §3.23.6), the FANUC 0i-TF as radii (``LatheCycles.groove_x_on_diameter``). Every
move is recorded as a pass of its cycle (``pass_of``).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .cycle_passes import Pass, record_passes
from .turning_cycles import in_increments

if TYPE_CHECKING:
    from .planner import Planner

_MOST_STEPS = 99999  # pecks or columns of one cycle at most, whatever its words


def _step_words(p: Planner, words: dict[str, float]) -> tuple[float, float]:
    """The block's step along X and along Z in least input increments: P and Q, or where the
    profile names other letters (``LatheCycles.groove_letters``, Haas's I and K, written in the
    program's unit) those, converted."""
    letters = p.dialect.lathe_cycles.groove_letters
    if letters is None:
        return words.get("P", 0.0), words.get("Q", 0.0)
    one = in_increments(p, 1.0)
    return words.get(letters[0], 0.0) / one, words.get(letters[1], 0.0) / one


def face_grooving(p: Planner, words: dict[str, float], file: str, line: int, target: list[float]) -> None:
    """G74: pecks along Z, columns along X (module docstring)."""
    x_step, z_step = _step_words(p, words)
    _grooving(p, 74.0, words, file, line, target, "Z", "X", z_step, x_step)


def diameter_grooving(p: Planner, words: dict[str, float], file: str, line: int, target: list[float]) -> None:
    """G75: pecks along X, columns along Z (module docstring)."""
    x_step, z_step = _step_words(p, words)
    _grooving(p, 75.0, words, file, line, target, "X", "Z", x_step, z_step)


def _steps(start: float, end: float, step: float) -> list[float]:
    """The points from ``start`` (left out) to ``end`` by ``step``, the last one ``end``."""
    way = (end > start) - (end < start)
    if way == 0:
        return []
    points: list[float] = []
    at = start
    if step > 0.0:
        while len(points) < _MOST_STEPS and (end - (at + way * step)) * way > 1e-9:
            at += way * step
            points.append(at)
    points.append(end)
    return points


def _grooving(
    p: Planner,
    code: float,
    words: dict[str, float],
    file: str,
    line: int,
    target: list[float],
    peck_axis: str,
    shift_axis: str,
    peck_word: float,
    shift_word: float,
) -> None:
    """Plan and record a grooving cycle from where the tool is to ``target`` (module docstring)."""
    pi, si = p.axis_index[peck_axis], p.axis_index[shift_axis]
    diameter = p.times.diameter
    x_words = 1.0 if p.dialect.lathe_cycles.groove_x_on_diameter else 2.0  # X units per unit of P, R

    def along(axis: int, amount: float, per_radius: float) -> float:
        """An amount along ``axis`` in its units: on X, ``per_radius`` X units per unit."""
        return amount * (per_radius if axis == diameter else 1.0)

    retract = along(pi, p.cycle_params.get(code, {}).get("R", 0.0), 2.0)  # e: a radius
    peck = along(pi, in_increments(p, peck_word), x_words)
    shift = along(si, in_increments(p, shift_word), x_words)
    relief = along(si, words.get("R", 0.0), x_words)
    start = tuple(p.pos)
    a_peck, a_shift = start[pi], start[si]
    e_peck, e_shift = target[pi], target[si]
    way = (e_peck > a_peck) - (e_peck < a_peck)
    shift_way = (e_shift > a_shift) - (e_shift < a_shift)
    off = -shift_way if shift_way else 1  # the bottom's relief: against the columns' way
    passes: list[Pass] = []
    at = start

    def go(mode: float, peck_at: float, shift_at: float) -> None:
        nonlocal at
        if at[pi] == peck_at and at[si] == shift_at:
            return
        end = list(at)
        end[pi], end[si] = peck_at, shift_at
        passes.append((mode, at, tuple(end), None))
        at = passes[-1][2]

    columns = [a_shift, *_steps(a_shift, e_shift, shift)]
    for n, column in enumerate(columns):
        depths = _steps(a_peck, e_peck, peck)
        for j, depth in enumerate(depths):
            go(1.0, depth, column)
            if j < len(depths) - 1 and retract > 0.0:
                go(0.0, depth - way * retract, column)
        go(0.0, at[pi], column + off * relief)
        go(0.0, a_peck, at[si])
        if n < len(columns) - 1:
            go(0.0, a_peck, columns[n + 1])
    go(0.0, a_peck, a_shift)
    record_passes(p, file, line, passes, f"G{code:g}")
