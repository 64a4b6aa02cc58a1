"""The GSK980TDi's threads as its manual (§3.24, §3.25) has them cut, and the FANUC 0i-TF's G34
lead that would run out (docs/semantics.md §10.3, §10.4): the S of a G50 that sets coordinates,
left-hand threads by a negative F, G92.3's passes across the root, G34's alarm and G78's passes.
Every number is worked by hand; gsk980tdi rapids X 6000 mm/min (of the radius), Z 8000."""

from __future__ import annotations

import math

import pytest

from running import alarm, lines, run

GSK = "gsk980tdi"


# ---------------------------------------------------------------------------------------------
# G50 S (§3.24.12's example, §3.25, §3.18)


def test_gsk_g50_that_sets_coordinates_takes_its_s_as_the_spindle_speed_under_g97() -> None:
    # the manual's G76 example: "G50 X100 Z50 M3 S300；(设置工件坐标系启动主轴，指定转速)": the spindle
    # turns at 300, #4119 reads 300; a G32 of 30 mm at F2: 30 / (2 x 300) min = 0.05 min = 3 s.
    # "G50 S2000" alone is the clamp: #4119 still reads 300
    m = run(lines("G50 X100 Z50 M3 S300", "#100=#4119", "G00 X60 Z5", "G32 W-30 F2", "G50 S2000", "#101=#4119",
                  "M30"), GSK)  # fmt: skip
    assert (m.C[100], m.C[101]) == (300.0, 300.0)
    assert m.planner.moves[-1].seconds == pytest.approx(3.0)


def test_gsk_g50_s_with_coordinates_under_g96_stays_the_clamp() -> None:
    # under G96 "G50 S__可限制主轴最高转速" (§3.25): G96 S100 then G50 X100 Z50 S1500 leaves S at 100
    m = run(lines("G96 S100 M3", "G50 X100 Z50 S1500", "#100=#4119", "M30"), GSK)
    assert m.C[100] == 100.0


def test_fanuc_lathe_g50_s_with_coordinates_is_the_clamp() -> None:
    # the 0i-TF's G50 X Z S: S is the maximum spindle speed; the S code stays 800
    m = run(lines("G97 S800 M03", "G50 X100. Z50. S2000", "#100=#4119", "M30"), "fanuc-0i-lathe")
    assert m.C[100] == 800.0


# ---------------------------------------------------------------------------------------------
# left-hand threads: "F（I）> 0 右旋螺纹，F（I）< 0 左旋螺纹" (§3.24.2, §3.24.10, §3.24.6)


def test_gsk_negative_f_of_g92_1_and_g32_1_is_a_left_hand_thread_of_lead_minus_f() -> None:
    # G92.1 X19 Z-30 F-1.5 S400 from X24 Z5: in 2.5 mm of radius at 6000 mm/min = 0.025 s, the
    # thread 35 mm / (1.5 x 400) min = 3.5 s, out 0.025 s, back 35 mm at 8000 mm/min = 0.2625 s:
    # 3.8125 s. G32.1 Z-20 F-2 S500 from Z2: 22 / (2 x 500) min = 1.32 s
    m = run(lines("G97 M3 S500", "G00 X24 Z5", "G92.1 X19 Z-30 F-1.5 S400", "G00 X24 Z2", "G32.1 Z-20 F-2 S500",
                  "M30"), GSK)  # fmt: skip
    cycle, _, thread = m.planner.moves[1:]
    assert cycle.seconds == pytest.approx(3.8125)
    assert thread.seconds == pytest.approx(1.32)


def test_gsk_negative_i_of_g32_1_is_a_left_hand_thread_of_25_4_over_minus_i() -> None:
    # I-12.7 threads per inch: lead 25.4 / 12.7 = 2 mm, left-hand; 20 mm / (2 x 500) min = 1.2 s
    m = run(lines("G97 M3 S500", "G00 X24 Z0", "G32.1 Z-20 I-12.7", "M30"), GSK)
    assert m.planner.moves[-1].seconds == pytest.approx(1.2)


