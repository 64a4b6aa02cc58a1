"""The debugger going backwards and at the end (docs/design.md "The debugger", docs/debugging.md):
reverse continue stops exactly where the forward run stopped, hit counts included (the hit
number of a visit is the count the forward run had just after it), across many checkpoints;
step back takes hits back; the end of the program is a stop; breakpoints on ``/`` blocks
follow the block delete switch."""

from __future__ import annotations

from pathlib import Path

from cncmacro.debugging.breakpoints import Asked, Breakpoints
from cncmacro.debugging.history import History
from cncmacro.debugging.stepping import CONTINUE, STEP_IN, Stepper, Stop, last_line_run
from running import lines, machine

LOOP = lines(
    "O0001 (LOOP)",  # 1
    "#1=0",  # 2
    "#101=0",  # 3
    "WHILE[#1 LT 30]DO1",  # 4
    "#1=#1+1",  # 5
    "#100=#1*2",  # 6
    "IF[[#1 MOD 5] NE 0]GOTO9",  # 7
    "#101=#101+1",  # 8
    "N9 END1",  # 9
    "M30",  # 10
)


def session(tmp_path: Path, text: str = LOOP, interval: int = 7) -> tuple[Stepper, Breakpoints, str]:
    """A stepper on ``text`` (saved as MAIN.nc) with a short checkpoint interval, so that going
    back crosses many checkpoints; the machine stops at the program's end."""
    path = tmp_path / "MAIN.nc"
    path.write_text(text, encoding="utf-8")
    m = machine(text, folder=tmp_path)
    bps = Breakpoints()
    history = History(interval=interval)
    history.reset(m)
    stepper = Stepper(m, bps, history, lambda _text, _category: None)
    stepper.stop_at_end = True
    bps.bind(m)
    return stepper, bps, str(path)


def on_line(n: int, condition: str | None = None, hit_condition: str | None = None) -> Asked:
    """A line breakpoint on line ``n``, counted from 1 as an editor shows it (``LOOP``'s numbers)."""
    return Asked(n - 1, condition, hit_condition)


def where(stepper: Stepper, stop: Stop) -> tuple[str, int, int, float | None, float | None]:
    m = stepper.machine
    return stop.reason, m.blocks, m.frames[-1].pc + 1, m.L[1], m.C[101]


def forward(stepper: Stepper) -> list[tuple]:
    seen = []
    while True:
        stop = stepper.run(CONTINUE)
        if stop.description and stop.description.startswith("program end"):
            return seen
        seen.append(where(stepper, stop))


def backward(stepper: Stepper) -> list[tuple]:
    seen = []
    while True:
        stop = stepper.reverse()
        if stop.reason == "entry":
            assert stepper.machine.blocks == 0
            return seen
        seen.append(where(stepper, stop))


def test_reverse_continue_stops_where_the_forward_run_stopped_with_hit_counts_and_conditions(tmp_path):
    stepper, bps, path = session(tmp_path)
    bps.set_lines(path, [on_line(6, hit_condition="%4"),
                         on_line(8, condition="#1 GT 12", hit_condition=">=2")])  # fmt: skip
    bps.set_data([Asked("#101", hit_condition="%2")])
    ahead = forward(stepper)
    # line 6 at passes 4, 8, ..., 28; line 8 from its second visit with #1 > 12 (#1 = 20, 25, 30);
    # #101 at its even changes (0 -> 1 is the second: vacant -> 0 was the first)
    assert [(r, pc, i) for r, _b, pc, i, _c in ahead if r == "breakpoint" and pc == 6] == [
        ("breakpoint", 6, float(k)) for k in range(4, 29, 4)
    ]
    assert [i for r, _b, pc, i, _c in ahead if r == "breakpoint" and pc == 8] == [20.0, 25.0, 30.0]
    assert [c for r, *_x, c in ahead if r == "data breakpoint"] == [1.0, 3.0, 5.0]
    assert backward(stepper) == ahead[::-1]


def test_going_back_takes_the_hits_back_so_forward_stops_again_at_the_same_pass(tmp_path):
    stepper, bps, path = session(tmp_path)
    bps.set_lines(path, [on_line(6, hit_condition="%4")])
    first = where(stepper, stepper.run(CONTINUE))
    second = where(stepper, stepper.run(CONTINUE))
    assert (first[3], second[3]) == (4.0, 8.0)
    for _ in range(5):  # back to line 6 in pass 7
        stepper.step_back()
    assert (stepper.machine.frames[-1].pc + 1, stepper.machine.L[1]) == (6, 7)
    assert where(stepper, stepper.run(CONTINUE)) == second
    assert where(stepper, stepper.reverse()) == first


def test_a_step_that_lands_on_a_breakpoint_counts_as_a_hit(tmp_path):
    stepper, bps, path = session(tmp_path)
    bps.set_lines(path, [on_line(6, hit_condition="2")])
    while stepper.machine.frames[-1].pc != 5:  # step in until the first visit of line 6
        stepper.run(STEP_IN)
    assert stepper.machine.L[1] == 1
    assert where(stepper, stepper.run(CONTINUE))[3] == 2.0  # the second visit, not the third


