"""The Haas NGC mill table (``dialects/profiles/haas.py``): what its rows, codes and switches say
that no other profile says (the checks every profile's rows pass are in test_dialect_tables.py).

docs/profiles.md "haas: sources and decisions" says where each number comes from and which are
still to be confirmed against a Haas manual.
"""

from __future__ import annotations

import re

import pytest

from cncmacro.dialects import fanuc_data, get_dialect, normalise_dialect
from cncmacro.dialects.describe import describe_system_variable, variable_class
from cncmacro.dialects.profiles import haas as data
from cncmacro.dialects.tables import SystemVariable

CJK = re.compile(r"[\u4e00-\u9fff]")
HAAS = get_dialect("haas")


def row(number: int) -> SystemVariable:
    found = HAAS.system_variable(number)
    assert found is not None, f"#{number} is missing"
    return found


def text(number: int, locale: str = "en") -> str:
    doc = describe_system_variable(HAAS, number, locale)
    assert doc is not None
    return doc.text


def test_haas_answers_to_its_aliases_and_is_a_six_axis_mill() -> None:
    for spelling in ("haas", "Haas-NGC", "haas-mill", "HAAS_NGC"):
        assert normalise_dialect(spelling) == "haas", spelling
    assert not HAAS.lathe and HAAS.axes == ("X", "Y", "Z", "A", "B", "C")


def test_3026_is_the_tool_in_the_spindle_and_read_only() -> None:
    r = row(3026)
    assert r.access == "r" and "Tool in the spindle" in r.en and "主轴上的刀具" in r.zh
    assert get_dialect("fanuc-0i").system_variable(3026) is None


@pytest.mark.parametrize(
    ("number", "words"),
    [(3020, "Power-on timer"), (3021, "Cycle start timer"), (3022, "Feed timer"), (3023, "Present part timer"),
     (3024, "Last complete part timer"), (3025, "Previous part timer"), (3027, "Spindle speed"),
     (3028, "Pallet loaded"), (3030, "Single block"), (3031, "Dry run"), (3032, "Block delete"),
     (3033, "Optional stop"), (3901, "M30 counter 1"), (3902, "M30 counter 2"), (1094, "Coolant level"),
     (1098, "Spindle load"), (8550, "Tool data access")],
)  # fmt: skip
def test_haas_machine_state_numbers(number: int, words: str) -> None:
    assert words in text(number)


@pytest.mark.parametrize(
    ("number", "axis", "zh"),
    [(1064, "X", "X轴"), (1065, "Y", "Y轴"), (1066, "Z", "Z轴"), (1067, "A", "A轴"), (1068, "B", "B轴"),
     (1264, "C", "C轴"), (1265, "U", "U轴"), (1266, "V", "V轴"), (1267, "W", "W轴"), (1268, "T", "T轴")],
)  # fmt: skip
def test_axis_loads_1064_to_1068_and_1264_to_1268_are_read_only_percentages(number: int, axis: str, zh: str) -> None:
    r = row(number)
    assert (r.access, r.group, r.source, r.default) == ("r", "signals", "store", 0.0)
    assert text(number) == f"{axis} axis: the highest load seen so far, in percent"
    assert text(number, "zh").startswith(zh) and "至今的最大负载（百分比）" in text(number, "zh")
    assert get_dialect("fanuc-0i").system_variable(number) is None


def test_no_axis_load_rows_past_the_ten_axes() -> None:
    assert (row(1063).first, row(1063).last) == (1000, 1063)  # the last discrete input
    assert HAAS.system_variable(1069) is None and row(1080).first == 1080
    assert HAAS.system_variable(1263) is None and HAAS.system_variable(1269) is None


def test_power_on_and_part_timers_are_read_only_the_switches_are_not() -> None:
    assert [row(n).access for n in (3020, 3023, 3024, 3025, 3027, 3028)] == ["r"] * 6
    assert [row(n).access for n in (3021, 3030, 3031, 3032, 3033, 3901, 3902)] == ["rw"] * 7


def test_14001_is_g154_p1_x_the_same_offset_as_7001() -> None:
    assert "X" in text(14001) and "G154 P1 " in text(14001) and "G110" in text(14001)
    for p in (1, 20):
        long, short = 14001 + 20 * (p - 1), 7001 + 20 * (p - 1)
        assert (row(short).source, row(short).param) == ("alias", str(long)), p  # kept at #14001...
        assert row(long).source == "store"
        assert f"G{109 + p}" in text(short) and f"G154 P{p})" in text(short)
    assert "C" in text(7386) and "G129" in text(7386)


def test_g154_p21_to_p99_have_their_own_offsets() -> None:
    for p in (21, 99):
        first = 14001 + 20 * (p - 1)
        r = row(first)
        assert (r.first, r.last, r.source, r.access) == (first, first + 5, "store", "rw")
        assert f"G154 P{p};" in r.en and f"G154 P{p}" in r.zh
    assert HAAS.system_variable(15967) is None and HAAS.system_variable(7387) is None


