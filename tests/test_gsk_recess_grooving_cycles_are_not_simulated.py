"""GSK980TDi's recess grooving cycles G74.1 and G75.1 (programming manual §3.23.7, §3.23.8) are
known but their passes are not simulated (docs/semantics.md §10.3): the blocks' words are the
cycle's (X, Z the groove's start, H its depth, D its width, A and B its angles: no axis moves),
the tool ends where the manual says the cycle ends, step ⑩ "刀具快速返回凹槽切削前起点处" (back
at rapid to the start point it had before the cycle), and the run says so once, on the block
that describes the groove, as a `not-simulated` information."""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_capture import cli, run_json
from running import lines

GROOVES = {
    # the manual's own example (§3.23.7) and the same for G75.1
    "G74.1": ("G00 X70 Z10 M3 S500", "G74.1 X66 Z0 P3000 Q5000 H-10 D-20 A45 B60", "G74.1 R0.5"),
    "G75.1": ("G00 X82 Z-20 M3 S500", "G75.1 X82 Z-20 P3000 Q3000 H-10 D-20 A60 B60", "G75.1 R0.5"),
}


@pytest.mark.parametrize("code", GROOVES)
def test_a_recess_grooving_cycle_moves_no_axis_and_leaves_the_tool_at_its_start(tmp_path: Path, code: str) -> None:
    text = lines("O0008 (cncmacro: dialect=gsk980tdi)", *GROOVES[code], "G00 X100 Z50", "M30")
    result = run_json(tmp_path, text, "O0008.CNC")
    moves = result["moves"]
    # the positioning, then the G00 after the cycle straight from the start point: nothing between,
    # and neither C (H was an incremental C) nor B (an axis of its own) ever moves
    assert [mv["line"] for mv in moves] == [2, 5]
    start = moves[0]["to"]
    assert (moves[1]["from"]["X"], moves[1]["from"]["Z"]) == (start["X"], start["Z"])
    assert all(mv["to"].get(axis, 0.0) == 0.0 for mv in moves for axis in ("C", "B"))
    assert result["messages"] == [
        f"{code} is not simulated: the cycle's passes are not drawn or timed, and the tool is left at its start point"
    ]


def test_check_notes_once_that_the_recess_grooving_cycle_is_not_simulated(tmp_path: Path) -> None:
    path = tmp_path / "O0008.CNC"
    path.write_text(lines("O0008 (cncmacro: dialect=gsk980tdi)", *GROOVES["G74.1"], "G00 X100 Z50", "M30"),
                    encoding="utf-8")  # fmt: skip
    _, out, _ = cli("check", str(path))
    assert "O0008.CNC:3:1: information: G74.1 is not simulated" in out and out.count("[not-simulated]") == 1
    _, zh, _ = cli("check", "--locale", "zh-CN", str(path))
    assert "G74.1 未模拟" in zh
