"""docs/semantics.md §8 "A move from or to a place the run does not know": the tool starts where the
operator left it, and a G28 goes to a reference point whose work coordinates only the work offsets
give. A move from or to such a place is marked (``Move.unknown``, ``"unknown"`` in ``cncmacro run
--json``) and is not drawn nor counted in the extents; where the machine file gives the offsets,
the return is known and drawn, and timed to the reference point."""

from __future__ import annotations

import pytest

from cncmacro.planner.move_json import move_json
from running import lines, run

LATHE = lines(
    "O0001",
    "G98",  # feed per minute
    "G00 X100. Z100.",  # from where the operator left the tool
    "G01 Z50. F1000",  # 50 mm at 1000 mm/min: 3 s
    "G28 W0",  # W0: no intermediate move; then Z to machine 0
    "G00 Z5.",
    "M30",
)


def marks(m: object) -> list[tuple[int, str | None]]:
    return [(mv.line, mv.unknown) for mv in m.planner.moves]  # type: ignore[attr-defined]


def test_lathe_first_rapid_and_return_to_an_unknown_reference_point_are_marked() -> None:
    m = run(LATHE, "fanuc-0i-lathe")
    assert m.status == "completed"
    # line 2 from the unknown start; line 3 known; line 4: the intermediate point (W0, no travel)
    # known, the return to machine Z0 (G54 Z not given) to an unknown place; line 5 from there
    assert marks(m) == [(2, "start"), (3, None), (4, None), (4, "end"), (5, "start")]
    p = m.planner
    assert p.moves[1].seconds == pytest.approx(3.0)  # the cut: 50 mm / 1000 mm/min = 0.05 min
    assert move_json(p.moves[0], m.dialect.axes)["unknown"] == "start"
    assert move_json(p.moves[3], m.dialect.axes)["unknown"] == "end"
    assert "unknown" not in move_json(p.moves[1], m.dialect.axes)


def test_lathe_return_to_a_reference_point_the_machine_file_gives_is_drawn_and_timed() -> None:
    # G54 Z = -300 (#5222): machine Z0 is work Z300. The start is still the operator's
    m = run(LATHE, "fanuc-0i-lathe", presets={5221: -200.0, 5222: -300.0})
    assert marks(m) == [(2, "start"), (3, None), (4, None), (4, None), (5, None)]
    ends = [mv.end[1] for mv in m.planner.moves]
    assert ends[3:] == [pytest.approx(300.0), pytest.approx(5.0)]
    p = m.planner
    # Z rapids at 15000 mm/min (the profile's rate): Z50 -> Z300, 250 mm: 1 s; Z300 -> Z5, 295 mm: 1.18 s
    assert [mv.seconds for mv in p.moves[3:]] == [pytest.approx(1.0), pytest.approx(1.18)]


def test_lathe_program_that_sets_its_coordinates_at_the_start_is_drawn_from_there() -> None:
    # G50 X200. Z100.: the program says where the tool is; X200 Z100 -> X40 Z5 is drawn
    m = run(lines("O0001", "G50 X200. Z100.", "G00 X40. Z5.", "M30"), "fanuc-0i-lathe")
    assert marks(m) == [(2, None)]


def test_mill_return_of_z_to_an_unknown_home_is_marked_and_the_next_z_move_from_it() -> None:
    text = lines(
        "O0001",
        "G90 G00 X0. Y0. Z50.",  # from the unknown start
        "G01 Z10. F600",  # 40 mm at 600 mm/min: 4 s
        "G91 G28 Z0.",  # intermediate point: here (no travel); then machine Z0, G54 Z not given
        "G90 G00 X20.",  # X and Y known, Z not travelled: drawn
        "Z5.",  # from the unknown home
        "M30",
    )
    m = run(text, "fanuc")
    assert marks(m) == [(1, "start"), (2, None), (3, None), (3, "end"), (4, None), (5, "start")]
    # X20 from X0 at 24000 mm/min: 0.05 s; the cut Z50 -> Z10, 40 mm at 600 mm/min: 4 s
    assert [m.planner.moves[i].seconds for i in (1, 4)] == [pytest.approx(4.0), pytest.approx(0.05)]


def test_mill_program_that_never_names_z_draws_its_moves_in_the_plane() -> None:
    # Z never named: it stays where the operator left it. A line that moves only X and Y is drawn
    # (the plain lines' run takes it as the general path does); one that goes nowhere stands at an
    # unknown Z and is marked
    m = run(lines("O0001", "G90 G17 G94", "G00 X0. Y0.", "G01 X10. Y0. F600", "G01 X10. Y20.",
                  "G01 X10. Y20.", "M30"), "fanuc-0i")  # fmt: skip
    assert m.status == "completed"
    assert marks(m) == [(2, "start"), (3, None), (4, None), (5, "start")]
    # 10 mm and 20 mm at 600 mm/min: 1 s and 2 s
    assert [mv.seconds for mv in m.planner.moves[1:3]] == [pytest.approx(1.0), pytest.approx(2.0)]
