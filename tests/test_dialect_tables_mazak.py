"""The Mazak EIA/ISO profile (``dialects/profiles/mazak_eia.py``, its tables
``dialects/mazak_eia_data.py``): what sets it apart from the FANUC 0i it is built on and from the
Mitsubishi M70/M80 that shares its block IF, each run under ``fanuc-0i`` too (the checks every
profile's rows pass are in test_dialect_tables.py; ``&&`` and ``||`` in
test_semantics_3_logical_symbols.py, the block IF in test_semantics_4_block_if.py).
docs/profiles.md "mazak-eia" says where each fact comes from and which are still to be confirmed.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from analysis_helpers import analyse_files
from cncmacro.dialects import fanuc_data, get_dialect, mazak_eia_data, normalise_dialect
from cncmacro.dialects.describe import describe_system_variable
from running import final, lines, run
from static_helpers import check, coded

CJK = re.compile(r"[\u4e00-\u9fff]")
MAZAK = "mazak-eia"
FANUC = "fanuc-0i"
M70 = "mitsubishi-m70"


def test_mazak_answers_to_its_aliases() -> None:
    for spelling in ("mazak-eia", "Mazak", "mazakeia", "mazak-matrix", "mazak-smooth", "MAZATROL"):
        assert normalise_dialect(spelling) == MAZAK, spelling
    d = get_dialect(MAZAK)
    assert d.block_if and d.logical_symbols and d.keyword_abbreviations and not d.lathe
    assert not get_dialect(FANUC).logical_symbols and not get_dialect(M70).logical_symbols


def test_mazak_reuses_the_fanuc_rows_where_it_reads_a_number_alike() -> None:
    ids = {id(r) for r in mazak_eia_data.SYSTEM_VARIABLES}
    rows = fanuc_data._TOOL_OFFSETS + fanuc_data._MODAL + fanuc_data._POSITIONS + fanuc_data._WORK_OFFSETS
    assert all(id(r) in ids for r in rows)
    assert mazak_eia_data.G_CODES == fanuc_data.G_CODES


@pytest.mark.parametrize(
    ("number", "en", "zh"),
    [
        (3000, "stops the program with the control's macro alarm", "系统的宏程序报警"),
        (3011, "", ""),
        (4001, "group 01", "第1组"),
        (5221, "G54", "G54"),
        (11001, "Tool length offset H1: geometry", "刀具长度补偿H1"),
    ],
)
def test_mazak_rows_say_what_the_number_is_in_both_languages(number: int, en: str, zh: str) -> None:
    doc, doc_zh = (describe_system_variable(get_dialect(MAZAK), number, locale) for locale in ("en", "zh-CN"))
    assert doc is not None and doc_zh is not None
    assert en in doc.text and zh in doc_zh.text and CJK.search(doc_zh.text)


def test_m98_p_is_the_whole_program_number() -> None:
    # P10020 names O10020 here; a 0i reads it as 1 pass of O0020
    text = lines("O1000", "M98 P10020", "M30", "O0020", "#101=20", "M99", "O10020", "#101=10020", "M99")
    assert final(text, MAZAK)[101] == 10020
    assert final(text, FANUC)[101] == 20


def test_macro_words_may_be_shortened_to_two_letters() -> None:
    # WH for WHILE, GO for GOTO, TH for THEN: #1 counts 0 -> 1 -> 2, the loop ends at 2;
    # [2 EQ 2] holds, so GO 20 passes over #2=5 and TH sets #3 = 2 * 3 = 6
    text = lines(
        "#1=0", "WH [#1 LT 2] DO1", "#1=#1+1", "END1", "IF [#1 EQ 2] GO 20", "#2=5", "N20 IF [#1 GT 0] TH #3=#1*3",
        "M30",
    )  # fmt: skip
    assert final(text, MAZAK) == {1: 2, 3: 6}
    assert final(text, FANUC) == {1: 2, 3: 6}  # FANUC reads them too
    assert not coded(check(text, MAZAK), "dialect-feature")
    assert len(coded(check(text, M70), "dialect-feature")) == 3  # the M70 wants the words in full
    assert run(text, M70).status == "alarm"


def test_mod_is_the_remainder_as_on_fanuc() -> None:
    # 17 MOD 5 = 2; -7 MOD 3 = -1 (the sign of the dividend, as FANUC's)
    text = lines("#1=17 MOD 5", "#2=-7 MOD 3", "M30")
    assert final(text, MAZAK) == final(text, FANUC) == {1: 2, 2: -1}


def test_alarms_are_shown_without_a_number() -> None:
    text = lines("#3000=1 (TOOL BROKEN)", "M30")
    mazak, fanuc = run(text, MAZAK), run(text, FANUC)
    assert mazak.alarm is not None and fanuc.alarm is not None
    assert str(mazak.alarm.message) == str(fanuc.alarm.message) == "TOOL BROKEN"
    assert get_dialect(MAZAK).shown_alarm(mazak.alarm.number) is None
    assert get_dialect(FANUC).shown_alarm(fanuc.alarm.number) == 3001


# ---------------------------------------------------------------------------------------------
# which profile a FANUC file is offered


def suggestions(tmp_path: Path, text: str) -> list[str]:
    """The messages of the ``profile-suggestion`` of ``text`` read as a file under fanuc-0i."""
    return [
        d.message for d in analyse_files(tmp_path, {"MAIN.nc": text}, dialect=FANUC) if d.code == "profile-suggestion"
    ]


def test_logical_symbols_under_fanuc_suggest_mazak_once(tmp_path: Path) -> None:
    text = lines(
        "#1=3", "IF [[#1 GT 0] && [#1 LT 5]] GOTO 10", "#2=1", "N10 IF [[#1 EQ 3] || [#2 EQ 0]] THEN #3=1", "M30"
    )
    [message] = suggestions(tmp_path, text)
    assert message.startswith("This file uses what Mazak EIA/ISO (Matrix, Smooth) has and FANUC 0i Custom Macro B")
    assert "(lines 2, 4)" in message and "add (cncmacro: dialect=mazak-eia)" in message
    assert "IF..THEN / ELSE / ENDIF" not in message  # no block IF in this file
    assert check(text, MAZAK) == []


def test_block_if_alone_under_fanuc_still_suggests_mitsubishi_and_names_mazak(tmp_path: Path) -> None:
    text = lines("#1=7", "IF [#1 GT 5] THEN", "#2=10", "ELSE", "#2=20", "ENDIF", "M30")
    [message] = suggestions(tmp_path, text)
    assert "add (cncmacro: dialect=mitsubishi-m70)" in message
    assert message.endswith(
        "; the profile mazak-eia (Mazak EIA/ISO (Matrix, Smooth)) reads IF..THEN / ELSE / ENDIF blocks too"
    )


def test_block_if_with_logical_symbols_under_fanuc_suggests_mazak_and_names_mitsubishi(tmp_path: Path) -> None:
    text = lines("#1=7", "IF [[#1 GT 5] || [#1 LT 0]] THEN", "#2=10", "ELSE", "#2=20", "ENDIF", "M30")
    [message] = suggestions(tmp_path, text)
    assert "add (cncmacro: dialect=mazak-eia)" in message
    assert "the profile mitsubishi-m70 (Mitsubishi M70/M80 user macro) reads IF..THEN" in message
    assert final(text, MAZAK) == {1: 7, 2: 10}  # [7 GT 5] holds
    assert run(text, M70).status == "alarm"  # the M70 has the block IF, not ||
