"""docs/semantics.md §12: cutter radius compensation on a mill (planner/cutter_stage.py).

Each program sets its radius with G10 L12 (geometry) and L13 (wear), so the offset memory's
numbers are the profile's (#13001… on FANUC, #2401… on Haas); the expected tool-centre points
are worked out by hand in the comments, to 0.001 mm. ``centre_points`` lists, per move, the
points its centre path goes through in the XY plane (the ``from`` of the first, then each piece's
``to``)."""

from __future__ import annotations

import json
import math
import random
from pathlib import Path

import pytest

from cli_capture import cli, run_json
from cncmacro.dialects.alarms import CUTTER_ARC_START, CUTTER_INTERFERENCE, CUTTER_PLANE
from cncmacro.library.machine_file import MachineFileError, MachineSettings, settings_from_mapping
from running import lines, machine, run

ROOT = Path(__file__).resolve().parent.parent
MILLS = ["fanuc", "fanuc-30i", "haas"]


def centre_points(m) -> list[list[tuple[float, float]] | None]:  # type: ignore[no-untyped-def]
    """Per move, the XY points of its tool-centre path (None: no compensation on it)."""
    out: list[list[tuple[float, float]] | None] = []
    for mv in m.planner.moves:
        path = mv.tool_path
        if path is None:
            out.append(None)
            continue
        out.append([(path.start[0], path.start[1])] + [(pc.end[0], pc.end[1]) for pc in path.pieces])
    return out


def same(got: list[tuple[float, float]] | None, want: list[tuple[float, float]]) -> bool:
    return (
        got is not None
        and len(got) == len(want)
        and all(math.dist(a, b) < 0.001 for a, b in zip(got, want, strict=True))
    )


def radius(r: float, wear: float = 0.0) -> list[str]:
    """The blocks that give offset D1 radius ``r`` (and ``wear``)."""
    return [f"G10 L12 P1 R{r}", *([f"G10 L13 P1 R{wear}"] if wear else [])]


# an outside contour, a 50 x 50 square cut clockwise with the tool on the left (outside), from
# X-20 Y-20; each move's centre path below
SQUARE = ["G90 G17 G00 X-20. Y-20.", "G41 D1 G01 X0 Y0 F100", "Y50.", "X50.", "Y0", "X0", "G40 X-20. Y-20.", "M30"]


@pytest.mark.parametrize("dialect", MILLS)
def test_an_outside_square_has_its_corners_at_the_offsets_intersections(dialect: str) -> None:
    # radius 5, tool on the left of a clockwise path: outside. Start-up (-20,-20)->(0,0) then +Y: a
    # left turn, inside for a left tool: the start-up line moved left by 5 (y - x = 5*sqrt2 =
    # 7.071068) meets x = -5 at (-5, 2.071068). The square's corners turn right, outside, by 90°
    # (obtuse): (-5,55), (55,55), (55,-5). The last side -X to (0,0), then the cancel to (-20,-20)
    # turns left, inside: y = -5 meets the cancel line moved left (y - x = -7.071068) at
    # (2.071068, -5); the cancel block goes from there to (-20,-20)
    m = run(lines("O0001", *radius(5.0), *SQUARE), dialect)
    assert m.status == "completed", m.alarm
    pts = centre_points(m)
    assert pts[0] is None  # the G00 before G41
    assert same(pts[1], [(-20.0, -20.0), (-5.0, 2.071068)])
    assert same(pts[2], [(-5.0, 2.071068), (-5.0, 55.0)])
    assert same(pts[3], [(-5.0, 55.0), (55.0, 55.0)])
    assert same(pts[4], [(55.0, 55.0), (55.0, -5.0)])
    assert same(pts[5], [(55.0, -5.0), (2.071068, -5.0)])
    assert same(pts[6], [(2.071068, -5.0), (-20.0, -20.0)])


