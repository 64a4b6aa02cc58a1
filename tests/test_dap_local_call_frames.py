"""The debugger on a local subprogram call (Haas ``M97 P n``, docs/semantics.md §5 "M97 local
subprogram call"): stepping into the M97 shows a stack frame of its own for the local
subprogram, named like an M98 level; step over runs it to completion and step out leaves it.

The stepper runs a machine whose dialect is ``fanuc`` with the switch on
(``running.haas_switched``), so that the switch is what these test; a debug session of a
``haas`` program launched through the adapter and a DAP client is in tests/dap/haas.test.js.
"""

from __future__ import annotations

from pathlib import Path

from cncmacro.dap.presentation import stack_frames
from cncmacro.debugging.breakpoints import Breakpoints
from cncmacro.debugging.history import History
from cncmacro.debugging.stepping import STEP_IN, STEP_OUT, STEP_OVER, Stepper
from running import haas_switched, lines, machine

PROGRAM = lines(
    "O0011",  # 1
    "#100=0",  # 2
    "M97 P1000",  # 3
    "#101=#100",  # 4
    "M30",  # 5
    "N1000 #100=#100+1",  # 6
    "G01 X1. F100",  # 7
    "M99",  # 8
)


def stepper(tmp_path: Path) -> Stepper:
    path = tmp_path / "MAIN.nc"
    path.write_text(PROGRAM, encoding="utf-8")
    m = machine(PROGRAM, haas_switched(), folder=tmp_path)
    history = History(interval=4)
    history.reset(m)
    s = Stepper(m, Breakpoints(), history, lambda _text, _category: None)
    s.stop_at_end = True
    return s


def shown(s: Stepper) -> list[tuple[str, int]]:
    return [(f["name"], f["line"]) for f in stack_frames(s.machine)]


def test_5_stepping_into_m97_shows_a_frame_for_the_local_subprogram(tmp_path: Path) -> None:
    s = stepper(tmp_path)
    s.run(STEP_IN)  # #100=0
    assert shown(s) == [("O0011 (main)", 3)]
    s.run(STEP_IN)  # M97 P1000
    assert shown(s) == [("O0011 (M97, main's locals)", 6), ("O0011 (main)", 3)]
    s.run(STEP_OUT)  # past the M99
    assert shown(s) == [("O0011 (main)", 4)]
    assert s.machine.read(100) == 1


def test_5_step_over_an_m97_runs_it_to_completion(tmp_path: Path) -> None:
    s = stepper(tmp_path)
    s.run(STEP_IN)
    s.run(STEP_OVER)  # M97 P1000 and its three blocks
    assert shown(s) == [("O0011 (main)", 4)]
    assert s.machine.read(100) == 1 and [mv.line for mv in s.machine.planner.moves] == [6]
