"""A lathe's stock removal and finishing cycles G71, G72, G73 and G70 (docs/semantics.md §10.2),
through ``cncmacro run --json`` on both lathe profiles: the passes as moves of the cycle block,
their end points, and their time computed by hand.

Every program runs at S500 under G97/G99 with F0.2: the feed is 0.2 × 500 = 100 mm/min, so a
cut of L mm takes L × 0.6 s. Rapids run each axis at its own rate (X's rate is radial):
gsk980tdi X 6,000 and Z 8,000 mm/min (100 and 133.33 mm/s); fanuc-0i-lathe X 12,000 and Z 15,000
(200 and 250 mm/s).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from cli_capture import run_json
from running import lines

# profile -> (X mm/s radial, Z mm/s)
RAPIDS = {"gsk980tdi": (100.0, 8000.0 / 60.0), "fanuc-0i-lathe": (200.0, 250.0)}
HEAD = ("O0002", "G97 S500 M03", "G99")


def passes(tmp_path: Path, dialect: str, *body: str, code: str = "G71") -> list[dict[str, Any]]:
    text = lines(*HEAD, *body, "M30")
    result = run_json(tmp_path, text, "O0002.CNC", f'base = "{dialect}"\n')
    return [mv for mv in result["moves"] if mv.get("pass_of") == code]


def ends(moves: list[dict[str, Any]]) -> list[tuple[float, float]]:
    return [(round(mv["to"]["X"], 4), round(mv["to"]["Z"], 4)) for mv in moves]


def feed_seconds(moves: list[dict[str, Any]]) -> float:
    return sum(mv["time"] for mv in moves if mv["kind"] != "rapid")


def test_10_g71_steps_in_by_depth_cuts_to_the_shape_pulls_back_by_e_and_ends_along_the_shape(tmp_path: Path) -> None:
    dialect = "fanuc-0i-lathe"  # gsk980tdi's steps differ: the test below
    # A = X40 Z2 (radius 20); Δd 2, e 0.5; shape X30 (radius 15) then Z-20, no allowances.
    # Levels radius 18 (X36), 16 (X32); 14 would pass 15. The shape never comes up to them, so
    # each cuts to its end Z-20. Retract: radius +0.5, Z +0.5 (X37 Z-19.5, X33 Z-19.5).
    moves = passes(tmp_path, dialect, "G00 X40. Z2.", "G71 U2. R0.5", "G71 P10 Q20 U0 W0 F0.2",
                   "N10 G00 X30.", "N20 G01 Z-20.")  # fmt: skip
    assert ends(moves) == [
        (36.0, 2.0), (36.0, -20.0), (37.0, -19.5), (37.0, 2.0),
        (32.0, 2.0), (32.0, -20.0), (33.0, -19.5), (33.0, 2.0),
        (30.0, 2.0), (30.0, -20.0),  # the pass along the shape
        (40.0, -20.0), (40.0, 2.0),  # out to A's diameter, back to A
    ]  # fmt: skip
    # three cuts of 22 mm at 100 mm/min: 3 × 13.2 s
    assert feed_seconds(moves) == pytest.approx(39.6)
    x, z = RAPIDS[dialect]
    # rapids: X in 2, 2.5, 1.5 and out 5 mm (radial); the two 45° pull-backs of 0.5; Z back 21.5, 21.5, 22
    rapid = 11.0 / x + 2 * max(0.5 / x, 0.5 / z) + 65.0 / z
    assert sum(mv["time"] for mv in moves) == pytest.approx(39.6 + rapid, rel=0.01)


def test_10_g71_on_gsk_pulls_back_at_the_feed_and_goes_from_the_shape_end_straight_to_a(tmp_path: Path) -> None:
    # GSK §3.23.1 ④ "X 轴、Z 轴按切削进给速度退刀 e(45°直线)" (the 45° retract at the cutting feed),
    # ⑧ "从C’点快速移动到A点" (from C' to A at rapid). A = X40 Z2 = A' (no allowances); Δd 2, e 0.5;
    # levels X36, X32 as on FANUC; each retract (radius 0.5, Z 0.5) is √0.5 = 0.7071 mm at 100 mm/min.
    moves = passes(tmp_path, "gsk980tdi", "G00 X40. Z2.", "G71 U2. R0.5", "G71 P10 Q20 U0 W0 F0.2",
                   "N10 G00 X30.", "N20 G01 Z-20.")  # fmt: skip
    assert ends(moves) == [
        (36.0, 2.0), (36.0, -20.0), (37.0, -19.5), (37.0, 2.0),
        (32.0, 2.0), (32.0, -20.0), (33.0, -19.5), (33.0, 2.0),
        (30.0, 2.0), (30.0, -20.0),  # the pass along the shape
        (40.0, 2.0),  # straight back to A
    ]  # fmt: skip
    assert [mv["kind"] for mv in moves[:4]] == ["rapid", "feed", "feed", "rapid"]
    # three cuts of 22 mm (39.6 s) and two retracts of 0.7071 mm, 0.6 s a millimetre
    assert feed_seconds(moves) == pytest.approx(39.6 + 2 * 0.5**0.5 * 0.6)


def test_10_g72_on_gsk_counts_the_levels_from_a_moved_by_the_allowances(tmp_path: Path) -> None:
    # GSK §3.23.2 ① "从起点 A 点快速移动到 A’点，X 轴移动 Δu、Z 轴移动 Δw", ② from A' Z moves Δd,
    # ⑤ X back at rapid to A''s, ⑥ in again by Δd + e, ⑦ B'→C' at the feed, ⑧ C'→A at rapid.
    # A = X80 Z2, Δd 2, e 0.5, U0.4 W0.2: A' = X80.4 Z2.2. Shape Z-6 (G01), X20, Z0: B' = X80.4
    # Z-5.8, C' = X20.4 Z0.2. Levels Z0.2, -1.8, -3.8 (from A', not Z0, -2, -4 from A); the next,
    # -5.8, is B'. Each faces X80.4 → X20.4 and pulls back by (X+1, Z+0.5) at the feed.
    moves = passes(tmp_path, "gsk980tdi", "G00 X80. Z2.", "G72 W2. R0.5", "G72 P10 Q20 U0.4 W0.2 F0.2",
                   "N10 G01 Z-6.", "X20.", "N20 Z0", code="G72")  # fmt: skip
    assert ends(moves) == [
        (80.4, 2.2),
        (80.4, 0.2), (20.4, 0.2), (21.4, 0.7), (80.4, 0.7),
        (80.4, -1.8), (20.4, -1.8), (21.4, -1.3), (80.4, -1.3),
        (80.4, -3.8), (20.4, -3.8), (21.4, -3.3), (80.4, -3.3),
        (80.4, -5.8), (20.4, -5.8), (20.4, 0.2),
        (80.0, 2.0),
    ]  # fmt: skip
    # at the feed (0.6 s/mm): in 2 + 3 × 2.5 = 9.5 mm; faces 3 × 30 mm (radial); retracts 3 × 0.7071;
    # the shape 30 + 6 mm: 137.621 mm
    assert feed_seconds(moves) == pytest.approx((9.5 + 90.0 + 3 * 0.5**0.5 + 36.0) * 0.6)


def test_10_g71_leaves_the_finishing_allowances_on_the_part(tmp_path: Path) -> None:
    dialect = "fanuc-0i-lathe"  # on gsk980tdi the levels count from A' (the test above)
    # The same shaft with U0.5 W0.1: the shape moves to X30.5 and Z up by 0.1, so the last pass
    # runs X30.5 from Z2.1 to Z-19.9 and the levels cut to Z-19.9.
    moves = passes(tmp_path, dialect, "G00 X40. Z2.", "G71 U2. R0.5", "G71 P10 Q20 U0.5 W0.1 F0.2",
                   "N10 G00 X30.", "N20 G01 Z-20.")  # fmt: skip
    assert ends(moves)[1] == (36.0, -19.9)
    assert ends(moves)[8:10] == [(30.5, 2.1), (30.5, -19.9)]


@pytest.mark.parametrize("dialect", ["gsk980tdi", "fanuc-0i-lathe"])
def test_10_g71_cuts_each_level_to_where_the_shape_comes_up_to_it(tmp_path: Path, dialect: str) -> None:
    # A = X50 Z2; Δd 2 (X steps of 4), shape X20, Z-20, X40 (a shoulder), Z-40, X50.
    # Level X46 and X42: above the shoulder, cut to where the shape reaches them on its last
    # step, Z-40; X38 … X22: below it, cut to the shoulder Z-20.
    moves = passes(tmp_path, dialect, "G00 X50. Z2.", "G71 U2. R1.", "G71 P10 Q20 U0 W0 F0.2", "N10 G00 X20.",
                   "G01 Z-20.", "X40.", "Z-40.", "N20 X50.")  # fmt: skip
    cuts = [e for mv, e in zip(moves, ends(moves), strict=True)
            if mv["kind"] == "feed" and mv["from"]["X"] == mv["to"]["X"]][:-2]  # fmt: skip
    assert cuts == [(46.0, -40.0), (42.0, -40.0), (38.0, -20.0), (34.0, -20.0), (30.0, -20.0), (26.0, -20.0),
                    (22.0, -20.0)]  # fmt: skip


def test_10_g72_steps_along_z_and_faces_along_x(tmp_path: Path) -> None:
    dialect = "fanuc-0i-lathe"  # gsk980tdi: test_10_g72_on_gsk_counts_the_levels_from_a_moved_by_the_allowances
    # A = X42 Z1; G72 W1 R0.5: levels Z0, Z-1 (Z-2 is the shape's first point); shape Z-2 then X20.
    # Each level faces from X42 to X20 (11 mm radial: 6.6 s), pulls back to Z+0.5 and X+1 (radius 0.5),
    # returns to X42 at rapid; then the pass along the shape at Z-2; then out to Z1 and back to X42.
    moves = passes(tmp_path, dialect, "G00 X42. Z1.", "G72 W1. R0.5", "G72 P10 Q20 U0 W0 F0.2",
                   "N10 G00 Z-2.", "N20 G01 X20.", code="G72")  # fmt: skip
    assert ends(moves) == [
        (42.0, 0.0), (20.0, 0.0), (21.0, 0.5), (42.0, 0.5),
        (42.0, -1.0), (20.0, -1.0), (21.0, -0.5), (42.0, -0.5),
        (42.0, -2.0), (20.0, -2.0),
        (20.0, 1.0), (42.0, 1.0),
    ]  # fmt: skip
    assert feed_seconds(moves) == pytest.approx(3 * 6.6)


def test_10_g73_repeats_the_shape_with_the_relief_shrinking_to_none(tmp_path: Path) -> None:
    # fanuc-0i-lathe: A = X50 Z2; G73 U3 W0 R3: relief 3 (radius) shared over 3 passes: 3, 1.5, 0
    # -> the shape X30 Z-20 cut at X36, X33, X30, each from A at rapid, 22 mm at the feed, back to A.
    moves = passes(tmp_path, "fanuc-0i-lathe", "G00 X50. Z2.", "G73 U3. W0 R3", "G73 P10 Q20 U0 W0 F0.2",
                   "N10 G00 X30.", "N20 G01 Z-20.", code="G73")  # fmt: skip
    assert ends(moves) == [
        (36.0, 2.0), (36.0, -20.0), (50.0, 2.0),
        (33.0, 2.0), (33.0, -20.0), (50.0, 2.0),
        (30.0, 2.0), (30.0, -20.0), (50.0, 2.0),
    ]  # fmt: skip
    assert feed_seconds(moves) == pytest.approx(3 * 13.2)


def test_10_g73_on_gsk_goes_from_each_pass_end_to_the_next_offset_start_at_rapid(tmp_path: Path) -> None:
    # gsk980tdi §3.23.3: A→A1 at rapid, An→Bn in N10's mode (G00 here), Bn→Cn at the feed,
    # Cn→An+1 at rapid, Cd→A at rapid. A = X50 Z2, relief 3, 1.5, 0 (radius): A1 X56, A2 X53, A3 X50.
    moves = passes(tmp_path, "gsk980tdi", "G00 X50. Z2.", "G73 U3. W0 R3", "G73 P10 Q20 U0 W0 F0.2",
                   "N10 G00 X30.", "N20 G01 Z-20.", code="G73")  # fmt: skip
    assert ends(moves) == [
        (56.0, 2.0), (36.0, 2.0), (36.0, -20.0),
        (53.0, 2.0), (33.0, 2.0), (33.0, -20.0),
        (50.0, 2.0), (30.0, 2.0), (30.0, -20.0),
        (50.0, 2.0),
    ]  # fmt: skip
    assert [mv["kind"] for mv in moves[:3]] == ["rapid", "rapid", "feed"]
    assert feed_seconds(moves) == pytest.approx(3 * 13.2)


def test_10_g73_on_gsk_goes_from_an_to_bn_at_the_cycle_feed_when_the_first_block_is_g01(tmp_path: Path) -> None:
    # GSK §3.23.3: "ns 程序段是 G01 时按 G73 指定的切削进给速度". A = X60 Z5; U3 W0 R3; U0.4 W0.1.
    # Offsets (diameter, Z): pass 1 (3×2+0.4, 0+0.1) = (6.4, 0.1), pass 2 (3.4, 0.1), pass 3 (0.4, 0.1).
    # Shape A→B X30 Z0 (G01), Z-20, X50 (C). An = A + offset, Bn = B + offset, Cn = C + offset.
    moves = passes(tmp_path, "gsk980tdi", "G00 X60. Z5.", "G73 U3.0 W0 R3", "G73 P10 Q20 U0.4 W0.1 F0.2",
                   "N10 G01 X30. Z0", "Z-20.", "N20 X50.", code="G73")  # fmt: skip
    assert ends(moves) == [
        (66.4, 5.1), (36.4, 0.1), (36.4, -19.9), (56.4, -19.9),
        (63.4, 5.1), (33.4, 0.1), (33.4, -19.9), (53.4, -19.9),
        (60.4, 5.1), (30.4, 0.1), (30.4, -19.9), (50.4, -19.9),
        (60.0, 5.0),
    ]  # fmt: skip
    assert [mv["kind"] for mv in moves[:5]] == ["rapid", "feed", "feed", "feed", "rapid"]
    # per pass at 100 mm/min (0.6 s/mm): An→Bn √(15² + 5²) = 15.811 mm, Z 20 mm, X 10 mm (radius)
    assert feed_seconds(moves) == pytest.approx(3 * (250**0.5 + 20.0 + 10.0) * 0.6)


def test_10_g73_on_gsk_cuts_a_count_of_one_in_two_passes(tmp_path: Path) -> None:
    # GSK §3.23.3 on d: "如果切削次数为1，系统将按2次切削完成封闭切削循环". R1 as R2: offsets
    # (3×2+0.4, 0.1) = (6.4, 0.1), then (0.4, 0.1): B1 X36.4 Z0.1, B2 X30.4 Z0.1.
    moves = passes(tmp_path, "gsk980tdi", "G00 X60. Z5.", "G73 U3.0 W0 R1", "G73 P10 Q20 U0.4 W0.1 F0.2",
                   "N10 G01 X30. Z0", "Z-20.", "N20 X50.", code="G73")  # fmt: skip
    at = ends(moves)
    assert [at[i] for i in range(1, len(at), 4)] == [(36.4, 0.1), (30.4, 0.1)]
    assert len(moves) == 2 * 4 + 1


def test_10_g73_on_fanuc_cuts_a_count_of_one_once(tmp_path: Path) -> None:
    # fanuc-0i-lathe: R1 is one pass, at the allowances only: X30.4 Z0.1, then the shape.
    moves = passes(tmp_path, "fanuc-0i-lathe", "G00 X60. Z5.", "G73 U3.0 W0 R1", "G73 P10 Q20 U0.4 W0.1 F0.2",
                   "N10 G01 X30. Z0", "Z-20.", "N20 X50.", code="G73")  # fmt: skip
    assert ends(moves) == [(30.4, 0.1), (30.4, -19.9), (50.4, -19.9), (60.0, 5.0)]


@pytest.mark.parametrize("dialect", ["gsk980tdi", "fanuc-0i-lathe"])
def test_10_g70_runs_the_shape_with_its_own_feed_and_returns_to_its_start(tmp_path: Path, dialect: str) -> None:
    # After the G71 (roughing at F0.2), G70 from A = X40 Z2 runs N10 (rapid to X30) and N20
    # (Z-20 at the shape's own F0.1: 50 mm/min, 22 mm in 26.4 s), then rapids back to A.
    text = lines(*HEAD, "G00 X40. Z2.", "G71 U2. R0.5", "G71 P10 Q20 U0.2 W0 F0.2", "N10 G00 X30.",
                 "N20 G01 Z-20. F0.1", "G70 P10 Q20", "M30")  # fmt: skip
    result = run_json(tmp_path, text, "O0002.CNC", f'base = "{dialect}"\n')
    finishing = [mv for mv in result["moves"] if mv["line"] >= 7 and mv.get("pass_of") is None]
    assert [(mv["line"], mv["kind"]) for mv in finishing] == [(7, "rapid"), (8, "feed"), (9, "rapid")]
    assert ends(finishing) == [(30.0, 2.0), (30.0, -20.0), (40.0, 2.0)]
    assert finishing[1]["time"] == pytest.approx(26.4)
    roughing = [mv for mv in result["moves"] if mv.get("pass_of") == "G71"]
    assert all(mv["feed"] == 0.2 for mv in roughing)  # the shape's F0.1 is not the roughing's


@pytest.mark.parametrize("dialect", ["gsk980tdi", "fanuc-0i-lathe"])
def test_10_the_run_goes_on_after_the_shape_once_roughing_is_done(tmp_path: Path, dialect: str) -> None:
    # The shape's blocks run once, as G70's; #100 counts the passes through N10's line.
    text = lines(*HEAD, "#100=0", "G00 X40. Z2.", "G71 U2. R0.5", "G71 P10 Q20 U0 W0 F0.2", "N10 G00 X30.",
                 "#100=#100+1", "N20 G01 Z-20.", "#101=#100", "G70 P10 Q20", "#102=#100", "M30")  # fmt: skip
    result = run_json(tmp_path, text, "O0002.CNC", f'base = "{dialect}"\n')
    # read once while roughing (the macro statement in the shape runs), once by G70
    assert result["variables"]["101"] == 1 and result["variables"]["102"] == 2


@pytest.mark.parametrize("dialect", ["gsk980tdi", "fanuc-0i-lathe"])
def test_10_g71_cuts_a_pocket_level_by_level_entering_it_from_above(tmp_path: Path, dialect: str) -> None:
    # A = X50 Z2; Δd 2, e 0.5; shape X30, Z-10, X40 (a ridge), Z-15, X30 (the pocket), Z-25, X50.
    # Levels X46 and X42 pass over the ridge (X40): one cut each to Z-25, where the shape comes up.
    # Levels X38 and X34 meet the ridge at Z-10 and go on in the pocket from Z-15 to Z-25: out to
    # X50, over to Z-15, down to the level above (X42, X38) at rapid, in at the feed, along to Z-25.
    moves = passes(tmp_path, dialect, "G00 X50. Z2.", "G71 U2. R0.5", "G71 P10 Q20 U0 W0 F0.2", "N10 G00 X30.",
                   "G01 Z-10.", "X40.", "Z-15.", "X30.", "Z-25.", "N20 X50.")  # fmt: skip
    feeds = [e for mv, e in zip(moves, ends(moves), strict=True) if mv["kind"] == "feed"]
    assert [e for e in feeds if e[0] == 46.0] == [(46.0, -25.0)]
    assert [e for e in feeds if e[0] == 38.0] == [(38.0, -10.0), (38.0, -15.0), (38.0, -25.0)]
    at = ends(moves)
    plunge = at.index((38.0, -15.0))
    assert at[plunge - 3 : plunge] == [(50.0, -9.5), (50.0, -15.0), (42.0, -15.0)]


@pytest.mark.parametrize("dialect", ["gsk980tdi", "fanuc-0i-lathe"])
def test_10_g71_meets_an_arc_of_the_shape_where_the_circle_crosses_the_level(tmp_path: Path, dialect: str) -> None:
    # A = X40 Z2; shape X20, Z-10, G02 X30 Z-15 R5 (a fillet about X30 Z-10: radius 15, Z-10), X40.
    # On the radius: (r - 15)² + (z + 10)² = 25. Level X28 (r 14): z = -10 - √24 = -14.899;
    # level X24 (r 12): z = -10 - √16 = -14. Arcs are followed in chords of 2°: within 0.01.
    moves = passes(tmp_path, dialect, "G00 X40. Z2.", "G71 U2. R0.5", "G71 P10 Q20 U0 W0 F0.2", "N10 G00 X20.",
                   "G01 Z-10.", "G02 X30. Z-15. R5.", "N20 G01 X40.")  # fmt: skip
    cut = {mv["to"]["X"]: mv["to"]["Z"] for mv in moves if mv["kind"] == "feed" and mv["from"]["X"] == mv["to"]["X"]}
    assert cut[28.0] == pytest.approx(-10 - 24**0.5, abs=0.01)
    assert cut[24.0] == pytest.approx(-14.0, abs=0.01)
    arc = [mv for mv in moves if mv["kind"] == "arc"]
    shown = [(a["to"]["X"], a["to"]["Z"], a["centre"]["X"], a["centre"]["Z"]) for a in arc]
    assert shown == [(30.0, -15.0, 30.0, -10.0)]


def test_10_g71_type_ii_roughs_a_pocket_deeper_than_the_shapes_first_point_in_levels(tmp_path: Path) -> None:
    dialect = "fanuc-0i-lathe"
    # Type II (N10 names X and Z): A = X42 Z2 (radius 21); Δd 2, e 0.5; shape X40 Z0 (B, radius 20),
    # Z-10, X30 (the pocket, radius 15), Z-20, X40, Z-30, X42. The levels go on below B down to the
    # pocket's floor: radius 19 (X38) and 17 (X34); 15 would reach the floor. B is at radius 20, so
    # each level is a pocket from Z-10 to Z-20: over at A's diameter to Z-10, down at rapid to the
    # level above (X42, then X38), in at the feed, along to Z-20, pulled back by e to X+1 Z+0.5,
    # out to A's diameter and back along Z. Then the pass along the shape and back to A.
    # It was one pass along the shape: the 5 mm (radius) pocket cut in one go.
    moves = passes(tmp_path, dialect, "G00 X42. Z2.", "G71 U2. R0.5", "G71 P10 Q20 U0 W0 F0.2",
                   "N10 G00 X40. Z0", "G01 Z-10.", "X30.", "Z-20.", "X40.", "Z-30.", "N20 X42.")  # fmt: skip
    assert ends(moves) == [
        (42.0, -10.0), (38.0, -10.0), (38.0, -20.0), (39.0, -19.5), (42.0, -19.5), (42.0, 2.0),
        (42.0, -10.0), (38.0, -10.0), (34.0, -10.0), (34.0, -20.0), (35.0, -19.5), (42.0, -19.5), (42.0, 2.0),
        (40.0, 0.0), (40.0, -10.0), (30.0, -10.0), (30.0, -20.0), (40.0, -20.0), (40.0, -30.0), (42.0, -30.0),
        (42.0, -30.0), (42.0, 2.0),  # out to A's diameter (already there), back to A
    ]  # fmt: skip
    # feeds: two levels of 2 (in) + 10 (along) mm, the shape 10 + 5 + 10 + 5 + 10 + 1 = 41 mm:
    # 65 mm at 100 mm/min = 39 s
    assert feed_seconds(moves) == pytest.approx(39.0)


def test_10_gsk_g71_type_ii_roughs_a_pocket_deeper_than_the_shapes_first_point_in_levels(tmp_path: Path) -> None:
    # The same shape on gsk980tdi (A′ = A, no allowances): the levels' cuts are the same, X38 and
    # X34 from Z-10 to Z-20, and only then the pass along the shape from B (X40 Z0).
    moves = passes(tmp_path, "gsk980tdi", "G00 X42. Z2.", "G71 U2. R0.5", "G71 P10 Q20 U0 W0 F0.2",
                   "N10 G00 X40. Z0", "G01 Z-10.", "X30.", "Z-20.", "X40.", "Z-30.", "N20 X42.")  # fmt: skip
    along_z = [(mv["to"]["X"], mv["from"]["Z"], mv["to"]["Z"]) for mv in moves
               if mv["kind"] == "feed" and mv["from"]["X"] == mv["to"]["X"] and mv["to"]["X"] < 40.0]  # fmt: skip
    assert along_z == [(38.0, -10.0, -20.0), (34.0, -10.0, -20.0), (30.0, -10.0, -20.0)]
