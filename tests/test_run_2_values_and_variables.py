"""docs/semantics.md §2 "Values and variables", run on the interpreter, in both dialects."""

from __future__ import annotations

import pytest

from running import alarm, final, lines, run


def test_copying_vacant_gives_vacant_and_arithmetic_treats_it_as_zero():
    # seed 000 and seed 003 table: #2=#1 stays vacant, #1*5 and #1+#1 give 0
    for dialect in ("fanuc", "gsk980tdi"):
        v = final(lines("#2=#1", "#3=#1*5", "#4=#1+#1", "#5=SIN[#1]", "M30"), dialect)
        assert 2 not in v and v[3] == 0 and v[4] == 0 and v[5] == 0


@pytest.mark.parametrize(
    ("value", "relation", "fanuc", "gsk"),
    [
        # seed 003 (fanuc): vacant differs from 0 in EQ and NE only
        (None, "EQ", True, True),
        (None, "NE", False, False),
        (None, "GE", True, True),
        (None, "GT", False, False),
        # with #1 = 0: fanuc says 0 EQ vacant is false; gsk (seed 000) says it holds
        (0.0, "EQ", False, True),
        (0.0, "NE", True, False),
        (0.0, "GE", True, True),
        (0.0, "GT", False, False),
    ],
)
def test_vacant_in_conditions(value, relation, fanuc, gsk):
    program = lines(f"IF[#1 {relation} #0] THEN #100=1", "M30")
    presets = {} if value is None else {1: value}
    assert (final(program, "fanuc", presets=presets).get(100) == 1) is fanuc
    assert (final(program, "gsk980tdi", presets=presets).get(100) == 1) is gsk


def test_vacant_address_is_dropped_on_fanuc_and_zero_on_gsk():
    m = run(lines("G90 G00 X100 Y#1 Z#1", "M30"), "fanuc", presets={})
    assert m.planner.moves[-1].end[:3] == (100.0, 0.0, 0.0)
    m = run(lines("G00 X100 Z50", "G00 X100 Z#1", "M30"), "gsk980tdi")
    assert m.planner.moves[-1].end[2] == 0.0  # G00 X100 Z#1 = G00 X100 Z0 (seed 000)
    m = run(lines("G90 G00 X100 Z50", "G00 X100 Z#1", "M30"), "fanuc")
    assert m.planner.moves[-1].end[2] == 50.0  # the Z word is dropped


def test_zero_is_vacant_and_read_only():
    assert 100 not in final(lines("#100=#0", "M30"))
    assert alarm(lines("#1=1", "#0=5", "M30")) == (116, 2)


@pytest.mark.parametrize("number", [34, 99, 1020, 4200])
def test_numbers_outside_the_ranges_are_alarm_115(number):
    assert alarm(lines(f"#{number}=1", "M30"))[0] == 115
    assert alarm(lines(f"#1=#{number}", "M30"))[0] == 115


def test_2_common_range_is_a_machine_setting():
    assert final(lines("#300=1", "M30"))[300] == 1  # fanuc-0i: #100-#499 by default
    assert alarm(lines("#300=1", "M30"), common=((100, 199), (500, 999)))[0] == 115
    assert alarm(lines("#200=1", "M30"), "gsk980tdi")[0] == 115  # seed 000: #100-#199 only


def test_locals_commons_and_persistent_ranges():
    v = final(lines("#1=1", "#33=33", "#100=100", "#199=199", "#500=500", "#999=999", "M30"))
    assert {1: 1, 33: 33, 100: 100, 199: 199, 500: 500, 999: 999}.items() <= v.items()


def test_indirection_rounds_half_away_from_zero():
    v = final(lines("#1=100.5", "#[#1]=7", "#[-#1+200.4]=8", "M30"))
    assert v[101] == 7  # #[100.5] is #101
    assert v[100] == 8  # #[99.9] is #100


def test_indirection_reads_the_rounded_number():
    v = final(lines("#101=7", "#100=5", "#1=#[100.5]", "#2=#[100.4]", "M30"))
    assert v[1] == 7 and v[2] == 5


def test_nine_indirection_on_gsk_only():
    # seed 000 "用变量置换变量号": #100=205, #205... (commons here are #100-#199, so use #150)
    v = final(lines("#100=150", "#150=500", "#1=#9100", "#9100=#9100+1", "M30"), "gsk980tdi")
    assert v[1] == 500 and v[150] == 501
    assert alarm(lines("#100=150", "#1=#9100", "M30"), "fanuc")[0] == 115


def test_nine_indirection_in_an_address():
    m = run(lines("#100=150", "#150=500", "G00 X#9100 Z-#9100", "M30"), "gsk980tdi")
    assert m.planner.moves[-1].end == (500.0, 0.0, -500.0, 0.0, 0.0)


def test_comparisons_are_exact():
    v = final(lines("#1=0.1+0.2", "IF[#1 EQ 0.3] THEN #100=1", "IF[ABS[#1-0.3] LT 0.000001] THEN #101=1", "M30"))
    assert 100 not in v and v[101] == 1
