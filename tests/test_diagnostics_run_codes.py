"""Diagnostics found by running (docs/design.md "Diagnostic codes"): each run-found code at the
right file and line with the right severity, and a near miss that does not trigger it."""

from __future__ import annotations

from pathlib import Path

from analysis_helpers import analyse_files as analyse
from cncmacro.analysis.diagnostics import Diagnostic


def found(diags: list[Diagnostic], code: str) -> list[tuple[str, int, str]]:
    """(file name, 1-based line, severity) of each diagnostic with ``code``."""
    return [(Path(d.file).name, d.line + 1, d.severity) for d in diags if d.code == code]


def test_3_expressions_division_by_zero_found_by_running(tmp_path):
    diags = analyse(tmp_path, {"O0001.nc": "O0001\n#1=0\n#2=5/#1\nM30\n"})
    assert found(diags, "division-by-zero") == [("O0001.nc", 3, "error")]
    near = analyse(tmp_path, {"O0001.nc": "O0001\n#1=2\n#2=5/#1\nM30\n"})
    assert found(near, "division-by-zero") == []


def test_3_expressions_sqrt_of_a_negative_is_argument_range(tmp_path):
    diags = analyse(tmp_path, {"O0001.nc": "O0001\n#1=-4\n#2=SQRT[#1]\nM30\n"})
    assert found(diags, "argument-range") == [("O0001.nc", 3, "error")]
    assert found(analyse(tmp_path, {"O0001.nc": "O0001\n#1=4\n#2=SQRT[#1]\nM30\n"}), "argument-range") == []


def test_4_control_flow_computed_goto_to_a_missing_label(tmp_path):
    diags = analyse(tmp_path, {"O0001.nc": "O0001\n#1=20\nGOTO#1\nN10 M30\n"})
    assert found(diags, "undefined-label") == [("O0001.nc", 3, "error")]
    near = analyse(tmp_path, {"O0001.nc": "O0001\n#1=10\nGOTO#1\nN10 M30\n"})
    assert found(near, "undefined-label") == []


def test_5_calls_computed_l_out_of_range_is_an_error_on_fanuc(tmp_path):
    files = {"MAIN.nc": "O0001\n#1=0\nG65 P9001 L#1\nM30\n", "O9001.nc": "O9001\nM99\n"}
    assert found(analyse(tmp_path, files), "repeat-count-range") == [("MAIN.nc", 3, "error")]
    files["MAIN.nc"] = "O0001\n#1=2\nG65 P9001 L#1\nM30\n"
    assert found(analyse(tmp_path, files), "repeat-count-range") == []


def test_5_calls_computed_l_above_9999_is_clamped_with_a_warning_on_gsk980tdi(tmp_path):
    files = {"MAIN.nc": "O0001\n#1=10000\nG65 P9001 L#1\nM30\n", "O9001.nc": "O9001\nM99\n"}
    assert found(analyse(tmp_path, files, dialect="gsk980tdi"), "repeat-count-range") == [("MAIN.nc", 3, "warning")]
    assert found(analyse(tmp_path, files, dialect="fanuc"), "repeat-count-range") == [("MAIN.nc", 3, "error")]


def test_5_calls_macro_nesting_beyond_four_levels(tmp_path):
    files = {"MAIN.nc": "O0001\nG65 P9001\nM30\n", "O9001.nc": "O9001\n#1=#1+1\nG65 P9001\nM99\n"}
    assert found(analyse(tmp_path, files), "nesting-depth") == [("O9001.nc", 3, "error")]


def test_5_calls_computed_program_not_found(tmp_path):
    diags = analyse(tmp_path, {"O0001.nc": "O0001\n#1=8876\nG65 P#1\nM30\n"})  # not the control's 9000s
    assert found(diags, "program-not-found") == [("O0001.nc", 3, "error")]
    near = analyse(tmp_path, {"O0001.nc": "O0001\n#1=9001\nG65 P#1\nM30\n", "O9001.nc": "O9001\nM99\n"})
    assert found(near, "program-not-found") == []


