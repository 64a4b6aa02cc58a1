"""docs/semantics.md §9, "Hole data": FANUC clears the hole data at G80 and a G00-G03 (the 0i-MF /
30i-B operator's manuals, "canned cycle for drilling": the hole machining data are cancelled by G80
or a group 01 code). The run keeps Z and R across them and times the hole by them; on `fanuc-0i` and
`fanuc-30i` a hole that drills by a Z or an R given before the cancel is a `cycle-block` warning,
once a canned cycle mode. Haas, Mitsubishi and Mazak: no warning (no source at hand clears Z and R)."""

from __future__ import annotations

from pathlib import Path

import pytest

from analysis_helpers import analyse_files
from running import lines, run

BODY = (
    "G90 G17 G21 G94 G80",
    "G00 X0 Y0 Z10.",
    "G99 G81 X10. Y0 Z-10. R2. F600",  # line 4 (0-based 3)
    "G80",
    "G00 X20.",
    "G99 G81 X30. Y0",  # line 7: Z and R from line 4
    "X40.",  # the same mode: said once
    "G80",
    "G99 G81 X50. Y0 Z-10.",  # line 10: R from line 4
    "G80",
    "G99 G81 X60. Y0 Z-10. R2.",  # line 12: all given
    "G80",
    "M30",
)


def _warnings(tmp_path: Path, profile: str) -> list[tuple[int, str]]:
    found = analyse_files(tmp_path, {"O0001.CNC": lines(f"O0001 (cncmacro: dialect={profile})", *BODY)}, profile)
    return [(d.line, d.message) for d in found if d.code == "cycle-block"]


@pytest.mark.parametrize("profile", ["fanuc-0i", "fanuc-30i"])
def test_a_fanuc_hole_drilled_by_z_or_r_from_before_g80_is_a_warning(tmp_path: Path, profile: str) -> None:
    found = _warnings(tmp_path, profile)
    assert [line for line, _ in found] == [6, 9]
    assert "the Z and R in force were given before the G80" in found[0][1]
    assert "the R in force was given before the G80" in found[1][1]


@pytest.mark.parametrize("profile", ["haas", "mitsubishi-m70", "mazak-eia"])
def test_other_makers_keep_z_and_r_without_a_warning(tmp_path: Path, profile: str) -> None:
    assert _warnings(tmp_path, profile) == []


def test_the_run_still_drills_by_the_kept_z_and_r() -> None:
    # every hole from R2 to Z-10 at F600: 12 mm = 1.2 s, back to R2 12 mm = 0.03 s
    # rapids: Z10 10 mm, first hole 10 + 8 (to R2), X20 10, then 10 mm to each next hole: 4 x 10
    # total rapid 10 + 18 + 10 + 40 = 78 mm = 0.195 s; 5 holes x (1.2 + 0.03) = 6.15 s
    m = run(lines(*BODY), "fanuc-0i")
    assert m.status == "completed", m.alarm
    assert m.planner.clock == pytest.approx(0.195 + 6.15, abs=1e-9)
