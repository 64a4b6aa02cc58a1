"""One debug session: each DAP request mapped onto the machine, its breakpoints and history.

The request loop reads from standard input on the main thread; continue and the steps run
the machine on a worker thread, so pause, threads and the other requests are answered while a
long run goes on. A request that needs a stopped machine (stack trace, variables, evaluate)
is refused with a message while it runs. An unknown or malformed request gets
``success: false`` and the session goes on. Terminate and disconnect save ``#500–#999``. A
program launched on its own that ends at its M99 (a subprogram; ``repeat`` runs it again as a
control would) gets ``cncmacro run``'s sentence and its callers in the console.
``source`` and ``setBreakpoints`` read program files of the launch's folders only (see
``debugging.breakpoints.Breakpoints.read_scope``); a pipe or a device is refused, never waited on.
"""

from __future__ import annotations

import sys
import threading
from collections.abc import Callable
from functools import partial
from pathlib import Path
from typing import Any, BinaryIO

from ..analysis.runs.subprogram_alone import LAUNCH_REPEAT, subprogram_remarks
from ..bilingual import detail, pick
from ..debugging.breakpoints import Asked, Breakpoint, Breakpoints, LineBreakpoint, data_id, data_level, data_number
from ..debugging.history import History
from ..debugging.stepping import CONTINUE, STEP_IN, STEP_OUT, STEP_OVER, Filters, Stepper, Stop, last_line_run
from ..debugging.toolpath_position import next_moves, run_to_move
from ..library.files import SkippedFileError
from ..machine import Machine
from ..machine.evaluate import EvaluationError, assign, evaluate, is_assignment, set_variable
from ..machine.status import RunStatus
from ..planner.move_json import machine_json, move_json
from ..syntax.block_parser import warm_up
from . import presentation as show
from .launch import LaunchConfig, Launched, LaunchError, launch
from .protocol import Event, MessageWriter, ProtocolError, Request, Response, read_message

THREAD_ID = 1


def exception_filters(locale: str | None) -> list[dict[str, Any]]:
    """The two exception filters the Breakpoints view lists, named in the editor's language."""
    return [
        {"filter": "alarms", "label": pick(locale, "All alarms", "所有报警"), "default": True,
         "description": pick(locale, "Stop when the program raises an alarm (#3000, division by zero, ...)",
                             "程序发出报警时停止（#3000、除数为零等）")},
        {"filter": "messages", "label": pick(locale, "#3006 messages", "#3006 信息"), "default": True,
         "description": pick(locale, "Stop at #3006 operator messages and M00", "在 #3006 操作信息和 M00 处停止")},
    ]  # fmt: skip


TOOLPATH_PAGE = 100_000  # moves in one toolpath answer (about 12 MB of JSON)


class RequestFailed(Exception):
    """A request that cannot be carried out; the message goes back to the client."""


