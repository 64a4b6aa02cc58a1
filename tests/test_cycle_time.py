"""Cycle time and path length (docs/semantics.md §9): five programs timed by hand, each within 1 %
of ``cncmacro run --json``, the machine file's ``[timing]``, and the clock that #3001 reads
agreeing with the cycle time (one rule, planner/cycle_time.py)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from cli_capture import cli, run_json
from running import lines, run


def test_feed_per_minute_and_each_axis_at_its_own_rapid_rate(tmp_path: Path) -> None:
    # fanuc-0i rapids: X, Y, Z 24000 mm/min each; a rapid lasts as long as its slowest axis.
    #   G00 X120 Y60 Z5:  max(120, 60, 5) / 24000 min = 0.3 s   (path sqrt(120²+60²+5²) = 134.257 mm)
    #   G01 Z-5 F100:     10 mm / 100 mm/min          = 6 s
    #   G01 X0 F600:      120 mm / 600 mm/min         = 12 s
    #   G01 Y0 F300:      60 mm / 300 mm/min          = 12 s
    #   G00 Z50:          55 / 24000 min              = 0.1375 s (55 mm)
    #   total 30.4375 s; cut 190 mm; rapid 189.257 mm
    text = lines("O1001", "G21 G90 G94 G17", "G00 X120. Y60. Z5.", "G01 Z-5. F100",
                 "G01 X0 F600", "G01 Y0 F300", "G00 Z50.", "M30")  # fmt: skip
    result = run_json(tmp_path, text)
    cycle = result["cycle"]
    assert cycle["seconds"] == pytest.approx(30.4375, rel=0.01)
    assert cycle["cut"] == pytest.approx(190.0, rel=0.01)
    assert cycle["rapid"] == pytest.approx(189.257, rel=0.01)
    assert [round(mv["time"], 4) for mv in result["moves"]] == [0.3, 6.0, 12.0, 12.0, 0.1375]


@pytest.mark.parametrize(("profile", "rapid"), [("fanuc-0i", 24000.0), ("gsk980tdi", 8000.0)])
def test_g53_moves_at_rapid_whatever_motion_is_in_force(tmp_path: Path, profile: str, rapid: float) -> None:
    # GSK980TDi §3.20: "刀具快速定位到该位置，速度及运动方式与快速定位 G00 相同"; FANUC alike. Under
    # G01 F100, G53 Z0 from Z-31 with no work offset: 31 mm of Z at its rapid (fanuc-0i 24000,
    # gsk980tdi 8000 mm/min): 0.0775 s or 0.2325 s, not 31 / 100 min = 18.6 s; then G01 Z-10 feeds
    # again: 10 mm at F100 = 6 s
    text = lines("O0001", f"(cncmacro: dialect={profile})", "G98 G94 G00 Z-30.", "G01 Z-31. F100", "G53 Z0",
                 "Z-10.", "M30")  # fmt: skip
    moves = run_json(tmp_path, text)["moves"]
    g53, after = moves[2], moves[3]
    assert (g53["kind"], g53["time"]) == ("rapid", pytest.approx(31 / rapid * 60))
    assert (after["kind"], after["time"]) == ("feed", pytest.approx(6.0))


def test_feed_per_revolution_on_a_lathe_is_f_times_s_and_x_is_a_diameter(tmp_path: Path) -> None:
    # gsk980tdi: rapids X 6000 mm/min (radius), Z 8000; T0101 indexes the turret: 1 s.
    #   T0101:                 1 s
    #   G00 X40 Z2:            X 20 mm radius / 6000 = 0.2 s, Z 2 / 8000 = 0.015 s -> 0.2 s
    #   G99 G01 Z-48 F0.2 S500: 50 mm / (0.2 mm/rev * 500 rev/min = 100 mm/min) = 30 s
    #   G01 X50 F0.1:          5 mm radius / (0.1 * 500 = 50 mm/min)           = 6 s
    #   G00 X100 Z2:           X 25 / 6000 = 0.25 s, Z 50 / 8000 = 0.375 s       -> 0.375 s
    #   total 37.575 s; cut 55 mm
    text = lines("O0002", "T0101", "M03 S500", "G00 X40. Z2.", "G99 G01 Z-48. F0.2", "G01 X50. F0.1",
                 "G00 X100. Z2.", "M30")  # fmt: skip
    cycle = run_json(tmp_path, text, "O0002.CNC", 'base = "gsk980tdi"\n')["cycle"]
    assert cycle["seconds"] == pytest.approx(37.575, rel=0.01)
    assert cycle["cut"] == pytest.approx(55.0, rel=0.01)


def test_constant_surface_speed_turns_the_spindle_by_the_diameter(tmp_path: Path) -> None:
    # G96 S100 (m/min) at X50 (a diameter of 50 mm): 100000 / (pi * 50) = 636.62 rev/min;
    #   G99 G01 Z-50 F0.2: 50 mm / (0.2 * 636.62 = 127.32 mm/min) = 23.562 s
    text = lines("O0003", "G00 X50. Z0", "G96 S100 M03", "G99 G01 Z-50. F0.2", "M30")
    result = run_json(tmp_path, text, "O0003.CNC", 'base = "gsk980tdi"\n')
    assert result["moves"][1]["time"] == pytest.approx(50 / (0.2 * 100000 / (math.pi * 50)) * 60, rel=0.01)
    assert result["moves"][1]["time"] == pytest.approx(23.562, rel=0.01)


def test_an_arc_takes_the_time_of_its_length_not_of_its_chord(tmp_path: Path) -> None:
    # F500 mm/min throughout:
    #   G01 X10:                 10 mm                          = 1.2 s
    #   G03 X-10 Y0 R10:         half circle, pi * 10 = 31.416 mm = 3.7699 s (the chord, 20 mm, would be 2.4 s)
    #   G02 X-10 Y0 I10 J0:      back to its start: a full circle, 2 pi * 10 = 62.832 mm = 7.5398 s
    #   G02 X0 Y10 Z-5 I10:      a quarter turn (15.708 mm) with 5 mm down: FANUC feeds a helix
    #                            along its arc (docs/semantics.md §9): 15.708 mm = 1.885 s
    #   total 14.3947 s; cut 119.956 mm
    text = lines("O1004", "G17 G90 G94", "G01 X10. F500", "G03 X-10. Y0 R10.", "G02 X-10. Y0 I10. J0",
                 "G02 X0 Y10. Z-5. I10. J0", "M30")  # fmt: skip
    result = run_json(tmp_path, text)
    assert result["cycle"]["seconds"] == pytest.approx(14.3947, rel=0.001)
    assert result["cycle"]["cut"] == pytest.approx(119.956, rel=0.001)
    assert [round(mv["time"], 3) for mv in result["moves"]] == [1.2, 3.77, 7.54, 1.885]


@pytest.mark.parametrize(
    ("profile", "name", "dwells", "seconds"),
    [
        # FANUC: P counts milliseconds, X seconds: 1.5 + 2 = 3.5 s
        ("fanuc-0i", "MAIN.nc", ["G04 P1500", "G04 X2."], 3.5),
        # GSK980TDi: P milliseconds, X and U seconds: 0.25 + 0.5 + 1 = 1.75 s
        ("gsk980tdi", "O0005.CNC", ["G04 P250", "G04 U0.5", "G04 X1."], 1.75),
        # Haas: P written with a decimal point counts seconds: 2 s
        ("haas", "MAIN.nc", ["G04 P2."], 2.0),
    ],
)
def test_a_dwell_counts_in_the_profiles_units(tmp_path: Path, profile, name, dwells, seconds) -> None:
    text = lines("O0005", *dwells, "M30")
    cycle = run_json(tmp_path, text, name, f'base = "{profile}"\n')["cycle"]
    assert cycle["seconds"] == pytest.approx(seconds, rel=0.01)


def test_an_inch_program_moves_in_inches_and_reports_inches(tmp_path: Path) -> None:
    # G20: G00 X2. is 50.8 mm at 24000 mm/min = 0.127 s; G01 X0 F20. is 2 in at 20 in/min = 6 s;
    # the path is shown in the program's unit: 2 in cut, 2 in rapid (docs/semantics.md §9)
    text = lines("O1007", "G20 G90 G94", "G00 X2.", "G01 X0 F20.", "M30")
    cycle = run_json(tmp_path, text)["cycle"]
    assert cycle["seconds"] == pytest.approx(6.127, rel=0.01)
    assert (cycle["cut"], cycle["rapid"], cycle["unit"]) == (pytest.approx(2.0), pytest.approx(2.0), "in")
    assert cycle["text"] == "≈ 6.1 s · 2.0 in cut · 2.0 in rapid"


def test_tool_changes_and_m_codes_take_the_machine_files_times(tmp_path: Path) -> None:
    # [timing]: tool change 5 s, M08 0.5 s, rapid X 12000 mm/min.
    #   T1 M06: 5 s | G00 X100: 100 / 12000 min = 0.5 s | G01 X0 F1000: 100 / 1000 min = 6 s  -> T1 11.5 s
    #   T2 M06: 5 s | M08: 0.5 s | G01 X50 F500: 50 / 500 min = 6 s                             -> T2 11.5 s
    #   total 23 s
    timing = "[timing]\nrapid = { X = 12000 }\ntool_change = 5\n[timing.m_codes]\nM08 = 0.5\n"
    text = lines("O1006", "T1 M06", "G00 X100.", "G01 X0 F1000", "T2 M06", "M08", "G01 X50. F500", "M30")
    cycle = run_json(tmp_path, text, machine_file=timing)["cycle"]
    assert cycle["seconds"] == pytest.approx(23.0, rel=0.01)
    tools = [(t["tool"], t["line"], round(t["seconds"], 3), t["cut"], t["rapid"]) for t in cycle["tools"]]
    assert tools == [(1.0, 2, 11.5, 100.0, 100.0), (2.0, 5, 11.5, 50.0, 0.0)]


def test_run_prints_the_totals_of_the_program_and_of_each_tool(tmp_path: Path) -> None:
    text = lines("O1006", "T1 M06", "G00 X100.", "G01 X0 F1000", "T2 M06", "G01 X50. F500", "M30")
    path = tmp_path / "MAIN.nc"
    path.write_text(text, encoding="utf-8")
    code, out, _ = cli("run", "--no-save", str(path))
    assert code == 0
    # 3 + 0.25 + 6 = 9.25 s for T1, 3 + 6 = 9 s for T2
    assert "cycle time O1006: ≈ 18 s · 150 mm cut · 100 mm rapid" in out
    assert "  T1 (MAIN.nc:2): ≈ 9.2 s · 100 mm cut · 100 mm rapid" in out
    assert "  T2 (MAIN.nc:5): ≈ 9.0 s · 50 mm cut · 0 mm rapid" in out
    code, out, _ = cli("run", "--no-save", "--locale", "zh-CN", str(path))
    assert "加工时间 O1006：≈ 18 秒 · 切削 150 mm · 快移 100 mm" in out


@pytest.mark.parametrize(
    ("table", "message"),
    [
        ("rapid = { X = -5 }", "'timing.rapid' must map axis letters to rapid rates (above 0, at most 1000000 mm/min)"),
        ("peck_clearance = -1", "'timing.peck_clearance' must be the distance in mm above the depth reached where "
                                "G83's rapid back in stops (0 to 100000)"),
        # finite, but beyond any machine: two tool changes would make the cycle time infinite
        ("tool_change = 1e308", "'timing.tool_change' must be the seconds a tool change takes (0 to 3600)"),
        ("m_codes = { M08 = 1e300 }", "'timing.m_codes.M08' must map M codes to seconds (0 to 3600)"),
        ("max_spindle_speed = 1e50", "'timing.max_spindle_speed' must be a speed in rev/min (above 0, at most"),
    ],
)  # fmt: skip
def test_a_bad_timing_value_names_its_key(tmp_path: Path, table: str, message: str) -> None:
    (tmp_path / ".cncmacro.toml").write_text(f"[timing]\n{table}\n", encoding="utf-8")
    path = tmp_path / "MAIN.nc"
    path.write_text("O1\nM30\n", encoding="utf-8")
    code, _, err = cli("run", str(path))
    assert code == 2
    assert message in err


def test_the_clock_that_3001_reads_is_the_cycle_time() -> None:
    # #3001 counts milliseconds: G01 X100 F600 is 10 s, the dwell 1.5 s, the tool change 3 s
    m = run(lines("O1", "#3001=0", "T1 M06", "G01 X100. F600", "G04 P1500", "#1=#3001", "M30"))
    assert m.variables()[1] == pytest.approx(14500.0, abs=1.0)
    assert m.planner.clock == pytest.approx(14.5)


# ---------------------------------------------------------------- drilling canned cycles
# fanuc-0i rapids X, Y, Z 24000 mm/min (400 mm/s): a rapid of n mm takes n / 400 s.


def test_a_drilling_cycle_rapids_to_r_feeds_to_z_and_rapids_back_to_the_initial_level(tmp_path: Path) -> None:
    # G98 G81 Z-10 R2 F120, initial level Z50 (where the G00 left the tool):
    #   G00 X0 Y0 Z50:             50 mm rapid                                        = 0.125 s
    #   hole 1 X20 Y0:  position X0 -> X20 at Z50: 20 mm rapid                         = 0.05 s
    #                   rapid Z50 -> R2: 48 mm = 0.12 s; feed R2 -> Z-10: 12 mm at 120 = 6 s
    #                   rapid Z-10 -> Z50 (G98): 60 mm                                  = 0.15 s   -> 6.32 s
    #   hole 2 X40:     20 mm positioning, then the same                                          -> 6.32 s
    #   hole 3 Y30:     30 mm positioning = 0.075 s, then the same                                 -> 6.345 s
    #   total 19.11 s; cut 3 x 12 = 36 mm; rapid 50 + (20 + 48 + 60) + (20 + 108) + (30 + 108) = 444 mm
    # (as one feed from the hole before at Z50 to the hole's bottom, hole 1 alone would have
    # been sqrt(20² + 60²) = 63.2 mm at F120, 31.6 s)
    text = lines("O1010", "G21 G90 G94 G17", "G00 X0 Y0 Z50.", "G98 G81 X20. Y0 Z-10. R2. F120", "X40.",
                 "Y30.", "G80", "M30")  # fmt: skip
    result = run_json(tmp_path, text)
    cycle = result["cycle"]
    assert cycle["seconds"] == pytest.approx(19.11, rel=0.01)
    assert cycle["cut"] == pytest.approx(36.0, rel=0.01)
    assert cycle["rapid"] == pytest.approx(444.0, rel=0.01)
    assert [round(mv["time"], 3) for mv in result["moves"]] == [0.125, 6.32, 6.32, 6.345]
    # each hole is drawn from where the tool was to the hole's bottom; Z stays in force
    assert [(mv["to"]["X"], mv["to"]["Y"], mv["to"]["Z"]) for mv in result["moves"][1:]] == [
        (20.0, 0.0, -10.0), (40.0, 0.0, -10.0), (40.0, 30.0, -10.0)]  # fmt: skip
    assert [mv["from"]["Z"] for mv in result["moves"][1:]] == [50.0, 50.0, 50.0]  # back at the initial level


@pytest.mark.parametrize(
    ("machine_file", "seconds", "cut", "rapid"),
    [
        # d = 0 (the profile's): pecks to 5, 10, 14 mm below R2, each later one from where the
        # last ended.  hole 1: position 10 mm (0.025 s), rapid Z20 -> R2 18 mm (0.045 s),
        #   feed 5, rapid up 5 to R and down 5, feed 5, rapid up 10 and down 10, feed 4,
        #   rapid up 14 to R (G99): feeds 14 mm at F100 = 8.4 s, rapids 44 mm = 0.11 s -> 8.58 s
        # hole 2: position 20 mm at R2 (0.05 s), no rapid to R, the same pecks       -> 8.56 s
        # G00 Z20: 0.05 s. Total 17.19 s; cut 28 mm; rapid 20 + (10 + 18 + 44) + (20 + 44) = 156 mm
        ("", 17.19, 28.0, 156.0),
        # d = 1 mm (parameter 5115): the rapid back in stops 1 mm above the last depth and the
        # feed takes that 1 mm too: feeds 5 + 6 + 5 = 16 mm = 9.6 s, rapids 5 + 4 + 10 + 9 + 14
        # = 42 mm = 0.105 s. Hole 1: 0.025 + 0.045 + 9.6 + 0.105 = 9.775 s, hole 2: 0.05 + 9.6 +
        # 0.105 = 9.755 s. Total 19.58 s; cut 32 mm; rapid 20 + (10 + 18 + 42) + (20 + 42) = 152 mm
        ("[timing]\npeck_clearance = 1\n", 19.58, 32.0, 152.0),
    ],
)
def test_g83_pecks_by_q_back_to_r_and_g99_returns_to_r(tmp_path: Path, machine_file, seconds, cut, rapid) -> None:
    text = lines("O1011", "G21 G90 G94", "G00 X0 Y0 Z20.", "G99 G83 X10. Y0 Z-12. R2. Q5. F100", "X30.", "G80",
                 "M30")  # fmt: skip
    result = run_json(tmp_path, text, machine_file=machine_file)
    cycle = result["cycle"]
    assert cycle["seconds"] == pytest.approx(seconds, rel=0.01)
    assert (cycle["cut"], cycle["rapid"]) == (pytest.approx(cut, rel=0.01), pytest.approx(rapid, rel=0.01))
    assert result["moves"][2]["from"]["Z"] == 2.0  # G99: the second hole starts from R


def test_g73_retracts_d_after_each_peck(tmp_path: Path) -> None:
    # peck_retract = 0.5 mm (parameter 5114). G98 G73 Z-12 R2 Q5 F100 from Z20:
    #   G00 Z20: 0.05 s; position 10 mm: 0.025 s; rapid Z20 -> R2 18 mm: 0.045 s
    #   feed 5, rapid up 0.5, feed 5.5, rapid up 0.5, feed 4.5: feeds 15 mm = 9 s, rapids 1 mm = 0.0025 s
    #   rapid Z-12 -> Z20 (G98): 32 mm = 0.08 s
    #   total 9.2025 s; cut 15 mm; rapid 20 + 10 + 18 + 1 + 32 = 81 mm
    text = lines("O1012", "G21 G90 G94", "G00 X0 Y0 Z20.", "G98 G73 X10. Z-12. R2. Q5. F100", "G80", "M30")
    cycle = run_json(tmp_path, text, machine_file="[timing]\npeck_retract = 0.5\n")["cycle"]
    assert cycle["seconds"] == pytest.approx(9.2025, rel=0.01)
    assert (cycle["cut"], cycle["rapid"]) == (pytest.approx(15.0), pytest.approx(81.0))


def test_a_peck_q_keeps_its_decimals(tmp_path: Path) -> None:
    # peck_retract = 0.5 mm. G98 G73 Z-10 R2 Q2.5 F100 from Z20 (a Q read as 3 would peck 4 times, not 5):
    #   G00 Z20: 0.05 s; position 10 mm: 0.025 s; rapid Z20 -> R2 18 mm: 0.045 s
    #   feed 2.5, then 3.0, 3.0, 3.0 (d + Q), then 2.5 (the last 2 mm + d): 14 mm = 8.4 s;
    #   four retracts of 0.5 mm: 2 mm = 0.005 s; rapid Z-10 -> Z20 (G98): 30 mm = 0.075 s
    #   total 8.6 s; cut 14 mm; rapid 20 + 10 + 18 + 2 + 30 = 80 mm
    text = lines("O1016", "G21 G90 G94", "G00 X0 Y0 Z20.", "G98 G73 X10. Z-10. R2. Q2.5 F100", "G80", "M30")
    cycle = run_json(tmp_path, text, machine_file="[timing]\npeck_retract = 0.5\n")["cycle"]
    assert cycle["seconds"] == pytest.approx(8.6, rel=0.01)
    assert (cycle["cut"], cycle["rapid"]) == (pytest.approx(14.0), pytest.approx(80.0))


def test_g82_dwells_p_at_the_bottom_and_k_repeats_the_hole_by_the_g91_increment(tmp_path: Path) -> None:
    # G91: R-8 is 8 mm below the initial level Z10 (R at Z2), Z-8 is 8 mm below R (bottom Z-6);
    # K3 drills three holes, each 15 mm further along X. Each hole:
    #   position 15 mm: 0.0375 s; rapid Z10 -> R2 8 mm: 0.02 s; feed 8 mm at F200: 2.4 s;
    #   dwell P500: 0.5 s; rapid Z-6 -> Z10 (G98) 16 mm: 0.04 s                      -> 2.9975 s
    #   G00 Z10: 0.025 s. Total 0.025 + 3 x 2.9975 = 9.0175 s; cut 24 mm; rapid 10 + 3 x 39 = 127 mm
    text = lines("O1013", "G21 G90 G94", "G00 X0 Y0 Z10.", "G91 G98 G82 X15. Z-8. R-8. P500 F200 K3", "G90 G80",
                 "M30")  # fmt: skip
    result = run_json(tmp_path, text)
    cycle = result["cycle"]
    assert cycle["seconds"] == pytest.approx(9.0175, rel=0.01)
    assert (cycle["cut"], cycle["rapid"]) == (pytest.approx(24.0), pytest.approx(127.0))
    holes = [(mv["to"]["X"], mv["to"]["Z"]) for mv in result["moves"][1:]]
    assert holes == [(15.0, -6.0), (30.0, -6.0), (45.0, -6.0)]


@pytest.mark.parametrize(
    ("cycle_block", "seconds"),
    [
        # G85 boring: feed in and feed out to R, then rapid to the initial level (G98):
        #   G00 Z20 0.05 s; position 10 mm 0.025 s; rapid Z20 -> R2 0.045 s; feed 12 mm at F120
        #   6 s; feed 12 mm back to R 6 s; rapid R2 -> Z20 0.045 s: 12.165 s
        ("G98 G85 X10. Z-10. R2. F120", 12.165),
        # G84 tapping (F per minute under G94): the same moves, and with no P no dwell: 12.165 s
        ("G98 G84 X10. Z-10. R2. F120", 12.165),
        # G89: the same with a dwell P1000 at the bottom: 13.165 s
        ("G98 G89 X10. Z-10. R2. P1000 F120", 13.165),
        # G81 with the same data: feed in, rapid out Z-10 -> Z20 (0.075 s): 0.05 + 0.025 + 0.045
        # + 6 + 0.075 = 6.195 s
        ("G98 G81 X10. Z-10. R2. F120", 6.195),
    ],
)
def test_tapping_and_feed_out_boring_come_back_to_r_at_f(tmp_path: Path, cycle_block, seconds) -> None:
    text = lines("O1014", "G21 G90 G94", "G00 X0 Y0 Z20.", cycle_block, "G80", "M30")
    assert run_json(tmp_path, text)["cycle"]["seconds"] == pytest.approx(seconds, rel=0.01)


def test_the_bolt_circle_example_drills_a_hole_in_seconds_not_a_diagonal_feed() -> None:
    # examples/fanuc/bolt_circle.nc: 18 holes by G98 G81 from the initial level Z50.
    #   feeds: 6 x 14 mm (R2 to Z-12) at F120 = 42 s, 4 x 11 mm (R3 to Z-8) at F100 = 26.4 s,
    #          8 x 17 mm (R2 to Z-15) at F120 = 68 s: 264 mm, 136.4 s
    #   tool change 3 s
    #   rapids along Z: per hole down to R and up from the bottom, 6 x (48 + 62) + 4 x (47 + 58) +
    #          8 x (48 + 65) = 1984 mm, with G43 Z50, G00 Z100 and G28 Z0 (200 mm): 2184 mm, 5.46 s
    #   positioning between holes, each axis at 24000 mm/min: the longer axis of each move sums
    #          to 702.45 mm, 1.756 s (their straight lengths to 760.56 mm)
    #   total 146.6 s; rapid 2184 + 760.56 = 2944.6 mm
    example = Path(__file__).parent.parent / "examples" / "fanuc" / "bolt_circle.nc"
    code, out, _ = cli("run", "--no-save", str(example))
    assert code == 0
    assert "cycle time O1000: ≈ 2 min 27 s · 264 mm cut · 2,945 mm rapid" in out


def test_a_repeat_count_past_9999_is_an_alarm_and_haas_repeats_by_l() -> None:
    m = run(lines("O1", "G00 Z10.", "G91 G81 X10. Z-5. R-8. F100 K10000", "M30"))
    assert m.alarm is not None and m.alarm.number == 119
    m = run(lines("O1", "G00 Z10.", "G91 G81 X10. Z-5. R-8. F100 L3", "G90 G80", "M30"), "haas")
    assert [move.end[0] for move in m.planner.moves if move.mode == 81.0] == [10.0, 20.0, 30.0]


def test_9_lathe_single_cycles_are_timed_leg_by_leg_and_a_thread_at_its_lead_per_revolution(tmp_path: Path) -> None:
    # gsk980tdi rapids: X 6000 mm/min (of the radius), Z 8000 mm/min; S500; the tool at X50 Z2.
    # G99 G90 X40 Z-30 F0.2 (100 mm/min):
    #   in along X at rapid: 5 mm radius / 6000 = 0.05 s;   cut along Z: 32 mm / 100 = 19.2 s
    #   out along X at the feed: 5 mm / 100 = 3 s;           back along Z at rapid: 32 / 8000 = 0.24 s
    #   = 22.49 s (as one diagonal cut it was 32.39 mm / 100 = 19.43 s)
    # G98 G92 X48 Z-20 F1.5: a thread's F is the lead per revolution even under G98: 1.5 x 500
    # = 750 mm/min. In: 1 mm / 6000 = 0.01 s; thread: 22 / 750 = 1.76 s; out at rapid: 0.01 s;
    # back: 22 / 8000 = 0.165 s = 1.945 s (per minute it was 22.02 mm / 1.5 mm/min: 14.7 min)
    # G99 G94 X20 Z-2 F0.1 (50 mm/min):
    #   in along Z at rapid: 4 / 8000 = 0.03 s;   face along X: 15 mm / 50 = 18 s
    #   out along Z at the feed: 4 / 50 = 4.8 s;  back along X at rapid: 15 / 6000 = 0.15 s = 22.98 s
    text = lines("O0009", "M03 S500", "G00 X50. Z2.", "G99 G90 X40. Z-30. F0.2", "G98 G92 X48. Z-20. F1.5",
                 "G99 G94 X20. Z-2. F0.1", "M30")  # fmt: skip
    result = run_json(tmp_path, text, "O0009.CNC", 'base = "gsk980tdi"\n')
    cycles = [mv for mv in result["moves"] if mv["kind"] == "cycle"]
    assert [round(mv["time"], 3) for mv in cycles] == [22.49, 1.945, 22.98]
    assert result["cycle"]["cut"] == pytest.approx(5 + 32 + 22 + 15 + 4, rel=0.001)  # the cutting legs, mm


def test_9_a_gsk980tdi_skip_move_goes_at_200_mm_per_minute_at_most(tmp_path: Path) -> None:
    # GSK980TDi manual §3.16.2, note: "进给速度超过 200mm/min 时被箝制在该速度". No [skip] table: each
    # G31 runs to its end point.
    #   G98 G31 Z-20 F500 from Z10:  30 mm at 200 mm/min (not 500)   = 9.0 s (was 3.6 s)
    #   G31 Z-30 F100:               10 mm at 100 mm/min, as written  = 6.0 s
    #   G01 Z-40 F500:               10 mm at 500 mm/min, no skip     = 1.2 s
    #   G20 G31 W-1. F20. (20 in/min = 508 mm/min): 200 mm/min = 7.874 in/min, 1 in -> 7.62 s
    text = lines("O0004 (cncmacro: dialect=gsk980tdi)", "G00 X20. Z10.", "G98 G31 Z-20. F500", "G31 Z-30. F100",
                 "G01 Z-40. F500", "G20", "G31 W-1. F20.", "M30")  # fmt: skip
    moves = run_json(tmp_path, text, "O0004.nc")["moves"]
    assert [round(mv["time"], 3) for mv in moves[1:]] == [9.0, 6.0, 1.2, 7.62]
    # FANUC's manuals give G31 no such clamp: 30 mm at 500 mm/min = 3.6 s
    fanuc = run_json(tmp_path, lines("O0005", "G00 Z10.", "G94 G31 Z-20. F500", "M30"), "O0005.nc")["moves"]
    assert round(fanuc[1]["time"], 3) == 3.6
