"""Static diagnostics of docs/semantics.md §2 "Values and variables", §3 "Expressions" and the block
rule of §4 (NC words and a macro statement), plus the whole-file promises: the bundled examples
are clean, messages come in Chinese, and the per-line part can be asked for one block."""

from __future__ import annotations

from pathlib import Path

from cncmacro.analysis.checks.static_checks import block_diagnostics
from cncmacro.dialects import get_dialect
from cncmacro.library.dialect_choice import dialect_from_text
from cncmacro.library.machine_file import MachineSettings
from cncmacro.library.programs import ProgramLibrary
from cncmacro.syntax import parse_block
from running import alarm
from static_helpers import at, check, coded, lines

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"

# ---------------------------------------------------------------- variable-number


def test_2_values_and_variables_a_variable_the_dialect_lacks_is_an_error():
    text = lines("O1000", "#1=#50+1", "M30")
    found = coded(check(text), "variable-number")
    assert [at(d) for d in found] == [(2, 3, 6, "error")]
    assert alarm(text) == (115, 2)


def test_2_values_and_variables_common_range_is_a_machine_setting():
    text = lines("O1000", "#300=1", "M30")
    assert check(text) == []  # fanuc-0i: #100-#499 unless the machine file names fewer
    narrow = MachineSettings(common=((100, 199), (500, 999)))
    assert [at(d) for d in coded(check(text, settings=narrow), "variable-number")] == [(2, 0, 4, "error")]
    assert [at(d) for d in coded(check(text, "gsk980tdi"), "variable-number")] == [(2, 0, 4, "error")]


def test_2_values_and_variables_nine_indirection_exists_on_gsk980tdi_only():
    text = lines("O1000", "#9102=#9103+1", "M30")
    assert check(text, "gsk980tdi") == []
    found = check(text)
    assert [(d.code, *at(d)) for d in found] == [
        ("dialect-feature", 2, 0, 5, "error"),
        ("dialect-feature", 2, 6, 11, "error"),
    ]
    assert "#[#102]" in found[0].message
    assert alarm(text) == (115, 2)


def test_2_values_and_variables_nine_indirection_through_a_non_common_is_an_error_on_gsk980tdi():
    found = coded(check(lines("O1000", "#1=#9050", "M30"), "gsk980tdi"), "variable-number")
    assert [at(d) for d in found] == [(2, 3, 8, "error")]
    assert "#50" in found[0].message


def test_2_values_and_variables_literal_indirection_and_words_are_checked():
    found = coded(check(lines("O1000", "#1=#[50]", "G00 X#60", "M30")), "variable-number")
    assert [at(d) for d in found] == [(2, 3, 8, "error"), (3, 5, 8, "error")]
    assert check(lines("O1000", "#1=#[#2+100]", "G00 X#5001", "M30")) == []


# ---------------------------------------------------------------- write-protected / write-only


def test_6_alarms_writing_a_read_only_system_variable_is_write_protected():
    text = lines("O1000", "#4001=1", "M30")
    found = coded(check(text), "write-protected")
    assert [at(d) for d in found] == [(2, 0, 5, "error")]
    assert alarm(text) == (116, 2)
    assert check(lines("O1000", "#1=#4001", "#2001=0.5", "M30")) == []


def test_2_values_and_variables_writing_0_is_write_protected_also_in_if_then():
    found = coded(check(lines("O1000", "IF[#1 EQ 0] THEN #0=1", "M30")), "write-protected")
    assert [at(d) for d in found] == [(2, 17, 19, "error")]


def test_7_h_code_destination_read_only_is_write_protected_on_gsk980tdi():
    found = coded(check(lines("O1000", "G65 H01 P#4001 Q1", "M30"), "gsk980tdi"), "write-protected")
    assert [at(d) for d in found] == [(2, 9, 14, "error")]


def test_6_alarms_reading_3000_is_write_only():
    text = lines("O1000", "#1=#3000", "M30")
    for dialect in ("fanuc", "gsk980tdi"):
        found = coded(check(text, dialect), "write-only")
        assert [at(d) for d in found] == [(2, 3, 8, "error")]
    assert alarm(text, "gsk980tdi")[0] == 115
    assert check(lines("O1000", "#3000=1(STOP)", "M30")) == []


# ---------------------------------------------------------------- nc-and-macro


def test_4_control_flow_nc_word_and_macro_statement_in_one_block_is_an_error():
    text = lines("O1000", "G01 X1 #1=2", "M30")
    found = coded(check(text), "nc-and-macro")
    assert [at(d) for d in found] == [(2, 0, 3, "error")]
    assert alarm(text) == (127, 2)


