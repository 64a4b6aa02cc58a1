"""Where the machine is, as ``cncmacro check`` knows it (planner/whereabouts.py; docs/semantics.md
§2 "Unknown, not vacant", §8, §11): a position variable that adds an offset the folder does not
give is unknown, a G92/G50 made where the tool's machine position is unknown makes a frame the
travel check does not know until one made at the reference point, and after a G30 the axis is at
the 2nd reference position, which the machine file does not give."""

from __future__ import annotations

from pathlib import Path

from cli_capture import check_findings

MILL_LIMITS = """[variables]
5221 = -420.0
5222 = -210.0
5223 = -380.0
11001 = 120.0
[limits]
travel = { X = [-510, 0], Y = [-410, 0], Z = [-460, 0] }
"""
LATHE_LIMITS = """base = "fanuc-0i-lathe"
[variables]
5221 = 0.0
5222 = -620.0
[limits]
travel = { X = [-420, 10], Z = [-720, 5] }
"""


check = check_findings


def codes(found: list[str]) -> list[str]:
    return [f.split(":", 2)[0] + " " + f.rsplit("[", 1)[1].rstrip("]") for f in found]


# a shop's guards on the machine position and the tool length in force, before it cuts
GUARDS = (
    "O0100\nG21 G90 G54 G00 X0. Y0.\nG43 H1 Z100.\n"
    "IF [#5023 LT -5.] GOTO 10\n#3000=1 (Z NOT AT SAFE HEIGHT)\n"
    "N10 IF [#5083 NE 0] GOTO 20\n#3000=2 (NO TOOL LENGTH)\n"
    "N20 G01 Z-1. F100.\nM30\n"
)


def test_the_machine_position_with_an_unknown_work_offset_and_tool_length_is_unknown(tmp_path: Path) -> None:
    # G54 Z and H1 are the machine's: #5023 = 100 + G54 Z + H1 is unknown, and so is #5083 = H1, so
    # the run passes both guards on the side without the program's alarm (machine/guards.py), each
    # with a note; it read 100 + 0 + 0 = 100 and reached neither alarm, but #5083 read 0 and
    # reached alarm 3002
    code, found = check(tmp_path, GUARDS)
    assert code == 0
    assert codes(found) == ["4 unknown-value", "6 unknown-value"]


def test_the_tool_length_in_force_with_an_unknown_geometry_is_unknown(tmp_path: Path) -> None:
    # G54 Z given, H1 not: #5023 = 100 - 380 + H1 still unknown; #5083 = H1 unknown
    text = GUARDS.replace("IF [#5023 LT -5.] GOTO 10", "GOTO 10")
    code, found = check(tmp_path, text, "[variables]\n5223 = -380.0\n")
    assert code == 0
    assert codes(found) == ["5 not-executed", "6 unknown-value"]


def test_the_positions_with_the_offsets_given_are_known(tmp_path: Path) -> None:
    # G54 Z -380, H1 120: #5023 = 100 - 380 + 120 = -160 < -5 jumps to N10; #5083 = 120 jumps to N20
    code, found = check(tmp_path, GUARDS, MILL_LIMITS)
    assert code == 0
    assert codes(found) == ["5 not-executed", "7 not-executed"]


def test_a_lathe_machine_position_with_an_unknown_tool_offset_is_unknown(tmp_path: Path) -> None:
    # T0101's X geometry is the machine's: #5021 = 100 + G54 X + T01 X is unknown
    text = "O0100\nT0101\nG54 G00 X100. Z50.\nIF [#5021 GT 150.] GOTO 10\n#3000=1 (NOT CLEAR)\nN10 M30\n"
    code, found = check(tmp_path, text, None, "--dialect", "fanuc-0i-lathe")
    assert codes(found) == ["4 unknown-value"]
    assert code == 0


def test_a_g92_at_the_start_point_makes_a_frame_the_travel_check_does_not_know(tmp_path: Path) -> None:
    # the operator put the tool somewhere and G92 calls it X0 Y0 Z50: the run starts at G54 0, so
    # X-150 went to machine -420 - 150 = -570, "past" -510; on the machine it is inside
    text = "O0100\nG21 G90\nG92 X0. Y0. Z50.\nG00 X-150. Y-100.\nG01 Z-5. F200.\nM30\n"
    assert check(tmp_path, text, MILL_LIMITS) == (0, [])


