"""docs/semantics.md §11 "Feed": a G93 (inverse time) cut whose 1/F minutes would move the tool
faster than the machine's highest cutting feed goes at that feed. FANUC (Power Mate i
descriptions B-63172EN/01 §4.2.2, "Cutting feed rate clamp"): "If the actual cutting feed rate …
is commanded exceeding the upper limit, it is clamped to a speed not exceeding the upper limit";
Mitsubishi M700V programming manual §7.5, G93: "The feed function is clamped at the maximum
cutting speed". Every expected time is worked out by hand in the comments."""

from __future__ import annotations

import pytest

from cncmacro.library.limits_settings import MachineLimits
from running import lines, run

LIMITS = MachineLimits(feed=5000.0)  # the highest cutting feed, mm/min


@pytest.mark.parametrize("profile", ["fanuc-0i", "haas", "mitsubishi-m70"])
def test_an_inverse_time_cut_faster_than_the_highest_feed_is_clamped(profile: str) -> None:
    # G93 G01 X100. F100.: 1/100 min = 0.6 s for 100 mm is 10000 mm/min, above 5000: it goes at
    # 5000, 100 / 5000 * 60 = 1.2 s (it took 0.6 s)
    # X150. F10.: 1/10 min = 6 s for 50 mm is 500 mm/min, under 5000: 6 s as written
    m = run(lines("G90 G94 G00 X0 Y0", "G93 G01 X100. F100.", "X150. F10.", "G94", "M30"), profile,
            limits=LIMITS)  # fmt: skip
    assert m.status == "completed", m.alarm
    assert [mv.seconds for mv in m.planner.moves[-2:]] == [pytest.approx(1.2), pytest.approx(6.0)]


def test_an_inverse_time_cut_under_g20_is_clamped_in_mm() -> None:
    # G20: X10. is 254 mm; F20. asks 1/20 min = 3 s, 5080 mm/min, above 5000: 254 / 5000 * 60 = 3.048 s
    m = run(lines("G20 G90 G94 G00 X0 Y0", "G93 G01 X10. F20.", "G94", "M30"), "fanuc-0i", limits=LIMITS)
    assert m.planner.moves[-1].seconds == pytest.approx(3.048)
