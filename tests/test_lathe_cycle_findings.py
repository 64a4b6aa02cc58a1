"""docs/semantics.md §10.5 "Findings of the cycles": what a lathe control refuses in its multiple
repetitive cycles G70–G76, found from the text (``cncmacro check``'s static analysis) and, where a
value comes from a variable, by running. Every finding on both lathe profiles; none on a mill's
own G73/G74/G76 drilling cycles."""

from __future__ import annotations

from pathlib import Path

import pytest

from analysis_helpers import analyse_files
from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.library.machine_file import MachineFileError, MachineSettings, settings_from_mapping
from running import alarm, run
from static_helpers import at, check, coded, lines

LATHES = ["gsk980tdi", "fanuc-0i-lathe"]


def shape(*body: str, cycle: str = "G71 P10 Q20 U0.2 W0.1 F0.2", first: str = "G71 U1. R0.5",
          start: str = "G00 X42. Z2.") -> str:  # fmt: skip
    """A program: go to the start point, the cycle's two blocks, the shape N10…N20, the end."""
    return lines("O0001", start, first, cycle, *body, "M30")


TURNING = ("N10 G00 X20.", "G01 Z-10.", "X30. Z-20.", "N20 X42.")


def findings(text: str, dialect: str, code: str, **kw: object) -> list[tuple[int, int, int, str]]:
    return [at(d) for d in coded(check(text, dialect, **kw), code)]  # type: ignore[arg-type]


# ---------------------------------------------------------------- a good program is clean
@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_a_plain_turning_cycle_has_no_finding(dialect: str) -> None:
    text = shape(*TURNING) + "G70 P10 Q20\n"
    found = [d for d in check(text, dialect) if d.code.startswith("cycle") or d.code == "duplicate-label"]
    assert found == []
    assert run(text, dialect).status == "completed"


@pytest.mark.parametrize(("dialect", "code"), [("fanuc", "G73"), ("fanuc", "G74"), ("fanuc", "G76"),
                                               ("haas", "G73"), ("fanuc-30i", "G76")])  # fmt: skip
def test_10_5_a_mills_drilling_cycles_get_no_lathe_finding(dialect: str, code: str) -> None:
    # G73 peck drilling, G74 left-hand tapping, G76 fine boring: Q and P mean something else there
    text = lines("O0001", "G90 G00 X0 Y0 Z10.", f"{code} X10. Y10. Z-5. R2. Q0 P0 F100.", "G80", "M30")
    assert [d for d in check(text, dialect) if d.code.startswith("cycle")] == []


# ---------------------------------------------------------------- PS0061
@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_g70_to_g73_without_p_or_q_is_ps0061(dialect: str) -> None:
    text = shape(*TURNING, cycle="G71 P10 U0.2 W0.1 F0.2") + "G70 Q20\n"
    assert findings(text, dialect, "cycle-block") == [(4, 0, 22, "error"), (10, 0, 7, "error")]
    assert "(alarm 61)" in coded(check(text, dialect), "cycle-block")[0].message


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_a_g71_block_with_u_and_r_only_is_a_legal_first_block(dialect: str) -> None:
    assert findings(shape(*TURNING), dialect, "cycle-block") == []


