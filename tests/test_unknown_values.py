"""Values the machine has and the folder does not are unknown, not vacant (docs/semantics.md §2,
"Unknown, not vacant"), through ``cncmacro check``: a kept common or an offset as a divisor is no
alarm; a branch or a move on one stops the analysis run with an ``unknown-value`` hint that
names the variable, and the blocks after it are not faded; a value given in ``[variables]`` or in
the persistent file the machine file names is used; what the program could have set itself
stays vacant."""

from __future__ import annotations

import json
from pathlib import Path

from cli_capture import check_findings, cli

# a production grinder's wear compensation: #706 is a count kept on the machine
GRINDER = "O0100\n#641=#640/#706\n#642=#641*2\nM30\n"
# the opening of the note of a guard the analysis run goes past (docs/semantics.md §2, the
# program's own guard is passed; tests/test_unknown_guards.py)
PASSED = (
    "the analysis run goes on past this guard, on the side that does not raise the program's own alarm, as the "
    "machine passes it in production: the condition depends"
)


check = check_findings


def test_a_kept_common_as_divisor_is_no_alarm(tmp_path: Path) -> None:
    assert check(tmp_path, GRINDER) == (0, [])


def test_a_kept_common_given_zero_in_variables_is_the_alarm_the_control_raises(tmp_path: Path) -> None:
    code, found = check(tmp_path, GRINDER, "[variables]\n640 = 3.0\n706 = 0\n")
    assert code == 1
    assert found == ["2:1: error: division by zero (alarm 112) [division-by-zero]",
                     "3:1: hint: no analysis run reaches these 2 lines [not-executed]"]  # fmt: skip


def test_a_kept_common_from_the_persistent_file_the_machine_file_names(tmp_path: Path) -> None:
    # #706 = 4 from the persistent file: #641 = 10 / 4 = 2.5, so IF [#641 GT 2] jumps over the alarm
    text = "O0100\n#641=10/#706\nIF [#641 GT 2] GOTO 10\n#3000=1 (WORN)\nN10 M30\n"
    (tmp_path / "vars.json").write_text(json.dumps({"variables": {"706": 4.0}}), encoding="utf-8")
    code, found = check(tmp_path, text, 'persistent_file = "vars.json"\n')
    assert (code, found) == (0, ["4:1: hint: no analysis run reaches this block [not-executed]"])
    # without it the branch cannot be decided; the block after it is the program's own alarm, so
    # the run jumps past it as the machine does in production (a note, the alarm block not faded, exit 0)
    (tmp_path / ".cncmacro.toml").unlink()
    code, found = check(tmp_path, text)
    assert code == 0
    assert found == [
        f"3:1: hint: {PASSED} on a value computed from #706 (line 2), "
        "which the machine keeps; this folder does not give it; set it under [variables] in .cncmacro.toml (or in "
        "the persistent file it names) to check further [unknown-value]"
    ]


def test_a_branch_on_a_kept_common_names_it(tmp_path: Path) -> None:
    code, found = check(tmp_path, "O0100\nIF [#500 EQ 1] GOTO 10\nG00 X10.\nN10 M30\n")
    assert code == 0
    assert found == [
        "2:1: hint: the analysis run stops here: this block depends on #500, which the machine keeps; this "
        "folder does not give it; set it under [variables] in .cncmacro.toml (or in the persistent file it names) to "
        "check further [unknown-value]"
    ]


def test_a_move_by_the_tool_diameter_from_the_offset_table_stops_with_a_note(tmp_path: Path) -> None:
    # Haas: #2401 is the diameter geometry of tool 1; a stepover of 40 % of it, divided into the width
    text = "O0100\n#1=#2401*0.4\n#2=FUP[50/#1]\nG01 X#1 F500\nM30\n"
    code, found = check(tmp_path, text, None, "--dialect", "haas")
    assert code == 0
    assert [f.split(": ")[1] for f in found] == ["hint"]
    assert found[0].startswith("4:1: hint: the analysis run stops here: this block depends on a value "
                               "computed from #2401 (line 2)")  # fmt: skip
    # the diameter given, the program runs to its end: 12.7 x 0.4 = 5.08, FUP[50 / 5.08] = 10
    assert check(tmp_path, text, "[variables]\n2401 = 12.7\n", "--dialect", "haas") == (0, [])


