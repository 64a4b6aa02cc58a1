"""Static diagnostics of docs/semantics.md §5 "Calls" and §7 (the GSK macro A form): call words,
argument addresses, repeat counts, program numbers and programs that do not exist."""

from __future__ import annotations

from pathlib import Path

from cncmacro.library.machine_file import CallCode, MachineSettings
from cncmacro.library.programs import ProgramLibrary
from running import alarm, final, run
from static_helpers import at, check, coded, lines

# ---------------------------------------------------------------- g65-nc-words


def test_5_calls_a_modal_g_code_before_g65_is_alarm_127_on_gsk980tdi():
    text = lines("O1000", "G54 G65 P1001 A1", "M30", "O1001", "M99")
    [d] = coded(check(text, "gsk980tdi"), "g65-nc-words")
    assert at(d) == (2, 0, 3, "error")
    assert "G54 before G65" in d.message and "alarm 127" in d.message
    assert alarm(text, "gsk980tdi") == (127, 2)


def test_5_calls_a_modal_g_code_before_g65_is_a_hint_on_fanuc_that_says_what_the_control_does():
    text = lines("O1000", "G90 G54 G65 P1001 A1", "M30", "O1001", "M99")
    [d] = coded(check(text), "g65-nc-words")
    assert at(d) == (2, 0, 7, "hint")
    assert "sets G90 G54 (it stays in force) and then G65 calls the macro" in d.message
    [zh] = coded(check(text, locale="zh-CN"), "g65-nc-words")
    assert "先执行 G90 G54" in zh.message
    g66 = lines("O1000", "G54 G66 P1001 A1", "G67", "M30", "O1001", "M99")
    assert [at(d) for d in coded(check(g66), "g65-nc-words")] == [(2, 0, 3, "hint")]


def test_5_calls_a_modal_g_code_before_g65_takes_effect_and_the_macro_is_called_on_fanuc():
    text = lines("G55 G65 P1001 A7", "#101=#4014", "M30", "O1001", "#100=#1", "#102=#4014", "M99")
    assert final(text) == {100: 7, 101: 55, 102: 55}
    modal = lines("G91 G66 P1001 A2", "G00 X5", "G67", "#101=#4003", "M30", "O1001", "#100=#1", "M99")
    assert final(modal) == {100: 2, 101: 91}


def test_5_calls_other_words_before_g65_are_alarm_127_on_fanuc_too():
    for before in ("X10", "M03", "G04", "G67"):
        text = lines("O1000", f"{before} G65 P1001 A1", "M30", "O1001", "M99")
        [d] = coded(check(text), "g65-nc-words")
        assert at(d)[3] == "error", before
        assert alarm(text) == (127, 2), before


def test_5_calls_g66_with_an_o_word_after_it_is_an_error_on_gsk980tdi():
    found = coded(check(lines("O1000", "G66 P1000 O5", "M30"), "gsk980tdi"), "g65-nc-words")
    assert [at(d) for d in found] == [(2, 10, 12, "error")]


def test_5_calls_only_n_before_g65_and_m_after_it_is_an_argument():
    assert check(lines("O1000", "N5 G65 P1000 A1 M3", "M30", "O1001", "M99"), file="X.nc") == []


# ---------------------------------------------------------------- argument-address


def test_5_calls_g_after_g65_is_argument_address_alarm_129():
    text = lines("O1000", "G65 P1000 A1 G01", "M30")
    found = coded(check(text), "argument-address")
    assert [at(d) for d in found] == [(2, 13, 16, "error")]
    assert alarm(text) == (129, 2)


def test_5_calls_n_or_eleven_i_arguments_are_refused():
    found = coded(check(lines("O1000", "G65 P1000 A1 N5", "M30")), "argument-address")
    assert [at(d) for d in found] == [(2, 13, 15, "error")]
    eleven = "G65 P1000 " + " ".join(f"I{k}" for k in range(11))
    found = coded(check(lines("O1000", eleven, "M30")), "argument-address")
    assert [at(d) for d in found] == [(2, len(eleven) - 3, len(eleven), "error")]


def test_5_calls_argument_specification_ii_is_fine_on_both_dialects():
    text = lines("O1000", "G65 P1000 A1 B2 C3 I14 J15 I6 J7 K9 K11 K12 J30", "M30")
    assert coded(check(text), "argument-address") == []
    assert coded(check(text, "gsk980tdi"), "argument-address") == []


