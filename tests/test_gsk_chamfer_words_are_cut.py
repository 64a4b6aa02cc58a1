"""The GSK980TDi's chamfer words cut as its manual says (§3.11 "倒角功能": "倒角功能是在两轮廓间插入
一段直线或圆弧", a line or an arc inserted between two contours; docs/semantics.md §10.1): ``L`` a
straight chamfer whose own length is L (type I, state parameter №181.0's default), ``D`` an arc of
radius D tangent to both moves, on G01, G02 or G03 blocks; §3.11.3's special cases insert nothing
and its alarms stop the run. Before, the moves ran as written and the run noted the block as
`not-simulated`."""

from __future__ import annotations

from math import pi, sqrt
from pathlib import Path

import pytest

from analysis_helpers import analyse_files
from cli_capture import run_json
from running import lines, run

PROGRAM = lines("O0004", "T0101", "G98 M03 S500", "G0 X0 Z2", "G01 Z0 F100", "X40 L2", "Z-20 D3", "X60", "G0 Z2 L1",
                "M30")  # fmt: skip


def test_10_lathe_gsk_l_is_the_chamfers_length_and_d_the_rounding_radius(tmp_path: Path) -> None:
    result = run_json(tmp_path, PROGRAM, "O0004.nc", 'base = "gsk980tdi"\n')
    cuts = [(round(mv["to"]["X"], 6), round(mv["to"]["Z"], 6), mv["mode"], round(mv["time"], 6))
            for mv in result["moves"] if mv["kind"] != "rapid"]  # fmt: skip
    # L2 between +X and -Z (a right angle): ends at one distance d from the corner X40 Z0 (radius 20),
    # the chamfer 2 long: d = 2 / (2·sin 45°) = √2 = 1.414214; X (20 - √2)·2 = 37.171573, Z-1.414214.
    # D3 between -Z and +X: tangent 3·tan 45° = 3 from the corner X40 Z-20: Z-17, X (20+3)·2 = X46,
    # a clockwise quarter (G02). At 100 mm/min: Z 2 mm 1.2 s; X 18.585786 mm 11.151472 s; the chamfer
    # 2 mm 1.2 s; Z 15.585786 mm 9.351472 s; the arc 3·π/2 = 4.712389 mm 2.827433 s; X 7 mm 4.2 s
    d = sqrt(2.0)
    assert cuts == [
        (0.0, 0.0, "G01", 1.2),
        (round(40.0 - 2.0 * d, 6), 0.0, "G01", round((20.0 - d) * 0.6, 6)),
        (40.0, round(-d, 6), "G01", 1.2),
        (40.0, -17.0, "G01", round((17.0 - d) * 0.6, 6)),
        (46.0, -20.0, "G02", round(1.5 * pi * 0.6, 6)),
        (60.0, -20.0, "G01", 4.2),
    ]
    # G00's L1 is no chamfer (only G01, G02, G03 take one); nothing is noted as not simulated
    assert [mv["to"]["Z"] for mv in result["moves"]][-1] == 2.0
    found = analyse_files(tmp_path, {"O0004.nc": PROGRAM}, "gsk980tdi")
    assert [d for d in found if d.code == "not-simulated"] == []


def test_10_lathe_gsk_two_moves_on_one_line_take_no_chamfer() -> None:
    # §3.11.3 情形 1: "两插补直线段在同一条直线上时，倒角功能无效"
    m = run(lines("O0001", "G98 G0 X40 Z2", "G01 Z-10 F100 L2", "Z-20 D1", "Z-30", "M30"), "gsk980tdi")
    assert m.status == "completed", m.alarm
    assert [mv.end[2] for mv in m.planner.moves] == [2.0, -10.0, -20.0, -30.0]


@pytest.mark.parametrize(
    ("second", "why"),
    [
        # 情形 2: the chamfer longer than the triangle's third side: from X0 Z0 to X40 Z-20 is
        # √(20² + 20²) = 28.28 (radius), L30 is longer
        ("X40 L30", "third side"),
        # 情形 3: L5 at a right angle is 5/√2 = 3.54 from the corner, the next move only 2 long
        ("X40 L5", "too short"),
        # 圆弧倒角 情形 2: D5 needs 5 along each move, the next move only 2 long
        ("X40 D5", "too large"),
    ],
)
def test_10_lathe_gsk_a_chamfer_that_does_not_fit_is_the_controls_alarm(second: str, why: str) -> None:
    last = "Z-20" if "L30" in second else "Z-2"
    m = run(lines("O0001", "G98 G0 X0 Z0", f"G01 {second} F100", last, "M30"), "gsk980tdi")
    assert m.status == "alarm" and m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (55, 4)
    assert why in m.alarm.message
