"""docs/semantics.md §5 "Calls", run on the interpreter: G65 arguments (specifications I and II),
L, G66/G67, M98 counts and Q, M99 and M99 Pn, nesting, and finding programs across files."""

from __future__ import annotations

import pytest

from running import alarm, final, lines, run

MACRO_ECHO = lines("O9000", *(f"#{100 + k}=#{k}" for k in range(1, 34)), "M99")


def locals_passed(call: str, dialect: str = "fanuc") -> dict[int, float]:
    """The locals a called macro saw, as {local: value}."""
    v = final(lines(call, "M30", MACRO_ECHO), dialect)
    return {k - 100: x for k, x in v.items() if 101 <= k <= 133}


def test_argument_specification_i():
    got = locals_passed("G65 P9000 A1 B2 C3 D7 E8 F9 H11 M13 Q17 R18 S19 T20 U21 V22 W23 X24 Y25 Z26")
    assert got == {1: 1, 2: 2, 3: 3, 7: 7, 8: 8, 9: 9, 11: 11, 13: 13, 17: 17, 18: 18, 19: 19, 20: 20, 21: 21,
                   22: 22, 23: 23, 24: 24, 25: 25, 26: 26}  # fmt: skip


def test_seed_000_argument_specification_ii():
    got = locals_passed("G65 P9000 A1 B2 C3 I14 J15 I6 J7 K9 K11 K12 J30", "gsk980tdi")
    assert got == {1: 1, 2: 2, 3: 3, 4: 14, 5: 15, 7: 6, 8: 7, 6: 9, 9: 11, 12: 12, 11: 30}


def test_seed_001_argument_specification_ii():
    got = locals_passed("G65 P9000 J12 K22 J25 I33 J32", "gsk980tdi")
    assert got == {5: 12, 6: 22, 8: 25, 4: 33, 11: 32}


def test_mixing_specifications_a_later_word_wins():
    # FANUC example: A1. B2. I-3. I4. D5. -> #4=-3, #7=5 (D after the second I)
    got = locals_passed("G65 P9000 A1. B2. I-3. I4. D5.")
    assert got == {1: 1, 2: 2, 4: -3, 7: 5}


def test_ten_sets_of_ijk_fill_up_to_33():
    words = " ".join(f"I{k} J{k} K{k}" for k in range(1, 11))
    got = locals_passed(f"G65 P9000 {words}")
    assert got[31] == 10 and got[32] == 10 and got[33] == 10 and got[4] == 1


def test_ijk_out_of_order_is_accepted_with_a_note_on_fanuc():
    m = run(lines("G65 P9000 J1 I2", "M30", MACRO_ECHO))
    assert m.status == "completed" and m.variables()[104] == 2 and m.variables()[105] == 1
    assert any("order" in n.message for n in m.notes)
    m = run(lines("G65 P9000 J1 I2", "M30", MACRO_ECHO), "gsk980tdi")
    assert not any("order" in n.message for n in m.notes)


def test_vacant_argument_values():
    # fanuc: the argument is not passed (its local stays vacant); gsk: it is 0
    assert 24 not in locals_passed("G65 P9000 X#1 Y2")
    assert locals_passed("G65 P9000 X#1 Y2", "gsk980tdi")[24] == 0


@pytest.mark.parametrize("word", ["G1", "N5", "O5"])
def test_g_n_o_are_not_arguments(word):
    number, line = alarm(lines(f"G65 P9000 A1 {word}", "M30", MACRO_ECHO))
    assert line == 1 and number in (127, 129)


def test_only_n_may_precede_g65():
    assert alarm(lines("G01 G65 P9000 A1", "M30", MACRO_ECHO), "gsk980tdi")[0] == 127
    assert final(lines("G01 G65 P9000 A1", "M30", MACRO_ECHO))[101] == 1  # fanuc: a modal G code, then the call
    assert alarm(lines("X5 G65 P9000 A1", "M30", MACRO_ECHO))[0] == 127
    assert alarm(lines("M03 G65 P9000 A1", "M30", MACRO_ECHO))[0] == 127
    assert locals_passed("G65 P9000 A1 M03")[13] == 3  # after G65, M is the argument #13
    assert final(lines("N10 G65 P9000 A1", "M30", MACRO_ECHO))[101] == 1