def test_an_inside_pocket_has_every_corner_at_the_intersection() -> None:
    # a 50 x 50 pocket cut counterclockwise from its middle (25,25), tool left (inside), radius 5:
    # start-up +X to (50,25), then +Y: inside: y = 30 meets x = 45 at (45,30); corners (45,45),
    # (5,45), (5,5), (45,5); the last side +Y to (50,25), then the cancel -X to (25,25) turns left:
    # x = 45 meets y = 25 - 5 = 20 at (45,20)
    m = run(lines("O0001", *radius(5.0), "G90 G17 G00 X25. Y25.", "G41 D1 G01 X50. F100", "Y50.", "X0", "Y0",
                  "X50.", "Y25.", "G40 X25.", "M30"))  # fmt: skip
    assert m.status == "completed", m.alarm
    pts = centre_points(m)
    assert same(pts[1], [(25.0, 25.0), (45.0, 30.0)])
    assert same(pts[2], [(45.0, 30.0), (45.0, 45.0)])
    assert same(pts[3], [(45.0, 45.0), (5.0, 45.0)])
    assert same(pts[4], [(5.0, 45.0), (5.0, 5.0)])
    assert same(pts[5], [(5.0, 5.0), (45.0, 5.0)])
    assert same(pts[6], [(45.0, 5.0), (45.0, 20.0)])
    assert same(pts[7], [(45.0, 20.0), (25.0, 25.0)])


def test_a_contour_with_an_arc_has_its_corners_on_the_offset_circle() -> None:
    # radius 2, tool left. From (-10,0): start-up +X to (0,0), then +X on: tangent, (0,2). +X to
    # (10,0), then G02 to (20,10) R10 (centre (20,0): the arc starts going +Y): inside, y = 2 meets
    # the arc grown to 12, x = 20 - sqrt(140) = 8.167840. The arc ends going +X, then +Y: inside, the
    # circle of 12 meets x = 18 at y = sqrt(140) = 11.832160. The cancel goes on +Y: tangent, from
    # (18,30) to (20,40). The arc piece keeps the programmed centre (20,0) and turns clockwise
    m = run(lines("O0001", *radius(2.0), "G90 G17 G00 X-10. Y0", "G41 D1 G01 X0 F100", "X10.", "G02 X20. Y10. R10.",
                  "G01 Y30.", "G40 Y40.", "M30"))  # fmt: skip
    assert m.status == "completed", m.alarm
    pts = centre_points(m)
    assert same(pts[1], [(-10.0, 0.0), (0.0, 2.0)])
    assert same(pts[2], [(0.0, 2.0), (8.167840, 2.0)])
    assert same(pts[3], [(8.167840, 2.0), (18.0, 11.832160)])
    assert same(pts[4], [(18.0, 11.832160), (18.0, 30.0)])
    assert same(pts[5], [(18.0, 30.0), (20.0, 40.0)])
    arc = m.planner.moves[3].tool_path.pieces[0]
    assert arc.clockwise and (arc.centre[0], arc.centre[1]) == (20.0, 0.0)


def test_an_acute_outside_corner_goes_through_the_extension_points() -> None:
    # radius 2, tool right (G42): +X to (10,0), then up-left to (0,5): direction (-0.894427,
    # 0.447214), outside, turned by 153.4° (acute): the first side runs on to (12,-2), then straight to
    # (12.683282, 0.894427), where the second side's offset (10.894427, 1.788854) + t(-0.894427,
    # 0.447214) starts (test_offset_geometry: the same numbers). The connection is the first block's
    m = run(lines("O0001", *radius(2.0), "G90 G17 G00 X-10. Y0", "G42 D1 G01 X0 F100", "X10.", "X0 Y5.",
                  "G40 X-10.", "M30"))  # fmt: skip
    assert m.status == "completed", m.alarm
    pts = centre_points(m)
    assert same(pts[2], [(0.0, -2.0), (12.0, -2.0), (12.683282, 0.894427)])
    assert pts[3] is not None and same(pts[3][:1], [(12.683282, 0.894427)])