# ---------------------------------------------------------------- PS0062, PS0321
@pytest.mark.parametrize("dialect", LATHES)
@pytest.mark.parametrize(("first", "cycle", "column"), [("G71 U0 R0.5", "G71", 4), ("G72 W-1. R0.5", "G72", 4)])
def test_10_5_a_depth_of_cut_not_above_zero_is_ps0062(dialect: str, first: str, cycle: str, column: int) -> None:
    text = shape(*TURNING, first=first, cycle=f"{cycle} P10 Q20 U0.2 W0.1 F0.2")
    assert [f[:2] for f in findings(text, dialect, "cycle-block")] == [(3, column)]


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_a_depth_of_cut_from_a_variable_is_ps0062_at_run_time(dialect: str) -> None:
    # #1 = 0.5 - 0.5 = 0: the depth U#1 is 0, known only when the block runs
    text = lines("O0001", "#1=0.5-0.5", "G00 X42. Z2.", "G71 U#1 R0.5", "G71 P10 Q20 F0.2", *TURNING, "M30")
    assert findings(text, dialect, "cycle-block") == []
    assert alarm(text, dialect) == (62, 4)


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_a_g73_count_not_above_zero_is_ps0321(dialect: str) -> None:
    text = shape(*TURNING, first="G73 U3. W0 R0", cycle="G73 P10 Q20 U0.2 W0.1 F0.2")
    assert [f[:2] for f in findings(text, dialect, "cycle-block")] == [(3, 11)]
    assert "(alarm 321)" in coded(check(text, dialect), "cycle-block")[0].message


# ---------------------------------------------------------------- PS0063 and reused labels
@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_a_shape_label_not_in_the_program_is_ps0063(dialect: str) -> None:
    text = shape(*TURNING, cycle="G71 P10 Q30 U0.2 F0.2")
    found = coded(check(text, dialect), "cycle-shape")
    assert [at(d) for d in found] == [(4, 8, 11, "error")]  # the Q30 word
    assert "N30" in found[0].message and "(alarm 63)" in found[0].message
    assert alarm(text, dialect) == (63, 4)


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_a_shape_label_used_twice_is_a_duplicate_label_warning(dialect: str) -> None:
    text = shape(*TURNING) + lines("N10 G00 X50.", "M30")
    assert findings(text, dialect, "duplicate-label") == [(4, 4, 7, "warning")]


# ---------------------------------------------------------------- PS0064, PS0329, type II
Z_BACK = ("N10 G00 X20.", "G01 Z-10.", "X30. Z-5.", "N20 X42.")  # Z goes -10 then back to -5


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_a_shape_turning_back_along_z_is_a_ps0064_warning_by_default(dialect: str) -> None:
    text = shape(*Z_BACK)
    assert findings(text, dialect, "cycle-shape") == [(4, 0, 26, "warning")]
    assert "(alarm 64)" in coded(check(text, dialect), "cycle-shape")[0].message
    assert run(text, dialect).status == "completed"  # the control runs it where its check is off


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_the_machine_file_turns_the_monotone_check_on(dialect: str) -> None:
    text = shape(*Z_BACK)
    on = MachineSettings(shape_monotone_check=True)
    assert findings(text, dialect, "cycle-shape", settings=on) == [(8, 4, 8, "error")]  # at N20, where the run stops
    assert alarm(text, dialect, shape_monotone_check=True) == (64, 8)


def test_10_5_gsk_k1_turns_the_monotone_check_on() -> None:
    text = shape(*Z_BACK, cycle="G71 P10 Q20 U0.2 W0.1 F0.2 K1")
    assert findings(text, "gsk980tdi", "cycle-shape") == [(8, 4, 8, "error")]
    assert alarm(text, "gsk980tdi") == (64, 8)


def test_10_5_k1_is_no_switch_on_fanuc() -> None:
    text = shape(*Z_BACK, cycle="G71 P10 Q20 U0.2 W0.1 F0.2 K1")
    assert [f[3] for f in findings(text, "fanuc-0i-lathe", "cycle-shape")] == ["warning"]


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_a_type_i_pocket_is_a_ps0329_warning_and_type_ii_is_legal(dialect: str) -> None:
    # X 20 -> 30 -> 25 -> 42: a pocket; the first block names X only (type I), then X and W0 (type II)
    body = ("G01 Z-10.", "X30. Z-20.", "X25. Z-30.", "N20 X42. Z-35.")
    type_one = shape("N10 G00 X20.", *body)
    found = coded(check(type_one, dialect), "cycle-shape")
    assert [at(d) for d in found] == [(4, 0, 26, "warning")] and "(alarm 329)" in found[0].message
    assert findings(shape("N10 G00 X20. W0", *body), dialect, "cycle-shape") == []
    on = MachineSettings(shape_monotone_check=True)
    assert findings(shape("N10 G00 X20. W0", *body), dialect, "cycle-shape", settings=on) == []
    assert alarm(type_one, dialect, shape_monotone_check=True) == (329, 9)
    assert run(shape("N10 G00 X20. W0", *body), dialect, shape_monotone_check=True).status == "completed"