def test_what_the_program_could_set_itself_stays_vacant(tmp_path: Path) -> None:
    # a local never set and a common cleared at power-on (#100 on fanuc) divide to alarm 112
    for variable in ("#1", "#100"):
        code, found = check(tmp_path, f"O0100\n#2=10/{variable}\nM30\n")
        assert code == 1
        assert found[0] == "2:1: error: division by zero (the divisor is vacant) (alarm 112) [division-by-zero]"


def test_gsk_commons_cleared_at_power_off_are_the_operators_until_the_program_writes_them(tmp_path: Path) -> None:
    # GSK980TDi §3.28.1: the operator types #100-#199 in on the macro page, and the manual's own
    # O0100 keeps the parts made in #100 from run to run ("初始值=0"): a division by it is no
    # alarm, a branch on it stops the run with a note naming it; once the program wrote #101 = 0
    # a division by it is alarm 112 again, and a local never set still divides to alarm 112
    gsk = "O0100 (cncmacro: dialect=gsk980tdi)\n"
    assert check(tmp_path, f"{gsk}#1=10/#100\n#100=#100+1\nM30\n") == (0, [])
    code, found = check(tmp_path, f"{gsk}IF[#100<100]GOTO10\nG00 X10\nN10 M30\n")
    assert code == 0 and len(found) == 1 and "#100" in found[0] and "[unknown-value]" in found[0]
    for variable in ("#101", "#1"):
        code, found = check(tmp_path, f"{gsk}#101=0\n#2=10/{variable}\nM30\n")
        assert code == 1 and found[0].startswith("3:1: error: division by zero") and "(alarm 112)" in found[0]


def test_a_macro_checked_without_its_caller_gets_notes_not_alarms(tmp_path: Path) -> None:
    # O9010 returns with M99 and no program here calls it: its arguments are unknown, not
    # vacant. ``#20 EQ #0`` is false for an unknown (a value, not vacant), so the argument check
    # raises no #3000; the offset read by the tool number T (#20) stops the run with a note
    text = "O9010 (MACRO)\nIF [#20 EQ #0] THEN #3000=1 (T MISSING)\n#30=#[2000+#20]\nG01 Z-#30 F100\nM99\n"
    code, found = check(tmp_path, text)
    assert code == 0
    assert found == [
        "3:1: hint: the analysis run stops here: this block depends on #20 (T), which a caller passes; checked "
        "without its caller, this macro has no arguments; a program in the folder that calls it has it checked with "
        "the caller's [unknown-value]"
    ]
    # a main program (it ends in M30) starts with vacant locals, as on the control: every run
    # reaches the alarm, an error (docs/semantics.md §6, macro alarms the program surely reaches)
    code, found = check(tmp_path, text.replace("M99", "M30"))
    assert code == 1 and found[0] == "2:1: error: the run reaches macro alarm 3001: T MISSING [macro-alarm]"


def test_cncmacro_run_keeps_the_kept_common_vacant(tmp_path: Path) -> None:
    # the simulated machine has no value for #706 either: run stops where the control with a
    # vacant #706 would, with alarm 112
    (tmp_path / "O0100.nc").write_text(GRINDER, encoding="utf-8")
    code, out, err = cli("run", "--no-save", str(tmp_path / "O0100.nc"))
    assert code != 0 and "112" in out + err


