"""The interpreter: a steppable FANUC 0i / GSK980TDi macro machine.

``Machine`` holds the whole state of a run (variables, frames, modal state, positions, moves)
and advances it one block at a time. ``run`` executes blocks until the program ends, alarms,
pauses (``M00``, ``#3006``) or spends its block budget; ``step`` executes one block;
``run_until`` stops when a predicate holds. ``snapshot`` and ``restore`` copy the state
cheaply and deterministically, which the debugger's step back and the incremental analysis
build on. The front ends read ``result()``, ``frames``, and variables through ``read``; a run's
status is a ``RunStatus`` (status.py). The analysis watches a run through the ``RunObserver``
the machine is made with (observer.py); a machine without one knows nothing of it.
"""

from __future__ import annotations

import datetime as _dt
import gc
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ..bilingual import detail
from ..dialects import Dialect, get_dialect
from ..dialects.alarms import MACRO_NESTING, P_VALUE_RANGE, PROGRAM_NOT_FOUND, SUBPROGRAM_NESTING
from ..library.machine_file import CallCode, MachineSettings
from ..library.profiles import machine_profile
from ..library.programs import FoundProgram, LoadedFile, ProgramLibrary, is_program_name
from .alarms import Alarm, CallLevel, MacroAlarm
from .blocks import CompiledFile
from .calls import Arguments, bad_name_detail, map_arguments, repeat_count
from .expressions import VariableKinds
from .frames import Frame, ModalCall, Move, Note
from .motion import Motion
from .observer import RunObserver
from .probing import Probe, SkipState
from .status import FINISHED, RunStatus
from .straight_runs import run_straight
from .tracking import run_tracked
from .variables import StopRequest, VariableAccess

Value = float | None

CANCEL_CHECK = 4096


@dataclass(slots=True)
class RunResult:
    """What a run ended with, in docs/design.md's terms (``cncmacro run --json``)."""

    status: RunStatus
    alarm: Alarm | None
    blocks: int
    variables: dict[int, float]
    moves: list[Move]
    output: list[str]
    notes: list[Note]
    message: str | None = None
    probes: list[Probe] = field(default_factory=list)  # the G31 blocks (probing.py)


@dataclass(slots=True)
class Snapshot:
    """A copy of a machine's state at one moment; restore it any number of times."""

    frames: list[Frame]
    C: list[Value]
    S: dict[int, Value]
    modal: dict[str, float]
    codes: dict[str, Value]
    positions: tuple[list[float], list[float], list[float], list[float]]
    extra_wcs: int
    cycle_start_z: float | None
    modal_calls: list[ModalCall]
    counts: tuple[int, int, int]
    clock: float
    blocks: int
    status: RunStatus
    alarm: Alarm | None
    message: str | None
    written_system: set[int] = field(default_factory=set)
    timer_marks: dict[int, float] = field(default_factory=dict)
    lengths: tuple[float, float] = (0.0, 0.0)  # the cut and rapid path so far (mm, cycle_time.py)
    tool_count: int = 0  # tool changes recorded
    skip_state: SkipState = field(default_factory=SkipState)  # with the number of probes recorded (probing.py)
    probes: int = 0


