"""docs/semantics.md §10.1 "Coordinates, tools and the codes that act once", on both lathe
profiles (``fanuc-0i-lathe``, ``gsk980tdi``): X a diameter and U/W incremental, arc I a radius,
T0101 and T0100, G28 U0 W0, G04 X/U/P, what #5001/#5021/#5041 read, G50 X Z and G50 S, G99 feed
per revolution; and what is the FANUC lathe's own (its aliases, G18 and G99 at power-on, the
short numbers of its tool offsets). Every expected value is worked out by hand in a comment.
"""

from __future__ import annotations

import re
from itertools import pairwise
from pathlib import Path
from typing import NamedTuple

import pytest

from cncmacro.dialects import get_dialect
from cncmacro.library.dialect_choice import dialect_from_text
from cncmacro.library.machine_file import MachineFileError, MachineSettings, load_machine_file
from cncmacro.library.profiles import machine_profile
from running import final, lines, run


class Lathe(NamedTuple):
    """What differs between the two lathe profiles in these tests: the profile, where Z's
    positions are (#5002 on the 0i-TF, whose axes are X Z C Y; #5003 on the GSK980TDi, X Y Z C B),
    the offset-1 numbers of X/Z geometry and wear, and the rapid rates (mm/min; X's radial)."""

    name: str
    z: int  # Z's axis number: #5000 + z is its block end point
    x_geometry: int
    x_wear: int
    z_geometry: int
    z_wear: int
    rapid_x: float
    rapid_z: float


FANUC = Lathe("fanuc-0i-lathe", 2, 15001, 10001, 16001, 11001, 12000.0, 15000.0)
GSK = Lathe("gsk980tdi", 3, 2701, 2001, 2801, 2101, 6000.0, 8000.0)
LATHES = pytest.mark.parametrize("lathe", [FANUC, GSK], ids=lambda lathe: lathe.name)


# ---------------------------------------------------------------------------------------------
# X a diameter, U and W incremental, #5001 and the moves on the diameter


@LATHES
def test_10_1_x_is_a_diameter_and_u_w_move_incrementally(lathe: Lathe) -> None:
    m = run(lines("G00 X50 Z10", "G01 U-10 W-5 F0.2", "#100=#5001", f"#101=#{5000 + lathe.z}", "M30"), lathe.name)
    # X50 then U-10: diameter 40; Z10 then W-5: Z5
    assert (m.C[100], m.C[101]) == (40.0, 5.0)
    first, second = m.planner.moves
    assert (first.end[0], second.start[0], second.end[0]) == (50.0, 50.0, 40.0)
    # the rapid from X0 Z0: X moves a radius of 50 / 2 = 25 mm, Z 10 mm, each at its own rate;
    # the move takes as long as the slower axis
    assert first.seconds == pytest.approx(max(25.0 / lathe.rapid_x, 10.0 / lathe.rapid_z) * 60.0)


@LATHES
def test_10_1_arc_i_is_the_radius_distance_of_the_centre(lathe: Lathe) -> None:
    m = run(lines("G98 G00 X20 Z0", "G02 X40 Z-10 I10 K0 F100", "M30"), lathe.name)
    arc = m.planner.moves[1]
    # the start is on radius 10; I10 puts the centre at radius 10 + 10 = 20, that is X40 as a
    # diameter, at Z0. Start (r10, Z0) and end (r20, Z-10) are both 10 from it: a quarter circle
    # of radius 10, 2π·10 / 4 = 15.708 mm at F100 mm/min = 9.425 s. (Were I a diameter, the
    # centre would be at radius 15 and no arc of one radius would join the two points.)
    assert arc.centre is not None and (arc.centre[0], arc.centre[lathe.z - 1]) == (40.0, 0.0)
    assert arc.seconds == pytest.approx(2 * 3.141592653589793 * 10.0 / 4 / 100.0 * 60.0)


# ---------------------------------------------------------------------------------------------
# T0101: tool 01 with offset 01; T0100 cancels the offset