def test_the_tool_in_the_spindle_before_any_t_is_unknown(tmp_path: Path) -> None:
    # Haas: #3026 is the tool in the spindle; before the program loads one the machine has one
    # loaded, so #[2400+#3026] (its diameter) is unknown, not the diameter of tool 0 (#2400,
    # which does not exist: alarm 115)
    text = "O0100\n#1=#[2400+#3026]\nIF [#1 GT 10.] GOTO 10\nN10 M30\n"
    code, found = check(tmp_path, text, None, "--dialect", "haas")
    assert code == 0
    assert [f.split(": ")[1] for f in found] == ["hint"] and found[0].startswith("2:1: ")
    # after T2 M06 it is tool 2: #2402 given as 12 in [variables], the program runs to its end
    loaded = text.replace("O0100\n", "O0100\nT2 M06\n")
    assert check(tmp_path, loaded, "[variables]\n2402 = 12.0\n", "--dialect", "haas") == (0, [])


# a touch probe switched on by M51 and checked through the interface input #1004 (UI004), with
# the shop's own alarm when it stays off: the sensor's state is the machine's, not the folder's
PROBE_ON = "O0100\nM51\nG04 X1.\nIF [#1004 EQ 1] GOTO 9\n#3000=7 (PROBE NOT ON)\nN9 G00 Z50.\nM30\n"


def test_an_input_signal_is_unknown_not_zero(tmp_path: Path) -> None:
    # read as 0 offline, #1004 EQ 1 was false and the run reached alarm 3007 on every check
    code, found = check(tmp_path, PROBE_ON)
    assert code == 0
    assert found == [
        f"4:1: hint: {PASSED} on #1004, an input signal the machine sends; "
        "this folder does not give it; set it under [variables] in .cncmacro.toml to check further [unknown-value]"
    ]
    # the signal given: on (1) jumps over the alarm to N9; off (0) reaches 3000 + 7 = 3007
    assert check(tmp_path, PROBE_ON, "[variables]\n1004 = 1\n") == (
        0, ["5:1: hint: no analysis run reaches this block [not-executed]"])  # fmt: skip
    code, found = check(tmp_path, PROBE_ON, "[variables]\n1004 = 0\n")
    assert code == 0 and found[0] == "5:1: warning: the run reaches macro alarm 3007: PROBE NOT ON [macro-alarm]"


# a bar-fed lathe's batch stop: the parts done (#3901) against the parts required (#3902), which the
# operator sets on the setting screen; read as 0 offline it alarmed on every check
BATCH = "O0100 (cncmacro: dialect=fanuc-0i-lathe)\nIF [#3901 GE #3902] THEN #3000=1 (BATCH COMPLETE)\nM30\n"


def test_the_parts_counters_are_the_machines(tmp_path: Path) -> None:
    code, found = check(tmp_path, BATCH)
    assert code == 0
    assert found == [
        f"2:1: hint: {PASSED} on #3901, #3902, which the machine keeps; "
        "this folder does not give it; set it under [variables] in .cncmacro.toml (or in the persistent file it "
        "names) to check further [unknown-value]"
    ]


def test_parts_counters_given_in_variables_are_used(tmp_path: Path) -> None:
    assert check(tmp_path, BATCH, "[variables]\n3901 = 41\n3902 = 500\n") == (0, [])
    code, found = check(tmp_path, BATCH, "[variables]\n3901 = 500\n3902 = 500\n")
    assert code == 0  # a warning: the shop's own alarm, which this machine's counts reach
    assert found == ["2:1: warning: the run reaches macro alarm 3001: BATCH COMPLETE [macro-alarm]",
                     "3:1: hint: no analysis run reaches this block [not-executed]"]  # fmt: skip


# a probe routine's own guard: the signal not on at the end of the G31 is the shop's alarm
PROBE_GUARD = ("O0100\nG90 G00 X0 Y0 Z5.\nG31 X20. F200.\n#2=#5061\nIF [ABS[#2-20.] LT 0.001] GOTO 910\n"
               "G00 X0\nM30\nN910 #3000=1 (PROBE DID NOT TRIGGER)\nM30\n")  # fmt: skip


def test_where_a_probe_touched_is_the_machines(tmp_path: Path) -> None:
    # without a [skip] table the G31 ran to its end in the simulation, which would reach the guard's
    # alarm on every check; where the probe touches is known only on the machine
    code, found = check(tmp_path, PROBE_GUARD)
    assert code == 0
    assert found == [
        f"5:1: hint: {PASSED} on a value computed from #5061 (line 4), "
        "where the probe's G31 touched; only the machine finds it; a [skip] table in .cncmacro.toml says where "
        "the probe touches, to check further [unknown-value]"
    ]


