"""Cycle time and path length (docs/semantics.md §9): five programs timed by hand, each within 1 %
of ``cncmacro run --json``, the machine file's ``[timing]``, and the clock that #3001 reads
agreeing with the cycle time (one rule, machine/cycle_time.py)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from cli_capture import cli
from running import lines, run


def run_json(tmp_path: Path, text: str, name: str = "MAIN.nc", machine_file: str | None = None) -> dict:
    if machine_file is not None:
        (tmp_path / ".cncmacro.toml").write_text(machine_file, encoding="utf-8")
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    code, out, err = cli("run", "--json", "--no-save", str(path))
    assert code == 0, err
    return json.loads(out)


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
    #   G02 X0 Y10 Z-5 I10:      a quarter turn (15.708 mm) with 5 mm down: sqrt(15.708² + 5²)
    #                            = 16.485 mm = 1.9782 s
    #   total 14.4879 s; cut 120.733 mm
    text = lines("O1004", "G17 G90 G94", "G01 X10. F500", "G03 X-10. Y0 R10.", "G02 X-10. Y0 I10. J0",
                 "G02 X0 Y10. Z-5. I10. J0", "M30")  # fmt: skip
    result = run_json(tmp_path, text)
    assert result["cycle"]["seconds"] == pytest.approx(14.4879, rel=0.01)
    assert result["cycle"]["cut"] == pytest.approx(120.733, rel=0.01)
    assert [round(mv["time"], 3) for mv in result["moves"]] == [1.2, 3.77, 7.54, 1.978]


@pytest.mark.parametrize(
    ("profile", "name", "dwells", "seconds"),
    [
        # FANUC: P counts milliseconds, X seconds: 1.5 + 2 = 3.5 s
        ("fanuc-0i", "MAIN.nc", ["G04 P1500", "G04 X2."], 3.5),
        # GSK980TDi: P milliseconds, X and U seconds: 0.25 + 0.5 + 1 = 1.75 s
        ("gsk980tdi", "O0005.CNC", ["G04 P250", "G04 U0.5", "G04 X1."], 1.75),
        # Haas: P counts seconds (written with a point): 2 s
        ("haas", "MAIN.nc", ["G04 P2."], 2.0),
    ],
)
def test_a_dwell_counts_in_the_profiles_units(tmp_path: Path, profile, name, dwells, seconds) -> None:
    text = lines("O0005", *dwells, "M30")
    cycle = run_json(tmp_path, text, name, f'base = "{profile}"\n')["cycle"]
    assert cycle["seconds"] == pytest.approx(seconds, rel=0.01)


def test_an_inch_program_moves_in_inches_and_reports_millimetres(tmp_path: Path) -> None:
    # G20: G00 X2. is 50.8 mm at 24000 mm/min = 0.127 s; G01 X0 F20. is 2 in at 20 in/min = 6 s
    text = lines("O1007", "G20 G90 G94", "G00 X2.", "G01 X0 F20.", "M30")
    cycle = run_json(tmp_path, text)["cycle"]
    assert cycle["seconds"] == pytest.approx(6.127, rel=0.01)
    assert (cycle["cut"], cycle["rapid"]) == (pytest.approx(50.8), pytest.approx(50.8))


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


def test_a_bad_timing_value_names_its_key(tmp_path: Path) -> None:
    (tmp_path / ".cncmacro.toml").write_text("[timing]\nrapid = { X = -5 }\n", encoding="utf-8")
    path = tmp_path / "MAIN.nc"
    path.write_text("O1\nM30\n", encoding="utf-8")
    code, _, err = cli("run", str(path))
    assert code == 2
    assert "'timing.rapid' must map axis letters to rapid rates above 0" in err


def test_the_clock_that_3001_reads_is_the_cycle_time() -> None:
    # #3001 counts milliseconds: G01 X100 F600 is 10 s, the dwell 1.5 s, the tool change 3 s
    m = run(lines("O1", "#3001=0", "T1 M06", "G01 X100. F600", "G04 P1500", "#1=#3001", "M30"))
    assert m.variables()[1] == pytest.approx(14500.0, abs=1.0)
    assert m.clock == pytest.approx(14.5)
