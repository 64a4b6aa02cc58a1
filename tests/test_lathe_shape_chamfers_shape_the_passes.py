"""Inside a G71/G72/G73 finishing shape the chamfers and corner R of its blocks (``,C``, ``,R``; the
GSK980TDi's L and D) shape the cycle's passes and its last pass along the shape, as they shape G70's
finishing pass (docs/semantics.md §10.2). FANUC allows them on every shape block but the last
(PS0069). Before, the shape kept its sharp corners."""

from __future__ import annotations

import pytest

from running import lines, run

SHAPE = ("G00 X60. Z2.", "G71 U2. R1.", "G71 P10 Q20 U0 W0 F0.2", "N10 G00 X20.", "G01 Z0", "X40. {c}", "Z-20.",
         "N20 X60.", "G70 P10 Q20", "M30")  # fmt: skip


@pytest.mark.parametrize(("profile", "chamfer"), [("fanuc-0i-lathe", ",C2."), ("gsk980tdi", "L2.828427")])
def test_10_lathe_a_chamfer_in_the_shape_shapes_the_roughing_and_finishing_passes(profile: str, chamfer: str) -> None:
    text = lines("O0001", "G99 S500 M03 T0101", *(s.format(c=chamfer) for s in SHAPE))
    m = run(text, profile)
    assert m.status == "completed", m.alarm
    cycle = [(round(mv.end[0], 2), round(mv.end[-3 if profile == "gsk980tdi" else 1], 2))
             for mv in m.planner.moves if mv.line + 1 == 5 and mv.mode == 1.0]  # fmt: skip
    # the chamfer runs from X36 Z0 to X40 Z-2 (,C2: 2 from the corner X40 Z0 along each move; L
    # 2.828427 = 2·√2 long at a right angle: the same, to 0.01 since the word is rounded to 2.828). The
    # passes 2 deep (radius) from X56: X40's cut ends on the chamfer at Z-2, X36's at its start Z0
    assert (40.0, -2.0) in cycle and (36.0, 0.0) in cycle
    assert (40.0, -20.0) in cycle[-3:]  # the last pass along the shape: …, X36 Z0, X40 Z-2, X40 Z-20, X60
    last = cycle[-5:]
    assert last == [(20.0, 0.0), (36.0, 0.0), (40.0, -2.0), (40.0, -20.0), (60.0, -20.0)]
    finishing = [(round(mv.end[0], 2), round(mv.end[-3 if profile == "gsk980tdi" else 1], 2))
                 for mv in m.planner.moves if mv.line + 1 in (8, 9)]  # fmt: skip
    assert finishing == [(36.0, 0.0), (40.0, -2.0), (40.0, -20.0)]
