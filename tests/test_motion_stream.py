"""The planner's one stream of moves (ARCHITECTURE.md, ``planner/``): what each move is, as
``cncmacro run --json`` says and the toolpath draws it. Every expected move here is worked out by
hand from the program, not read back from a run: the kind of a move, an arc's plane and
direction, a drilling hole's legs (position, rapid to R, the cut, the way out) and a lathe's
single fixed cycles' legs (docs/semantics.md §9)."""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_capture import run_json
from running import lines


def moves(tmp_path: Path, text: str, name: str = "MAIN.nc", machine_file: str | None = None) -> list[dict]:
    return list(run_json(tmp_path, text, name, machine_file)["moves"])


def xyz(point: dict) -> tuple[float, float, float]:
    return point["X"], point["Y"], point["Z"]


def xz(point: dict) -> tuple[float, float]:
    return point["X"], point["Z"]


def test_each_move_says_its_kind_rapid_feed_arc_and_probe(tmp_path: Path) -> None:
    text = lines("O0001", "G90 G17 G00 X10. Y0 Z5.", "G01 Z-1. F100", "G02 X20. Y10. R10.", "G31 X50. F50", "M30")
    assert [(mv["mode"], mv["kind"]) for mv in moves(tmp_path, text)] == [
        ("G00", "rapid"), ("G01", "feed"), ("G02", "arc"), ("G31", "probe"),
    ]  # fmt: skip


def test_an_arc_names_the_plane_in_force_and_its_direction(tmp_path: Path) -> None:
    # G17: X, Y (G03 turns from X toward Y); G18: Z, X; G19: Y, Z. G02 is clockwise, G03 is not.
    text = lines("O0002", "G90 G00 X0 Y0 Z0", "G17 G02 X10. Y10. R10. F100", "G18 G03 X20. Z10. R10.",
                 "G19 G02 Y10. Z20. R10.", "M30")  # fmt: skip
    arcs = [(mv["plane"], mv["clockwise"]) for mv in moves(tmp_path, text) if mv["kind"] == "arc"]
    assert arcs == [(["X", "Y"], True), (["Z", "X"], False), (["Y", "Z"], True)]


def test_a_plain_line_arc_under_g18_names_the_zx_plane_too(tmp_path: Path) -> None:
    # the fast path of plain lines keeps the plane a plain G18 line set
    text = lines("O0003", "G18", "G00 X0 Z0", "G02 X10. Z10. R10. F100", "X20. Z20. R10.", "M30")
    assert [mv["plane"] for mv in moves(tmp_path, text) if mv["kind"] == "arc"] == [["Z", "X"], ["Z", "X"]]


def test_a_g98_drilling_hole_is_positioned_drilled_and_left_to_the_initial_level(tmp_path: Path) -> None:
    # From X0 Y0 Z50: position at rapid over X10 Y10 (at Z50), rapid to R2, feed to Z-10, rapid back
    # to the initial level Z50 (G98). The move ends at the bottom; the hole is the bottom.
    text = lines("O0004", "G90 G00 X0 Y0 Z50.", "G98 G81 X10. Y10. Z-10. R2. F100", "G80", "M30")
    hole = moves(tmp_path, text)[1]
    assert (hole["kind"], hole["cycle"]) == ("cycle", "drilling")
    assert [(leg["rapid"], xyz(leg["to"])) for leg in hole["legs"]] == [
        (True, (10.0, 10.0, 50.0)), (True, (10.0, 10.0, 2.0)), (False, (10.0, 10.0, -10.0)),
        (True, (10.0, 10.0, 50.0)),
    ]  # fmt: skip
    assert xyz(hole["hole"]) == xyz(hole["to"]) == (10.0, 10.0, -10.0)


def test_a_g99_tapping_hole_feeds_out_to_r_and_stays_there(tmp_path: Path) -> None:
    # G84 under G99: in to Z-8 at the feed and out to R3 at the feed; the return level is R, so
    # no rapid follows (a rapid leg of no length, from R to R).
    text = lines("O0005", "G90 G00 X0 Y0 Z30.", "M03 S500", "G99 G84 X5. Y0 Z-8. R3. F250", "G80", "M30")
    tap = moves(tmp_path, text)[1]
    assert [(leg["rapid"], xyz(leg["to"])) for leg in tap["legs"]] == [
        (True, (5.0, 0.0, 30.0)), (True, (5.0, 0.0, 3.0)), (False, (5.0, 0.0, -8.0)),
        (False, (5.0, 0.0, 3.0)), (True, (5.0, 0.0, 3.0)),
    ]  # fmt: skip