@LATHES
def test_10_1_t0101_shifts_the_machine_position_by_geometry_plus_wear(lathe: Lathe) -> None:
    presets = {lathe.x_geometry: -200.0, lathe.x_wear: 0.1, lathe.z_geometry: -300.0, lathe.z_wear: -0.05}
    z = lathe.z
    m = run(lines("G00 X50 Z10", "T0101",
                  "#100=#5001", f"#101=#{5000 + z}", "#102=#5021", f"#103=#{5020 + z}", "#104=#5041",
                  "G01 X40 F0.2", "#106=#5001", "#107=#5021", "#108=#4120", "M30"),
            lathe.name, presets=presets)  # fmt: skip
    # the programmed point stays where the program put it: X50 Z10, then X40
    assert (m.C[100], m.C[101], m.C[106]) == (50.0, 10.0, 40.0)
    # the machine position takes the offset: X 50 + (-200 + 0.1) = -149.9 (on the diameter, as X
    # is programmed), Z 10 + (-300 - 0.05) = -290.05; after X40: 40 - 199.9 = -159.9
    assert m.C[102] == pytest.approx(-149.9) and m.C[103] == pytest.approx(-290.05)
    assert m.C[107] == pytest.approx(-159.9)
    # #5041, the current position in work coordinates with the offset: 50 - 199.9 = -149.9
    assert m.C[104] == pytest.approx(-149.9)
    assert m.C[108] == 101.0  # #4120: tool 01 x 100 + offset 01
    # the moves are the programmed path, the path the tool tip follows: T0101 moves nothing itself
    moves = m.planner.moves
    assert [(mv.start[0], mv.end[0]) for mv in moves] == [(0.0, 50.0), (50.0, 40.0)]


@LATHES
def test_10_1_t0100_cancels_the_offset(lathe: Lathe) -> None:
    presets = {lathe.x_geometry: -200.0, lathe.z_geometry: -300.0}
    m = run(lines("G00 X50 Z10", "T0101", "T0100", "#100=#5021", f"#101=#{5020 + lathe.z}", "#102=#4120", "M30"),
            lathe.name, presets=presets)  # fmt: skip
    # offset 00: no offset, the machine position is the program's again (X50, Z10); T reads 100
    assert (m.C[100], m.C[101], m.C[102]) == (50.0, 10.0, 100.0)


def test_10_1_g10_c_adds_to_the_nose_radius_as_u_and_w_add_to_x_and_z() -> None:
    """0i-TF "G10 P_ X(U)_ Z(W)_ R(C)_ Q_": C is the nose radius's increment. G10 P1 R0.4, then
    G10 P1 U-0.01 W-0.02 C0.1: the wear radius (#12001) 0.4 + 0.1 = 0.5, X wear (#10001) -0.01,
    Z wear (#11001) -0.02; the C axis does not turn."""
    m = run(lines("G10 P1 R0.4", "G10 P1 U-0.01 W-0.02 C0.1", "#100=#12001", "#101=#10001", "#102=#11001",
                  "#103=#5023", "M30"), "fanuc-0i-lathe")  # fmt: skip
    v = m.variables()
    assert (v[100], v[101], v[102], v[103]) == (pytest.approx(0.5), -0.01, -0.02, 0.0)
    assert not m.planner.moves


@pytest.mark.parametrize("dialect", ["fanuc-0i-lathe", "fanuc-30i-lathe"])
def test_10_1_g10_p0_sets_the_workpiece_shift_the_external_offset(dialect: str, tmp_path: Path) -> None:
    """The lathe G10 format "G10 P_ X(U)_ Z(W)_": P0 is the workpiece coordinate system shift,
    which a control with G54-G59 keeps as the external work offset. G10 P0 X2. Z-5.: #5201 = 2,
    #5202 = -5; then G00 X50. Z10. is machine X 50 + 2 = 52, Z 10 - 5 = 5; G10 P0 W1. adds: Z -4.
    It was written to wear offset 0 (#10000, #11000), which does not exist, and shifted nothing."""
    text = lines("G10 P0 X2. Z-5.", "#100=#5201", "#101=#5202", "G00 X50. Z10.", "#102=#5021", "#103=#5022",
                 "G10 P0 W1.", "#104=#5202", "M30")  # fmt: skip
    lathe_30i = machine_profile(None, _machine_file(tmp_path, 'base = "fanuc-30i"\nlathe = true\n'))
    m = run(text, lathe_30i if dialect == "fanuc-30i-lathe" else dialect)
    assert m.status == "completed", m.alarm
    assert [m.C[n] for n in range(100, 105)] == [2.0, -5.0, 52.0, 5.0, -4.0]


