"""docs/semantics.md §11 "The machine's limits": the machine file's ``[limits]`` held against a run.
Every expected position, distance and time is worked out by hand in the comments."""

from __future__ import annotations

import pytest

from cncmacro.library.limits_settings import MachineLimits
from cncmacro.library.machine_file import MachineFileError, settings_from_mapping
from running import lines, machine, run

TRAVEL = {"X": (-500.0, 0.0), "Y": (-400.0, 0.0), "Z": (-450.0, 0.0)}
LIMITS = MachineLimits(TRAVEL, feed=5000.0, spindle=8000.0, tools=((1, 24),), offsets=((1, 200),))
G54 = {5221: -300.0, 5222: -200.0, 5223: -100.0}  # G54 X, Y, Z (#5221-#5223)
# the same line run by the run of plain lines (straight_runs.py) and, with a comment, by the general path
PATHS = pytest.mark.parametrize("tail", ["", " (general path)"])


@PATHS
def test_over_travel_on_x_plus_after_a_g54_shift_stops_the_move_at_the_limit(tail):
    m = run(lines("O0001", "G90 G54 G00 X0 Y0", "G01 X250. F1000", f"X320.{tail}", "M30"),
            limits=LIMITS, presets=G54)  # fmt: skip
    # machine X = program X + G54's -300: X320 is machine X20, 20 mm past the + limit 0;
    # the axis stops at machine X0, program X300
    assert m.status == "alarm" and m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (500, 4)
    assert "X+" in m.alarm.message and "machine X20.000, 20.000 mm past" in m.alarm.message
    last = m.planner.moves[-1]
    assert (last.line + 1, last.start[0], last.end[0]) == (4, 250.0, 300.0)
    assert last.seconds == pytest.approx(3.0)  # the 50 mm it did move at F1000: 50 / 1000 * 60


def test_over_travel_on_the_minus_side_is_alarm_501():
    m = run(lines("G90 G54 G00 X0 Y0", "G01 Y-250. F1000", "M30"), limits=LIMITS, presets=G54)
    # machine Y = -250 - 200 = -450, 50 past the - limit -400: it stops at program Y-200
    assert m.alarm is not None and (m.alarm.number, m.alarm.line + 1) == (501, 2)
    assert "Y-" in m.alarm.message and "50.000 mm past" in m.alarm.message
    assert m.planner.moves[-1].end[1] == pytest.approx(-200.0)


def test_a_g53_move_outside_the_travel_is_checked_without_any_work_offset():
    m = run(lines("G90 G00 X0 Y0 Z0", "G53 G00 Z10.", "M30"), limits=LIMITS)
    # G53 names machine coordinates: Z10 is 10 past the + limit 0 whatever the work offsets
    assert m.alarm is not None and (m.alarm.number, m.alarm.line + 1) == (500, 2)
    assert "machine Z10.000, 10.000 mm past" in m.alarm.message
    m = run(lines("G53 G00 Z-460.", "M30"), limits=LIMITS)  # 10 past the - limit -450
    assert m.alarm is not None and m.alarm.number == 501 and "10.000 mm past" in m.alarm.message
    m = run(lines("G53 G00 Z-450.", "M30"), limits=LIMITS)  # on the limit: inside
    assert m.status == "completed"


def test_the_tool_length_offset_counts_in_the_machine_position():
    # G43 H1 with a 100 mm tool: machine Z = program Z + G54 Z (-100) + 100; Z50. is machine Z50
    m = run(lines("G90 G54 G00 X0 Y0", "G43 H1 Z-20.", "Z50.", "M30"), limits=LIMITS,
            presets={**G54, 11001: 100.0})  # fmt: skip
    assert m.alarm is not None and (m.alarm.number, m.alarm.line + 1) == (500, 3)
    assert "machine Z50.000, 50.000 mm past" in m.alarm.message


def test_an_arc_that_bulges_past_the_limit_stops_where_it_crosses_it():
    # G54 X-80: program X80 is machine X0. The clockwise half circle from (50, 0) to (50, -100)
    # about (50, -50), radius 50, reaches program X100 (machine X20) at its right; it crosses X80
    # where cos(a) = (80 - 50) / 50 = 0.6, sin(a) = 0.8: at Y = -50 + 50 * 0.8 = -10
    m = run(lines("G90 G54 G00 X50. Y0", "G02 X50. Y-100. R50. F1000", "M30"), limits=LIMITS,
            presets={5221: -80.0, 5222: 0.0, 5223: 0.0})  # fmt: skip
    assert m.alarm is not None and (m.alarm.number, m.alarm.line + 1) == (500, 2)
    assert "machine X20.000, 20.000 mm past" in m.alarm.message
    end = m.planner.moves[-1].end
    assert end[0] == pytest.approx(80.0, abs=1e-6) and end[1] == pytest.approx(-10.0, abs=1e-6)


