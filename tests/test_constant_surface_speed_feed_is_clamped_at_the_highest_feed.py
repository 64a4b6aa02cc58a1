"""docs/semantics.md §11 "Feed": under G96 a feed per revolution times the spindle's speed, which
grows as the tool nears the centre, is clamped at the machine's highest cutting feed as any
cutting feed (FANUC's cutting feed clamp, parameters 1430/1432: "If the actual cutting feed rate
… is commanded exceeding the upper limit, it is clamped to a speed not exceeding the upper
limit", Power Mate i descriptions B-63172EN/01 §4.2.2). A thread is not clamped. Every expected
time is worked out by hand in the comments."""

from __future__ import annotations

import math

import pytest

from cncmacro.library.limits_settings import MachineLimits
from running import lines, run

LIMITS = MachineLimits(feed=4000.0, spindle=3000.0)  # mm/min, rev/min


@pytest.mark.parametrize("profile", ["fanuc-0i-lathe", "gsk980tdi"])
def test_a_g96_facing_cut_is_clamped_at_the_highest_feed_near_the_centre(profile: str) -> None:
    # G96 S300, G50 S3000, F1.5 per revolution, facing from X100 to X0 (50 mm along the radius).
    # rpm = 1000 * 300 / (pi * D) = 95492.966 / D; F * rpm passes 4000 mm/min where rpm > 4000 / 1.5
    # = 2666.667, D < 95492.966 / 2666.667 = 35.810 (the spindle's clamp 3000 is at D 31.831).
    # D 100 -> 35.810: (100 - 35.810) / 2 = 32.095 mm, time = length * mean D / (F * 95492.966)
    #   = 32.095 * 67.905 / 143239.449 min = 0.015215 min = 0.91291 s
    # D 35.810 -> 0: 17.905 mm at 4000 mm/min = 0.0044762 min = 0.26857 s; total 1.18149 s
    # (it took 1.15330 s: the last 15.915 mm at 1.5 * 3000 = 4500 mm/min, above the highest feed)
    surface = 1000.0 * 300.0 / math.pi
    knee = surface / (4000.0 / 1.5)
    expected = ((100.0 - knee) / 2 * (100.0 + knee) / 2 / (1.5 * surface) + knee / 2 / 4000.0) * 60.0
    assert expected == pytest.approx(1.18149, abs=1e-5)
    text = lines("G50 S3000", "G96 S300 M03", "G00 X100. Z0", "G99 G01 X0 F1.5", "M30")
    m = run(text, profile, limits=LIMITS)
    assert m.status == "completed", m.alarm
    assert m.planner.moves[-1].seconds == pytest.approx(expected)


def test_a_g96_cut_slower_than_the_highest_feed_is_not_changed() -> None:
    # F0.2: at the spindle's clamp 3000 rpm it is 600 mm/min, under 4000: the clamp of the feed
    # plays no part. D 100 -> 31.831 (the spindle's clamp): 34.085 mm, mean D 65.915:
    # 34.085 * 65.915 / (0.2 * 95492.966) min = 0.117638 min = 7.0583 s; D 31.831 -> 0: 15.915 mm
    # at 600 mm/min = 1.5915 s; total 8.6498 s
    surface = 1000.0 * 300.0 / math.pi
    knee = surface / 3000.0
    expected = ((100.0 - knee) / 2 * (100.0 + knee) / 2 / (0.2 * surface) + knee / 2 / 600.0) * 60.0
    assert expected == pytest.approx(8.6498, abs=1e-4)
    text = lines("G50 S3000", "G96 S300 M03", "G00 X100. Z0", "G99 G01 X0 F0.2", "M30")
    m = run(text, "fanuc-0i-lathe", limits=LIMITS)
    assert m.planner.moves[-1].seconds == pytest.approx(expected)
