"""Whether the run knows where the machine is on an axis (docs/semantics.md §2 "Unknown, not
vacant", §8, §11): the one rule the position variables of an analysis run (#5021…, #5041…,
#5081…) and the travel check (machine_limits.py) follow.

The machine position is the program position plus the work offset in force, the coordinate
shift and the tool offset (positions.py). The run knows it on an axis when it knows each part:

- **the frame** (the work offset and the coordinate shift): its work offset's variable is given
  (the machine file's ``[variables]``, the persistent file, ``G10`` or the program; the external
  offset counts as 0 unless given), unless a coordinate setting (G92, a lathe's G50) decided it.
  A coordinate setting says that the tool is *now* at the commanded coordinates, so the frame it
  makes is known only where the machine position was known just before: at the reference point
  after a ``G28`` (or a ``G53`` move) on that axis with no move since, or after a move the frame
  knew. At the program's start the tool is where the operator left it, which no file says: the
  run starts it at work 0, but a G92/G50 there makes a frame the run does not know, until a
  coordinate setting made at a known position.
- **the tool offset**: none in force, or its geometry given (a lathe's T offset, a mill's G43/G44 H).
- **the program position**: after a ``G30`` the axis is at the 2nd reference position (FANUC
  parameter 1241, set by the machine builder), which the machine file does not give; the axis's
  position is unknown until an absolute move of it, a ``G28`` or a ``G53``. After a ``G28`` or a
  ``G53`` the machine position is known and the program position (#5001…, #5041…) follows from
  it: machine position less the frame and the tool offset, so it is known only where those are,
  until an absolute move of the axis or a coordinate setting names it.

**On the drawing** (``astray``, ``home_known``): the axes that place the tool in the toolpath view
(X and Z on a lathe, X, Y and Z on a mill) are *astray* where the run does not know the program
position: not named by an absolute move, a reference return or a coordinate setting since the start,
left by a G30, or at a reference point (G28, G53) whose frame or tool offset is not given. A move
that travels an astray axis from where the block found it starts at an unknown place, and a G28,
G30 or G53 that ends an axis at such a point ends at one (``Move.unknown``, docs/semantics.md §8).

``Whereabouts`` is immutable: a snapshot (state.py) keeps it as it is.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from .moves import UNKNOWN_BOTH, UNKNOWN_END, UNKNOWN_START
from .positions import WORK_BASE, work_offset_variable
from .tool_offsets import lathe_offset_number

if TYPE_CHECKING:
    from .planner import Planner


@dataclass(frozen=True, slots=True)
class Whereabouts:
    """What the run knows of where the tool is, per axis index: the axes moved, referenced or set
    since the made-up start point (``placed``), the axes a G30 left at an unknown position (``lost``), the axes at
    a reference point or a G53 position with the program position they have there
    (``at_reference``), and the frames a coordinate setting made: (axis, known, the work offset
    variable in force then); the axes whose program position a G28 or G53 gave, from their machine
    position, and no absolute move has named since (``homed``)."""

    placed: frozenset[int] = frozenset()
    lost: frozenset[int] = frozenset()
    at_reference: tuple[tuple[int, float], ...] = ()
    frames: tuple[tuple[int, bool, int], ...] = ()
    homed: frozenset[int] = frozenset()

    def leave_reference(self) -> Whereabouts:
        """The same with no axis at a reference point (a run of plain lines may move any)."""
        return replace(self, at_reference=()) if self.at_reference else self


START = Whereabouts()  # at the program's start: every axis where the operator left it


def tool_known(p: Planner, axis: int) -> bool:
    """Whether the tool offset ``axis`` moves by is known: none in force, or its geometry given."""
    stored = p.host.stored
    if p.lathe:
        t = p.codes.get("T")
        offset = lathe_offset_number(t) if t else 0
        if not offset:
            return True
        name = p.dialect.axes[axis]
        return all(stored(geometry + offset) is not None for letter, geometry, _ in p.dialect.lathe_offsets.axes
                   if letter == name)  # fmt: skip
    if p.axis_index.get("Z") != axis or p.modal.get("length") not in (43.0, 44.0):
        return True
    h = p.codes.get("H")
    return not h or stored(p.dialect.tool_offset_bases[0] + int(h)) is not None


def frame_known(p: Planner, axis: int) -> bool:
    """Whether the work offset in force plus the coordinate shift on ``axis`` is known."""
    variable = work_offset_variable(p, axis)
    stored = p.host.stored
    for i, known, then in p.whereabouts.frames:
        if i == axis:  # a coordinate setting's frame; under another work offset, that one's too
            return known and (then == variable or (stored(then) is not None and stored(variable) is not None))
    return stored(variable) is not None


def _at_reference(p: Planner, axis: int) -> bool:
    return any(i == axis and p.pos[i] == at for i, at in p.whereabouts.at_reference)


def machine_known(p: Planner, axis: int) -> bool:
    """Whether the run knows ``axis``'s machine position (module docstring)."""
    if not tool_known(p, axis) or axis in p.whereabouts.lost:
        return False
    return _at_reference(p, axis) or frame_known(p, axis)