@pytest.mark.parametrize(("kind", "corner"), [("A", (5.0, 0.0)), ("B", (5.0, -5.0))])
def test_start_up_of_type_a_and_b_as_the_manual_draws_them(kind: str, corner: tuple[float, float]) -> None:
    # G42, radius 5, start-up +X to (0,0), then +Y: outside by 90°. FANUC's start-up figures: type A
    # ends the start-up block on the perpendicular of the next block, (5,0); type B at the
    # intersection of the offsets y = -5 and x = 5, (5,-5). The next block then runs up x = 5 to the
    # inside corner with +X at y = 10 - 5: (5,5)
    m = run(lines("O0001", *radius(5.0), "G90 G17 G00 X-10. Y0", "G42 D1 G01 X0 F100", "Y10.", "X20.", "G40 Y0",
                  "M30"), cutter_startup=kind)  # fmt: skip
    assert m.status == "completed", m.alarm
    pts = centre_points(m)
    assert same(pts[1], [(-10.0, 0.0), corner])
    assert same(pts[2], [corner, (5.0, 5.0)])


@pytest.mark.parametrize(("kind", "corner"), [("A", (20.0, 5.0)), ("B", (25.0, 5.0))])
def test_cancel_of_type_a_and_b_as_the_manual_draws_them(kind: str, corner: tuple[float, float]) -> None:
    # G41, radius 5, along +X from (0,0) to (20,0) (tool above), cancel down to (20,-10): a right
    # turn, outside by 90°. Type A starts the cancel on the perpendicular of the block before, (20,5);
    # type B at the intersection of y = 5 and x = 25, (25,5). (The start-up +Y to (0,0) then +X is a
    # right turn, outside: type A ends it at (0,5), type B at (-5,5).)
    m = run(lines("O0001", *radius(5.0), "G90 G17 G00 X0 Y-10.", "G41 D1 G01 Y0 F100", "X20.", "G40 Y-10.",
                  "M30"), cutter_startup=kind)  # fmt: skip
    assert m.status == "completed", m.alarm
    assert same(centre_points(m)[3], [corner, (20.0, -10.0)])


def test_the_time_and_length_follow_the_centre_path() -> None:
    # the outside square at F100: the side X0 Y50 -> X50 Y50 is cut on y = 55 from x = -5 to 55,
    # 60 mm at 100 mm/min: 36 s (the programmed 50 mm would be 30 s). The whole cut: start-up
    # sqrt(15² + 22.071068²) = 26.685 mm, sides 52.929 + 60 + 60 + 52.929, cancel 26.685: 279.229 mm
    m = run(lines("O0001", *radius(5.0), *SQUARE))
    assert m.planner.moves[3].seconds == pytest.approx(36.0)
    assert m.planner.cut_length == pytest.approx(279.229, abs=0.001)


def test_the_radius_is_geometry_plus_wear_from_g10_l12_and_l13() -> None:
    # L12 R5. and L13: radius 4.8; the outside square's corner at (-4.8, 54.8)
    m = run(lines("O0001", *radius(5.0, -0.2), *SQUARE))
    assert same(centre_points(m)[3], [(-4.8, 54.8), (54.8, 54.8)])


def test_the_radius_comes_from_the_offset_memory_variables() -> None:
    # #13001 (D geometry, memory C) written by the program, as a setter's macro does
    m = run(lines("O0001", "#13001=5.", *SQUARE))
    assert same(centre_points(m)[3], [(-5.0, 55.0), (55.0, 55.0)])


def test_d0_moves_nothing_off_the_path_and_is_no_finding() -> None:
    # D0 is a radius of 0 (FANUC: "D0 always means 0"): the programmed path, no note
    m = run(lines("O0001", *radius(5.0), *[b.replace("D1", "D0") for b in SQUARE]))
    assert m.status == "completed"
    assert all(p is None for p in centre_points(m))
    assert [n for n in m.notes if n.kind == "cutter"] == []


