"""What real shop programs (FANUC 0i/30i, Haas and GSK controls) taught: forms that a control
runs and that must not be reported, and mistakes that a control alarms on and that must be.

Each test names the docs/semantics.md section whose rule it proves.
"""

from __future__ import annotations

from dataclasses import replace

from cncmacro.analysis.checks.static_checks import static_diagnostics
from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.debugging.breakpoints import Asked, Breakpoints
from cncmacro.dialects import get_dialect
from cncmacro.library.machine_file import CallCode, MachineSettings
from cncmacro.lsp.semantic_tokens import TOKEN_TYPES, line_tokens
from cncmacro.syntax.document import ParsedDocument
from conftest import block
from running import alarm, final, run
from static_helpers import at, check, coded, lines

# ---------------------------------------------------------------- §3 bracket depth

# five nested pairs: the condition's, ABS's, two plain ones and the indirection's
FIVE_DEEP = "IF[ABS[#5061-[#31-[#[#111+2]]*#129]]GE#123]GOTO14"
SIX_DEEP = "IF[ABS[#5061-[#31-[#[[#111]+2]]*#129]]GE#123]GOTO14"


def test_3_expressions_bracket_depth_counts_indirection_once():
    text = lines("O1000", FIVE_DEEP, "N14 M30")
    assert coded(check(text), "bracket-depth") == []
    assert final(text) is not None


def test_3_expressions_six_real_bracket_levels_are_still_alarm_118():
    text = lines("O1000", SIX_DEEP, "N14 M30")
    found = coded(check(text), "bracket-depth")
    assert [at(d) for d in found] == [(2, 2, 45, "error")]
    assert "nested 6 deep" in found[0].message
    assert alarm(text) == (118, 2)


def test_3_expressions_indirection_inside_an_assignment_counts_once():
    assert check(lines("O1000", "#1=#[#[#[#[#[1]]]]]", "M30")) == []
    text = lines("O1000", "#1=#[#[#[#[#[#[1]]]]]]", "M30")
    assert [d.code for d in check(text)] == ["bracket-depth"]
    assert alarm(text) == (118, 2)


# ---------------------------------------------------------------- §3 long expressions

CHAIN = "#1=1" + "+1" * 500  # a generated line: 500 operators in a row
SIGNS = "#1=" + "-" * 1000 + "1"  # 1,000 unary minus signs


def test_3_expressions_500_chained_operators_evaluate_without_recursion():
    text = lines("O1000", CHAIN, "#2=2*3-1/2*4+7-3*2+1" + "-1+2" * 40, "M30")
    assert check(text) == []
    got = final(text)
    assert got[1] == 501 and got[2] == 2 * 3 - 1 / 2 * 4 + 7 - 3 * 2 + 1 + 40


def test_3_expressions_1000_unary_signs_evaluate_without_recursion():
    text = lines("O1000", SIGNS, "#2=" + "-" * 999 + "#0", "#3=" + "-+" * 300 + "2", "M30")
    assert check(text) == []
    got = final(text)
    assert got[1] == 1 and got[2] == 0 and got[3] == 2


def test_3_expressions_a_long_chain_still_divides_by_zero_as_alarm_112():
    assert alarm(lines("O1000", "#1=1" + "+1" * 40 + "/#5", "M30")) == (112, 2)


# ---------------------------------------------------------------- §1 the end of the tape


def test_1_text_and_blocks_a_dos_end_of_file_byte_after_the_closing_percent_is_not_read():
    text = "%\nO1000\n#1=1\nM30\n%\n\x1a"
    assert [(d.code, *at(d)) for d in check(text)] == [("after-tape-end", 5, 0, 1, "hint")]
    assert final(text)[1] == 1


def test_1_text_and_blocks_junk_after_the_closing_percent_is_only_a_hint():
    text = lines("O1000", "#1=1", "N10 M30", "%", "this is no program [[[", "GOTO 99", "O2000", "#1=#50")
    [d] = check(text)
    assert (d.code, *at(d)) == ("after-tape-end", 4, 0, 1, "hint")
    assert "the 4 lines after it (to line 8)" in d.message
    assert final(text)[1] == 1


def test_1_text_and_blocks_a_leading_percent_starts_the_tape_and_the_second_ends_it():
    text = lines("", "(TAPE START)", "%", "O1000", "#1=1", "%", "#1=5", "#2=[", "M30")
    assert [(d.code, d.line + 1) for d in check(text)] == [("after-tape-end", 6)]
    got = final(text)
    assert got[1] == 1 and 2 not in got  # the run ends at the closing '%'


def test_1_text_and_blocks_running_into_the_closing_percent_ends_the_program():
    text = lines("O1000", "#1=1", "%", "#1=2", "M30")
    assert final(text)[1] == 1


def test_1_text_and_blocks_what_follows_the_closing_percent_on_its_line_is_not_read():
    text = lines("O1000", "#1=1", "% #1=2 G65 P9999 #3=[", "#1=3", "M30")
    assert [(d.code, d.line + 1) for d in check(text)] == [("after-tape-end", 3)]
    got = final(text)
    assert got[1] == 1 and 2 not in got and 3 not in got