def test_6_alarms_macro_alarm_shows_number_and_text(tmp_path):
    # a main program that sets #1 itself reaches the alarm on every run: an error
    diags = analyse(tmp_path, {"O0001.nc": "O0001\n#1=1\nIF[#1 EQ 1] THEN #3000=7(TOOL BROKEN)\nM30\n"})
    [d] = [d for d in diags if d.code == "macro-alarm"]
    assert (d.line + 1, d.severity) == (3, "error")
    assert "3007" in d.message and "TOOL BROKEN" in d.message
    near = analyse(tmp_path, {"O0001.nc": "O0001\n#1=2\nIF[#1 EQ 1] THEN #3000=7(TOOL BROKEN)\nM30\n"})
    assert found(near, "macro-alarm") == []


def test_7_h_codes_h99_is_a_macro_alarm_on_gsk980tdi(tmp_path):
    diags = analyse(tmp_path, {"O0001.nc": "O0001\nG65 H99 P15\nM30\n"}, dialect="gsk980tdi")
    [d] = [d for d in diags if d.code == "macro-alarm"]
    assert d.line == 1 and "5915" in d.message
    text = "O0001\nG65 H99 P15(/用户自定义报警)\nM30\n"
    [d] = [d for d in analyse(tmp_path, {"O0001.nc": text}, dialect="gsk980tdi") if d.code == "macro-alarm"]
    assert d.message == "the run reaches macro alarm 5915: 用户自定义报警"


def test_5_calls_vacant_argument_names_the_letter_and_the_caller(tmp_path):
    files = {"MAIN.nc": "O0001\nG65 P9001 Y2.\nM30\n", "O9001.nc": "O9001\n#100=#24+#25\nM99\n"}
    diags = analyse(tmp_path, files)
    [d] = [d for d in diags if d.code == "vacant-argument"]
    assert (Path(d.file).name, d.line + 1, d.severity) == ("O9001.nc", 2, "information")
    assert "#24 (X)" in d.message and "O0001" in d.message
    assert [(Path(r.file).name, r.line + 1) for r in d.related] == [("MAIN.nc", 2)]


def test_5_calls_testing_an_argument_for_vacant_is_not_a_vacant_argument_read(tmp_path):
    files = {"MAIN.nc": "O0001\nG65 P9001 Y2.\nM30\n",
             "O9001.nc": "O9001\nIF[#24 EQ #0] THEN #24=0\n#100=#24+#25\nM99\n"}  # fmt: skip
    assert found(analyse(tmp_path, files), "vacant-argument") == []


def test_2_values_main_program_locals_are_never_vacant_arguments(tmp_path):
    assert found(analyse(tmp_path, {"O0001.nc": "O0001\n#100=#24\nM30\n"}), "vacant-argument") == []


def test_5_calls_finding_in_a_macro_appears_in_its_file_with_the_caller_related(tmp_path):
    files = {"MAIN.nc": "O0001\nG65 P9001 A0\nM30\n", "O9001.nc": "O9001\n#2=1/#1\nM99\n"}
    diags = analyse(tmp_path, files)
    [d] = [d for d in diags if d.code == "division-by-zero"]
    assert Path(d.file).name == "O9001.nc" and d.line == 1
    assert [(Path(r.file).name, r.line) for r in d.related] == [("MAIN.nc", 1)]
    assert "O0001:2 (G65)" in d.message


def test_4_control_flow_endless_loop_stops_at_the_run_limit(tmp_path):
    diags = analyse(tmp_path, {"O0001.nc": "O0001\nN1 #1=#1+1\nGOTO1\nM30\n"}, max_blocks=1000)
    [(name, line, severity)] = found(diags, "run-limit")
    assert name == "O0001.nc" and line in (2, 3) and severity == "information"
    assert found(analyse(tmp_path, {"O0001.nc": "O0001\n#1=#1+1\nM30\n"}, max_blocks=1000), "run-limit") == []