def test_locals_are_per_level_and_restored_on_m99():
    program = lines("#1=5", "#2=6", "G65 P9001 A1", "#100=#1", "#101=#2", "M30", "O9001", "#2=99", "#102=#1", "M99")
    v = final(program)
    assert v[100] == 5 and v[101] == 6 and v[102] == 1


def test_l_repeats_the_call_with_fresh_arguments():
    program = lines("G65 P9002 L3 A2", "M30", "O9002", "#100=#100+#1", "#1=#1+10", "M99")
    assert final(program)[100] == 6


def test_l_from_a_variable():
    program = lines("#5=4", "G65 P9002 L#5 A1", "M30", "O9002", "#100=#100+#1", "M99")
    assert final(program)[100] == 4


def test_l_below_one_is_an_alarm():
    program = lines("#5=0", "G65 P9002 L#5 A1", "M30", "O9002", "M99")
    assert alarm(program)[1] == 2
    assert alarm(program, "gsk980tdi")[1] == 2


def test_l_above_9999_is_clamped_on_gsk_and_an_alarm_on_fanuc():
    program = lines("G65 P9002 L10000", "M30", "O9002", "#100=#100+1", "M99")
    m = run(program, "gsk980tdi", max_blocks=1_000_000)
    assert m.status == "completed" and m.variables()[100] == 9999
    assert any("9999" in n.message for n in m.notes)
    assert alarm(program)[1] == 1


def test_g66_calls_after_every_move_and_g67_cancels():
    program = lines(
        "G90 G00 X0 Y0",
        "G66 P9003 A7",
        "G00 X10",  # calls
        "#110=#110",  # no move: no call
        "G01 Y5 F100",  # calls
        "G67",
        "G00 X20",  # no call
        "M30",
        "O9003",
        "#100=#100+1",
        "#101=#1",
        "#102=#5001",  # the macro sees the position the move reached
        "G00 Z1",  # a modally called macro does not call itself
        "M99",
    )
    v = final(program)
    assert v[100] == 2 and v[101] == 7 and v[102] == 10


def test_5_g66_seed_001_example_a_block_without_movement_calls_nothing_on_gsk980tdi():
    # seed 001 G66 example O0002 and its note 3: "G0 U0 W0" has no amount of movement, no call
    program = lines(
        "G00 X100 Z50",
        "G66 P0100 L2 A2 B20 C20 I30 J20 K20",
        "G01 X80 Z50",  # calls O0100 twice
        "G0 U0 W0",  # no call
        "G01 X80 Z50",  # already there: no call either
        "G01 U1",  # calls twice
        "G67",
        "G01 X20 Z50",  # no call
        "M30",
        "O0100",
        "#100=#100+1",
        "M99",
    )
    assert final(program, "gsk980tdi")[100] == 4


def test_5_g66_a_move_command_to_where_the_tool_is_calls_on_fanuc():
    # fanuc: the macro is called after a block with a move command (seed 003 §8.3, seed 004)
    program = lines("G90 G00 X10", "G66 P9003", "G01 X10 F100", "G91 X0", "G67", "M30", "O9003", "#100=#100+1", "M99")
    assert final(program)[100] == 2


def test_g66_block_itself_calls_nothing():
    v = final(lines("G66 P9003 A1 X5", "G67", "M30", "O9003", "#100=#100+1", "M99"))
    assert 100 not in v


