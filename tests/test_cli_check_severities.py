"""``cncmacro check`` on shop programs: the severity a finding gets is the one a machinist
should meet (issue "never cry wolf"): an error where the control surely stops, a hint where
it runs the block as written."""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_capture import cli


def _folder(tmp_path: Path, **programs: str) -> Path:
    for name, text in programs.items():
        (tmp_path / f"{name}.nc").write_text(text, encoding="utf-8")
    return tmp_path


# ---------------------------------------------------------------- g65-nc-words


def test_a_modal_g_code_before_g65_on_fanuc_is_only_a_hint_and_check_is_quiet(tmp_path):
    folder = _folder(tmp_path, O1000="O1000\nG90 G54 G65 P1001 A1.\nM30\n", O1001="O1001\n#100=#1\nM99\n")
    for profile in ("fanuc-0i", "fanuc-30i"):
        code, out, err = cli("check", "--dialect", profile, str(folder))
        assert (code, out) == (0, ""), out + err  # nothing to say by default
        code, out, _ = cli("check", "--hints", "--dialect", profile, str(folder))
        assert code == 0
        assert ":2:1: hint: G90 G54 before G65" in out and "[g65-nc-words]" in out


def test_a_modal_g_code_before_g65_stays_an_error_where_the_control_stops_with_alarm_127(tmp_path):
    folder = _folder(tmp_path, O1000="O1000\nG90 G54 G65 P1001 A1.\nM30\n", O1001="O1001\n#100=#1\nM99\n")
    code, out, _ = cli("check", "--dialect", "gsk980tdi", str(folder))
    assert code == 1
    assert ":2:1: error: G90 before G65" in out and "alarm 127" in out


# ---------------------------------------------------------------- endless loops


def test_a_while_loop_whose_condition_nothing_in_it_changes_is_an_error(tmp_path):
    # #1 is 1 and the body writes only #2: WHILE [#1 LT 10] is true at every pass
    folder = _folder(tmp_path, O0001="O0001\n#1=1\nWHILE[#1 LT 10]DO1\n#2=5\nG00 X#2\nEND1\nM30\n")
    code, out, _ = cli("check", str(folder))
    assert code == 1
    assert ":6:1: error: an endless loop: line 6 comes back" in out and "[endless-loop]" in out
    code, out, _ = cli("check", "--locale", "zh-CN", str(folder))
    assert code == 1 and "死循环：第 6 行" in out


def test_an_if_goto_back_on_an_unchanged_local_is_an_error_too(tmp_path):
    folder = _folder(tmp_path, O0001="O0001\n#1=0\nN5 IF[#1 LT 3] GOTO5\nM30\n")
    code, out, _ = cli("check", str(folder))
    assert code == 1 and ":3:1: error: an endless loop" in out


def test_a_loop_on_a_common_variable_is_a_warning_another_path_or_the_operator_could_end(tmp_path):
    folder = _folder(tmp_path, O0001="O0001\n#100=1\nWHILE[#100 LT 10]DO1\n#2=5\nEND1\nM30\n")
    code, out, _ = cli("check", str(folder))
    assert code == 0
    assert ":5:1: warning: an endless loop" in out and "another path of the control or the operator" in out


def test_endless_loops_a_shop_writes_on_purpose_or_that_wait_for_the_machine_are_no_error(tmp_path):
    programs = {
        "O0001": "O0001\nN1 G00 X0\nG00 X10.\nGOTO1\nM30\n",  # a warm-up: unconditional GOTO back
        "O0002": "O0002\nDO1\nG00 X0\nEND1\nM30\n",  # DO without WHILE
        "O0003": "O0003\nWHILE[#1004 EQ 0]DO1\nEND1\nM30\n",  # waits for an input signal
        "O0004": "O0004\nWHILE[#1 LT 3]DO1\nM98 P5\nEND1\nM30\n",  # calls a program
        "O0005": "O0005\nM99\n",
    }
    code, out, err = cli("check", str(_folder(tmp_path, **programs)))
    assert code == 0, out + err
    assert "error" not in out and "warning" not in out and "[endless-loop]" not in out
    assert out.count("information: an endless loop") == 3  # O0001, O0002, O0004
    # the wait on the input signal: #1004 is the machine's, so the run goes through the loop once
    # and leaves it, with a hint (docs/semantics.md §2, a loop on a value only the machine has)
    code, out, _ = cli("check", "--hints", str(tmp_path / "O0003.nc"))
    assert code == 0 and ":2:1: hint: the analysis run goes through this WHILE loop once" in out
    assert "depends on #1004, an input signal the machine sends" in out


