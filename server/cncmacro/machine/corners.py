"""Chamfer and corner words on a move: ``,C``, ``,R`` and ``,A`` (docs/semantics.md §8).

FANUC's optional chamfering and corner R (``G01 X50. ,R5.``, ``G02 ... ,C3.``), Haas corner
rounding and chamfering, and FANUC's ``,A`` angle of direct drawing dimension programming. A
chamfer's or corner R's letter and value are handed to the planner while the block runs
(``Planner.block_corner``), which cuts it between the move and the next
(``planner/corner_stage.py``). A move that names one coordinate of the plane and an angle
(``G01 X30. ,A135.``) goes at that angle to the other coordinate (``Planner.block_angle``,
``planner/angled_moves.py``).
The values are still computed when the block runs, in the address rules, so that what
goes wrong in them (a vacant argument read, a division by zero, a variable that does not exist)
is found where it is written. What the static check says of them is ``corner_findings``'s.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from ..bilingual import Detail, detail
from ..syntax.nodes import Block, CornerWord, Number

if TYPE_CHECKING:
    from .blocks import CompiledFile, Runner
    from .expressions import Getter

NAMES: dict[str, Detail] = {
    "C": detail("chamfer", "倒角"),
    "R": detail("corner radius", "拐角圆弧"),
    "A": detail("angle", "角度"),
}
INTERPOLATION = (1.0, 2.0, 3.0)


def with_corners(cf: CompiledFile, block: Block, run: Runner) -> Runner:
    """``run`` preceded by computing the block's corner values that are not literal numbers (the
    literal ones need nothing); an angle ``,A`` is handed to the planner for the block's move
    (``Planner.block_angle``: a move that names one coordinate of the plane goes at that angle),
    and so is a chamfer's or corner R's letter (``Planner.block_corner``)."""
    angle = next((c for c in block.corners if c.letter == "A"), None)
    rounded = next((c for c in block.corners if c.letter != "A"), None)
    getters: list[Getter] = [
        cf.addresses.value(c.value)
        for c in block.corners
        if c is not angle and c is not rounded and not cf.addresses.constant(c.value)[0]
    ]
    if rounded is not None:  # a chamfer or corner R: the planner hears of it while the block runs
        known, literal = cf.addresses.constant(rounded.value)
        get = None if known else cf.addresses.value(rounded.value, rounded.letter)
        run = _with_rounded(run, rounded.letter, literal, get)
    if angle is not None:
        known, literal = cf.addresses.constant(angle.value)
        get_angle = None if known else cf.addresses.value(angle.value, "A")
        alone = not block.words and not block.statements  # ",A1" alone: FANUC's two-block form

        def angled(m: Any, pc: int) -> int:
            for get in getters:
                get(m)
            p = m.planner
            p.block_angle = literal if get_angle is None else get_angle(m)
            try:
                if alone:
                    p.angle_alone(pc)
                return run(m, pc)
            finally:
                p.block_angle = None

        return angled
    if not getters:
        return run

    def corners(m: Any, pc: int) -> int:
        for get in getters:
            get(m)
        return run(m, pc)

    return corners


def _with_rounded(run: Runner, letter: str, literal: Any, get: Getter | None) -> Runner:
    """``run`` with ``Planner.block_corner`` set to ``letter`` (C or R) and
    ``Planner.block_corner_value`` to its value (``literal``, else computed by ``get``; None when
    vacant) while it runs: the planner cuts the chamfer or corner R after the move
    (planner/corner_stage.py), and the cutter compensation stage refuses one on a start-up, a
    cancel or a change of side (planner/cutter_stage.py, PS0039)."""

    def rounded(m: Any, pc: int) -> int:
        p = m.planner
        value = literal if get is None else get(m)
        p.block_corner = letter
        p.block_corner_value = None if value is None else float(value)
        try:
            return run(m, pc)
        finally:
            p.block_corner = None
            p.block_corner_value = None

    return rounded


def no_move(corner: CornerWord, block: Block, axis_letters: frozenset[str]) -> Detail | None:
    """Why ``corner`` has no move to act on, from the block alone: a literal group 01 code other
    than G01/G02/G03 (G00, a cycle), or no axis word at all. None when the block may well be a
    G01/G02/G03 move (its motion code can be modal from an earlier block)."""
    name = NAMES[corner.letter]
    for w in block.words:
        if w.letter == "G" and isinstance(w.value, Number) and w.value.value in (0.0, 33.0, 32.0):
            code = f"G{w.value.text}"
            return detail(
                f",{corner.letter} ({name}) in a {code} block: chamfering and corner R act only on a "
                "G01, G02 or G03 move; the control does not insert it",
                f",{corner.letter}（{name.zh}）写在 {code} 程序段中：倒角和拐角圆弧只用于 G01、G02、G03 移动，"
                "系统不会插入",
            )
    if not any(w.letter in axis_letters for w in block.words):
        if corner.letter == "A":  # ,A1 alone: the first block of FANUC's two-block direct drawing form
            return None
        return detail(
            f",{corner.letter} ({name}) in a block without a move: it belongs at the end of a G01, G02 "
            "or G03 move that another move follows",
            f",{corner.letter}（{name.zh}）所在程序段没有移动：它应写在 G01、G02、G03 移动的末尾，且其后还有移动",
        )
    return None
