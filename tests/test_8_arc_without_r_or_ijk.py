"""docs/semantics.md §8 "Arcs": a G02/G03 block that moves in its plane with neither R nor an
offset word of the plane. FANUC's PS alarm list: PS0022 "R OR I,J,K COMMAND NOT FOUND", "The
command for circular interpolation lacks arc radius R or coordinate I, J, or K of the distance
between the start point to the center of the arc". The FANUC profiles stop there; the others cut
the block as a straight line, as before (no source at hand gives them the alarm)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from cli_capture import cli
from running import alarm, final, lines, run

FANUC_MILLS = ("fanuc-0i", "fanuc-30i")
START = ("G90 G54 G17 G21 G94", "G00 X0 Y0 Z0")


@pytest.mark.parametrize("profile", FANUC_MILLS)
def test_an_arc_with_no_r_or_ijk_that_moves_in_the_plane_stops_with_ps0022(profile: str) -> None:
    assert alarm(lines(*START, "G02 X20. Y0 F200", "M30"), profile) == (22, 3)


@pytest.mark.parametrize("profile", FANUC_MILLS)
def test_a_modal_arc_block_with_no_r_or_ijk_stops_with_ps0022(profile: str) -> None:
    # line 3 is a good half circle (R10. over a chord of 20); line 4 is G02 again by the modal group
    assert alarm(lines(*START, "G02 X20. Y0 R10. F200", "X40.", "M30"), profile) == (22, 4)


@pytest.mark.parametrize("profile", FANUC_MILLS)
def test_a_modal_arc_block_after_plain_lines_stops_with_ps0022(profile: str) -> None:
    # plain lines run a pass of their own (machine/straight_runs.py): the arc line is judged too
    text = lines(*START, "G01 X5. F200", "X10.", "G02 X20. Y10.", "M30")
    assert alarm(text, profile) == (22, 5)


def test_fanuc_lathe_arc_with_no_r_or_ik_stops_with_ps0022() -> None:
    text = lines("G97 S1000 M03", "G00 X20. Z0", "G02 X40. Z-10. F0.2", "M30")
    assert alarm(text, "fanuc-0i-lathe") == (22, 3)


@pytest.mark.parametrize("profile", FANUC_MILLS)
def test_an_arc_block_that_moves_only_the_normal_axis_or_nothing_is_no_alarm(profile: str) -> None:
    # under modal G02: Z-5. moves no axis of the plane (the manual gives no alarm for it: the run
    # moves Z straight down), F300 moves nothing at all
    m = run(lines(*START, "G02 X20. Y0 R10. F200", "Z-5.", "F300", "#100=#5003", "M30"), profile)
    assert m.status == "completed", m.alarm
    assert m.variables()[100] == -5.0


@pytest.mark.parametrize("profile", ["haas", "mitsubishi-m70", "mazak-eia"])
def test_an_arc_with_no_r_or_ijk_is_cut_straight_where_no_source_gives_the_alarm(profile: str) -> None:
    got = final(lines(*START, "G02 X20. Y0 F200", "#100=#5001", "M30"), profile)
    assert got[100] == 20.0


def test_gsk_arc_with_no_r_or_ik_is_cut_straight() -> None:
    # the GSK980TDi reads Z at #5003 (its #5002 is Y)
    got = final(lines("G00 X20. Z0", "G02 X40. Z-10. F100", "#100=#5003", "M30"), "gsk980tdi")
    assert got[100] == -10.0


def test_an_arc_with_no_r_or_ijk_is_an_arc_centre_error_through_check(tmp_path: Path) -> None:
    path = tmp_path / "MAIN.nc"
    path.write_text(lines("O0001", *START, "G02 X20. Y0 F200", "M30"))
    code, out, _ = cli("check", "--format", "json", "--dialect", "fanuc-0i", str(path))
    found = [(d["line"], d["severity"], d["code"]) for d in json.loads(out) if d["code"] != "not-executed"]
    assert code == 1
    assert found == [(4, "error", "arc-centre")]
