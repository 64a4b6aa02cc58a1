"""docs/semantics.md §9, "Hole data": a drilling cycle's dwell P is hole data, which G80 and a
G00-G03 clear (FANUC 0i-MF / 30i-B operator's manuals, "canned cycle for drilling": the hole
machining data are cancelled by G80 or a group 01 code; Haas 96-8000, G73: "When the canned cycle
is cancelled (i.e. G00, G01, G80, RESET) the dwell time will be reset to zero"). A G82 named again
after G80 without P dwells nothing; within one canned cycle mode P stays for the next holes."""

from __future__ import annotations

import pytest

from running import lines, run


def _seconds(text: str, profile: str) -> float:
    m = run(text, profile)
    assert m.status == "completed", f"{m.status}: {m.alarm}"
    return m.planner.clock


@pytest.mark.parametrize("profile", ["fanuc-0i", "fanuc-30i", "haas"])
@pytest.mark.parametrize("cancel", ["G80", "G00 X20.", "G01 X20. F200"])
def test_g82_dwell_is_cleared_by_g80_or_a_group_01_code(profile: str, cancel: str) -> None:
    # rapids of 400 mm/s on FANUC (24000 mm/min), 423.333 mm/s on Haas (25400 mm/min)
    # line 3: G00 Z10.                                   10 mm rapid
    # line 4: G99 G82 X10. Z-10. R2. P2000 F200: position 10 mm rapid, Z10 -> R2 8 mm rapid,
    #         feed 12 mm at F200 = 3.6 s, dwell P2000 = 2 s, Z-10 -> R2 12 mm rapid
    # line 5: the cancel (G80: nothing; G00 X20.: 10 mm rapid; G01 X20. F200: 10 mm at F200 = 3 s)
    # line 6: G00 X20.                                   0 or 10 mm rapid (already at X20 after a cancel that moved)
    # line 7: G99 G82 X30. Z-10. R2. F200 (no P): position 10 mm rapid, already at R2, feed
    #         12 mm = 3.6 s, no dwell, 12 mm rapid back to R2
    # rapids: 10 + 10 + 8 + 12 + 10 (to X20, by the cancel or line 6) + 10 + 12 = 72 mm
    # feeds: 3.6 + 3.6 = 7.2 s (+ 3 s where G01 X20. moves), dwell 2 s (the first hole only)
    rate = 400.0 if profile != "haas" else 25400.0 / 60.0
    text = lines(
        "G90 G17 G21 G94 G80",
        "G00 X0 Y0 Z10.",
        "G99 G82 X10. Y0 Z-10. R2. P2000 F200",
        cancel,
        "G00 X20.",
        "G99 G82 X30. Y0 Z-10. R2. F200",
        "G80",
        "M30",
    )
    fed = 3.0 if cancel.startswith("G01") else 0.0
    rapid = 72.0 - (10.0 if fed else 0.0)
    assert _seconds(text, profile) == pytest.approx(rapid / rate + 7.2 + 2.0 + fed, abs=1e-6)


@pytest.mark.parametrize("profile", ["fanuc-0i", "haas"])
def test_g82_dwell_stays_for_the_next_holes_of_the_same_cycle_mode(profile: str) -> None:
    # both holes dwell P2000: 2 x (3.6 s feed + 2 s dwell) = 11.2 s; rapids 10 (G00 Z10.)
    # + 10 + 8 + 12 (first hole) + 10 + 12 (second, from R2) = 62 mm
    rate = 400.0 if profile != "haas" else 25400.0 / 60.0
    text = lines(
        "G90 G17 G21 G94 G80",
        "G00 X0 Y0 Z10.",
        "G99 G82 X10. Y0 Z-10. R2. P2000 F200",
        "X20.",
        "G80",
        "M30",
    )
    assert _seconds(text, profile) == pytest.approx(62.0 / rate + 11.2, abs=1e-6)


@pytest.mark.parametrize("profile", ["mitsubishi-m70", "mazak-eia"])
def test_g82_dwell_is_kept_across_g80_where_no_source_says_it_is_cleared(profile: str) -> None:
    # as the first test with G80: the second hole dwells the first hole's 2 s again
    text = lines(
        "G90 G17 G21 G94 G80",
        "G00 X0 Y0 Z10.",
        "G99 G82 X10. Y0 Z-10. R2. P2000 F200",
        "G80",
        "G00 X20.",
        "G99 G82 X30. Y0 Z-10. R2. F200",
        "G80",
        "M30",
    )
    assert _seconds(text, profile) == pytest.approx(72.0 / 400.0 + 7.2 + 4.0, abs=1e-6)
