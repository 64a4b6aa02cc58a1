"""The toolpath while paused under cutter radius compensation (docs/semantics.md §12,
docs/debugging.md "The toolpath while paused"): the moves the debugger sends carry the tool
centre's path; the last move's path ends on the perpendicular of its end until the next move in
the plane is run, and stepping back puts it back so."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from cncmacro.debugging.breakpoints import Breakpoints
from cncmacro.debugging.history import History
from cncmacro.debugging.stepping import STEP_IN, Stepper
from cncmacro.planner.move_json import move_json
from running import lines, machine

SQUARE = lines(
    "O0001",  # 1
    "G10 L12 P1 R5.",  # 2
    "G90 G17 G00 X-20. Y-20.",  # 3
    "G41 D1 G01 X0 Y0 F100",  # 4
    "Y50.",  # 5
    "X50.",  # 6
    "Y0",  # 7
    "X0",  # 8
    "G40 X-20. Y-20.",  # 9
    "M30",  # 10
)


def stepper_for(tmp_path: Path) -> Stepper:
    (tmp_path / "MAIN.nc").write_text(SQUARE, encoding="utf-8")
    m = machine(SQUARE, folder=tmp_path)
    history = History(interval=2)
    history.reset(m)
    bps = Breakpoints()
    bps.bind(m)
    stepper = Stepper(m, bps, history, lambda _text, _category: None)
    stepper.stop_at_end = True
    return stepper


def at_line(stepper: Stepper) -> int:
    return stepper.machine.frames[-1].pc + 1


def centre_end(move: dict[str, Any]) -> tuple[float, float]:
    last = move["tool_path"]["pieces"][-1]["to"]
    return last["X"], last["Y"]


def toolpath(stepper: Stepper) -> list[dict[str, Any]]:
    m = stepper.machine
    return [move_json(mv, m.dialect.axes) for mv in m.planner.moves]


def test_the_paused_toolpath_carries_the_centre_path_and_stepping_back_restores_it(tmp_path: Path) -> None:
    stepper = stepper_for(tmp_path)
    while at_line(stepper) != 6:
        stepper.run(STEP_IN)
    # paused before X50.: Y50. (line 5) is the last move; nothing after it yet, so its centre ends
    # on the perpendicular of its end, left of +Y at (0,50): (-5,50)
    moves = toolpath(stepper)
    assert [mv["line"] for mv in moves] == [3, 4, 5]
    assert "tool_path" not in moves[0]
    assert math.dist(centre_end(moves[2]), (-5.0, 50.0)) < 0.001
    stepper.run(STEP_IN)
    # X50. run: the corner is known, y = 55 meets x = -5 at (-5,55)
    moves = toolpath(stepper)
    assert math.dist(centre_end(moves[2]), (-5.0, 55.0)) < 0.001
    assert math.dist(centre_end(moves[3]), (50.0, 55.0)) < 0.001  # X50.'s own perpendicular end, for now
    stepper.step_back()
    assert at_line(stepper) == 6
    moves = toolpath(stepper)
    assert len(moves) == 3 and math.dist(centre_end(moves[2]), (-5.0, 50.0)) < 0.001