def test_a_d_without_a_value_draws_the_programmed_path_with_a_note() -> None:
    # nothing gave offset 1: the control has a value, the run does not: a cutter-offset note on the
    # start-up line (0-based 2), once
    m = run(lines("O0001", *SQUARE))
    assert m.status == "completed"
    assert [(n.line, n.subject) for n in m.notes if n.kind == "cutter"] == [(2, "cutter-offset")]


@pytest.mark.parametrize("dialect", MILLS)
def test_start_up_on_an_arc_is_alarm_34(dialect: str) -> None:
    m = run(lines("O0001", *radius(5.0), "G90 G17 G00 X0 Y0", "G41 D1 G02 X20. Y0 R10. F100", "M30"), dialect)
    assert m.status == "alarm"
    assert (m.alarm.number, m.alarm.line) == (CUTTER_ARC_START, 3)


def test_cancel_on_an_arc_is_alarm_34() -> None:
    m = run(lines("O0001", *radius(5.0), "G90 G17 G00 X-10. Y0", "G41 D1 G01 X0 F100", "X10.",
                  "G40 G03 X20. Y10. R10.", "M30"))  # fmt: skip
    assert m.status == "alarm"
    assert (m.alarm.number, m.alarm.line) == (CUTTER_ARC_START, 5)


# a groove 3 wide and 10 deep in a top face cut with the tool above it (G41 along +X), radius 5
GROOVE = ["G90 G17 G00 X0 Y10.", "G41 D1 G01 Y0 F100", "X20.", "Y-10.", "X23.", "Y0", "X40.", "G40 Y10.", "M30"]


def test_a_groove_narrower_than_the_cutter_is_interference_alarm_41() -> None:
    # the bottom +X from (20,-10) to (23,-10): its offset starts where x = 20 + 5 meets y = -5, (25,-5),
    # and ends where y = -5 meets the right wall's offset x = 23 - 5, (18,-5): it runs -X, against the
    # programmed +X (FANUC's "groove smaller than the compensation value"): PS0041, found when the
    # right wall (line 8, 1-based) is read; the message names the bottom's line 7
    m = run(lines("O0001", *radius(5.0), *GROOVE))
    assert m.status == "alarm"
    assert (m.alarm.number, m.alarm.line + 1) == (CUTTER_INTERFERENCE, 8)
    assert "line 7" in m.alarm.message


def test_the_same_groove_with_a_smaller_cutter_is_cut() -> None:
    # radius 1: the bottom runs from (21,-9) to (22,-9), +X as programmed
    m = run(lines("O0001", *radius(1.0), *GROOVE))
    assert m.status == "completed", m.alarm
    assert same(centre_points(m)[4], [(21.0, -9.0), (22.0, -9.0)])


def test_interference_on_haas_is_a_warning_the_run_goes_past() -> None:
    # Haas's manuals at hand number no interference alarm: a cutter-interference note on line 8
    m = run(lines("O0001", *radius(5.0), *GROOVE), "haas")
    assert m.status == "completed", m.alarm
    assert [(n.line + 1, n.subject) for n in m.notes if n.kind == "cutter"] == [(8, "cutter-interference")]


def test_a_cutter_larger_than_an_inside_arc_is_interference_alarm_41() -> None:
    # tool left (radius 5) on a counterclockwise arc of radius 3 (centre on the left: the inside):
    # the offset radius would be 3 - 5 < 0
    m = run(lines("O0001", *radius(5.0), "G90 G17 G00 X-10. Y0", "G41 D1 G01 X0 F100", "X10.",
                  "G03 X13. Y3. R3.", "G01 Y20.", "G40 X0", "M30"))  # fmt: skip
    assert m.status == "alarm"
    assert (m.alarm.number, m.alarm.line + 1) == (CUTTER_INTERFERENCE, 6)
    assert "too large" in m.alarm.message