def test_a_g92_at_the_reference_point_is_a_known_frame(tmp_path: Path) -> None:
    # G28 puts X at machine 0; G92 X300. there: machine = program - 300, so X-250. is machine -550,
    # 40 past -510: alarm 501 (the run stops at the limit)
    text = "O0100\nG21 G90\nG28 X0.\nG92 X300.\nG00 X-250.\nM30\n"
    code, found = check(tmp_path, text, MILL_LIMITS)
    assert code == 1
    assert found[0] == (
        "5:1: error: X- over travel: the move goes to machine X-550.000, 40.000 mm past the - limit X-510.000 "
        "([limits] travel); the axis stops at the limit (alarm 501) [over-travel]"
    )


def test_a_lathe_g50_at_the_start_point_is_not_travel_checked(tmp_path: Path) -> None:
    # G50 X200. Z150. where the operator left the turret: the run started at G54 0, so the shift
    # is -150 and Z2. went to machine -620 - 150 + 2 = -768, "past" -720; on the machine it is inside
    text = "O0100\nG21 G99\nG50 X200. Z150.\nT0100\nG97 S800 M03\nG00 X52. Z2.\nG01 Z-40. F0.2\nM30\n"
    assert check(tmp_path, text, LATHE_LIMITS) == (0, [])


def test_a_lathe_g50_after_g28_is_travel_checked_whatever_the_work_offset(tmp_path: Path) -> None:
    # G28 U0 W0: machine X0 Z0; G50 X150. Z100. there, so machine = program - 150 (X, a diameter)
    # and program - 100 (Z) with no G54 given; X170. is machine X20, 10 past +10: alarm 500
    text = "O0100\nG21 G99\nG28 U0 W0\nG50 X150. Z100.\nT0100\nG00 X52. Z2.\nG00 X170. Z100.\nM30\n"
    machine_file = 'base = "fanuc-0i-lathe"\n[limits]\ntravel = { X = [-420, 10], Z = [-720, 5] }\n'
    code, found = check(tmp_path, text, machine_file)
    assert code == 1
    assert found[0] == ("7:1: error: X+ over travel: the move goes to machine X20.000, 10.000 mm past the + limit "
                        "X10.000 ([limits] travel); the axis stops at the limit (alarm 500) [over-travel]")  # fmt: skip


def test_after_g30_the_axis_is_at_a_position_the_machine_file_does_not_give(tmp_path: Path) -> None:
    # G30 Y: the 2nd reference position (parameter 1241) was taken as machine 0, so G91 Y5. was
    # "past" Y0; on the machine it is 5 mm from the tool-change position, inside
    text = "O0100\nG21 G90 G54 G00 X0. Y0.\nG91 G30 Y0.\nG91 G00 Y5.\nG90\nM30\n"
    assert check(tmp_path, text, MILL_LIMITS) == (0, [])


def test_an_absolute_move_after_g30_is_travel_checked_again(tmp_path: Path) -> None:
    # after G30 Y, G90 Y-100. puts Y at machine -210 - 100 = -310; then Y-250. is machine -460,
    # 50 past -410: alarm 501
    text = "O0100\nG21 G90 G54 G00 X0. Y0.\nG91 G30 Y0.\nG90 G00 Y-100.\nY-250.\nM30\n"
    code, found = check(tmp_path, text, MILL_LIMITS)
    assert code == 1
    assert found[0] == (
        "5:1: error: Y- over travel: the move goes to machine Y-460.000, 50.000 mm past the - limit Y-410.000 "
        "([limits] travel); the axis stops at the limit (alarm 501) [over-travel]"
    )


