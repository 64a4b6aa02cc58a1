"""Running programs on ``haas`` (Haas NGC mills): the variables, program numbers and codes that
set it apart, each run on ``fanuc-0i`` too, which must not have it.

The rules are docs/semantics.md's (§2 variables and commons, §5 calls and program numbers, §6
alarms, §8 words a control refuses) with the sources in docs/profiles.md "haas: sources and
decisions".
"""

from __future__ import annotations

import pytest

from cncmacro.library.machine_file import MachineSettings
from cncmacro.library.programs import ProgramLibrary
from cncmacro.machine import Machine
from running import FIXED_CLOCK, alarm, final, lines, machine, run

HAAS = "haas"
FANUC = "fanuc-0i"

# ---------------------------------------------------------------------------------------------
# §2 system variables Haas has and the 0i does not


def test_haas_3026_reads_the_tool_in_the_spindle() -> None:
    assert final(lines("T7 M06", "#1=#3026", "M30"), HAAS)[1] == 7.0


def test_3026_does_not_exist_on_the_0i_alarm_115() -> None:
    assert alarm(lines("#1=#3026", "M30"), FANUC) == (115, 1)


@pytest.mark.parametrize("number", [3026, 3020, 3027, 1066, 1264, 20001, 30001])
def test_haas_read_only_variables_cannot_be_written_alarm_116(number: int) -> None:
    assert alarm(lines("#1=1", f"#{number}=3", "M30"), HAAS) == (116, 2)


@pytest.mark.parametrize("number", [3026, 3020, 3027, 1066, 1264, 20001, 30001])
def test_the_haas_read_only_variables_do_not_exist_on_the_0i_a_write_is_alarm_115(number: int) -> None:
    # the 0i's table (fanuc_data) has no #3020-#3027 timers and switches, axis loads, settings or
    # parameters
    assert alarm(lines("#1=1", f"#{number}=3", "M30"), FANUC) == (115, 2)


def test_haas_settings_and_parameters_read_0_until_preset() -> None:
    got = final(lines("#1=#20020", "#2=#30001", "M30"), HAAS, presets={30001: 2.0})
    assert (got[1], got[2]) == (0.0, 2.0)


@pytest.mark.parametrize("number", [20020, 30001])
def test_settings_and_parameters_do_not_exist_on_the_0i_alarm_115(number: int) -> None:
    assert alarm(lines(f"#1=#{number}", "M30"), FANUC) == (115, 1)


def test_haas_14001_is_g154_p1_the_same_offset_as_g110_7001() -> None:
    got = final(lines("#1=#14001", "#14021=2.5", "#2=#7021", "#3=#15966", "M30"), HAAS, presets={7001: 5.0})
    assert (got[1], got[2], got[3]) == (5.0, 2.5, 0.0)


def test_g154_p99_offsets_do_not_exist_on_the_0i_alarm_115() -> None:
    assert alarm(lines("#1=#15961", "M30"), FANUC) == (115, 1)


def test_haas_has_a_sixth_axis_c_in_the_position_variables() -> None:
    got = final(lines("G90 G00 X1. C30.", "#1=#5006", "#2=#5026", "M30"), HAAS)
    assert (got[1], got[2]) == (30.0, 30.0)
    assert alarm(lines("#1=#5006", "M30"), FANUC) == (115, 1)


G54_C = lines("#5226=30.", "G90 G54 G00 C10.", "#1=#5026", "#2=#5006", "M30")


def test_haas_g54_to_g59_offsets_have_six_axes_5226_is_the_g54_c_offset() -> None:
    got = final(G54_C, HAAS)
    assert (got[1], got[2]) == (40.0, 10.0)  # machine C = work C + the G54 C offset
    assert final(lines("#5326=2.", "#1=#5326", "M30"), HAAS)[1] == 2.0  # G59 C


def test_fanuc_0i_work_offsets_have_four_axes_5226_is_alarm_115() -> None:
    # the 0i's G54-G59 rows are #5221-#5224 ... #5321-#5324 (X Y Z A; docs/profiles.md)
    assert alarm(G54_C, FANUC) == (115, 1)