def test_gsk_negative_f_of_g84_is_a_left_hand_tap() -> None:
    # G84 Z-20 F-1 from Z0 at S600 (GSK: from where the tool stands, no R point): in 20 mm at
    # 1 x 600 = 600 mm/min = 2 s, out the same 2 s; the same program with F1 takes as long
    def seconds(lead: str) -> float:
        m = run(lines("G97 M3 S600", "G00 X0 Z0", f"G84 Z-20 F{lead}", "G80", "M30"), GSK)
        return m.planner.moves[-1].seconds

    assert seconds("-1") == pytest.approx(seconds("1")) == pytest.approx(4.0)


# ---------------------------------------------------------------------------------------------
# G34's lead below zero: FANUC PS0313 "illegal lead command"; GSK §3.24.4 "螺距出现负值时产生报警"


@pytest.mark.parametrize(("profile", "letter"), [("fanuc-0i-lathe", "K"), (GSK, "R")])
def test_g34_whose_lead_would_fall_below_zero_stops_with_the_illegal_lead_alarm(profile: str, letter: str) -> None:
    # F2 changing by -0.2 a revolution: the lead is 0 after 2 / 0.2 = 10 turns, 2 x 10 - 0.1 x 10^2
    # = 10 mm along; from Z5 to Z-50 is 55 mm: the lead would go negative (4 - 2 x 0.2 x 55 < 0)
    text = lines("G97 S300 M03", "G00 X40. Z5.", f"G34 Z-50. F2. {letter}-0.2", "G00 X50.", "M30")
    assert alarm(text, profile) == (313, 3)


def test_fanuc_lathe_g34_with_a_negative_lead_stops_with_the_illegal_lead_alarm() -> None:
    assert alarm(lines("G97 S300 M03", "G00 X40. Z5.", "G34 Z-50. F-2. K0.01", "M30"), "fanuc-0i-lathe") == (313, 3)


@pytest.mark.parametrize(("profile", "letter"), [("fanuc-0i-lathe", "K"), (GSK, "R")])
def test_g34_whose_lead_stays_above_zero_is_timed_by_its_turns(profile: str, letter: str) -> None:
    # F2 changing by -0.02 over 55 mm: N = (sqrt(4 - 2 x 0.02 x 55) - 2) / -0.02 = (sqrt(1.8) - 2) / -0.02
    # = 32.918 turns at 300 rev/min = 6.5836 s
    m = run(lines("G97 S300 M03", "G00 X40. Z5.", f"G34 Z-50. F2. {letter}-0.02", "M30"), profile)
    assert m.planner.moves[-1].seconds == pytest.approx((math.sqrt(1.8) - 2) / -0.02 / 300 * 60)


# ---------------------------------------------------------------------------------------------
# G92.3: "余量加工循环切削的次数＝(F－E－A)/Q ＋ 1" (§3.24.14)


def test_gsk_g92_3_cuts_f_minus_e_minus_a_over_q_plus_1_passes() -> None:
    # G92.3 X50 Z-60 F6 E1 A2 Q1000 from X60 Z5 at S200: (6 - 1 - 2) / 1 + 1 = 4 passes, each G92's
    # path: in 5 mm of radius at 6000 mm/min = 0.05 s, the thread 65 mm / (6 x 200) min = 3.25 s,
    # out 0.05 s, back 65 mm at 8000 mm/min = 0.4875 s: 3.8375 s, x 4 = 15.35 s.
    # Then X48 alone: E, A, Q are modal, 4 passes of 0.06 + 3.25 + 0.06 + 0.4875 = 3.8575 s: 15.43 s.
    # Q800 (0.8 mm): 3 / 0.8 = 3.75, the last step the rest: 4 steps, 5 passes: 5 x 3.8375 = 19.1875 s
    m = run(lines("G97 M3 S200", "G00 X60 Z5", "G92.3 X50 Z-60 F6 E1 A2 Q1000", "X48", "G92.3 X50 Z-60 Q800",
                  "M30"), GSK)  # fmt: skip
    assert [mv.seconds for mv in m.planner.moves[1:]] == pytest.approx([15.35, 15.43, 19.1875])


