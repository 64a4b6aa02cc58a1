"""The stepping API (one block at a time, run to a predicate, frames, snapshots) and the
interpreter's properties over generated programs: every run ends as completed, alarm or
limit within its budget, and a snapshot restored then continued equals an uninterrupted run."""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cncmacro.machine import Machine
from running import lines, machine
from strategies import line as any_line

CALLING = lines(
    "O0001",
    "#1=1",
    "G65 P9001 A5",
    "#2=2",
    "M30",
    "O9001",
    "#100=#1",
    "M99",
)


def test_step_runs_one_block_and_frames_show_the_call():
    m = machine(CALLING)
    assert m.frame.pc == 1  # the O header is line 0
    assert m.step() == "paused" and m.L[1] == 1 and m.frame.pc == 2
    m.step()  # the G65 block: now inside O9001, level 1
    assert len(m.frames) == 2 and m.frame.name == "O9001" and m.frame.macro_level == 1
    assert m.frame.pc == 6 and m.frame.letters == {1: "A"} and m.L[1] == 5
    m.step()
    m.step()  # M99
    assert len(m.frames) == 1 and m.frame.pc == 3 and m.L[1] == 1
    assert m.run() == "completed" and m.C[100] == 5 and m.blocks == 6


def test_run_until_a_predicate():
    m = machine(lines("#1=0", "WHILE[#1 LT 100]DO1", "#1=#1+1", "END1", "M30"))
    assert m.run_until(lambda mm: mm.L[1] == 42) == "paused"
    assert m.L[1] == 42 and m.frame.pc == 3
    assert m.run() == "completed" and m.L[1] == 100


def test_read_and_write_any_variable_while_stopped():
    m = machine(lines("#1=1", "#2=#1+#100", "M30"))
    m.step()
    m.write(100, 41.0)
    m.write(1, 1.5)
    assert m.read(100) == 41 and m.read(5001) == 0
    m.run()
    assert m.L[2] == 42.5


def test_a_budget_and_cancellation():
    m = machine(lines("N1 #1=#1+1", "GOTO 1"), max_blocks=1_000)
    assert m.run() == "limit" and m.blocks == 1000
    m = machine(lines("N1 #1=#1+1", "GOTO 1"), max_blocks=10**9)
    m.cancel()
    assert m.run() == "stopped" and m.blocks < 10_000


def test_snapshot_restore_rewinds_everything():
    m = machine(lines("G90 G00 X1", "#100=1", "G00 X2", "#100=2", "DPRNT[DONE]", "M30"))
    m.step()
    snap = m.snapshot()
    m.run()
    assert m.C[100] == 2 and len(m.planner.moves) == 2 and m.output == ["DONE"] and m.status == "completed"
    m.restore(snap)
    assert (
        m.C[100] is None and len(m.planner.moves) == 1 and m.output == [] and m.planner.pos[0] == 1 and m.frame.pc == 1
    )
    m.run()
    assert m.C[100] == 2 and len(m.planner.moves) == 2


def outcome(m: Machine) -> tuple[object, ...]:
    alarm = (m.alarm.number, m.alarm.line, m.alarm.message) if m.alarm else None
    return (m.status, alarm, m.blocks, m.variables(), list(m.planner.moves), list(m.output), m.planner.pos)


# ---------------------------------------------------------------- generated programs

SMALL_VAR = st.sampled_from(["#1", "#2", "#3", "#24", "#100", "#101", "#500", "#[#1]", "#5001", "#4001"])
SMALL_NUM = st.integers(-5, 12).map(str) | st.sampled_from(["0.5", "-2.5", "100", ".1"])
OPERAND = SMALL_VAR | SMALL_NUM


@st.composite
def small_expr(draw) -> str:
    parts = [draw(OPERAND)]
    for _ in range(draw(st.integers(0, 3))):
        parts.append(draw(st.sampled_from(["+", "-", "*", "/", "MOD", "AND"])))
        parts.append(draw(OPERAND))
    text = " ".join(parts)
    if draw(st.booleans()):
        text = f"{draw(st.sampled_from(['ABS', 'ROUND', 'FIX', 'SQRT', 'SIN']))}[{text}]"
    return text


@st.composite
def program_line(draw) -> str:
    label = f"N{draw(st.integers(1, 6))} " if draw(st.integers(0, 4)) == 0 else ""
    kind = draw(st.integers(0, 14))
    cond = f"[{draw(OPERAND)} {draw(st.sampled_from(['LT', 'GT', 'EQ', 'NE', 'GE', 'LE']))} {draw(OPERAND)}]"
    body = {
        0: lambda: f"{draw(SMALL_VAR)}={draw(small_expr())}",
        1: lambda: f"{draw(SMALL_VAR)}={draw(small_expr())}",
        2: lambda: f"IF{cond} GOTO {draw(st.integers(1, 7))}",
        3: lambda: f"IF{cond} THEN #2=#2+1",
        4: lambda: f"WHILE{cond} DO{draw(st.integers(1, 3))}",
        5: lambda: f"END{draw(st.integers(1, 3))}",
        6: lambda: f"G65 P9001 A{draw(st.integers(0, 3))} L{draw(st.integers(0, 3))}",
        7: lambda: f"M98 P{draw(st.sampled_from(['9002', '20040', '9003']))}",
        8: lambda: f"G0{draw(st.integers(0, 1))} X{draw(OPERAND)} Y{draw(OPERAND)} F100",
        9: lambda: f"G66 P9001 A1\nG01 X{draw(OPERAND)}\nG67",
        10: lambda: draw(any_line()),
        11: lambda: f"GOTO {draw(st.integers(1, 7))}",
        12: lambda: "#3006=1(STOP)" if draw(st.booleans()) else "M00",
        13: lambda: "M99",
        14: lambda: "#3000=1(USER)" if draw(st.integers(0, 3)) == 0 else "M30",
    }[kind]()
    return label + body


@st.composite
def program(draw) -> str:
    main = draw(st.lists(program_line(), min_size=1, max_size=14))
    sub = draw(st.lists(program_line(), min_size=0, max_size=5))
    return lines("O0001", *main, "M30", "O9001", *sub, "M99", "O9002", "#101=#101+1", "M99")


BUDGET = 3_000


def run_to_end(m: Machine) -> str:
    while m.run(BUDGET - m.blocks if m.blocks < BUDGET else 1) == "paused":
        m.resume()
    return m.status


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program(), st.sampled_from(["fanuc", "gsk980tdi"]))
def test_every_generated_program_ends_within_its_budget(text, dialect):
    m = machine(text, dialect, max_blocks=BUDGET)
    status = run_to_end(m)
    assert status in ("completed", "alarm", "limit")
    assert m.blocks <= BUDGET + 1
    if status == "alarm":
        assert m.alarm is not None and m.alarm.number > 0 and m.alarm.message


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program(), st.sampled_from(["fanuc", "gsk980tdi"]), st.integers(0, 40))
def test_snapshot_restore_continue_equals_an_uninterrupted_run(text, dialect, at):
    whole = machine(text, dialect, max_blocks=BUDGET)
    run_to_end(whole)

    m = machine(text, dialect, max_blocks=BUDGET)
    for _ in range(at):
        if m.step() != "paused":
            break
        if m.message is not None:
            m.resume()
    snap = m.snapshot()
    run_to_end(m)
    assert outcome(m) == outcome(whole)
    m.restore(snap)
    run_to_end(m)
    assert outcome(m) == outcome(whole)
