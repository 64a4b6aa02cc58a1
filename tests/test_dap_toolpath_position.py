"""Where a paused run stands on its toolpath (docs/debugging.md "The toolpath while paused"): the
moves of the current block are found by running it and putting the machine back, so nothing is
printed, counted or kept (a lathe cycle that names its shape: every pass it makes); "run to
here" on a move stops before the block that makes it (a drilling cycle's too), going back
across checkpoints for a move behind, and in a loop at the pass that makes it."""

from __future__ import annotations

from pathlib import Path

from cncmacro.debugging.breakpoints import Breakpoints
from cncmacro.debugging.history import History
from cncmacro.debugging.stepping import STEP_IN, Stepper
from cncmacro.debugging.toolpath_position import next_moves, run_to_move
from running import lines, machine

HOLES = lines(
    "O0001 (HOLES)",  # 1
    "#1=0",  # 2
    "G90 G00 X0 Y0 Z10.",  # 3
    "WHILE[#1 LT 4]DO1",  # 4
    "#1=#1+1",  # 5
    "G01 X[#1*10] F100",  # 6
    "DPRNT[PASS*#1[1]]",  # 7
    "END1",  # 8
    "G81 X50. Y0 Z-5. R2.",  # 9
    "G80",  # 10
    "G00 X0 Y0",  # 11
    "M30",  # 12
)


def stepper_for(tmp_path: Path, text: str = HOLES) -> Stepper:
    (tmp_path / "MAIN.nc").write_text(text, encoding="utf-8")
    m = machine(text, folder=tmp_path)
    history = History(interval=5)  # going back crosses checkpoints
    history.reset(m)
    bps = Breakpoints()
    bps.bind(m)
    stepper = Stepper(m, bps, history, lambda _text, _category: None)
    stepper.stop_at_end = True
    return stepper


def line(stepper: Stepper) -> int:
    return stepper.machine.frames[-1].pc + 1


def test_the_current_blocks_moves_are_found_without_running_it_for_good(tmp_path: Path) -> None:
    stepper = stepper_for(tmp_path)
    m = stepper.machine
    while line(stepper) != 6:
        stepper.run(STEP_IN)
    before = (m.blocks, len(m.planner.moves), list(m.output), m.L[1], list(m.planner.pos))
    ahead = next_moves(m)
    assert [(mv.line + 1, mv.end[0]) for mv in ahead] == [(6, 10.0)]
    assert (m.blocks, len(m.planner.moves), list(m.output), m.L[1], list(m.planner.pos)) == before
    while line(stepper) != 7:
        stepper.run(STEP_IN)
    assert next_moves(m) == []  # DPRNT makes no move
    assert m.output == []  # and printed nothing


def test_run_to_a_move_of_a_loop_stops_at_the_pass_that_makes_it(tmp_path: Path) -> None:
    stepper = stepper_for(tmp_path)
    stop = run_to_move(stepper, 3)  # moves: line 3, then line 6 in passes 1, 2, 3, ...
    assert stop.reason == "goto"
    assert (line(stepper), stepper.machine.L[1], len(stepper.machine.planner.moves)) == (6, 3.0, 3)


def test_run_to_the_move_of_a_drilling_cycle_stops_at_the_cycle(tmp_path: Path) -> None:
    stepper = stepper_for(tmp_path)
    stop = run_to_move(stepper, 5)  # after the G00 and the four passes' G01
    assert (stop.reason, line(stepper), len(stepper.machine.planner.moves)) == ("goto", 9, 5)
    assert [mv.mode for mv in next_moves(stepper.machine)] == [81.0]


def test_run_back_to_a_move_behind_crosses_checkpoints(tmp_path: Path) -> None:
    stepper = stepper_for(tmp_path)
    run_to_move(stepper, 6)  # the G00 X0 Y0 of line 11
    assert line(stepper) == 11
    stop = run_to_move(stepper, 2)
    assert (stop.reason, line(stepper), stepper.machine.L[1], len(stepper.machine.planner.moves)) == ("goto", 6, 2.0, 2)
    assert run_to_move(stepper, 6).reason == "goto"  # and forward again, to the same block
    assert line(stepper) == 11


def test_run_to_a_move_past_the_end_stops_at_the_end(tmp_path: Path) -> None:
    stepper = stepper_for(tmp_path)
    stop = run_to_move(stepper, 99)
    assert stop.description is not None and stop.description.startswith("program end")


ROUGH_AND_FINISH = lines(
    "O0500",  # 1
    "G99 G00 X40. Z2.",  # 2
    "G71 U2. R1.",  # 3
    "G71 P10 Q20 U0 W0 F0.2",  # 4
    "N10 G00 X30.",  # 5
    "N20 G01 Z-20.",  # 6
    "G70 P10 Q20",  # 7
    "M30",  # 8
)


def test_the_current_moves_of_a_shape_cycle_are_all_its_passes(tmp_path: Path) -> None:
    (tmp_path / "MAIN.nc").write_text(ROUGH_AND_FINISH, encoding="utf-8")
    m = machine(ROUGH_AND_FINISH, "gsk980tdi", folder=tmp_path)
    stepper = Stepper(m, Breakpoints(), History(interval=5), lambda _text, _category: None)
    while line(stepper) != 4:
        stepper.run(STEP_IN)
    before = (m.blocks, len(m.planner.moves), list(m.planner.pos), len(m.frames))
    ahead = next_moves(m)
    # U2. is a radius: X falls 4 a pass from X40, to X36, X32 and the shape's X30; each pass is
    # in, cut to Z-20., out by R1. (X+2, Z+1) at the feed (GSK §3.23.1 ④) and back to Z2.: 2 x 4
    # moves, then in to X30, the cut along the shape and from its end straight to A (⑧): 11 moves
    assert len(ahead) == 11 and {(mv.line + 1, mv.pass_of) for mv in ahead} == {(4, "G71")}
    assert [mv.end[0] for mv in ahead if mv.mode == 1.0] == [36.0, 38.0, 32.0, 34.0, 30.0]
    assert (m.blocks, len(m.planner.moves), list(m.planner.pos), len(m.frames)) == before
    while line(stepper) != 7:
        stepper.run(STEP_IN)
    # G70 runs the shape as written (lines 5 and 6) and returns to its start point X40. Z2.
    z = m.dialect.axes.index("Z")
    assert [(mv.line + 1, mv.mode, mv.end[0], mv.end[z]) for mv in next_moves(m)] == [
        (5, 0.0, 30.0, 2.0),
        (6, 1.0, 30.0, -20.0),
        (7, 0.0, 40.0, 2.0),
    ]
