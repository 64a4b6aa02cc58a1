"""docs/semantics.md §9, "Hole data": a G00-G03 in the same block as a drilling cycle's code.

On `mitsubishi-m70` the G00 moves as written and the cycle is cancelled (Mitsubishi M700V/M70V
programming manual, appendix 2 "Order of G function command priority": G00 to G03.1 with G73 to
G89 in one block, "Group 1 command is executed", "Group 9 is canceled"). On the FANUC profiles,
whose manuals at hand do not say, the cycle is named and drills the block's hole, as before
(to confirm). Every time worked by hand; rapids 24000 mm/min = 400 mm/s on X, Y and Z."""

from __future__ import annotations

import pytest

from running import lines, run

PROGRAM = lines(
    "G90 G17 G21 G94 G80",
    "G00 X0 Y0 Z10.",
    "G00 G99 G81 X10. Y0 Z-10. R2. F600",
    "X20.",
    "G80",
    "M30",
)


def test_on_mitsubishi_a_g00_beside_g81_moves_and_cancels_the_cycle() -> None:
    # line 2: 10 mm rapid (Z) = 0.025 s
    # line 3: a rapid to X10 Y0 Z-10: X 10 mm, Z 20 mm, the longest axis 20 mm = 0.05 s; no hole
    # line 4: X20.: a rapid of 10 mm = 0.025 s (G00 in force, no cycle)
    m = run(PROGRAM, "mitsubishi-m70")
    assert m.status == "completed", m.alarm
    assert [mv.mode for mv in m.planner.moves] == [0.0, 0.0, 0.0]
    assert m.planner.moves[1].end[:3] == (10.0, 0.0, -10.0)
    assert m.planner.clock == pytest.approx(0.025 + 0.05 + 0.025, abs=1e-9)
    assert m.planner.modal["canned"] == 80.0


def test_on_fanuc_the_cycle_named_beside_g00_drills_the_hole() -> None:
    # line 3: a G81 hole: position 10 mm = 0.025 s, Z10 -> R2 8 mm = 0.02 s, feed 12 mm at F600
    # = 1.2 s, G99 back to R2 12 mm = 0.03 s; line 4: the next hole from R2: 0.025 + 1.2 + 0.03
    m = run(PROGRAM, "fanuc-0i")
    assert [mv.mode for mv in m.planner.moves] == [0.0, 81.0, 81.0]
    assert m.planner.clock == pytest.approx(0.025 + (0.025 + 0.02 + 1.2 + 0.03) + (0.025 + 1.2 + 0.03), abs=1e-9)