# ---------------------------------------------------------------------------------------------
# G78, the enhanced threading cycle (§3.24.13): G76's passes, its first block read otherwise


def test_gsk_g78_cuts_g76s_passes_and_returns_to_the_start() -> None:
    # G78 P010060 Q100 R0.05 D1: m 1 (decreasing, as G76), r 00 (in along the thread's middle: X
    # alone), a 60; D1 one finishing pass. G78 X18.05 Z-30 P975 Q400 F1.5 from X24 Z5 at S500:
    # depths as G76's 0.4, 0.5657, 0.6928, 0.8, 0.9, 0.925, 0.975, at X = 18.05 + 2 (0.975 - d)
    # = 19.2, 18.869, 18.614, 18.4, 18.2, 18.15, 18.05, each from Z5.
    # Each pass: in and out (24 - X) / 2 of radius at 6000 mm/min, together (24 - X) x 0.01 s; the
    # thread 35 / (1.5 x 500) min = 2.8 s; back 35 mm at 8000 mm/min = 0.2625 s.
    # 7 x 3.0625 + 0.01 x sum(24 - X) = 21.4375 + 0.01 x 38.517 = 21.822 s
    m = run(lines("G97 M3 S500", "G00 X24 Z5", "G78 P010060 Q100 R0.05 D1", "G78 X18.05 Z-30 P975 Q400 F1.5",
                  "M30"), GSK)  # fmt: skip
    moves = [mv for mv in m.planner.moves if mv.pass_of == "G78"]
    assert len(moves) == 7 * 4
    depths = [0.4, 0.4 * math.sqrt(2), 0.4 * math.sqrt(3), 0.8, 0.9, 0.925, 0.975]
    xs = [18.05 + 2 * (0.975 - d) for d in depths]
    threads = [mv for mv in moves if mv.mode == 32.0]
    assert [mv.end[0] for mv in threads] == pytest.approx(xs)
    assert all(mv.start[2] == 5.0 and mv.end[2] == -30.0 for mv in threads)
    assert (moves[-1].end[0], moves[-1].end[2]) == (24.0, 5.0)
    assert sum(mv.seconds for mv in moves) == pytest.approx(7 * 3.0625 + 0.01 * sum(24 - x for x in xs))


def test_gsk_g78_equal_depths_left_flank_and_starts() -> None:
    # G78 P000160 Q100 R0.05 D2 L2: m 0 (equal depths of Q), r 01 (the left flank: the pass's start
    # moves toward the thread's start by depth x tan 30), a 60, D2 finishing passes, L2 starts.
    # G78 X18.05 Z-30 P975 Q300 F1.5: depths 0.3, 0.6, 0.9 (1.2 would pass k - d = 0.925), 0.925,
    # then 0.975 twice; each cut for 2 starts: 12 threads, the first from Z 5 + 0.3 tan 30 = 5.1732
    m = run(lines("G97 M3 S500", "G00 X24 Z5", "G78 P000160 Q100 R0.05 D2 L2", "G78 X18.05 Z-30 P975 Q300 F1.5",
                  "M30"), GSK)  # fmt: skip
    threads = [mv for mv in m.planner.moves if mv.pass_of == "G78" and mv.mode == 32.0]
    depths = [0.3, 0.3, 0.6, 0.6, 0.9, 0.9, 0.925, 0.925, 0.975, 0.975, 0.975, 0.975]
    assert [mv.end[0] for mv in threads] == pytest.approx([18.05 + 2 * (0.975 - d) for d in depths])
    assert [mv.start[2] for mv in threads] == pytest.approx([5 + d * math.tan(math.radians(30)) for d in depths])
