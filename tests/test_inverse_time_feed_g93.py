"""G93 inverse time feed: a cut takes 1/F minutes whatever its length, F in every block
(Haas, "G93 Inverse Time Feed Mode": "the time (in seconds) to complete the programmed motion
using G93 is, 60 (seconds) divided by the F value", "feedrate (F) is mandatory for all
interpolated motion blocks"; FANUC 16/18-C, "Inverse time feed": F10.0 takes 60 / 10 = 6 s;
docs/semantics.md §9 "Inverse time feed")."""

from __future__ import annotations

from pathlib import Path

import pytest

from analysis_helpers import analyse_files
from running import lines, run


@pytest.mark.parametrize("profile", ["haas", "fanuc-0i"])
def test_g93_a_cut_takes_60_over_f_seconds_whatever_its_length(profile: str) -> None:
    # G93 G01 X10. A90. F2.: 60 / 2 = 30 s; X0. A0. F4.: 60 / 4 = 15 s; the arc G02 X10. R5. F6.
    # (a half circle, 15.7 in long): 60 / 6 = 10 s; then G94 G01 X20. F100.: 10 in at 100 in/min,
    # 6 s. #3001 counts milliseconds: 30000, 45000, 55000, 61000.
    text = lines(
        "O1027",
        "G20 G17 G90 G94 G00 X0. Y0. Z0.1 A0.",
        "#3001=0",
        "G93 G01 X10. A90. F2.",
        "#100=#3001",
        "X0. A0. F4.",
        "#101=#3001",
        "G02 X10. R5. F6.",
        "#102=#3001",
        "G94 G01 X20. F100.",
        "#103=#3001",
        "M30",
    )
    v = run(text, profile).variables()
    assert [v[100], v[101], v[102], v[103]] == pytest.approx([30000.0, 45000.0, 55000.0, 61000.0], abs=1.0)


def test_g93_lines_of_a_cam_program_are_timed_by_their_f() -> None:
    # plain lines (the one-pass run of straight lines): 60/2 + 60/4 + 60/5 = 30 + 15 + 12 = 57 s
    text = lines("O1", "G21 G90 G00 X0 Y0 Z0 A0", "G93 G01 X10. A90. F2.", "X20. A180. F4.", "X0 A0 F5.", "M30")
    m = run(text, "haas")
    assert m.planner.clock == pytest.approx(57.0, abs=0.01)


def test_a_g93_cut_without_f_in_its_block_is_a_warning_and_takes_the_last_f(tmp_path: Path) -> None:
    # the second cut has no F: timed at the last F, 60 / 2 = 30 s again (60 s in all), and said
    body = ("G21 G90 G00 X0 Y0 Z0 A0", "#3001=0", "G93 G01 X10. A90. F2.", "X20. A0.", "#100=#3001", "M30")
    assert run(lines("O1", *body), "haas").variables()[100] == pytest.approx(60000.0, abs=1.0)
    found = analyse_files(tmp_path, {"O0001.nc": lines("O0001 (cncmacro: dialect=haas)", *body)}, "haas")
    no_feed = [(d.line, d.message) for d in found if d.code == "no-feed"]
    assert len(no_feed) == 1 and no_feed[0][0] == 4
    assert "G93" in no_feed[0][1] and "every block" in no_feed[0][1]