@pytest.mark.parametrize("dialect", ["fanuc", "gsk980tdi"])
def test_5_g66_sets_modal_group_12_to_66_and_g67_back_to_67(dialect):
    # seed 000 system variable table (#4012: G66, G67, group 12), seed 003 §4.8
    program = lines(
        "#101=#4012",
        "G66 P9003",
        "#102=#4012",
        "G66 P9003",  # nested modal calls: still 66 until the last one is cancelled
        "G67",
        "#103=#4012",
        "G67",
        "#104=#4012",
        "M30",
        "O9003",
        "M99",
    )
    v = final(program, dialect)
    assert (v[101], v[102], v[103], v[104]) == (67, 66, 66, 67)


def test_m30_cancels_the_modal_call():
    m = run(lines("G66 P9003", "M30", "O9003", "M99"))
    assert m.status == "completed" and not m.modal_calls


def test_m98_count_in_p():
    program = lines("M98 P30040", "M30", "O0040", "#100=#100+1", "#1=#1+1", "M99")
    v = final(program)
    assert v[100] == 3 and v[1] == 3  # M98 keeps the caller's locals


def test_m98_l_and_leading_zeros():
    assert final(lines("M98 P0040 L4", "M30", "O0040", "#100=#100+1", "M99"))[100] == 4
    assert final(lines("M98 P00020040", "M30", "O0040", "#100=#100+1", "M99"))[100] == 2


def test_m98_count_in_both_p_and_l_is_alarm_293_on_gsk():
    program = lines("M98 P20040 L3", "M30", "O0040", "M99")
    assert alarm(program, "gsk980tdi") == (293, 1)


def test_m98_q_starts_at_a_label():
    program = lines("M98 P0040 Q20", "M30", "O0040", "#100=1", "N20 #101=1", "M99")
    v = final(program)
    assert 100 not in v and v[101] == 1


def test_m98_after_the_motion_of_its_block():
    m = run(lines("G90 G01 X100 F100 M98 P0040", "M30", "O0040", "#100=#5001", "M99"))
    assert m.variables()[100] == 100


def test_m99_p_returns_to_a_label_in_the_caller():
    program = lines("M98 P0040", "#100=1", "N30 #101=1", "M30", "O0040", "M99 P30")
    v = final(program)
    assert 100 not in v and v[101] == 1


@pytest.mark.parametrize(
    ("before", "after", "expected"),
    [
        # seed 002 注2: both before the M98 -> the later one; both after -> the earlier one;
        # one before and one after -> the later one (the one after)
        (["N30 #101=1", "GOTO 99", "N30 #101=2", "GOTO 99"], [], 2),
        ([], ["N30 #101=3", "GOTO 99", "N30 #101=4", "GOTO 99"], 3),
        (["N30 #101=5", "GOTO 99"], ["N30 #101=6", "GOTO 99"], 6),
    ],
)
def test_seed_002_m99_p_with_duplicate_labels(before, after, expected):
    head = ["GOTO 5", *before, "N5 M98 P0040", *after, "N99 M30"]
    program = lines(*head, "O0040", "M99 P30")
    assert final(program)[101] == expected


def test_m99_in_a_main_program_restarts_it():
    m = run(lines("#100=#100+1", "M99"), max_blocks=100)
    assert m.status == "limit" and m.C[100] == 50


def test_macro_nesting_limit_is_4_levels():
    def chain(depth: int) -> str:
        body = [f"G65 P{9101}"]
        for k in range(depth):
            body += [f"O{9101 + k}", f"G65 P{9102 + k}" if k + 1 < depth else "#100=1", "M99"]
        return lines(body[0], "M30", *body[1:])

    assert final(chain(4))[100] == 1
    assert alarm(chain(5)) == (122, 13)  # the G65 that would open a 5th level


@pytest.mark.parametrize(("dialect", "limit"), [("fanuc", 10), ("gsk980tdi", 12)])
def test_subprogram_nesting_limit(dialect, limit):
    def chain(depth: int) -> str:
        body = []
        for k in range(depth):
            body += [f"O{100 + k}", f"M98 P{101 + k}" if k + 1 < depth else "#100=1", "M99"]
        return lines("M98 P100", "M30", *body)

    assert final(chain(limit), dialect)[100] == 1
    assert alarm(chain(limit + 1), dialect)[0] == 77


