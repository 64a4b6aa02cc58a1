"""A lathe's turret indexes only when a T code names another station (docs/semantics.md §9):
``T0100`` after ``T0101`` cancels the offset of the tool in place and ``T0101`` again takes it
back, neither turning the turret, so neither costs a tool change nor starts a tool's part of the
cycle time; ``T0202`` does. Both lathe profiles take 1 s a change; rapids X 12000 mm/min (of the
radius) and Z 15000 on fanuc-0i-lathe, X 6000 and Z 8000 on gsk980tdi."""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_capture import run_json
from running import lines


@pytest.mark.parametrize(("profile", "x_rate"), [("fanuc-0i-lathe", 12000.0), ("gsk980tdi", 6000.0)])
def test_an_offset_change_on_the_same_station_is_no_tool_change(tmp_path: Path, profile: str, x_rate: float) -> None:
    program = lines(f"O0001 (cncmacro: dialect={profile})", "T0101", "G00 X50.", "T0100", "T0101", "G00 X60.",
                    "T0202", "M30")  # fmt: skip
    result = run_json(tmp_path, program, "O0001.nc")
    # the rapids: 25 and then 5 mm of radius along X; two changes of 1 s (T0101 first, T0202)
    rapids = 30 / x_rate * 60
    assert result["cycle"]["seconds"] == pytest.approx(rapids + 2.0)
    tools = [(t["tool"], t["line"]) for t in result["cycle"]["tools"]]
    assert tools == [(101.0, 2), (202.0, 7)]
    assert result["cycle"]["tools"][0]["seconds"] == pytest.approx(1.0 + rapids)