def test_4_control_flow_not_executed_covers_exactly_the_unreached_blocks(tmp_path):
    text = "O0001\n#1=1\nIF[#1 EQ 1] GOTO 10\n#2=2\n(COMMENT)\n#3=3\nN10 M30\n"
    diags = analyse(tmp_path, {"O0001.nc": text})
    [d] = [d for d in diags if d.code == "not-executed"]
    assert (d.line + 1, d.end_line + 1, d.severity, d.tags) == (4, 6, "hint", ("unnecessary",))
    assert found(analyse(tmp_path, {"O0001.nc": "O0001\n#1=1\n(ONLY A COMMENT)\nM30\n"}), "not-executed") == []


def test_5_calls_a_program_no_run_enters_gets_no_not_executed(tmp_path):
    files = {"MAIN.nc": "O0001\n#1=1\nIF[#1 EQ 1] GOTO 10\nG65 P9001\nN10 M30\n", "O9001.nc": "O9001\n#5=1\nM99\n"}
    diags = analyse(tmp_path, files)
    assert [(Path(d.file).name, d.line + 1) for d in diags if d.code == "not-executed"] == [("MAIN.nc", 4)]


def test_5_calls_same_finding_in_a_loop_is_reported_once(tmp_path):
    files = {"MAIN.nc": "O0001\n#1=0\nWHILE[#1 LT 5] DO1\nG65 P9001\n#1=#1+1\nEND1\nM30\n",
             "O9001.nc": "O9001\n#100=#24\nM99\n"}  # fmt: skip
    assert found(analyse(tmp_path, files), "vacant-argument") == [("O9001.nc", 2, "information")]


def test_2_values_vacant_on_gsk980tdi_passes_an_explicit_vacant_argument_as_zero(tmp_path):
    # fanuc drops a vacant argument (the macro finds it vacant); gsk980tdi passes it as 0
    files = {"MAIN.nc": "O0001\nG65 P9001 X#10\nM30\n", "O9001.nc": "O9001\n#100=#24\nM99\n"}
    assert found(analyse(tmp_path, files, dialect="fanuc"), "vacant-argument") == [("O9001.nc", 2, "information")]
    assert found(analyse(tmp_path, files, dialect="gsk980tdi"), "vacant-argument") == []


def test_messages_in_chinese(tmp_path):
    diags = analyse(tmp_path, {"O0001.nc": "O0001\n#1=0\n#2=5/#1\nM30\n"}, locale="zh-CN")
    [d] = [d for d in diags if d.code == "division-by-zero"]
    assert "除数为零" in d.message


def test_static_finding_on_the_same_line_is_not_repeated_by_the_run(tmp_path):
    diags = analyse(tmp_path, {"O0001.nc": "O0001\n#2=5/0\nM30\n"})
    assert len([d for d in diags if d.line == 1 and d.severity == "error"]) == 1


def test_5_calls_a_called_program_no_caller_reaches_is_not_run_with_vacant_arguments(tmp_path):
    macro = "O9001\nIF[#20 EQ #0] THEN #3000=1(T MISSING)\n#2=1/#20\nM99\n"
    files = {"MAIN.nc": "O0001\n#1=1\nIF[#1 EQ 1] GOTO 10\nG65 P9001 T2.\nN10 M30\n", "O9001.nc": macro}
    diags = analyse(tmp_path, files)
    assert found(diags, "macro-alarm") == [] and found(diags, "division-by-zero") == []
    alone = analyse(tmp_path, {"O9001.nc": macro})  # nothing calls it: it runs on its own, arguments unknown
    assert found(alone, "macro-alarm") == [] and found(alone, "division-by-zero") == []


def test_5_calls_a_local_the_macro_assigned_itself_is_not_a_vacant_argument(tmp_path):
    files = {"MAIN.nc": "O0001\nG65 P9001 A1.\nM30\n",
             "O9001.nc": "O9001\n#33=#[3+3*#1]\nG00 Z[#33+2.]\n#100=#32\nM99\n"}  # fmt: skip
    assert found(analyse(tmp_path, files), "vacant-argument") == [("O9001.nc", 4, "information")]