def test_without_limits_nothing_is_checked():
    m = run(lines("G90 G54 G00 X0", "G01 X320. F10000 S9000", "T99 M06", "G53 Z10.", "M30"), presets=G54)
    assert m.status == "completed" and m.notes == []
    assert m.planner.moves[1].seconds == pytest.approx(1.92)  # 320 mm at F10000, unclamped: 320 / 10000 * 60


def test_an_axis_whose_work_offset_is_not_given_is_not_guessed():
    # no G54 X given: machine X is unknown, so X320 is not judged
    m = run(lines("G90 G54 G00 X320. Y0", "M30"), limits=LIMITS, presets={5222: 0.0})
    assert m.status == "completed"
    # G54 Y given as 0: Y50 is machine Y50, 50 past the + limit 0
    m = run(lines("G90 G54 G00 X320. Y50.", "M30"), limits=LIMITS, presets={5222: 0.0})
    assert m.alarm is not None and "Y+" in m.alarm.message and "50.000 mm past" in m.alarm.message


@PATHS
def test_a_feed_above_the_maximum_is_clamped_and_the_time_follows(tail):
    m = run(lines("G90 G00 X0", f"G01 X100. F10000{tail}", "X200. F2000", "M30"), limits=LIMITS)
    assert m.status == "completed"
    seconds = [mv.seconds for mv in m.planner.moves]
    # F10000 is clamped at the highest cutting feed 5000: 100 / 5000 * 60 = 1.2 s; F2000 is kept: 100 / 2000 * 60 = 3 s
    assert seconds[1:] == [pytest.approx(1.2), pytest.approx(3.0)]
    assert m.planner.moves[1].feed == 10000.0  # the program's F, as the toolpath shows it


@PATHS
def test_a_spindle_speed_above_the_maximum_is_a_warning_and_clamped_in_the_time(tail):
    m = run(lines("G90 G00 X0", f"S9000 M03{tail}", "G95 G01 X100. F0.1", "M30"), limits=LIMITS)
    assert m.status == "completed"
    # S9000 turns at the top speed 8000: 0.1 mm/rev * 8000 = 800 mm/min; 100 / 800 * 60 = 7.5 s
    assert m.planner.moves[-1].seconds == pytest.approx(7.5)
    assert [(n.line + 1, n.subject) for n in m.notes] == [(2, "spindle-limit")]
    assert "S9000" in m.notes[0].message and "8000" in m.notes[0].message


def test_a_feed_per_revolution_is_clamped_at_the_highest_feed():
    m = run(lines("S8000 M03", "G95 G01 X100. F1.", "M30"), limits=LIMITS)
    # 1 mm/rev * 8000 rev/min = 8000 mm/min, clamped at 5000: 100 / 5000 * 60 = 1.2 s
    assert m.status == "completed" and m.planner.moves[-1].seconds == pytest.approx(1.2)


def test_a_spindle_speed_under_g96_is_no_warning():
    m = run(lines("G96 S9000 M03", "G97 S2000", "M30"), limits=LIMITS, dialect="fanuc-0i-lathe")
    assert m.status == "completed" and m.notes == []


@PATHS
def test_an_unknown_t_is_a_finding(tail):
    m = run(lines(f"T30 M06{tail}", "T12 M06", "T0 M06", "M30"), limits=LIMITS)
    assert m.status == "completed"  # the machine's own alarm: no number, the run goes on
    assert [(n.line + 1, n.subject) for n in m.notes] == [(1, "unknown-tool")]
    assert "T30" in m.notes[0].message and "1-24" in m.notes[0].message


def test_a_lathe_t_names_its_tool_before_its_offset():
    limits = MachineLimits(tools=((1, 8),), offsets=((1, 16),))
    m = run(lines("T0101", "T0912", "M30"), "gsk980tdi", limits=limits)
    assert [(n.line + 1, n.subject) for n in m.notes] == [(2, "unknown-tool")]  # tool 9, offset 12
    m = run(lines("T0117", "M30"), "fanuc-0i-lathe", limits=limits)
    assert m.alarm is not None and (m.alarm.number, m.alarm.line + 1) == (30, 1)  # offset 17: PS0030


