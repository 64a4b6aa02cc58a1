"""docs/semantics.md §8 "The simulated machine": modal state and codes in #4001.., positions in
#5001.., work and tool offsets, G10, G31, the clock, and the persistent variables; plus the
seed 000 tool-wear pair O0100 / O9580 run with presets."""

from __future__ import annotations

from pathlib import Path

import pytest

from cncmacro.library.persistence import load_persistent, save_persistent
from cncmacro.library.skip_model import planes_model
from running import final, lines, run

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def test_modal_groups_and_codes_are_readable():
    program = lines(
        "G91 G01 X1 F250 S1200 M03 T5",
        "#100=#4001", "#101=#4003", "#102=#4109", "#103=#4119", "#104=#4113", "#105=#4120",
        "N77 #106=#4114",
        "G90 G00 X0",
        "#107=#4003", "#108=#4001", "#109=#4115",
        "M30",
    )  # fmt: skip
    v = final(lines("O1234", program))
    assert (v[100], v[101], v[102], v[103], v[104], v[105]) == (1, 91, 250, 1200, 3, 5)
    assert v[106] == 77 and v[107] == 90 and v[108] == 0 and v[109] == 1234


def test_gsk_t_code_and_modal_groups():
    v = final(lines("G99 G01 X10 Z5 F0.2", "T0101", "#100=#4120", "#101=#4005", "#102=#4001", "M30"), "gsk980tdi")
    assert v[100] == 101 and v[101] == 99 and v[102] == 1


def test_positions_absolute_incremental_and_lathe_u_w():
    m = run(lines("G90 G00 X10 Y20 Z30", "G91 G01 X5 Y-5 F100", "#100=#5001", "#101=#5002", "#102=#5003", "M30"))
    assert (m.C[100], m.C[101], m.C[102]) == (15, 15, 30)
    m = run(lines("G00 X40 Z10", "G01 U-10 W-5 F0.2", "#100=#5001", "#101=#5003", "M30"), "gsk980tdi")
    assert (m.C[100], m.C[101]) == (30, 5)  # X is a diameter; U and W move incrementally


def test_moves_are_recorded_with_line_mode_from_and_to():
    m = run(lines("G90 G00 X10", "G01 Y5 F100", "G02 X20 Y15 R10", "M30"))
    assert [(mv.line, mv.mode, mv.start[:2], mv.end[:2]) for mv in m.planner.moves] == [
        (0, 0.0, (0.0, 0.0), (10.0, 0.0)),
        (1, 1.0, (10.0, 0.0), (10.0, 5.0)),
        (2, 2.0, (10.0, 5.0), (20.0, 15.0)),
    ]


def test_8_machine_a_motion_code_cancels_a_drilling_cycle_on_fanuc():
    """Group 01 (G00-G03) cancels a group 09 drilling cycle: the later moves drill nothing."""
    for text in ("G00 X30. Y10.", "G00 X30. Y10. (rapid)"):  # the plain-line path and the general path
        m = run(lines("O0001", "G90 G99 G81 X10. Y10. Z-5. R2. F100.", text, "G01 X40. F200.", "M30"))
        assert [move.mode for move in m.planner.moves if move.line >= 2] == [0.0, 1.0]
        assert m.planner.moves[-1].end[:3] == (40.0, 10.0, 2.0)
        assert m.read(4009) == 80.0


def test_work_offsets_shift_the_machine_position():
    presets = {5221: 100.0, 5222: 50.0, 5241: -10.0}
    m = run(lines("G54 G90 G00 X1 Y2", "#100=#5021", "#101=#5022", "G55 X1", "#102=#5021", "#103=#5001", "M30"),
            presets=presets)  # fmt: skip
    assert (m.C[100], m.C[101], m.C[102], m.C[103]) == (101, 52, -9, 1)


def test_fanuc_work_offset_aliases():
    v = final(lines("#2501=12.5", "#100=#5221", "#5242=3", "#101=#2602", "M30"))
    assert v[100] == 12.5 and v[101] == 3


def test_g10_l2_writes_work_offsets():
    v = final(lines("G90 G10 L2 P1 X20 Y30", "#100=#5221", "#101=#5222", "G91 G10 L2 P1 X5", "#102=#5221", "M30"))
    assert (v[100], v[101], v[102]) == (20, 30, 25)


def test_g10_writes_tool_offsets():
    v = final(lines("G90 G10 L10 P3 R50", "G10 L11 P3 R0.2", "#100=#11003", "#101=#2003", "#102=#2203", "M30"))
    assert (v[100], v[101], v[102]) == (50, 0.2, 50)
    v = final(lines("G10 P2 X0.5 Z-0.1", "G10 P10002 X100", "#100=#2002", "#101=#2102", "#102=#2702", "M30"),
              "gsk980tdi")  # fmt: skip
    assert (v[100], v[101], v[102]) == (0.5, -0.1, 100)