class Session:
    def __init__(self, writer: MessageWriter) -> None:
        self.writer = writer
        self.locale: str | None = None
        self.breakpoints = Breakpoints(log=lambda text: self.output(text + "\n", "console"))
        self.history = History()
        self.filters = Filters()
        self.launched: Launched | None = None
        self.stepper: Stepper | None = None
        self.configured = False
        self.started = False
        self.worker: threading.Thread | None = None
        self.busy = False  # the worker is running the machine (not just finishing)
        self.ended = False
        self.leaving = False  # terminate or disconnect asked: the halted run stops in silence
        self.last_stop: Stop | None = None
        self.told_subprogram = False  # the launched program ended at its M99, and the console says so
        self.done = False
        self._after: list[Callable[[], None]] = []
        self.warming: threading.Thread | None = None  # builds the grammar parser (see on_initialize)

    # ---------------------------------------------------------------- plumbing
    def output(self, text: str, category: str = "console") -> None:
        self.writer.send(Event("output", {"category": category, "output": text}))

    def event(self, name: str, body: dict[str, Any] | None = None) -> None:
        self.writer.send(Event(name, body))

    def handle(self, request: Request) -> None:
        handler: Callable[[dict[str, Any]], dict[str, Any] | None] | None = getattr(self, "on_" + request.command, None)
        if handler is None:
            message = f"unknown request '{request.command}'"
            self.writer.send(Response(request.seq, request.command, False, message=message))
            return
        after: list[Callable[[], None]] = []
        self._after = after
        try:
            body = handler(request.arguments)
        except RequestFailed as e:
            self.writer.send(Response(request.seq, request.command, False, message=str(e)))
            return
        except Exception as e:  # a bug must not end the session
            self.writer.send(Response(request.seq, request.command, False, message=f"internal error: {e!r}"))
            return
        self.writer.send(Response(request.seq, request.command, True, body))
        for action in after:
            action()

    def later(self, action: Callable[[], None]) -> None:
        """Run ``action`` after the response to the current request has been sent."""
        self._after.append(action)

    @property
    def running(self) -> bool:
        return self.busy

    def machine(self) -> Machine:
        if self.launched is None:
            raise RequestFailed("no program is running: launch one first")
        if self.running:
            raise RequestFailed("the program is running: pause it first")
        return self.launched.machine

    # ---------------------------------------------------------------- setting up
    def on_initialize(self, args: dict[str, Any]) -> dict[str, Any]:
        locale = args.get("locale")
        self.locale = locale if isinstance(locale, str) else None
        self.breakpoints.locale = self.locale
        self.later(lambda: self.event("initialized"))
        # the grammar parser, built while the client sets up, so that the first watch or console
        # line the fast path cannot read (an unfinished `#1 GT`, a `GOTO10`) does not wait for it
        self.warming = threading.Thread(target=warm_up, name="cncmacro-grammar", daemon=True)
        self.warming.start()
        return {
            "supportsConfigurationDoneRequest": True,
            "supportsConditionalBreakpoints": True,
            "supportsHitConditionalBreakpoints": True,
            "supportsLogPoints": True,
            "supportsFunctionBreakpoints": True,
            "supportsDataBreakpoints": True,
            "supportsEvaluateForHovers": True,
            "supportsSetVariable": True,
            "supportsRestartRequest": True,
            "supportsTerminateRequest": True,
            "supportsStepBack": True,
            "supportsExceptionInfoRequest": True,
            "exceptionBreakpointFilters": exception_filters(self.locale),
        }

    def on_launch(self, args: dict[str, Any]) -> None:
        try:
            config = LaunchConfig.from_arguments(args)
            if self.launched is not None and not self.ended:  # the first would be out of reach
                raise LaunchError(detail(
                    "a program is already running in this session: stop it (or restart) before launching another",
                    "本次调试已有程序在运行：请先停止（或重新启动）再启动另一个程序"))  # fmt: skip
            launched = launch(config)
        except LaunchError as e:
            raise RequestFailed(show.detail_text(e.args[0], self.locale)) from None
        self._use(launched)
        if self.configured:
            self.later(self._start)

    def _breakpoint_changed(self, bp: LineBreakpoint) -> None:
        self.event("breakpoint", {"reason": "changed", "breakpoint": _line_json(bp)})

    def _use(self, launched: Launched) -> None:
        self.launched = launched
        m = launched.machine
        moved = self.breakpoints.bind(m, launched.scope)
        for bp in moved:  # this launch's block delete switch and folders decide where each can stop
            self.later(partial(self._breakpoint_changed, bp))
        for fb in self.breakpoints.renamed:  # a code the launch's dialect lacks
            self.later(partial(self.event, "breakpoint", {"reason": "changed", "breakpoint": _json(fb)}))
        self.history.reset(m)
        config = launched.config
        if config.no_debug:  # Run Without Debugging: nothing stops the run
            self.stepper = Stepper(m, Breakpoints(), self.history, self.output, config.echo_motion,
                                   Filters(alarms=False, messages=False))  # fmt: skip
            self.stepper.never_stop = True
        else:
            self.stepper = Stepper(m, self.breakpoints, self.history, self.output, config.echo_motion,
                                   self.filters)  # fmt: skip
            self.stepper.stop_at_end = config.stop_at_end
        self.stepper.locale = self.locale
        self.started = False
        self.ended = False
        self.leaving = False
        self.last_stop = None
        self.told_subprogram = False

    def on_configurationDone(self, args: dict[str, Any]) -> None:
        self.configured = True
        if self.launched is not None:
            self.later(self._start)

    def _start(self) -> None:
        if self.started or self.launched is None:
            return
        self.started = True
        self.event("process", {"name": Path(self.launched.config.program).name, "startMethod": "launch"})
        if self.launched.config.stop_on_entry and not self.launched.config.no_debug:
            self._stopped(Stop("entry"))
        else:
            self._go(lambda s: s.run(CONTINUE))

    # ---------------------------------------------------------------- breakpoints
    def on_setBreakpoints(self, args: dict[str, Any]) -> dict[str, Any]:
        source = args.get("source") or {}
        path = source.get("path") if isinstance(source, dict) else None
        if not isinstance(path, str):
            raise RequestFailed("setBreakpoints needs a source with a path")
        specs = args.get("breakpoints")
        if specs is None:
            specs = [{"line": n} for n in args.get("lines") or []]
        specs = _specs(specs)
        made = self.breakpoints.set_lines(path, [_asked(s, _line(s.get("line"))) for s in specs])
        return {"breakpoints": [_line_json(bp) for bp in made]}

    def on_setFunctionBreakpoints(self, args: dict[str, Any]) -> dict[str, Any]:
        specs = _specs(args.get("breakpoints") or [])
        made = self.breakpoints.set_functions([_asked(s, str(s.get("name", ""))) for s in specs])
        return {"breakpoints": [_json(bp) for bp in made]}

    def on_setExceptionBreakpoints(self, args: dict[str, Any]) -> dict[str, Any]:
        filters = args.get("filters") or []
        if not isinstance(filters, list):
            raise RequestFailed("'filters' must be a list")
        self.filters.alarms = "alarms" in filters
        self.filters.messages = "messages" in filters
        return {"breakpoints": [{"verified": True} for _ in filters]}

    def on_dataBreakpointInfo(self, args: dict[str, Any]) -> dict[str, Any]:
        name = str(args.get("name", ""))
        number = data_number(name)  # what setDataBreakpoints takes: nothing is offered that it would refuse
        if number is None:
            return {"dataId": None, "description": f"{name} is not a # variable"}
        level = self._local_level(number, args)
        if level is None:
            what = f"#{number}"
        elif level == 0:
            what = pick(self.locale, f"#{number} of the main program", f"主程序的 #{number}")
        else:
            what = pick(self.locale, f"#{number} of macro level {level}", f"宏程序第 {level} 层的 #{number}")
        description = pick(self.locale, f"when {what} changes", f"{what}改变时")
        return {"dataId": data_id(number, level), "description": description, "accessTypes": ["write"],
                "canPersist": True}  # fmt: skip

    def _local_level(self, number: int, args: dict[str, Any]) -> int | None:
        """The macro level of the local ``#number`` asked about (docs/debugging.md): the frame's
        (``frameId``), the scope's (``variablesReference``) or the top frame's; None for any
        other variable, 0 (the main program's) when no program is paused."""
        if data_level(f"#{number}") is None:
            return None
        if self.launched is None or self.running:
            return 0
        m = self.launched.machine
        ref, frame_id = args.get("variablesReference"), args.get("frameId")
        if isinstance(frame_id, int) and 1 <= frame_id <= len(m.frames):
            index = frame_id - 1
        elif isinstance(ref, int) and ref >= 1 and show.decode_reference(ref)[0] < len(m.frames):
            index = show.decode_reference(ref)[0]
        else:
            index = len(m.frames) - 1
        return m.frames[index].macro_level if m.frames else 0

    def on_setDataBreakpoints(self, args: dict[str, Any]) -> dict[str, Any]:
        specs = _specs(args.get("breakpoints") or [])
        made = self.breakpoints.set_data([_asked(s, str(s.get("dataId", ""))) for s in specs])
        return {"breakpoints": [_json(bp) for bp in made]}

    # ---------------------------------------------------------------- running
    def _go(self, action: Callable[[Stepper], Stop]) -> None:
        stepper = self.stepper
        assert stepper is not None

        def work() -> None:
            try:
                stop = action(stepper)
            except Exception as e:  # never leave the client waiting
                self.output(f"internal error: {e!r}\n", "stderr")
                stop = Stop("exception", f"internal error: {e!r}")
            self.busy = False
            self._stopped(stop)

        stepper.arm()
        self.busy = True
        self.worker = threading.Thread(target=work, name="cncmacro-run", daemon=True)
        self.worker.start()

    def _stopped(self, stop: Stop) -> None:
        if self.ended or self.leaving:  # a run halted by terminate or disconnect: the client hears no more of it
            return
        self.last_stop = stop
        self._tell_subprogram()
        if stop.finished:
            self._finish()
            return
        body: dict[str, Any] = {"reason": stop.reason, "threadId": THREAD_ID, "allThreadsStopped": True}
        if stop.description:
            body["description"] = stop.description
        if stop.text:
            body["text"] = stop.text
        if stop.hit_ids:
            body["hitBreakpointIds"] = stop.hit_ids
        self.event("stopped", body)

    def _tell_subprogram(self) -> None:
        """A program launched on its own that ended at its M99 is a subprogram: say so once, in
        ``cncmacro run``'s words, with the programs in its folder that call it."""
        launched = self.launched
        if launched is None or self.told_subprogram or not launched.machine.ended_by_main_m99:
            return
        self.told_subprogram = True
        config = launched.config
        try:
            remarks = subprogram_remarks(launched.machine, config.program, config.dialect, self.locale, LAUNCH_REPEAT)
        except Exception as e:  # never leave the client waiting for the stop
            self.output(f"internal error: {e!r}\n", "stderr")
            return
        for remark in remarks:
            self.output(remark + "\n", "console")

    def _finish(self) -> None:
        if self.ended or self.launched is None:
            return
        self.ended = True
        problem = self.launched.save()
        if problem:
            self.output(problem + "\n", "stderr")
        m = self.launched.machine
        self.output(f"status: {m.status} after {m.blocks} blocks\n", "console")
        self.event(
            "exited", {"exitCode": {RunStatus.COMPLETED: 0, RunStatus.ALARM: 1, RunStatus.LIMIT: 3}.get(m.status, 0)}
        )
        self.event("terminated")

    def _resume(self, action: Callable[[Stepper], Stop]) -> dict[str, Any]:
        self.machine()
        if not self.started:
            raise RequestFailed("the run has not started yet (configurationDone)")
        self.later(lambda: self._go(action))
        return {"allThreadsContinued": True}

    def on_continue(self, args: dict[str, Any]) -> dict[str, Any]:
        return self._resume(lambda s: s.run(CONTINUE))

    def on_next(self, args: dict[str, Any]) -> None:
        self._resume(lambda s: s.run(STEP_OVER))

    def on_stepIn(self, args: dict[str, Any]) -> None:
        self._resume(lambda s: s.run(STEP_IN))

    def on_stepOut(self, args: dict[str, Any]) -> None:
        self._resume(lambda s: s.run(STEP_OUT))

    def on_stepBack(self, args: dict[str, Any]) -> None:
        self._resume(self._step_back)

    def on_reverseContinue(self, args: dict[str, Any]) -> None:
        self._resume(self._reverse)

    def _step_back(self, stepper: Stepper) -> Stop:
        return stepper.step_back()

    def _reverse(self, stepper: Stepper) -> Stop:
        return stepper.reverse()

    # ---------------------------------------------------------------- the toolpath view's requests
    def on_toolpath(self, args: dict[str, Any]) -> dict[str, Any]:
        """The moves run so far, a page of them: from ``start`` (0 when not given), at most
        ``limit`` (``TOOLPATH_PAGE`` when not given or larger; ``made`` counts them all, so a client
        asks for the next page from ``start`` + the moves it got), the moves of the block the run
        stands on (``current``, not run yet) and where that block is: what the toolpath view draws
        while the run is paused. No answer holds more than a page, however many moves the run made."""
        m = self.machine()
        axes = m.dialect.axes
        frame = m.frames[-1]
        line = last_line_run(m) if m.status == RunStatus.COMPLETED else frame.pc
        start = _whole(args, "start", 0)
        limit = min(_whole(args, "limit", 0) or TOOLPATH_PAGE, TOOLPATH_PAGE)
        page = m.planner.moves[start : start + limit]
        return {
            "moves": [move_json(mv, axes) for mv in page], "start": start, "made": len(m.planner.moves),
            "current": [move_json(mv, axes) for mv in next_moves(m)],
            "file": frame.file, "line": line + 1, "blocks": m.blocks, **machine_json(m.dialect),
        }  # fmt: skip

    def on_runToMove(self, args: dict[str, Any]) -> dict[str, Any]:
        """Run (forward or back) to the block that makes move ``index`` of the run (0-based)."""
        index = args.get("index")
        if not isinstance(index, int) or isinstance(index, bool) or index < 0:
            raise RequestFailed("runToMove needs the 'index' of a move (0 for the first)")
        return self._resume(lambda s: run_to_move(s, index))

    def on_pause(self, args: dict[str, Any]) -> None:
        if self.stepper is not None and self.running:
            self.stepper.request_pause()

    def on_restart(self, args: dict[str, Any]) -> None:
        if self.launched is None:
            raise RequestFailed("no program to restart")
        self._halt()
        self._save()
        new_args = args.get("arguments")
        try:
            config = LaunchConfig.from_arguments(new_args) if isinstance(new_args, dict) else self.launched.config
            launched = launch(config)
        except LaunchError as e:
            raise RequestFailed(show.detail_text(e.args[0], self.locale)) from None
        self._use(launched)
        self.later(self._start)

    def _halt(self) -> None:
        if self.stepper is not None and self.running:
            self.stepper.request_pause()
        if self.worker is not None:
            self.worker.join()

    def _save(self) -> None:
        if self.launched is not None and not self.ended:
            problem = self.launched.save()
            if problem:
                self.output(problem + "\n", "stderr")

    def on_terminate(self, args: dict[str, Any]) -> None:
        self.leaving = True
        self._halt()
        self._save()
        self.ended = True
        self.later(lambda: self.event("terminated"))

    def on_disconnect(self, args: dict[str, Any]) -> None:
        self.leaving = True
        self._halt()
        self._save()
        self.ended = True
        self.done = True

    # ---------------------------------------------------------------- looking at a stopped run
    def on_threads(self, args: dict[str, Any]) -> dict[str, Any]:
        name = "main program"
        if self.launched is not None:
            name = Path(self.launched.config.program).name
        return {"threads": [{"id": THREAD_ID, "name": name}]}

    def on_stackTrace(self, args: dict[str, Any]) -> dict[str, Any]:
        m = self.machine()
        frames = show.stack_frames(m)
        if m.status == RunStatus.COMPLETED and frames:  # stopped at the end: show the block that ended the run
            frames[0]["line"] = last_line_run(m) + 1
        start = _whole(args, "startFrame", 0)
        levels = _whole(args, "levels", 0) or len(frames)
        return {"stackFrames": frames[start : start + levels], "totalFrames": len(frames)}

    def _level(self, frame_id: Any) -> int:
        m = self.machine()
        if frame_id is None:
            return len(m.frames) - 1
        if not isinstance(frame_id, int) or not 1 <= frame_id <= len(m.frames):
            raise RequestFailed(f"no stack frame {frame_id}")
        return frame_id - 1

    def on_scopes(self, args: dict[str, Any]) -> dict[str, Any]:
        level = self._level(args.get("frameId"))
        return {"scopes": show.scopes(self.machine(), level, self.locale)}

    def _scope(self, ref: Any) -> tuple[Machine, int, int, int]:
        m = self.machine()
        if not isinstance(ref, int) or isinstance(ref, bool) or ref < 1:
            raise RequestFailed(f"no variables reference {ref}")
        level, scope, group = show.decode_reference(ref)
        if level >= len(m.frames) or scope > show.OFFSETS or not show.has_group(m, scope, group):
            raise RequestFailed(f"no variables reference {ref}")
        return m, level, scope, group

    def on_variables(self, args: dict[str, Any]) -> dict[str, Any]:
        """A scope's variables, or the rows of its hundreds and a hundred's variables (a large
        Common or Persistent scope); ``start`` and ``count`` page them. Every row is a named
        variable: a client asking for ``indexed`` ones gets none."""
        m, level, scope, group = self._scope(args.get("variablesReference"))
        if args.get("filter") == "indexed":
            return {"variables": []}
        shown = show.children(m, level, scope, group, self.locale)
        start = _whole(args, "start", 0)
        count = _whole(args, "count", 0) or len(shown)
        return {"variables": shown[start : start + count]}

    def on_setVariable(self, args: dict[str, Any]) -> dict[str, Any]:
        m, level, _scope, _group = self._scope(args.get("variablesReference"))
        name = str(args.get("name", ""))
        number = show.variable_number(name)
        if number is None:
            raise RequestFailed(f"'{name}' is not a # variable")
        text = str(args.get("value", ""))
        try:
            value = set_variable(m, number, "" if show.is_vacant_text(text) else text, level)
        except EvaluationError as e:
            raise RequestFailed(f"#{number} = {text}: {show.detail_text(e.args[0], self.locale)}") from None
        self.history.mark(m)
        self.breakpoints.prime()
        return {"value": show.show(value, self.locale), "variablesReference": 0}

    def on_evaluate(self, args: dict[str, Any]) -> dict[str, Any]:
        text = args.get("expression")
        if not isinstance(text, str) or not text.strip():
            raise RequestFailed("nothing to evaluate")
        m = self.machine()
        level = self._level(args.get("frameId"))
        try:
            if args.get("context") == "repl" and is_assignment(text):
                number, value = assign(m, text, level)
                self.history.mark(m)
                self.breakpoints.prime()
                return {"result": f"#{number} = {show.show(value, self.locale)}", "variablesReference": 0}
            value = evaluate(m, text, level)
        except EvaluationError as e:
            raise RequestFailed(show.detail_text(e.args[0], self.locale)) from None
        return {"result": show.show(value, self.locale), "variablesReference": 0}

    def on_exceptionInfo(self, args: dict[str, Any]) -> dict[str, Any]:
        m = self.machine()
        if m.alarm is None:
            stop = self.last_stop
            text = stop.description if stop and stop.description else "no alarm"
            return {"exceptionId": "stop", "description": text, "breakMode": "always"}
        a = m.alarm
        message = show.detail_text(a.message, self.locale)
        chain = "\n".join(f"{c.program} ({c.how}) at {Path(c.file).name}:{c.line + 1}" for c in reversed(a.chain))
        return {
            "exceptionId": a.words(), "description": a.headline(self.locale), "breakMode": "always",
            "details": {"message": message, "typeName": a.words(), "stackTrace": chain},
        }  # fmt: skip

    def on_source(self, args: dict[str, Any]) -> dict[str, Any]:
        source = args.get("source") or {}
        path = source.get("path") if isinstance(source, dict) else None
        if not isinstance(path, str):
            raise RequestFailed("the source has no path")
        try:  # program files in the launch's folders only, never a pipe or a device
            text = self.breakpoints.read_scope(path).read(path).text
        except SkippedFileError as e:
            raise RequestFailed(show.detail_text(e.message, self.locale)) from None
        except OSError as e:
            raise RequestFailed(f"cannot read {path}: {e.strerror or e}") from None
        return {"content": text.encode("utf-8", "replace").decode("utf-8")}  # bytes no encoding took stay '?'


