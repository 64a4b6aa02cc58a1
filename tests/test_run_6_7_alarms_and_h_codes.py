"""docs/semantics.md §6 "Alarms and messages" and §7 "GSK macro A form: G65 Hm P#i Q#j R#k", run on
the interpreter."""

from __future__ import annotations

import pytest

from running import alarm, final, lines, machine, run


@pytest.mark.parametrize(("dialect", "base"), [("fanuc", 3000), ("gsk980tdi", 5900)])
def test_3000_numbering_and_message(dialect, base):
    m = run(lines("#1=0", "IF[#24 EQ #0] THEN #3000=12(X MISSING)", "M30"), dialect)
    assert m.status == "alarm" and m.alarm.number == base + 12 and m.alarm.message == "X MISSING"
    assert m.alarm.line == 1


def test_alarm_carries_the_call_chain():
    program = lines("G65 P9100 A1", "M30", "O9100", "M98 P9200", "M99", "O9200", "#3000=1(DEEP)", "M99")
    m = run(program)
    assert m.alarm.number == 3001 and m.alarm.line == 6
    assert [(c.program, c.line, c.how) for c in m.alarm.chain] == [
        ("MAIN", 0, "main"),
        ("O9100", 3, "G65"),
        ("O9200", 6, "M98"),
    ]


def test_3006_pauses_with_its_message_and_resumes():
    m = machine(lines("#1=1", "#3006=1(CHECK TOOL)", "#2=2", "M30"))
    assert m.run() == "paused" and m.message == "CHECK TOOL"
    assert m.frame.pc == 2 and m.L[2] is None
    m.resume()
    assert m.run() == "completed" and m.L[2] == 2


def test_m00_pauses_and_resumes():
    m = machine(lines("#1=1", "M00", "#2=2", "M30"))
    assert m.run() == "paused"
    m.resume()
    assert m.run() == "completed" and m.L[2] == 2


def test_3000_cannot_be_read_on_gsk():
    assert alarm(lines("#1=#3000", "M30"), "gsk980tdi")[1] == 1


@pytest.mark.parametrize(
    ("dialect", "number"), [("fanuc", 5001), ("fanuc", 4120), ("gsk980tdi", 4001), ("fanuc", 3011)]
)
def test_read_only_system_variables_are_alarm_116(dialect, number):
    assert alarm(lines(f"#{number}=1", "M30"), dialect) == (116, 1)


# ---------------------------------------------------------------- §7 H codes


@pytest.mark.parametrize(
    ("h", "q", "r", "expected"),
    [
        ("01", "7", "0", 7),
        ("02", "7", "5", 12),
        ("03", "7", "5", 2),
        ("04", "7", "5", 35),
        ("05", "35", "5", 7),
        ("11", "12", "3", 15),
        ("12", "12", "10", 8),
        ("13", "12", "10", 6),
        ("21", "16", "0", 4),
        ("22", "-4", "0", 4),
        ("23", "-7", "3", -1),  # j - TRUNC(j/k)*k
        ("23", "101", "100", 1),
        ("24", "37", "0", 25),
        ("25", "25", "0", 37),
        ("27", "3", "4", 5),
        ("31", "10", "30", 5),
        ("32", "10", "60", 5),
        ("33", "10", "45", 10),
        ("34", "1", "1", 45),
    ],
)
def test_h_code_arithmetic(h, q, r, expected):
    v = final(lines(f"G65 H{h} P#100 Q{q} R{r}", "M30"), "gsk980tdi")
    assert v[100] == pytest.approx(expected, abs=1e-9)


def test_h_code_operands_are_variables_or_constants_and_q_may_be_negated():
    v = final(lines("#101=8", "#102=3", "G65 H02 P#100 Q-#102 R#101", "M30"), "gsk980tdi")
    assert v[100] == 5


def test_h26_scales_the_destination():
    v = final(lines("#100=10", "G65 H26 P#100 Q6 R4", "M30"), "gsk980tdi")
    assert v[100] == 15


@pytest.mark.parametrize(
    ("h", "q", "r", "jumps"),
    [
        ("80", "0", "0", True),
        ("81", "5", "5", True),
        ("81", "5", "6", False),
        ("82", "5", "6", True),
        ("83", "6", "5", True),
        ("83", "5", "5", False),
        ("84", "5", "6", True),
        ("85", "5", "5", True),
        ("86", "6", "5", False),
    ],
)
def test_h_code_branches(h, q, r, jumps):
    v = final(lines(f"G65 H{h} P50 Q{q} R{r}", "#100=1", "N50 M30"), "gsk980tdi")
    assert (100 not in v) is jumps