def test_a_skip_table_says_where_the_probe_touches(tmp_path: Path) -> None:
    # the part's face at X15: the G31 stops there, #5061 = 15, the guard lets the program go on
    code, found = check(tmp_path, PROBE_GUARD, "[skip]\nX = 15\n")
    assert (code, found) == (0, ["8:1: hint: no analysis run reaches these 2 lines [not-executed]"])
    # and a probe that misses (the table's contact "miss") reaches the alarm, as on the machine
    code, found = check(tmp_path, PROBE_GUARD, '[skip]\ncontacts = ["miss"]\n')
    assert code == 0
    assert "8:1: warning: the run reaches macro alarm 3001: PROBE DID NOT TRIGGER [macro-alarm]" in found


# the same guard on the GSK980TDi, which stores where the signal came on in #995-#999 (X, Z, Y, 4th,
# 5th; its manual §3.16.2): the program clears #996, probes the face, and takes the alarm where #996
# is still what it wrote
GSK_PROBE_GUARD = ("(cncmacro: dialect=gsk980tdi)\nO0100\n#996=-999\nG00 X40 Z10\nG98 G31 Z-20 F50\n"
                   "IF[#996 NE -999]GOTO10\n#3000=1(PROBE DID NOT TRIGGER)\nN10 G00 Z10\nM30\n")  # fmt: skip


def test_where_a_gsk980tdi_probe_touched_is_the_machines(tmp_path: Path) -> None:
    # without a [skip] table the G31 ran to its end with the signal off and #996 kept -999: the check
    # reached the guard's alarm 5901. The G31 leaves #996 unknown, and the note says why, though the
    # program wrote #996 before it
    code, found = check(tmp_path, GSK_PROBE_GUARD)
    assert code == 0
    assert found == [
        f"6:1: hint: {PASSED} on #996, where the probe's G31 touched; only "
        "the machine finds it; a [skip] table in .cncmacro.toml says where the probe touches, to check further "
        "[unknown-value]"
    ]
    # the face at Z2: #996 = 2, the guard jumps over the alarm
    code, found = check(tmp_path, GSK_PROBE_GUARD, "[skip]\nZ = 2\n")
    assert (code, found) == (0, ["7:1: hint: no analysis run reaches this block [not-executed]"])


def test_a_value_read_through_an_indirect_number_is_named_as_such(tmp_path: Path) -> None:
    # the tool is known after T2 M06; the unknown is the length offset #11002 read through #[11000+#11]
    text = "O0100\nT2 M06\n#11=#4120\n#12=#[11000+#11]\nIF [#12 GT -50.] GOTO 10\nG00 X0\nN10 M30\n"
    code, found = check(tmp_path, text)
    assert code == 0
    assert found == [
        "5:1: hint: the analysis run stops here: this block depends on a value read through #[...] (line 4), a "
        "variable whose number the run works out (an offset or a common the machine keeps); set it under "
        "[variables] in .cncmacro.toml (or in the persistent file it names) to check further [unknown-value]"
    ]


def test_a_random_number_is_unknown_and_a_branch_on_it_is_not_judged(tmp_path: Path) -> None:
    # GSK980TDi §3.29.1 RAND/SRAND: no check can foresee the number, so the IF on line 4 stops
    # the analysis run with a note (no syntax error, no alarm, the block after it not faded)
    text = "O0100\n#1=RAND[10]\n#2=SRAND[5,10]\nIF [#1 GT 5] GOTO 10\nG00 X1\nN10 M30\n"
    code, found = check(tmp_path, text, None, "--dialect", "gsk980tdi")
    assert code == 0
    assert found == [
        "4:1: hint: the analysis run stops here: this block depends on a random number (RAND, SRAND) (line 2), "
        "which the control draws as the program runs; no check can foresee it, so what the block decides with "
        "it is not judged [unknown-value]"
    ]
    code, found = check(tmp_path, text, None, "--dialect", "gsk980tdi", "--locale", "zh-CN")
    assert found[0].startswith("4:1: ") and "随机数（RAND、SRAND）（第 2 行）" in found[0]


