"""The macro machine: a steppable FANUC / Haas / GSK980TDi custom-macro interpreter.

``Machine`` holds the whole state of a run (variables, frames, modal calls, the status) and its
motion planner (``planner``: modal NC state, positions, moves; planner/), which it hosts
(``stored``, ``store``, ``tool_changed``, ``note``: planner/host.py), and advances it one
block at a time. Its parts by job: reading and writing variables (``VariableAccess``, variables.py),
presets and final variables (``VariableSets``, variable_sets.py), calls and returns
(``CallStack``, call_stack.py) and running (``RunLoop``, run_loop.py). ``run`` executes blocks
until the program ends, alarms, pauses (``M00``, ``#3006``) or spends its block budget; ``step`` executes one block;
``run_until`` stops when a predicate holds. ``snapshot`` and ``restore`` copy the state
cheaply and deterministically, which the debugger's step back and the incremental analysis
build on. The front ends read ``result()``, ``frames``, and variables through ``read``; a run's
status is a ``RunStatus`` (status.py). The analysis watches a run through the ``RunObserver``
the machine is made with (observer.py); a machine without one knows nothing of it.
"""

from __future__ import annotations

import datetime as _dt
from collections.abc import Sequence

from ..bilingual import detail
from ..dialects import Dialect, get_dialect
from ..library.machine_file import MachineSettings
from ..library.profiles import machine_profile, profile_settings
from ..library.programs import FoundProgram, LoadedFile, ProgramLibrary
from ..planner.planner import Planner
from .alarms import Alarm, CallLevel
from .blocks import CompiledFile
from .call_stack import CallStack
from .expressions import VariableKinds
from .frames import Frame, ModalCall, Note
from .observer import RunObserver
from .run_loop import RunLoop
from .run_records import RunResult, Snapshot
from .status import FINISHED, RunStatus
from .unknown_values import UNKNOWN, is_kept, seed_caller_commons, seed_unknowns, touch_unknown
from .variable_sets import VariableSets
from .variables import VariableAccess

Value = float | None


