"""Mitsubishi M70/M80's multi-step skip (M700V/M70V programming manual §15.3, "Multi-step Skip
Function; G31.n"): ``G31.1``, ``G31.2`` and ``G31.3`` are codes of the control, each a G31 that
stops where its skip signal comes on; with no [skip] model the signal stays off and the move runs
to its end point, where #5061… read it (docs/semantics.md §8)."""

from __future__ import annotations

from pathlib import Path

from cli_capture import cli, run_json
from running import lines

PROBE = lines("O4001 (cncmacro: dialect=mitsubishi-m70)", "G90 G00 X0 Y0 Z10.", "G31.1 X20. F200.",
              "#101=#5061", "G31.2 Y-15. F100.", "#102=#5062", "G31.3 Z2. F50.", "#103=#5063", "M30")  # fmt: skip


def test_g31_1_to_g31_3_are_the_controls_skip_codes(tmp_path: Path) -> None:
    (tmp_path / "O4001.nc").write_text(PROBE, encoding="utf-8")
    assert cli("check", str(tmp_path / "O4001.nc"))[:2] == (0, "")


def test_each_skips_as_g31_does(tmp_path: Path) -> None:
    result = run_json(tmp_path, PROBE, "O4001.nc")
    skips = [mv for mv in result["moves"] if mv["mode"] == "G31"]
    assert [(mv["line"], mv["to"]["X"], mv["to"]["Y"], mv["to"]["Z"]) for mv in skips] == [
        (3, 20.0, 0.0, 10.0), (5, 20.0, -15.0, 10.0), (7, 20.0, -15.0, 2.0)]  # fmt: skip
    # 20 mm at 200 mm/min, 15 at 100, 8 at 50: 6 + 9 + 9.6 s
    assert [mv["time"] for mv in skips] == [6.0, 9.0, 9.6]
    assert (result["variables"]["101"], result["variables"]["102"], result["variables"]["103"]) == (20.0, -15.0, 2.0)