def test_haas_group_12_reads_the_work_coordinate_system() -> None:
    assert final(lines("G55", "#1=#4012", "M30"), HAAS)[1] == 55.0
    assert final(lines("G55", "#1=#4012", "M30"), FANUC)[1] == 67.0  # the 0i's group 12 is G66/G67


# ---------------------------------------------------------------------------------------------
# §2 commons: #10000-#10999, and every common kept at power-off


def test_haas_10000_range_is_common_and_kept_at_power_off() -> None:
    m = run(lines("#10500=3", "#1=#10500", "#100=4", "#10999=1", "M30"), HAAS)
    assert m.status == "completed" and m.variables()[1] == 3.0
    kept = {n: v for n, v in m.persistent_values().items() if v is not None}
    assert kept == {100: 4.0, 10500: 3.0, 10999: 1.0}


def test_10000_range_commons_do_not_exist_on_the_0i_alarm_115() -> None:
    assert alarm(lines("#10500=3", "M30"), FANUC) == (115, 1)


def test_haas_has_no_commons_200_to_499_alarm_115() -> None:
    assert alarm(lines("#300=1", "M30"), HAAS) == (115, 1)


def test_fanuc_0i_has_commons_200_to_499_by_the_option_that_adds_them() -> None:
    # docs/profiles.md "Common variables": the 0i's #100-#499 with the option, allowed by default
    assert final(lines("#300=1", "#1=#300", "M30"), FANUC)[1] == 1.0


# ---------------------------------------------------------------------------------------------
# §5 programs: five-digit numbers, probing macros kept on the control


def test_haas_m98_p_names_a_five_digit_program() -> None:
    text = lines("O1", "M98 P12345", "#2=#1", "M30", "O12345", "#1=9", "M99")
    assert final(text, HAAS)[2] == 9.0
    assert alarm(text, FANUC) == (76, 2)  # the 0i reads P12345 as O2345 once


def test_haas_probing_macro_o9832_is_on_the_control() -> None:
    assert final(lines("G65 P9832", "#1=1", "M30"), HAAS)[1] == 1.0
    assert final(lines("G65 P9832", "#1=1", "M30"), FANUC)[1] == 1.0  # FANUC keeps its 9000 series too
    assert alarm(lines("G65 P8832", "#1=1", "M30"), FANUC) == (76, 1)


# §2 address variables: #4101-#4126 hold each letter's last value on Haas, only codes on FANUC
ADDRESSES = lines(
    "#6=#4124",  # no X written yet: vacant
    "G00 X1.3 Y2.",
    "#7=#4124",  # X1.3
    "G01 Z-1. F10.",
    "G02 X3. R1.",  # from X1.3 Y2. to X3. Y2.: a chord of 1.7 under a radius of 1
    "#1=#4124",  # X: the G02's 3.
    "#2=#4125",  # Y: still the G00's 2.
    "#3=#4126",  # Z: -1.
    "#4=#4118",  # R: 1.
    "#5=#4109",  # F: 10.
    "M30",
)


def test_haas_4101_to_4126_hold_the_last_value_of_every_address_axes_and_r_too() -> None:
    got = final(ADDRESSES, HAAS)
    assert (got.get(6), got[7]) == (None, 1.3)
    assert (got[1], got[2], got[3], got[4], got[5]) == (3.0, 2.0, -1.0, 1.0, 10.0)


@pytest.mark.parametrize("dialect", [FANUC, "fanuc-30i"])
def test_fanuc_4101_to_4130_hold_only_codes_4124_is_alarm_115(dialect: str) -> None:
    # FANUC's modal information table has B D F H M N O S T (and P) at #4101-#4130, no axis
    assert alarm(ADDRESSES, dialect) == (115, 1)
    assert final(lines("G01 X1. F10.", "#5=#4109", "M30"), dialect)[5] == 10.0


# §5 M99 Pn in a main program: a branch to Nn on Haas ("N50 M99 P10 branches to N10")
COUNTED_LOOP = lines(
    "O01000",
    "#100=0",
    "N10 #100=#100+1",
    "IF [#100 GE 3] GOTO 60",
    "N50 M99 P10",
    "N60 #101=1",
    "M30",
)


