"""The Mitsubishi M70/M80 profile (``dialects/profiles/mitsubishi_m70.py``, its tables
``dialects/mitsubishi_m70_data.py``): what sets it apart from the FANUC 0i it is built on, each run
under both profiles (the checks every profile's rows pass are in test_dialect_tables.py; the block
IF in test_semantics_4_block_if.py). docs/profiles.md "mitsubishi-m70" says where each number comes
from and which are still to be confirmed.
"""

from __future__ import annotations

import re

import pytest

from cncmacro.dialects import fanuc_data, get_dialect, mitsubishi_m70_data, normalise_dialect
from cncmacro.dialects.describe import describe_system_variable
from running import final, lines, run
from static_helpers import check, coded

CJK = re.compile(r"[\u4e00-\u9fff]")
M70 = "mitsubishi-m70"
FANUC = "fanuc-0i"


def text(number: int, locale: str = "en") -> str:
    doc = describe_system_variable(get_dialect(M70), number, locale)
    assert doc is not None, f"#{number} is missing"
    return doc.text


def test_mitsubishi_answers_to_its_aliases() -> None:
    for spelling in ("mitsubishi-m70", "M80", "meldas", "m70", "Mitsubishi", "mitsubishim70"):
        assert normalise_dialect(spelling) == M70, spelling
    d = get_dialect(M70)
    assert d.block_if and not get_dialect(FANUC).block_if and not d.lathe


@pytest.mark.parametrize(
    ("number", "en", "zh"),
    [
        (2001, "Tool compensation 1: tool length geometry", "刀长形状补偿值"),
        (2200, "Tool compensation 200: tool length geometry", "刀长形状补偿值"),
        (2201, "Tool compensation 1: tool length wear", "刀长磨损补偿值"),
        (2401, "Tool compensation 1: tool radius geometry", "刀具半径形状补偿值"),
        (2601, "Tool compensation 1: tool radius wear", "刀具半径磨损补偿值"),
        (1031, "User macro input signal 31", "用户宏程序输入信号31"),
        (1035, "User macro input signals, word 4", "用户宏程序输入信号第4组"),
        (1135, "User macro output signals, word 4", "用户宏程序输出信号第4组"),
        (5061, "skip position", "跳转信号位置"),
        (3011, "", ""),
        (4001, "group 01", "第1组"),
    ],
)
def test_mitsubishi_rows_say_what_the_number_is_in_both_languages(number: int, en: str, zh: str) -> None:
    assert en in text(number) and zh in text(number, "zh-CN") and CJK.search(text(number, "zh-CN"))


def test_mitsubishi_reuses_the_fanuc_rows_where_it_reads_a_number_alike() -> None:
    ids = {id(r) for r in mitsubishi_m70_data.SYSTEM_VARIABLES}
    assert all(id(r) in ids for r in fanuc_data._POSITIONS + fanuc_data._MODAL)
    # the FANUC mill's codes, and the multi-step skip G31.1-G31.3 of its own
    assert mitsubishi_m70_data.G_CODES[: len(fanuc_data.G_CODES)] == fanuc_data.G_CODES
    assert [c.code for c in mitsubishi_m70_data.G_CODES[len(fanuc_data.G_CODES) :]] == ["G31.1", "G31.2", "G31.3"]
    m98 = next(c for c in mitsubishi_m70_data.M_CODES if c.code == "M98")
    assert "8 digits" in m98.en and "只能用L" in m98.zh


def test_radius_tables_2401_2800_are_tool_offsets_not_fanucs_work_offset_short_numbers() -> None:
    # #2501 is radius geometry D101 here; on a FANUC 0i it is G54's X (#5221), so G54 X0 goes to 7.
    text_ = lines("#2501=7.", "G90 G54 G00 X0 Y0", "M30")
    m70, fanuc = run(text_, M70), run(text_, FANUC)
    assert m70.status == fanuc.status == "completed"
    assert (m70.read(2501), m70.read(5221)) == (7.0, 0.0)
    assert (fanuc.read(2501), fanuc.read(5221)) == (7.0, 7.0)


def test_tool_radius_from_2401_offsets_the_cutter() -> None:
    # G41 D1 with #2401 = 5. (geometry) and #2601 = -0.5 (wear): the tool runs 4.5 to the left of a
    # line along +X at Y0, so at Y4.5
    text_ = lines("#2401=5.", "#2601=-0.5", "G90 G17 G00 X-20. Y-20.", "G41 D1 G01 X0 Y0 F100", "X50.",
                  "G40 G00 X70. Y-20.", "M30")  # fmt: skip
    m = run(text_, M70)
    assert m.status == "completed", m.alarm
    path = m.planner.moves[2].tool_path  # X50.: its centre path
    assert path is not None and {round(p.end[1], 3) for p in path.pieces} == {4.5}
    assert run(text_, FANUC).status == "alarm"  # no #2401 on a FANUC 0i (memory C stops at #2400)


def test_thirty_two_signals_each_way_and_four_words() -> None:
    text_ = lines("#1=#1033", "#1135=1", "M30")
    assert run(text_, M70).status == "completed"
    assert run(text_, FANUC).status == "alarm"  # #1033 is not a variable of a 0i


def test_commons_are_100_to_199_and_500_to_999() -> None:
    text_ = lines("#300=1", "M30")
    [d] = coded(check(text_, M70), "variable-number")
    assert "#300 is not a common variable" in d.message and "#100-#199" in d.message
    assert check(text_, FANUC) == []


def test_m98_p_is_the_whole_program_number() -> None:
    # P10020 names O10020 here; a 0i reads it as 1 pass of O0020
    text_ = lines("O1000", "M98 P10020", "M30", "O0020", "#101=20", "M99", "O10020", "#101=10020", "M99")
    assert final(text_, M70)[101] == 10020
    assert final(text_, FANUC)[101] == 20


def test_macro_words_are_written_in_full() -> None:
    text_ = lines("#1=0", "WH [#1 LT 2] DO1", "#1=#1+1", "END1", "M30")
    assert [d.code for d in check(text_, M70)] == ["dialect-feature"]
    assert [d.code for d in check(text_, FANUC)] == ["keyword-abbreviation"]


def test_alarms_are_shown_without_a_number() -> None:
    text_ = lines("#3000=1 (TOOL BROKEN)", "M30")
    m70, fanuc = run(text_, M70), run(text_, FANUC)
    assert m70.alarm is not None and fanuc.alarm is not None
    assert str(m70.alarm.message) == str(fanuc.alarm.message) == "TOOL BROKEN"
    assert get_dialect(M70).shown_alarm(m70.alarm.number) is None
    assert get_dialect(FANUC).shown_alarm(fanuc.alarm.number) == 3001


def test_else_and_endif_are_statement_words_where_the_block_if_is() -> None:
    # the editor colours, completes and documents the words of its function table (FunctionDoc.kind)
    def words(profile: str) -> dict[str, str]:
        return {f.signature: f.kind for f in get_dialect(profile).functions() if f.name in ("IF", "ELSE", "ENDIF")}

    assert words(M70) == {
        "IF [condition] GOTO n / IF [condition] THEN statement": "statement",
        "IF [condition] THEN … ELSE … ENDIF": "statement",
        "ELSE": "statement",
        "ENDIF": "statement",
    }
    assert list(words(FANUC)) == ["IF [condition] GOTO n / IF [condition] THEN statement"]
    endif = next(f for f in get_dialect(M70).functions() if f.name == "ENDIF")
    assert "Ends the block IF" in endif.en and CJK.search(endif.zh)
