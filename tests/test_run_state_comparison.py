"""docs/design.md "How the analysis stays incremental": two machine states are the same when every
part that can change what a run does next is equal (``machine.tracking.same_state``), which is
when an analysis run resumed after an edit may take over the rest of the earlier run."""

from __future__ import annotations

from cncmacro.library.machine_file import MachineSettings
from cncmacro.machine import Machine
from cncmacro.machine.tracking import same_state

LINES = ["O0001", "#1=2", "#100=0", "G01 X5. Y1. F100.", "WHILE[#1 GT 0] DO1", "#1=#1-1", "END1", "M30"]


def _machine(tmp_path) -> Machine:
    m = Machine("fanuc", MachineSettings(date=20261122, time=80000))
    m.start_file(str(tmp_path / "O0001.nc"), "\n".join(LINES))
    m.run(4, is_limit=False)
    return m


def test_2_values_the_same_run_restored_has_the_same_state(tmp_path):
    m = _machine(tmp_path)
    a = m.snapshot()
    m.run(3, is_limit=False)
    m.restore(a)
    assert same_state(a, m.snapshot(), clock=True)
    m.run(2, is_limit=False)  # one pass of the loop later: #1 and the loop differ
    assert not same_state(a, m.snapshot(), clock=False)


def test_2_values_a_different_value_or_a_zero_of_another_sign_is_another_state(tmp_path):
    m = _machine(tmp_path)
    a = m.snapshot()
    m.C[100] = 1.0
    assert not same_state(a, m.snapshot(), clock=False)
    m.C[100] = -0.0  # equal to 0 yet ATAN[1]/[#100] tells them apart
    assert not same_state(a, m.snapshot(), clock=False)
    m.C[100] = 0.0
    m.frames[-1].locals[1] = None  # vacant is not 0
    assert not same_state(a, m.snapshot(), clock=False)


def test_8_machine_the_clock_counts_only_when_asked(tmp_path):
    m = _machine(tmp_path)
    a = m.snapshot()
    m.planner.clock += 12.5  # the same state after a slower move
    b = m.snapshot()
    assert same_state(a, b, clock=False)
    assert not same_state(a, b, clock=True)
    m.planner.pos[0] += 1.0
    assert not same_state(a, m.snapshot(), clock=False)