# the machine of these tests: G54 X is -420, X travels from -510 to 0 (machine = program + G54 X)
G54_AND_TRAVEL = "[variables]\n5221 = -420.0\n\n[limits]\ntravel = { X = [-510, 0] }\n"


def test_g10_with_a_kept_value_writes_an_unknown_offset_and_the_run_goes_on(tmp_path: Path) -> None:
    # G10 L12 P5 R#570 writes D5's radius geometry from kept #570, as #13005=#570 does: the offset
    # becomes unknown and the run goes on (it stopped at the G10 with a note), so the rapid to
    # under G54 is checked: machine X = -95 + (-420) = -515, 5 mm past the - limit -510
    over = ("3:1: error: X- over travel: the move goes to machine X-515.000, 5.000 mm past the - limit X-510.000 "
            "([limits] travel); the axis stops at the limit (alarm 501) [over-travel]")  # fmt: skip
    for write in ("G10 L12 P5 R#570", "#13005=#570"):
        code, found = check(tmp_path, f"O0100\n{write}\nG90 G54 G00 X-95.\nM30\n", G54_AND_TRAVEL)
        assert (code, found[:1]) == (1, [over]), write
    # G10 L2 P1 X#570 makes G54 X itself unknown: X is then not checked, and nothing is said
    assert check(tmp_path, "O0100\nG10 L2 P1 X#570\nG90 G54 G00 X-95.\nM30\n", G54_AND_TRAVEL) == (0, [])
    # what G10 writes to is still decided by the run: an offset number from a kept value stops it
    code, found = check(tmp_path, "O0100\nG10 L12 P#570 R2.\nG90 G54 G00 X-95.\nM30\n", G54_AND_TRAVEL)
    assert code == 0 and len(found) == 1 and found[0].startswith("2:1: hint: the analysis run stops here")


def test_g10_adding_to_an_unknown_offset_leaves_it_unknown(tmp_path: Path) -> None:
    # G54 X is not given: the machine keeps it. G91 G10 L2 P1 X1. adds 1 mm to it, as
    # #5221=#5221+1. would: still unknown, so the rapid to X-600. is not travel-checked (the
    # offset was taken as 0 + 1 = 1, machine X-599, a false over-travel past -510)
    limits = "[limits]\ntravel = { X = [-510, 0] }\n"
    for write in ("G91 G10 L2 P1 X1.", "#5221=#5221+1."):
        assert check(tmp_path, f"O0100\n{write}\nG90 G54 G00 X-600.\nM30\n", limits) == (0, []), write
    # given (-420), it adds: -419, and X-95. goes to machine -514, 4 mm past the limit
    code, found = check(tmp_path, "O0100\nG91 G10 L2 P1 X1.\nG90 G54 G00 X-95.\nM30\n", G54_AND_TRAVEL)
    assert code == 1 and "machine X-514.000, 4.000 mm past" in found[0]


# O1007 is a subprogram (M99, no M30): #101 the total depth and #102 the passes, set by its caller
SUBPROGRAM = "O1007\n#3=#101/#102\n#4=1\nWHILE [#4 LE #102] DO 1\nG01 Z[-#4*#3] F100.\n#4=#4+1\nEND 1\nM99\n"