def test_a_cutter_smaller_than_an_inside_arc_follows_it() -> None:
    # radius 2 on the same R3 arc: radius 1 about (10,3), from (10,2) to (12,3)
    m = run(lines("O0001", *radius(2.0), "G90 G17 G00 X-10. Y0", "G41 D1 G01 X0 F100", "X10.",
                  "G03 X13. Y3. R3.", "G01 Y20.", "G40 X0", "M30"))  # fmt: skip
    assert m.status == "completed", m.alarm
    assert same(centre_points(m)[3], [(10.0, 2.0), (11.0, 3.0)])


def test_a_plane_change_in_offset_mode_is_alarm_37() -> None:
    m = run(lines("O0001", *radius(5.0), "G90 G17 G00 X-10. Y0", "G41 D1 G01 X0 F100", "X10.", "G18", "M30"))
    assert m.status == "alarm"
    assert (m.alarm.number, m.alarm.line + 1) == (CUTTER_PLANE, 6)


def test_a_z_move_between_two_sides_is_made_at_the_corner() -> None:
    # the outside square with a Z move after Y50.: the corner is still (-5,55), where Z moves
    text = lines("O0001", *radius(5.0), *SQUARE[:3], "Z-1.", *SQUARE[3:])
    m = run(text)
    pts = centre_points(m)
    assert same(pts[2], [(-5.0, 2.071068), (-5.0, 55.0)])
    assert same(pts[3], [(-5.0, 55.0), (-5.0, 55.0)])
    assert same(pts[4], [(-5.0, 55.0), (55.0, 55.0)])


def test_without_compensation_moves_have_no_centre_path() -> None:
    m = run(lines("O0001", *radius(5.0), "G90 G00 X0 Y0", "G01 X10. F100", "G02 X20. Y10. R10.", "M30"))
    assert all(p is None for p in centre_points(m))


def test_run_json_moves_carry_the_centre_path(tmp_path: Path) -> None:
    # the outside square: the side on line 6 (X50.) is drawn programmed from (0,50) to (50,50) and
    # its centre from (-5,55) to (55,55)
    out = run_json(tmp_path, lines("O0001", *radius(5.0), *SQUARE))
    side = next(mv for mv in out["moves"] if mv["line"] == 6)
    assert (side["from"]["X"], side["to"]["X"]) == (0.0, 50.0)
    path = side["tool_path"]
    assert (path["from"]["X"], path["from"]["Y"]) == pytest.approx((-5.0, 55.0))
    assert [(pc["to"]["X"], pc["to"]["Y"]) for pc in path["pieces"]] == [pytest.approx((55.0, 55.0))]
    assert "tool_path" not in out["moves"][0]
    json.dumps(out)


def test_g28_in_offset_mode_is_made_as_programmed_and_the_offset_starts_again_after_it() -> None:
    # radius 5, tool left, +X to (20,0), then G28 by Z: its moves have no centre path; the next
    # move in the plane, +Y from (20,0) to (20,20), starts the offset again from the programmed
    # point; the block after it is the cancel (+X, to (40,20)), a right turn, outside for a left
    # tool: type A starts the cancel on the perpendicular of the block before it, left of +Y at
    # (20,20): (15,20)
    m = run(lines("O0001", *radius(5.0), "G90 G17 G00 X-10. Y0", "G41 D1 G01 X0 F100", "X20.", "G28 Z10.",
                  "G01 Y20.", "G40 X40.", "M30"))  # fmt: skip
    assert m.status == "completed", m.alarm
    pts = centre_points(m)
    assert [mv.line + 1 for mv in m.planner.moves] == [3, 4, 5, 6, 6, 7, 8]
    assert pts[3] is None and pts[4] is None  # G28's two moves
    assert same(pts[5], [(20.0, 0.0), (15.0, 20.0)])
    assert same(pts[2], [(0.0, 5.0), (20.0, 5.0)])  # the move before G28 ends on its perpendicular


