"""The GSK980TDi's independent reciprocating feed cycle ``G86 Z_ A_ I_ R_ F_`` (programming
manual §3.23.11; docs/semantics.md §10.3), on the profile whose ``Dialect.reciprocating_feed_code``
names it.

Z is the start point and A the end point along Z, both absolute; I the stroke forward and R the
advance of each stroke, both taken without their sign; F the feed in mm/min, whatever G98/G99
says ("G86 指令速度不受 G99 影响"). The manual's steps: 1) Z feeds at F to the start point; 2) it
feeds I toward the end point (on reaching the end point, step 6); 3) it backs off I − R; 4) it
feeds I; 5) steps 3 and 4 repeat until the end point; 6) it returns to the start point. Each
stroke is recorded as a pass of G86, one after another in the block's time: the control goes on
with the program once Z is at the start point, but waits for the cycle before any block that
moves Z and before T codes, G28, G30, G54–G59, M30 and the threads (the manual's notes), so the
project times the cycle as if the next such block came right after it (a decision; the program
around an oscillation that X feeds beside is timed longer than on the control).

I of 0 and I below R are the manual's alarms ("G86 指令中 I 为 0 时，系统发出报警"; "I 小于 R 值时，
系统发出报警"), no number given. With R 0 and the end point more than one stroke away the cycle
never gets there: Z goes back and forth until a ``G86.1`` stops it, which is not drawn (a note).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..bilingual import detail
from ..dialects.alarms import RECIPROCATION_AMOUNT
from .alarms import MacroAlarm
from .cycle_passes import Pass, record_passes
from .whereabouts import placed

if TYPE_CHECKING:
    from .planner import Planner

_MOST_STROKES = 99999  # strokes of one cycle at most, whatever its words
PER_MINUTE = 98.0


def reciprocating_feed(p: Planner, axes: dict[int, float], other: dict[str, float], file: str, line: int) -> bool:
    """Carry out a G86 block (module docstring); whether Z moved."""
    stroke, advance = abs(other.get("I", 0.0)), abs(other.get("R", 0.0))
    if stroke == 0.0:
        raise MacroAlarm(RECIPROCATION_AMOUNT, detail(
            "G86: the stroke I is 0",
            "G86：每次进刀量 I 为 0"))  # fmt: skip
    if stroke < advance:
        raise MacroAlarm(RECIPROCATION_AMOUNT, detail(
            f"G86: the stroke I{stroke:g} is less than the advance R{advance:g}",
            f"G86：每次进刀量 I{stroke:g} 小于每次前进量 R{advance:g}"))  # fmt: skip
    zi = p.axis_index["Z"]
    start = tuple(p.pos)
    begin = list(start)
    begin[zi] = axes.get(zi, start[zi])
    end_z = other.get("A", begin[zi])
    placed(p, (zi,))
    passes: list[Pass] = []

    def feed_to(z: float) -> None:
        at = passes[-1][2] if passes else start
        if at[zi] != z:
            to = list(at)
            to[zi] = z
            passes.append((1.0, at, tuple(to), None))

    feed_to(begin[zi])
    length = abs(end_z - begin[zi])
    way = 1.0 if end_z >= begin[zi] else -1.0
    endless = advance == 0.0 and length > stroke
    if not endless:
        reached = 0.0  # how far along from the start the stroke forward got
        back = 0.0  # where the last back-off left the tool
        while len(passes) < 2 * _MOST_STROKES:
            reached = min(back + stroke, length)
            feed_to(begin[zi] + way * reached)
            if reached >= length:
                break
            back = reached - (stroke - advance)
            feed_to(begin[zi] + way * back)
        feed_to(begin[zi])
    feed_mode = p.modal.get("feed")
    p.modal["feed"] = PER_MINUTE
    try:
        record_passes(p, file, line, passes, "G86")
    finally:
        if feed_mode is None:
            del p.modal["feed"]
        else:
            p.modal["feed"] = feed_mode
    p.pos[:] = begin
    if endless:
        p.host.note("simulation", detail(
            f"G86 with R0: Z goes back and forth by I{stroke:g} without advancing until G86.1 stops it; the "
            "strokes are not drawn or timed",
            f"G86 的 R 为 0：Z 轴以 I{stroke:g} 往复而不前进，直到 G86.1 中止；未绘制也不计时其往复"),
            line, "not-simulated")  # fmt: skip
    return bool(passes)
