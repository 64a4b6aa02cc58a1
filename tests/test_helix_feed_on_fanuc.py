"""A helix (G02/G03 whose third axis moves too) is fed along its arc on FANUC controls: "The
feedrate along the circumference of two circular interpolated axes is the specified feedrate"
(FANUC operator's manuals, helical interpolation; FANUC 15i/150i-MB connection manual B-63783EN-1/01
§6.7: with parameter HTG = 0 "a feedrate along an arc is specified by an F command"). Its time is
the arc's length in the plane over F (`Timing.helix_fed_on_arc`); elsewhere the helix's own length
over F, as before (docs/semantics.md §9)."""

from __future__ import annotations

import math

import pytest

from running import lines, run

# a full circle of radius 10 (62.832 mm) dropping 5 mm, at F200 mm/min
HELIX = ("G21 G17 G90 G94", "G00 X10. Y0 Z0", "G03 X10. Y0 Z-5. I-10. J0 F200", "M30")
ARC = 2 * math.pi * 10


@pytest.mark.parametrize(("dialect", "length"), [
    ("fanuc-0i", ARC),  # 18.850 s
    ("fanuc-30i", ARC),
    ("haas", math.hypot(ARC, 5.0)),  # no Haas source says otherwise: along the helix, 18.910 s
])  # fmt: skip
def test_a_helix_is_timed_by_the_feed_on_its_circumference(dialect: str, length: float) -> None:
    m = run(lines(*HELIX), dialect)
    assert m.status == "completed", m.alarm
    assert m.planner.moves[-1].seconds == pytest.approx(length / 200.0 * 60.0)