def test_1_text_and_blocks_plain_moves_run_up_to_the_closing_percent_and_not_past_it():
    text = lines("O1000", "G90 G0 X1. Y1.", "G1 X2. Y2. F100.", "", "%", "G1 X3. Y3.", "G1 X4. Y4.")
    m = run(text)
    assert m.status == "completed"
    assert [(mv.line + 1, mv.end[:2]) for mv in m.planner.moves] == [(2, (1.0, 1.0)), (3, (2.0, 2.0))]


def test_1_text_and_blocks_a_dos_end_of_file_byte_without_percent_ends_the_file():
    assert check("O1000\n#1=1\nM30\n\x1a") == []
    assert check("O1000\n#1=1\nM30\n\x1a\n#1=[\n")[0].code == "after-tape-end"


def test_1_text_and_blocks_a_breakpoint_after_the_tape_end_is_never_reached(tmp_path):
    path = tmp_path / "O9100.nc"
    path.write_text("%\nO9100\n#100=1\nM99\n%\n#100=2\nM99\n", encoding="utf-8")
    made = Breakpoints().set_lines(str(path), [Asked(2), Asked(5)])
    assert [(b.verified, b.line) for b in made] == [(True, 2), (False, None)]


def test_1_text_and_blocks_the_checker_passes_over_what_follows_the_tape(tmp_path):
    path = tmp_path / "O1000.nc"
    path.write_text("%\nO1000\nG65 P2000\nM30\n%\nO2000\n#1=1/0\nM99\nGOTO 5\n\x1a", encoding="utf-8")
    ws = WorkspaceAnalysis()
    ws.open(str(path), path.read_text(encoding="utf-8"), 1)
    result = ws.analyze(str(path))
    assert result is not None
    assert [(d.code, d.line + 1) for d in result.diagnostics[str(path)]] == [
        ("program-not-found", 3),  # O2000 after the end of the tape is not a program of the file
        ("not-executed", 4),
        ("after-tape-end", 5),
    ]


# ---------------------------------------------------------------- §8 words a control refuses


def test_8_the_simulated_machine_an_m_code_with_a_decimal_point_is_alarm_007():
    text = lines("O1000", "G00 X0", "M30.")
    [d] = check(text)
    assert (d.code, *at(d)) == ("decimal-point", 3, 0, 4, "error")
    assert "write M30" in d.message
    assert alarm(text) == (7, 3)


def test_8_the_simulated_machine_an_unknown_g_code_is_alarm_010_not_a_move():
    text = lines("O1000", "G229 X10", "M30")
    [d] = check(text)
    assert (d.code, *at(d)) == ("unknown-g-code", 2, 0, 4, "error")
    assert alarm(text) == (10, 2)
    assert alarm(lines("O1000", "#1=229", "G#1 X10", "M30")) == (10, 3)  # known only when it runs


def test_8_the_simulated_machine_g_codes_real_programs_use_are_known():
    codes = (
        "G05.1 Q1", "G05.1 Q0", "G07.1 C20.", "G07.1 C0", "G10.6 X5.", "G12.1", "G13.1", "G43.4 H1", "G43.5 H1",
        "G49.1", "G50.1 X0", "G51.1 X0", "G50.1", "G53.1", "G54.1 P2", "G54.2 P1", "G61", "G62", "G63", "G64",
        "G68 X0 Y0 R10.", "G69", "G68.2 X0 Y0 Z0 I0 J0 K0", "G69", "G91.1", "G90", "G98", "G99", "G98",
        "G70 P10 Q20", "G71 U1. R0.5", "G72 W1. R0.5", "G75 X10.", "G77 X1.", "G78 X1.", "G79 X1.", "G80",
        "G32 Z-10. F1.5", "G00 X0", "G107 C0", "G112", "G113", "G06.2 X1. K0", "G00 X0",
    )  # fmt: skip
    text = lines("O1000", *codes, "M30")
    assert check(text) == []
    assert final(text) is not None


def test_8_the_simulated_machine_a_g_code_the_machine_maps_to_a_macro_is_not_unknown():
    settings = MachineSettings(calls={"G100": CallCode(9010)})
    text = lines("O1000", "G100 X1. M3.5", "M30", "O9010", "#100=#24", "M99")
    assert check(text, settings=settings) == []  # M3.5 is an argument of the call, not an M code
    assert final(text, calls={"G100": CallCode(9010)})[100] == 1
    assert [d.code for d in check(text)] == ["unknown-g-code", "decimal-point"]  # without the mapping
    assert alarm(text) == (10, 2)


def test_8_the_simulated_machine_macro_arguments_may_have_decimal_points():
    assert check(lines("O1000", "G65 P9010 M3.5 S1.5", "M30", "O9010", "M99")) == []


def test_8_the_simulated_machine_on_gsk980tdi_the_same_words_are_warnings_and_the_run_goes_on():
    text = lines("O1000", "G229 X10", "M30.")
    assert [(d.code, d.severity) for d in check(text, "gsk980tdi")] == [
        ("unknown-g-code", "warning"),
        ("decimal-point", "warning"),
    ]
    assert final(text, "gsk980tdi") is not None


