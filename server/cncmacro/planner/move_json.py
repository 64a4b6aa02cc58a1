"""A move as JSON (docs/design.md's run object): what ``cncmacro run --json`` prints and what
the debug adapter sends the toolpath view, in one form."""

from __future__ import annotations

from typing import Any

from .arcs import PLANES
from .moves import ARC, CYCLE, DRILLING, MODE_NAMES, Move, move_kind


def move_json(mv: Move, axes: tuple[str, ...]) -> dict[str, Any]:
    """A move with its file, 1-based line, mode (``G01``), ``kind`` (moves.py's ``move_kind``:
    rapid, feed, arc, probe or cycle), end points, feed and time in seconds (``cycle_time.py``);
    an arc (G02/G03) also gets its ``centre``, axis by axis, and its ``plane``: the two axes it
    turns in, ordered so that G03 turns from the first toward the second (G17 X Y, G18 Z X,
    G19 Y Z), and whether it turns ``clockwise``; a cycle gets its ``legs`` (each ``rapid`` or
    not, ``to`` a point) and its ``cycle`` (``drilling`` or ``turning``), and a drilling cycle's
    hole its ``hole`` (where it was drilled to: its bottom); a pass of a lathe cycle names the
    cycle in ``pass_of`` (``G71``)."""
    kind = move_kind(mv)
    move: dict[str, Any] = {
        "file": mv.file,
        "line": mv.line + 1,
        "mode": MODE_NAMES.get(mv.mode, f"G{mv.mode:g}"),
        "kind": kind,
        "from": dict(zip(axes, mv.start, strict=True)),
        "to": dict(zip(axes, mv.end, strict=True)),
        "feed": mv.feed,
        "time": mv.seconds,
    }
    if mv.centre is not None:
        move["centre"] = dict(zip(axes, mv.centre, strict=True))
    if kind == ARC:
        plane = PLANES.get(mv.plane)
        if plane is not None:
            move["plane"] = [plane[0], plane[1]]
        move["clockwise"] = mv.mode == 2.0
    if kind == CYCLE and mv.legs is not None:
        move["cycle"] = mv.cycle
        move["legs"] = [{"rapid": leg.rapid, "to": dict(zip(axes, leg.end, strict=True))} for leg in mv.legs]
    if mv.pass_of is not None:
        move["pass_of"] = mv.pass_of
    if mv.cycle == DRILLING:
        move["hole"] = dict(zip(axes, mv.end, strict=True))
    return move