def test_a_subprogram_checked_without_its_caller_reads_the_commons_its_caller_sets_as_unknown(tmp_path: Path) -> None:
    # its caller sets #101 and #102 before M98 P1007 and is not in the folder: #101/#102 is
    # unknown (no alarm 112, which the control never raises); WHILE [1 LE #102] is gone through once
    # with a note naming #102 (tests/test_unknown_loops.py), and the move by #3 in it stops the run
    # with a note naming #101 and #102 (it was "division by zero (alarm 112)", an error, on line 2)
    tail = (
        "which a caller sets before the call; checked without its caller, this subprogram does not have what its "
        "caller sets; a program in the folder that calls it has it checked with the caller's values"
    )
    code, found = check(tmp_path, SUBPROGRAM)
    assert code == 0
    assert found == [
        "4:1: hint: the analysis run goes through this WHILE loop once and then leaves it, so that its body and what "
        f"follows are checked; the machine repeats it as its condition says, which depends on #102, {tail} "
        "[unknown-value]",
        "5:1: hint: the analysis run stops here: this block depends on a value computed from #101 (line 2), #102 "
        f"(line 2), {tail}, in iteration 1 of the WHILE loop at line 4, at block 4 of the run (inside a loop) "
        "[unknown-value]",
    ]
    # a main program (M30) starts with #100-#199 vacant after power-on, as before: alarm 112
    code, found = check(tmp_path, SUBPROGRAM.replace("M99", "M30"))
    assert (
        code == 1 and found[0] == "2:1: error: division by zero (the divisor is vacant) (alarm 112) [division-by-zero]"
    )


def test_a_subprogram_with_its_caller_in_the_folder_runs_with_the_commons_the_caller_sets(tmp_path: Path) -> None:
    # O1010 sets #101 = 6. and #102 = 0 and calls O1007: 6 / 0 is alarm 112 on O1007's line 2
    (tmp_path / "O1007.nc").write_text(SUBPROGRAM, encoding="utf-8")
    (tmp_path / "O1010.nc").write_text("O1010\n#101=6.\n#102=0\nM98 P1007\nM30\n", encoding="utf-8")
    code, out, _ = cli("check", str(tmp_path))
    assert code == 1
    assert "O1007.nc:2:1: error: division by zero (alarm 112); reached from O1010:4 (M98), at block 4" in out
    # #102 = 3 passes of 6 / 3 = 2 mm: Z-2., Z-4., Z-6., and nothing to say
    (tmp_path / "O1010.nc").write_text("O1010\n#101=6.\n#102=3\nM98 P1007\nM30\n", encoding="utf-8")
    assert cli("check", str(tmp_path))[:2] == (0, "")


def test_an_unknown_hint_names_the_position_variable_and_says_no_value_is_assumed(tmp_path: Path) -> None:
    # G43 H1 with H1 not given: #5083 (the tool length in force) is unknown, and the hint names it
    text = "O0100\nG21 G90 G54 G00 X0. Y0.\nG43 H1 Z100.\nIF [#5083 GT 50.] GOTO 10\nG00 X5.\nN10 M30\n"
    code, found = check(tmp_path, text)
    assert code == 0
    assert found == [
        "4:1: hint: the analysis run stops here: this block depends on #5083, a position or offset in force the "
        "machine has: it adds an offset this folder does not give (or follows a G30, or a G92/G50 where the tool's "
        "place is not known), so the check assumes no value for it; this folder does not give it; set it under "
        "[variables] in .cncmacro.toml (or in the persistent file it names) to check further [unknown-value]"
    ]


def test_an_unknown_hint_in_a_called_macro_names_the_argument_and_its_letter(tmp_path: Path) -> None:
    # O0100 passes A#560 (kept): in O9101, IF [#1 GT 10.] decides with #1 (A), named with its letter
    (tmp_path / "O9101.nc").write_text("O9101\nIF [#1 GT 10.] GOTO 10\nG00 X5.\nN10 M99\n", encoding="utf-8")
    (tmp_path / "O0100.nc").write_text("O0100\nG65 P9101 A#560\nM30\n", encoding="utf-8")
    code, out, err = cli("check", "--hints", str(tmp_path))
    assert (code, err) == (0, "")
    assert out.splitlines() == [
        f"{tmp_path / 'O9101.nc'}:2:1: hint: the analysis run stops here: this block depends on #1 (A), which the "
        "call passes from a value the machine has; this folder does not give it; set it under [variables] in "
        ".cncmacro.toml (or in the persistent file it names) to check further; reached from O0100:2 (G65), at "
        "block 2 of the run [unknown-value]"
    ]
