"""docs/semantics.md §9, "Hole data": the initial level of a drilling canned cycle is the Z
where the canned cycle mode began (after G80 or a G00-G03); naming another cycle with no G80
between does not start it again (FANUC 0i-MF operator's manual, "canned cycle for drilling":
the initial level is the absolute Z position when the canned cycle mode is entered)."""

from __future__ import annotations

import pytest

from running import final, lines


@pytest.mark.parametrize("profile", ["fanuc-0i", "fanuc-30i", "haas"])
def test_g98_returns_to_the_level_where_the_cycle_mode_began_when_the_cycle_changes(profile: str) -> None:
    # the mode begins at Z50. (line 3); G99 leaves the first hole at R2.; G82 with no G80 between
    # is the same cycle mode: G98 returns its hole to the initial level Z50., not to Z2.
    text = lines(
        "G90 G54 G17 G21 G94 G80",
        "G00 X0 Y0 Z50.",
        "G99 G81 X10. Y0 Z-10. R2. F100",
        "G98 G82 X20. Z-10. R2. P100",
        "#103=#5003",
        "G80",
        "M30",
    )
    assert final(text, profile)[103] == 50.0


@pytest.mark.parametrize("profile", ["fanuc-0i", "haas"])
def test_a_cycle_after_g80_takes_the_level_where_it_begins(profile: str) -> None:
    # G80, then Z30.: the next cycle mode begins at Z30. and G98 returns there
    text = lines(
        "G90 G54 G17 G21 G94 G80",
        "G00 X0 Y0 Z50.",
        "G99 G81 X10. Y0 Z-10. R2. F100",
        "G80",
        "G00 Z30.",
        "G98 G81 X20. Y0 Z-10. R2. F100",
        "#103=#5003",
        "G80",
        "M30",
    )
    assert final(text, profile)[103] == 30.0


def test_fanuc_lathe_face_cycle_change_keeps_the_initial_level() -> None:
    # 0i-TF: G83 from Z10. (R-5.: the R point at Z5., the bottom Z-20.), then G85 with no G80:
    # the same cycle mode, the initial level still Z10.; G85 feeds out to R and rapids to Z10.
    text = lines(
        "G97 S1000 M03",
        "G00 X0 Z10.",
        "G83 Z-20. R-5. F100",
        "G00 X0 Z30.",  # a G00 ends the cycle mode: the next cycle begins at Z30.
        "G83 Z-20. R-5. F100",
        "G85 X0 Z-10. R-5.",
        "#105=#5002",
        "G80",
        "M30",
    )
    # R-5. from Z30. is Z25.; G85's hole returns to the initial level Z30.
    assert final(text, "fanuc-0i-lathe")[105] == 30.0