def test_a_haas_keeping_diameters_offsets_by_half_of_d() -> None:
    # the machine file's cutter_offset = "diameter" (Haas Setting 40): #2401 = 10 is a radius of 5,
    # the outside square's corner at (-5,55) as with a radius of 5 on FANUC
    m = run(lines("O0001", "G10 L12 P1 R10.", *SQUARE), "haas", cutter_offset="diameter")
    assert m.status == "completed", m.alarm
    assert same(centre_points(m)[3], [(-5.0, 55.0), (55.0, 55.0)])


def test_the_machine_file_reads_the_start_up_type_and_what_d_holds() -> None:
    s = settings_from_mapping({"cutter_startup": "B", "cutter_offset": "diameter"})
    assert (s.cutter_startup, s.cutter_offset) == ("B", "diameter")
    assert (MachineSettings().cutter_startup, MachineSettings().cutter_offset) == ("A", "radius")
    with pytest.raises(MachineFileError, match=r'cutter_startup.*"A" or "B"'):
        settings_from_mapping({"cutter_startup": "C"})
    with pytest.raises(MachineFileError, match=r'cutter_offset.*"radius" or "diameter"'):
        settings_from_mapping({"cutter_offset": 5})


def test_the_run_of_plain_lines_and_the_general_path_give_the_same_centre_path() -> None:
    # the outside square with an acute corner added, once as plain lines (the one-pass run of
    # plain lines, cutter_stage.StraightCuts) and once with its coordinates in variables (each
    # block through Planner.execute_nc and Planner.record): the same centre points and time
    plain = ["G90 G17 G00 X-20. Y-20.", "G41 D1 G01 X0 Y0 F100", "Y50.", "X50.", "X10. Y30.", "X60. Y0", "X0",
             "G40 X-20. Y-20.", "M30"]  # fmt: skip
    by_variables = ["#1=50.", "#2=10.", "#3=30.", "#4=60.", *plain[:3], "X#1", "X#2 Y#3", "X#4 Y0", *plain[6:]]
    a = run(lines("O0001", *radius(5.0), *plain))
    b = run(lines("O0001", *radius(5.0), *by_variables))
    assert a.status == b.status == "completed"
    pa, pb = centre_points(a), centre_points(b)
    assert len(pa) == len(pb)
    for x, y in zip(pa, pb, strict=True):
        assert (x is None and y is None) or same(x, y or [])
    assert a.planner.clock == pytest.approx(b.planner.clock)


def centre_path_points(m) -> list[tuple[tuple[float, ...], ...]]:  # type: ignore[no-untyped-def]
    """Per move, every point of its tool-centre path, all axes (none without compensation)."""
    return [(mv.tool_path.start, *(pc.end for pc in mv.tool_path.pieces)) if mv.tool_path else ()
            for mv in m.planner.moves]  # fmt: skip


