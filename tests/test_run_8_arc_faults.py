"""docs/semantics.md §8 "Arcs": an arc the control cannot cut as written.

I, J, K whose end point is off the start's circle by more than the arc tolerance (0.02 mm unless
the machine file's ``arc_tolerance`` says otherwise) is FANUC's alarm 20 (PS0020 "over tolerance
of radius"); on Haas and the GSK980TDi, whose manuals at hand give no alarm for it, the run notes
it and goes on. An R shorter than half the chord and an R arc whose end is its start are notes
(warnings) on every profile. Every path an arc line takes (the one-pass run of plain lines, the
compiled plain line, the general block) finds the same, on the arc's own line. Fanuc axes are
X Y Z A.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from cli_capture import cli, run_json
from cncmacro.dialects.alarms import ARC_RADIUS
from running import lines, run


def arc_notes(m) -> list[tuple[int, str | None]]:  # type: ignore[no-untyped-def]
    """(0-based line, subject) of each note about an arc."""
    return [(n.line, n.subject) for n in m.notes if n.kind == "arc"]


@pytest.mark.parametrize("dialect", ["fanuc", "fanuc-30i"])
def test_8_arc_radius_i_j_end_off_the_circle_is_alarm_20_on_fanuc(dialect: str) -> None:
    # from X0 Y0, I10.1 puts the centre at X10.1 Y0: the start is 10.1 from it, the end X20. is
    # 20 - 10.1 = 9.9 from it; 10.1 - 9.9 = 0.2 > 0.02: alarm 20 on line 3 (0-based 2)
    m = run(lines("O0001", "G90 G17 G00 X0 Y0", "G03 X20. Y0 I10.1 J0 F100", "M30"), dialect)
    assert m.status == "alarm"
    assert (m.alarm.number, m.alarm.line) == (ARC_RADIUS, 2)
    assert "0.200 off its circle" in m.alarm.message


@pytest.mark.parametrize("dialect", ["haas", "gsk980tdi"])
def test_8_arc_radius_i_j_end_off_the_circle_is_a_note_where_no_alarm_is_documented(dialect: str) -> None:
    # G18 Z-X plane (both profiles have X and Z); from X0 Z0, K10.1 puts the centre at Z10.1:
    # the start is 10.1 from it, the end Z20. is 9.9 (on gsk980tdi X is a diameter, X0 both ends)
    m = run(lines("O0001", "G18 G00 X0 Z0", "G03 X0 Z20. K10.1 I0 F100", "M30"), dialect)
    assert m.status == "completed", m.alarm
    assert arc_notes(m) == [(2, "arc-radius")]


def test_8_arc_radius_within_the_tolerance_is_cut_without_a_finding() -> None:
    # a CAM end point rounded to 0.001: centre X10. Y0, end X10.007 Y10.  -> radius sqrt(0.007² + 10²)
    # = 10.0000025, 0.0000025 from the start's 10: far inside 0.02
    m = run(lines("O0001", "G90 G00 X0 Y0", "G02 X10.007 Y10. I10. J0 F100", "M30"))
    assert m.status == "completed", m.alarm
    assert arc_notes(m) == []


def test_8_arc_radius_the_machine_files_arc_tolerance_decides() -> None:
    # the same 0.2 mm off: within arc_tolerance = 0.5; arc_tolerance = 0 checks nothing (parameter 3410 = 0)
    text = lines("O0001", "G90 G17 G00 X0 Y0", "G03 X20. Y0 I10.1 J0 F100", "M30")
    assert run(text, arc_tolerance=0.5).status == "completed"
    assert run(text, arc_tolerance=0.0).status == "completed"
    assert run(text, arc_tolerance=0.1).status == "alarm"


def test_8_arc_radius_under_g20_the_tolerance_is_taken_in_inches() -> None:
    # G20: the end is 0.0005 in (0.0127 mm) off, inside 0.02 mm; then 0.001 in (0.0254 mm), beyond
    # (from X0, I0.5 puts the centre at X0.5: the start 0.5 from it, the end X1.0005 0.5005)
    inside = run(lines("O0001", "G20 G90 G00 X0 Y0", "G03 X1.0005 Y0 I0.5 J0 F10.", "M30"))
    assert inside.status == "completed", inside.alarm
    beyond = run(lines("O0001", "G20 G90 G00 X0 Y0", "G03 X1.001 Y0 I0.5 J0 F10.", "M30"))
    assert (beyond.alarm.number, beyond.alarm.line) == (ARC_RADIUS, 2)


def test_8_arc_radius_in_a_run_of_plain_lines_alarms_on_its_own_line() -> None:
    # a CAM run of plain moves (the one-pass path) with a bad arc as its sixth line: the alarm is on
    # that line (0-based 6), and the moves before it are all there (G00 and four G01, the arc not)
    m = run(lines("O0001", "G90 G17 G00 X0 Y0", "G01 X1. F100", "X2.", "X3.", "X0",
                  "G03 X20. Y0 I10.1 J0", "X5.", "M30"))  # fmt: skip
    assert (m.alarm.number, m.alarm.line) == (ARC_RADIUS, 6)
    assert [mv.line for mv in m.planner.moves] == [1, 2, 3, 4, 5]


def test_8_arc_short_radius_r_below_half_the_chord_is_a_note_and_a_half_circle() -> None:
    # G02 X50. Y0 R10. from X0 Y0: the chord is 50, half of it 25 > R10 by 15: a note; the run
    # draws the half circle about the chord's midpoint X25. Y0, 25·π = 78.540 mm long
    m = run(lines("O0001", "G90 G17 G00 X0 Y0", "G02 X50. Y0 R10. F100", "M30"))
    assert m.status == "completed", m.alarm
    assert arc_notes(m) == [(2, "arc-short-radius")]
    arc = m.planner.moves[-1]
    assert arc.centre == (25.0, 0.0, 0.0, 0.0)
    assert m.planner.cut_length == pytest.approx(25.0 * math.pi)


def test_8_arc_short_radius_within_the_tolerance_is_no_finding() -> None:
    # R24.99 for a chord of 50: 0.01 short, inside 0.02 (an exact half circle rounded by a post)
    m = run(lines("O0001", "G90 G17 G00 X0 Y0", "G02 X50. Y0 R24.99 F100", "M30"))
    assert arc_notes(m) == []


@pytest.mark.parametrize("dialect", ["fanuc", "haas", "fanuc-30i"])
def test_8_arc_r_full_circle_r_with_the_end_at_the_start_is_a_note_and_no_motion(dialect: str) -> None:
    # G02 X10. Y0 R5. from X10. Y0, and G02 R5. with no axis word: an arc of 0° each, nothing moves
    m = run(lines("O0001", "G90 G17 G00 X10. Y0", "G02 X10. Y0 R5. F100", "G02 R5.", "M30"), dialect)
    assert m.status == "completed", m.alarm
    assert arc_notes(m) == [(2, "arc-r-full-circle"), (3, "arc-r-full-circle")]
    assert m.planner.cut_length == 0.0  # the rapid to X10. is the only path
    assert all(mv.start == mv.end for mv in m.planner.moves if mv.mode == 2.0)


def test_8_arc_a_good_i_j_full_circle_is_no_finding() -> None:
    # I-10. from X10. back to X10.: the end is 10 from the centre like the start, 20·π mm cut
    m = run(lines("O0001", "G90 G00 X10. Y0", "G02 X10. Y0 I-10. F100", "M30"))
    assert arc_notes(m) == [] and m.status == "completed"
    assert m.planner.cut_length == pytest.approx(20.0 * math.pi)


@pytest.mark.parametrize(("dialect", "exit_code", "severity"), [("fanuc-0i", 1, "error"), ("haas", 0, "warning")])
def test_8_arc_findings_through_check_on_their_lines(
    tmp_path: Path, dialect: str, exit_code: int, severity: str
) -> None:
    # line 3 (1-based): R10. for a chord of 50; line 4: I10.1 off its circle by 0.2
    path = tmp_path / "MAIN.nc"
    path.write_text(lines("O0001", "G90 G17 G00 X0 Y0", "G02 X50. Y0 R10. F100", "G03 X70. Y0 I10.1 J0", "M30"))
    code, out, _ = cli("check", "--format", "json", "--dialect", dialect, str(path))
    found = [(d["line"], d["severity"], d["code"]) for d in json.loads(out) if d["code"] != "not-executed"]
    assert code == exit_code
    assert found == [(3, "warning", "arc-short-radius"), (4, severity, "arc-radius")]


def test_8_arc_short_radius_through_run_json_draws_the_half_circle(tmp_path: Path) -> None:
    # the half circle about X25. Y0: 25·π = 78.540 mm at F100, 47.124 s
    out = run_json(tmp_path, lines("O0001", "G90 G17 G00 X0 Y0", "G02 X50. Y0 R10. F100", "M30"))
    arc = out["moves"][-1]
    assert arc["centre"] == {"X": 25.0, "Y": 0.0, "Z": 0.0, "A": 0.0}
    assert arc["time"] == pytest.approx(25.0 * math.pi / 100.0 * 60.0)


def test_8_arc_radius_the_machine_file_sets_the_tolerance(tmp_path: Path) -> None:
    # the 0.2 mm of the first test, within arc_tolerance = 0.5: the run completes and cuts the
    # half turn about X10.1 (the centre I gives) as a spiral from radius 10.1 to 9.9, timed at the
    # mean radius 10: 10·π = 31.416 mm
    text = lines("O0001", "G90 G17 G00 X0 Y0", "G03 X20. Y0 I10.1 J0 F100", "M30")
    out = run_json(tmp_path, text, machine_file="arc_tolerance = 0.5\n")
    assert out["status"] == "completed" and out["cycle"]["cut"] == pytest.approx(10.0 * math.pi)


@pytest.mark.parametrize("value", ['"fine"', "-0.1", "true", "5"])
def test_8_arc_radius_a_bad_arc_tolerance_gets_a_clear_message(tmp_path: Path, value: str) -> None:
    (tmp_path / ".cncmacro.toml").write_text(f"arc_tolerance = {value}\n", encoding="utf-8")
    path = tmp_path / "MAIN.nc"
    path.write_text(lines("O0001", "G00 X0", "M30"), encoding="utf-8")
    code, _, err = cli("run", str(path))
    assert code == 2
    assert "'arc_tolerance' must be a number of mm from 0 to 1" in err