class Machine(VariableAccess, VariableSets, CallStack, RunLoop):
    """One simulated control running one program: the macro machine, with its planner (``planner``)."""

    def __init__(
        self,
        dialect: Dialect | str | None = None,
        settings: MachineSettings | None = None,
        library: ProgramLibrary | None = None,
        *,
        m99_ends_main: bool = False,
        observer: RunObserver | None = None,
        kept_unknown: bool = False,
    ) -> None:
        self.settings = settings or MachineSettings()
        if dialect is None or isinstance(dialect, str):
            dialect = get_dialect(dialect or self.settings.dialect)
        dialect = machine_profile(dialect, self.settings)
        self.settings = profile_settings(self.settings, dialect)  # without the [calls] it does not call
        self.dialect = dialect
        self.library = library or ProgramLibrary()
        self.kinds = VariableKinds(dialect)
        self.m99_ends_main = m99_ends_main
        # set when an M99 of the main program ended the run (``m99_ends_main``): a subprogram
        # run on its own stopped after one pass (``cncmacro run`` says so); a restore clears it
        self.ended_by_main_m99 = False
        # the main program's last loop back by ``M99 Pn`` where the profile makes it a branch
        # (``Dialect.main_m99_p_jumps``): (file, the line of Nn, the line of the M99), the loop a
        # shop writes to run a program for ever; a restore clears it
        self.main_loop: tuple[str, int, int] | None = None
        # the code that ended a completed run (30, 2, or 99 for a main program's M99 that ends
        # it), as the run evaluated it; None while it runs or when it ran off its program's end
        self.ended_with: float | None = None
        # who hears of the run (the analysis, see observer.py); None for plain runs, which pay
        # nothing for it: it is fixed before the first block is compiled
        self.observer = observer
        self.L: list[Value] = [None] * 34
        self.C: list[Value] = [None] * 1000
        self.S: dict[int, Value] = {}
        today = _dt.datetime.now()
        self.start_date = self.settings.date if self.settings.date is not None else int(today.strftime("%Y%m%d"))
        self.start_time = self.settings.time if self.settings.time is not None else int(today.strftime("%H%M%S"))
        self.timer_marks: dict[int, float] = {}
        self.written_system: set[int] = set()
        self.preset_system: set[int] = set()
        self.planner = Planner(dialect, self.settings, self)
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
        # an analysis run: what the machine keeps and nothing here gives is unknown, not vacant
        # (unknown_values.py); fixed before the first block is compiled, as ``observer`` is
        self.kept_unknown = kept_unknown
        if kept_unknown:
            seed_unknowns(self.kinds, self.C)

    def unknown_from_caller(self) -> None:
        """The main program is a macro run without its caller (an analysis run): its arguments
        (the locals #1–#33 at level 0) are values a call would pass, and its commons cleared at
        power-off (#100–#199) values the caller may have set before the call, unknown rather
        than vacant (unknown_values.py)."""
        for n in range(1, 34):
            if self.L[n] is None:
                self.L[n] = UNKNOWN
        seed_caller_commons(self.kinds, self.C)

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

    # ---------------------------------------------------------------- the planner's host (planner/host.py)
    def stored(self, n: int) -> Value:
        """Stored system variable ``#n`` (an offset the planner reads); one written from an
        unknown value counts as vacant for the motion (unknown_values.py)."""
        v = self.S.get(n)
        return None if v is not None and v != v else v

    def store(self, n: int, value: float) -> None:
        """The planner writes stored system variable ``#n`` (``G10``)."""
        self.S[n] = value
        self.written_system.add(n)

    def store_added(self, n: int, amount: float) -> None:
        """The planner adds to stored system variable ``#n`` (a ``G10`` increment). In an analysis
        run an offset the machine keeps and nothing here gives is unknown, and so is the sum, as
        ``#n=#n+amount`` reads it (unknown_values.py)."""
        v = self.S.get(n)
        if v is None and self.kept_unknown and is_kept(n, self.kinds, self.dialect):
            v = UNKNOWN
        self.store(n, (0.0 if v is None else v) + amount)

    def probed(self, stored: Sequence[tuple[int, float]], touched: bool) -> None:
        """A G31 ended on a control that stores where the skip signal came on in commons
        (``Dialect.skip_commons``): they take ``stored`` where it came on (``touched``) and are
        left as they were where it did not; in an analysis run without a ``[skip]`` table, which
        cannot know whether or where the probe touched, they become unknown (unknown_values.py)."""
        unknown = touch_unknown(self.kept_unknown, self.settings.skip)
        if not touched and not unknown:
            return
        kind = self.kinds.kind
        for n, v in stored:
            if kind(n) in ("common", "persistent"):  # one a machine file's commons leave out is not written
                self.C[n] = UNKNOWN if unknown else v

    def tool_changed(self, file: str, line: int) -> None:
        """The planner made a tool change: whoever watches the run hears of it."""
        if self.observer is not None:
            self.observer.tool_changed(file, line)

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

    def print_line(self, text: str, pc: int, subject: str | None = None) -> None:
        """Send ``text`` out (a DPRNT line; a BPRNT record, ``subject`` BPRNT, binary_output.py)."""
        self.output.append(text)
        self.notes.append(Note("output", text, self.frames[-1].file, pc, subject))

    def chain(self, at: int | None = None) -> tuple[CallLevel, ...]:
        """Who called whom, from the main program inward (each with the line of its call;
        the innermost with ``at``, or its frame's line)."""
        sites = []
        for k, f in enumerate(self.frames):
            line = self.frames[k + 1].call_line if k + 1 < len(self.frames) else (f.pc if at is None else at)
            sites.append(CallLevel(f.name, f.file, line, f.kind))
        return tuple(sites)

    # ---------------------------------------------------------------- snapshots
    def in_main_loop(self) -> bool:
        """Whether the main program stands in its loop back (``main_loop``): between the line
        of Nn and the ``M99 Pn`` that branches back to it, the loop a shop writes on purpose to
        run a program for ever (a bar feeder, a warm-up), which no run of it ends."""
        loop = self.main_loop
        if loop is None or not self.frames:
            return False
        path, first, last = loop
        main = self.frames[0]
        return main.file == path and first <= main.pc <= last

    def snapshot(self) -> Snapshot:
        return Snapshot(
            self._copy_frames(self.frames), list(self.C), dict(self.S), self.planner.snapshot(),
            list(self.modal_calls), (len(self.output), len(self.notes)), self.blocks, self.status, self.alarm,
            self.message, set(self.written_system), dict(self.timer_marks), self.ended_with,
        )  # fmt: skip

    def restore(self, snap: Snapshot) -> None:
        self.frames = self._copy_frames(snap.frames)
        self.L = self.frames[-1].locals if self.frames else [None] * 34
        self.C = list(snap.C)
        self.S = dict(snap.S)
        self.planner.restore(snap.motion)
        self.modal_calls = list(snap.modal_calls)
        output, notes = snap.counts
        del self.output[output:]
        del self.notes[notes:]
        self.blocks = snap.blocks
        self.status = snap.status
        self.alarm = snap.alarm
        self.message = snap.message
        self.written_system = set(snap.written_system)
        self.timer_marks = dict(snap.timer_marks)
        self.ended_with = snap.ended_with
        self.cancel_requested = False
        self.ended_by_main_m99 = False
        self.main_loop = None

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
    def result(self) -> RunResult:
        p = self.planner
        return RunResult(self.status, self.alarm, self.blocks, self.variables(), p.moves, self.output, self.notes,
                         self.message, p.probes)  # fmt: skip
