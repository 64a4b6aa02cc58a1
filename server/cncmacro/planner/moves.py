"""The planner's output: the one stream of moves every front end reads (ARCHITECTURE.md,
"The motion planner").

A ``Move`` is one block's motion (a drilling cycle's: one hole's) with where it came from, its
mode, end points, feed, time and, for an arc, its centre and plane; a cycle's move lists its
canonical legs (rapid or feed, each to a point). ``ToolChange`` marks where a tool's part of the
run starts. ``move_kind`` is the one rule of what a move is drawn as.
"""

from __future__ import annotations

from typing import NamedTuple

from .arcs import ARC_MODES
from .numbers import format_plain

MODE_NAMES = {0.0: "G00", 1.0: "G01", 2.0: "G02", 3.0: "G03", 31.0: "G31"}
RAPID = "rapid"
FEED = "feed"
ARC = "arc"
PROBE = "probe"
CYCLE = "cycle"
DRILLING = "drilling"  # a ``Move.cycle``: a hole of a drilling canned cycle
TURNING = "turning"  # a lathe's turning cycle
UNKNOWN_START = "start"  # a ``Move.unknown``: the move starts where the run does not know the tool is
UNKNOWN_END = "end"  # … it ends at a place the run does not know
UNKNOWN_BOTH = "both"


class Leg(NamedTuple):
    """One canonical straight move of a cycle: at rapid (``rapid``) or at the feed, to ``end``
    (work coordinates, one value per axis like a ``Move``'s)."""

    rapid: bool
    end: tuple[float, ...]


class CentrePiece(NamedTuple):
    """One piece of the tool centre's path under cutter radius compensation (cutter_stage.py): a
    straight move to ``end`` (``centre`` None) or an arc about ``centre`` to ``end``, turning
    ``clockwise`` or not; points in work coordinates, one value per axis like a ``Move``'s."""

    end: tuple[float, ...]
    centre: tuple[float, ...] | None = None
    clockwise: bool = False


class CentrePath(NamedTuple):
    """Where the tool's centre goes during a move under cutter radius compensation: from
    ``start`` through ``pieces`` in order."""

    start: tuple[float, ...]
    pieces: tuple[CentrePiece, ...]


class Move(NamedTuple):
    """One executed motion: where (file, 0-based line), the motion code (0, 1, 2, 3, a cycle
    or 31 for a skip), the end points in work coordinates before and after, one value per
    axis in the dialect's order, the feed, and for a G02/G03 arc its centre (arcs.py): one
    value per axis like the end points (X a diameter on a lathe), the axes off the arc's
    plane keeping their start values; None for every other move. ``seconds`` is the time the
    move takes (cycle_time.py). ``plane`` is the plane in force (17, 18, 19: which two axes an
    arc turns in). ``legs`` is the path of a cycle (a drilling cycle's hole, a lathe's turning
    cycle): the canonical straight moves it is made of, in order, each a ``Leg`` from where the
    one before it ended (the first from ``start``); None for a move that is one straight line or
    one arc from ``start`` to ``end``. ``cycle`` says which kind of cycle a move with legs
    belongs to: ``DRILLING`` (a drilling cycle's hole, drilled at ``end``) or ``TURNING``.
    ``pass_of`` names the lathe cycle (``G71``) whose pass this move is, a move of its own
    planned from the cycle block (lathe_cycles.py); None for any other move. ``tool_path`` is
    where the tool's centre goes under cutter radius compensation (G41/G42: cutter_stage.py),
    which the time and the cut length follow; None when no compensation is in force, the
    centre then being on the programmed path, and in a run that keeps no centre paths
    (``Planner.centre_paths``: ``cncmacro run``'s text, which shows none). ``unknown`` says which
    end of the move is at a place the run does not know (whereabouts.py, ``astray``): ``UNKNOWN_START``
    (the tool's place before it: where the operator left it, or after a G30), ``UNKNOWN_END`` (a reference
    point whose offsets are not given), ``UNKNOWN_BOTH``; None when both are known. The front ends draw
    neither such a move nor its ends (docs/semantics.md §8)."""

    file: str
    line: int
    mode: float
    start: tuple[float, ...]
    end: tuple[float, ...]
    feed: float
    centre: tuple[float, ...] | None
    seconds: float
    plane: float = 17.0
    legs: tuple[Leg, ...] | None = None
    cycle: str | None = None
    pass_of: str | None = None
    tool_path: CentrePath | None = None
    unknown: str | None = None

    def text(self, axes: tuple[str, ...], shown: list[int] | None = None) -> str:
        """``G01  X0.000 Y0.000 -> X10.000 Y5.000  F200`` for a person: the axes in ``shown``
        (``commanded_axes.CommandedAxes`` gives those the program has named so far; without
        them, or with none, those that moved, and every axis when none did, so that a move to
        where the tool already is still says where that is: never an empty ``->``) and the feed
        of a cutting move."""
        if not shown:
            shown = [i for i in range(len(axes)) if self.start[i] != self.end[i]] or list(range(len(axes)))
        mode = MODE_NAMES.get(self.mode, f"G{self.mode:g}")
        start = " ".join(f"{axes[i]}{self.start[i]:.3f}" for i in shown)
        end = " ".join(f"{axes[i]}{self.end[i]:.3f}" for i in shown)
        feed = f"  F{format_plain(self.feed)}" if self.mode != 0.0 and self.feed else ""
        return f"{mode:<4} {start} -> {end}{feed}"


class ToolChange(NamedTuple):
    """A tool change (cycle_time.py): where (file, 0-based line), the T in force, and the
    clock (seconds) and the cut and rapid path (mm) before it."""

    file: str
    line: int
    tool: float | None
    clock: float
    cut: float
    rapid: float


def move_kind(mv: Move) -> str:
    """What a move is: ``rapid`` (G00 and the moves of G28/G30/G53 at rapid), ``arc`` (G02/G03),
    ``probe`` (G31), ``cycle`` (a move made of legs) or ``feed`` (every other cutting move)."""
    if mv.cycle is not None:
        return CYCLE
    mode = mv.mode
    if mode == 0.0:
        return RAPID
    if mode in ARC_MODES:
        return ARC
    if mode == 31.0:
        return PROBE
    return FEED
