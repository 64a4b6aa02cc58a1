"""A move as JSON (docs/design.md's run object): what ``cncmacro run --json`` prints and what
the debug adapter sends the toolpath view, in one form; and the machine the moves were made on
(``machine_json``: its profile, whether it is a lathe and the roles of a lathe's axes), so that
the view draws a lathe as a lathe without guessing."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from .arcs import PLANES
from .moves import ARC, CYCLE, DRILLING, MODE_NAMES, Move, move_kind

if TYPE_CHECKING:
    from ..dialects import Dialect

LATHE_PLANE = 18.0  # a lathe turns in the ZX plane: its first axis is the spindle's, its second the radial one


def machine_json(dialect: Dialect) -> dict[str, Any]:
    """The machine the moves were made on: its profile (``dialect``), whether it is a ``lathe``
    and, for a lathe, ``lathe_axes``: the ``spindle`` axis (Z: the view draws it across, with the
    centre line at radial 0), the ``radial`` axis (X, drawn up) and whether the radial axis is
    programmed as a ``diameter`` (on every lathe profile it is: docs/semantics.md §8)."""
    head: dict[str, Any] = {"dialect": dialect.name, "lathe": dialect.lathe}
    spindle, radial = PLANES[LATHE_PLANE][:2]
    if dialect.lathe and spindle in dialect.axes and radial in dialect.axes:
        head["lathe_axes"] = {"spindle": spindle, "radial": radial, "diameter": True}
    return head


def move_json(mv: Move, axes: tuple[str, ...]) -> dict[str, Any]:
    """A move with its file, 1-based line, mode (``G01``), ``kind`` (moves.py's ``move_kind``:
    rapid, feed, arc, probe or cycle), end points, feed and time in seconds (``cycle_time.py``);
    an arc (G02/G03) also gets its ``centre``, axis by axis, and its ``plane``: the two axes it
    turns in, ordered so that G03 turns from the first toward the second (G17 X Y, G18 Z X,
    G19 Y Z), and whether it turns ``clockwise``; a cycle gets its ``legs`` (each ``rapid`` or
    not, ``to`` a point) and its ``cycle`` (``drilling`` or ``turning``), and a drilling cycle's
    hole its ``hole`` (where it was drilled to: its bottom); a pass of a lathe cycle names the
    cycle in ``pass_of`` (``G71``); a move from or to a place the run does not know says which end
    in ``unknown`` (``start``, ``end`` or ``both``: moves.py), and the view draws it not."""
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
    if mv.unknown is not None:
        move["unknown"] = mv.unknown
    if mv.tool_path is not None:
        move["tool_path"] = centre_path_json(mv, axes)
    if mv.cycle == DRILLING:
        move["hole"] = dict(zip(axes, mv.end, strict=True))
    return move


def centre_path_json(mv: Move, axes: tuple[str, ...]) -> dict[str, Any]:
    """A move's tool centre path (``Move.tool_path``) as JSON: ``from`` and the ``pieces``."""
    path = mv.tool_path
    assert path is not None
    pieces: list[dict[str, Any]] = []
    for piece in path.pieces:
        item: dict[str, Any] = {"to": dict(zip(axes, piece.end, strict=True))}
        if piece.centre is not None:
            item["centre"] = dict(zip(axes, piece.centre, strict=True))
            item["clockwise"] = piece.clockwise
        pieces.append(item)
    return {"from": dict(zip(axes, path.start, strict=True)), "pieces": pieces}