def one_pass_run(text: str, dialect: str) -> Machine:
    """``text`` run as ``cncmacro run`` and ``cncmacro check`` run a program: one pass, a main
    program's M99 ending it."""
    m = Machine(dialect, MachineSettings(**FIXED_CLOCK), ProgramLibrary(), m99_ends_main=True)
    m.start_file("/nonexistent-test-folder/O01000.nc", text)
    m.run()
    return m


def test_haas_m99_p_in_the_main_program_branches_to_n_in_every_run() -> None:
    # passes at N10: #100 = 1, 2, 3; at 3 the IF leaves for N60, which sets #101 and M30 ends
    m = one_pass_run(COUNTED_LOOP, HAAS)
    assert m.status == "completed" and not m.ended_by_main_m99 and m.ended_with == 30.0
    assert (m.variables()[100], m.variables()[101]) == (3.0, 1.0)


def test_fanuc_0i_one_pass_run_stops_at_the_main_programs_m99_p() -> None:
    # run alone, a FANUC program's M99 P10 is most often a subprogram's return to its caller's N10
    m = one_pass_run(COUNTED_LOOP, FANUC)
    assert m.status == "completed" and m.ended_by_main_m99
    assert (m.variables()[100], m.variables().get(101)) == (1.0, None)


# §5 DPRNT on Haas ([H5] p. 125): the manual's own example, and a format it calls illegal


def test_haas_dprnt_prints_the_whole_part_even_when_no_place_is_reserved_for_it() -> None:
    # #1 = 1.5436: [44] 1.5436; [03] keeps one whole place: 1 and .5436 rounded to 3 places,
    # 1.544; [40] the whole part alone: 1; each * prints a space
    m = run(lines("#1=1.5436", "DPRNT[X#1[44]*Z#1[03]*T#1[40]]", "M30"), HAAS)
    assert m.status == "completed" and m.output == ["X1.5436 Z1.544 T1"]


@pytest.mark.parametrize("fmt", ["54", "45", "36", "00"])
def test_haas_dprnt_format_of_more_than_8_places_or_none_is_alarm_114(fmt: str) -> None:
    # 5 + 4 = 9 places, 4 + 5, 3 + 6 = 9, 0 + 0 = 0: the manual's illegal formats
    assert alarm(lines("#1=1.5436", f"DPRNT[X#1[{fmt}]]", "M30"), HAAS) == (114, 2)


# §6 alarm numbers: Haas documents none of FANUC's, so its alarms are shown without one


@pytest.mark.parametrize(
    ("program", "fanuc_number"),
    [
        (lines("GOTO 99", "M30"), 128),  # no N99: FANUC 128
        (lines("#3000=1(HOLE COUNT MISSING)", "M30"), 3001),  # FANUC 3000 + 1
        (lines("#1=0", "#2=1/#1", "M30"), 112),  # division by zero: FANUC 112
    ],
)
def test_haas_alarms_are_shown_without_fanucs_numbers(program: str, fanuc_number: int) -> None:
    haas, fanuc = run(program, HAAS), run(program, FANUC)
    assert haas.alarm is not None and fanuc.alarm is not None
    assert haas.alarm.shown is None and not any(ch.isdigit() for ch in haas.alarm.words())
    assert haas.alarm.words() == "alarm" and haas.alarm.words("zh-CN") == "报警"
    assert fanuc.alarm.shown == fanuc_number and fanuc.alarm.words() == f"alarm {fanuc_number}"


# the body counts its passes in #1 and files each pass's #1 at #(100 + #1)
G65_L3 = lines("G65 P100 L3 A1.", "M30", "O100", "#1=#1+1", "#[100+#1]=#1", "M99")


def test_haas_g65_l_sets_the_arguments_on_the_first_pass_only_locals_carry_over() -> None:
    # pass 1: #1 = 1 + 1 = 2 -> #102; pass 2 keeps #1: 2 + 1 = 3 -> #103; pass 3: 4 -> #104
    got = final(G65_L3, HAAS)
    assert (got.get(102), got.get(103), got.get(104)) == (2.0, 3.0, 4.0)


def test_fanuc_0i_g65_l_fills_each_pass_from_the_arguments_again() -> None:
    # every pass starts from A1.: #1 = 1 + 1 = 2 -> #102 three times; #103 and #104 stay vacant
    got = final(G65_L3, FANUC)
    assert (got.get(102), got.get(103), got.get(104)) == (2.0, None, None)


