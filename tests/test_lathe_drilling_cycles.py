"""A lathe's drilling cycles hole by hole (docs/semantics.md §10.3; planner/lathe_drilling.py),
every time worked by hand.

fanuc-0i-lathe ("canned cycle for drilling", G-code system A): ``G83 Z(W) R Q P F`` positions at
rapid, rapids from the initial level by R to the R point, drills to the bottom (pecks of Q in
0.001 mm, no retract by default), dwells P and rapids back to the initial level; ``G87`` the
same along X (R a radius value); a C word positions the next hole; G80, or a G00, ends it.
Rapids: X 12000 mm/min of the radius, Z 15000, C 10800 deg/min.

gsk980tdi (§3.23.9): no R point; pecks of Q from where the tool stands, a rapid retract of R
(1 mm when left out) after each (J0), or back to the start and down to R short of the depth
reached (J1); then back to the start. Rapid Z 8000 mm/min."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from cli_capture import run_json
from running import lines


def run_lathe(folder: Path, profile: str, *body: str) -> dict[str, Any]:
    return run_json(folder, lines(f"O0001 (cncmacro: dialect={profile})", *body, "M30"), "O0001.nc")


def holes(result: dict[str, Any], code: str) -> list[dict[str, Any]]:
    return [mv for mv in result["moves"] if mv["mode"] == code]


def test_fanuc_face_drilling_rapids_to_r_drills_and_returns(tmp_path: Path) -> None:
    # from Z5: rapid to R (5 - 3 = Z2), 3 mm: 0.012 s; drill to Z-30, 32 mm at F80 (G98): 24 s;
    # Q5000 = 5 mm pecks without a retract feed the same 32 mm; back to Z5, 35 mm: 0.14 s
    result = run_lathe(tmp_path, "fanuc-0i-lathe", "G98 G97 S800 M03", "G00 X0 Z5.",
                       "G83 Z-30. R-3. Q5000 F80.", "G80", "G00 X50.")  # fmt: skip
    [hole] = holes(result, "G83")
    assert hole["time"] == pytest.approx(0.012 + 24.0 + 0.14)
    assert [(leg["rapid"], leg["to"]["Z"]) for leg in hole["legs"]] == [(True, 5.0), (True, 2.0), (False, -30.0),
                                                                      (True, 5.0)]  # fmt: skip
    after = result["moves"][-1]
    assert (after["mode"], after["from"]["Z"], after["to"]["X"]) == ("G00", 5.0, 50.0)  # G80: a plain rapid


def test_fanuc_side_drilling_along_x_and_the_next_hole_by_c(tmp_path: Path) -> None:
    # from X50 (diameter): R-2 (a radius) puts R at X46, 0.01 s; drill to X10, 18 mm of radius at
    # F60: 18 s; P500: 0.5 s; back to X50, 20 mm: 0.1 s. The next hole turns C 90 deg first: 0.5 s
    result = run_lathe(tmp_path, "fanuc-0i-lathe", "G98 G97 S800 M03", "G00 X50. Z-10. C0",
                       "G87 X10. R-2. P500 F60.", "C90.", "G00 X100.")  # fmt: skip
    first, second = holes(result, "G87")
    assert first["time"] == pytest.approx(0.01 + 18.0 + 0.5 + 0.1)
    assert second["time"] == pytest.approx(0.5 + 0.01 + 18.0 + 0.5 + 0.1)
    assert (second["to"]["X"], second["to"]["C"]) == (10.0, 90.0)
    # the G00 after it cancels the cycle: a rapid from the return level, X50
    assert (result["moves"][-1]["mode"], result["moves"][-1]["from"]["X"]) == ("G00", 50.0)


def test_fanuc_face_tapping_feeds_out_to_r(tmp_path: Path) -> None:
    # G84 at F1.5 per revolution (G99) and S500: 750 mm/min. From Z5: R at Z2 (0.012 s), in to
    # Z-20 and out to Z2 at the feed: 2 x 22 / 750 x 60 = 3.52 s; rapid to Z5: 0.012 s
    result = run_lathe(tmp_path, "fanuc-0i-lathe", "G99 G97 S500 M03", "G00 X0 Z5.", "G84 Z-20. R-3. F1.5", "G80")
    [tap] = holes(result, "G84")
    assert tap["time"] == pytest.approx(0.012 + 2 * 22 / 750 * 60 + 0.012)


@pytest.mark.parametrize(
    ("mode", "seconds"),
    [
        # J0: 5 pecks of 5 mm in 22 mm, a retract of R1 after the first four: feed 26 mm at F100
        # (15.6 s), rapids 4 mm and the 22 mm back: 26 mm at 8000 (0.195 s)
        ("", 26 / 100 * 60 + 26 / 8000 * 60),
        # J1: back to the start after each peck and down to 1 mm short: the same 26 mm of feed;
        # rapids 2 x (5 + 10 + 15 + 20) - 4 = 96 mm, and the 22 mm back
        (" J1", 26 / 100 * 60 + 118 / 8000 * 60),
    ],
)
def test_gsk_drilling_pecks_from_the_start_point(tmp_path: Path, mode: str, seconds: float) -> None:
    result = run_lathe(tmp_path, "gsk980tdi", "G98 G97 S500 M03", "G00 X0 Z2.", f"G83 Z-20. Q5000 F100{mode}",
                       "G80", "G00 X50.")  # fmt: skip
    [hole] = holes(result, "G83")
    assert hole["time"] == pytest.approx(seconds)
    assert (hole["to"]["Z"], result["moves"][-1]["from"]["Z"]) == (-20.0, 2.0)  # back at the start


def test_gsk_rigid_tapping_goes_in_and_out_at_the_lead(tmp_path: Path) -> None:
    # §3.24.6's own example: G88 X-50 P3000 F2 from X50 at S1000, under G98: F2 is the lead, so
    # 50 mm of radius in and out at 2 x 1000 = 2000 mm/min (1.5 s each) and the 3 s dwell; I16
    # (threads per inch) on G84: a lead of 25.4 / 16, 30 mm in and out at S1000 = 2 x 1.134 s, and
    # the dwell P3000, which stays in force with the cycle's data
    result = run_lathe(tmp_path, "gsk980tdi", "G98 G97 S1000 M03", "G0 X50 Z0", "G88 X-50 P3000 F2", "G80",
                       "G0 X0 Z2.", "G84 Z-28. I16", "G80")  # fmt: skip
    [side] = holes(result, "G88")
    [face] = holes(result, "G84")
    assert side["time"] == pytest.approx(1.5 + 3.0 + 1.5)
    assert face["time"] == pytest.approx(2 * 30 / (25.4 / 16 * 1000) * 60 + 3.0)


def test_each_drilling_axis_keeps_its_own_bottom(tmp_path: Path) -> None:
    # a face hole to Z-20, a side hole to X20, then a face hole by C alone: it drills to Z-20 again
    result = run_lathe(tmp_path, "fanuc-0i-lathe", "G98 G97 S800 M03", "G00 X0 Z5. C0", "G83 Z-20. R-2. F100.",
                       "G80", "G00 X60. Z-10.", "G87 X20. R-2. F100.", "G80", "G00 X0 Z5.", "G83 R-2. C90.",
                       "G80")  # fmt: skip
    assert [(mv["to"]["Z"], mv["to"]["C"]) for mv in holes(result, "G83")] == [(-20.0, 0.0), (-20.0, 90.0)]


def test_a_30i_lathe_drills_as_the_0i_tf(tmp_path: Path) -> None:
    result = run_json(tmp_path, lines("O0001", "G98 G97 S800 M03", "G00 X0 Z5.", "G83 Z-30. R-3. F80.", "G80", "M30"),
                      "O0001.nc", machine_file='dialect = "fanuc-30i"\nlathe = true\n')  # fmt: skip
    [hole] = holes(result, "G83")
    assert hole["time"] == pytest.approx(0.012 + 24.0 + 0.14)  # as the first test's hole