# ---------------------------------------------------------------- macro alarms


def test_a_macro_alarm_a_main_program_surely_reaches_is_an_error(tmp_path):
    # #1 = 2 is set by the program; 2 GT 1 on every run, so the control stops there every cycle
    folder = _folder(tmp_path, O1000="O1000\n#1=2\nIF[#1 GT 1] THEN #3000=1(TOO BIG)\nM30\n")
    code, out, _ = cli("check", str(folder))
    assert code == 1
    assert out.endswith(":3:1: error: the run reaches macro alarm 3001: TOO BIG [macro-alarm]\n")


def test_a_macro_alarm_reached_through_a_macro_from_a_main_program_is_an_error(tmp_path):
    folder = _folder(
        tmp_path,
        O1005="O1005\n#100=3\nG65 P9000 A#100\nM30\n",  # #100 set by the program before it is passed
        O9000="O9000\nIF[#1 GT 1] THEN #3000=2(A TOO BIG)\nM99\n",
    )
    code, out, _ = cli("check", str(folder))
    assert code == 1 and ": error: the run reaches macro alarm 3002: A TOO BIG" in out


@pytest.mark.parametrize(
    "program",
    [
        # a machine position, through a local (G54 X given: without it #5021 is unknown, docs/semantics.md §2)
        "O1001\n#5221=0\n#1=#5021\nIF[#1 EQ 0] THEN #3000=1(HOME)\nM30\n",
        "O1001\nIF[#100 EQ #0] THEN #3000=1(SET 100)\nM30\n",  # a common the program never set
        "O1001\n#1=#3001\n#3000=1(CLOCK)\nM30\n",  # the clock
    ],
)
def test_a_macro_alarm_on_a_path_that_depends_on_the_machine_stays_a_warning(tmp_path, program):
    code, out, _ = cli("check", str(_folder(tmp_path, O1001=program)))
    assert code == 0
    assert ": warning: the run reaches macro alarm 3001" in out


@pytest.mark.parametrize(
    "programs",
    [
        {"O1001": "O1001\nIF[#500 EQ #0] THEN #3000=1(SET 500)\nM30\n"},  # a kept common: the machine's
        {"O1001": "O1001\nIF[#2001 LT 0.1] THEN #3000=1(OFFSET)\nM30\n"},  # a tool offset
        {"O9100": "O9100\nIF[#1 EQ #0] THEN #3000=1(A MISSING)\nM99\n"},  # a macro checked without its caller
        {"O1001": "O1001\nIF[#1004 EQ 0] THEN #3000=1(NO AIR)\nM30\n"},  # an input signal: unknown, a hint
    ],
)
def test_a_macro_alarm_behind_a_value_only_the_machine_or_the_caller_has_is_never_an_error(tmp_path, programs):
    code, out, _ = cli("check", "--hints", str(_folder(tmp_path, **programs)))
    assert code == 0 and ": error:" not in out, out


def test_a_macro_checked_alone_that_reaches_its_alarm_keeps_it_a_warning(tmp_path):
    # no caller in the folder: the caller decides whether the macro is called this way at all
    folder = _folder(tmp_path, O9100="O9100\n#3000=1(CALL ME WITH A)\nM99\n")
    code, out, _ = cli("check", str(folder))
    assert code == 0 and ": warning: the run reaches macro alarm 3001: CALL ME WITH A" in out


def test_a_macro_checked_alone_whose_alarm_depends_on_its_arguments_is_only_information(tmp_path):
    # a probe macro refuses S and T together; checked alone its arguments are unknown (a value,
    # not vacant), so both tests of #19 and #20 fall through to the alarm: the caller decides
    macro = "O9100\nIF [#19 EQ #0] GOTO 10\nIF [#20 EQ #0] GOTO 10\n#3000=91 (S AND T BOTH GIVEN)\nN10 M99\n"
    code, out, _ = cli("check", str(_folder(tmp_path, O9100=macro)))
    assert code == 0
    assert out.endswith(": information: the run reaches macro alarm 3091: S AND T BOTH GIVEN [macro-alarm]\n")
    assert out.count("\n") == 1
    # a caller that passes both: the run goes through it and the control stops on every cycle
    code, out, _ = cli("check", str(_folder(tmp_path, O1001="O1001\nG65 P9100 S1. T2.\nM30\n")))
    assert code == 1 and ": error: the run reaches macro alarm 3091: S AND T BOTH GIVEN" in out


