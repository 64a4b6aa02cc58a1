"""A lathe's threads, grooves and spindle as the control runs them (docs/semantics.md §10.3,
§10.4), on both lathe profiles: G76's passes, G74/G75's pecks, G32/G34 at the lead per
revolution, G90/G92/G94 tapered by R and modal, G96 integrated along the cut under the G50 S
clamp, and gsk980tdi's hint for a per-minute feed below 1. Every number is worked by hand.

Rapid rates (the profiles' typical values): gsk980tdi X 6000 mm/min (of the radius), Z 8000;
fanuc-0i-lathe X 12000, Z 15000."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import pytest

from cli_capture import cli, run_json
from running import lines

PROFILES = ("gsk980tdi", "fanuc-0i-lathe")


def run_lathe(folder: Path, profile: str, *body: str) -> dict[str, Any]:
    """``cncmacro run --json`` of ``body`` as a program of ``profile``."""
    return run_json(folder, lines(f"O0001 (cncmacro: dialect={profile})", *body), "O0001.CNC")


def passes(result: dict[str, Any], code: str) -> list[dict[str, Any]]:
    return [mv for mv in result["moves"] if mv.get("pass_of") == code]


def xz(point: dict[str, float]) -> tuple[float, float]:
    return point["X"], point["Z"]


@pytest.mark.parametrize("profile", PROFILES)
def test_g76_cuts_at_constant_area_by_the_square_root_of_the_pass(tmp_path: Path, profile: str) -> None:
    # M20x1.5: G76 P010060 Q100 R0.05 (m 1, r 0, a 60 deg; dmin 100 um = 0.1; d 0.05);
    # G76 X18.05 Z-30 P975 Q400 F1.5 (k 0.975, first depth 0.4; P and Q in 0.001 mm on both).
    # depth n = max(0.4 sqrt(n), depth n-1 + 0.1) while below k - d = 0.925:
    #   0.4, 0.5657, 0.6928, 0.8, then max(0.8944, 0.9) = 0.9, then max(0.9798, 1.0) = 1.0 >= 0.925
    #   so the last roughing pass at 0.925; then m = 1 pass at k = 0.975.
    # X of pass at depth d = 18.05 + 2 (0.975 - d): 19.2, 18.8686, 18.6144, 18.4, 18.2, 18.15, 18.05
    # its Z start moves toward the end by d tan 30 deg: 5 - 0.4 x 0.57735 = 4.76906 on the first
    result = run_lathe(tmp_path, profile, "G97 S600 M03", "G00 X22. Z5.", "G76 P010060 Q100 R0.05",
                       "G76 X18.05 Z-30. P975 Q400 F1.5", "M30")  # fmt: skip
    moves = passes(result, "G76")
    assert len(moves) == 7 * 4  # each pass: in, thread, out, back
    threads = [mv for mv in moves if mv["mode"] == "G32"]
    depths = [0.4, 0.4 * math.sqrt(2), 0.4 * math.sqrt(3), 0.8, 0.9, 0.925, 0.975]
    assert [mv["to"]["X"] for mv in threads] == pytest.approx([18.05 + 2 * (0.975 - d) for d in depths])
    assert [mv["from"]["Z"] for mv in threads] == pytest.approx([5 - d * math.tan(math.radians(30)) for d in depths])
    assert all(mv["to"]["Z"] == -30.0 for mv in threads)
    assert xz(moves[-1]["to"]) == (22.0, 5.0)  # back at the start point
    # the first thread: 34.769 mm at 1.5 x 600 = 900 mm/min = 2.318 s (per revolution)
    assert threads[0]["time"] == pytest.approx((5 - 0.4 * math.tan(math.radians(30)) + 30) / 900 * 60, rel=0.001)


@pytest.mark.parametrize(("profile", "seconds"), [("gsk980tdi", 2.3075), ("fanuc-0i-lathe", 2.16)])
def test_g92_r_tapers_the_thread_from_x_plus_2r(tmp_path: Path, profile: str, seconds: float) -> None:
    # from X40 Z5, S500: G92 X30 Z-20 R-2 F1.5: in at rapid to X30 + 2 x (-2) = 26 (7 mm of radius),
    # the thread to X30 Z-20: its long axis Z 25 mm at 1.5 x 500 = 750 mm/min = 2 s, out at rapid
    # to X40 (5 mm), back along Z 25 mm at rapid.
    #   gsk980tdi: 0.07 + 2 + 0.05 + 0.1875 = 2.3075 s;  fanuc-0i-lathe: 0.035 + 2 + 0.025 + 0.1 = 2.16 s
    result = run_lathe(tmp_path, profile, "G97 S500 M03", "G00 X40. Z5.", "G92 X30. Z-20. R-2. F1.5", "M30")
    cycle = result["moves"][-1]
    assert [xz(leg["to"]) for leg in cycle["legs"]] == [(26.0, 5.0), (30.0, -20.0), (40.0, -20.0), (40.0, 5.0)]
    assert cycle["time"] == pytest.approx(seconds, rel=0.001)


@pytest.mark.parametrize(("profile", "seconds"), [("gsk980tdi", 11.39), ("fanuc-0i-lathe", 11.253)])
def test_g90_repeated_with_x_alone_cuts_to_the_last_cycles_z(tmp_path: Path, profile: str, seconds: float) -> None:
    # G90 X48 Z-30 F0.25, then X44 alone: the second pass cuts to Z-30 too (X, Z, R are modal).
    # G99 S800: 0.25 x 800 = 200 mm/min. The second pass from X54 Z2: in 5 mm of radius at rapid,
    # cut 32 mm: 9.6 s, out 5 mm at the feed: 1.5 s, back 32 mm at rapid.
    #   gsk980tdi: 0.05 + 9.6 + 1.5 + 0.24 = 11.39 s;  fanuc-0i-lathe: 0.025 + 9.6 + 1.5 + 0.128 = 11.253 s
    result = run_lathe(tmp_path, profile, "G50 S2500", "T0101", "G99 G97 S800 M03", "G00 X54. Z2.",
                       "G90 X48. Z-30. F0.25", "X44.", "G00 X100. Z100.", "M30")  # fmt: skip
    second = [mv for mv in result["moves"] if mv["mode"] == "G90"][1]
    assert xz(second["to"]) == (44.0, -30.0)
    assert [xz(leg["to"]) for leg in second["legs"]] == [(44.0, 2.0), (44.0, -30.0), (54.0, -30.0), (54.0, 2.0)]
    assert second["time"] == pytest.approx(seconds, rel=0.001)


@pytest.mark.parametrize(("profile", "seconds"), [("gsk980tdi", 23.359), ("fanuc-0i-lathe", 23.2595)])
def test_g94_r_is_the_z_difference_and_x_alone_repeats_z_and_r(tmp_path: Path, profile: str, seconds: float) -> None:
    # from X50 Z2, G99 S500 F0.1 (50 mm/min): G94 X20 Z-2 R-3: in along Z at rapid to Z-2 + (-3) = -5
    # (7 mm), the cut to X20 Z-2: sqrt(15^2 + 3^2) = 15.2971 mm = 18.3565 s, out along Z at the
    # feed to Z2: 4 mm = 4.8 s, back along X at rapid: 15 mm of radius.
    #   gsk980tdi: 0.0525 + 18.3565 + 4.8 + 0.15 = 23.359 s;  fanuc: 0.028 + 18.3565 + 4.8 + 0.075 = 23.2595 s
    # then X30 alone faces again to Z-2 with R-3: in to Z-5, cut to X30 Z-2.
    result = run_lathe(tmp_path, profile, "G99 G97 S500 M03", "G00 X50. Z2.", "G94 X20. Z-2. R-3. F0.1", "X30.",
                       "M30")  # fmt: skip
    first, second = [mv for mv in result["moves"] if mv["mode"] == "G94"]
    assert [xz(leg["to"]) for leg in first["legs"]] == [(50.0, -5.0), (20.0, -2.0), (20.0, 2.0), (50.0, 2.0)]
    assert first["time"] == pytest.approx(seconds, rel=0.001)
    assert [xz(leg["to"]) for leg in second["legs"]][:2] == [(50.0, -5.0), (30.0, -2.0)]


@pytest.mark.parametrize("profile", PROFILES)
def test_g74_pecks_by_q_and_retracts_e_after_each(tmp_path: Path, profile: str) -> None:
    # from X0 Z2: G74 R0.5 / G74 Z-10 Q3000 F0.1 (Q 3 mm): feed to Z-1, rapid back 0.5 to -0.5,
    # feed to -4, back to -3.5, feed to -7, back to -6.5, feed to -10, rapid out to Z2: 8 moves
    result = run_lathe(tmp_path, profile, "G99 G97 S500 M03", "G00 X0 Z2.", "G74 R0.5", "G74 Z-10. Q3000 F0.1",
                       "M30")  # fmt: skip
    moves = passes(result, "G74")
    assert [(mv["mode"], mv["to"]["Z"]) for mv in moves] == [
        ("G01", -1.0), ("G00", -0.5), ("G01", -4.0), ("G00", -3.5), ("G01", -7.0), ("G00", -6.5), ("G01", -10.0),
        ("G00", 2.0),
    ]  # fmt: skip


@pytest.mark.parametrize(("profile", "columns"), [("gsk980tdi", [36.0, 34.0, 32.0, 30.0]),
                                                  ("fanuc-0i-lathe", [36.0, 32.0, 30.0])])  # fmt: skip
def test_g74_shifts_by_p_a_diameter_on_gsk_a_radius_on_fanuc(
    tmp_path: Path, profile: str, columns: list[float]
) -> None:
    # from X36 Z2: G74 R0.5 / G74 X30 Z-6 P2000 Q3000 F0.1: P is 2 mm, a diameter on the GSK980TDi
    # (X36, 34, 32, 30), a radius on the 0i-TF (X36, 32, 30). Each column: feeds to Z-1, -4, -6 with
    # two retracts between, back to Z2, across to the next: 6 moves and a shift; at the end back
    # to X36: gsk 4 x 6 + 3 + 1 = 28 moves, fanuc 3 x 6 + 2 + 1 = 21.
    result = run_lathe(tmp_path, profile, "G99 G97 S500 M03", "G00 X36. Z2.", "G74 R0.5",
                       "G74 X30. Z-6. P2000 Q3000 F0.1", "M30")  # fmt: skip
    moves = passes(result, "G74")
    bottoms = [mv["to"]["X"] for mv in moves if mv["mode"] == "G01" and mv["to"]["Z"] == -6.0]
    assert bottoms == columns
    assert len(moves) == len(columns) * 6 + len(columns) - 1 + 1
    assert xz(moves[-1]["to"]) == (36.0, 2.0)


@pytest.mark.parametrize(("profile", "count"), [("gsk980tdi", 27), ("fanuc-0i-lathe", 15)])
def test_g75_pecks_along_x_and_shifts_by_q_along_z(tmp_path: Path, profile: str, count: int) -> None:
    # from X42 Z-10: G75 R0.5 / G75 X30 Z-14 P3000 Q2000 F0.05: columns at Z-10, -12, -14 (Q 2 mm);
    # pecks of P 3 mm: on the 0i-TF a radius (X42, 36, 30: 2 feeds, 1 retract of e = 0.5 radius,
    # back out: 4 moves a column), on the GSK980TDi a diameter (X39, 36, 33, 30: 4 feeds, 3
    # retracts, back: 8). fanuc 3 x 4 + 2 shifts + 1 home = 15, gsk 3 x 8 + 2 + 1 = 27.
    result = run_lathe(tmp_path, profile, "G99 G97 S500 M03", "G00 X42. Z-10.", "G75 R0.5",
                       "G75 X30. Z-14. P3000 Q2000 F0.05", "M30")  # fmt: skip
    moves = passes(result, "G75")
    assert len(moves) == count
    assert [xz(mv["to"]) for mv in moves if mv["mode"] == "G01" and mv["to"]["X"] == 30.0] == [
        (30.0, -10.0), (30.0, -12.0), (30.0, -14.0)]  # fmt: skip
    retract = next(mv for mv in moves if mv["mode"] == "G00")
    assert retract["to"]["X"] - retract["from"]["X"] == pytest.approx(1.0)  # e 0.5 of radius: 1 on the diameter
    assert xz(moves[-1]["to"]) == (42.0, -10.0)


@pytest.mark.parametrize("profile", PROFILES)
def test_g96_turns_the_spindle_by_the_diameter_along_the_cut_clamped_by_g50_s(tmp_path: Path, profile: str) -> None:
    # G50 S2500 clamps; G96 S180 (m/min); facing from X60 to X0 at F0.2 mm/rev under G99.
    # The spindle reaches 2500 rev/min at D = 1000 x 180 / (pi x 2500) = 22.918 mm.
    # From D60 to D22.918 (radius moves dD/2): t = integral of dl / (F rpm) = pi / (1000 V F) x
    #   integral of D dD / 2 = pi / 36000 x (60^2 - 22.918^2) / 4 = 0.067081 min = 4.0249 s;
    # from D22.918 to 0 at 2500 rev/min: 11.459 mm / (0.2 x 2500) = 0.022918 min = 1.3751 s.
    # Total 5.4000 s (a midpoint rpm, D30: 1909.9 rev/min, would give 4.712 s).
    result = run_lathe(tmp_path, profile, "G00 X60. Z0", "G50 S2500", "G96 S180 M03", "G99 G01 X0 F0.2", "M30")
    knee = 1000 * 180 / (math.pi * 2500)
    by_hand = (math.pi / 36000 * (60**2 - knee**2) / 4 + knee / 2 / 500) * 60
    assert by_hand == pytest.approx(5.4, rel=0.001)
    assert result["moves"][-1]["time"] == pytest.approx(by_hand, rel=0.01)


@pytest.mark.parametrize("profile", PROFILES)
def test_g97_without_s_keeps_the_speed_g96_turned_at_and_g96_without_s_its_surface_speed(
    tmp_path: Path, profile: str
) -> None:
    # GSK980TDi §3.25 notes 4 and 1 (FANUC alike): G96 S150 at X50 turns 1000 x 150 / (pi x 50) =
    # 954.93 rev/min; a G97 without S keeps it (#4119 reads it): Z-20 to Z-40 at F0.2 is
    # 20 / (0.2 x 954.93) min = 6.283 s (it turned at 150 rev/min: 40 s); a G96 without S cuts at
    # 150 m/min again (#4119 reads 150)
    result = run_lathe(tmp_path, profile, "G50 S2000", "G96 S150 M03", "G00 X50. Z2.", "G99 G01 Z-20. F0.2", "G97",
                       "#100=#4119", "G01 Z-40.", "G96", "#101=#4119", "M30")  # fmt: skip
    rpm = 1000 * 150 / (math.pi * 50)
    assert (result["variables"]["100"], result["variables"]["101"]) == (pytest.approx(rpm), 150.0)
    cut = next(mv for mv in result["moves"] if mv["line"] == 8)
    assert cut["time"] == pytest.approx(20 / (0.2 * rpm) * 60, rel=1e-6)
    assert cut["time"] == pytest.approx(6.283, rel=1e-3)


def test_g96_under_g20_is_a_surface_speed_in_feet_per_minute(tmp_path: Path) -> None:
    # G20: G96 S600 is 600 ft/min; at D2.0 in the spindle turns at 12 x 600 / (pi x 2) = 1145.9
    # rev/min, 11.459 in/min at F0.01 in/rev: Z0.1 to Z-3.0 (3.1 in) takes 0.27053 min =
    # 16.232 s, the same as G97 S1146 (taken as m/min it turned 3.28 times faster: 4.95 s)
    result = run_lathe(tmp_path, "fanuc-0i-lathe", "G20 G99", "G50 S4000", "G96 S600 M03", "G00 X2.0 Z0.1",
                       "G01 Z-3.0 F0.01", "M30")  # fmt: skip
    rpm = 12 * 600 / (math.pi * 2.0)
    assert result["moves"][-1]["time"] == pytest.approx(3.1 / (0.01 * rpm) * 60, rel=1e-4)
    assert result["moves"][-1]["time"] == pytest.approx(16.232, rel=1e-4)


@pytest.mark.parametrize("profile", PROFILES)
def test_g50_s_is_the_spindle_clamp_not_a_spindle_speed(tmp_path: Path, profile: str) -> None:
    # G97 S800, then G50 S2500: the spindle still turns at 800; 10 mm at 0.2 x 800 = 160 mm/min = 3.75 s;
    # the S code (#4119) still reads 800, and the surface speed once G96 S180 is given
    result = run_lathe(tmp_path, profile, "G97 S800 M03", "G50 S2500", "#100=#4119", "G00 X40. Z0",
                       "G99 G01 Z-10. F0.2", "G96 S180", "#101=#4119", "M30")  # fmt: skip
    assert result["moves"][-1]["time"] == pytest.approx(3.75, rel=0.001)
    assert (result["variables"]["100"], result["variables"]["101"]) == (800.0, 180.0)


@pytest.mark.parametrize("profile", PROFILES)
def test_g32_threads_at_the_lead_per_revolution_even_under_g98(tmp_path: Path, profile: str) -> None:
    # S600, G98: G32 Z-30 F1.5 from Z2: 32 mm at 1.5 x 600 = 900 mm/min = 2.1333 s (not 1.5 mm/min);
    # a taper G32 X24 Z-30: its long axis is Z (32 mm against 2 mm of radius): 2.1333 s too
    result = run_lathe(tmp_path, profile, "G97 S600 M03", "G98 G00 X20. Z2.", "G32 Z-30. F1.5", "G00 X26.", "Z2.",
                       "X20.", "G32 X24. Z-30. F1.5", "M30")  # fmt: skip
    threads = [mv for mv in result["moves"] if mv["mode"] == "G32"]
    assert [mv["time"] for mv in threads] == pytest.approx([32 / 900 * 60] * 2, rel=0.001)


@pytest.mark.parametrize(("profile", "letter"), [("gsk980tdi", "R"), ("fanuc-0i-lathe", "K")])
def test_g34_lead_grows_by_its_change_each_revolution(tmp_path: Path, profile: str, letter: str) -> None:
    # G34 Z-30 F1.5 with a change of 0.1 mm per revolution (K on the 0i-TF, R on the GSK980TDi),
    # from Z2, S600: after N turns 1.5 N + 0.05 N^2 = 32, N = (sqrt(2.25 + 6.4) - 1.5) / 0.1
    # = 14.4109 turns = 14.4109 / 600 min = 1.4411 s
    result = run_lathe(tmp_path, profile, "G97 S600 M03", "G00 X20. Z2.", f"G34 Z-30. F1.5 {letter}0.1", "M30")
    turns = (math.sqrt(1.5**2 + 2 * 0.1 * 32) - 1.5) / 0.1
    assert result["moves"][-1]["time"] == pytest.approx(turns / 600 * 60, rel=0.001)
    assert result["moves"][-1]["time"] == pytest.approx(1.4411, rel=0.001)


@pytest.mark.parametrize(("profile", "hinted"), [("gsk980tdi", True), ("fanuc-0i-lathe", False)])
def test_a_cut_at_f_below_1_under_power_on_g98_is_a_hint_that_g99_is_missing(
    tmp_path: Path, profile: str, hinted: bool
) -> None:
    # gsk980tdi powers on in G98: G01 F0.2 cuts at 0.2 mm/min, surely meant per revolution. The
    # 0i-TF powers on in G99, where a G98 before F0.2 is the programmer's own choice.
    path = tmp_path / "O0001.CNC"
    path.write_text(lines(f"O0001 (cncmacro: dialect={profile})", "M03 S500", "G98 G00 X40. Z2.", "G01 Z-20. F0.2",
                          "X50.", "M30"), encoding="utf-8")  # fmt: skip
    _, out, _ = cli("check", "--hints", str(path))
    assert ("O0001.CNC:4:1: hint:" in out and "[feed-per-minute]" in out) == hinted
    assert out.count("feed-per-minute") == (1 if hinted else 0)  # once a run, not on every line
    _, zh, _ = cli("check", "--hints", "--locale", "zh-CN", str(path))
    assert ("请在切削前加 G99" in zh) == hinted
