"""Running programs on ``fanuc-30i``: system variable names, constants, the 30i functions, M98 P.

The rules are docs/semantics.md's (§2 names and constants, §3 functions, §5 M98) with the sources
in docs/profiles.md "fanuc-30i: sources and decisions". Each rule that the 30i adds is also run
on ``fanuc`` (FANUC 0i) and ``gsk980tdi``, which must not have it.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from running import alarm, final, lines, run

D30 = "fanuc-30i"

# ---------------------------------------------------------------------------------------------
# constants #3100-#3102


def test_30i_constant_3101_is_pi() -> None:
    assert final(lines("#1=#3101", "M30"), D30)[1] == math.pi


def test_30i_constant_3102_is_e() -> None:
    assert final(lines("#1=#3102", "M30"), D30)[1] == math.e


def test_30i_constant_3100_is_vacant_like_0() -> None:
    got = final(lines("#1=5", "#1=#3100", "IF[#3100 EQ #0] THEN #2=1", "M30"), D30)
    assert 1 not in got and got[2] == 1.0


@pytest.mark.parametrize("number", [3100, 3101, 3102])
def test_30i_constants_cannot_be_written_alarm_116(number: int) -> None:
    assert alarm(lines(f"#{number}=3", "M30"), D30) == (116, 1)


def test_30i_constants_cannot_be_preset_either() -> None:
    with pytest.raises(ValueError, match="cannot be preset"):
        final(lines("#1=#3101", "M30"), D30, presets={3101: 3.0})


@pytest.mark.parametrize("dialect", ["fanuc", "gsk980tdi"])
def test_constant_3101_does_not_exist_on_the_0i_or_gsk_alarm_115(dialect: str) -> None:
    assert alarm(lines("#1=#3101", "M30"), dialect) == (115, 1)


# ---------------------------------------------------------------------------------------------
# names [#_NAME] and [#_NAME[n]]


def test_30i_named_variable_absio_is_5001() -> None:
    got = final(lines("G90 G00 X12.5 Y-3", "#1=[#_ABSIO[1]]", "#2=[#_ABSIO[2]]", "#3=#5001", "M30"), D30)
    assert (got[1], got[2], got[3]) == (12.5, -3.0, 12.5)


def test_30i_named_variable_subscript_is_an_expression_rounded_like_a_variable_number() -> None:
    got = final(lines("G90 G00 X1 Y2 Z3", "#9=2.5", "#1=[#_ABSIO[#9]]", "#2=#_ABSIO[#9-1]+10", "M30"), D30)
    assert (got[1], got[2]) == (3.0, 12.0)


def test_30i_named_variable_without_subscript_date_is_3011() -> None:
    got = final(lines("#1=[#_DATE]", "#2=#3011", "#3=[#_PI]", "M30"), D30)
    assert got[1] == got[2] == 20261122.0 and got[3] == math.pi


def test_30i_named_variable_assignment_uo_writes_1100() -> None:
    got = final(lines("[#_UO[1]]=1", "[#_UO[32]]=1", "#1=#1100", "#2=#1131", "#3=[#_UO[1]]", "M30"), D30)
    assert (got[1], got[2], got[3]) == (1.0, 1.0, 1.0)


def test_30i_named_variable_in_an_if_then_and_an_address() -> None:
    got = final(lines("#100=7", "IF[#100 GT 1] THEN [#_UO[2]]=#100", "G90 G00 X[#_UO[2]]", "#1=#5001", "M30"), D30)
    assert got[1] == 7.0 and got[1101] == 7.0


def test_30i_named_tool_offset_ofshw_is_10001() -> None:
    got = final(lines("[#_OFSHW[3]]=0.25", "#1=#10003", "#2=#2003", "M30"), D30)
    assert got[1] == got[2] == 0.25


def test_30i_named_macro_alarm_alm_raises_3000_plus_n() -> None:
    assert alarm(lines("[#_ALM]=12(TOO DEEP)", "M30"), D30) == (3012, 1)


def test_30i_named_read_only_variable_cannot_be_written_alarm_116() -> None:
    assert alarm(lines("[#_ABSIO[1]]=2", "M30"), D30) == (116, 1)


def test_30i_unknown_name_is_alarm_1098() -> None:
    assert alarm(lines("#1=[#_NOSUCH]", "M30"), D30) == (1098, 1)


@pytest.mark.parametrize(
    "text",
    ["#1=[#_ABSIO[5]]", "#1=[#_ABSIO[0]]", "#1=[#_ABSIO]", "#1=[#_DATE[1]]", "#1=[#_ABSIO[#0]]", "[#_UO[33]]=1"],
)
def test_30i_missing_unexpected_or_out_of_range_subscript_is_alarm_1099(text: str) -> None:
    assert alarm(lines(text, "M30"), D30) == (1099, 1)


@pytest.mark.parametrize("dialect", ["fanuc", "gsk980tdi"])
@pytest.mark.parametrize("text", ["#1=[#_ABSIO[1]]", "[#_UO[1]]=1", "#1=[#_DATE]"])
def test_names_are_not_a_feature_of_the_0i_or_gsk_alarm_114(dialect: str, text: str) -> None:
    assert alarm(lines(text, "M30"), dialect) == (114, 1)


# ---------------------------------------------------------------------------------------------
# other 30i system variables


def test_30i_4000_is_the_main_program_number_also_inside_a_subprogram(tmp_path: Path) -> None:
    (tmp_path / "O0200.nc").write_text("O0200\n#100=#4000\n#101=#4115\nM99\n", encoding="utf-8")
    got = final(lines("O0012", "M98 P200", "M30"), D30, folder=tmp_path)
    assert (got[100], got[101]) == (12.0, 200.0)


def test_30i_4201_reads_the_modal_of_the_block_being_executed() -> None:
    got = final(lines("G91 G01 X1 F100 G55", "#1=#4201", "#2=#4203", "#3=#4214", "#4=[#_ACTG[3]]", "M30"), D30)
    assert (got[1], got[2], got[3], got[4]) == (1.0, 91.0, 55.0, 91.0)


def test_30i_14001_is_another_number_for_g54_1_p1() -> None:
    got = final(lines("#7001=3.5", "#1=#14001", "#14942=-2", "#2=#7942", "M30"), D30)
    assert (got[1], got[2]) == (3.5, -2.0)


def test_30i_100001_is_the_block_end_position_like_5001() -> None:
    got = final(lines("G90 G00 X4 Y5", "#1=#100001", "#2=#100002", "M30"), D30)
    assert (got[1], got[2]) == (4.0, 5.0)


@pytest.mark.parametrize("dialect", ["fanuc", D30])
def test_5121_manual_handle_interruption_reads_0(dialect: str) -> None:
    assert final(lines("G90 G00 X4", "#1=#5121", "#2=#5124", "M30"), dialect)[1] == 0.0


def test_30i_has_32_interface_input_bits() -> None:
    assert final(lines("#1=#1031", "M30"), D30, presets={1031: 1.0})[1] == 1.0
    assert alarm(lines("#1=#1031", "M30"), "fanuc") == (115, 1)


# ---------------------------------------------------------------------------------------------
# functions


def test_30i_pow_2_3_is_8() -> None:
    got = final(lines("#1=POW[2,3]", "#2=POW[9,0.5]", "#3=POW[-2,3]", "#4=POW[#0,2]", "M30"), D30)
    assert (got[1], got[2], got[3], got[4]) == (8.0, 3.0, -8.0, 0.0)


@pytest.mark.parametrize("text", ["#1=POW[-8,1/3]", "#1=POW[0,-1]"])
def test_30i_pow_without_a_real_value_is_alarm_119(text: str) -> None:
    assert alarm(lines(text, "M30"), D30) == (119, 1)


def test_30i_pow_too_large_is_alarm_111() -> None:
    assert alarm(lines("#1=POW[10,400]", "M30"), D30) == (111, 1)


def test_30i_atan_with_a_comma_is_atan_with_a_slash() -> None:
    got = final(lines("#1=ATAN[1,-1]", "#2=ATAN[1]/[-1]", "#3=ATAN[-1,0]", "M30"), D30)
    assert got[1] == got[2] == 135.0 and got[3] == 270.0


def test_30i_adp_gives_back_the_argument_written_in_both_input_modes(tmp_path: Path) -> None:
    (tmp_path / "O9000.nc").write_text("O9000\n#100=ADP[#24]\nM99\n", encoding="utf-8")
    for mode in ("calculator", "increment"):
        assert final(lines("O0001", "G65 P9000 X10", "M30"), D30, folder=tmp_path, decimal_point=mode)[100] == 10.0


def test_30i_prm_reads_0_as_the_simulated_machine_has_no_parameters() -> None:
    got = final(lines("#1=PRM[6001]", "#2=PRM[1320,2]", "#3=PRM[3202]/[4]", "#4=PRM[1005,1]/[0]", "M30"), D30)
    assert (got[1], got[2], got[3], got[4]) == (0.0, 0.0, 0.0, 0.0)


@pytest.mark.parametrize("dialect", ["fanuc", "gsk980tdi"])
@pytest.mark.parametrize("text", ["#1=POW[2,3]", "#1=ATAN[1,1]", "#1=ADP[1]", "#1=PRM[6001]"])
def test_30i_functions_are_alarm_114_on_the_0i_and_gsk(dialect: str, text: str) -> None:
    assert alarm(lines(text, "M30"), dialect) == (114, 1)


@pytest.mark.parametrize("dialect", ["fanuc", D30])
@pytest.mark.parametrize("text", ["#1=SIN[1,2]", "#1=POW[2]", "#1=ADP[1,2]"])
def test_a_function_written_with_the_wrong_arguments_is_alarm_114(dialect: str, text: str) -> None:
    assert alarm(lines(text, "M30"), dialect) == (114, 1)


# ---------------------------------------------------------------------------------------------
# M98 P on the 30i: the whole program number, the count in L


def test_30i_m98_p_is_the_whole_program_number(tmp_path: Path) -> None:
    (tmp_path / "O30040.nc").write_text("O30040\n#100=#100+1\nM99\n", encoding="utf-8")
    (tmp_path / "O0040.nc").write_text("O0040\n#101=#101+1\nM99\n", encoding="utf-8")
    assert final(lines("O0001", "M98 P30040", "M30"), D30, folder=tmp_path) == {100: 1.0}
    assert final(lines("O0001", "M98 P30040", "M30"), "fanuc", folder=tmp_path) == {101: 3.0}


def test_30i_m98_counts_only_in_l(tmp_path: Path) -> None:
    (tmp_path / "O12345678.nc").write_text("O12345678\n#100=#100+1\nM99\n", encoding="utf-8")
    assert final(lines("O0001", "M98 P12345678 L3", "M30"), D30, folder=tmp_path) == {100: 3.0}


# ---------------------------------------------------------------- §2 common ranges of the 30i


def test_2_30i_extended_commons_98000_to_98499_exist_and_0i_lacks_them():
    got = final(lines("#98000=1.5", "#98499=#98000*2", "#400=#98499", "M30"), D30)
    assert got[98000] == 1.5 and got[98499] == 3.0 and got[400] == 3.0
    assert alarm(lines("#98000=1", "M30"))[0] == 115  # fanuc-0i
    assert alarm(lines("#98500=1", "M30"), D30)[0] == 115


def test_2_30i_a_machine_without_the_extended_commons_alarms_on_them():
    narrow = ((100, 199), (500, 999))
    assert alarm(lines("#98000=1", "M30"), D30, common=narrow)[0] == 115


def test_2_30i_extended_commons_are_kept_at_power_off():
    from cncmacro.dialects import get_dialect
    from cncmacro.machine.expressions import VariableKinds

    kinds = VariableKinds(get_dialect(D30))
    assert kinds.kind(98000) == "extended" and 98000 in kinds.persistent_numbers()
    m = run(lines("#98000=7", "#500=8", "#100=9", "M30"), D30)
    assert m.persistent_values() == {500: 8.0, 98000: 7.0}


def test_5_an_8_digit_file_name_without_header_is_found(tmp_path):
    (tmp_path / "O00012345.nc").write_text("#100=5\nM99\n", encoding="utf-8")
    assert final(lines("O00001000", "M98 P00012345", "M30"), D30, folder=tmp_path)[100] == 5