def test_10_1_gsk_2501_2502_are_the_workpiece_shift_the_machine_position_takes() -> None:
    """GSK980TDi manual §3.28.1 item 4: #2501/#2502, the X/Z work coordinate system shift, read and
    write. They are the shift a FANUC lathe's G10 P0 sets (the external work offset, #5201 X and
    #5203 Z on the GSK's axes X Y Z): #2501=0.4, #2502=#2502-0.15 (0 - 0.15 = -0.15); G00 X100 Z100
    is machine X 100 + 0.4 = 100.4 (a diameter, as the FANUC shift's X) and Z 100 - 0.15 = 99.85;
    #5001/#5003 and #5041/#5043 stay 100 (no offset, no tool). They were stored and shifted nothing."""
    v = final(lines("#2501=0.4", "#2502=#2502-0.15", "G00 X100 Z100", "#100=#5021", "#101=#5023", "#102=#5001",
                    "#103=#5003", "#104=#5041", "#105=#5043", "#106=#5201", "#107=#5203", "#108=#2502", "M30"),
              "gsk980tdi")  # fmt: skip
    assert [v[n] for n in range(100, 109)] == pytest.approx([100.4, 99.85, 100, 100, 100, 100, 0.4, -0.15, -0.15])


def test_10_1_fanuc_lathe_offsets_have_short_numbers_for_offsets_1_to_64() -> None:
    v = final(lines("#2701=-200", "#2001=0.1", "#2864=-5", "G10 P10002 X-180 Z-250", "G10 P2 X0.2",
                    "#100=#15001", "#101=#10001", "#102=#16064", "#103=#2702", "#104=#2802", "#105=#2002",
                    "G00 X50 Z10 T0101", "#106=#5021", "#107=#5081", "T0100", "#108=#5081", "M30"),
              "fanuc-0i-lathe")  # fmt: skip
    # #2701, #2001, #2864 are #15001, #10001, #16064; G10 P10002 writes geometry 2 (#15002 =
    # #2702, #16002 = #2802), G10 P2 wear 2 (#10002 = #2002)
    assert (v[100], v[101], v[102]) == (-200.0, 0.1, -5.0)
    assert (v[103], v[104], v[105]) == (-180.0, -250.0, 0.2)
    assert v[106] == pytest.approx(50.0 - 200.0 + 0.1)  # T0101 reads them: 50 - 199.9 = -149.9
    # #5081, the X offset in effect: -200 + 0.1 = -199.9; none after T0100
    assert v[107] == pytest.approx(-199.9) and v[108] == 0.0


# ---------------------------------------------------------------------------------------------
# G28 U0 W0, G04, G50


@LATHES
def test_10_1_g28_u0_w0_returns_through_where_it_is_to_the_reference_point(lathe: Lathe) -> None:
    presets = {5221: 30.0, 5220 + lathe.z: -100.0}  # G54: X 30 (diameter), Z -100
    m = run(lines("G54 G00 X50 Z10", "G28 U0 W0", "#100=#5001", f"#101=#{5000 + lathe.z}", "#102=#5021",
                  f"#103=#{5020 + lathe.z}", "M30"), lathe.name, presets=presets)  # fmt: skip
    rapid, intermediate, home = m.planner.moves
    # U0 W0: the intermediate point is where the tool is, X50 Z10, so the first leg goes nowhere
    assert intermediate.start == intermediate.end == rapid.end and intermediate.seconds == 0.0
    # the reference point is machine 0: in G54 work coordinates X = 0 - 30 = -30, Z = 0 + 100 = 100
    assert (m.C[100], m.C[101], m.C[102], m.C[103]) == (-30.0, 100.0, 0.0, 0.0)
    assert home.mode == 0.0 and (home.end[0], home.end[lathe.z - 1]) == (-30.0, 100.0)
    # at rapid: X from 50 to -30 is a radius of 80 / 2 = 40 mm, Z from 10 to 100 is 90 mm
    assert home.seconds == pytest.approx(max(40.0 / lathe.rapid_x, 90.0 / lathe.rapid_z) * 60.0)


@LATHES
@pytest.mark.parametrize("dwell", ["G04 X1.5", "G04 U1.5", "G04 P1500"])
def test_10_1_g04_dwells_x_and_u_in_seconds_p_in_milliseconds(lathe: Lathe, dwell: str) -> None:
    m = run(lines(dwell, "M30"), lathe.name)
    assert m.planner.clock == pytest.approx(1.5)  # X1.5 s, U1.5 s, P1500 ms: 1.5 s each
    assert m.planner.moves == []  # X and U are the time here, not a move