# ---------------------------------------------------------------- §1 abbreviated macro words

SHORT = lines(
    "O1000",
    "#1=0",
    "WH[#1LT3]DO1",
    "#1=#1+1",
    "EN1",
    "#2=AT[1]/[1]+RO[1.4]+SQ[16]",
    "IF[#1GT2]TH#3=7",
    "IF[#1EQ3]GO10",
    "M30",
    "N10 #4=#1 AN 1 XO 4",
    "M30",
)
LONG = lines(
    "O1000",
    "#1=0",
    "WHILE[#1LT3]DO1",
    "#1=#1+1",
    "END1",
    "#2=ATAN[1]/[1]+ROUND[1.4]+SQRT[16]",
    "IF[#1GT2]THEN#3=7",
    "IF[#1EQ3]GOTO10",
    "M30",
    "N10 #4=#1 AND 1 XOR 4",
    "M30",
)


def test_1_text_and_blocks_fanuc_reads_the_first_two_letters_of_a_macro_word_as_the_word():
    assert final(SHORT) == final(LONG) == {1: 3, 2: 50, 3: 7, 4: 5}
    hints = check(SHORT)
    assert {d.severity for d in hints} == {"hint"} and {d.code for d in hints} == {"keyword-abbreviation"}
    assert [(d.line + 1, d.column, d.end_column, d.message) for d in hints][:2] == [
        (3, 0, 2, "'WH' is short for WHILE"),
        (5, 0, 2, "'EN' is short for END"),
    ]
    assert len(hints) == 9
    assert check(LONG) == []


def test_1_text_and_blocks_three_letters_and_lower_case_are_abbreviations_too():
    text = lines("O1000", "#1=0", "whi[#1 lt 2] do1", "#1=#1+1", "end1", "#2=ata[1]/[1]", "M30")
    assert final(text) == {1: 2, 2: 45}


def test_1_text_and_blocks_abbreviations_are_a_dialect_feature_on_gsk980tdi():
    found = check(SHORT, "gsk980tdi")
    assert {(d.code, d.severity) for d in found} == {("dialect-feature", "error")}
    assert "'WH' for WHILE" in found[0].message and "write WHILE" in found[0].message
    assert alarm(SHORT, "gsk980tdi") == (114, 3)


def test_1_text_and_blocks_nc_words_never_read_as_abbreviations():
    # a value never starts with a letter: these stay NC words (or are the errors they were)
    assert check(lines("O1000", "G01 X10. Y5. F100", "T0101", "E1. M08", "M30")) == []
    assert [d.code for d in check(lines("O1000", "GO1 X10.", "M30"))] == ["keyword-abbreviation", "nc-and-macro"]


# ---------------------------------------------------------------- §4 IF without THEN


def test_4_control_flow_if_without_then_is_alarm_114_on_gsk980tdi():
    text = lines("O1000", "#1=20", "IF[#1GT10]#2=5", "M30")
    [d] = check(text, "gsk980tdi")
    assert (d.code, *at(d)) == ("dialect-feature", 3, 10, 14, "error")
    assert "THEN is missing" in d.message and "alarm 114" in d.message
    assert alarm(text, "gsk980tdi") == (114, 3)


def test_4_control_flow_if_without_then_runs_the_statement_on_the_fanuc_profiles():
    # a production FANUC grinder program uses it and no FANUC manual forbids it
    text = lines("O1000", "#1=20", "IF[#1GT10]#2=5", "IF[#1LT10]#3=5", "M30")
    for name in ("fanuc-0i", "fanuc-30i"):
        dialect = get_dialect(name)
        assert dialect.if_without_then
        assert final(text, dialect) == {1: 20, 2: 5}
        found = static_diagnostics(ParsedDocument(text).program, "MAIN.nc", dialect, MachineSettings())
        assert found == []
    assert not get_dialect("gsk980tdi").if_without_then


def test_4_control_flow_if_without_then_runs_the_statement_where_the_control_accepts_it():
    haas_like = replace(get_dialect("gsk980tdi"), if_without_then=True)
    text = lines("O1000", "#1=20", "IF[#1GT10]#2=5", "IF[#1LT10]#3=5", "M30")
    assert final(text, haas_like) == {1: 20, 2: 5}
    found = static_diagnostics(ParsedDocument(text).program, "MAIN.nc", haas_like, MachineSettings())
    assert found == []


def test_1_text_and_blocks_an_abbreviated_word_is_coloured_as_its_whole_word():
    text = "WH[#1LT3]DO1"
    tokens = line_tokens(text, block(text), get_dialect("fanuc"))
    assert (0, 2, TOKEN_TYPES.index("keyword"), 0) in tokens
    text = "#2=AT[1]/[2]"
    tokens = line_tokens(text, block(text), get_dialect("fanuc"))
    assert (3, 5, TOKEN_TYPES.index("function"), 0) in tokens