def test_4_control_flow_n_and_o_may_precede_a_macro_statement():
    assert check(lines("O1000 #1=2", "N10 #2=3", "/N20 #3=4", "M30")) == []


# ---------------------------------------------------------------- dialect-feature and bracket-depth


def test_3_expressions_c_style_relation_is_a_dialect_feature_on_fanuc():
    text = lines("O1000", "IF[#1==2] GOTO 10", "N10 M30")
    found = coded(check(text), "dialect-feature")
    assert [at(d) for d in found] == [(2, 3, 8, "error")]
    assert alarm(text) == (114, 2)
    assert check(text, "gsk980tdi") == []
    assert check(lines("O1000", "IF[#1 EQ 2] GOTO 10", "N10 M30")) == []


def test_3_expressions_more_than_five_nested_brackets_is_an_error():
    text = lines("O1000", "#1=[[[[[[1]]]]]]", "M30")
    found = coded(check(text), "bracket-depth")
    assert [at(d) for d in found] == [(2, 3, 16, "error")]
    assert alarm(text) == (118, 2)
    assert check(lines("O1000", "#1=[[[[[1]]]]]", "#2=SIN[[[[1]]]]", "M30")) == []


def test_3_expressions_function_brackets_count_toward_the_depth():
    found = coded(check(lines("O1000", "#1=SIN[[[[[[1]]]]]]", "M30")), "bracket-depth")
    assert [at(d) for d in found] == [(2, 3, 19, "error")]


# ---------------------------------------------------------------- whole files, locale, per line


def test_1_text_and_blocks_bundled_examples_give_no_static_error_or_warning():
    library = ProgramLibrary()
    checked = 0
    for path in sorted(EXAMPLES.rglob("*.nc")):
        text = path.read_text(encoding="utf-8")
        dialect = dialect_from_text(text.splitlines()) or "fanuc"
        found = check(text, dialect, file=str(path), library=library)
        assert [d for d in found if d.severity in ("error", "warning")] == [], path.name
        checked += 1
    assert checked >= 9


def test_4_control_flow_generated_cam_program_only_jumps_past_its_last_label():
    from camgen import cam_program

    text = cam_program(3000)
    last = max(int(line.split()[0][1:]) for line in text.splitlines() if line.startswith("N"))
    found = check(text)
    # the generator's IF..GOTOs near the end aim at the label after the last one: a real finding
    assert found and all(d.code == "undefined-label" and f"GOTO {last + 1}:" in d.message for d in found)


def test_6_alarms_messages_are_in_chinese_for_a_zh_locale():
    text = lines("O1000", "GOTO 20", "#1=#50", "WHILE[#1 LT 1] DO5", "END5", "M30")
    found = check(text, locale="zh-CN")
    assert {d.code for d in found} == {"undefined-label", "variable-number", "loop-number"}
    assert all("报警" in d.message for d in found)


def test_1_text_and_blocks_block_diagnostics_checks_one_line_alone():
    fanuc = get_dialect("fanuc")
    found = block_diagnostics(parse_block("G90 G65 P9100 A1"), 7, "A.nc", fanuc, MachineSettings())
    assert [(d.line, d.code) for d in found] == [(7, "g65-nc-words")]
    assert block_diagnostics(parse_block("G01 X1. Y2."), 0, "A.nc", fanuc, MachineSettings()) == []


def test_2_profile_suggestion_names_the_control_a_file_reads_cleanly_on():
    from cncmacro.analysis.checks.profile_suggestion import suggested_profile
    from cncmacro.dialects import get_dialect
    from cncmacro.syntax.document import ParsedDocument

    def suggested(text: str, dialect: str) -> str | None:
        found = suggested_profile(ParsedDocument(text).program, get_dialect(dialect), MachineSettings())
        return None if found is None else found.name

    assert suggested(lines("O1", "#1=[#_ABSIO[1]]", "M30"), "fanuc-0i") == "fanuc-30i"
    assert suggested(lines("O1", "G65 H01 P#101 Q5", "IF[#101==5]GOTO9", "N9 M30"), "fanuc-0i") == "gsk980tdi"
    assert suggested(lines("O1", "#1=POW[2,3]", "G65 H01 P#101 Q5", "M30"), "fanuc-0i") is None  # no one has both
    assert suggested(lines("O1", "#1=[#_ABSIO[1]]", "M30"), "gsk980tdi") == "fanuc-30i"
    mill = lines("O1", "G21 G17 G40 G49 G80 G90", "G43 Z50. H01", "G81 X10 Y10 Z-5 R2 F100", "M30")
    assert suggested(mill, "gsk980tdi") == "fanuc-0i"  # G codes the lathe does not have