def star_contour(seed: int, side: int) -> tuple[list[str], list[str]]:
    """A closed star-shaped contour around the origin (random radii at increasing angles: inside,
    outside, obtuse and acute corners, with a Z step and a feed change now and then), cut with
    the tool on ``side`` (41, 42), once as plain lines and once with its coordinates in variables."""
    rng = random.Random(seed)
    # on the right of the contour (outside) it starts with a spike, its tip an acute outside
    # corner where the offsets meet beyond two extension points
    polar = [(40.0, 0.0), (75.0, 0.03), (40.0, 0.06)] if side == 42 else [(40.0, 0.0)]
    angle = 0.4
    while angle < 2 * math.pi - 0.3:
        polar.append((rng.uniform(25.0, 60.0), angle))
        angle += rng.uniform(0.05, 0.6)
    points = [(round(r * math.cos(a), 3), round(r * math.sin(a), 3)) for r, a in polar]
    points.append(points[0])
    for k in range(len(points) - 3, 0, -4):  # a straight-on corner: a side cut in two at its middle
        (x0, y0), (x1, y1) = points[k], points[k + 1]
        hx, hy = round((x1 - x0) / 2, 3), round((y1 - y0) / 2, 3)
        points[k + 1 : k + 2] = [(round(x0 + hx, 3), round(y0 + hy, 3)), (round(x0 + 2 * hx, 3), round(y0 + 2 * hy, 3))]
    plain = [f"G90 G17 G00 X{points[0][0]} Y-30.", f"G{side} D1 G01 X{points[0][0]} Y{points[0][1]} F300"]
    by_variables = list(plain)
    for k, (x, y) in enumerate(points[1:], 1):
        extra = f" Z{-0.5 * k:.1f}" if k % 7 == 0 else (" F150" if k % 5 == 0 else "")
        step = [f"Z{-0.25 * k:.2f}"] if k % 11 == 0 else []  # a move off the plane, made at the corner
        plain += [*step, f"X{x} Y{y}{extra}"]
        by_variables += [*step, f"#1={x}", f"#2={y}", f"X#1 Y#2{extra}"]
    end = ["G40 G00 X0 Y0", "M30"]
    return plain + end, by_variables + end


@pytest.mark.parametrize("side", [41, 42])
@pytest.mark.parametrize("seed", range(5))
def test_a_contour_of_plain_lines_is_offset_and_timed_as_its_blocks_one_by_one(seed: int, side: int) -> None:
    # a run of plain lines joins its cuts by their reach along each move (cutter_stage.StraightCuts);
    # a block with variables is joined on its own from its corner's points: the same centre path,
    # time and length, whether the run keeps its moves (cncmacro run, the toolpath) or not (the
    # editor's analysis)
    plain, by_variables = star_contour(seed, side)
    a = run(lines("O0001", *radius(2.0), *plain))
    b = run(lines("O0001", *radius(2.0), *by_variables))
    c = machine(lines("O0001", *radius(2.0), *plain))
    c.planner.record_moves = False
    c.run()
    d = machine(lines("O0001", *radius(2.0), *plain))  # a toolpath that fills up after a few moves
    d.planner.move_budget = 9
    d.run()
    assert a.status == b.status == c.status == d.status == "completed", (a.alarm, b.alarm, c.alarm, d.alarm)
    pa, pb = centre_path_points(a), centre_path_points(b)
    assert len(pa) == len(pb)
    assert sum(bool(x) for x in pa) > 10  # the contour is cut under compensation
    for x, y in zip(pa, pb, strict=True):  # every axis of every point, Z too
        assert len(x) == len(y) and all(math.dist(p, q) < 1e-9 for p, q in zip(x, y, strict=True)), (x, y)
    kept = centre_path_points(d)
    assert len(kept) == 9
    for x, y in zip(kept, pa, strict=False):
        assert len(x) == len(y) and all(math.dist(p, q) < 1e-9 for p, q in zip(x, y, strict=True)), (x, y)
    for m in (b, c, d):
        assert m.planner.clock == pytest.approx(a.planner.clock, rel=1e-12)
        assert m.planner.cut_length == pytest.approx(a.planner.cut_length, rel=1e-12)
    seconds = [mv.seconds for mv in a.planner.moves]
    assert seconds == pytest.approx([mv.seconds for mv in b.planner.moves], rel=1e-12)