class Machine(VariableAccess, Motion):
    """One simulated control running one program."""

    def __init__(
        self,
        dialect: Dialect | str | None = None,
        settings: MachineSettings | None = None,
        library: ProgramLibrary | None = None,
        *,
        m99_ends_main: bool = False,
        observer: RunObserver | None = None,
    ) -> None:
        self.settings = settings or MachineSettings()
        if dialect is None or isinstance(dialect, str):
            dialect = get_dialect(dialect or self.settings.dialect)
        dialect = machine_profile(dialect, self.settings)
        self.dialect = dialect
        self.library = library or ProgramLibrary()
        self.kinds = VariableKinds(dialect)
        self.m99_ends_main = m99_ends_main
        # set when an M99 of the main program ended the run (``m99_ends_main``): a subprogram
        # run on its own stopped after one pass (``cncmacro run`` says so); a restore clears it
        self.ended_by_main_m99 = False
        # who hears of the run (the analysis, see observer.py); None for plain runs, which pay
        # nothing for it: it is fixed before the first block is compiled
        self.observer = observer
        self.L: list[Value] = [None] * 34
        self.C: list[Value] = [None] * 1000
        self.S: dict[int, Value] = {}
        self.clock = 0.0
        today = _dt.datetime.now()
        self.start_date = self.settings.date if self.settings.date is not None else int(today.strftime("%Y%m%d"))
        self.start_time = self.settings.time if self.settings.time is not None else int(today.strftime("%H%M%S"))
        self.timer_marks: dict[int, float] = {}
        self.written_system: set[int] = set()
        self.preset_system: set[int] = set()
        self.init_motion()
        self.frames: list[Frame] = []
        self.modal_calls: list[ModalCall] = []
        self.compiled: dict[str, CompiledFile] = {}
        self.status = RunStatus.READY
        self.alarm: Alarm | None = None
        self.message: str | None = None
        self.blocks = 0
        self.output: list[str] = []
        self.notes: list[Note] = []
        self.cancel_requested = False
        self.pause_requested = False
        # presets of the machine file that this profile cannot take (a variable it lacks): the
        # run refuses to start with them (``setup.prepare_run``), the analysis runs without them
        self.preset_problems: list[str] = []
        for n, v in self.settings.variables.items():
            try:
                self.apply_presets({n: v})
            except ValueError as e:
                self.preset_problems.append(e.args[0] if e.args else str(e))

    # ---------------------------------------------------------------- setting up
    def apply_presets(self, presets: dict[int, float]) -> None:
        """Set variables before the run (``--set``, the machine file). Offsets and other
        stored system variables may be preset even where a program may not write them;
        computed ones (positions, modal codes) may not. ``ValueError`` says why."""
        for n, v in presets.items():
            kind = self.kinds.kind(n)
            if kind == "local":
                self.L[n] = v
            elif kind in ("common", "persistent"):
                self.C[n] = v
            elif kind == "extended":
                self.S[n] = v
            elif kind == "system":
                row = self.dialect.system_variable(n)
                assert row is not None
                if row.source == "alias":
                    self.S[int(row.param) + n - row.first] = v
                elif row.source in ("store", "date", "time", "timer"):
                    self.S[n] = v
                else:
                    raise ValueError(f"#{n} ({row.en.split(';')[0]}) is computed by the machine and cannot be preset")
                self.preset_system.add(n)
            else:
                raise ValueError(f"#{n} is not a variable of {self.dialect.title} that can be preset")

    def load_persistent(self, values: dict[int, float]) -> None:
        """Put back the values kept at power-off (the machine's persistent common ranges)."""
        for n, v in values.items():
            kind = self.kinds.kind(n)
            if kind == "persistent":
                self.C[n] = v
            elif kind == "extended" and any(n in r for r in self.kinds.persistent):
                self.S[n] = v

    def persistent_values(self) -> dict[int, float]:
        out: dict[int, float] = {}
        for n in self.kinds.persistent_numbers():
            v = self.C[n] if n < 1000 else self.S.get(n)
            if v is not None:
                out[n] = v
        return out

    def discard(self) -> None:
        """Break the reference cycles of a machine nobody will run again (its compiled files
        and frames point back at it), so that reference counting frees it at once: the
        language server freezes what survives each analysis (``lsp/collector.py``), and a
        dropped machine left to the cycle collector would stay until the next clean-up."""
        self.compiled.clear()
        self.frames.clear()
        self.modal_calls.clear()
        self.observer = None

    def compiled_file(self, file: LoadedFile) -> CompiledFile:
        cf = self.compiled.get(file.path)
        if cf is None or cf.file is not file:
            cf = self.compiled[file.path] = CompiledFile(self, file)
        return cf

    def start(self, found: FoundProgram) -> None:
        """Make ``found`` the main program (level 0) and get ready to run its first block."""
        cf = self.compiled_file(found.file)
        first = cf.entry(found.unit)
        self.frames = [Frame(found, cf, first, "main", self.L, 0, start_pc=first)]
        self._program_number()
        self.status = RunStatus.READY

    def start_file(self, path: str, text: str | None = None) -> FoundProgram:
        """Load a file (or ``text`` as that file) and start its first program."""
        loaded = self.library.add_text(path, text) if text is not None else self.library.load(path)
        if loaded is None:
            raise OSError(f"{path}: cannot read the program")
        program = loaded.program
        units = program.named_units()
        unit = next((u for u in units if u.number is not None or u.end > u.start), units[0])
        found = FoundProgram(loaded, unit)
        self.start(found)
        for u in program.units:
            if u.duplicate and u.number is not None:
                kept = program.unit_numbered(u.number)
                first = kept.start + 1 if kept is not None else 0
                self.notes.append(Note("call", detail(
                    f"O{u.number:04d} repeats the program number of line {first}: the control keeps the first "
                    "program and ignores this one",
                    f"O{u.number:04d} 与第 {first} 行的程序号重复：系统只保留前一个程序，忽略此处的程序",
                ), path, u.start, "duplicate-program"))  # fmt: skip
        return found

    # ---------------------------------------------------------------- state for the front ends
    @property
    def frame(self) -> Frame:
        return self.frames[-1]

    @property
    def watching(self) -> bool:
        """Blocks are compiled watched, reporting to the observer (see observer.py)."""
        return self.observer is not None

    @property
    def finished(self) -> bool:
        return self.status in FINISHED

    def current_line(self) -> tuple[str, int] | None:
        if not self.frames:
            return None
        f = self.frames[-1]
        return f.file, f.pc

    def note(self, kind: str, message: str, line: int | None = None, subject: str | None = None) -> None:
        """Record a remark about the block on ``line`` (the current frame's, by default)."""
        f = self.frames[-1]
        at = f.pc if line is None else line
        self.notes.append(Note(kind, message, f.file, at, subject, self.chain(at)))

    def vacant_local(self, n: int, line: int) -> None:
        """A watched read found local ``#n`` vacant on ``line``: when the macro level that
        owns the locals was called without the argument that fills ``#n``, tell the
        observer (``RunObserver.vacant_argument``). Main-level locals have no caller to blame."""
        observer = self.observer
        if observer is None:
            return
        frames = self.frames
        k = len(frames) - 1
        while k > 0 and frames[k - 1].locals is frames[k].locals:
            k -= 1  # M98 levels share the locals of the level that called them
        if k == 0 or n in frames[k].arguments:
            return
        written = frames[k].written
        if written is not None and n in written:
            return  # the macro assigned it itself (perhaps a vacant value): not the caller's doing
        observer.vacant_argument(n, frames[-1].file, line, self.chain(line))

    def wrote_local(self, n: int) -> None:
        """A watched run saw a macro level assign its local ``#n`` (see ``vacant_local``)."""
        frames = self.frames
        k = len(frames) - 1
        while k > 0 and frames[k - 1].locals is frames[k].locals:
            k -= 1
        if k == 0:
            return
        f = frames[k]
        if f.written is None:
            f.written = {n}
        else:
            f.written.add(n)

    def print_line(self, text: str, pc: int) -> None:
        self.output.append(text)
        self.notes.append(Note("output", text, self.frames[-1].file, pc))

    def chain(self, at: int | None = None) -> tuple[CallLevel, ...]:
        """Who called whom, from the main program inward (each with the line of its call;
        the innermost with ``at``, or its frame's line)."""
        sites = []
        for k, f in enumerate(self.frames):
            line = self.frames[k + 1].call_line if k + 1 < len(self.frames) else (f.pc if at is None else at)
            sites.append(CallLevel(f.name, f.file, line, f.kind))
        return tuple(sites)

    # ---------------------------------------------------------------- running
    def run(self, max_blocks: int | None = None, *, is_limit: bool = True) -> RunStatus:
        """Run until the program ends, alarms, pauses or has run ``max_blocks`` more blocks
        (status ``limit``, or ``paused`` when ``is_limit`` is False). Returns the status.

        Python's cycle collector is paused meanwhile: a run creates no garbage cycles, yet
        the collector would walk every compiled block again and again (a 100k-block
        program ran 3x slower with it). A machine with an observer runs
        ``tracking.run_tracked``, which the property tests hold to this plain loop."""
        if self.status in FINISHED or not self.frames:
            return self.status
        was_enabled = gc.isenabled()
        gc.disable()
        try:
            if self.observer is not None:
                return run_tracked(self, self.observer, max_blocks, is_limit)
            return self._run(max_blocks, is_limit)
        finally:
            if was_enabled:
                gc.enable()

    def _run(self, max_blocks: int | None, is_limit: bool) -> RunStatus:
        budget = self.settings.max_blocks if max_blocks is None else max_blocks
        limit = self.blocks + budget
        self.status = RunStatus.RUNNING
        self.message = None
        frame = self.frames[-1]
        cf = frame.code
        code = cf.code
        pc = frame.pc
        n = self.blocks
        try:
            while True:
                if n >= limit:
                    self.status = RunStatus.LIMIT if is_limit else RunStatus.PAUSED
                    break
                c = code[pc]
                if c is None:
                    if not self.modal_calls:
                        done, pc = run_straight(self, cf, pc, min(limit - n, CANCEL_CHECK - n % CANCEL_CHECK))
                        if done:
                            n += done
                            if not n % CANCEL_CHECK and (self.cancel_requested or self.pause_requested):
                                self.take_request()
                                break
                            continue
                    c = cf.runner(pc)
                n += 1
                pc = c(self, pc)
                if pc < 0:
                    if self.status != RunStatus.RUNNING:
                        break
                    frame = self.frames[-1]
                    cf = frame.code
                    code = cf.code
                    pc = frame.pc
                if not n % CANCEL_CHECK and (self.cancel_requested or self.pause_requested):
                    self.take_request()
                    break
        except (MacroAlarm, StopRequest) as e:
            return self.interrupted(e, n, pc)
        return self.stopped_at(n, pc)

    # The run loops (``_run`` and the analysis's ``tracking.run_tracked``) end through these.
    def take_request(self) -> None:
        """Honour a cancel or pause request from another thread (seen every ``CANCEL_CHECK`` blocks)."""
        if self.cancel_requested:
            self.status = RunStatus.STOPPED
        else:
            self.pause_requested = False
            self.status = RunStatus.PAUSED

    def interrupted(self, e: MacroAlarm | StopRequest, n: int, pc: int) -> RunStatus:
        """A run stopped inside block ``pc``, the ``n``-th: by an alarm, or by ``M00``/``#3006``
        (paused, to go on with the next block)."""
        self.blocks = n
        f = self.frames[-1]
        if isinstance(e, MacroAlarm):
            f.pc = pc
            self.alarm = Alarm(e.number, e.message, f.file, pc, self.chain(), e.subject)
            self.status = RunStatus.ALARM
        else:
            f.pc = f.code.next_line(pc)
            self.status = RunStatus.PAUSED
            self.message = e.message
            self.notes.append(Note("message", e.message, f.file, pc))
        return self.status

    def stopped_at(self, n: int, pc: int) -> RunStatus:
        """A run loop left after ``n`` blocks with ``pc`` next (negative: the frames say)."""
        self.blocks = n
        if pc >= 0:
            self.frames[-1].pc = pc
        return self.status

    def step(self) -> RunStatus:
        """Execute one block; the status is ``paused`` unless the run ended."""
        return self.run(1, is_limit=False)

    def run_until(self, stop: Callable[[Machine], bool], max_blocks: int | None = None) -> RunStatus:
        """Execute blocks until ``stop(machine)`` holds after one, or the run ends."""
        budget = self.settings.max_blocks if max_blocks is None else max_blocks
        limit = self.blocks + budget
        while True:
            status = self.step()
            if status != RunStatus.PAUSED or self.message is not None:
                return status
            if stop(self):
                return status
            if self.blocks >= limit:
                self.status = RunStatus.LIMIT
                return RunStatus.LIMIT

    def resume(self) -> None:
        """Continue after a pause (``M00``, ``#3006``)."""
        if self.status == RunStatus.PAUSED:
            self.status = RunStatus.READY
            self.message = None

    def cancel(self) -> None:
        """Ask a running ``run`` (in another thread) to stop soon."""
        self.cancel_requested = True

    def request_pause(self) -> None:
        """Ask a running ``run`` (in another thread) to pause soon, within ``CANCEL_CHECK``
        blocks (an endless loop too); it returns ``paused`` and may be run on afterwards."""
        self.pause_requested = True

    # ---------------------------------------------------------------- calls and returns
    def find_program(self, number: int) -> FoundProgram:
        near = self.frames[-1].found.file if self.frames else None
        found = self.library.find_number(number, near)
        if found is None and self.dialect.on_control(number):
            return self.library.control_program(number)
        if found is None:
            raise MacroAlarm(PROGRAM_NOT_FOUND, detail(f"program O{number:04d} not found", f"未找到程序 O{number:04d}"))
        return found

    def find_program_named(self, name: str) -> FoundProgram:
        if not self.dialect.bracket_names:
            raise MacroAlarm(
                PROGRAM_NOT_FOUND,
                detail(
                    f"P[{name}]: {self.dialect.title} names programs only by number",
                    f"P[{name}]：{self.dialect.title} 只能用程序号指定程序",
                ),
            )
        if not is_program_name(name):
            raise MacroAlarm(P_VALUE_RANGE, bad_name_detail(name))
        near = self.frames[-1].found.file if self.frames else None
        found = self.library.find_name(name, near)
        if found is None:
            raise MacroAlarm(PROGRAM_NOT_FOUND, detail(f"program {name} not found", f"未找到程序 {name}"))
        return found

    def _check_depth(self, macro: bool) -> None:
        if len(self.frames) > self.dialect.subprogram_levels:
            raise MacroAlarm(
                SUBPROGRAM_NESTING,
                detail(
                    f"more than {self.dialect.subprogram_levels} nested program calls",
                    f"程序调用嵌套超过 {self.dialect.subprogram_levels} 层",
                ),
            )
        if macro and self.frames[-1].macro_level >= self.dialect.macro_levels:
            raise MacroAlarm(
                MACRO_NESTING,
                detail(
                    f"more than {self.dialect.macro_levels} nested macro calls (G65/G66)",
                    f"宏程序调用（G65/G66）嵌套超过 {self.dialect.macro_levels} 层",
                ),
            )

    def macro_call(
        self, found: FoundProgram, arguments: Arguments, repeats: int, pc: int, nxt: int, kind: str, modal: Any = None
    ) -> int:
        """G65 (or a modal or code call): a new local level filled with the arguments."""
        self._check_depth(macro=True)
        caller = self.frames[-1]
        caller.pc = pc
        cf = self.compiled_file(found.file)
        start = cf.entry(found.unit)
        local: list[Value] = [None] * 34
        for k, v in arguments.values.items():
            local[k] = v
        frame = Frame(found, cf, start, kind, local, caller.macro_level + 1, pc, nxt, repeats - 1, start,
                      arguments.values, arguments.letters, [], modal)  # fmt: skip
        self.frames.append(frame)
        self.L = local
        self._program_number()
        return -1

    def subprogram_call(self, found: FoundProgram, repeats: int, q: float | None, pc: int, nxt: int, kind: str) -> int:
        """M98: the caller's locals stay in force; Q starts at a label."""
        self._check_depth(macro=False)
        cf = self.compiled_file(found.file)
        start = cf.label_from_start(found.unit, int(q)) if q is not None else cf.entry(found.unit)
        return self._enter_subprogram(found, cf, start, repeats, pc, nxt, kind)

    def local_subprogram_call(self, label: float | None, repeats: int, pc: int, nxt: int, kind: str) -> int:
        """Haas ``M97 P n L k`` (``Dialect.local_subprogram_code``): the program running is run
        from its Nn as a subprogram level (the locals stay, the level counts for nesting) until
        M99, k times, then on after the call."""
        self._check_depth(macro=False)
        caller = self.frames[-1]
        start = caller.code.local_call_line(caller.found, kind, label)
        return self._enter_subprogram(caller.found, caller.code, start, repeats, pc, nxt, kind)

    def _enter_subprogram(
        self, found: FoundProgram, cf: CompiledFile, start: int, repeats: int, pc: int, nxt: int, kind: str
    ) -> int:
        caller = self.frames[-1]
        caller.pc = pc
        frame = Frame(found, cf, start, kind, caller.locals, caller.macro_level, pc, nxt, repeats - 1, start)
        self.frames.append(frame)
        self._program_number()
        return -1

    def return_from_call(self, pc: int, p: float | None) -> int:
        """M99 (Pn): back to the caller, or the next pass of a repeated call."""
        frame = self.frames[-1]
        if len(self.frames) == 1:
            if self.m99_ends_main:
                self.status = RunStatus.COMPLETED
                self.ended_by_main_m99 = True
                frame.pc = pc
                return -1
            frame.loops.clear()
            if p is not None:  # M99 Pn in a main program: on from its Nn (FANUC 0i)
                return frame.code.label_from_start(frame.found.unit, int(p))
            return frame.start_pc  # M99 in a main program runs it again
        if frame.repeats > 0 and p is None:
            frame.repeats -= 1
            frame.loops.clear()
            if frame.locals is not self.frames[-2].locals:
                local: list[Value] = [None] * 34
                for k, v in frame.arguments.items():
                    local[k] = v
                frame.locals = local
                self.L = local
            return frame.start_pc
        self.frames.pop()
        caller = self.frames[-1]
        self.L = caller.locals
        self._program_number()
        if p is not None:
            target = caller.code.label_in_caller(caller.found.unit, frame.call_line, int(p))
            caller.loops[:] = [d for d in caller.loops if d < target <= caller.code.do_end.get(d, -1)]
            caller.pc = target
        else:
            caller.pc = frame.return_pc
        return -1

    def _program_number(self) -> None:
        number = self.frames[-1].found.unit.number
        self.codes["O"] = float(number) if number is not None else None

    def end_of_program(self, pc: int) -> int:
        """Ran off the end of a program: a called one returns, the main one ends."""
        if len(self.frames) > 1:
            return self.return_from_call(pc, None)
        self.status = RunStatus.COMPLETED
        self.frames[-1].pc = pc
        return -1

    def end_program(self, pc: int) -> int:
        """M30 / M02: the run is complete; modal calls are cancelled."""
        self.modal_calls.clear()
        self.modal["macro"] = 67.0
        self.status = RunStatus.COMPLETED
        self.frames[-1].pc = pc
        return -1

    def pause(self, message: str, nxt: int) -> int:
        self.status = RunStatus.PAUSED
        self.message = message
        f = self.frames[-1]
        f.pc = nxt
        self.notes.append(Note("message", message, f.file, nxt))
        return -1

    def skip_past_label(self, pc: int, label: float) -> int:
        """A lathe roughing cycle ``G71 P Q``: continue after the block labelled Q."""
        f = self.frames[-1]
        lines = f.found.file.program.label_lines(int(label), f.found.unit)
        after = [x for x in lines if x > pc]
        return f.code.next_line(after[0]) if after else f.code.next_line(pc)

    # ---------------------------------------------------------------- modal and code calls
    def set_modal_call(self, found: FoundProgram, arguments: Arguments, repeats: int) -> None:
        """G66: the macro is called after each later move; modal group 12 (#4012) reads 66."""
        self.modal_calls.append(
            ModalCall(
                found,
                tuple(arguments.values.items()),
                tuple(arguments.letters.items()),
                repeats,
                self.frames[-1].macro_level,
            )
        )
        self.modal["macro"] = 66.0

    def cancel_modal_call(self) -> None:
        """G67: the innermost G66 ends; group 12 reads 67 once none is left."""
        if self.modal_calls:
            self.modal_calls.pop()
        if not self.modal_calls:
            self.modal["macro"] = 67.0

    def modal_call(self, pc: int, nxt: int) -> int:
        """After a move while G66 is in force: call the macro, unless it is that macro moving."""
        top = self.modal_calls[-1]
        if any(f.modal is top for f in self.frames):
            return nxt
        args = Arguments(dict(top.arguments), dict(top.letters))
        return self.macro_call(top.found, args, top.repeats, pc, nxt, "G66", modal=top)

    def call_code_for(self, values: list[tuple[str, float]]) -> tuple[str, CallCode] | None:
        """The configured call for a G, M or T code in the block, with the code as the
        machine file names it (``G100``, ``M50``, ``T``); none inside such a call."""
        calls = self.settings.calls
        local = f"M{self.dialect.local_subprogram_code:g}" if self.dialect.local_subprogram_code is not None else ""
        if any(f.kind[:1] in ("G", "M", "T") and f.kind not in ("G65", "G66", "M98", local) for f in self.frames):
            return None
        for letter, v in values:
            if letter in ("G", "M"):
                code = f"{letter}{v:g}"
                c = calls.get(code)
                if c is not None:
                    return code, c
            elif letter == "T" and "T" in calls:
                return "T", calls["T"]
        return None

    def code_macro_call(self, code: str, call: CallCode, values: list[tuple[str, float]], pc: int, nxt: int) -> int:
        """A code configured as a macro call: like G65, the block's other words the arguments."""
        found = self.find_program(call.program)
        args_words = [(letter, v) for letter, v in values if f"{letter}{v:g}" != code and letter != "L"]
        notes: list[str] = []
        repeats = repeat_count(dict(values).get("L"), self.dialect, notes)
        arguments = map_arguments(args_words, self.dialect)
        for text in notes:
            self.note("call", text, pc, "repeat-count")
        for text in arguments.remarks:
            self.note("call", text, pc, "argument-order")
        return self.macro_call(found, arguments, repeats, pc, nxt, code)

    def code_subprogram_call(
        self, code: str, call: CallCode, values: list[tuple[str, float]], pc: int, nxt: int
    ) -> int:
        """A code configured as a subprogram call: like M98; a T code leaves its value in #149."""
        found = self.find_program(call.program)
        t = dict(values).get("T")
        if t is not None and self.kinds.kind(149) in ("common", "persistent"):
            self.C[149] = t
        return self.subprogram_call(found, 1, None, pc, nxt, code)

    # ---------------------------------------------------------------- snapshots
    def snapshot(self) -> Snapshot:
        return Snapshot(
            self._copy_frames(self.frames), list(self.C), dict(self.S), dict(self.modal), dict(self.codes),
            (list(self.pos), list(self.shift), list(self.skip_pos), list(self.tool_vector)), self.extra_wcs,
            self.cycle_start_z, list(self.modal_calls), (len(self.moves), len(self.output), len(self.notes)),
            self.clock, self.blocks, self.status, self.alarm, self.message, set(self.written_system),
            dict(self.timer_marks), (self.cut_length, self.rapid_length), len(self.tool_changes), self.skip_state,
            len(self.probes),
        )  # fmt: skip

    def restore(self, snap: Snapshot) -> None:
        self.frames = self._copy_frames(snap.frames)
        self.L = self.frames[-1].locals if self.frames else [None] * 34
        self.C = list(snap.C)
        self.S = dict(snap.S)
        self.modal = dict(snap.modal)
        self.codes = dict(snap.codes)
        pos, shift, skip, tool = snap.positions
        self.pos, self.shift, self.skip_pos, self.tool_vector = list(pos), list(shift), list(skip), list(tool)
        self.extra_wcs = snap.extra_wcs
        self.cycle_start_z = snap.cycle_start_z
        self.modal_calls = list(snap.modal_calls)
        moves, output, notes = snap.counts
        del self.moves[moves:]
        del self.output[output:]
        del self.notes[notes:]
        self.clock = snap.clock
        self.cut_length, self.rapid_length = snap.lengths
        del self.tool_changes[snap.tool_count :]
        self.blocks = snap.blocks
        self.status = snap.status
        self.alarm = snap.alarm
        self.message = snap.message
        self.written_system = set(snap.written_system)
        self.timer_marks = dict(snap.timer_marks)
        self.skip_state = snap.skip_state
        del self.probes[snap.probes :]
        self.cancel_requested = False
        self.ended_by_main_m99 = False

    @staticmethod
    def _copy_frames(frames: list[Frame]) -> list[Frame]:
        memo: dict[int, list[Value]] = {}
        out = []
        for f in frames:
            copied = memo.get(id(f.locals))
            if copied is None:
                copied = memo[id(f.locals)] = list(f.locals)
            out.append(f.copy(copied))
        return out

    # ---------------------------------------------------------------- results
    def variables(self) -> dict[int, float]:
        """docs/design.md's ``variables``: non-vacant level-0 locals, commons and persistent, and
        the system variables that were preset or written (vacant ones are absent)."""
        out: dict[int, float] = {}
        level0 = self.frames[0].locals if self.frames else self.L
        for n in range(1, 34):
            v = level0[n]
            if v is not None:
                out[n] = v
        for r in self.kinds.ranges:
            for n in range(r.first, r.last + 1):
                v = self.C[n] if n < 1000 else self.S.get(n)
                if v is not None:
                    out[n] = v
        for n in sorted(self.preset_system | self.written_system):
            try:
                v = self.read_system(n)
            except MacroAlarm:
                continue
            if v is not None:
                out[n] = v
        return dict(sorted(out.items()))

    def result(self) -> RunResult:
        return RunResult(self.status, self.alarm, self.blocks, self.variables(), self.moves, self.output, self.notes,
                         self.message, self.probes)  # fmt: skip
