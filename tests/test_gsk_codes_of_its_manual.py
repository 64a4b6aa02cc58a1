"""The GSK980TDi's G codes as its manual gives them (GSK980TDi 系列车床（车削中心）数控系统 操作使用
手册, chapter 3), each run as the control runs it (docs/semantics.md §8, §10.3):

- G05 / G05.1 (§3.5): an arc through the start, a point on the arc (I, K: relative to the start
  as a radius value, or absolute with X a diameter) and the end;
- G33 (§3.24.5): taps in to Z and back out to the start, both at the lead per revolution, each of
  L starts in turn; G92 (§3.24.9) cuts its L starts (modal);
- I instead of F in a thread (§3.24.1, §3.24.5, §3.24.9): threads per inch, a lead of 25.4 / I;
- G52 (§3.19) sets a local coordinate system without moving; G53 (§3.20), G22/G23 (§3.31), the
  ellipse and parabola codes (§3.6, §3.7) are codes of the control, not unknown ones; an
  ellipse's B is its half axis, not the B axis;
- #4001 (§3.28.1) reads G6.2, G6.3, G32.1, G7.2, G7.3 as 124, 126, 132, 144, 146.

Rates: G98 (per minute) at power-on; rapids X 6000 mm/min (of the radius), Z 8000."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import pytest

from cli_capture import cli, run_json
from running import final, lines, run


def run_gsk(folder: Path, *body: str) -> dict[str, Any]:
    return run_json(folder, lines("O0001 (cncmacro: dialect=gsk980tdi)", *body, "M30"), "O0001.nc")


def xz(point: dict[str, float]) -> tuple[float, float]:
    return round(point["X"], 6), round(point["Z"], 6)


def test_g05_and_g05_1_cut_the_manuals_half_circle(tmp_path: Path) -> None:
    # §3.5's example: from X10 Z20 through the point I5 K-5 from it (G05), or X20 Z15 (G05.1), to
    # X10 Z10: the circle about X10 Z15 (radius 5), half of it: 5 pi = 15.708 mm at F150 -> 6.283 s
    result = run_gsk(tmp_path, "G98 G00 X10 Z20", "G05 X10 Z10 I5 K-5 F150", "G00 X10 Z20", "G05.1 X10 Z10 I20 K15")
    arcs = [mv for mv in result["moves"] if mv["line"] in (3, 5)]
    assert [xz(mv["centre"]) for mv in arcs] == [(10.0, 15.0), (10.0, 15.0)]
    assert [xz(mv["to"]) for mv in arcs] == [(10.0, 10.0), (10.0, 10.0)]
    assert [mv["time"] for mv in arcs] == pytest.approx([5 * math.pi / 150 * 60] * 2)


def test_a_three_point_arc_is_the_one_through_its_point(tmp_path: Path) -> None:
    # from X20 Z0 (radius 10) to X40 Z-10 (radius 20) through the point 45 deg round the circle
    # about radius 10, Z-10: X = 2 (10 + 10 sin 45) = 34.142, Z = -10 + 10 cos 45 = -2.929. That is
    # the quarter circle (15.708 mm, 9.425 s at F100), not the three quarters (47.124 mm, 28.274 s)
    r = 10 * math.sqrt(0.5)
    result = run_gsk(tmp_path, "G98 G00 X20. Z0", f"G05.1 X40. Z-10. I{2 * (10 + r):.4f} K{-10 + r:.4f} F100")
    arc = result["moves"][1]
    assert xz(arc["centre"]) == pytest.approx((20.0, -10.0), abs=1e-3)  # I, K written to 0.0001
    assert arc["time"] == pytest.approx(10 * math.pi / 2 / 100 * 60, rel=1e-4)


def test_g33_taps_in_and_back_at_the_lead_per_revolution(tmp_path: Path) -> None:
    # §3.24.5's M10x1.5: G33 Z50 F1.5 from Z90 at S300: 40 mm in and 40 mm out at 1.5 x 300 =
    # 450 mm/min (whatever G98 says): 80 / 450 x 60 = 10.667 s; the tool is back at Z90, so the
    # next G00 starts there. L2 cuts it twice: 21.333 s
    result = run_gsk(tmp_path, "G98 G97 S300 M03", "G00 X0 Z90.", "G33 Z50. F1.5", "M03", "G00 X60. Z100.",
                     "G00 X0 Z90.", "G33 Z50. F1.5 L2")  # fmt: skip
    taps = [mv for mv in result["moves"] if mv["mode"] == "G33"]
    assert [mv["time"] for mv in taps] == pytest.approx([80 / 450 * 60, 2 * 80 / 450 * 60])
    after = next(mv for mv in result["moves"] if mv["line"] == 6)
    assert xz(after["from"]) == (0.0, 90.0)
    assert result["cycle"]["cut"] == pytest.approx(80.0 + 160.0)


def test_threads_per_inch_give_the_lead(tmp_path: Path) -> None:
    # I14: a lead of 25.4 / 14 = 1.8143 mm; at S400, 725.71 mm/min.
    # G32 from Z3 to Z-20: 23 mm -> 1.9016 s. G92 from X30 Z3: in to X26.8 (1.6 mm of radius at
    # 6000 mm/min: 0.016 s), the thread 1.9016 s, out 0.016 s, back 23 mm at 8000: 0.1725 s
    thread = 23 / (25.4 / 14 * 400) * 60
    result = run_gsk(tmp_path, "G97 S400 M03", "G00 X26. Z3.", "G32 Z-20. I14", "G00 X30.", "Z3.",
                     "G92 X26.8 Z-20. I14", "G00 X50.")  # fmt: skip
    g32 = next(mv for mv in result["moves"] if mv["line"] == 4)
    g92 = next(mv for mv in result["moves"] if mv["line"] == 7)
    assert g32["time"] == pytest.approx(thread)
    assert g92["time"] == pytest.approx(0.016 + thread + 0.016 + 23 / 8000 * 60)


def test_g92_cuts_each_of_its_l_starts_and_l_stays(tmp_path: Path) -> None:
    # one pass from X32 Z3 to X29.2 Z-30 at F1.5, S500: in 1.4 mm of radius (0.014 s), the thread
    # 33 mm at 750 mm/min (2.64 s), out 0.014 s, back 33 mm at 8000 (0.2475 s): 2.9155 s; L2 twice.
    # The next pass, X28.6 alone, keeps L2: in and out 1.7 mm (0.017 s each): 2 x 2.9215 s
    result = run_gsk(tmp_path, "G97 S500 M03", "G00 X32. Z3.", "G92 X29.2 Z-30. F1.5 L2", "X28.6", "G00 X50.")
    passes = [mv["time"] for mv in result["moves"] if mv["mode"] == "G92"]
    assert passes == pytest.approx([2 * 2.9155, 2 * 2.9215])


def test_g52_sets_a_local_origin_without_moving(tmp_path: Path) -> None:
    # G52 X10 Z10: the program's X40 Z-5 is where the tool stands (work X50 Z5); X40 Z0 is work X50 Z10
    result = run_gsk(tmp_path, "G00 X50. Z5.", "G52 X10. Z10.", "G01 X40. Z0 F100", "G52 X0 Z0", "G00 X60.")
    assert [mv["line"] for mv in result["moves"]] == [2, 4, 6]
    cut = result["moves"][1]
    assert (xz(cut["from"]), xz(cut["to"])) == ((40.0, -5.0), (40.0, 0.0))
    assert cut["time"] == pytest.approx(5 / 100 * 60)
    assert xz(result["moves"][2]["to"]) == (60.0, 10.0)  # the local origin cancelled: work X60 Z10


def test_an_ellipses_b_is_its_half_axis_not_the_b_axis(tmp_path: Path) -> None:
    result = run_gsk(tmp_path, "G98 G00 X0 Z0 B0", "G6.2 X20. Z-10. A20. B10. Q0 F100")
    ellipse = [mv for mv in result["moves"] if mv["line"] == 3]
    assert xz(ellipse[-1]["to"]) == (20.0, -10.0)
    assert {mv["to"]["B"] for mv in ellipse} == {0.0}


def test_the_manuals_codes_are_known_to_the_checker(tmp_path: Path) -> None:
    program = tmp_path / "O0002.nc"
    program.write_text(
        lines("O0002 (cncmacro: dialect=gsk980tdi)", "G98 G00 X50. Z5.", "G22 X200. Z150. I-10. K-200.", "G23",
              "G52 X10. Z10.", "G52 X0 Z0", "G53 X0 Z0", "G00 X50. Z5.", "G05.1 X50. Z-5. I60. K0 F100",
              "G6.3 X40. Z-20. A20. B10. Q0", "G7.2 X30. Z-30. P10. Q0", "G12.1", "G13.1", "M30"),
        encoding="utf-8",
    )  # fmt: skip
    code, out, _ = cli("check", str(program))
    assert (code, out) == (0, "")


def test_g52_takes_u_and_w_as_x_and_z(tmp_path: Path) -> None:
    # §3.19: "绝对代码或相对代码指定时执行的结果一样", and G52 U0 W0 cancels: the same as X, Z
    result = run_gsk(tmp_path, "G00 X50. Z5.", "G52 U10. W10.", "G01 X40. Z0 F100", "G52 U0 W0", "G00 X60.")
    cut = result["moves"][1]
    assert (xz(cut["from"]), xz(cut["to"])) == ((40.0, -5.0), (40.0, 0.0))
    assert xz(result["moves"][2]["to"]) == (60.0, 10.0)


def test_g33_cuts_one_start_where_l_is_left_out(tmp_path: Path) -> None:
    # §3.24.5: "省略 L 时默认为 1 头": L is not kept from the G33 before (each 80 mm at 450 mm/min)
    result = run_gsk(tmp_path, "G97 S300 M03", "G00 X0 Z90.", "G33 Z50. F1.5 L2", "G33 Z50.")
    assert [mv["time"] for mv in result["moves"] if mv["mode"] == "G33"] == pytest.approx(
        [2 * 80 / 450 * 60, 80 / 450 * 60]
    )


def test_4001_reads_the_special_interpolation_codes_as_the_manuals_numbers() -> None:
    # §3.28.1, the modal system variables: #4001 (group 01) reads "G124(G06.2)，G126(G06.3)，
    # G132(G32.1)，G144(G07.2)，G146(G07.3)". Each code alone in its block sets the mode and moves
    # nothing; #4001 then reads 124, 126, 132, 144, 146, and after G01 plain 1. A macro that tests
    # IF[#4001 EQ 124] after G6.2 takes the jump over its alarm.
    program = lines(
        "G6.2", "#101=#4001", "G6.3", "#102=#4001", "G32.1", "#103=#4001", "G7.2", "#104=#4001",
        "G7.3", "#105=#4001", "G01", "#106=#4001", "G6.2", "IF[#4001 EQ 124]GOTO10",
        "#3000=1(WRONG BRANCH)", "N10 M30",
    )  # fmt: skip
    v = final(program, "gsk980tdi")
    assert [v[n] for n in range(101, 107)] == [124, 126, 132, 144, 146, 1]


@pytest.mark.parametrize(
    "body",
    [
        # §3.9: "（也可使用 G112）", "（也可使用 G113）", and G16/G15 "只在极坐标插补中有效"
        (
            "G00 X80. C0 Z0",
            "G112",
            "G98 G01 X40. C0 F500",
            "G16",
            "G02 X15.8114 C108.435 R5.",
            "G15",
            "G01 X40. C-20.",
            "G113",
        ),
        # §3.36: "开始同步：G51.2 P_ Q_ R_ A_", "解除同步：G50.2"
        ("G51.2 P2 Q6", "S300", "G98 G00 X40. Z2.", "G01 X30. F100", "W-10.", "G00 X50.", "G50.2"),
        # §3.35: "G165 P/L__ Q__ K__", P0 ends it; §3.23.11: "G86.1；------循环中止"
        ("G99 G97 S500 M03", "G00 X30. Z2.", "G165 P3 Q80", "G01 Z-20. F0.2", "G165 P0", "G86.1", "G00 X50."),
    ],
    ids=["polar-g112-g16-g15", "polygon-g51.2-g50.2", "chip-breaking-g165-and-g86.1"],
)
def test_the_manuals_other_codes_are_no_unknown_code(tmp_path: Path, body: tuple[str, ...]) -> None:
    # each was "not in the GSK980TDi G-code table: the control alarms", a warning on a code of its manual
    program = tmp_path / "O0003.nc"
    program.write_text(lines("O0003 (cncmacro: dialect=gsk980tdi)", *body, "M30"), encoding="utf-8")
    code, out, _ = cli("check", str(program))
    assert (code, out) == (0, "")


def test_g112_turns_polar_interpolation_on_as_g12_1_does(tmp_path: Path) -> None:
    # an arc in X and C under polar interpolation is not judged in G18's plane (docs/semantics.md
    # §8); under G112 it was "an R arc with its end at its start" before G112 was the GSK's code
    program = tmp_path / "O0004.nc"
    program.write_text(lines("O0004 (cncmacro: dialect=gsk980tdi)", "G98 G00 X40. C0 Z0", "G112",
                             "G01 X40. C-5. F200", "G03 X40. C5. R5.", "G113", "M30"), encoding="utf-8")  # fmt: skip
    code, out, _ = cli("check", str(program))
    assert (code, out) == (0, "")


def test_a_work_offset_in_a_g50_block_is_void() -> None:
    # §3.21 note 6: "若G54~G59指令与G50共段执行时，G54~G59指令将无效，G50执行有效". G54 (offset 0) at
    # X50 Z50, then G55 (X-20 Z-30) G50 X100 Z50: G54 stays, and the tool, at machine X50 Z50, is
    # called X100 Z50. G00 X0 Z0 then goes to machine X50 + (0 - 100) = -50, Z50 + (0 - 50) = 0. Had
    # G55 been taken, the position would have been read in G55 and #4014 would read 55
    m = run(lines("O0001 (cncmacro: dialect=gsk980tdi)", "G10 L2 P1 X0 Z0", "G10 L2 P2 X-20 Z-30",
                  "G54 G00 X50 Z50", "G55 G50 X100 Z50", "#100=#4014", "#101=#5001", "#102=#5003", "G00 X0 Z0",
                  "#103=#5021", "#104=#5023", "M30"), "gsk980tdi")  # fmt: skip
    assert m.status == "completed"
    assert [m.C[n] for n in range(100, 105)] == [54.0, 100.0, 50.0, -50.0, 0.0]


def test_g28_and_g30_cancel_the_tool_offset() -> None:
    # §3.15.1 note 4: "执行 G28 代码回机床零点操作后，系统取消刀具长度补偿" (G30: §3.15.2 note 3). G50 X200 Z100
    # at machine 0; offset 1's X geometry 4 (a diameter). After T0101, G00 X50 Z10 is machine
    # X 50 - 200 + 4 = -146. G28 U0 W0 ends at machine 0 with the offset off: program X200 Z100 (it
    # read X196 before, the offset kept), and G00 X50 Z10 is then machine 50 - 200 = -150 (not -146)
    # until a T sets the offset again: T0101 and X50 give -146 again. G30 the same (its point is
    # machine 0 here too)
    m = run(lines("O0001 (cncmacro: dialect=gsk980tdi)", "G50 X200 Z100", "#2701=4", "T0101", "G00 X50 Z10",
                  "#100=#5021", "G28 U0 W0", "#101=#5001", "#102=#5021", "G00 X50 Z10", "#103=#5021", "T0101",
                  "G00 X50", "#104=#5021", "G30 U0", "#105=#5001", "G00 X50", "#106=#5021", "M30"),
            "gsk980tdi")  # fmt: skip
    assert m.status == "completed"
    assert [m.C[n] for n in range(100, 107)] == [-146.0, 200.0, 0.0, -150.0, -146.0, 200.0, -150.0]