def test_10_5_more_pockets_than_the_profile_takes_is_a_warning() -> None:
    # FANUC takes 10 pockets, GSK 20: 11 pockets of X 20 -> 30 -> 25 each
    pockets = [f"X30. Z-{10 * i + 5}." if j == 0 else f"X25. Z-{10 * i + 10}." for i in range(11) for j in range(2)]
    text = shape("N10 G00 X20. W0", "G01 Z-1.", *pockets, "N20 X42. Z-200.")
    assert [f[3] for f in findings(text, "fanuc-0i-lathe", "cycle-shape")] == ["warning"]
    assert findings(text, "gsk980tdi", "cycle-shape") == []


# ---------------------------------------------------------------- PS0065, PS0069, PS0322, PS0325
@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_a_shape_starting_with_an_arc_is_ps0065(dialect: str) -> None:
    text = shape("N10 G02 X20. Z0 R5.", *TURNING[1:])
    found = coded(check(text, dialect), "cycle-shape")
    assert [at(d)[0] for d in found] == [8] and "(alarm 65)" in found[0].message
    assert alarm(text, dialect) == (65, 8)


@pytest.mark.parametrize(("dialect", "severity"), [("fanuc-0i-lathe", "error"), ("gsk980tdi", "warning")])
def test_10_5_a_shape_ending_in_a_corner_r_is_ps0069(dialect: str, severity: str) -> None:
    text = shape(*TURNING[:-1], "N20 X42. ,R1.")
    assert findings(text, dialect, "cycle-shape") == [(8, 9, 13, severity)]


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_a_shape_going_past_the_start_point_is_a_ps0322_warning(dialect: str) -> None:
    # start X42, the shape's last block goes out to X44
    text = shape(*TURNING[:-1], "N20 X44.")
    found = coded(check(text, dialect), "cycle-shape")
    assert [at(d) for d in found] == [(4, 0, 26, "warning")] and "(alarm 322)" in found[0].message


@pytest.mark.parametrize("dialect", LATHES)
@pytest.mark.parametrize("command", ["M98 P100", "M99", "G65 P100"])
def test_10_5_a_call_or_return_in_the_shape_is_ps0325(dialect: str, command: str) -> None:
    text = shape(*TURNING[:2], command, *TURNING[2:])
    assert [f[0::3] for f in findings(text, dialect, "cycle-shape")] == [(7, "error")]
    if command == "M99":  # (a call looks for its program first: O0100 is not there)
        assert alarm(text, dialect) == (325, 7)


def test_10_5_a_g_code_outside_gsks_list_in_the_shape_is_a_warning() -> None:
    text = shape(*TURNING[:2], "G50 S2000", *TURNING[2:])
    assert findings(text, "gsk980tdi", "cycle-shape") == [(7, 0, 3, "warning")]
    assert findings(text, "fanuc-0i-lathe", "cycle-shape") == []


def test_10_5_more_than_200_shape_blocks_on_gsk_is_a_warning() -> None:
    body = [f"X{20 + i * 0.01:.2f} Z-{i + 1}." for i in range(200)]
    text = shape("N10 G00 X20.", "G01", *body, "N20 X42.")
    assert [f[0::3] for f in findings(text, "gsk980tdi", "cycle-shape")] == [(4, "warning")]
    assert findings(text, "fanuc-0i-lathe", "cycle-shape") == []