def test_ngc_commons_10000_to_10999_are_commons_kept_at_power_off() -> None:
    assert [(r.first, r.last, r.persistent) for r in HAAS.common_ranges] == [
        (100, 199, True), (500, 999, True), (10000, 10999, True)
    ]  # fmt: skip
    for number in (10000, 10500, 10999, 100, 999):
        assert variable_class(number, HAAS) == "persistent", number
        assert HAAS.system_variable(number) is None, number
    assert variable_class(300, HAAS) == "undefined" and variable_class(11000, HAAS) == "system"


def test_settings_and_parameters_are_read_only() -> None:
    assert row(20001).access == row(29999).access == row(30001).access == row(39999).access == "r"
    assert "Setting 20 " in text(20020) and "设定20" in text(20020, "zh") and "Parameter 1 " in text(30001)


def test_tool_offsets_are_by_tool_number_length_then_diameter() -> None:
    assert "Tool 1: length offset" in text(2001) and "Tool 200: length wear" in text(2400)
    assert "Tool 1: diameter" in text(2401) and "wear" in text(2601) and "Tool 200" in text(2800)
    assert all(row(n).access == "rw" and row(n).source == "store" for n in (2001, 2201, 2401, 2601))


def test_positions_have_six_axes_and_work_offsets_start_with_g52() -> None:
    assert "C axis" in text(5006) and "machine" in text(5026) and "skip" in text(5066)
    assert "G52" in text(5201) and "G54" in text(5226) and "C" in text(5226) and "G59" in text(5321)
    assert HAAS.system_variable(5007) is None


def test_address_codes_follow_the_macro_argument_letters() -> None:
    # #4100 + the local variable of the argument letter: A #4101, I #4104, D #4107, F #4109, Z #4126
    assert (row(4109).source, row(4109).param) == ("code", "F") and (row(4120).param) == "T"
    assert "Address I" in text(4104) and "Address D" in text(4107) and "Address Z" in text(4126)
    assert row(4104).default is None


def test_group_12_is_the_work_coordinate_system() -> None:
    assert (row(4012).source, row(4012).param) == ("modal", "wcs") and "G154" in text(4012)
    assert row(4014).source == "store" and row(4014).default is None


def test_the_date_and_time_rows_are_the_0i_s() -> None:
    for number in (3011, 3012):
        assert row(number) == next(r for r in fanuc_data.SYSTEM_VARIABLES if number in r)


def test_probing_macros_o9000_to_o9999_are_on_the_control() -> None:
    assert HAAS.on_control(9832) and HAAS.on_control(9000) and HAAS.on_control(9999)
    assert not HAAS.on_control(8999) and not get_dialect("gsk980tdi").on_control(9832)


def test_haas_switches() -> None:
    assert (HAAS.program_digits, HAAS.m98_program_digits) == (5, 5)
    assert HAAS.if_without_then and not HAAS.keyword_abbreviations and not HAAS.word_format_alarms
    assert HAAS.macro_alarm_base == 3000


HAAS_G = (
    "G00 G01 G02 G03 G04 G09 G10 G12 G13 G17 G18 G19 G20 G21 G28 G29 G31 G35 G36 G37 G40 G41 G42 G43 G44 G47 G49 "
    "G50 G51 G52 G53 G54 G55 G56 G57 G58 G59 G60 G61 G64 G65 G68 G69 G70 G71 G72 G73 G74 G76 G77 G80 G81 G82 G83 "
    "G84 G85 G86 G87 G88 G89 G90 G91 G92 G93 G94 G95 G98 G99 G100 G101 G103 G107 G110 G129 G136 G141 G143 G150 "
    "G153 G154 G174 G184 G187 G234 G254 G255 G268 G269"
).split()
HAAS_M = (
    "M00 M01 M02 M03 M04 M05 M06 M07 M08 M09 M10 M11 M12 M13 M16 M19 M21 M28 M30 M31 M33 M34 M35 M36 M39 M41 M42 "
    "M46 M48 M49 M50 M51 M58 M59 M61 M68 M69 M75 M76 M77 M78 M79 M80 M81 M82 M83 M84 M86 M88 M89 M95 M96 M97 M98 "
    "M99 M104 M105 M109 M130 M131 M138 M139 M158 M159"
).split()


def test_haas_codes_present() -> None:
    assert set(HAAS_G) <= {c.code for c in data.G_CODES}, sorted(set(HAAS_G) - {c.code for c in data.G_CODES})
    assert set(HAAS_M) <= {c.code for c in data.M_CODES}, sorted(set(HAAS_M) - {c.code for c in data.M_CODES})


def test_work_coordinate_codes_are_one_modal_group() -> None:
    groups = {c.code: c.group for c in data.G_CODES}
    assert {groups[c] for c in ("G54", "G59", "G110", "G129", "G154")} == {"wcs"}
    assert groups["G187"] == groups["G65"] == groups["G12"] == groups["G150"] == ""
    assert groups["G141"] == "cutter" and groups["G143"] == "length" and groups["G153"] == "canned"
    m97 = next(c for c in data.M_CODES if c.code == "M97")
    assert "Local subprogram call" in m97.en and "本地子程序" in m97.zh