def _line(line: Any) -> int | None:
    """The 0-based line of a DAP SourceBreakpoint's ``line`` (1-based), None when it is no number."""
    return line - 1 if isinstance(line, int) and not isinstance(line, bool) else None


def _specs(specs: object) -> list[dict[str, Any]]:
    """A request's ``breakpoints``: a list of objects, else the request fails."""
    if not isinstance(specs, list) or not all(isinstance(s, dict) for s in specs):
        raise RequestFailed("'breakpoints' must be a list of objects")
    return specs


def _asked(spec: dict[str, Any], place: int | str | None) -> Asked:
    """A DAP SourceBreakpoint, FunctionBreakpoint or DataBreakpoint as the debugger takes it."""
    return Asked(place, spec.get("condition"), spec.get("hitCondition"), spec.get("logMessage"))


def _json(bp: Breakpoint, **more: Any) -> dict[str, Any]:
    """A breakpoint as DAP shows it: its id, whether it is verified, and why not."""
    out: dict[str, Any] = {"id": bp.id, "verified": bp.verified, **more}
    if bp.message:
        out["message"] = bp.message
    return out


def _line_json(bp: LineBreakpoint) -> dict[str, Any]:
    """A line breakpoint as DAP shows it: where it really stops (1-based), or why not."""
    if bp.line is None:
        return _json(bp)
    return _json(bp, line=bp.line + 1, source={"name": Path(bp.shown_path).name, "path": bp.shown_path})


def _whole(args: dict[str, Any], name: str, default: int) -> int:
    value = args.get(name, default)
    if value is None:
        return default
    if not isinstance(value, int) or isinstance(value, bool) or value < 0:
        raise RequestFailed(f"'{name}' must be a whole number of at least 0")
    return value


def serve(stdin: BinaryIO | None = None, stdout: BinaryIO | None = None) -> int:
    """Answer requests until the client disconnects or the input ends."""
    reader = stdin or sys.stdin.buffer
    writer = MessageWriter(stdout or sys.stdout.buffer)
    session = Session(writer)
    while not session.done:
        try:
            request = read_message(reader)
        except ProtocolError as e:
            if e.seq is not None:
                writer.send(Response(e.seq, e.command or "", False, message=str(e)))
            else:
                session.output(f"cncmacro dap: {e}\n", "stderr")
            if e.fatal:
                return 1
            continue
        if request is None:
            break
        session.handle(request)
    session._halt()
    session._save()
    return 0