# ---------------------------------------------------------------- G74/G75: PS0318–PS0320
@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_grooving_steps_and_relief(dialect: str) -> None:
    text = lines("O0001", "G00 X42. Z2.", "G75 R0.5",
                 "G75 X20. Z-20. P-500 Q1000 F0.05",  # a negative step: PS0320
                 "G75 X20. Z-20. P500 Q0 F0.05",  # Q0 while Z travels 22: PS0319
                 "G75 X20. Z2. P500 Q0 F0.05",  # Q0 and no travel along Z: fine
                 "G74 X20. Z-20. P1000 Q2000 R-1. F0.05",  # a negative relief: PS0318, a warning
                 "M30")  # fmt: skip
    found = coded(check(text, dialect), "cycle-block")
    assert [(at(d)[0], at(d)[3], d.message.split("(alarm ")[1]) for d in found] == [
        (4, "error", "320)"), (5, "error", "319)"), (7, "warning", "318)")]  # fmt: skip


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_a_grooving_end_point_away_along_x_without_its_step_p_is_a_warning(tmp_path: Path, dialect: str) -> None:
    # G74 from X42 to X20 (22 on the diameter) with no P: neither manual gives P a default (GSK §3.23.5
    # "0＜Δi"), so a warning on the G74 line, from the text and from the run, shown once; it was nothing.
    # The run cuts its columns at X42 and at X20 and goes on. A G74 with neither X nor P (drilling) is fine.
    text = lines("O0001", "T0101", "G00 X42. Z2.", "G74 R0.5", "G74 X20. Z-20. Q2000 F0.05", "G74 Z-20. Q2000 F0.05",
                 "M30")  # fmt: skip
    assert findings(text, dialect, "cycle-block") == [(5, 0, 26, "warning")]
    found = [d for d in analyse_files(tmp_path, {"O0001.nc": text}, dialect) if d.code == "cycle-block"]
    assert [(d.line + 1, d.severity) for d in found] == [(5, "warning")]
    assert "the step P is left out" in found[0].message
    assert run(text, dialect).status == "completed"


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_a_grooving_step_from_a_variable_is_found_at_run_time(dialect: str) -> None:
    text = lines("O0001", "#2=-500", "G00 X42. Z2.", "G75 R0.5", "G75 X20. Z-20. P#2 Q1000 F0.05", "M30")
    assert findings(text, dialect, "cycle-block") == []
    assert alarm(text, dialect) == (320, 5)


# ---------------------------------------------------------------- G76: PS0315–PS0317, PS0050
def test_10_5_a_g76_tool_angle_outside_fanucs_list_is_ps0315_and_any_angle_on_gsk() -> None:
    text = lines("O0001", "G00 X32. Z5.", "G76 P020045 Q100 R0.05", "G76 X27.4 Z-30. P1300 Q400 F2.", "M30")
    assert findings(text, "fanuc-0i-lathe", "cycle-block") == [(3, 4, 11, "error")]
    assert findings(text, "gsk980tdi", "cycle-block") == []


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_g76_depths(dialect: str) -> None:
    text = lines("O0001", "G00 X32. Z5.", "G76 P020060 Q1500 R0.05",
                 "G76 X27.4 Z-30. P1300 Q400 F2.",  # Q1500 (minimum) > P1300 (height): PS0316
                 "G76 X27.4 Z-30. P0 Q400 F2.",  # the height 0: PS0317
                 "G76 X27.4 Z-30. P1600 F2.",  # no first depth: PS0317
                 "M30")  # fmt: skip
    found = coded(check(text, dialect), "cycle-block")
    assert [(at(d)[0], d.message.split("(alarm ")[1]) for d in found] == [(4, "316)"), (5, "317)"), (6, "317)")]


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_a_g76_height_from_a_variable_is_found_at_run_time(dialect: str) -> None:
    text = lines("O0001", "#3=0", "G00 X32. Z5.", "G76 P020060 Q100 R0.05", "G76 X27.4 Z-30. P#3 Q400 F2.", "M30")
    assert findings(text, dialect, "cycle-block") == []
    assert alarm(text, dialect) == (317, 5)


