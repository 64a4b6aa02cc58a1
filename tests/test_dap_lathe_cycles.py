"""The debugger on a lathe's stock removal and finishing cycles (docs/semantics.md §10.2): a
G71 is one step, its shape read without stopping in it; a G70 runs its shape as a level of its
own, which step in enters and where a breakpoint stops; step over runs it to the end.

On both lathe profiles; the stepper runs the machine as the debug adapter does.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from cncmacro.dap.presentation import stack_frames
from cncmacro.debugging.breakpoints import Asked, Breakpoints
from cncmacro.debugging.history import History
from cncmacro.debugging.stepping import CONTINUE, STEP_IN, STEP_OVER, Stepper
from running import lines, machine

LATHES = ["gsk980tdi", "fanuc-0i-lathe"]
PROGRAM = lines(
    "O0001",  # 1
    "G00 X52. Z2.",  # 2
    "G71 U2. R1.",  # 3
    "G71 P10 Q20 U0.5 W0.1 F0.25",  # 4
    "N10 G00 X20.",  # 5
    "G01 Z-20. F0.1",  # 6
    "N20 X52.",  # 7
    "G70 P10 Q20",  # 8
    "M30",  # 9
)


def stepper(tmp_path: Path, dialect: str, breakpoint_lines: tuple[int, ...] = ()) -> Stepper:
    path = tmp_path / "MAIN.nc"
    path.write_text(PROGRAM, encoding="utf-8")
    m = machine(PROGRAM, dialect, folder=tmp_path)
    history = History(interval=4)
    history.reset(m)
    bps = Breakpoints()
    if breakpoint_lines:
        bps.set_lines(str(path), [Asked(n - 1) for n in breakpoint_lines])
    s = Stepper(m, bps, history, lambda _text, _category: None)
    s.stop_at_end = True
    return s


def shown(s: Stepper) -> list[tuple[str, int]]:
    return [(f["name"], f["line"]) for f in stack_frames(s.machine)]


@pytest.mark.parametrize("dialect", LATHES)
def test_10_step_over_a_g71_runs_the_whole_roughing_and_stops_after_its_shape(tmp_path: Path, dialect: str) -> None:
    s = stepper(tmp_path, dialect)
    s.run(STEP_IN)  # G00
    s.run(STEP_IN)  # G71 U R
    assert shown(s) == [("O0001 (main)", 4)]
    s.run(STEP_OVER)  # G71 P Q: the roughing, its shape read
    assert shown(s) == [("O0001 (main)", 8)]
    assert any(mv.pass_of == "G71" for mv in s.machine.planner.moves)


@pytest.mark.parametrize("dialect", LATHES)
def test_10_step_in_on_a_g71_does_not_stop_inside_the_shape_it_reads(tmp_path: Path, dialect: str) -> None:
    s = stepper(tmp_path, dialect)
    for _ in range(3):
        s.run(STEP_IN)
    assert shown(s) == [("O0001 (main)", 8)]


@pytest.mark.parametrize("dialect", LATHES)
def test_10_step_in_on_a_g70_enters_its_shape_and_step_over_finishes_it(tmp_path: Path, dialect: str) -> None:
    s = stepper(tmp_path, dialect)
    for _ in range(3):
        s.run(STEP_IN)  # G00, G71 U R, G71 P Q
    s.run(STEP_IN)  # G70 P Q: into N10
    assert shown(s) == [("O0001 (G70 shape N10–N20)", 5), ("O0001 (main)", 8)]
    s.run(STEP_IN)  # N10
    s.run(STEP_IN)  # G01 Z-20.
    assert shown(s)[0][1] == 7
    s.run(STEP_OVER)  # N20, the last block: the finishing ends, back to A
    assert shown(s) == [("O0001 (main)", 9)]


@pytest.mark.parametrize("dialect", LATHES)
def test_10_a_breakpoint_in_the_shape_stops_only_when_g70_runs_it(tmp_path: Path, dialect: str) -> None:
    s = stepper(tmp_path, dialect, breakpoint_lines=(6,))
    stop = s.run(CONTINUE)
    assert stop.reason == "breakpoint"
    assert shown(s)[0][1] == 6 and len(shown(s)) == 2  # inside the G70's level, not the G71's reading
    assert any(mv.pass_of == "G71" for mv in s.machine.planner.moves)  # the roughing is done already
    stop = s.run(CONTINUE)
    assert stop.reason != "breakpoint"


@pytest.mark.parametrize("dialect", LATHES)
def test_10_step_back_over_a_g71_returns_to_its_block_with_its_passes_undone(tmp_path: Path, dialect: str) -> None:
    s = stepper(tmp_path, dialect)
    for _ in range(3):
        s.run(STEP_IN)  # G00, G71 U R, G71 P Q (the roughing)
    assert shown(s) == [("O0001 (main)", 8)]
    s.step_back()
    assert shown(s) == [("O0001 (main)", 4)]  # the G71 P Q block again, not inside its shape
    assert not any(mv.pass_of == "G71" for mv in s.machine.planner.moves)
    s.run(STEP_IN)
    assert shown(s) == [("O0001 (main)", 8)]