def test_seed_000_h99_p15_is_alarm_5915():
    assert alarm(lines("G65 H99 P15", "M30"), "gsk980tdi") == (5915, 1)


def test_7_h99_carries_the_comment_text_like_3000():
    # seed 000 §3.28.2: G65 H99 P15(/用户自定义报警) is alarm 5915 with the text 用户自定义报警
    m = run(lines("G65 H99 P15(/用户自定义报警);", "M30"), "gsk980tdi")
    assert (m.alarm.number, m.alarm.message) == (5915, "用户自定义报警")
    m = run(lines("#1=3", "G65 H99 P#1 (TOOL BROKEN)", "M30"), "gsk980tdi")
    assert (m.alarm.number, m.alarm.message) == (5903, "TOOL BROKEN")
    m = run(lines("G65 H99 P15", "M30"), "gsk980tdi")  # no text: the alarm has none of its own
    assert m.alarm.message == "G65 H99 P15: user alarm 5915"


def test_h05_by_zero_is_alarm_112():
    assert alarm(lines("G65 H05 P#100 Q1 R0", "M30"), "gsk980tdi") == (112, 1)


def test_h_codes_are_a_gsk_feature():
    # on fanuc G65 H.. P#100 is a macro call of the program numbered by #100 (vacant: none)
    assert alarm(lines("G65 H01 P#100 Q1 R0", "M30"))[0] in (76, 291)


def test_dprnt_formats_values():
    from running import run

    m = run(lines("#1=12.3456", "#2=-7", "POPEN", "DPRNT[X#1[53]**Y#2[30]*Z#3[20]]", "PCLOS", "M30"))
    assert m.output == ["X12.346  Y-7 Z0"]


# ---------------------------------------------------------------- §7 G65 P.. H.. is a call, G65 H.. P.. arithmetic


MACRO_9013 = ("M30", "O9013", "#100=#1", "#101=#11", "M99")


def test_7_the_first_of_p_and_h_after_g65_decides_call_or_h_code():
    # GSK980TDi §3.28.3 note 3: G65 is followed at once by P or H; §3.28.3.1: H is argument #11.
    # G65 P9013 A1 H5 calls O9013 with #1 = 1 and #11 = 5, so #100 = 1 and #101 = 5
    assert final(lines("G65 P9013 A1 H5", *MACRO_9013), "gsk980tdi") == {100: 1, 101: 5}
    # G65 P9013 H5: #11 = 5 and #1 not passed (vacant), so #100 stays vacant and #101 = 5
    assert final(lines("G65 P9013 H5", *MACRO_9013), "gsk980tdi") == {101: 5}
    # G65 H01 P#100 Q5 is still the assignment #100 = 5 (H first)
    assert final(lines("G65 H01 P#100 Q5", "M30"), "gsk980tdi") == {100: 5}


def test_7_h01_assigns_a_vacant_q_as_vacant():
    # §3.28.1: "除用<空变量>赋值以外" vacant is 0; H01 is the assignment (赋值运算), so
    # #100 = 5 then G65 H01 P#100 Q#0 leaves #100 vacant, as #100=#0 would; Q#1 (a vacant local)
    # the same for #101; H02 is an operation: #102 = vacant + 1 = 0 + 1 = 1
    text = lines("#100=5", "#101=6", "G65 H01 P#100 Q#0", "G65 H01 P#101 Q#1", "G65 H02 P#102 Q#0 R1", "M30")
    assert final(text, "gsk980tdi") == {102: 1}


@pytest.mark.parametrize("block", ["#3000=100(TEST)", "#3000=-1", "G65 H99 P100", "G65 H99 P-1"])
def test_6_gsk_alarm_numbers_outside_0_to_99_are_alarm_119(block):
    # §3.28.1 and §3.28.2: "报警范围为5900到5999", so n is 0 to 99; 100 and -1 are outside it: an
    # argument out of range (119), never a made-up 6000 or 5899
    assert alarm(lines(block, "M30"), "gsk980tdi") == (119, 1)


def test_6_gsk_alarm_numbers_0_and_99_are_5900_and_5999_and_fanuc_is_not_limited():
    assert alarm(lines("#3000=99(LAST)", "M30"), "gsk980tdi") == (5999, 1)
    assert alarm(lines("G65 H99 P0", "M30"), "gsk980tdi") == (5900, 1)
    assert alarm(lines("#3000=100(TEST)", "M30")) == (3100, 1)  # fanuc: 3000 + 100, as before