# after G30 on every axis, a drilling cycle under G90 (docs/semantics.md §8, after G30): the holes'
# X, Y are absolute, and under G99 the tool stops at the absolute R level
AFTER_G30_CYCLE = "O0100\nG21 G90 G54 G00 X0. Y0.\nG91 G30 X0. Y0. Z0.\nG90 G99 G81 X-10. Y-10. Z-5. R2. F100.\nG80\n"


def test_a_drilling_cycle_with_absolute_holes_after_g30_is_travel_checked_again(tmp_path: Path) -> None:
    # the hole at X-10.: machine -420 - 10 = -430; G91 X-100. then goes to -530, 20 past -510: alarm 501
    text = AFTER_G30_CYCLE + "G91 G00 X-100.\nM30\n"
    code, found = check(tmp_path, text, MILL_LIMITS)
    assert code == 1
    assert found[0] == (
        "6:1: error: X- over travel: the move goes to machine X-530.000, 20.000 mm past the - limit X-510.000 "
        "([limits] travel); the axis stops at the limit (alarm 501) [over-travel]"
    )


def test_a_drilling_cycle_under_g99_leaves_z_at_the_r_level_known(tmp_path: Path) -> None:
    # G99: Z stops at R2., machine -380 + 2 = -378, so 1 / [#5023 + 378.] = 1 / 0: alarm 112
    text = AFTER_G30_CYCLE + "#3=1/[#5023+378.]\nM30\n"
    code, found = check(tmp_path, text, MILL_LIMITS)
    assert code == 1
    assert found[0] == "6:1: error: division by zero (alarm 112) [division-by-zero]"
    # G98: Z goes back to the initial level, the 2nd reference position: unknown, no alarm
    assert check(tmp_path, text.replace("G99", "G98")) == (0, [])


def test_a_lathe_drilling_cycle_after_g30_places_the_hole_on_x(tmp_path: Path) -> None:
    # G83 X0. C0.: the hole at program X0, machine X = 0 (G54 X 0, no tool offset), so 1 / #5021
    # = 1 / 0: alarm 112; Z goes back to where the drilling started, the 2nd reference position
    text = "O0100\nG21 G98\nG30 U0 W0\nG83 X0. C0. Z-10. R-1. Q2000 F100.\nG80\n#3=1/#5021\nM30\n"
    code, found = check(tmp_path, text, LATHE_LIMITS)
    assert code == 1
    assert found[0] == "6:1: error: division by zero (alarm 112) [division-by-zero]"


# after G28 Z the tool is at machine Z0; its program position (#5003, #5043) is machine Z less the
# G54 Z (and the tool offset, none here), so it is known only where G54 Z is (planner/whereabouts.py)
AFTER_G28 = "O0100\nG21 G90 G54 G00 X10. Y0. Z50.\nG91 G28 Z0.\nG90\n"


def test_the_program_position_after_g28_with_an_unknown_work_offset_is_unknown(tmp_path: Path) -> None:
    # it read 0 - 0 = 0 (G54 Z taken as 0), so 1 / #5003 was "division by zero (alarm 112)"
    assert check(tmp_path, AFTER_G28 + "#3=1/#5003\n#4=1/#5043\nM30\n") == (0, [])


def test_the_program_position_after_g28_with_the_work_offset_given_is_known(tmp_path: Path) -> None:
    # G54 Z -380: #5003 = 0 - (-380) = 380, so 1 / [#5003 - 380.] = 1 / 0: alarm 112
    code, found = check(tmp_path, AFTER_G28 + "#3=1/[#5003-380.]\nM30\n", MILL_LIMITS)
    assert code == 1
    assert found[0] == "5:1: error: division by zero (alarm 112) [division-by-zero]"


def test_an_absolute_move_after_g28_makes_the_program_position_known_again(tmp_path: Path) -> None:
    # G00 Z20. under G90: #5003 = 20, so 1 / [#5003 - 20.] = 1 / 0: alarm 112 (no G54 given)
    code, found = check(tmp_path, AFTER_G28 + "G00 X0. Y0.\nG91 G00 Z-5.\nG90 G00 Z20.\n#3=1/[#5003-20.]\nM30\n")
    assert code == 1
    assert found[0] == "8:1: error: division by zero (alarm 112) [division-by-zero]"
