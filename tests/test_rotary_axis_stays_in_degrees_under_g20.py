"""docs/semantics.md §9 and §11: under G20 a rotary axis (A, B, C) stays in degrees. FANUC 30i-A
common manual B-63944EN/02 §8.2: "The unit of data input for degrees remains unchanged"; FANUC
16i/18i descriptions B-63682EN/01 §7.4: "For rotation axes … Inch-metric switching is not
performed". So an inch program's A90. is 90°, for the travel check and the rapid's time alike.
Every expected value is worked out by hand in the comments."""

from __future__ import annotations

import pytest

from cncmacro.library.limits_settings import MachineLimits
from running import lines, run

# A's travel -360° to +360°; A's rapid 10000 °/min, X's 30000 mm/min
LIMITS = MachineLimits({"A": (-360.0, 360.0)})
TIMING = {"rapid": {"X": 30000.0, "A": 10000.0}}
# the plain-line run (straight_runs.py) and, with a comment, the general path
PATHS = pytest.mark.parametrize("tail", ["", " (general path)"])


@PATHS
def test_a_rotary_axis_under_g20_is_inside_a_travel_given_in_degrees(tail):
    # G53 A90. is machine A90°, inside ±360°; it was taken as 90 in = 2286 and alarmed (500)
    m = run(lines("G20", f"G90 G53 G00 A90.{tail}", "G53 A-45.", "M30"), "fanuc-0i", limits=LIMITS)
    assert m.status == "completed", m.alarm


@PATHS
def test_a_rotary_axis_past_its_travel_under_g20_alarms_in_degrees(tail):
    # work offset A (#5224) 0: G00 A400. is machine A400°, 40° past the + limit 360°
    m = run(lines("G20", "G90 G54 G00 A0", f"G00 A400.{tail}", "M30"), "fanuc-0i", limits=LIMITS,
            presets={5224: 0.0})  # fmt: skip
    assert m.alarm is not None and (m.alarm.number, m.alarm.line + 1) == (500, 3)
    assert "machine A400.000, 40.000 deg past the + limit A360.000" in m.alarm.message
    assert m.planner.moves[-1].end[3] == pytest.approx(360.0)  # stopped at the limit


@PATHS
def test_a_rotary_rapid_under_g20_is_timed_in_degrees(tail):
    # G00 A90.: 90° at 10000 °/min = 90 / 10000 * 60 = 0.54 s (it took 0.54 * 25.4 = 13.716 s);
    # then X-5. A0: X 5 in = 127 mm at 30000 mm/min = 0.254 s, A 90° = 0.54 s: the slower, 0.54 s
    m = run(lines("G20", "G90 G00 X0 A0", f"G00 A90.{tail}", f"X-5. A0{tail}", "M30"), "fanuc-0i",
            timing=TIMING)  # fmt: skip
    assert m.status == "completed"
    assert [mv.seconds for mv in m.planner.moves[-2:]] == [pytest.approx(0.54), pytest.approx(0.54)]
    # X alone: 5 in = 127 mm at 30000 mm/min = 0.254 s (the linear axis is still in inches)
    m = run(lines("G20", "G90 G00 X0 A0", f"G00 X5.{tail}", "M30"), "fanuc-0i", timing=TIMING)
    assert m.planner.moves[-1].seconds == pytest.approx(0.254)
