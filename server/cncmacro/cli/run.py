"""``cncmacro run``: run a program on the simulated machine and show what it did.

The text output is for a machinist: the moves (each with every axis the program has
commanded so far, ``machine/commanded_axes.py``), anything the program printed or stopped
with, the alarm and where it came from, and the final variables. A program that ends in M99,
run on its own, is a subprogram: the run stops at that M99 after one pass and says so, naming
the programs in its folder that call it (``--repeat`` runs it again and again, as a control
runs a main program that ends in M99). ``--json`` prints docs/design.md's
object. ``--locale zh-CN`` writes the text output in Chinese, its fixed words and the
interpreter's alarm details and notes alike (in the JSON only the details and notes: its keys
and status words are a contract and stay English). Exit status: 0 when the program completed, 1 on
an alarm, 3 when the block budget ran out (a likely endless loop), 2 on bad usage or a FILE
that is no readable program (a folder, a missing, binary or unreadable file: said in a
sentence) or an unreadable machine file (and when another run or debug session kept the persistent
variables for longer than ``--wait`` seconds). Texts go to the terminal through ``terminal``:
control characters in them are shown escaped, never sent raw.
"""

from __future__ import annotations

import argparse
import signal
import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any, TextIO

from ..analysis.runs.subprogram_alone import subprogram_remarks, subprogram_text
from ..bilingual import in_language, is_chinese, pick
from ..library.machine_file import parse_preset
from ..library.persistence_lock import LOCK_WAIT
from ..machine import Machine, RunResult
from ..machine.alarms import budget_spent
from ..machine.binary_output import BPRNT
from ..machine.commanded_axes import CommandedAxes
from ..machine.setup import prepare_run
from ..machine.status import RunStatus
from ..planner.move_json import machine_json, move_json
from ..planner.moves import Move
from ..planner.numbers import format_plain
from .cycle_report import cycle_json, write_cycle_text
from .locale_option import add_locale_option
from .process_end import keep_to_the_end
from .profiles import add_dialect_option
from .terminal import Printable, TextOut, json_text

MAX_TEXT_MOVES = 1000
STATUS_ZH = {
    RunStatus.COMPLETED: "完成",
    RunStatus.ALARM: "报警",
    RunStatus.LIMIT: "达到程序段数上限",
    RunStatus.STOPPED: "停止",
}


def add_run_parser(sub: Any) -> None:
    run = sub.add_parser(
        "run",
        help="run a program on the simulated machine",
        description="Run a program on the simulated machine: the moves it makes, its alarms and its final variables.",
    )
    run.add_argument("file", metavar="FILE", help="the program to run")
    add_dialect_option(run, "over the machine file's (a file's own dialect comment still wins)")
    run.add_argument(
        "--path", action="append", default=[], metavar="DIR", help="another folder where called programs are looked up"
    )
    run.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="N=VALUE",
        help="preset a variable, e.g. --set 100=5 or --set 2001=0.5",
    )
    run.add_argument("--machine", metavar="FILE", help="machine settings (default: the nearest .cncmacro.toml)")
    run.add_argument("--max-blocks", type=int, metavar="N", help="stop after N blocks (default 1000000)")
    run.add_argument("--json", action="store_true", help="print the result as JSON")
    add_locale_option(run, "the text output, alarm details and notes")
    run.add_argument(
        "--no-save", action="store_true", help="do not write #500-#999 back to the persistent-variable file"
    )
    run.add_argument(
        "--wait", type=float, default=LOCK_WAIT, metavar="SECONDS",
        help="how long to wait for another run or debug session that is using the persistent variables "
             f"(default {LOCK_WAIT:g})",
    )  # fmt: skip
    run.add_argument(
        "--repeat", action="store_true",
        help="run a program that ends in M99 again from its start each time, as a control runs a main program "
             "(by default a subprogram run on its own stops at its M99 after one pass)",
    )  # fmt: skip
    run.add_argument(
        "--stdin", action="store_true",
        help="read the program from standard input (an editor's unsaved text); FILE still names it",
    )  # fmt: skip
    run.set_defaults(handler=main_run)


def main_run(args: argparse.Namespace, out: TextIO | None = None, err: TextIO | None = None) -> int:
    """Run the program; text goes to ``out`` with control characters escaped. Ctrl-C, and a
    ``SIGTERM`` or ``SIGHUP`` (a closed terminal), end the run through its clean-up: the lock
    of the persistent variables is let go and its file deleted."""
    with _ended_cleanly():
        return _run(args, out, err)


