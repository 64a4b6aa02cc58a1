"""docs/semantics.md §9, "Drilling canned cycles on a mill", step 4: on FANUC a tapping cycle's P
dwells at the bottom of the hole and again at the R point on the way out, where the spindle turns
back (FANUC Series 16i/18i/21i-TA/TB, G84/G88: "P_ : Dwell time at the bottom of the hole and at
point R when a return is made"): G84 and G74 on the FANUC mills, G84 and G88 on the FANUC lathes.
Haas, Mitsubishi and Mazak dwell at the bottom only (no source at hand has the second dwell).
Every time worked by hand."""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_capture import run_json
from running import lines, run

# FANUC rapids: 24000 mm/min = 400 mm/s on X, Y and Z; Haas 25400 mm/min
# line 2: G00 X0 Y0 Z10. from work 0: 10 mm rapid
# line 3: G99 G84 X10. Y0 Z-10. R2. P1000 F600: position 10 mm rapid, Z10 -> R2 8 mm rapid,
#         in 12 mm at F600 = 1.2 s, dwell P1000 = 1 s, out 12 mm at F600 = 1.2 s, G99: ends at R2
# rapids 28 mm; feeds 2.4 s; dwells 1 s at the bottom (+ 1 s at R on FANUC)
MILL = lines(
    "G90 G17 G21 G94 G80",
    "G00 X0 Y0 Z10.",
    "G99 {cycle} X10. Y0 Z-10. R2. P1000 F600",
    "G80",
    "M30",
)


@pytest.mark.parametrize("profile", ["fanuc-0i", "fanuc-30i"])
@pytest.mark.parametrize("cycle", ["G84", "G74"])
def test_a_fanuc_tap_dwells_p_at_the_bottom_and_again_at_point_r(profile: str, cycle: str) -> None:
    # 28 / 400 + 2.4 + 1 (bottom) + 1 (R) = 0.07 + 4.4 = 4.47 s
    m = run(MILL.format(cycle=cycle), profile)
    assert m.status == "completed", m.alarm
    assert m.planner.clock == pytest.approx(28.0 / 400.0 + 2.4 + 2.0, abs=1e-9)


@pytest.mark.parametrize("profile", ["haas", "mitsubishi-m70", "mazak-eia"])
def test_other_makers_taps_dwell_at_the_bottom_only(profile: str) -> None:
    # 28 mm of rapid + 2.4 s of feed + 1 s at the bottom (Haas: P1000 without a point is 1000 ms)
    rate = 25400.0 / 60.0 if profile == "haas" else 400.0
    m = run(MILL.format(cycle="G84"), profile)
    assert m.status == "completed", m.alarm
    assert m.planner.clock == pytest.approx(28.0 / rate + 2.4 + 1.0, abs=1e-9)


def test_a_fanuc_tap_that_gives_no_p_dwells_nothing() -> None:
    # the same hole without P: 0.07 + 2.4 s
    m = run(MILL.format(cycle="G84").replace(" P1000", ""), "fanuc-0i")
    assert m.planner.clock == pytest.approx(0.07 + 2.4, abs=1e-9)


@pytest.mark.parametrize("profile", ["fanuc-0i-lathe", "fanuc-30i"])
def test_a_fanuc_lathe_tap_dwells_at_the_bottom_and_at_point_r(tmp_path: Path, profile: str) -> None:
    # 0i-TF rapids X 12000 (radius), Z 15000 mm/min: 250 mm/s along Z
    # G84 at F1.5 per revolution (G99) and S500: 750 mm/min. From Z5: R-3 puts R at Z2, 3 mm rapid
    # = 0.012 s; in to Z-20 and out to Z2 at the feed: 2 x 22 / 750 x 60 = 3.52 s; P800 = 0.8 s at
    # the bottom and 0.8 s at R; back to Z5 (the initial level): 0.012 s
    body = lines("O0001", "G99 G97 S500 M03", "G00 X0 Z5.", "G84 Z-20. R-3. P800 F1.5", "G80", "M30")
    result = run_json(tmp_path, body, "O0001.nc", machine_file=f'dialect = "{profile}"\nlathe = true\n')
    [tap] = [mv for mv in result["moves"] if mv["mode"] == "G84"]
    assert tap["time"] == pytest.approx(0.012 + 2 * 22 / 750 * 60 + 0.8 + 0.8 + 0.012)