def test_5_calls_j_before_i_in_a_set_is_an_argument_order_warning_on_fanuc():
    # docs/semantics.md §5, seed 004: "J_I_" is wrong; the value still goes where the letter says
    text = lines("O1000", "G65 P1001 B1. A2. D3. J4. I5.", "M30", "O1001", "M99")
    [d] = coded(check(text), "argument-order")
    assert at(d) == (2, 26, 29, "warning")
    assert "I after J" in d.message and "#4" in d.message
    assert "系统仍把它赋给 #4" in coded(check(text, locale="zh-CN"), "argument-order")[0].message
    second_set = lines("O1000", "G65 P1001 I1. J2. K3. I4. K5. J6.", "M30", "O1001", "M99")
    assert [at(d)[:2] for d in coded(check(second_set), "argument-order")] == [(2, 30)]
    assert coded(check(text, "gsk980tdi"), "argument-order") == []  # GSK's manuals ask for no order


def test_5_calls_i_before_j_gives_no_argument_order_warning():
    text = lines("O1000", "G65 P1001 B1. A2. D3. I5. J4.", "G65 P1001 I1 J2 K3 I4 J5 K6", "M30", "O1001", "M99")
    assert coded(check(text), "argument-order") == []


def test_5_calls_configured_call_code_takes_arguments_like_g65():
    settings = MachineSettings(calls={"G100": CallCode(9010)})
    text = lines("O1000", "G100 A1 P5", "M30", "O9010", "M99")
    found = coded(check(text, settings=settings), "argument-address")
    assert [at(d) for d in found] == [(2, 8, 10, "error")]
    assert check(lines("O1000", "G100 A1 B2", "M30", "O9010", "M99"), settings=settings) == []


def test_5_calls_a_standard_g_code_in_calls_is_no_call_on_gsk980tdi_and_a_call_on_fanuc(tmp_path: Path):
    # [calls] G90 = 2000 with no O2000 anywhere: on GSK980TDi G90 stays the turning cycle
    # (manual §3.32), nothing is called, nothing is missing; FANUC calls O2000, not found
    settings = MachineSettings(calls={"G90": CallCode(2000)})
    main = str(tmp_path / "MAIN.nc")
    text = lines("O1000", "G00 X50 Z2", "G90 X40 Z-20 F100", "M30")
    assert check(text, "gsk980tdi", file=main, library=ProgramLibrary(), settings=settings) == []
    found = coded(check(text, file=main, library=ProgramLibrary(), settings=settings), "program-not-found")
    assert [at(d)[0] for d in found] == [3] and "O2000" in found[0].message


# ---------------------------------------------------------------- repeat-count-range


def test_5_calls_l0_is_an_error_on_both_dialects():
    text = lines("O1000", "G65 P1000 L0 A1", "M30")
    for dialect in ("fanuc", "gsk980tdi"):
        found = coded(check(text, dialect), "repeat-count-range")
        assert [at(d) for d in found] == [(2, 10, 12, "error")]


def test_5_calls_l_above_9999_is_an_error_on_fanuc_and_a_warning_on_gsk980tdi():
    text = lines("O1000", "M98 P2000 L10000", "M30", "O2000", "M99")
    assert [at(d) for d in coded(check(text), "repeat-count-range")] == [(2, 10, 16, "error")]
    assert [at(d) for d in coded(check(text, "gsk980tdi"), "repeat-count-range")] == [(2, 10, 16, "warning")]
    assert check(lines("O1000", "M98 P2000 L9999", "M30", "O2000", "M99")) == []


def test_5_calls_count_in_p_and_l_is_alarm_293_on_gsk980tdi_and_a_warning_on_fanuc():
    text = lines("O1000", "M98 P32000 L2", "M30", "O2000", "M99")
    found = coded(check(text, "gsk980tdi"), "repeat-count-range")
    assert [at(d) for d in found] == [(2, 11, 13, "error")]
    assert "293" in found[0].message
    assert alarm(text, "gsk980tdi")[0] == 293
    assert [at(d) for d in coded(check(text), "repeat-count-range")] == [(2, 11, 13, "warning")]


def test_5_calls_count_in_p_and_l_the_check_and_the_run_name_the_same_p_and_l_on_gsk980tdi():
    # M98 P29013 L2: P's leading digit 2 is a count (O9013 twice), and L2 gives it again; the
    # check and the run both write the block's own P and L, never an L the check made up
    text = lines("O1000", "M98 P29013 L2", "M30", "O9013", "M99")
    [d] = coded(check(text, "gsk980tdi"), "repeat-count-range")
    assert d.message == "P29013 L2: the count is given in both P and L (alarm 293)"
    [zh] = coded(check(text, "gsk980tdi", locale="zh-CN"), "repeat-count-range")
    assert zh.message.startswith("P29013 L2：P 和 L 同时指定了调用次数")
    m = run(text, "gsk980tdi")
    assert m.alarm is not None and m.alarm.describe() == "alarm 293: P29013 L2: the count is given in both P and L"


