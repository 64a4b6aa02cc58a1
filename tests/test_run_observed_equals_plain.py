"""A run with an observer ends exactly as the same run without one.

The analysis watches its runs through a ``RunObserver`` (machine/observer.py): the machine then
compiles watched blocks and runs ``tracking.run_tracked``, a copy of the plain loop that stamps
each line, and its one-pass plain lines (``straight_runs.run_straight``) stamp them too. Those
loops exist only for speed, so on generated programs, run whole or in the analysis's chunks, they
must stop where the plain loop stops and reach the same status, alarm, block count, variables,
position, moves, output and clock; and the observer hears of each line that ran, once.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cncmacro.machine import Machine, RunObserver, RunStatus
from running import lines, machine
from test_run_plain_lines_fast_path import program as plain_program
from test_run_stepping_and_properties import BUDGET, run_to_end
from test_run_stepping_and_properties import program as macro_program


class Recording(RunObserver):
    """Keeps what it hears of the lines run."""

    def __init__(self) -> None:
        super().__init__()
        self.heard: list[tuple[str, int]] = []

    def first_run(self, file: str, line: int, step: int) -> None:
        self.heard.append((file, line))


def observed(text: str, dialect: str, **settings: object) -> tuple[Machine, Recording]:
    observer = Recording()
    m = machine(text, dialect, max_blocks=BUDGET, **settings)
    # the same program on a machine made with an observer (``machine`` makes a plain one)
    m2 = Machine(m.dialect, m.settings, m.library, observer=observer)
    m2.start(m.frames[0].found)
    return m2, observer


def run_in_chunks(m: Machine, chunk: int) -> list[tuple[object, ...]]:
    """As ``run_to_end``, but at most ``chunk`` blocks at a time, as the analysis runs; where
    each chunk stopped."""
    stops: list[tuple[object, ...]] = []
    while True:
        left = BUDGET - m.blocks
        status = m.run(min(chunk, left) if left > 0 else 1, is_limit=chunk >= left)
        stops.append((status, m.blocks, m.message, [(f.file, f.pc, tuple(f.loops)) for f in m.frames]))
        if status != RunStatus.PAUSED:
            return stops
        m.resume()


def outcome(m: Machine) -> tuple[object, ...]:
    alarm = (m.alarm.number, m.alarm.file, m.alarm.line, m.alarm.message) if m.alarm else None
    p = m.planner
    return (m.status, alarm, m.blocks, m.variables(), list(p.moves), list(m.output), list(p.pos), p.clock,
            dict(p.modal), dict(p.codes))  # fmt: skip


def lines_run(text: str, dialect: str, blocks: int, **settings: object) -> set[tuple[str, int]]:
    """The lines a plain run of ``text`` runs in its first ``blocks`` blocks, one step at a time."""
    m = machine(text, dialect, max_blocks=BUDGET, **settings)
    out = set()
    while m.blocks < blocks and not m.finished:
        out.add((m.frame.file, m.frame.pc))
        if m.step() == RunStatus.PAUSED and m.message is not None:
            m.resume()
    return out


def heard_each_line_once(m: Machine, observer: Recording, text: str, dialect: str, **settings: object) -> None:
    """The observer heard of each line the run ran, once, and stamped just those."""
    ran = lines_run(text, dialect, m.blocks, **settings)
    stamped = {(path, line) for path, stamps in observer.last_run.items() for line, s in enumerate(stamps) if s >= 0}
    assert sorted(observer.heard) == sorted(ran)
    assert stamped == ran


CALLEE = lines("O9003", "#101=#101+1", "G01 X#101 Y1. F100", "X2.", "Y3.", "WHILE[#101 LT 3]DO1", "#101=#101+1",
               "END1", "M99")  # fmt: skip


@pytest.fixture(scope="module")
def callee(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A folder holding O9003, which the generated programs call with M98: a file of its own,
    so that the run goes from file to file (without the folder the call alarms)."""
    folder = tmp_path_factory.mktemp("callee")
    (folder / "O9003.nc").write_text(CALLEE, encoding="utf-8")
    return folder


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(macro_program(), st.sampled_from(["fanuc", "gsk980tdi"]), st.integers(1, 60), st.integers(0, 2))
def test_an_observed_macro_program_ends_as_the_plain_run(
    callee: Path, text: str, dialect: str, chunk: int, calls: int
) -> None:
    if calls == 2:  # called first thing as well
        text = text.replace("O0001\n", "O0001\nM98 P9003\n", 1)
    where = {"folder": callee} if calls else {}
    plain = machine(text, dialect, max_blocks=BUDGET, **where)
    run_to_end(plain)
    whole, observer = observed(text, dialect, **where)
    run_to_end(whole)
    assert outcome(whole) == outcome(plain)
    heard_each_line_once(whole, observer, text, dialect, **where)
    plain = machine(text, dialect, max_blocks=BUDGET, **where)
    chunked, observer = observed(text, dialect, **where)
    assert run_in_chunks(chunked, chunk) == run_in_chunks(plain, chunk)
    assert outcome(chunked) == outcome(plain)
    heard_each_line_once(chunked, observer, text, dialect, **where)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(plain_program(), st.integers(1, 7))
def test_observed_plain_lines_end_as_the_plain_run(case: tuple[str, list[str], str], chunk: int) -> None:
    dialect, body, mode = case
    text = lines("O0001", *body, "M30")
    plain = machine(text, dialect, max_blocks=BUDGET, decimal_point=mode)
    run_to_end(plain)
    whole, observer = observed(text, dialect, decimal_point=mode)
    run_to_end(whole)
    assert outcome(whole) == outcome(plain)
    heard_each_line_once(whole, observer, text, dialect, decimal_point=mode)
    plain = machine(text, dialect, max_blocks=BUDGET, decimal_point=mode)
    chunked, observer = observed(text, dialect, decimal_point=mode)
    assert run_in_chunks(chunked, chunk) == run_in_chunks(plain, chunk)
    assert outcome(chunked) == outcome(plain)
    heard_each_line_once(chunked, observer, text, dialect, decimal_point=mode)


def test_without_an_observer_a_run_is_not_watched() -> None:
    m = machine(lines("#1=1", "M30"))
    assert m.observer is None and not m.watching
    assert m.run() == RunStatus.COMPLETED
