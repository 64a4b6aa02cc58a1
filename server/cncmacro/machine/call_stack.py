"""Calls and returns on the macro machine (docs/semantics.md §5): G65 and G66 macro calls with
their local levels, M98 and Haas M97 subprograms, codes the machine file makes calls, M99 and
the ends of programs, with the nesting limits of the profile.

``CallStack`` is the part of ``Machine`` (machine.py) that pushes and pops its ``frames``; the
compiled blocks (nc_blocks.py) call it once a block's call words are evaluated (calls.py).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from ..bilingual import detail
from ..dialects.alarms import (
    CYCLE_BLOCK_NOT_FOUND,
    MACRO_NESTING,
    P_VALUE_RANGE,
    PROGRAM_NOT_FOUND,
    SHAPE_COMMAND,
    SUBPROGRAM_NESTING,
)
from ..library.programs import FoundProgram, is_program_name
from ..planner.lathe_cycles import end_shape
from .alarms import MacroAlarm
from .calls import Arguments, bad_name_detail, map_arguments, repeat_count
from .frames import Frame, ModalCall, Note
from .status import RunStatus

if TYPE_CHECKING:
    from ..dialects import Dialect
    from ..library.machine_file import CallCode, MachineSettings
    from ..library.programs import LoadedFile, ProgramLibrary
    from ..planner.lathe_cycles import ShapeCall
    from ..planner.planner import Planner
    from .blocks import CompiledFile
    from .expressions import VariableKinds

Value = float | None


class CallStack:
    """The calls and returns of ``Machine`` (module docstring)."""

    dialect: Dialect
    settings: MachineSettings
    library: ProgramLibrary
    kinds: VariableKinds
    planner: Planner
    frames: list[Frame]
    modal_calls: list[ModalCall]
    L: list[Value]
    C: list[Value]
    status: RunStatus
    m99_ends_main: bool
    ended_by_main_m99: bool
    main_loop: tuple[str, int, int] | None
    ended_with: float | None
    message: str | None
    notes: list[Note]

    if TYPE_CHECKING:

        def compiled_file(self, file: LoadedFile) -> CompiledFile: ...

        def note(self, kind: str, message: str, line: int | None = None, subject: str | None = None) -> None: ...

    def find_program(self, number: int) -> FoundProgram:
        near = self.frames[-1].found.file if self.frames else None
        found = self.library.find_number(number, near)
        if found is None and self.dialect.on_control(number):
            return self.library.control_program(number)
        if found is None:
            unread = self.library.unread_for(number, near)  # there, but a DNC program holds it open
            if unread is not None:
                raise MacroAlarm(PROGRAM_NOT_FOUND, detail(f"program O{number:04d} not found: {unread}",
                                                           f"未找到程序 O{number:04d}：{unread.zh}"))  # fmt: skip
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
        if self.frames and self.frames[-1].end_line >= 0:
            raise MacroAlarm(SHAPE_COMMAND, detail(f"no program call in the shape of {self.frames[-1].kind} "
                                                   "(M98, M99, G65, G66 are not allowed there)",
                                                   f"{self.frames[-1].kind}的形状程序中不能调用程序（不允许M98、M99、G65、G66）"),
                             "shape-command")  # fmt: skip
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
        frame.increments = arguments.increments
        frame.passes = max(repeats, 1)
        self.frames.append(frame)
        self.L = local
        self._program_number()
        return -1

    def passed_in_increments(self, n: int, value: float) -> float:
        """The factor local ``#n`` was divided by when the call passed it in least input
        increments (an argument without a decimal point, docs/semantics.md §5), while it still
        holds ``value``, the value passed; 1 otherwise. For ``ADP``."""
        for f in reversed(self.frames):
            if f.locals is self.L and f.increments:
                return f.increments.get(n, 1.0) if f.arguments.get(n) == value else 1.0
        return 1.0

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
        frame.passes = max(repeats, 1)
        self.frames.append(frame)
        self._program_number()
        return -1

    def return_from_call(self, pc: int, p: float | None) -> int:
        """M99 (Pn): back to the caller, or the next pass of a repeated call."""
        frame = self.frames[-1]
        if frame.end_line >= 0:
            self._check_depth(macro=False)  # M99 in a cycle's shape: the same alarm as a call
        if len(self.frames) == 1:
            if p is not None and self.dialect.main_m99_p_jumps:  # Haas: a branch, as GOTO n
                frame.loops.clear()
                target = frame.code.label_from_start(frame.found.unit, int(p))
                self.main_loop = (frame.file, target, pc)
                return target
            if self.m99_ends_main:
                self.status = RunStatus.COMPLETED
                self.ended_by_main_m99 = True
                self.ended_with = 99.0
                frame.pc = pc
                return -1
            frame.loops.clear()
            if p is not None:  # M99 Pn in a main program: on from its Nn (FANUC 0i)
                return frame.code.label_from_start(frame.found.unit, int(p))
            return frame.start_pc  # M99 in a main program runs it again
        if frame.repeats > 0 and p is None:
            frame.repeats -= 1
            frame.loops.clear()
            if frame.locals is not self.frames[-2].locals and not self.dialect.macro_repeat_keeps_locals:
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
        self.planner.codes["O"] = float(number) if number is not None else None

    def end_of_program(self, pc: int) -> int:
        """Ran off the end of a program: a called one returns, the main one ends."""
        if len(self.frames) > 1:
            return self.return_from_call(pc, None)
        self.status = RunStatus.COMPLETED
        self.frames[-1].pc = pc
        return -1

    def end_program(self, pc: int, code: float) -> int:
        """M30 / M02 (``code``, as the run evaluated it): the run is complete and keeps the code
        it ended with; modal calls are cancelled."""
        self.ended_with = code
        self.modal_calls.clear()
        self.planner.modal["macro"] = 67.0
        self.status = RunStatus.COMPLETED
        self.frames[-1].pc = pc
        return -1

    def pause(self, message: str, pc: int, nxt: int) -> int:
        """The block at ``pc`` (an ``M00``) stops the run with ``message``; it goes on at ``nxt``.
        The message names the block's own line, as a ``#3006`` stop does."""
        self.status = RunStatus.PAUSED
        self.message = message
        f = self.frames[-1]
        f.pc = nxt
        self.notes.append(Note("message", message, f.file, pc))
        return -1

    def enter_shape(self, call: ShapeCall, pc: int, nxt: int) -> int:
        """A lathe cycle naming its finishing shape (``G71 P Q``, ``G70 P Q``;
        planner/lathe_cycles.py): run the blocks N(P) to N(Q) of the program running as a level
        of their own, sharing its locals, while the planner reads them (roughing) or makes
        their moves (G70). The block N(P) is looked for after the cycle block first, then from
        the program's start; N(Q) at or after N(P). Afterwards a roughing cycle goes on after
        N(Q) when the shape follows it, a finishing cycle (or a shape elsewhere) after its
        own block."""
        caller = self.frames[-1]
        if caller.end_line >= 0:
            raise MacroAlarm(SHAPE_COMMAND, detail(f"G{call.code:g} inside the shape of another cycle",
                                                   f"在另一个循环的形状程序中指令了G{call.code:g}"))  # fmt: skip
        program = caller.found.file.program
        unit = caller.found.unit
        firsts = program.label_lines(int(call.first), unit)
        first = next((x for x in firsts if x > pc), firsts[0] if firsts else None)
        lasts = [] if first is None else [x for x in program.label_lines(int(call.last), unit) if x >= first]
        if first is None or not lasts:
            missing = call.first if first is None else call.last
            letter = "P" if first is None else "Q"
            raise MacroAlarm(CYCLE_BLOCK_NOT_FOUND,
                             detail(f"G{call.code:g}: no block N{missing:g} in this program for its {letter}",
                                    f"G{call.code:g}：本程序中没有其{letter}指定的程序段N{missing:g}"),
                             "shape-label")  # fmt: skip
        last = lasts[0]
        roughing = call.code != 70.0
        back = caller.code.next_line(last) if roughing and first > pc else nxt
        caller.pc = pc
        frame = Frame(caller.found, caller.code, first, f"G{call.code:g}", caller.locals, caller.macro_level,
                      pc, back, 0, first, end_line=last)  # fmt: skip
        self.frames.append(frame)
        return -1

    def leave_shape(self, pc: int) -> int:
        """The block N(Q) of a lathe cycle's shape is done: the planner plans the passes (or
        returns to the start point) and the run goes on where ``enter_shape`` said."""
        frame = self.frames.pop()
        end_shape(self.planner)
        self.frames[-1].pc = frame.return_pc
        return -1

    def set_modal_call(self, found: FoundProgram, arguments: Arguments, repeats: int) -> None:
        """G66: the macro is called after each later move; modal group 12 (#4012) reads 66."""
        self.modal_calls.append(
            ModalCall(
                found,
                tuple(arguments.values.items()),
                tuple(arguments.letters.items()),
                repeats,
                self.frames[-1].macro_level,
                tuple(arguments.increments.items()),
            )
        )
        self.planner.modal["macro"] = 66.0

    def cancel_modal_call(self) -> None:
        """G67: the innermost G66 ends; group 12 reads 67 once none is left."""
        if self.modal_calls:
            self.modal_calls.pop()
        if not self.modal_calls:
            self.planner.modal["macro"] = 67.0

    def modal_call(self, pc: int, nxt: int) -> int:
        """After a move while G66 is in force: call the macro, unless it is that macro moving."""
        top = self.modal_calls[-1]
        if any(f.modal is top for f in self.frames):
            return nxt
        args = Arguments(dict(top.arguments), dict(top.letters), increments=dict(top.increments))
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