@LATHES
@pytest.mark.parametrize(("dwell", "seconds"), [("G04 X2. U3.", 2.0), ("G04 U3. X2.", 2.0), ("G04 X2. P500", 0.5)])
def test_10_1_g04_takes_x_before_u_and_p_before_both(lathe: Lathe, dwell: str, seconds: float) -> None:
    # GSK980TDi manual §3.14 note 3: "P、X、U在同一程序段，P有效；X、U在同一程序段，X有效" (P over X
    # and U, X over U); it dwelt U's 3 s. FANUC's manuals give X, U or P, never two: the same order
    m = run(lines(dwell, "M30"), lathe.name)
    assert m.planner.clock == pytest.approx(seconds)


@LATHES
def test_10_1_g50_x_z_sets_the_coordinates_of_where_the_tool_is(lathe: Lathe) -> None:
    m = run(lines("G00 X50 Z10", "G50 X100 Z0", "#100=#5001", f"#101=#{5000 + lathe.z}", "#102=#5021",
                  "G00 X80", "#103=#5021", "M30"), lathe.name)  # fmt: skip
    # the tool stays at machine X50 Z10 and is now called X100 Z0
    assert (m.C[100], m.C[101], m.C[102]) == (100.0, 0.0, 50.0)
    # X80 in the new system: machine 50 + (80 - 100) = 30
    assert m.C[103] == 30.0
    assert len(m.planner.moves) == 2  # G50 moves nothing


@LATHES
def test_10_1_g50_u_w_adds_to_the_coordinates_of_where_the_tool_is(lathe: Lathe) -> None:
    """GSK980TDi §3.18 "W：当前位置新的 Z 轴绝对坐标与执行代码前的绝对坐标的差值" (FANUC alike): bar
    work's G50 W15. at Z2 calls the same place Z17, so the next part's G00 Z1. moves 16 mm; G50 U10.
    at X20 calls it X30; the machine position stays (X20 Z2 from the machine's zero)."""
    m = run(lines("G00 X20 Z2", "G50 W15.", f"#100=#{5000 + lathe.z}", "G00 Z1.", "G50 U10.", "#101=#5001",
                  "#102=#5021", "M30"), lathe.name)  # fmt: skip
    assert (m.C[100], m.C[101], m.C[102]) == (17.0, 30.0, 20.0)
    last = m.planner.moves[-1]
    assert (last.start[lathe.z - 1], last.end[lathe.z - 1]) == (17.0, 1.0)


@LATHES
def test_10_1_g50_s_clamps_the_spindle_and_sets_neither_coordinates_nor_the_speed(lathe: Lathe) -> None:
    m = run(lines("G97 S800 M03", "G00 X50 Z10", "G50 S2000", "#100=#4119", "#101=#5001", "#102=#5021", "M30"),
            lathe.name)  # fmt: skip
    # S stays 800 (#4119); X stays 50 in work and machine coordinates
    assert (m.C[100], m.C[101], m.C[102]) == (800.0, 50.0, 50.0)


# ---------------------------------------------------------------------------------------------
# feed per revolution; the FANUC lathe's power-on state and names


@LATHES
def test_10_1_g99_f_is_a_feed_per_revolution(lathe: Lathe) -> None:
    m = run(lines("G97 S500 M03", "G00 X50 Z10", "G99 G01 W-10 F0.2", "M30"), lathe.name)
    # 0.2 mm/rev x 500 rev/min = 100 mm/min; 10 mm take 10 / 100 min = 6 s
    assert m.planner.moves[-1].seconds == pytest.approx(6.0)


def test_10_1_fanuc_lathe_starts_in_g18_and_g99() -> None:
    v = final(lines("#100=#4016", "#101=#4005", "#102=#4001", "G97 S500 M03", "G01 W-10 F0.2", "#103=#4003", "M30"),
              "fanuc-0i-lathe")  # fmt: skip
    # plane G18, feed per revolution G99, G00; system A has no G90/G91 group: #4003 vacant
    assert (v[100], v[101], v[102]) == (18.0, 99.0, 0.0)
    assert 103 not in v
    m = run(lines("G97 S500 M03", "G01 W-10 F0.2", "M30"), "fanuc-0i-lathe")
    assert m.planner.moves[-1].seconds == pytest.approx(6.0)  # G99 already: 0.2 x 500 = 100 mm/min, 6 s


