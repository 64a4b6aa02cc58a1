"""The GSK980TDi's threads as its manual (§3.24, §3.25) has them cut, and the FANUC 0i-TF's G34
lead that would run out (docs/semantics.md §10.3, §10.4): the S of a G50 that sets coordinates,
left-hand threads by a negative F, G92.3's passes across the root, G34's alarm and G78's passes.
Every number is worked by hand; gsk980tdi rapids X 6000 mm/min (of the radius), Z 8000."""

from __future__ import annotations

import pytest

from running import lines, run

GSK = "gsk980tdi"


# ---------------------------------------------------------------------------------------------
# G50 S (§3.24.12's example, §3.25, §3.18)


def test_gsk_g50_that_sets_coordinates_takes_its_s_as_the_spindle_speed_under_g97() -> None:
    # the manual's G76 example: "G50 X100 Z50 M3 S300；(设置工件坐标系启动主轴，指定转速)": the spindle
    # turns at 300, #4119 reads 300; a G32 of 30 mm at F2: 30 / (2 x 300) min = 0.05 min = 3 s.
    # "G50 S2000" alone is the clamp: #4119 still reads 300
    m = run(lines("G50 X100 Z50 M3 S300", "#100=#4119", "G00 X60 Z5", "G32 W-30 F2", "G50 S2000", "#101=#4119",
                  "M30"), GSK)  # fmt: skip
    assert (m.C[100], m.C[101]) == (300.0, 300.0)
    assert m.planner.moves[-1].seconds == pytest.approx(3.0)


def test_gsk_g50_s_with_coordinates_under_g96_stays_the_clamp() -> None:
    # under G96 "G50 S__可限制主轴最高转速" (§3.25): G96 S100 then G50 X100 Z50 S1500 leaves S at 100
    m = run(lines("G96 S100 M3", "G50 X100 Z50 S1500", "#100=#4119", "M30"), GSK)
    assert m.C[100] == 100.0


def test_fanuc_lathe_g50_s_with_coordinates_is_the_clamp() -> None:
    # the 0i-TF's G50 X Z S: S is the maximum spindle speed; the S code stays 800
    m = run(lines("G97 S800 M03", "G50 X100. Z50. S2000", "#100=#4119", "M30"), "fanuc-0i-lathe")
    assert m.C[100] == 800.0