def test_recursion_stops_at_the_nesting_limit():
    assert alarm(lines("G65 P9500", "M30", "O9500", "G65 P9500", "M99"))[0] == 122
    assert alarm(lines("M98 P500", "M30", "O0500", "M98 P500", "M99"))[0] == 77


def test_program_not_found_is_alarm_76():
    assert alarm(lines("G65 P1234", "M30")) == (76, 1)
    assert alarm(lines("M98 P1234", "M30")) == (76, 1)


def test_programs_are_found_across_files(tmp_path):
    (tmp_path / "O9100.nc").write_text("O9100\n#100=#1\nM99\n")
    (tmp_path / "9200.NC").write_text("#101=#2\nM99\n")  # named by its file, no header
    (tmp_path / "lib.nc").write_text("O9300\n#102=#3\nM99\n")  # found by its header
    (tmp_path / "O9400.CNC").write_text("O9400 (WRONG NAME INSIDE)\nM99\n")
    v = final(lines("G65 P9100 A1", "G65 P9200 B2", "G65 P9300 C3", "M30"), folder=tmp_path)
    assert v[100] == 1 and v[101] == 2 and v[102] == 3


def test_gsk_bracketed_program_names(tmp_path):
    (tmp_path / "CUT.CNC").write_text("#100=#1\nM99\n")
    (tmp_path / "O1004.nc").write_text("O1004\n#101=#101+1\nM99\n")
    (tmp_path / "螺纹切削.nc").write_text("#102=1\nM99\n".encode("gb18030").decode("gb18030"), encoding="gb18030")
    program = lines("G65 P[CUT] A5", "M98 P[O1004] L3", "#110=1004", "G65 P[#110]", "G65 P[螺纹切削]", "M30")
    v = final(program, "gsk980tdi", folder=tmp_path)
    assert v[100] == 5 and v[101] == 4 and v[102] == 1


def test_a_gsk_call_by_file_name_runs_the_program_after_the_dialect_comment(tmp_path):
    (tmp_path / "CUT.CNC").write_text("%\n(cncmacro: dialect=gsk980tdi)\nO0005 (CUT)\n#100=#1\nM99\n%\n")
    v = final(lines("G65 P[CUT] A5", "M30"), "gsk980tdi", folder=tmp_path)
    assert v[100] == 5


def test_gsk_p_from_a_variable_with_too_many_digits_is_alarm_291(tmp_path):
    # seed 001: #100=21234 -> alarm 291
    assert alarm(lines("#100=21234", "G65 P[#100] L2", "M30"), "gsk980tdi", folder=tmp_path) == (291, 2)
    assert alarm(lines("#100=21234", "G65 P#100", "M30"), "gsk980tdi")[0] == 291


def test_5_gsk_m98_p_bracket_variable_is_a_program_name_only_alarm_291(tmp_path):
    # seed 002 M98 format two: in P[#100] the variable names the program; 21234 is alarm 291
    assert alarm(lines("#100=21234", "M98 P[#100] L3", "M30"), "gsk980tdi", folder=tmp_path) == (291, 2)
    called = lines("#100=23.34", "M98 P[#100] L3", "M30", "O0023", "#101=#101+1", "M99")
    assert final(called, "gsk980tdi")[101] == 3  # O0023, three times
    # on fanuc the brackets are only an expression: P[#100] is P#100, count and program
    assert final(lines("#100=30040", "M98 P[#100]", "M30", "O0040", "#101=#101+1", "M99"))[101] == 3


@pytest.mark.parametrize("name", ["../secret", "..", "a/../secret", "/etc/passwd", "sub\\secret"])
def test_a_path_in_a_program_name_is_never_read(tmp_path, name):
    from cncmacro.library.programs import ProgramLibrary

    (tmp_path / "secret.nc").write_text("#100=1\nM99\n")
    inner = tmp_path / "work"
    inner.mkdir()
    (inner / "OK.nc").write_text("M99\n")
    library = ProgramLibrary()
    near = library.add_text(str(inner / "MAIN.nc"), "M30\n")
    assert library.find_name(name, near) is None
    assert library.find_name("secret", near) is None  # not in the caller's folder
    assert library.find_name("OK", near) is not None