def test_a_breakpoint_set_at_the_end_counts_from_there(tmp_path):
    stepper, bps, path = session(tmp_path)
    end = stepper.run(CONTINUE)
    assert (end.reason, end.description, end.finished) == ("step", "program end (M30)", False)
    end_block = stepper.machine.blocks
    bps.set_lines(path, [on_line(6, hit_condition="1")])
    assert stepper.reverse().reason == "entry"  # its earlier visits have no number
    # back before it was set, it counts from there: forward, the first visit is its first hit
    assert where(stepper, stepper.run(CONTINUE))[2:4] == (6, 1.0)
    assert stepper.run(CONTINUE).description == "program end (M30)"
    made = bps.set_lines(path, [on_line(6)])
    assert made[0].since == end_block
    assert where(stepper, stepper.reverse())[2:4] == (6, 30.0)  # without a hit count: the last visit


def test_a_breakpoint_asked_for_again_keeps_its_count(tmp_path):
    stepper, bps, path = session(tmp_path)
    bps.set_lines(path, [on_line(6, hit_condition="3")])
    assert stepper.run(STEP_IN).reason == "step"
    while stepper.machine.L[1] != 2:
        stepper.run(STEP_IN)
    # the editor sends all of a file's breakpoints whenever one changes
    bps.set_lines(path, [on_line(6, hit_condition="3"), on_line(10)])
    assert where(stepper, stepper.run(CONTINUE))[2:4] == (6, 3.0)


def test_the_end_of_the_program_is_a_stop_and_the_next_run_ends_the_session(tmp_path):
    for text, said in ((lines("#100=1", "M02"), "program end (M02)"), (lines("#100=1", "#101=2"), "program end")):
        stepper, _bps, _path = session(tmp_path, text)
        stop = stepper.run(CONTINUE)
        assert (stop.reason, stop.description, stop.finished) == ("step", said, False)
        assert stepper.machine.C[100] == 1.0
        assert stepper.run(CONTINUE).finished
    stepper, _bps, _path = session(tmp_path, lines("#100=1", "M30"))
    stepper.stop_at_end = False
    assert stepper.run(CONTINUE).finished


def test_a_step_back_from_the_end_of_a_file_without_m30_lands_on_its_last_block(tmp_path):
    # running off the end of the file counts as a block, but there is nothing there to show
    stepper, _bps, _path = session(tmp_path, lines("O0001", "#100=1", "#101=2", "", "(END OF PART)"))
    stop = stepper.run(CONTINUE)
    assert (stop.reason, stop.description) == ("step", "program end")
    stepper.step_back()
    m = stepper.machine
    assert (m.frames[-1].pc + 1, m.C[100], m.C[101]) == (3, 1.0, None)  # before #101=2, not past the end
    stepper.step_back()
    assert (m.frames[-1].pc + 1, m.C[100]) == (2, None)


def test_an_alarm_still_stops_as_an_exception_at_the_end(tmp_path):
    stepper, _bps, _path = session(tmp_path, lines("#100=1", "#3000=5(TOO DEEP)", "M30"))
    stop = stepper.run(CONTINUE)
    assert stop.reason == "exception" and "3005" in (stop.text or "")
    assert stepper.run(CONTINUE).finished


OPTIONAL = lines("O0006", "#100=1", "(NEXT IS OPTIONAL)", "/#100=#100+1", "/2 #101=1", "", "#102=#100", "M30")


def test_1_block_delete_a_breakpoint_on_a_deleted_block_is_not_verified_while_the_switch_is_on(tmp_path):
    path = tmp_path / "O0006.nc"
    path.write_text(OPTIONAL, encoding="utf-8")
    specs = [on_line(3), on_line(4), on_line(5), on_line(6)]
    off = Breakpoints()
    off.bind(machine(OPTIONAL, block_delete=False))
    placed = off.set_lines(str(path), specs)
    assert [(b.verified, b.line) for b in placed] == [(True, 3), (True, 3), (True, 4), (True, 6)]
    on = Breakpoints(locale="zh-CN")
    on.bind(machine(OPTIONAL, block_delete=True))
    made = on.set_lines(str(path), specs)
    assert [(b.verified, b.line) for b in made] == [(True, 6), (False, None), (False, None), (True, 6)]
    assert made[1].message == "此程序段会被跳过：跳段开关已打开"
    # set before the launch (the switch still unknown), placed again when the machine comes
    early = Breakpoints()
    early.set_lines(str(path), specs)
    moved = early.bind(machine(OPTIONAL, block_delete=True))
    assert [(b.asked, b.verified, b.line, b.message) for b in moved] == [
        (2, True, 6, None), (3, False, None, "this block is skipped: block delete is on"),
        (4, False, None, "this block is skipped: block delete is on"),
    ]  # fmt: skip


def test_5_program_end_a_code_from_a_variable_ends_the_run_and_the_debugger_names_it(tmp_path):
    # M#3 with #3=30 is M30 to the run: the end stop says so, the last line run is the M#3 line
    # (line 3), and one step back lands before it, on line 3 again with the run not over.
    stepper, _bps, _path = session(tmp_path, lines("#3=30", "#100=1", "M#3", "#101=2"))
    stop = stepper.run(CONTINUE)
    assert (stop.reason, stop.description) == ("step", "program end (M30)")
    m = stepper.machine
    assert (last_line_run(m) + 1, m.C[100], m.C[101]) == (3, 1.0, None)
    stepper.step_back()
    assert (m.status, m.frames[-1].pc + 1, m.C[100]) == ("paused", 3, 1.0)