@pytest.mark.parametrize("alias", ["0i-tf", "0i-td", "fanuc-0i-t", "FANUC-0i-TF"])
def test_10_1_fanuc_lathe_answers_to_its_aliases(alias: str) -> None:
    assert get_dialect(alias).name == "fanuc-0i-lathe"
    assert dialect_from_text([f"(cncmacro: dialect={alias})", "G00 X50"]) == "fanuc-0i-lathe"


# ---------------------------------------------------------------------------------------------
# the 30i lathes: ``lathe = true`` in the machine file


def _machine_file(tmp_path: Path, text: str) -> MachineSettings:
    path = tmp_path / ".cncmacro.toml"
    path.write_text(text, encoding="utf-8")
    return load_machine_file(path)


def test_10_1_fanuc_30i_with_lathe_true_runs_as_a_lathe(tmp_path: Path) -> None:
    settings = _machine_file(tmp_path, 'base = "fanuc-30i"\nlathe = true\n')
    profile = machine_profile(None, settings)
    assert profile.lathe and profile.name == "fanuc-30i" and profile.variable_names
    presets = {15001: -200.0, 10001: 0.1}
    program = lines("G97 S500 M03", "G00 X50 Z10", "T0101", "#100=#5021", "#101=[#_ABSIO[1]]", "#102=#4005",
                    "#103=#4016", "#104=#2701", "G01 W-10 F0.2", "M30")  # fmt: skip
    m = run(program, profile, presets=presets)
    assert m.status == "completed", m.alarm
    # machine X: 50 + (-200 + 0.1) = -149.9; #5001 (ABSIO) 50; G99 and G18 at power-on; #2701 is #15001
    assert m.C[100] == pytest.approx(-149.9) and (m.C[101], m.C[102], m.C[103], m.C[104]) == (50.0, 99.0, 18.0, -200.0)
    # G99 F0.2 at S500: 100 mm/min, W-10 in 6 s
    assert m.planner.moves[-1].seconds == pytest.approx(6.0)
    # without the key the 30i is a mill: #15001 does not exist, #4005 reads G94 feed per minute
    assert not machine_profile("fanuc-30i", None).lathe


@pytest.mark.parametrize(("text", "wanted"), [
    ('base = "fanuc-0i"\nlathe = true\n', "fanuc-0i-lathe"),
    ('base = "gsk980tdi"\nlathe = false\n', "is a lathe"),
    ('base = "fanuc-30i"\nlathe = 1\n', "true or false"),
])  # fmt: skip
def test_10_1_lathe_key_is_refused_where_it_means_nothing(tmp_path: Path, text: str, wanted: str) -> None:
    with pytest.raises(MachineFileError, match=wanted):
        _machine_file(tmp_path, text)


def test_10_1_fanuc_30i_lathe_tables_hold_together() -> None:
    """The 30i lathe's tables (not a registry profile, so not in the checks every profile passes):
    no two rows overlap, every alias names a stored row of its access, every name a row, and no
    row of the mill's tool offsets or G54.1 numbers is left where the lathe's offsets are."""
    profile = get_dialect("fanuc-30i").lathe_variant
    assert profile is not None
    rows = sorted(profile.system_variables(), key=lambda r: r.first)
    assert all(a.last < b.first for a, b in pairwise(rows))
    for r in rows:
        assert re.search(r"[\u4e00-\u9fff]", r.zh), r
        if r.source == "alias":
            target = profile.system_variable(int(r.param))
            assert target is not None and target.source == "store" and target.access == r.access, r
    for name in profile.system_variable_names():
        assert profile.system_variable(name.first) is not None, name
    assert "X wear" in profile.system_variable(10001).en and "Y wear" in profile.system_variable(14001).en
    assert profile.system_variable(4003).default is None  # no G90/G91 group on system A


@pytest.mark.parametrize("block", ["G53 X0 Z0", "G22", "G27 X0", "G52 Z0", "G09 G01 W-1 F0.1", "G12.1", "G68"])
def test_10_1_fanuc_lathe_knows_the_codes_of_a_lathe(block: str) -> None:
    """A code a 0i-TF has is no alarm 010 (docs/profiles.md, fanuc-0i-lathe decisions)."""
    assert run(lines(block, "M30"), "fanuc-0i-lathe").status == "completed"


def test_10_1_fanuc_lathe_refuses_a_mill_code() -> None:
    """G43 (tool length offset) is a mill's code: alarm 010 on the lathe, as on the control."""
    m = run(lines("G43 H1", "M30"), "fanuc-0i-lathe")
    assert m.status == "alarm" and m.alarm is not None and m.alarm.number == 10