@pytest.mark.parametrize(("dialect", "severity"), [("fanuc-0i-lathe", "error"), ("gsk980tdi", "warning")])
def test_10_5_a_chamfer_in_a_thread_block_is_ps0050(dialect: str, severity: str) -> None:
    text = lines("O0001", "G00 X20. Z2.", "G32 Z-10. F1.5 ,C1.", "M30")
    assert findings(text, dialect, "cycle-block") == [(3, 15, 19, severity)]


# ---------------------------------------------------------------- the run's warnings and the machine file
@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_a_warning_found_by_running_is_shown_once(dialect: str, tmp_path: Path) -> None:
    # the shape's Z comes from #1 = -5: only the run sees it turn back; the analysis shows it once
    text = lines("O0001", "#1=-5.", "G00 X42. Z2.", "G71 U1. R0.5", "G71 P10 Q20 U0.2 W0.1 F0.2",
                 "N10 G00 X20.", "G01 Z-10.", "X30. Z#1", "N20 X42.", "M30")  # fmt: skip
    assert findings(text, dialect, "cycle-shape") == []
    found = [d for d in analyse_files(tmp_path, {"MAIN.nc": text}, dialect) if d.code == "cycle-shape"]
    assert [(d.line + 1, d.severity) for d in found] == [(5, "warning")]


def test_10_5_the_machine_file_key_must_be_true_or_false() -> None:
    assert settings_from_mapping({"shape_monotone_check": True}).shape_monotone_check
    with pytest.raises(MachineFileError, match="shape_monotone_check"):
        settings_from_mapping({"shape_monotone_check": "yes"})


def test_10_5_fanuc_15s_one_block_g76_is_not_judged_by_the_two_block_rules() -> None:
    # G76 X Z I K D F A: K is the height and D the first depth there, P the cutting method
    text = lines("O0001", "G00 X32. Z5.", "G76 X27.4 Z-30. K1300 D400 F2. A60 P1", "M30")
    assert findings(text, "fanuc-0i-lathe", "cycle-block") == []


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_g76_depths_in_different_units_are_not_compared(dialect: str) -> None:
    # Q50 is 0.050 mm (increments), P0.975 is 0.975 mm: 50 > 0.975 says nothing
    text = lines("O0001", "G00 X32. Z5.", "G76 P010060 Q50 R0.05", "G76 X27.4 Z-30. P0.975 Q0.1 F1.5", "M30")
    assert findings(text, dialect, "cycle-block") == []


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_an_error_of_the_text_and_of_the_run_is_shown_once(dialect: str, tmp_path: Path) -> None:
    # the depth U0 (cycle-block, line 3) and, with the check on, Z turning back (cycle-shape, at N20: line 8)
    depth = shape(*TURNING, first="G71 U0 R0.5")
    found = [d for d in analyse_files(tmp_path, {"A.nc": depth}, dialect) if d.code.startswith("cycle")]
    assert [(d.line + 1, d.code, d.severity) for d in found] == [(3, "cycle-block", "error")]
    text = shape(*Z_BACK)
    ws = WorkspaceAnalysis(settings=MachineSettings(shape_monotone_check=True), dialect=dialect)
    path = tmp_path / "B.nc"
    path.write_text(text, encoding="utf-8")
    ws.open(str(path), text, 1)
    result = ws.analyze(str(path))
    assert result is not None
    found = [d for ds in result.diagnostics.values() for d in ds if d.code.startswith("cycle")]
    assert [(d.line + 1, d.code, d.severity) for d in found] == [(8, "cycle-shape", "error")]


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_g72s_shape_turning_back_along_x_is_ps0329_and_along_z_ps0064(dialect: str) -> None:
    # FANUC's alarms name the plane's axes: PS0064 the first (Z), PS0329 the second (X), whichever cycle
    # G72 faces along X: X 42 -> 30 -> 35 turns back (PS0329); type I, Z -20 -> -10 -> -15 turns back (PS0064)
    x_back = shape("N500 G00 Z-20.", "G01 X30.", "X35. Z-10.", "N600 Z2.", first="G72 W1. R0.5",
                   cycle="G72 P500 Q600 U0.2 W0.1 F0.2")  # fmt: skip
    found = coded(check(x_back, dialect), "cycle-shape")
    assert [at(d)[3] for d in found] == ["warning"] and "(alarm 329)" in found[0].message
    z_back = shape("N500 G00 Z-20.", "G01 X30. Z-10.", "X20. Z-15.", "N600 X0 Z2.", first="G72 W1. R0.5",
                   cycle="G72 P500 Q600 U0.2 W0.1 F0.2")  # fmt: skip
    found = coded(check(z_back, dialect), "cycle-shape")
    assert [at(d)[3] for d in found] == ["warning"] and "(alarm 64)" in found[0].message