@pytest.mark.parametrize(
    ("ending", "is_macro"),
    [("n10 m99\n", True), ("N10 M 099\n", True), ("n10 m30\nm99\n", False), ("N10 M99\nM02\n", False)],
)
def test_a_macro_is_told_by_its_m99_without_m30_or_m02_written_in_either_case(tmp_path, ending, is_macro):
    # checked alone, a program that returns with M99 and never ends with M30 or M02 is a macro:
    # its arguments are unknown, so the alarm behind #19 is the caller's to decide; a program
    # that ends is run with #19 vacant, and jumps over the alarm
    macro = "O9100\n(SPINDLE: M03, COOLANT: M08)\nIF [#19 EQ #0] GOTO 10\n#3000=91 (S GIVEN)\n" + ending
    code, out, _ = cli("check", str(_folder(tmp_path, O9100=macro)))
    assert code == 0
    assert ("macro alarm 3091: S GIVEN" in out) is is_macro, out


def test_a_macro_checked_alone_whose_alarm_depends_on_the_callers_tool_length_is_only_information(tmp_path):
    # #4111 is the H in effect, which the caller's G43 sets before it calls the macro
    macro = "O9100\nIF [#4111 GT 0] GOTO 5\n#3000=89 (NO TOOL LENGTH ACTIVE)\nN5 M99\n"
    code, out, _ = cli("check", str(_folder(tmp_path, O9100=macro)))
    assert code == 0 and ":3:1: information: the run reaches macro alarm 3089: NO TOOL LENGTH ACTIVE" in out
    # a caller with G43 H1 passes the test; one without it is run and warned about
    assert cli("check", str(_folder(tmp_path, O1001="O1001\nG43 H1 Z50.\nG65 P9100\nM30\n"))) == (0, "", "")
    code, out, _ = cli("check", str(_folder(tmp_path, O1001="O1001\nG65 P9100\nM30\n")))
    assert code == 0 and ": warning: the run reaches macro alarm 3089" in out


def test_a_common_set_by_a_gsk_g65_h01_counts_as_set_by_the_program_as_an_assignment_does(tmp_path):
    # GSK980TDi §3.28.2: H01 is the assignment, so G65 H01 P#100 Q3 sets #100 = 3 as #100=3 does;
    # H84 jumps to N20 when #100 < 2: 3 < 2 is false on every run, so H99 P15 stops with 5900 + 15
    # = 5915 every cycle: an error in both forms (it was an error with #100=3, a warning with H01)
    for setting in ("#100=3", "G65 H01 P#100 Q3", "G65 H02 P#100 Q1 R2"):  # H02: #100 = 1 + 2
        program = f"O0113\n{setting}\nG65 H84 P20 Q#100 R2\nG65 H99 P15(/USER ALARM)\nN20 M30\n"
        code, out, _ = cli("check", "--dialect", "gsk980tdi", str(_folder(tmp_path, O0113=program)))
        assert code == 1, (setting, out)
        assert ":4:1: error: the run reaches macro alarm 5915: USER ALARM [macro-alarm]" in out, (setting, out)


def test_a_gsk_g65_h26_reads_its_p_so_only_a_common_set_before_it_makes_its_alarm_sure(tmp_path):
    # H26 sets #100 = #100 * Q / R: it reads #100, which the program never set (the operator may
    # have): the check cannot say where H85 (jump past the alarm when #100 >= 2) goes, so no error
    program = "O0113\nG65 H26 P#100 Q2 R1\nG65 H85 P20 Q#100 R2\nG65 H99 P15(/USER ALARM)\nN20 M30\n"
    code, out, _ = cli("check", "--dialect", "gsk980tdi", str(_folder(tmp_path, O0113=program)))
    assert code == 0 and ": error:" not in out, out
    # with H01 P#100 Q0.5 first: 0.5 * 2 / 1 = 1, 1 >= 2 is false on every run: an error
    program = program.replace("O0113\n", "O0113\nG65 H01 P#100 Q0.5\n")
    code, out, _ = cli("check", "--dialect", "gsk980tdi", str(_folder(tmp_path, O0113=program)))
    assert code == 1 and ": error: the run reaches macro alarm 5915" in out, out