def test_the_lathe_g90_g92_g94_single_cycles_have_their_four_legs(tmp_path: Path) -> None:
    # gsk980tdi, from X50 Z2. G90 X40 Z-30: in along X at rapid to X40, cut along Z to Z-30, out
    # along X at the feed to X50, back along Z at rapid to Z2. G92 the same, out at rapid (the
    # thread's pull-out). G94 X20 Z-2: in along Z at rapid, face along X, out along Z at the feed,
    # back along X at rapid.
    text = lines("O0006", "G00 X50. Z2.", "G90 X40. Z-30. F0.2", "G00 X50. Z2.", "G92 X48. Z-20. F1.5",
                 "G00 X50. Z2.", "G94 X20. Z-2. F0.2", "M30")  # fmt: skip
    cycles = [mv for mv in moves(tmp_path, text, "O0006.CNC", 'base = "gsk980tdi"\n') if mv["kind"] == "cycle"]
    assert [(mv["mode"], mv["cycle"]) for mv in cycles] == [("G90", "turning"), ("G92", "turning"), ("G94", "turning")]
    legs = [[(leg["rapid"], xz(leg["to"])) for leg in mv["legs"]] for mv in cycles]
    assert legs == [
        [(True, (40.0, 2.0)), (False, (40.0, -30.0)), (False, (50.0, -30.0)), (True, (50.0, 2.0))],
        [(True, (48.0, 2.0)), (False, (48.0, -20.0)), (True, (50.0, -20.0)), (True, (50.0, 2.0))],
        [(True, (50.0, -2.0)), (False, (20.0, -2.0)), (False, (20.0, 2.0)), (True, (50.0, 2.0))],
    ]
    assert all("hole" not in mv for mv in cycles)


def test_a_lathe_roughing_cycle_is_sent_as_its_passes_each_a_move_of_its_own(tmp_path: Path) -> None:
    # A = X50 Z2; G71 U2 R1: depth 2 (X steps of 4 on the diameter), retract 1; allowances U0.5 W0.1.
    # The shape offset by them runs from X20.5 Z0.1 to X40.5 Z-19.9 (z = 0.1 - (x - 20.5)).
    # GSK §3.23.1: first A to A' (X50.5 Z2.1) at rapid; levels from A': X46.5, 42.5, 38.5, 34.5,
    # 30.5, 26.5, 22.5 (X18.5 would pass X20.5): 7 passes of 4 moves, then the approach and the
    # cut along the shape, and from its end straight to A: 1 + 28 + 2 + 1 = 32 moves.
    text = lines("O0007", "G00 X50. Z2.", "G71 U2. R1.", "G71 P10 Q20 U0.5 W0.1 F0.25", "N10 G01 X20. Z0",
                 "N20 X40. Z-20.", "M30")  # fmt: skip
    roughing = [mv for mv in moves(tmp_path, text, "O0007.CNC", 'base = "gsk980tdi"\n') if mv["line"] == 4]
    assert len(roughing) == 32
    assert all(mv.get("pass_of") == "G71" and mv["kind"] in ("rapid", "feed") for mv in roughing)
    assert (roughing[0]["to"]["X"], roughing[0]["to"]["Z"]) == (50.5, 2.1)
    first_cut = roughing[2]
    assert (first_cut["from"]["X"], first_cut["from"]["Z"], first_cut["to"]["X"]) == (46.5, 2.1, 46.5)
    assert first_cut["to"]["Z"] == pytest.approx(-19.9)  # the shape never reaches X46.5: cut to its end
    third_cut = roughing[10]
    assert third_cut["to"]["X"] == 38.5 and third_cut["to"]["Z"] == pytest.approx(0.1 - 18.0)
    assert (roughing[-1]["to"]["X"], roughing[-1]["to"]["Z"]) == (50.0, 2.0)