@contextmanager
def _ended_cleanly() -> Iterator[None]:
    """While the run lasts, ``SIGTERM`` and ``SIGHUP`` raise ``SystemExit(128 + signal)`` as
    Ctrl-C raises ``KeyboardInterrupt``, so that ``finally`` and ``except`` blocks run; the
    handlers before are put back after (only the main thread may set them)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    names = [getattr(signal, n) for n in ("SIGTERM", "SIGHUP") if hasattr(signal, n)]
    before = {n: signal.signal(n, _exit_on_signal) for n in names}
    try:
        yield
    finally:
        for n, handler in before.items():
            signal.signal(n, handler)


def _exit_on_signal(number: int, frame: object) -> None:
    raise SystemExit(128 + number)


def _run(args: argparse.Namespace, out: TextIO | None, err: TextIO | None) -> int:
    out = out or sys.stdout
    shown_err = Printable(err or sys.stderr)
    path = Path(args.file)
    if args.max_blocks is not None and args.max_blocks < 1:
        print(pick(args.locale, "cncmacro run: --max-blocks must be at least 1", "cncmacro run：--max-blocks 至少为 1"),
              file=shown_err)  # fmt: skip
        return 2
    if not 0 <= args.wait <= 86400:
        print(pick(args.locale, "cncmacro run: --wait must be from 0 to 86400 seconds",
                   "cncmacro run：--wait 必须在 0 到 86400 秒之间"), file=shown_err)  # fmt: skip
        return 2
    try:
        presets = dict(parse_preset(s) for s in args.set)
        prepared = prepare_run(
            path, machine_file=args.machine, dialect=args.dialect, presets=presets,
            search_paths=[Path(p) for p in args.path], data=sys.stdin.buffer.read() if args.stdin else None,
            saving=not args.no_save, wait=args.wait, m99_ends_main=not args.repeat, typed=True,
        )  # fmt: skip
    except ValueError as e:
        if not args.stdin and path.is_dir():
            print(_folder_text(path, args.locale), file=shown_err)
        elif is_chinese(args.locale) and e.args:
            print(f"cncmacro run：{in_language(e.args[0], True)}", file=shown_err)
        else:
            print(f"cncmacro run: {e}", file=shown_err)
        return 2
    for note in prepared.notes:
        print(f"cncmacro：注意：{note.zh}" if is_chinese(args.locale) else f"cncmacro: note: {note}", file=shown_err)
    machine = prepared.machine
    machine.planner.centre_paths = args.json  # the text shows the programmed moves, never a tool centre path
    dialect = machine.dialect
    program = machine.frames[0].name if machine.frames else path.name
    budget = args.max_blocks if args.max_blocks is not None else machine.settings.max_blocks
    try:
        while True:
            status = machine.run(budget - machine.blocks)  # 0 left (a pause on the last block): limit
            if status != RunStatus.PAUSED:
                break
            machine.resume()  # M00 and #3006 pause a machine; a simulation goes on
    except BaseException:
        prepared.release()
        raise
    if getattr(args, "ends_process", False):  # the run's records stay until the process ends
        keep_to_the_end()
    if not args.no_save:
        try:
            prepared.save()
        except OSError as e:
            print(pick(args.locale, f"cncmacro run: could not save the persistent variables: {e}",
                       f"cncmacro run：无法保存断电保持的公共变量（#500–#999）：{e}"), file=shown_err)  # fmt: skip
    result = machine.result()
    if args.json:
        head = machine_json(dialect)
        body = result_json(result, dialect.axes, args.locale)
        body["cycle"] = cycle_json(machine, program, args.locale)
        if machine.ended_by_main_m99:  # the sentence only: a toolpath refresh does not search the folder
            body["messages"].append(subprogram_text(path, args.locale))
        write_json({**head, **body}, out)
    else:
        remarks = subprogram_remarks(machine, path, args.dialect, args.locale) if machine.ended_by_main_m99 else []
        write_text(result, machine, Printable(out), args.locale, remarks)
        write_cycle_text(machine, program, Printable(out), args.locale)
    return {RunStatus.ALARM: 1, RunStatus.LIMIT: 3}.get(result.status, 0)


def _folder_text(path: Path, locale: str | None) -> str:
    """What to do when FILE names a folder: run one program in it, or check them all."""
    one = path / "FILE"
    return pick(locale,
                f"cncmacro run: {path} is a folder, not a program file: run one of the programs in it "
                f"(cncmacro run {one}), or check them all with cncmacro check {path}",
                f"cncmacro run：{path} 是文件夹，不是程序文件：请运行其中的一个程序（cncmacro run {one}），"
                f"或用 cncmacro check {path} 检查其中的全部程序")  # fmt: skip


def result_json(result: RunResult, axes: tuple[str, ...], locale: str | None = None) -> dict[str, Any]:
    chinese = is_chinese(locale)
    alarm = None
    if result.alarm is not None:
        a = result.alarm
        alarm = {
            "number": a.shown,  # null where the control documents no number (Haas)
            "message": in_language(a.message, chinese),
            "file": a.file,
            "line": a.line + 1,
            "chain": [{"program": c.program, "file": c.file, "line": c.line + 1, "how": c.how} for c in a.chain],
        }
    return {
        "status": result.status,
        "alarm": alarm,
        "blocks": result.blocks,
        "variables": {str(k): v for k, v in result.variables.items()},
        "moves": _moves_json(result, axes),
        "output": [in_language(text, chinese) for text in result.output],  # a BPRNT record's words in Chinese
        "messages": [in_language(n.message, chinese) for n in result.notes if n.kind in _MESSAGE_KINDS],
    }


_MESSAGE_KINDS = ("message", "call", "feed", "limits", "simulation")  # the notes ``--json`` lists as messages


def _moves_json(result: RunResult, axes: tuple[str, ...]) -> Iterator[dict[str, Any]]:
    """The moves for ``--json``, one at a time (``write_json`` writes each as it comes, so a
    run's JSON is never held whole); a G31's also says whether the skip signal came on (``skip``)."""
    hits = {probe.move: probe.hit for probe in result.probes}
    for k, mv in enumerate(result.moves):
        out = move_json(mv, axes)
        if k in hits:
            out["skip"] = hits[k]
        yield out


def write_json(result: dict[str, Any], out: TextIO) -> None:
    """``result`` as indented JSON, but one move to a line: a long run's moves stay readable
    (and diffable) and are written by the fast compact encoder (100k moves in a fraction of a
    second instead of seconds), each as it is made, never the whole text at once."""
    out.write("{\n")
    items = list(result.items())
    for k, (key, value) in enumerate(items):
        out.write(f" {json_text(key)}: ")
        if key == "moves":
            out.write("[")
            first = True
            for mv in value:
                out.write(("\n  " if first else ",\n  ") + json_text(mv))
                first = False
            out.write("]" if first else "\n ]")
        else:
            out.write(json_text(value, indent=1).replace("\n", "\n "))
        out.write(",\n" if k < len(items) - 1 else "\n")
    out.write("}\n")


def write_text(
    result: RunResult, machine: Machine, out: TextOut, locale: str | None = None, remarks: list[str] | None = None
) -> None:
    """The run for a machinist, in English or (``zh`` locale) in Chinese: codes, file names,
    numbers and the texts the program itself wrote stay as they are; ``remarks`` (already in
    the locale's language) come before the status line."""
    chinese = is_chinese(locale)
    axes = machine.dialect.axes
    moves = result.moves
    if moves:
        print(f"运动（{len(moves)} 段）：" if chinese else f"moves ({len(moves)}):", file=out)
        commanded = CommandedAxes(machine)  # every axis the program has named so far, even at 0
        head = moves if len(moves) <= MAX_TEXT_MOVES else moves[: MAX_TEXT_MOVES // 2]
        for mv in head:
            out.write(_move_line(mv, axes, commanded.shown(mv)))
        if len(head) < len(moves):
            rest = moves[-MAX_TEXT_MOVES // 2 :]
            more = len(moves) - len(head) - len(rest)
            commanded.absorb(moves[len(head) : len(moves) - len(rest)])
            print(f"  …… 另有 {more} 段运动 ……" if chinese else f"  ... {more} more moves ...", file=out)
            for mv in rest:
                out.write(_move_line(mv, axes, commanded.shown(mv)))
    for note in result.notes:
        where = f"{Path(note.file).name}:{note.line + 1}"
        text = in_language(note.message, chinese)
        if note.kind == "output" and note.subject == BPRNT:  # says itself what it is (machine/binary_output.py)
            print(text, file=out)
        elif note.kind == "output":
            print(f"DPRNT  {note.message}", file=out)
        elif note.kind == "message":
            print(f"停止（{where}）：{text}" if chinese else f"stop at {where}: {text}", file=out)
        elif note.kind in ("call", "skip", "feed", "limits", "simulation"):
            print(f"提示（{where}）：{text}" if chinese else f"note at {where}: {text}", file=out)
    if result.alarm is not None:
        a = result.alarm
        print(a.headline(locale), file=out)
        for place in a.places(locale):
            print(place, file=out)
    elif result.status == RunStatus.LIMIT:
        print(budget_spent(result.blocks, locale), file=out)
    for remark in remarks or ():
        print(remark, file=out)
    if chinese:
        print(f"状态：{STATUS_ZH.get(result.status, result.status)}，共执行 {result.blocks} 个程序段", file=out)
    else:
        noun = "block" if result.blocks == 1 else "blocks"
        print(f"status: {result.status} after {result.blocks} {noun}", file=out)
    if result.variables:
        print("变量：" if chinese else "variables:", file=out)
        for n, v in result.variables.items():
            print(f"  #{n} = {format_plain(v)}", file=out)


def _move_line(mv: Move, axes: tuple[str, ...], shown: list[int]) -> str:
    return f"  {Path(mv.file).name}:{mv.line + 1:<5} {mv.text(axes, shown)}\n"
