"""G20/G21: the unit a program's numbers are in, and when it may change (docs/semantics.md §8,
"Units").

FANUC's operator's manuals have G20 or G21 at the start of the program, in a block of its own,
before the coordinate system is set, and give no alarm for a change later on. A change of the
unit after the program has moved is therefore a note the run goes past (``unit-change``, a
warning): the positions, offsets and feeds written before it are read in the other unit from
there on. The lengths and times are kept in mm whatever the unit (cycle_time.py); ``length_unit``
names the unit a person is shown them in. A G20/G21 block is never a plain line
(plain_words.py), so this is the one place a change of the unit is looked at.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..bilingual import detail

if TYPE_CHECKING:
    from .planner import Planner

UNITS_GROUP = "units"
INCH_CODE = 20.0
MM = "mm"
INCH = "in"


def length_unit(units_code: float | None) -> str:
    """``in`` under G20, else ``mm``: the unit a program's lengths are shown in."""
    return INCH if units_code == INCH_CODE else MM


def unit_change(p: Planner, g: float, line: int) -> None:
    """The units group is about to take ``g`` on ``line``: a change after the tool has moved is
    a ``unit-change`` note."""
    current = p.modal.get(UNITS_GROUP, 21.0)
    if g == current or not (p.cut_length or p.rapid_length):
        return
    was, now = f"G{current:g}", f"G{g:g}"
    p.host.note(
        "units",
        detail(f"{now} changes the unit from {length_unit(current)} to {length_unit(g)} after the program has "
               f"moved in {was}: G20/G21 belong at the start of the program, before the coordinate system is "
               "set; the positions and offsets set before are read in the new unit from here",
               f"程序已按 {was} 移动后，{now} 把单位从 {length_unit(current)} 改为 {length_unit(g)}："
               "G20/G21 应在程序开头、设定坐标系之前指定；此前设定的位置和补偿从这里起按新单位读取"),
        line,
        "unit-change",
    )  # fmt: skip
