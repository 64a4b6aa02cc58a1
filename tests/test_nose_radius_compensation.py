"""docs/semantics.md §12: tool nose radius compensation on the lathes (planner/cutter_stage.py).

Each program gives offset 01 its nose radius and imaginary tool nose direction with
``G10 P10001 R.. Q..`` (geometry), selected by ``T0101``. The expected nose-centre points are
worked out by hand in the comments, in the Z-X plane with X as a radius (r = X / 2); they are
checked as program coordinates (X a diameter again), to 0.001 mm. ``centre_points`` lists, per
move, the (X, Z) points its centre path goes through (the ``from`` of the first, then each
piece's ``to``).

Tip 3 puts the imaginary tool nose at (-R, -R) from the nose centre in (X radial, Z), so outside
offset mode the centre is at the programmed point + (R, R): with R = 0.8 that is X + 1.6 (a
diameter) and Z + 0.8."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from cli_capture import run_json
from cncmacro.dialects import get_dialect
from cncmacro.dialects.alarms import CUTTER_ARC_START
from running import lines, run

LATHES = ["fanuc-0i-lathe", "gsk980tdi", get_dialect("fanuc-30i").lathe_variant]
LATHE_IDS = ["fanuc-0i-lathe", "gsk980tdi", "fanuc-30i-lathe"]


def centre_points(m) -> list[list[tuple[float, float]] | None]:  # type: ignore[no-untyped-def]
    """Per move, the (X, Z) points of its nose-centre path (None: no compensation on it)."""
    xi, zi = m.planner.axis_index["X"], m.planner.axis_index["Z"]
    out: list[list[tuple[float, float]] | None] = []
    for mv in m.planner.moves:
        path = mv.tool_path
        if path is None:
            out.append(None)
            continue
        out.append([(path.start[xi], path.start[zi])] + [(pc.end[xi], pc.end[zi]) for pc in path.pieces])
    return out


def same(got: list[tuple[float, float]] | None, want: list[tuple[float, float]]) -> bool:
    return (
        got is not None
        and len(got) == len(want)
        and all(math.dist(a, b) < 0.001 for a, b in zip(got, want, strict=True))
    )


def nose(radius: float, tip: int) -> list[str]:
    """The blocks that give offset 01 nose radius ``radius`` and tip ``tip``, and select it."""
    return [f"G10 P10001 R{radius} Q{tip}", "T0101"]


# an outside diameter: a start-up along -Z onto the face corner, a taper up to X60, a diameter, and a
# cancel out along +X; G42 keeps the nose above (outside) a cut toward the chuck
TAPER = ["G98 G00 X40. Z5.", "G42 G01 Z0 F100", "X60. Z-20.", "Z-40.", "G40 G00 X80.", "M30"]


@pytest.mark.parametrize("dialect", LATHES, ids=LATHE_IDS)
def test_a_taper_with_tip_3_has_its_nose_centre_where_the_offsets_meet(dialect: object) -> None:
    # R = 0.8, G42 (right, negative offset), in (z, r). Start-up from (5, 20) to (0, 20) along -Z:
    # its offset is r = 20.8; tip 3 starts the centre at (5 + 0.8, 20 + 0.8) = X41.6 Z5.8. The taper
    # (0, 20) -> (-20, 30) turns right, inside for G42: with n1 = (0, -1), n2 = (-0.447214, -0.894427)
    # (left normals) and t1.t2 = 0.894427 the corner is P + d (n1 + n2) / (1 + t1.t2) = (0, 20) +
    # (-0.8 / 1.894427) (-0.447214, -1.894427) = (0.188854, 20.8): X41.6 Z0.188854. The taper meets
    # Z-40 turning left by 26.6° (outside, obtuse): the same sum, (-20, 30) + (0.188854, 0.8) =
    # (-19.811146, 30.8): X61.6 Z-19.811146. Z-40 then the cancel +X turns right, inside: r = 30.8
    # meets the cancel's offset z = -40 + 0.8 at (-39.2, 30.8), and the cancel ends with the tip on
    # the programmed point: (-40 + 0.8, 40 + 0.8) = X81.6 Z-39.2
    m = run(lines("O0001", *nose(0.8, 3), *TAPER), dialect)  # type: ignore[arg-type]
    assert m.status == "completed", m.alarm
    pts = centre_points(m)
    assert pts[0] is None  # the G00 before G42
    assert same(pts[1], [(41.6, 5.8), (41.6, 0.188854)])
    assert same(pts[2], [(41.6, 0.188854), (61.6, -19.811146)])
    assert same(pts[3], [(61.6, -19.811146), (61.6, -39.2)])
    assert same(pts[4], [(61.6, -39.2), (81.6, -39.2)])


# a ball end: a start-up along the axis onto the tip of a R10 dome, a G03 quarter circle about Z-10
ARC = ["G98 G00 X0 Z2.", "G42 G01 Z0 F100", "G03 X20. Z-10. R10.", "G01 Z-20.", "G40 G00 X30.", "M30"]


@pytest.mark.parametrize("dialect", LATHES, ids=LATHE_IDS)
def test_an_arc_with_tip_3_has_its_nose_centre_on_the_circle_grown_by_the_radius(dialect: object) -> None:
    # R = 0.8, G42. In (z, r) the G03 from (0, 0) to (-10, 10) about (-10, 0) turns counterclockwise
    # (G18: from Z toward X), its centre on its left: the nose on its right is outside, on the circle
    # of 10.8. The start-up along r = 0 (offset r = 0.8) turns right into the arc (inside): it meets
    # the circle at z = -10 + sqrt(10.8² - 0.8²) = -10 + sqrt(116) = 0.770330: X1.6 Z0.770330, from the
    # centre's start (2 + 0.8, 0 + 0.8) = X1.6 Z2.8. The arc ends going -Z, as Z-20 goes on: tangent,
    # the centre at (-10, 10.8) = X21.6 Z-10. The cancel +X turns right (inside): r = 10.8 meets
    # z = -20 + 0.8 at X21.6 Z-19.2; it ends at (-20 + 0.8, 15 + 0.8) = X31.6 Z-19.2
    m = run(lines("O0001", *nose(0.8, 3), *ARC), dialect)  # type: ignore[arg-type]
    assert m.status == "completed", m.alarm
    pts = centre_points(m)
    assert same(pts[1], [(1.6, 2.8), (1.6, 0.770330)])
    assert same(pts[2], [(1.6, 0.770330), (21.6, -10.0)])
    assert same(pts[3], [(21.6, -10.0), (21.6, -19.2)])
    assert same(pts[4], [(21.6, -19.2), (31.6, -19.2)])
    arc = m.planner.moves[2].tool_path.pieces[0]
    xi, zi = m.planner.axis_index["X"], m.planner.axis_index["Z"]
    assert not arc.clockwise and (arc.centre[xi], arc.centre[zi]) == (0.0, -10.0)  # the programmed centre


@pytest.mark.parametrize(
    ("tip", "start", "end"),
    [(0, (40.0, 5.0), (60.0, -30.0)), (3, (41.6, 5.8), (61.6, -29.2)), (8, (41.6, 5.0), (61.6, -30.0))],
)
def test_the_tip_direction_sets_where_the_nose_centre_starts_and_ends(
    tip: int, start: tuple[float, float], end: tuple[float, float]
) -> None:
    # a straight cut along -Z at X40 under G42, R = 0.8: in offset mode the centre runs on r = 20.8
    # (X41.6) whatever the tip; it ends where that line meets the cancel's offset, z = -30 + 0.8.
    # Outside offset mode the programmed point is the imaginary tool nose: the centre is the point
    # minus the tip's vector. Tip 0: on the point, (5, 20) and (-30, 30). Tip 3, nose at (-R, -R) in
    # (X radial, Z): (5.8, 20.8) and (-29.2, 30.8). Tip 8, nose at (-R, 0): (5, 20.8) and (-30, 30.8)
    m = run(lines("O0001", *nose(0.8, tip), "G98 G00 X40. Z5.", "G42 G01 Z-30. F100", "G40 G00 X60.", "M30"),
            "fanuc-0i-lathe")  # fmt: skip
    assert m.status == "completed", m.alarm
    pts = centre_points(m)
    assert same(pts[1], [start, (41.6, -29.2)])
    assert same(pts[2], [(41.6, -29.2), end])


# a finishing shape roughed by G71 and finished by G70 under G42, R = 0.8, tip 3 (lines 0-based)
SHAPE = ["G71 P10 Q20 U0.4 W0.1 F100", "N10 G00 X40.", "G01 Z0 F50", "X60. Z-20.", "N20 Z-40.", "G70 P10 Q20"]
FINISH = ["O0001", *nose(0.8, 3), "G98 G00 X70. Z5.", "G42", "G71 U1. R0.5", *SHAPE, "G40 G00 X80. Z10.", "M30"]


@pytest.mark.parametrize("dialect", ["fanuc-0i-lathe", LATHES[2]], ids=["fanuc-0i-lathe", "fanuc-30i-lathe"])
def test_g70_under_g42_cuts_its_finishing_pass_on_the_nose_centre_path(dialect: object) -> None:
    # G70 (line 11) runs the shape blocks, lines 7-10, from the start point (70, 5) = (z 5, r 35). The
    # first, G00 -X to X40, is the start-up: the centre starts at (5.8, 35.8) = X71.6 Z5.8 (tip 3); it
    # turns right into -Z (inside for G42): its offset z = 5 - 0.8 meets r = 20.8 at X41.6 Z4.2. The
    # face corner and the taper's corners as in the taper test: X41.6 Z0.188854, X61.6 Z-19.811146.
    # The last block ends on its end's perpendicular, X61.6 Z-40, and the return to the start point is
    # drawn as programmed. Its length is 40 - 19.811146 = 20.188854 at F50: 24.2266 s (not 24 s)
    m = run(lines(*FINISH), dialect)  # type: ignore[arg-type]
    assert m.status == "completed", m.alarm
    pts = centre_points(m)
    g70 = [k for k, mv in enumerate(m.planner.moves) if 7 <= mv.line <= 11 and mv.pass_of is None]
    assert [m.planner.moves[k].line for k in g70] == [7, 8, 9, 10, 11]
    a, b, c, d, back = (pts[k] for k in g70)
    assert same(a, [(71.6, 5.8), (41.6, 4.2)])
    assert same(b, [(41.6, 4.2), (41.6, 0.188854)])
    assert same(c, [(41.6, 0.188854), (61.6, -19.811146)])
    assert same(d, [(61.6, -19.811146), (61.6, -40.0)])
    assert back is None
    assert m.planner.moves[g70[3]].seconds == pytest.approx(24.2266, abs=1e-4)


def test_roughing_passes_under_compensation_are_drawn_as_programmed() -> None:
    # G71's passes (line 6) are not compensated here (docs/semantics.md §12): no centre path
    m = run(lines(*FINISH), "fanuc-0i-lathe")
    passes = [mv for mv in m.planner.moves if mv.pass_of == "G71"]
    assert passes and all(mv.tool_path is None for mv in passes)


def test_g70_on_gsk_compensates_from_a_g42_on_the_shape_first_block_and_cancels_at_its_end() -> None:
    # GSK980TDi §3.23.1: G41/G42 on N(ns) compensates the cycle, which cancels it at its end and leaves
    # the G40 state as it was (#4007 reads 40 after it). The same centre points as on FANUC, G70 on
    # line 10 here (no separate G42 line), its shape lines 6-9
    text = [b for b in FINISH if b != "G42"]
    text = [b.replace("N10 G00", "N10 G42 G00").replace("G70 P10 Q20", "G70 P10 Q20\n#100=#4007") for b in text]
    m = run(lines(*text), "gsk980tdi")
    assert m.status == "completed", m.alarm
    assert m.variables()[100] == 40.0
    pts = centre_points(m)
    g70 = [k for k, mv in enumerate(m.planner.moves) if 6 <= mv.line <= 10 and mv.pass_of is None]
    assert [m.planner.moves[k].line for k in g70] == [6, 7, 8, 9, 10]
    a, b, c, d, back = (pts[k] for k in g70)
    assert same(a, [(71.6, 5.8), (41.6, 4.2)])
    assert same(b, [(41.6, 4.2), (41.6, 0.188854)])
    assert same(c, [(41.6, 0.188854), (61.6, -19.811146)])
    assert same(d, [(61.6, -19.811146), (61.6, -40.0)])
    assert back is None
    assert pts[-1] is None  # the G00 after the cycle: compensation ended with it
    assert [n for n in m.notes if n.subject == "cycle-shape"] == []


def test_a_g42_after_the_gsk_shape_first_block_is_a_warning_and_the_shape_is_cut_as_programmed() -> None:
    # G42 on the shape's second block (line 7): the GSK980TDi compensates a shape only from N(ns), so
    # the finishing pass has no centre path, and the run notes it there (no alarm in the manual)
    text = [b for b in FINISH if b != "G42"]
    text = [b.replace("G01 Z0 F50", "G42 G01 Z0 F50") for b in text]
    m = run(lines(*text), "gsk980tdi")
    assert m.status == "completed", m.alarm
    assert all(p is None for p in centre_points(m))
    assert sorted({(n.line, n.kind, n.subject) for n in m.notes}) == [(7, "cycle", "cycle-shape")]


def test_a_compensation_in_force_before_a_gsk_cycle_is_set_aside_with_a_warning() -> None:
    # G42 before G71 (line 4) without G41/G42 on N10: set aside for both cycles (GSK980TDi §3.23.1),
    # each cut as programmed, a cycle-shape warning on each cycle block (lines 6 and 11)
    m = run(lines(*FINISH), "gsk980tdi")
    assert m.status == "completed", m.alarm
    assert all(p is None for p in centre_points(m)[:-1])
    assert sorted((n.line, n.subject) for n in m.notes if n.kind == "cycle") == [(6, "cycle-shape"),
                                                                                 (11, "cycle-shape")]  # fmt: skip


@pytest.mark.parametrize("dialect", ["fanuc-0i-lathe", "gsk980tdi"])
def test_an_offset_without_a_nose_radius_draws_the_programmed_path_with_a_hint(dialect: str) -> None:
    # T0101 with nothing in offset 01: the control has a radius, the run does not: the programmed
    # path and one cutter-offset hint, on the start-up line (line 3)
    m = run(lines("O0001", "T0101", *TAPER), dialect)
    assert m.status == "completed", m.alarm
    assert all(p is None for p in centre_points(m))
    assert [(n.line, n.subject) for n in m.notes if n.kind == "cutter"] == [(3, "cutter-offset")]


def test_the_nose_radius_is_geometry_plus_wear() -> None:
    # G10 P10001 R0.5 (geometry) and G10 P1 R0.3 (wear): R = 0.8, the taper's first corner as above
    m = run(lines("O0001", "G10 P10001 R0.5 Q3", "G10 P1 R0.3", "T0101", *TAPER), "fanuc-0i-lathe")
    assert same(centre_points(m)[1], [(41.6, 5.8), (41.6, 0.188854)])


def test_a_start_up_on_an_arc_is_alarm_34_on_the_fanuc_lathe_and_a_warning_on_gsk() -> None:
    text = lines("O0001", *nose(0.8, 3), "G98 G00 X0 Z0", "G42 G03 X20. Z-10. R10. F100", "M30")
    m = run(text, "fanuc-0i-lathe")
    assert (m.status, m.alarm.number, m.alarm.line) == ("alarm", CUTTER_ARC_START, 4)
    g = run(text, "gsk980tdi")
    assert g.status == "completed", g.alarm
    assert [(n.line, n.subject) for n in g.notes if n.kind == "cutter"] == [(4, "cutter-arc")]
    assert all(p is None for p in centre_points(g))


def test_run_json_lathe_moves_carry_the_nose_centre_path(tmp_path: Path) -> None:
    # the taper on the GSK980TDi: its line 6 (1-based: the taper) is drawn programmed from X40 Z0 to X60 Z-20
    # and its nose centre from X41.6 Z0.188854 to X61.6 Z-19.811146
    out = run_json(tmp_path, lines("O0001", *nose(0.8, 3), *TAPER), machine_file='dialect = "gsk980tdi"\n')
    assert out["status"] == "completed"
    taper = next(mv for mv in out["moves"] if mv["line"] == 6)
    assert (taper["from"]["X"], taper["to"]["Z"]) == (40.0, -20.0)
    path = taper["tool_path"]
    assert (path["from"]["X"], path["from"]["Z"]) == pytest.approx((41.6, 0.188854), abs=1e-6)
    assert [(pc["to"]["X"], pc["to"]["Z"]) for pc in path["pieces"]] == [pytest.approx((61.6, -19.811146), abs=1e-6)]
    assert "tool_path" not in out["moves"][0]


def test_the_machine_file_variables_give_the_gsk_offset_its_radius_and_tip() -> None:
    # the GSK980TDi keeps offset 01's nose radius at #2901 and its tip at #2301 (seed 000 §3.28.1):
    # from the machine file's [variables], the taper's first corner is the one G10 gives above
    m = run(lines("O0001", "T0101", *TAPER), "gsk980tdi", variables={2901: 0.8, 2301: 3.0})
    assert m.status == "completed", m.alarm
    assert same(centre_points(m)[1], [(41.6, 5.8), (41.6, 0.188854)])