def test_an_offset_number_the_control_lacks_is_ps0030():
    m = run(lines("G43 H201 Z10.", "M30"), limits=LIMITS)
    assert m.alarm is not None and (m.alarm.number, m.alarm.line + 1) == (30, 1)
    assert "H201" in m.alarm.message and "1-200" in m.alarm.message
    assert run(lines("G41 D200 X1.", "G40 D0", "M30"), limits=LIMITS).status == "completed"


def test_gsk980tdi_shows_its_over_travel_without_a_number():
    m = run(lines("G53 G00 X10.", "M30"), "gsk980tdi", limits=MachineLimits({"X": (-300.0, 0.0)}))
    assert m.alarm is not None and m.alarm.number == 500 and m.alarm.shown is None


# ---------------------------------------------------------------- the machine file's table
def test_limits_are_read_from_the_machine_file():
    table = {"travel": {"x": [-500, 0]}, "feed": 10000, "rapid": 30000, "spindle": 8000, "tools": [1, 24],
             "offsets": [[1, 200], [1001, 1010]]}  # fmt: skip
    s = settings_from_mapping({"limits": table})
    assert s.limits == MachineLimits({"X": (-500.0, 0.0)}, 10000.0, 8000.0, ((1, 24),), ((1, 200), (1001, 1010)))
    # the rapid rate and the top spindle speed are the timing's: every axis of the profile at 30000
    assert s.timing["rapid"]["X"] == 30000.0 and s.timing["rapid_default"] == 30000.0
    assert s.timing["max_spindle_speed"] == 8000.0


@pytest.mark.parametrize(
    ("table", "key", "words"),
    [
        ({"travel": {"X": [0, -500]}}, "limits.travel.X", "lowest 0 above its highest -500"),
        ({"travel": {"X": 5}}, "limits.travel.X", "[lowest, highest]"),
        ({"travel": {"W": [0, 1]}}, "limits.travel.W", "is not an axis of the profile (X, Y, Z"),
        ({"feed": -1}, "limits.feed", "above 0"),
        ({"tools": [24]}, "limits.tools", "[first, last]"),
        ({"speed": 1}, "limits.speed", "is not a limit of the machine"),
        ({"rapid": {"X": 0}}, "limits.rapid", "above 0"),
        # finite, but beyond any machine (toml_numbers.TOPS)
        ({"feed": 1e300}, "limits.feed", "at most 1000000"),
        ({"spindle": 1e12}, "limits.spindle", "at most 1000000 (rev/min)"),
        ({"travel": {"X": [-1e300, 0]}}, "limits.travel.X", "[lowest, highest]"),
    ],
)
def test_a_bad_limit_is_an_error_naming_its_key(table, key, words):
    with pytest.raises(MachineFileError) as e:
        settings_from_mapping({"limits": table})
    assert e.value.key == key and words in str(e.value)


def test_the_rapid_rate_and_top_speed_are_given_once():
    for timing, limits, key in (({"rapid": {"X": 1}}, {"rapid": 2}, "limits.rapid"),
                                ({"max_spindle_speed": 1}, {"spindle": 2}, "limits.spindle")):  # fmt: skip
        with pytest.raises(MachineFileError) as e:
            settings_from_mapping({"timing": timing, "limits": limits})
        assert e.value.key == key and "same fact" in str(e.value)


def test_a_drilling_cycle_whose_bottom_is_past_the_travel_alarms_on_its_block():
    # G54 Z-100: the bottom Z-400. is machine Z-500, 50 past the - limit -450
    m = run(lines("G90 G54 G00 X0 Y0 Z50.", "G81 X10. Y10. Z-400. R2. F100", "M30"), limits=LIMITS, presets=G54)
    assert m.alarm is not None and (m.alarm.number, m.alarm.line + 1) == (501, 2)
    assert "Z-" in m.alarm.message and "machine Z-500.000, 50.000 mm past" in m.alarm.message


def test_a_roughing_cycle_pass_past_the_travel_alarms_in_a_check_run_too():
    # fanuc-0i-lathe, Z travel [-15, 10], the work offsets given as 0: the G71 passes cut to the
    # shape's Z-20. plus the W0.1 allowance, Z-19.9, 4.9 past the - limit; the alarm is on the
    # shape's last block N20, where the run has read the shape and plans the passes
    text = lines("G00 X42. Z2.", "G71 U1. R0.5", "G71 P10 Q20 U0.2 W0.1 F0.2", "N10 G00 X30.", "G01 Z-20.",
                 "N20 X42.", "M30")  # fmt: skip
    limits = MachineLimits({"Z": (-15.0, 10.0)})
    for keep in (True, False):  # cncmacro run, and an analysis run, which keeps no moves
        m = machine(text, "fanuc-0i-lathe", limits=limits, presets={5221: 0.0, 5222: 0.0, 5223: 0.0})
        m.planner.record_moves = keep
        m.run()
        assert m.alarm is not None and (m.alarm.number, m.alarm.line + 1) == (501, 6)
        assert "4.900 mm past" in m.alarm.message


