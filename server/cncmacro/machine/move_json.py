"""A move as JSON (docs/design.md's run object): what ``cncmacro run --json`` prints and what
the debug adapter sends the toolpath view, in one form."""

from __future__ import annotations

from typing import Any

from .frames import MODE_NAMES, Move


def move_json(mv: Move, axes: tuple[str, ...]) -> dict[str, Any]:
    """A move with its file, 1-based line, mode (``G01``), end points, feed and time in seconds
    (``cycle_time.py``); an arc (G02/G03) also gets its ``centre``, axis by axis."""
    move = {
        "file": mv.file,
        "line": mv.line + 1,
        "mode": MODE_NAMES.get(mv.mode, f"G{mv.mode:g}"),
        "from": dict(zip(axes, mv.start, strict=True)),
        "to": dict(zip(axes, mv.end, strict=True)),
        "feed": mv.feed,
        "time": mv.seconds,
    }
    if mv.centre is not None:
        move["centre"] = dict(zip(axes, mv.centre, strict=True))
    return move
