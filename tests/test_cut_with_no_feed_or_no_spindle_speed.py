"""A cut with no feed, or per revolution with no spindle speed, takes no time here and stops or
waits on the control: a ``no-feed`` warning, once a run each (docs/semantics.md §10.4, "A cut with
no feed"). FANUC raises PS0011 "feed zero (command)" for a cut at F0; F is modal, so an earlier
program may have left one; the GSK980TDi powers on with the feed of state parameter No.030
(§3.26: "CNC上电时，进给速度为CNC状态参数№.030设定的值")."""

from __future__ import annotations

from pathlib import Path

import pytest

from analysis_helpers import analyse_files
from cli_capture import cli
from running import lines


def _no_feed(tmp_path: Path, profile: str, *body: str, name: str = "O0001.CNC") -> list[tuple[int, str]]:
    """The ``no-feed`` findings of ``body`` run on ``profile``: (0-based line, message)."""
    found = analyse_files(tmp_path, {name: lines(f"O0001 (cncmacro: dialect={profile})", *body)}, profile)
    return [(d.line, d.message) for d in found if d.code == "no-feed"]


def test_a_lathe_cut_with_no_f_in_the_program_is_a_warning_once_that_it_takes_no_time(tmp_path: Path) -> None:
    # G01 Z-10. from Z2 with no F anywhere: 12 mm at F0 = 0 s, and the control alarms (PS0011);
    # the second cut (line 5) is not said again
    found = _no_feed(tmp_path, "fanuc-0i-lathe", "G99 G97 S800 M03", "G00 X20. Z2.", "G01 Z-10.", "X30.",
                     "G00 X50.", "M30")  # fmt: skip
    assert len(found) == 1 and found[0][0] == 3  # the line of the first cut
    assert "no time" in found[0][1] and "alarm 011 feed zero (command)" in found[0][1]
    assert "earlier program" in found[0][1]


def test_a_peck_cycle_with_no_f_is_the_same_warning_on_its_block(tmp_path: Path) -> None:
    # G74 Z-30. Q5000 from Z2: 38 mm of pecks at F0, 0 s
    found = _no_feed(tmp_path, "fanuc-0i-lathe", "G99 G97 S800 M03", "G00 X0 Z2.", "G74 R1.", "G74 Z-30. Q5000",
                     "G00 Z50.", "M30")  # fmt: skip
    assert [line for line, _ in found] == [4]


def test_a_gsk_cut_with_no_f_runs_at_the_power_on_feed_of_its_parameter(tmp_path: Path) -> None:
    found = _no_feed(tmp_path, "gsk980tdi", "G98 S800 M03", "G00 X20. Z2.", "G01 Z-10.", "M30")
    assert len(found) == 1 and found[0][0] == 3
    assert "No.030" in found[0][1] and "alarm" not in found[0][1]


def test_a_feed_per_revolution_or_a_thread_with_no_s_is_a_warning_that_the_axes_wait(tmp_path: Path) -> None:
    # G99 G01 Z-50 F0.2 with no S: 52 mm at 0.2 x 0 = 0 mm/min; the G92 after it is not said again
    found = _no_feed(tmp_path, "gsk980tdi", "G00 X50 Z2", "G99 G01 Z-50 F0.2", "G00 X60 Z2", "G92 X48 Z-30 F2",
                     "M30")  # fmt: skip
    assert len(found) == 1 and found[0][0] == 2
    assert "no spindle speed" in found[0][1] and "wait for the spindle" in found[0][1]


def test_a_thread_with_no_s_is_said_too(tmp_path: Path) -> None:
    found = _no_feed(tmp_path, "fanuc-0i-lathe", "G00 X20. Z2.", "G32 Z-30. F1.5", "M30")
    assert len(found) == 1 and found[0][0] == 2 and "a thread with no spindle speed" in found[0][1]


@pytest.mark.parametrize("profile", ["fanuc-0i", "haas"])
def test_a_mill_cut_with_no_f_is_the_same_warning(tmp_path: Path, profile: str) -> None:
    found = _no_feed(tmp_path, profile, "G90 G54 S1000 M03", "G00 X0 Y0 Z5.", "G01 Z-2.", "X50.", "M30")
    assert [line for line, _ in found] == [3]


def test_a_program_that_gives_f_and_s_has_no_such_finding(tmp_path: Path) -> None:
    assert _no_feed(tmp_path, "fanuc-0i-lathe", "G99 G97 S800 M03", "G00 X20. Z2.", "G01 Z-10. F0.2", "M30") == []
    assert _no_feed(tmp_path, "fanuc-0i", "G00 X0 Y0 Z5.", "G01 Z-2. F100.", "X50.", "M30") == []


def test_a_subprogram_checked_without_its_caller_cuts_at_its_callers_feed(tmp_path: Path) -> None:
    # O0002 returns with M99 and no caller in the folder: its caller gives F
    found = _no_feed(tmp_path, "fanuc-0i-lathe", "G01 Z-10.", "X30.", "M99", name="O0002.CNC")
    assert found == []


def test_the_check_command_shows_it_as_a_warning(tmp_path: Path) -> None:
    path = tmp_path / "O0001.CNC"
    path.write_text(lines("O0001 (cncmacro: dialect=fanuc-0i-lathe)", "G99 G97 S800 M03", "G00 X20. Z2.",
                          "G01 Z-10.", "M30"), encoding="utf-8")  # fmt: skip
    _, out, _ = cli("check", str(path))
    assert "O0001.CNC:4:1: warning:" in out and "[no-feed]" in out
