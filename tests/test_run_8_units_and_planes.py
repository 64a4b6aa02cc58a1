"""docs/semantics.md §8 "Units" and "Planes", through ``cncmacro run --json`` and ``check``.

G20/G21 belong at the start of a program: a change of the unit after the program has moved is a
``unit-change`` warning (FANUC's manuals say where G20/G21 go and give no alarm). A G20 program's
path is reported in inches, with the unit named. G17/G18/G19 decide the plane an arc turns in:
G18 Z then X (seen from +Y), G19 Y then Z (seen from +X).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from cli_capture import cli, run_json
from running import lines, run


def unit_notes(m) -> list[tuple[int, str | None]]:  # type: ignore[no-untyped-def]
    return [(n.line, n.subject) for n in m.notes if n.kind == "units"]


def test_8_unit_change_after_a_move_is_a_note_on_its_line() -> None:
    m = run(lines("O0001", "G21 G90 G00 X0 Y0", "G01 X10. F100", "G20", "G01 X1.", "M30"))
    assert m.status == "completed", m.alarm
    assert unit_notes(m) == [(3, "unit-change")]


def test_8_unit_change_at_the_start_or_to_the_unit_in_force_is_no_finding() -> None:
    # G20 before any move; a G20 again after the moves changes nothing
    m = run(lines("O0001", "G20", "G90 G00 X0 Y0", "G01 X1. F10.", "G20 G01 X2.", "M30"))
    assert unit_notes(m) == []


def test_8_unit_change_is_a_warning_of_check_on_the_right_line(tmp_path: Path) -> None:
    path = tmp_path / "MAIN.nc"
    path.write_text(lines("O0001", "G21 G90 G00 X0 Y0", "G01 X10. F100", "G20", "G01 X1.", "M30"), encoding="utf-8")
    code, out, _ = cli("check", "--format", "json", str(path))
    found = [(d["line"], d["severity"], d["code"]) for d in json.loads(out)]
    assert code == 0  # a warning only
    assert found == [(4, "warning", "unit-change")]


def test_8_units_an_inch_program_names_its_unit_in_run_text_and_json(tmp_path: Path) -> None:
    # G20: X0 -> X1. at F10. is 1 in; G02 X3. R1. is a half circle of 1 in radius, π in; 1 + π =
    # 4.1416 in cut (4.1 in shown); the rapid back X3. -> X0 is 3 in
    text = lines("O1002", "G20 G90 G17", "G00 X0 Y0", "G01 X1. F10.", "G02 X3. Y0 R1.", "G00 X0 Y0", "M30")
    cycle = run_json(tmp_path, text)["cycle"]
    assert cycle["unit"] == "in"
    assert cycle["cut"] == pytest.approx(1.0 + math.pi) and cycle["rapid"] == pytest.approx(3.0)
    # time: 4.1416 in at 10 in/min = 24.850 s; the rapid 76.2 mm at 24000 mm/min = 0.1905 s
    assert cycle["seconds"] == pytest.approx(24.850 + 0.1905, abs=0.001)
    assert cycle["text"] == "≈ 25 s · 4.1 in cut · 3.0 in rapid"
    (tmp_path / "MAIN.nc").write_text(text, encoding="utf-8")
    code, out, _ = cli("run", str(tmp_path / "MAIN.nc"))
    assert code == 0 and "cycle time O1002: ≈ 25 s · 4.1 in cut · 3.0 in rapid" in out


def test_8_units_a_metric_program_names_mm(tmp_path: Path) -> None:
    cycle = run_json(tmp_path, lines("O1003", "G21 G90 G00 X0", "G01 X10. F100", "M30"))["cycle"]
    assert (cycle["unit"], cycle["cut"]) == ("mm", pytest.approx(10.0))


def test_8_planes_g18_arc_turns_in_z_x(tmp_path: Path) -> None:
    # G18, G02 from X0 Z0 to X10. Z10. with R10.: seen from +Y with Z to the right and X up, the
    # clockwise quarter goes round Z10. X0 (start at 180°, end at 90°); 10·π/2 = 15.708 mm at
    # F100: 9.425 s
    text = lines("O1004", "G21 G90 G18", "G00 X0 Y0 Z0", "G02 X10. Z10. R10. F100", "M30")
    out = run_json(tmp_path, text)
    arc = out["moves"][-1]
    assert arc["plane"] == ["Z", "X"] and arc["clockwise"] is True
    assert arc["to"] == {"X": 10.0, "Y": 0.0, "Z": 10.0, "A": 0.0}
    assert arc["centre"] == {"X": 0.0, "Y": 0.0, "Z": 10.0, "A": 0.0}
    assert out["cycle"]["cut"] == pytest.approx(5.0 * math.pi)
    assert arc["time"] == pytest.approx(5.0 * math.pi / 100.0 * 60.0)


def test_8_planes_g19_arc_turns_in_y_z(tmp_path: Path) -> None:
    # G19, G03 from Y0 Z0 to Y10. Z10. with J0 K10.: centre Y0 Z10.; seen from +X with Y to the
    # right and Z up the start is below the centre (-90°) and the end right of it (0°):
    # counterclockwise, a quarter of radius 10, 15.708 mm; at F100 9.425 s
    text = lines("O1005", "G21 G90 G19", "G00 X0 Y0 Z0", "G03 Y10. Z10. J0 K10. F100", "M30")
    out = run_json(tmp_path, text)
    arc = out["moves"][-1]
    assert arc["plane"] == ["Y", "Z"] and arc["clockwise"] is False
    assert arc["to"] == {"X": 0.0, "Y": 10.0, "Z": 10.0, "A": 0.0}
    assert arc["centre"] == {"X": 0.0, "Y": 0.0, "Z": 10.0, "A": 0.0}
    assert out["cycle"]["cut"] == pytest.approx(5.0 * math.pi)
    assert arc["time"] == pytest.approx(5.0 * math.pi / 100.0 * 60.0)


def test_8_planes_the_same_words_in_g17_turn_in_x_y(tmp_path: Path) -> None:
    # the G18 block's X10. Z10. R10. under G17: X and Y make the plane, from X0 Y0 to X10. Y0 with
    # R10. (Z10. is a helical rise): the centre X5. Y-8.660 (G02 R+ lies right of the chord)
    text = lines("O1006", "G21 G90 G17", "G00 X0 Y0 Z0", "G02 X10. Z10. R10. F100", "M30")
    arc = run_json(tmp_path, text)["moves"][-1]
    assert arc["plane"] == ["X", "Y"]
    assert arc["centre"]["X"] == pytest.approx(5.0) and arc["centre"]["Y"] == pytest.approx(-math.sqrt(75.0))