def position_known(p: Planner, which: str, axis: int) -> bool:
    """Whether axis ``axis``'s position of a kind (positions.position_value) is known: the
    machine position as ``machine_known``; the current position and the tool offset when the
    tool offset is; the block end point unless a G30 left the axis unknown."""
    if axis >= len(p.pos):  # an axis the profile's table has and the simulated machine does not: 0
        return True
    if which == "machine":
        return machine_known(p, axis)
    if which == "tool":
        return tool_known(p, axis)
    w = p.whereabouts
    if which in ("current", "end"):
        if axis in w.lost:
            return False
        if axis in w.homed:  # from the machine position: less the frame and the tool offset
            return frame_known(p, axis) and tool_known(p, axis)
        return which == "end" or tool_known(p, axis)
    return True


def drawn_axes(p: Planner) -> frozenset[int]:
    """The axes that place the tool in the toolpath view: X and Z on a lathe, X, Y and Z on a mill
    (found once a planner: its axes do not change)."""
    drawn = p.drawn_axes
    if drawn is None:
        letters = ("X", "Z") if p.lathe else ("X", "Y", "Z")
        drawn = p.drawn_axes = frozenset(p.axis_index[a] for a in letters if a in p.axis_index)
    return drawn


_NONE: frozenset[int] = frozenset()


def astray(p: Planner) -> frozenset[int]:
    """The drawn axes whose program position the run does not know (module docstring). Asked at
    every block: the common answer, every drawn axis placed and none lost, costs two tests."""
    w = p.whereabouts
    axes = drawn_axes(p)
    if not w.lost and not w.homed and axes <= w.placed:
        return _NONE
    return frozenset(i for i in axes if i not in w.placed or not position_known(p, "end", i))


def home_known(p: Planner, axes: Iterable[int], returned: bool = True) -> bool:
    """Whether a G28 or G53 (``returned``; a G30: never) ends the drawn ``axes`` at a program position
    the run knows: the frame and the tool offset there are given (``position_known``'s rule)."""
    drawn = [i for i in axes if i in drawn_axes(p)]
    if not returned:
        return not drawn
    return all(frame_known(p, i) and tool_known(p, i) for i in drawn)


def unknown_ends(p: Planner, start: tuple[float, ...], end: tuple[float, ...], end_unknown: bool) -> str | None:
    """Which end of a move from ``start`` to ``end`` is at a place the run does not know (``Move.unknown``):
    it starts at one when it travels an axis astray where its block began from there (a move that
    travels nothing: when it is there), and ends at one when the caller says so (``home_known``)."""
    unknown = None
    origin = p.block_start
    here = [i for i in p.block_astray if start[i] == origin[i]]
    if here and (start == end or any(start[i] != end[i] for i in here)):
        unknown = UNKNOWN_START
    if end_unknown:
        unknown = UNKNOWN_END if unknown is None else UNKNOWN_BOTH
    return unknown


def frame_offset(p: Planner, axis: int) -> float:
    """From program to machine coordinates on ``axis``: the work offset (0 where not given), the
    external offset, the coordinate shift and the tool offset, as positions.machine_position."""
    stored = p.host.stored
    work = (stored(work_offset_variable(p, axis)) or 0.0) + (stored(WORK_BASE + axis) or 0.0)
    return work + p.shift[axis] + p.tool_vector[axis]


def placed(p: Planner, axes: Iterable[int]) -> None:
    """An absolute move names ``axes``: each is where the program says."""
    w = p.whereabouts
    named = frozenset(axes)
    if not named <= w.placed or named & w.lost or w.at_reference or named & w.homed:
        p.whereabouts = replace(w, placed=w.placed | named, lost=w.lost - named, homed=w.homed - named,
                                at_reference=tuple(r for r in w.at_reference if r[0] not in named))  # fmt: skip


def referenced(p: Planner, axes: Iterable[int]) -> None:
    """A G28 or G53 left ``axes`` at a machine position the run knows."""
    named = frozenset(axes)
    w = p.whereabouts
    kept = tuple(r for r in w.at_reference if r[0] not in named)
    p.whereabouts = replace(w, placed=w.placed | named, lost=w.lost - named, homed=w.homed | named,
                            at_reference=kept + tuple((i, p.pos[i]) for i in sorted(named)))  # fmt: skip


def lose(p: Planner, axes: Iterable[int]) -> None:
    """A G30 left ``axes`` at the 2nd reference position, which the machine file does not give."""
    named = frozenset(axes)
    w = p.whereabouts
    p.whereabouts = replace(w, lost=w.lost | named, homed=w.homed - named,
                            at_reference=tuple(r for r in w.at_reference if r[0] not in named))  # fmt: skip


def coordinates_set(p: Planner, axes: Iterable[int]) -> None:
    """Before a coordinate setting (G92, G50) of ``axes``: each axis's frame is known from then on
    where its machine position was known (module docstring); its program position is then the
    commanded one."""
    named = frozenset(axes)
    w = p.whereabouts
    frames = tuple(f for f in w.frames if f[0] not in named) + tuple(
        (i, i in w.placed and machine_known(p, i), work_offset_variable(p, i)) for i in sorted(named)
    )
    p.whereabouts = replace(w, placed=w.placed | named, lost=w.lost - named, frames=frames, homed=w.homed - named,
                            at_reference=tuple(r for r in w.at_reference if r[0] not in named))  # fmt: skip


def shift_cancelled(p: Planner, axes: Iterable[int]) -> None:
    """A preset (G92.1 IP0) cancelled the coordinate shift of ``axes``: the work offset decides again."""
    named = frozenset(axes)
    w = p.whereabouts
    if any(f[0] in named for f in w.frames):
        p.whereabouts = replace(w, frames=tuple(f for f in w.frames if f[0] not in named))