def test_g52_shifts_the_program_position_without_moving_and_the_travel_follows():
    # G54 X-300; G52 X310.: program X15. is work X325., machine X25., 25 past the + limit
    m = run(lines("G90 G54 G00 X0 Y0", "G52 X310.", "#100=#5001", "#101=#5021", "G00 X15.", "M30"),
            limits=LIMITS, presets=G54)  # fmt: skip
    assert [mv.line + 1 for mv in m.planner.moves] == [1, 5]  # G52 itself moves nothing
    assert (m.C[100], m.C[101]) == (-310.0, -300.0)  # program X0 - 310; the machine position stays
    assert m.alarm is not None and (m.alarm.number, m.alarm.line + 1) == (500, 5)
    assert "machine X25.000, 25.000 mm past" in m.alarm.message
    m = run(lines("G52 X310.", "G52 X0", "#100=#5001", "M30"))
    assert m.C[100] == 0.0  # G52 X0 cancels it


def test_a_lathe_cycles_d_is_no_offset_number():
    # gsk980tdi's G75 takes D (the relief at the end of a cut) in increments: D500 is no offset
    limits = MachineLimits(offsets=((1, 32),))
    m = run(lines("G00 X50. Z2.", "G75 R0.5", "G75 X30. Z-10. P2000 Q3000 D500 F0.1", "M30"), "gsk980tdi",
            limits=limits)  # fmt: skip
    assert m.status == "completed", m.alarm


def test_a_roughing_cycles_passes_are_timed_at_the_clamped_feed_whether_moves_are_kept_or_not():
    # the same G71 at F10000 per minute on a machine whose highest feed is 5000 takes as long as at
    # F5000 on one without [limits], in a run that keeps its moves and in one that does not
    def clock(feed: str, keep: bool, **kw: object) -> float:
        text = lines("G98 G00 X42. Z2.", "G71 U1. R0.5", f"G71 P10 Q20 U0.2 W0.1 {feed}", "N10 G00 X30.",
                     "G01 Z-20.", "N20 X42.", "M30")  # fmt: skip
        m = machine(text, "fanuc-0i-lathe", **kw)  # type: ignore[arg-type]
        m.planner.record_moves = keep
        m.run()
        assert m.status == "completed"
        return m.planner.clock

    for keep in (True, False):
        clamped = clock("F10000.", keep, limits=MachineLimits(feed=5000.0))
        assert clamped == pytest.approx(clock("F5000.", keep)) and clamped > clock("F10000.", keep)


def test_a_lathe_t_naming_an_offset_the_profiles_table_lacks_is_ps0030_without_a_limits_table():
    # GSK980TDi §3.28.1 item 2: offsets 1-32 (#2001-#2032, #2701-#2732...); T0133 names offset 33
    # (the last two digits), which the control does not have: the alarm stops the run at line 2,
    # before the move; T0132 is the last one it has. It ran silently before.
    m = run(lines("T0132", "T0133", "G00 X50 Z5", "M30"), "gsk980tdi")
    assert m.alarm is not None and (m.alarm.number, m.alarm.line + 1) == (30, 2)
    assert m.alarm.shown is None  # the GSK manual at hand gives no number for it
    assert "T133" in m.alarm.message and "offset number 33" in m.alarm.message and "1-32" in m.alarm.message
    assert not m.planner.moves
    # the haas-lathe table holds 50 offsets (#2001-#2050 X geometry, #2051- Y geometry): T0151 is 51
    m = run(lines("T0150", "T0151", "M30"), "haas-lathe")
    assert m.alarm is not None and (m.alarm.number, m.alarm.line + 1) == (30, 2)
    # the 0i-TF's table holds 400 (#15001-#15400): any two-digit offset of a T is one of them
    assert run(lines("T0199", "G00 X50. Z5.", "M30"), "fanuc-0i-lathe").status == "completed"
    # a machine file's [limits] offsets, where it gives them, is the control's count
    m = run(lines("T0133", "M30"), "gsk980tdi", limits=MachineLimits(offsets=((1, 40),)))
    assert m.status == "completed"
    m = run(lines("T0133", "M30"), "gsk980tdi", limits=MachineLimits(tools=((1, 8),)))  # no offsets: the table's
    assert m.alarm is not None and m.alarm.number == 30