def test_macro_call_codes_from_the_machine_file():
    from cncmacro.library.machine_file import CallCode

    calls = {"G100": CallCode(9010, "macro"), "M50": CallCode(9020, "macro"), "M60": CallCode(9001, "subprogram")}
    program = lines(
        "#1=77",
        "G100 X5 Y6",
        "M50 A3",
        "M60",
        "M30",
        "O9010",
        "#100=#24+#25",
        "G100",  # inside a G-code call a G code is an ordinary code
        "M99",
        "O9020",
        "#101=#1",
        "M99",
        "O9001",
        "#102=#1",  # a subprogram call keeps the caller's locals
        "M99",
    )
    v = final(program, calls=calls)
    assert v[100] == 11 and v[101] == 3 and v[102] == 77


def test_5_calls_a_call_code_with_l_above_9999_is_clamped_with_a_note_on_gsk():
    from cncmacro.library.machine_file import CallCode

    program = lines("M50 L12000 A3", "M30", "O9020", "#100=#100+#1", "M99")
    m = run(program, "gsk980tdi", calls={"M50": CallCode(9020, "macro")}, max_blocks=200_000)
    assert m.status == "completed" and m.variables()[100] == 3 * 9999
    assert [(n.kind, n.line) for n in m.notes] == [("call", 0)]
    assert "9999" in m.notes[0].message


def test_5_calls_a_standard_g_code_in_calls_is_no_call_on_gsk980tdi_and_a_call_on_fanuc():
    # GSK980TDi manual §3.32: a code set equal to a standard G code disables the call, so
    # [calls] G90 = 2000 leaves G90 the turning cycle: from X50 Z2 it cuts to X40 Z-20 and
    # O2000 (#100=1) never runs; FANUC calls O2000 for any code its parameters name
    from cncmacro.library.machine_file import CallCode

    calls = {"G90": CallCode(2000)}
    program = lines("G00 X50 Z2", "G90 X40 Z-20 F100", "M30", "O2000", "#100=1", "M99")
    m = run(program, "gsk980tdi", calls=calls)
    assert m.status == "completed" and 100 not in m.variables()
    cut = m.planner.moves[1]  # X, Y, Z, C, B
    assert (cut.line, cut.mode, cut.end[0], cut.end[2]) == (1, 90.0, 40.0, -20.0)
    assert final(program, "fanuc", calls=calls)[100] == 1


def test_5_calls_m99_p_in_a_main_program_goes_on_from_that_label():
    """M99 P5 jumps to N5 of the main program; the plain M99 after it restarts the program."""
    program = lines("#100=#100+1", "IF[#100 GE 3] GOTO 9", "M99 P5", "N9 M30", "N5 #101=#101+1", "M99")
    m = run(program, max_blocks=1000)
    assert m.status == "completed" and m.variables()[100] == 3 and m.variables()[101] == 2


def test_5_calls_m99_p_in_a_main_program_to_a_missing_label_alarms():
    m = run(lines("#1=1", "M99 P77", "M30"))
    assert m.status == "alarm" and m.alarm.number == 128 and m.alarm.line == 1


def test_t_code_calls_a_subprogram_with_the_t_value_in_149():
    from cncmacro.library.machine_file import CallCode

    program = lines("T0505", "M30", "O9000", "#100=#149", "M99")
    v = final(program, calls={"T": CallCode(9000, "subprogram")})
    assert v[100] == 505


def test_gsk_m98_without_p_calls_the_current_program_at_q():
    program = lines("#1=0", "M98 Q50", "M30", "N50 #100=#100+1", "M99")
    v = final(program, "gsk980tdi")
    assert v[100] == 1  # seed 002 format 3: the call starts at N50 and M99 returns to M30


