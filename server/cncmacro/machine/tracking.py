"""What an analysis run needs from the machine beyond a plain run: which chunk last ran each line,
and whether two snapshots hold the same state.

``run_tracked`` is ``Machine._run`` for a machine with an observer (observer.py), with one
more store per block: the line about to run is stamped with ``RunObserver.track_serial`` in
``RunObserver.last_run`` (file path -> one slot per line, -1 for never), so that an
incremental analysis can tell whether an edited line runs again after a given point of an
earlier run. A line whose stamp is below ``RunObserver.track_floor`` has not run since the
analysis last set the floor (after going back to a checkpoint), and ``RunObserver.first_run``
hears of it, instead of hearing of each line when it is compiled: the analysis can then go
back without compiling every later line again. It is a separate loop so that plain runs and
the debugger pay nothing for it; ``tests/test_run_observed_equals_plain.py`` holds it to the
plain loop (the same final variables, position, status and alarm). At a jump back within a
frame (``GOTO`` or ``IF … GOTO`` to a line at or before its own, a loop's ``END``) and when the
run enters or returns to another frame (a call, ``M99``, ``M99 P``) it asks
``RunObserver.came_back``, and pauses when that says so: the analysis then looks at the state
(an endless loop comes back to the same place with an equal state).

``same_state`` compares two snapshots in everything that can influence later execution or
findings (variables of every frame, commons, system store, frames with their pcs, loops and
repeats, modal state, codes, positions, modal calls, the status), and the simulated clock only
when asked to; block counts and list lengths are not compared. Floats compare exactly, and a
zero's sign counts (``ATAN[0]/[-0]`` differs).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from .alarms import MacroAlarm
from .frames import Frame
from .observer import RunObserver
from .status import CANCEL_CHECK, RunStatus
from .straight_runs import run_straight
from .variables import StopRequest

if TYPE_CHECKING:
    from .blocks import CompiledFile
    from .machine import Machine
    from .run_records import Snapshot


def track_list(observer: RunObserver, cf: CompiledFile) -> list[int]:
    """The per-line serials of ``cf``'s file (made, all -1, the first time the file runs)."""
    runs = observer.last_run
    path = cf.file.path
    trk = runs.get(path)
    if trk is None or len(trk) != len(cf.code):
        trk = runs[path] = [-1] * len(cf.code)
    return trk


def run_tracked(m: Machine, observer: RunObserver, max_blocks: int | None, is_limit: bool) -> RunStatus:
    """``Machine._run``, stamping each executed line (see the module docstring)."""
    budget = m.settings.max_blocks if max_blocks is None else max_blocks
    limit = m.blocks + budget
    m.status = RunStatus.RUNNING
    m.message = None
    serial = observer.track_serial
    floor = observer.track_floor
    first = observer.first_run
    back = observer.came_back
    frame = m.frames[-1]
    cf = frame.code
    code = cf.code
    trk = track_list(observer, cf)
    pc = frame.pc
    n = m.blocks
    try:
        while True:
            if n >= limit:
                m.status = RunStatus.LIMIT if is_limit else RunStatus.PAUSED
                break
            c = code[pc]
            if c is None:
                if not m.modal_calls:
                    done, pc = run_straight(
                        m, cf, pc, min(limit - n, CANCEL_CHECK - n % CANCEL_CHECK), (observer, trk), n
                    )
                    if done:
                        n += done
                        if not n % CANCEL_CHECK and (m.cancel_requested or m.pause_requested):
                            m.take_request()
                            break
                        continue
                c = cf.runner(pc)
            if trk[pc] < floor:
                first(cf.file.path, pc, n)
            trk[pc] = serial
            n += 1
            to = c(m, pc)
            if to > pc:
                pc = to
            elif to >= 0:  # a jump back in the same frame
                if back(pc, to):
                    pc = to
                    m.status = RunStatus.PAUSED
                    break
                pc = to
            else:
                pc = to
                if m.status != RunStatus.RUNNING:
                    break
                frame = m.frames[-1]
                cf = frame.code
                code = cf.code
                trk = track_list(observer, cf)
                pc = frame.pc
                if back(-1, pc):  # another frame: a call, or a return (M99 P too)
                    m.status = RunStatus.PAUSED
                    break
            if not n % CANCEL_CHECK and (m.cancel_requested or m.pause_requested):
                m.take_request()
                break
    except (MacroAlarm, StopRequest) as e:
        return m.interrupted(e, n, pc)
    return m.stopped_at(n, pc)


# ---------------------------------------------------------------- comparing states


def same_values(a: Iterable[Any], b: Iterable[Any]) -> bool:
    """Equal sequences of values (floats or vacant), a zero's sign included; two unknowns (NaN,
    unknown_values.py) are alike."""
    a, b = list(a), list(b)
    if a != b and (len(a) != len(b) or not all(x == y or (x != x and y != y) for x, y in zip(a, b, strict=True))):
        return False
    return all(math.copysign(1.0, x) == math.copysign(1.0, y) for x, y in zip(a, b, strict=True) if x == 0.0)


def _same_map(a: dict[Any, Any], b: dict[Any, Any]) -> bool:
    if a.keys() != b.keys():
        return False
    return same_values(a.values(), (b[k] for k in a))


def position_key(frames: list[Frame]) -> tuple[Any, ...]:
    """Where a machine is: each frame's program, line, loops and pass count (for lookups;
    ``same_state`` compares everything)."""
    return tuple((id(f.found.file), f.found.unit.start, f.pc, f.kind, tuple(f.loops), f.repeats) for f in frames)


def _same_frames(a: list[Frame], b: list[Frame]) -> bool:
    if len(a) != len(b):
        return False
    for k, (x, y) in enumerate(zip(a, b, strict=True)):
        if (x.found.file is not y.found.file or x.found.unit is not y.found.unit or x.code is not y.code
                or x.pc != y.pc or x.kind != y.kind or x.macro_level != y.macro_level or x.call_line != y.call_line
                or x.return_pc != y.return_pc or x.repeats != y.repeats or x.start_pc != y.start_pc
                or x.loops != y.loops or (x.modal is not y.modal and x.modal != y.modal) or x.written != y.written
                or x.letters != y.letters or not _same_map(x.arguments, y.arguments)):  # fmt: skip
            return False
        if k and (x.locals is a[k - 1].locals) != (y.locals is b[k - 1].locals):
            return False  # an M98 level shares its caller's locals in one and not the other
        if not same_values(x.locals, y.locals):
            return False
    return True


def same_state(a: Snapshot, b: Snapshot, *, clock: bool) -> bool:
    """Whether runs continuing from ``a`` and from ``b`` behave alike (module docstring)."""
    am, bm = a.motion, b.motion
    if (a.status != b.status or a.alarm is not b.alarm or a.message != b.message or am.extra_wcs != bm.extra_wcs
            or a.modal_calls != b.modal_calls or a.written_system != b.written_system
            or am.skip_state != bm.skip_state):  # fmt: skip
        return False
    if not same_values([am.cycle_start_z], [bm.cycle_start_z]):
        return False
    if clock and (am.clock != bm.clock or a.timer_marks != b.timer_marks):
        return False
    if not same_values(a.C, b.C) or not _same_map(a.S, b.S) or not _same_map(am.modal, bm.modal):
        return False
    if not _same_map(am.codes, bm.codes):
        return False
    if not all(same_values(x, y) for x, y in zip(am.positions, bm.positions, strict=True)):
        return False
    return _same_frames(a.frames, b.frames)
