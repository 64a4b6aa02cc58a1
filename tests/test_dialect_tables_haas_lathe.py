"""The Haas lathe tables (``dialects/haas_lathe_data.py``): what they say that the Haas mill's and
the FANUC lathe's do not (the checks every profile's rows pass are in test_dialect_tables.py).

docs/profiles.md "haas-lathe: sources and decisions" says where each number comes from and which
are still to be confirmed against the Haas lathe manual.
"""

from __future__ import annotations

import pytest

from cncmacro.dialects import get_dialect, normalise_dialect
from cncmacro.dialects.describe import describe_system_variable

LATHE = get_dialect("haas-lathe")
MILL = get_dialect("haas")


def text(number: int, locale: str = "en") -> str:
    doc = describe_system_variable(LATHE, number, locale)
    assert doc is not None, f"#{number} is missing"
    return doc.text


def test_haas_lathe_answers_to_its_aliases_and_is_a_lathe_with_the_mill_s_axis_order() -> None:
    for spelling in ("haas-lathe", "HAAS-ST", "haas-sl", "haaslathe", "haas-turn"):
        assert normalise_dialect(spelling) == "haas-lathe", spelling
    assert LATHE.lathe and LATHE.axes == MILL.axes  # #5023 is Z on both


@pytest.mark.parametrize(
    ("number", "en", "zh"),
    [(2001, "X geometry", "X轴几何形状补偿"), (2051, "Y geometry", "Y轴几何形状补偿"),
     (2101, "Z geometry", "Z轴几何形状补偿"),
     (2201, "tool nose radius", "刀尖半径"), (2301, "imaginary tool tip direction", "假想刀尖方向"),
     (2701, "X wear", "X轴磨损补偿"), (2751, "Y wear", "Y轴磨损补偿"), (2801, "Z wear", "Z轴磨损补偿"),
     (2901, "tool nose radius wear", "刀尖半径磨损补偿"), (2050, "X geometry", "X轴几何形状补偿")],
)  # fmt: skip
def test_tool_offsets_are_the_lathe_s_by_offset_number_in_english_and_chinese(number: int, en: str, zh: str) -> None:
    assert en in text(number) and zh in text(number, "zh-cn")


def test_the_offsets_stop_at_fifty_and_the_mill_s_tool_rows_are_gone() -> None:
    assert LATHE.system_variable(2051) is not None and LATHE.system_variable(2151) is None
    for number in (1601, 1801, 2401, 2601, 3026, 3028, 7501, 8550):  # flutes, diameters, spindle tool, pallets
        assert MILL.system_variable(number) is not None and LATHE.system_variable(number) is None, number


def test_the_offsets_the_planner_reads_are_the_tables_geometry_and_wear() -> None:
    offsets = LATHE.lathe_offsets
    assert ("X", 2000, 2700) in offsets.axes and ("Z", 2100, 2800) in offsets.axes
    assert offsets.radius == (2200, 2900) and offsets.tip == 2300
    # a FANUC lathe keeps its wear where Haas keeps the geometry
    assert ("X", 15000, 10000) in get_dialect("fanuc-0i-lathe").lathe_offsets.axes


def test_5081_is_the_tool_offset_in_effect_and_4010_the_feed_group() -> None:
    assert "tool offset in effect" in text(5081) and "当前生效的刀具偏置" in text(5081, "zh-cn")
    assert "G98, G99" in text(4010) and "G96, G97" in text(4013)


def test_rows_the_lathe_reads_as_the_mill_are_the_mill_s_own() -> None:
    for number in (3001, 3011, 4109, 5021, 5221, 14001, 20001, 10500):
        assert LATHE.system_variable(number) == MILL.system_variable(number), number


def test_g_and_m_codes_are_the_lathe_s() -> None:
    g = {c.code: c for c in LATHE.g_codes()}
    m = {c.code: c for c in LATHE.m_codes()}
    assert "D (first depth)" in g["G76"].en and "单段" in g["G71"].zh
    assert g["G99"].group == "feed" and g["G96"].group == "spindle"
    assert "G43" not in g and "G110" not in g  # no length offset; G112 is the XC interpolation
    assert "Parts catcher" in m["M36"].en and "接料器" in m["M36"].zh and "M06" not in m


def test_cycle_words_describe_haas_s_one_block_forms() -> None:
    g71 = LATHE.cycle_words[71.0].form_of("PQUWDF")
    g76 = LATHE.cycle_words[76.0].form_of("XZKDF")
    assert (word := g71.word("D")) is not None and "depth of each roughing cut" in word.en
    assert (word := g76.word("K")) is not None and "thread height" in word.en
    assert (word := g76.word("A")) is not None and "刀尖角度" in word.zh
    # the FANUC first block is still described where a program writes it
    assert LATHE.cycle_words[71.0].form_of("UR").word("U") is not None