@pytest.mark.parametrize("written", ["plain", "by variables"])
def test_a_run_that_keeps_no_centre_paths_has_the_same_moves_times_and_lengths(written: str) -> None:
    # cncmacro run's text shows the programmed moves and the totals, never a centre path: its run
    # leaves them out (Planner.centre_paths), and nothing it shows changes
    plain, by_variables = star_contour(3, 42)
    text = lines("O0001", *radius(2.0), *(plain if written == "plain" else by_variables))
    a, b = machine(text), machine(text)
    b.planner.centre_paths = False
    for m in (a, b):
        assert m.run() == "completed", m.alarm
    assert any(mv.tool_path for mv in a.planner.moves) and not any(mv.tool_path for mv in b.planner.moves)
    assert [mv[:7] for mv in b.planner.moves] == [mv[:7] for mv in a.planner.moves]
    assert [mv.seconds for mv in b.planner.moves] == pytest.approx([mv.seconds for mv in a.planner.moves], rel=1e-12)
    assert b.planner.clock == pytest.approx(a.planner.clock, rel=1e-12)
    assert b.planner.cut_length == pytest.approx(a.planner.cut_length, rel=1e-12)


def test_run_text_and_json_give_the_same_cycle_time_of_a_compensated_contour(tmp_path: Path) -> None:
    plain, _ = star_contour(1, 42)
    text = lines("O0001", *radius(2.0), *plain)
    data = run_json(tmp_path, text)
    assert any("tool_path" in mv for mv in data["moves"])  # --json draws the centre path
    code, out, _ = cli("run", "--no-save", str(tmp_path / "MAIN.nc"))
    assert code == 0
    assert f"cycle time O0001: {data['cycle']['text']}" in out, out[-300:]


def test_the_bundled_contour_example_cuts_its_plate_a_radius_outside(tmp_path: Path) -> None:
    # examples/fanuc/contour_g41.nc: a plate 80 x 50 (X -40…40, Y -25…25) with R8 corners, cut
    # clockwise with G41 D01 and G10 L12 P1 R5. (radius 5): the tool on the left is outside. The
    # start-up, line 15, goes +X from (-60,0) to (-40,0); the next side goes +Y: a left turn,
    # inside for a left tool, so it ends at the intersection of its offset (y = 0 + 5) with the
    # side's (x = -40 - 5): (-45, 5). The top-left corner (line 17, G02 R8 about (-32,17)) is cut
    # on the circle of radius 8 + 5 = 13 about the same centre: from (-32 - 13, 17) = (-45,17) to
    # (-32, 17 + 13) = (-32,30). The last side, line 24, runs up to Y10, the cancel (line 25) goes
    # -X: a left turn again, so the side ends where x = -45 meets y = 10 - 5: (-45,5), and the
    # cancel ends on the programmed point (-60,10)
    text = (ROOT / "examples" / "fanuc" / "contour_g41.nc").read_text(encoding="utf-8")
    out = run_json(tmp_path, text)
    assert out["status"] == "completed"

    def centre(line: int) -> list[tuple[float, float]]:
        path = next(mv for mv in out["moves"] if mv["line"] == line)["tool_path"]
        return [(path["from"]["X"], path["from"]["Y"])] + [(pc["to"]["X"], pc["to"]["Y"]) for pc in path["pieces"]]

    assert centre(15) == [pytest.approx((-60.0, 0.0)), pytest.approx((-45.0, 5.0))]
    assert centre(17) == [pytest.approx((-45.0, 17.0)), pytest.approx((-32.0, 30.0))]
    arc = next(mv for mv in out["moves"] if mv["line"] == 17)["tool_path"]["pieces"][0]
    assert (arc["centre"]["X"], arc["centre"]["Y"]) == pytest.approx((-32.0, 17.0))
    assert centre(24) == [pytest.approx((-45.0, -17.0)), pytest.approx((-45.0, 5.0))]
    assert centre(25) == [pytest.approx((-45.0, 5.0)), pytest.approx((-60.0, 10.0))]
    # the moves before G41 and after G40 have none
    assert all("tool_path" not in mv for mv in out["moves"] if mv["line"] < 15 or mv["line"] > 25)
