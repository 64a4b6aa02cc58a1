"""Checking programs for ``fanuc-30i``: names, constants and the 30i functions, and the same text on
the dialects that lack them (docs/semantics.md §2, §3; docs/design.md "Diagnostic codes").

What the text alone decides is found without running: an unknown name or a literal subscript out
of range is ``variable-number`` (alarm 1098/1099), writing a constant or a read-only name is
``write-protected`` (116), a name or 30i function on another dialect is ``dialect-feature`` (114),
a function written with the wrong arguments is ``syntax`` (114). A subscript known only when the
block runs is judged by the analysis run.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from analysis_helpers import analyse_files
from static_helpers import at, check, coded, lines

D30 = "fanuc-30i"


def codes(text: str, dialect: str = D30) -> list[str]:
    return [d.code for d in check(lines("O0001", text, "M30"), dialect) if d.code != "not-executed"]


@pytest.mark.parametrize(
    "text",
    ["#1=[#_ABSIO[1]]", "#1=[#_ABSIO[#2]]", "#1=[#_DATE]+[#_TIME]", "[#_UO[1]]=1", "[#_OFSHG[#3]]=#4",
     "IF[[#_UI[3]] EQ 1] THEN #5=1", "G90 G00 X[#_ABSIO[1]+1]", "#1=#3101*2", "#1=POW[2,3]+ATAN[1,2]",
     "#1=ADP[#24]", "#1=PRM[1320,1]/[2]", "#1=PRM[6001]/[0]"],
)  # fmt: skip
def test_30i_names_constants_and_functions_check_clean(text: str) -> None:
    assert codes(text) == []


def test_30i_unknown_name_is_variable_number_alarm_1098() -> None:
    found = coded(check(lines("O0001", "#1=[#_NOSUCH]", "M30"), D30), "variable-number")
    assert [at(d) for d in found] == [(2, 4, 12, "error")]
    assert "#_NOSUCH" in found[0].message and "alarm 1098" in found[0].message


@pytest.mark.parametrize("text", ["#1=[#_ABSIO[5]]", "#1=[#_ABSIO]", "#1=[#_DATE[1]]", "[#_UO[0]]=1"])
def test_30i_bad_literal_subscript_is_variable_number_alarm_1099(text: str) -> None:
    found = coded(check(lines("O0001", text, "M30"), D30), "variable-number")
    assert len(found) == 1 and "alarm 1099" in found[0].message


def test_30i_writing_a_constant_or_a_read_only_name_is_write_protected() -> None:
    assert codes("#3101=3") == ["write-protected"]
    assert codes("[#_PI]=3") == ["write-protected"]
    assert codes("[#_ABSIO[2]]=3") == ["write-protected"]


def test_30i_reading_the_alarm_by_name_is_write_only() -> None:
    assert codes("#1=[#_ALM]") == ["write-only"]


@pytest.mark.parametrize("dialect", ["fanuc", "gsk980tdi"])
def test_names_on_the_0i_and_gsk_are_a_dialect_feature(dialect: str) -> None:
    found = coded(check(lines("O0001", "#1=[#_ABSIO[1]]", "[#_UO[1]]=1", "M30"), dialect), "dialect-feature")
    assert [at(d)[:3] for d in found] == [(2, 4, 14), (3, 1, 8)]
    assert "FANUC 30i" in found[0].message and "alarm 114" in found[0].message


@pytest.mark.parametrize("dialect", ["fanuc", "gsk980tdi"])
@pytest.mark.parametrize("text", ["#1=POW[2,3]", "#1=ATAN[1,2]", "#1=ADP[1]", "#1=PRM[6001]"])
def test_30i_functions_on_the_0i_and_gsk_are_a_dialect_feature(dialect: str, text: str) -> None:
    found = check(lines("O0001", text, "M30"), dialect)
    assert [d.code for d in found if d.code != "not-executed"] == ["dialect-feature"]


def test_30i_function_on_the_0i_says_so_in_chinese() -> None:
    found = check(lines("O0001", "#1=POW[2,3]", "M30"), "fanuc", locale="zh-cn")
    message = coded(found, "dialect-feature")[0].message
    assert "没有 POW[a,b] 这个函数" in message and "报警 114" in message


@pytest.mark.parametrize("dialect", ["fanuc", D30, "gsk980tdi"])
@pytest.mark.parametrize("text", ["#1=SIN[1,2]", "#1=POW[2]", "#1=ADP[1,2]"])
def test_a_function_with_the_wrong_arguments_is_a_syntax_error(dialect: str, text: str) -> None:
    assert "syntax" in codes(text, dialect)


def test_30i_constant_does_not_exist_on_the_0i() -> None:
    assert codes("#1=#3101", "fanuc") == ["variable-number"]


def test_30i_subscript_known_only_when_running_is_found_by_the_run(tmp_path: Path) -> None:
    found = analyse_files(tmp_path, {"O0001.nc": lines("O0001", "#2=7", "#1=[#_ABSIO[#2]]", "M30")}, D30)
    wrong = [d for d in found if d.code == "variable-number"]
    assert len(wrong) == 1 and wrong[0].line == 2 and "1099" in wrong[0].message
