"""The FANUC alarms of a drilling canned cycle block (docs/semantics.md §9, "Drilling canned
cycles"): PS0044, G27-G30 commanded in canned cycle mode. Texts from the FANUC 0i PS alarm list."""

from __future__ import annotations

import pytest

from running import alarm, final, lines

FANUC_MILLS = ("fanuc-0i", "fanuc-30i")

# ---------------------------------------------------------------------------------------------
# PS0044 "G27-G30 NOT ALLOWED IN FIXED CYC": "One of G27 to G30 is commanded in canned cycle mode"


@pytest.mark.parametrize("profile", FANUC_MILLS)
@pytest.mark.parametrize("code", ["G27", "G28", "G29", "G30"])
def test_g27_to_g30_in_canned_cycle_mode_stop_with_ps0044(profile: str, code: str) -> None:
    text = lines(
        "G90 G54 G17 G21 G94 G80",
        "G00 X0 Y0 Z50.",
        "G99 G81 X10. Y0 Z-10. R2. F100",
        "X20.",
        f"G91 {code} Z0",  # line 5: G81 is still in force (no G80)
        "G90 G80",
        "M30",
    )
    assert alarm(text, profile) == (44, 5)


@pytest.mark.parametrize("profile", FANUC_MILLS)
def test_g28_after_g80_or_a_group_01_code_runs(profile: str) -> None:
    for cancel in ("G80", "G00"):
        text = lines(
            "G90 G54 G17 G21 G94 G80",
            "G00 X0 Y0 Z50.",
            "G99 G81 X10. Y0 Z-10. R2. F100",
            f"{cancel} G91 G28 Z0",  # the same block cancels the cycle first
            "G90",
            "M30",
        )
        final(text, profile)


def test_fanuc_lathe_g28_in_a_drilling_cycle_stops_with_ps0044() -> None:
    # the 0i-TF's drilling cycles G83-G89 are canned cycle mode too (the same PS alarm list)
    text = lines("G97 S1000 M03", "G00 X0 Z10.", "G83 Z-20. R-5. F100", "G28 U0 W0", "G80", "M30")
    assert alarm(text, "fanuc-0i-lathe") == (44, 4)


@pytest.mark.parametrize("profile", ["haas", "mitsubishi-m70", "mazak-eia"])
def test_g28_in_canned_cycle_mode_runs_where_no_source_gives_the_alarm(profile: str) -> None:
    text = lines("G90 G54 G17 G21 G94 G80", "G00 X0 Y0 Z50.", "G99 G81 X10. Y0 Z-10. R2. F100", "G91 G28 Z0", "M30")
    final(text, profile)


# ---------------------------------------------------------------------------------------------
# PS0045 "ADDRESS Q NOT FOUND (G73/G83)": "In a high-speed peck drilling cycle (G73) or peck
# drilling cycle (G83), the amount of each-time cutting is not specified by address Q, or Q0 is
# specified"


@pytest.mark.parametrize("profile", FANUC_MILLS)
@pytest.mark.parametrize("code", ["G73", "G83"])
@pytest.mark.parametrize("q", ["", " Q0"])
def test_peck_drilling_with_no_q_or_q0_stops_with_ps0045(profile: str, code: str, q: str) -> None:
    text = lines("G90 G54 G17 G21 G94 G80", "G00 X0 Y0 Z50.", f"G98 {code} X10. Y0 Z-20. R2.{q} F100", "G80", "M30")
    assert alarm(text, profile) == (45, 3)


@pytest.mark.parametrize("profile", FANUC_MILLS)
def test_peck_q_stays_for_the_cycles_next_holes(profile: str) -> None:
    # Q5. given on the first hole is in force for the second (the hole data are modal)
    text = lines(
        "G90 G54 G17 G21 G94 G80", "G00 X0 Y0 Z50.", "G99 G83 X10. Y0 Z-20. R2. Q5. F100", "X20.", "G80", "M30"
    )
    final(text, profile)


@pytest.mark.parametrize("profile", FANUC_MILLS)
def test_peck_q_of_an_earlier_cycle_mode_is_cleared_by_g80(profile: str) -> None:
    # G80 clears the hole data: the second G83 names no Q of its own
    text = lines(
        "G90 G54 G17 G21 G94 G80",
        "G00 X0 Y0 Z50.",
        "G98 G83 X10. Y0 Z-20. R2. Q5. F100",
        "G80",
        "G98 G83 X20. Y0 Z-20. R2. F100",
        "G80",
        "M30",
    )
    assert alarm(text, profile) == (45, 5)


def test_peck_q_is_kept_when_the_cycle_changes_without_g80() -> None:
    # G73 after G83 with no G80 between: still one canned cycle mode, Q5. still in force
    text = lines(
        "G90 G54 G17 G21 G94 G80", "G00 X0 Y0 Z50.", "G99 G83 X10. Y0 Z-20. R2. Q5. F100", "G73 X20.", "G80", "M30"
    )
    final(text, "fanuc-0i")


@pytest.mark.parametrize("profile", ["haas", "mitsubishi-m70", "mazak-eia"])
def test_peck_drilling_with_no_q_drills_in_one_feed_where_no_source_gives_the_alarm(profile: str) -> None:
    final(lines("G90 G54 G17 G21 G94 G80", "G00 X0 Y0 Z50.", "G98 G83 X10. Y0 Z-20. R2. F100", "G80", "M30"), profile)


def test_fanuc_lathe_g83_with_no_q_drills_in_one_feed() -> None:
    # 0i-TF, "canned cycle for drilling": with no Q the normal drilling cycle is used (no PS0045)
    final(lines("G97 S1000 M03", "G00 X0 Z10.", "G83 Z-20. R-5. F100", "G80", "M30"), "fanuc-0i-lathe")