def test_4_control_flow_a_finding_in_a_loop_names_the_iteration_of_the_innermost_loop(tmp_path):
    text = ("O0001\n#1=0\nWHILE[#1 LT 2] DO1\n#2=5\nWHILE[#2 GE -1] DO2\n#3=10/[#2+#1*10]\n#2=#2-1\nEND2\n"
            "#1=#1+1\nEND1\nM30\n")  # fmt: skip
    [d] = [d for d in analyse(tmp_path, {"O0001.nc": text}) if d.code == "division-by-zero"]
    assert d.line + 1 == 6 and "in iteration 6 of the WHILE loop at line 5" in d.message
    called = {"MAIN.nc": "O0001\n#1=0\nWHILE[#1 LT 9] DO1\nG65 P9001 A#1\n#1=#1+1\nEND1\nM30\n",
              "O9001.nc": "O9001\n#2=1/[#1-3]\nM99\n"}  # fmt: skip
    [d] = [d for d in analyse(tmp_path, called) if d.code == "division-by-zero"]
    assert "O0001:4 (G65)" in d.message and "iteration" not in d.message  # no loop runs in the macro itself


def test_5_calls_a_program_that_only_calls_itself_still_runs_and_reports_its_nesting(tmp_path):
    files = {"SELF.nc": "O0001\n#100=#100+1\nM98 P0001\nM30\n"}
    assert found(analyse(tmp_path, files), "nesting-depth") == [("SELF.nc", 3, "error")]


def test_a_block_the_static_check_finds_in_error_is_not_repeated_by_the_run_under_another_code(tmp_path):
    # the run meets the same problem as an alarm whose code differs from the static finding's
    for dialect, line, code in [
        ("fanuc", "M03 G65 P9001", "g65-nc-words"),  # alarm 127 when run
        ("fanuc", "G65 P9001 O5", "g65-nc-words"),
        ("gsk980tdi", "IF[#1 EQ 0] #2=3", "dialect-feature"),  # alarm 114 when run
        ("gsk980tdi", "G65 H01 Q1", "argument-address"),
        ("fanuc", "#1=#3000", "write-only"),
        ("fanuc", "G65 P[CUT]", "dialect-feature"),
    ]:
        files = {"O0001.nc": f"O0001\n{line}\nM30\n", "O9001.nc": "O9001\nM99\n"}
        diags = analyse(tmp_path, files, dialect=dialect)
        assert [(d.line, d.code) for d in diags if d.severity == "error"] == [(1, code)], (dialect, line)


def test_6_alarms_a_haas_finding_names_no_fanuc_alarm_number(tmp_path):
    """The same missing N99 and division by zero: "(alarm 128)" and "(alarm 112)" on the 0i,
    "(alarm)" on Haas, which documents neither number."""
    text = "O01000\nIF [#1 EQ 0] GOTO 99\n#2=1/#3\nM30\n"
    for dialect, shown in (("fanuc-0i", ("alarm 128", "alarm 112")), ("haas", ("alarm", "alarm"))):
        diags = [d for d in analyse(tmp_path, {"O01000.nc": text}, dialect) if d.severity == "error"]
        assert [d.message.rsplit("(", 1)[1].rstrip(")") for d in diags] == list(shown), dialect


def test_6_alarms_a_gsk_alarm_number_out_of_range_is_argument_range(tmp_path):
    # §3.28.1: alarms 5900-5999, so #3000=100 and #3000=-1 are out of range (119), not 6000 or 5899
    for block in ("#3000=100(TEST)", "#3000=-1", "G65 H99 P100"):
        diags = analyse(tmp_path, {"O0001.nc": f"O0001\n{block}\nM30\n"}, dialect="gsk980tdi")
        assert found(diags, "argument-range") == [("O0001.nc", 2, "error")], block
        assert found(diags, "macro-alarm") == found(diags, "syntax") == [], block
