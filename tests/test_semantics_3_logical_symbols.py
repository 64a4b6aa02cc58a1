"""docs/semantics.md §3 "``&&`` and ``||``": AND and OR spelled with symbols, behind
``Dialect.logical_symbols`` (the ``mazak-eia`` profile; docs/profiles.md "mazak-eia").

Where the profile reads them, ``&&`` is AND (the level of ``*``) and ``||`` is OR (the level of
``+``): between two bracketed conditions they join them, between numbers they work bit by bit as
the words do. Elsewhere each is a ``dialect-feature`` error that names the word to write, and the
run stops at the block with alarm 114. Every program here runs under ``fanuc-0i`` too.
"""

from __future__ import annotations

import pytest

from cncmacro.syntax.block_parser import parse_block
from cncmacro.syntax.formatting import SPACED, FormatOptions, format_lines
from cncmacro.syntax.nodes import Assign, Binary, Bracket, If
from running import lines, run
from static_helpers import at, check, coded

MAZAK = "mazak-eia"
FANUC = "fanuc-0i"


def outcome(text: str, dialect: str) -> tuple[str, dict[int, float], int | None]:
    """(status, variables, 1-based line of the alarm or None) of a run."""
    m = run(text, dialect)
    return m.status, m.variables(), None if m.alarm is None else m.alarm.line + 1


# ---------------------------------------------------------------------------------------------
# reading them


def test_3_logical_symbols_are_read_as_operators_of_their_words_level() -> None:
    [s] = parse_block("IF [[#1 GT 0] && [#2 LT 5]] GOTO 10").statements
    assert isinstance(s, If) and isinstance(s.condition, Bracket)
    joined = s.condition.inner
    assert isinstance(joined, Binary) and joined.op == "&&"
    # && binds as AND does, tighter than ||: 1 || 2 && 6 is 1 || [2 && 6]
    [a] = parse_block("#5=1 || 2 && 6").statements
    assert isinstance(a, Assign)
    value = a.value
    assert isinstance(value, Binary) and value.op == "||"
    assert isinstance(value.right, Binary) and value.right.op == "&&"


# ---------------------------------------------------------------------------------------------
# running them


# #1 = 3, #2 = 7: [3 GT 0] holds, [7 LT 5] fails, so && fails and the GOTO is not taken (#3 = 1);
# [3 EQ 3] holds, so || holds whatever [7 EQ 0] is, and #4 = 1
JOINED = lines(
    "O1000",
    "#1=3",
    "#2=7",
    "IF [[#1 GT 0] && [#2 LT 5]] GOTO 10",
    "#3=1",
    "N10 IF [[#1 EQ 3] || [#2 EQ 0]] THEN #4=1",
    "M30",
)


def test_3_logical_symbols_join_conditions_as_and_and_or() -> None:
    assert outcome(JOINED, MAZAK) == ("completed", {1: 3, 2: 7, 3: 1, 4: 1}, None)
    assert outcome(JOINED, FANUC) == ("alarm", {1: 3, 2: 7}, 4)  # alarm 114 at the first &&


def test_3_logical_symbols_run_the_same_as_the_words() -> None:
    words = JOINED.replace("&&", "AND").replace("||", "OR")
    assert outcome(words, MAZAK) == outcome(JOINED, MAZAK)
    assert outcome(words, FANUC) == ("completed", {1: 3, 2: 7, 3: 1, 4: 1}, None)


def test_3_logical_symbols_between_numbers_work_bit_by_bit() -> None:
    # 6 && 3 = 0b110 & 0b011 = 0b010 = 2; 4 || 1 = 0b100 | 0b001 = 5;
    # 1 || 2 && 6 = 1 | (2 & 6) = 1 | 2 = 3 (&& first, as AND before OR)
    text = lines("#1=6 && 3", "#2=4 || 1", "#3=1 || 2 && 6", "M30")
    assert outcome(text, MAZAK) == ("completed", {1: 2, 2: 5, 3: 3}, None)
    assert outcome(text, FANUC) == ("alarm", {}, 1)


def test_3_logical_symbols_in_a_while_condition() -> None:
    # #1 counts 0, 1, 2 … while [#1 LT 5] && [#2 NE 1]: #2 becomes 1 when #1 reaches 3
    # (pass 1: #1 = 1; pass 2: #1 = 2; pass 3: #1 = 3, #2 = 1), so the loop ends with #1 = 3
    text = lines(
        "#1=0",
        "#2=0",
        "WHILE [[#1 LT 5] && [#2 NE 1]] DO1",
        "#1=#1+1",
        "IF [#1 EQ 3] THEN #2=1",
        "END1",
        "M30",
    )
    assert outcome(text, MAZAK) == ("completed", {1: 3, 2: 1}, None)
    assert outcome(text, FANUC) == ("alarm", {1: 0, 2: 0}, 3)


def test_3_logical_symbols_in_a_long_chain() -> None:
    # 20 operands: 1 && 1 && … && 1 = 1, then || 2 = 3 (the chain is compiled as a loop)
    text = lines("#1=" + " && ".join(["1"] * 20) + " || 2", "M30")
    assert outcome(text, MAZAK) == ("completed", {1: 3}, None)
    assert outcome(text, FANUC)[0] == "alarm"


# ---------------------------------------------------------------------------------------------
# what the checks say


def test_3_logical_symbols_are_clean_on_mazak_and_a_dialect_feature_elsewhere() -> None:
    assert check(JOINED, MAZAK) == []
    found = coded(check(JOINED, FANUC), "dialect-feature")
    # marked between the two operands: "IF [[#1 GT 0] && [#2 LT 5]]" puts "] && [" at 13-17
    assert [at(d) for d in found] == [(4, 13, 17, "error"), (6, 17, 21, "error")]
    assert found[0].message == (
        "'&&' is not an operator of FANUC 0i Custom Macro B, which stops at this block with alarm 114 "
        "(Mazak controls in EIA/ISO read it as AND); write AND"
    )
    assert "write OR" in found[1].message


@pytest.mark.parametrize("profile", ["fanuc-30i", "haas", "gsk980tdi", "mitsubishi-m70"])
def test_3_logical_symbols_are_refused_on_every_other_profile(profile: str) -> None:
    assert len(coded(check(JOINED, profile), "dialect-feature")) == 2
    assert run(JOINED, profile).status == "alarm"


def test_3_logical_symbols_refused_is_said_in_chinese() -> None:
    [d, *_] = coded(check(JOINED, FANUC, locale="zh-CN"), "dialect-feature")
    assert d.message.startswith("“&&”不是 FANUC 0i Custom Macro B 的运算符") and "请写作 AND" in d.message


def test_3_logical_symbols_are_spaced_by_the_formatter_as_their_words() -> None:
    lines_ = ["IF[[#1GT0]&&[#2LT5]]GOTO10", "#5=1||2&&6"]
    spaced = format_lines(lines_, 0, 1, FormatOptions(spacing=SPACED))
    assert spaced == {0: "IF [[#1 GT 0] && [#2 LT 5]] GOTO 10", 1: "#5=1 || 2 && 6"}
    assert spaced[0] == format_lines(["IF[[#1GT0]AND[#2LT5]]GOTO10"], 0, 0, FormatOptions())[0].replace("AND", "&&")