RUN_CASES = [
    # (what, program lines after "O0001", alarm, 1-based line): each value comes from #1, so only the run sees it
    ("G73 passes", ["#1=0", "G00 X45. Z2.", "G73 U3. W0 R#1", "G73 P10 Q20 U0.2 F0.2", *TURNING], 321, 4),
    ("G76 minimum depth", ["#1=1500", "G00 X32. Z5.", "G76 P010060 Q#1 R0.05", "G76 X27.4 Z-30. P1300 Q400 F2."],
     316, 5),
    ("G75 zero step", ["#1=0", "G00 X42. Z2.", "G75 R0.5", "G75 X20. Z-20. P500 Q#1 F0.05"], 319, 5),
    ("G76 first depth", ["#1=-0.4", "G00 X32. Z5.", "G76 P010060 Q100 R0.05", "G76 X27.4 Z-30. P1300 Q#1 F2."],
     317, 5),
]  # fmt: skip


@pytest.mark.parametrize("dialect", LATHES)
@pytest.mark.parametrize(("what", "body", "number", "line"), RUN_CASES, ids=[c[0] for c in RUN_CASES])
def test_10_5_a_value_from_a_variable_is_found_at_run_time(
    dialect: str, what: str, body: list[str], number: int, line: int
) -> None:
    text = lines("O0001", *body, "M30")
    assert findings(text, dialect, "cycle-block") == []  # nothing the text alone shows
    assert alarm(text, dialect) == (number, line)


def test_10_5_a_g76_tool_angle_from_a_variable_is_ps0315_at_run_time_on_fanuc() -> None:
    text = lines("O0001", "#1=20045", "G00 X32. Z5.", "G76 P#1 Q100 R0.05", "G76 X27.4 Z-30. P1300 Q400 F2.", "M30")
    assert alarm(text, "fanuc-0i-lathe") == (315, 4)
    assert run(text, "gsk980tdi").status == "completed"


@pytest.mark.parametrize("dialect", LATHES)
def test_10_5_shape_warnings_from_variables_are_noted_by_the_run(dialect: str, tmp_path: Path) -> None:
    # #1 = 25: X 20 -> 30 -> 25 is a type I pocket (PS0329); #2 = 44 takes the shape past the start X42 (PS0322)
    text = lines("O0001", "#1=25.", "#2=44.", "G00 X42. Z2.", "G71 U1. R0.5", "G71 P10 Q20 U0.2 W0.1 F0.2",
                 "N10 G00 X20.", "G01 Z-10.", "X30. Z-20.", "X#1 Z-30.", "N20 X#2 Z-35.", "M30")  # fmt: skip
    assert coded(check(text, dialect), "cycle-shape") == []
    found = [d for d in analyse_files(tmp_path, {"MAIN.nc": text}, dialect) if d.code == "cycle-shape"]
    # both in one finding of the cycle block (one finding of a code per line)
    assert [(d.line + 1, d.severity) for d in found] == [(6, "warning")]
    assert "type I shape turns back along X" in found[0].message and "past the start point" in found[0].message