def test_5_calls_count_in_p_alone_is_fine():
    assert check(lines("O1000", "M98 P32000", "M30", "O2000", "M99")) == []


# ---------------------------------------------------------------- program-number


def test_5_calls_g65_p_with_five_digits_is_a_program_number_error_on_gsk980tdi_only():
    text = lines("O1000", "G65 P12345 A1", "M30", "O12345", "M99")
    found = coded(check(text, "gsk980tdi"), "program-number")
    assert [at(d) for d in found] == [(2, 4, 10, "error")]
    assert alarm(text, "gsk980tdi")[0] == 291
    assert coded(check(text), "program-number") == []


def test_5_calls_m98_p_with_more_than_eight_digits_is_a_program_number_error():
    found = coded(check(lines("O1000", "M98 P123456789", "M30")), "program-number")
    assert [at(d) for d in found] == [(2, 4, 14, "error")]


def test_5_calls_a_bracketed_name_with_a_character_outside_the_name_set_is_program_number(tmp_path: Path):
    # seed 001 P[] format two: letters, digits and + - _ . only; any other character is an alarm
    text = lines("O1000", "G65 P[A*B] L2", "M98 P[X=1]", "G66 P[CUT+1_A.B]", "G67", "M30")
    found = check(text, "gsk980tdi", file=str(tmp_path / "MAIN.nc"), library=ProgramLibrary())
    bad = coded(found, "program-number")
    assert [at(d) for d in bad] == [(2, 4, 10, "error"), (3, 4, 10, "error")]
    assert "P[A*B]: a program name may hold only letters, digits and + - _ ." in bad[0].message
    assert [at(d)[0] for d in coded(found, "program-not-found")] == [4]  # a good name, only missing
    assert alarm(lines("G65 P[A*B] L2", "M30"), "gsk980tdi", folder=tmp_path) == (291, 1)
    assert alarm(lines("M98 P[A*B]", "M30"), "gsk980tdi", folder=tmp_path) == (291, 1)


# ---------------------------------------------------------------- program-not-found


def test_5_calls_program_not_found_in_the_file_or_its_folder(tmp_path: Path):
    (tmp_path / "O8100.nc").write_text("O8100\nM99\n")
    main = str(tmp_path / "MAIN.nc")
    text = lines("O1000", "G65 P8100 A1", "G65 P8200 A1", "M98 P8300", "M98 P0040", "M30", "O0040", "M99")
    found = coded(check(text, file=main, library=ProgramLibrary()), "program-not-found")
    assert [at(d) for d in found] == [(3, 4, 9, "error"), (4, 4, 9, "error")]
    assert "O8200" in found[0].message


def test_5_calls_to_the_9000_series_are_the_controls(tmp_path: Path):
    # FANUC keeps O9000-O9999 protected in its memory (parameter 3202 NE9), where the probe
    # maker's macros live: not in the folder, so a call to one is no program-not-found
    main = str(tmp_path / "MAIN.nc")
    text = lines("O1000", "G65 P9810 Z10. F3000.", "G65 P9814 D52. Z-8.", "M98 P9300", "M30")
    for profile in ("fanuc-0i", "fanuc-30i", "fanuc-0i-lathe", "mazak-eia", "mitsubishi-m70", "haas"):
        assert coded(check(text, profile, file=main, library=ProgramLibrary()), "program-not-found") == [], profile
    found = coded(check(text, "gsk980tdi", file=main, library=ProgramLibrary()), "program-not-found")
    assert [at(d)[0] for d in found] == [2, 3, 4]  # no source puts the GSK's there


def test_5_calls_program_not_found_by_a_bracketed_name_on_gsk980tdi(tmp_path: Path):
    (tmp_path / "CUT.CNC").write_text("G00 X1\nM99\n")
    main = str(tmp_path / "MAIN.CNC")
    text = lines("O1000", "G65 P[CUT]", "G65 P[CUTS]", "M30")
    found = coded(check(text, "gsk980tdi", file=main, library=ProgramLibrary()), "program-not-found")
    assert [at(d) for d in found] == [(3, 4, 11, "error")]