def test_lathe_tool_offsets_enter_the_machine_position():
    m = run(lines("T0303", "G00 X10 Z5", "#100=#5021", "#101=#5023", "#102=#5001", "M30"), "gsk980tdi",
            presets={2703: 1.5, 2003: 0.25, 2803: -2.0})  # fmt: skip
    assert (m.C[100], m.C[101], m.C[102]) == (11.75, 3.0, 10.0)


def test_g31_skip_position():
    m = run(lines("G90 G00 Z10", "G31 Z-20 F100", "#100=#5063", "#101=#5003", "M30"), skip=planes_model({"Z": -12.5}))
    assert m.C[100] == -12.5 and m.C[101] == -12.5
    m = run(lines("G90 G00 Z10", "G31 Z-20 F100", "#100=#5063", "M30"))
    assert m.C[100] == -20  # no signal: the programmed end point


def test_g92_sets_the_coordinate_system():
    m = run(lines("G90 G00 X50", "G92 X0", "#100=#5001", "#101=#5021", "G00 X10", "#102=#5021", "M30"))
    assert (m.C[100], m.C[101], m.C[102]) == (0, 50, 60)


def test_clock_and_date_are_deterministic():
    program = lines("#100=#3011", "#101=#3012", "G01 X1000 F6000", "#102=#3001", "G04 P1500", "#103=#3001", "M30")
    v = final(program)
    assert v[100] == 20261122 and v[101] == 80000
    assert v[102] == pytest.approx(10000.0) and v[103] == pytest.approx(11500.0)  # ms: 10 s move, 1.5 s dwell


def test_8_machine_the_millisecond_timer_3001_counts_whole_milliseconds_and_wraps_at_2147483648():
    # seed 003 §4.5 (the 0i's #3001 row): a timer that counts in 1 ms steps and returns to 0 at
    # 2147483648 ms. G91 G01 X0.123 F6000: 0.123 mm at 6000 mm/min = 100 mm/s is 1.23 ms, so
    # after 1, 2, 3 such moves 1.23, 2.46, 3.69 ms have passed: 1, 2, 3 whole steps (it read
    # 1.23, 2.46, 3.69); 2147483647 + a 2 ms dwell = 2147483649, past 2^31: 1
    program = lines("#3001=0", "G91 G01 X0.123 F6000", "#101=#3001", "X0.123", "#102=#3001", "X0.123", "#103=#3001",
                    "#3001=2147483647", "#104=#3001", "G04 X0.002", "#105=#3001", "M30")  # fmt: skip
    v = final(program)
    assert (v[101], v[102], v[103], v[104], v[105]) == (1, 2, 3, 2147483647, 1)
    # the same on the 30i, which takes the 0i's row
    assert final(program, "fanuc-30i")[103] == 3


def test_parts_counters():
    v = final(lines("#3901=#3901+1", "#100=#3901", "M30"), presets={3901: 41})
    assert v[100] == 42 and v[3901] == 42


def test_persistent_variables_are_written_atomically_and_read_back(tmp_path):
    path = tmp_path / "vars.json"
    save_persistent(path, {500: 1.5, 999: -2.0})
    assert load_persistent(path) == {500: 1.5, 999: -2.0}
    assert [p.name for p in tmp_path.iterdir()] == ["vars.json"]  # no temporary file left behind


def test_seed_000_tool_wear_pair(tmp_path):
    """O0100 calls O9580 after 100 parts: the X/Z wear of the tool's offset drops by 0.01."""
    for name in ("O0100.nc", "O9580.nc"):
        (tmp_path / name).write_bytes((EXAMPLES / "gsk980tdi" / name).read_bytes())
    text = (tmp_path / "O0100.nc").read_text(encoding="utf-8")
    presets = {100: 100.0, 2001: 0.5, 2101: 0.2, 2002: 0.1, 2102: 0.0}
    v = final(text, "gsk980tdi", folder=tmp_path, presets=presets)
    assert v[2001] == pytest.approx(0.49) and v[2101] == pytest.approx(0.19)
    assert v[2002] == pytest.approx(0.09) and v[2102] == pytest.approx(-0.01)
    assert v[101] == 2 and v[100] == 101
    # part 99 -> 100: no compensation, and the counter goes back to 0
    v = final(text, "gsk980tdi", folder=tmp_path, presets={100: 99.0, 2001: 0.5})
    assert v[2001] == 0.5 and v[100] == 0
