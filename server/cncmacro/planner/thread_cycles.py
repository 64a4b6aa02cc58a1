"""G76, a lathe's multiple threading cycle, planned into its passes (docs/semantics.md §10.3).

The first block ``G76 P(m r a) Q(Δdmin) R(d)`` sets the parameters (``Planner.cycle_params``):
m finishing passes, r the pull-out chamfer in tenths of the lead, a the tool's angle (six digits,
``P010060``: m 1, r 0, a 60°), Δdmin the least depth of a pass and d the finishing allowance. The
second ``G76 X(U) Z(W) R(i) P(k) Q(Δd) F(L)`` cuts the thread: its root ends at X Z, i tapers it
(the radius at its start less at its end), k is the thread's height and Δd the first pass's depth
(both radii), L the lead. P and Q are written without a decimal point, in least input increments
(``in_increments``); R in millimetres.

The roughing passes remove a constant area: pass n goes to depth Δd·√n, each at least Δdmin
deeper than the one before, until the next would reach k − d, where the last roughing pass cuts;
then m passes at the full height k (the first takes the allowance d). Each pass is four moves:
at rapid in to its depth, the thread along Z at the lead per revolution (G32: F × S whatever
G98/G99 says), at rapid out along X to the start's diameter, at rapid back along Z to the start.
With a tool angle a the infeed is along one flank: a pass's start moves from the start point
toward the thread's end by its depth × tan(a/2), as the GSK980TDi manual (§3.24.12, step ①)
has X and Z move together in the direction from the start to the thread's end; the FANUC 0i-TF
cuts with one edge the same way. The chamfer r is not drawn: each pass threads to the end point.

Where the profile writes the cycle in one block (``LatheCycles.one_block``, Haas: ``G76 X Z K D
A I F``, with no first block) K is the thread's height and D the first pass's depth (radii, in
the program's unit), A the tool angle (0 when not given) and I the taper; the passes go as above
with no minimum depth and no allowance, and the pass that reaches K is the last.
The GSK980TDi's G78 (§3.24.13, "enhanced" threading) takes G76's two blocks with its first
block's P read otherwise, ``G78 P(m)(r)(a) Q(Δdmin) R(d) J K D L E``: m the infeed (0 equal
depths: pass n at n·Δd, at least Δdmin deeper each; 1 decreasing, G76's Δd·√n), r the way the
tool goes in (0 along the thread's middle: X alone; 2 the right flank: G76's, toward the thread's
end; 1 the left flank: toward its start; 3 both in turn, from the left), a the tool angle; D the
finishing passes (G76's m), L the starts (each pass cut once for each start, along the same path:
the starts differ by the spindle's phase). Its screw-in E and pull-out J, K are not drawn.
Every move is recorded as a pass of the cycle (``pass_of="G76"``, ``"G78"``); the tool ends where it began.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from .cycle_passes import Pass, record_passes
from .turning_cycles import THREAD_MODE, in_increments

if TYPE_CHECKING:
    from .planner import Planner

_MOST_PASSES = 9999  # a Δd too small for k is cut in this many roughing passes at most


def thread_depths(
    first: float, least: float, height: float, allowance: float, finishing: int, equal: bool = False
) -> list[float]:
    """The depths (radii, from the thread's crest) of G76's passes (module docstring): roughing at
    max(Δd·√n, the depth before + Δdmin) (``equal``: G78's m 0, max(n·Δd, the depth before +
    Δdmin)) while short of k − d, then k − d, then ``finishing`` passes at k."""
    last_rough = height - allowance
    depths: list[float] = []
    if first > 0.0:
        depth = 0.0
        n = 1
        while n <= _MOST_PASSES:
            step = first * n if equal else first * math.sqrt(n)
            depth = max(step, depth + least) if depths else first
            if depth >= last_rough:
                break
            depths.append(depth)
            n += 1
    if last_rough > 0.0 and (not depths or depths[-1] < last_rough):
        depths.append(last_rough)
    return depths + [height] * max(finishing, 1)


# G78's cutting-in r (its P's middle digits) -> the side of each pass's flank: 0 along the middle
# (X alone), 1 toward the thread's start (left), 2 toward its end (right: G76's), 3 both in turn
_MIDDLE, _LEFT, _RIGHT, _BOTH = 0, 1, 2, 3


def multiple_thread(p: Planner, words: dict[str, float], file: str, line: int, target: list[float]) -> None:
    """Plan and record G76's passes from where the tool is to the thread's end ``target``."""
    first_block = p.cycle_params.get(76.0, {})
    code = round(first_block.get("P", 10000.0))
    _thread(p, words, file, line, target, first_block, (code // 10000, code % 100, _RIGHT, False, 1), "G76")


def enhanced_thread(p: Planner, words: dict[str, float], file: str, line: int, target: list[float]) -> None:
    """Plan and record the GSK980TDi's G78 passes (module docstring) to the thread's end ``target``:
    the first block's P is m (infeed), r (cutting-in), a (angle), D the finishing passes, L the
    starts. Left out: m 1, r 0, a 0, D 1, L 1 (the control's parameters 061, 062, 058)."""
    first_block = p.cycle_params.get(78.0, {})
    code = round(first_block.get("P", 10000.0))
    infeed, side, angle = code // 10000, code // 100 % 100, code % 100
    finishing = round(first_block.get("D", 1.0))
    starts = max(1, round(first_block.get("L", 1.0)))
    _thread(p, words, file, line, target, first_block, (finishing, angle, side, infeed == 0, starts), "G78")


def _thread(
    p: Planner,
    words: dict[str, float],
    file: str,
    line: int,
    target: list[float],
    first_block: dict[str, float],
    plan: tuple[int, int, int, bool, int],
    name: str,
) -> None:
    """The passes of G76 or G78 (``name``) with ``plan``: the finishing passes, the tool angle,
    the side of its flank (``_RIGHT``...), whether the depths are equal steps, the starts."""
    finishing, angle, side, equal, starts = plan
    least = in_increments(p, first_block.get("Q", 0.0))
    allowance = first_block.get("R", 0.0)
    height = in_increments(p, words.get("P", 0.0))
    first = in_increments(p, words.get("Q", 0.0))
    taper = words.get("R", 0.0)
    one_block = p.dialect.lathe_cycles.one_block and "K" in words
    if one_block:  # Haas: G76 X Z K D A I F in one block, in the program's unit (module docstring)
        height, first = words["K"], words.get("D", words["K"])
        angle, taper, allowance, least = round(words.get("A", 0.0)), words.get("I", 0.0), 0.0, 0.0
    xi, zi = p.axis_index["X"], p.axis_index["Z"]
    start = tuple(p.pos)
    xa, za = start[xi], start[zi]
    xd, zd = target[xi], target[zi]
    inward = 1.0 if xd > xa else -1.0  # the way the passes go deeper along X
    along = (zd > za) - (zd < za)  # the way the thread runs along Z
    flank = math.tan(math.radians(angle / 2.0))
    passes: list[Pass] = []
    depths = thread_depths(first, least, height, allowance, finishing, equal)
    if one_block:  # the last pass at full height ends the thread: no finishing pass after it
        depths = depths[:-1]
    for n, depth in enumerate(d for d in depths for _ in range(starts)):
        toward = (1 if side == _RIGHT else -1 if side == _LEFT else (1 if n // starts % 2 else -1)) * along
        z_in = za + (0.0 if side == _MIDDLE else toward * depth * flank)
        share = (z_in - zd) / (za - zd) if za != zd else 0.0  # along the thread's line, from its end
        left = 2.0 * (height - depth)  # diameter still to go to the root
        x_in = xd + 2.0 * taper * share - inward * left
        x_end = xd - inward * left
        points = [(0.0, x_in, z_in), (THREAD_MODE, x_end, zd), (0.0, xa, zd), (0.0, xa, za)]
        at = start
        for mode, x, z in points:
            end = list(at)
            end[xi], end[zi] = x, z
            passes.append((mode, at, tuple(end), None))
            at = passes[-1][2]
    record_passes(p, file, line, passes, name)