def test_g66_counts_as_a_macro_level():
    # main -> G65 (1) -> G65 (2) -> G65 (3) -> G66 call (4) works; one more G65 inside is the 5th
    def program(extra: str) -> str:
        return lines(
            "G65 P9101",
            "M30",
            "O9101",
            "G65 P9102",
            "M99",
            "O9102",
            "G65 P9103",
            "M99",
            "O9103",
            "G66 P9104",
            "G00 X1",
            "G67",
            "M99",
            "O9104",
            extra,
            "#100=1",
            "M99",
            "O9105",
            "M99",
        )

    assert final(program("#1=1"))[100] == 1
    assert alarm(program("G65 P9105"))[0] == 122


def test_5_g66_on_gsk980tdi_calls_only_after_a_g00_g01_g02_g03_or_g05_block():
    # GSK980TDi manual §3.28.3.2 note 2: "执行完有 G00、G01、G02、G03、G05 代码的程序段后…将再次调用宏程序"
    # (Dialect.modal_call_codes): the code that moves the block (its one-shot code, else the motion
    # mode in force) must be one of them. O0100 counts its calls in #100 and its last caller's block
    # by the position it sees (#5001 X, #5003 Z).
    program = lines(
        "G00 X100 Z50",
        "G66 P0100",
        "G01 X90 F100",  # G01: call 1
        "X85",  # G01 still in force: call 2
        "G90 X80 Z40 F100",  # a turning cycle: no call
        "X70",  # the cycle again: no call
        "G00 X90 Z50",  # G00: call 3
        "G32 Z45 F1.5",  # a thread: no call
        "G31 Z40 F100",  # a skip: no call
        "G00 X40 Z0",  # call 4
        "G6.2 U20 W-10 A20 B10 Q0",  # an ellipse: no call
        "G28 U0 W0",  # the reference point: no call
        "G53 X0 Z0",  # machine coordinates: no call
        "G00 X50 Z5",  # call 5
        "G05 X50 Z-5 I5 K-5",  # a three-point arc: call 6
        "G02 X50 Z-15 R5",  # call 7
        "G67",
        "M30",
        "O0100",
        "#100=#100+1",
        "M99",
    )
    assert final(program, "gsk980tdi")[100] == 7


def test_5_g66_on_fanuc_calls_after_any_block_with_a_move_command():
    # FANUC (seed 003 §8.3: the macro is called after a block with a move command): a turning cycle
    # and G28 call too, as before
    program = lines("G00 X100 Z50", "G66 P0100", "G90 X80 Z40 F100", "G28 U0 W0", "G01 X90 F100", "G67", "M30",
                    "O0100", "#100=#100+1", "M99")  # fmt: skip
    assert final(program, "fanuc-0i-lathe")[100] == 3


def test_5_a_g65_call_cancels_g66_on_gsk980tdi():
    # GSK980TDi manual §3.28.3.2 note 4: "G65 调用会自动取消 G66 模态调用" (Dialect.g65_cancels_modal_call).
    # O0100 adds its A to #100 at each modal call, O0101 its B to #101:
    #   G01 X90: a modal call, #100 = 1; G65 P0101 B2: #101 = 2, and the G66 ends (#4012 = 67);
    #   G01 X80, G01 X70: no call, #100 stays 1.
    program = lines(
        "G00 X100 Z50",
        "G66 P0100 A1",
        "G01 X90 F100",
        "G65 P0101 B2",
        "#102=#4012",
        "G01 X80",
        "G01 X70",
        "M30",
        "O0100",
        "#100=#100+#1",
        "M99",
        "O0101",
        "#101=#101+#2",
        "M99",
    )
    v = final(program, "gsk980tdi")
    assert (v[100], v[101], v[102]) == (1, 2, 67)
    # FANUC's manuals say nothing of it: the G66 stays, X80 and X70 call O0100 (3 calls), #4012 = 66
    v = final(program, "fanuc-0i-lathe")
    assert (v[100], v[101], v[102]) == (3, 2, 66)