# ---------------------------------------------------------------------------------------------
# §8 words: G codes outside the table are warnings, Haas codes are in it; §1 whole words only


def test_haas_codes_run_and_an_unknown_g_code_does_not_stop_the_run() -> None:
    m = machine(lines("G187 P2", "G05", "#1=1", "M30"), HAAS)
    assert m.run() == "completed" and m.variables()[1] == 1.0
    assert alarm(lines("G187 P2", "M30"), FANUC) == (10, 1)


def test_haas_reads_no_abbreviated_macro_words_alarm_114() -> None:
    text = lines("#1=0", "WH[#1LT2]DO1", "#1=#1+1", "END1", "M30")
    assert alarm(text, HAAS) == (114, 2)
    assert final(text, FANUC)[1] == 2.0


# ---------------------------------------------------------------------------------------------
# §8 tool length offsets: Haas keeps them at #2001 (geometry) and #2201 (wear), not at FANUC's
# #11001/#10001, which are the NGC's commons


def test_haas_g43_h_adds_length_geometry_2001_and_wear_2201() -> None:
    got = final(lines("#2001=100.", "#2201=-0.5", "G90 G43 H1 G00 Z10.", "#1=#5023", "#2=#5043", "M30"), HAAS)
    assert (got[1], got[2]) == (109.5, 10.0)  # machine Z = work Z + 100 - 0.5


def test_fanuc_0i_g43_reads_2001_as_h1_wear_10001_and_2201_as_h1_geometry_11001() -> None:
    # the same program moves to the same Z on the 0i, but there #2001 is the short number of the
    # H1 wear (#10001) and #2201 of the H1 geometry (#11001), not Haas's length and its wear
    text = lines("#2001=100.", "#2201=-0.5", "G90 G43 H1 G00 Z10.", "#1=#5023", "#2=#10001", "#3=#11001", "M30")
    got = final(text, FANUC)
    assert (got[1], got[2], got[3]) == (109.5, 100.0, -0.5)
    haas = final(text, HAAS)  # on haas #10001 is a common, vacant, and #11001 an NGC input
    assert haas[1] == 109.5 and 2 not in haas and haas[3] == 0.0


def test_haas_commons_at_10001_are_no_tool_offset() -> None:
    got = final(lines("#10001=100.", "G90 G43 H1 G00 Z10.", "#1=#5023", "M30"), HAAS)
    assert got[1] == 10.0


def test_fanuc_0i_g43_h1_adds_the_h1_wear_at_10001() -> None:
    got = final(lines("#10001=100.", "G90 G43 H1 G00 Z10.", "#1=#5023", "M30"), FANUC)
    assert got[1] == 110.0  # offset memory C: #10001 is the H1 wear (docs/semantics.md §8)


def test_haas_g10_l10_and_l11_write_2001_and_2201() -> None:
    got = final(lines("G90 G10 L10 P3 R120.", "G10 L11 P3 R-0.2", "G10 L12 P3 R5.", "G10 L13 P3 R0.1",
                      "#1=#2003", "#2=#2203", "#3=#2403", "#4=#2603", "M30"), HAAS)  # fmt: skip
    assert [got[k] for k in (1, 2, 3, 4)] == [120.0, -0.2, 5.0, 0.1]


def test_haas_g10_l1_is_l11_the_length_wear_read_back_at_2201_plus_p() -> None:
    # G10 L1 P2 R0.2 writes H2's wear #2202 = 0.2; under G91 L1 P2 R0.05 adds: 0.2 + 0.05 = 0.25;
    # the geometry #2002 stays 0
    got = final(lines("G90 G10 L1 P2 R0.2", "#1=#2202", "G91 G10 L1 P2 R0.05", "#2=#2202", "#3=#2002", "M30"), HAAS)
    assert (got[1], got[2], got[3]) == (0.2, 0.25, 0.0)


def test_fanuc_0i_g10_l10_writes_11001_not_2001() -> None:
    got = final(lines("G90 G10 L10 P3 R120.", "#1=#11003", "M30"), FANUC)
    assert got[1] == 120.0