def test_5_calls_configured_call_code_to_a_missing_program_is_reported(tmp_path: Path):
    settings = MachineSettings(calls={"M60": CallCode(8001, "subprogram")})
    main = str(tmp_path / "MAIN.nc")
    text = lines("O1000", "G00 X1 M60", "M30")
    found = coded(check(text, file=main, library=ProgramLibrary(), settings=settings), "program-not-found")
    assert [at(d) for d in found] == [(2, 7, 10, "error")]
    (tmp_path / "O8001.nc").write_text("O8001\nM99\n")
    assert check(text, file=main, library=ProgramLibrary(), settings=settings) == []


def test_5_calls_without_a_library_only_the_files_own_programs_are_known():
    assert check(lines("O1000", "G65 P9100 A1", "M30")) == []


def test_5_calls_g65_without_p_is_program_not_found():
    found = coded(check(lines("O1000", "G65 A1", "M30")), "program-not-found")
    assert [at(d) for d in found] == [(2, 0, 3, "error")]


# ---------------------------------------------------------------- dialect-feature (calls)


def test_7_g65_h_codes_are_a_dialect_feature_on_fanuc_only():
    text = lines("O1000", "G65 H01 P#100 Q5", "M30")
    found = coded(check(text), "dialect-feature")
    assert [at(d) for d in found] == [(2, 4, 7, "error")]
    assert check(text, "gsk980tdi") == []


def test_5_calls_bracketed_program_name_is_a_dialect_feature_on_fanuc():
    text = lines("O1000", "G65 P[CUT] A1", "M30")
    assert [at(d) for d in coded(check(text), "dialect-feature")] == [(2, 4, 10, "error")]
    assert coded(check(text, "gsk980tdi"), "dialect-feature") == []


def test_7_h_code_with_another_address_or_unknown_operation_is_refused_on_gsk980tdi():
    found = coded(check(lines("O1000", "G65 H01 P#100 Q5 X1", "M30"), "gsk980tdi"), "argument-address")
    assert [at(d) for d in found] == [(2, 17, 19, "error")]
    found = coded(check(lines("O1000", "G65 H07 P#100 Q5", "M30"), "gsk980tdi"), "argument-address")
    assert [at(d) for d in found] == [(2, 4, 7, "error")]


def test_5_calls_plain_cam_lines_with_calls_are_checked():
    found = check(lines("O1000", "G01 X1. Y2.", "M98 P2000 L0", "M30", "O2000", "M99"))
    assert [(d.code, *at(d)) for d in found] == [("repeat-count-range", 3, 10, 12, "error")]


def test_7_g65_p_then_h_is_a_call_whose_h_is_argument_11_on_gsk980tdi():
    # §3.28.3.1 specification I: H is #11; P comes first, so these are calls, not H codes
    for block in ("G65 P9013 A1 H5", "G65 P9013 H5", "G65 P9013 L2 H5"):
        assert check(lines("O1000", block, "M30", "O9013", "M99"), "gsk980tdi") == [], block


# ---------------------------------------------------------------- g65-word-order


def test_5_calls_p_or_h_right_after_g65_else_a_warning_on_gsk980tdi():
    # §3.28.3 note 3: "紧跟其后要出现P或H代码字"; the manual gives no alarm number: a warning
    text = lines("O1000", "G65 A1 P9013", "G65 L2 P9013 A1", "G66 A1 P9013", "G67", "M30", "O9013", "M99")
    found = coded(check(text, "gsk980tdi"), "g65-word-order")
    assert [at(d) for d in found] == [(2, 4, 6, "warning"), (3, 4, 6, "warning"), (4, 4, 6, "warning")]
    assert "P or H" in found[0].message and "write P right after G65" in found[0].message
    [zh] = coded(check(lines("O1000", "G65 A1 P9013", "M30"), "gsk980tdi", locale="zh-CN"), "g65-word-order")
    assert "紧跟 P或H" in zh.message
    # P or H first: no finding; on fanuc the order is free
    fine = lines("O1000", "G65 P9013 A1", "G65 H01 P#100 Q1", "G66 P9013 A1", "G67", "M30", "O9013", "M99")
    assert coded(check(fine, "gsk980tdi"), "g65-word-order") == []
    assert coded(check(text), "g65-word-order") == []
    # the block still runs as a call of O9013
    assert final(lines("G65 L2 P9013 A1", "M30", "O9013", "#100=#100+#1", "M99"), "gsk980tdi") == {100: 2}
