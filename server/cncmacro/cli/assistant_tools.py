"""What ``cncmacro mcp``'s tools answer, as plain functions of plain values (``cli/mcp_server.py``
speaks the protocol around them).

Each tool is the command line's own work, not a copy of it: ``check_program`` gives the findings
``cncmacro check --format json`` gives (``check.check_paths`` on a path; the same analysis,
``check_work.analyse_files``, on a program's text); ``run_program`` runs the machine as
``cncmacro run --json --no-save`` does (``machine.setup``, ``run.result_json``,
``cycle_report.cycle_json``) and never writes the persistent variables; ``explain`` reads the
profile's tables through ``dialects.describe``, as the editor's hover does; ``list_profiles`` is
``cncmacro profiles --json``. A program comes as a ``path`` (a file, or for a check a folder), as
``text``, or as both (the text is the content and the path names it: its folder is where calls
find their programs and its machine file applies). With text alone nothing on disk is read.

What an assistant gets back is bounded whatever the program does: a run stops at the block
budget (the machine file's ``max_blocks``, 1,000,000 by default, or a smaller one asked for) or
after ``MAX_SECONDS`` (the analysis's limit of one run), and an answer lists at most
``MAX_FINDINGS`` findings, ``max_moves`` moves (``MAX_MOVES`` by default) and ``MAX_VARIABLES``
variables, saying how many there were. Every mistake in the input (no program, a missing or
binary file, an unknown profile, with the nearest name offered) is a ``ToolInputError`` whose
text says what to do.
"""

from __future__ import annotations

import argparse
import io
import json
import re
import time
from collections.abc import Callable
from functools import partial
from itertools import islice
from pathlib import Path
from typing import Any

from ..analysis import Diagnostic
from ..analysis.runs.run_checks import MAX_SECONDS
from ..analysis.runs.subprogram_alone import subprogram_text
from ..analysis.workspace import WorkspaceAnalysis
from ..bilingual import in_language, is_chinese, pick
from ..dialects import DEFAULT_DIALECT, DIALECTS, Dialect, describe, get_dialect, nearest_dialect, normalise_dialect
from ..dialects.alarms import VARIABLE_NUMBER
from ..dialects.functions_data import GSK_H_CODES
from ..dialects.registry import profile_facts
from ..library.callee_folders import callee_folders
from ..library.files import MAX_PROGRAM_BYTES, shown_text
from ..library.machine_file import parse_preset
from ..machine import Machine
from ..machine.calls import letters_for_local
from ..machine.setup import SetupError, machine_settings, prepare_run, prepare_text_run
from ..machine.status import RunStatus
from ..planner.move_json import machine_json
from .check import check_paths
from .check_work import analyse_files
from .cycle_report import cycle_json
from .findings_report import diagnostic_json
from .locale_option import ENGLISH, locale_argument
from .run import STATUS_ZH, result_json

MAX_FINDINGS = 200
MAX_MOVES = 100
MAX_MOVES_ASKED = 5000  # the most moves one answer lists, whatever is asked
MAX_VARIABLES = 500
TEXT_NAME = "program.nc"  # what a program given only as text is called in the answers
CHUNK = 100_000  # blocks run between two looks at the clock

_VARIABLE = re.compile(r"#?\s*(\d+)")
_CODE = re.compile(r"([GM])\s*(\d+(?:\.\d)?)")
_H_CODE = re.compile(r"(?:G\s*65\s*)?H\s*(\d+)")


class ToolInputError(ValueError):
    """A tool was asked something it cannot answer; the text says why and what to give instead."""


def tool_profile(profile: str | None) -> str | None:
    """The profile's canonical name (None: the program's own choice, else the default); an unknown
    one is a ``ToolInputError`` that offers the nearest name."""
    if profile is None or not profile.strip():
        return None
    name = normalise_dialect(profile)
    if name is None:
        near = nearest_dialect(profile)
        guess = f" Did you mean {near}?" if near else ""
        raise ToolInputError(f"unknown profile {profile!r}.{guess} The profiles are {', '.join(DIALECTS)} "
                             "(list_profiles describes them).")  # fmt: skip
    return name


def tool_locale(locale: str | None) -> str:
    """``en`` or ``zh-CN`` from any spelling of either (``--locale``'s rule); English by default."""
    if locale is None or not locale.strip():
        return ENGLISH
    try:
        return locale_argument(locale)
    except argparse.ArgumentTypeError as e:
        raise ToolInputError(str(e)) from None


def _budget(max_blocks: int | None) -> None:
    if max_blocks is not None and max_blocks < 1:
        raise ToolInputError("max_blocks must be at least 1")


def _program(path: str | None, text: str | None) -> None:
    """Refuse a call that names no program, or one whose text is larger than a program file may be."""
    if (path is None or not path.strip()) and text is None:
        raise ToolInputError("give the program: a path (a file, or a folder to check) or its text")
    if text is not None and len(text) > MAX_PROGRAM_BYTES:
        raise ToolInputError(f"the program's text is longer than {MAX_PROGRAM_BYTES:,} characters: "
                             "give its path instead")  # fmt: skip


# ---------------------------------------------------------------- check
def check_program(
    path: str | None = None,
    text: str | None = None,
    profile: str | None = None,
    locale: str | None = None,
    max_blocks: int | None = None,
) -> dict[str, Any]:
    """The findings of ``cncmacro check --format json`` for a file or folder, or for a program's text."""
    dialect, loc = tool_profile(profile), tool_locale(locale)
    _budget(max_blocks)
    _program(path, text)
    if text is None:
        assert path is not None
        findings, said = _check_path(path, dialect, loc, max_blocks)
    else:
        findings = [diagnostic_json(d) for d in _check_text(text, path, dialect, loc, max_blocks)]
        said = []
    errors = sum(1 for f in findings if f["severity"] == "error")
    warnings = sum(1 for f in findings if f["severity"] == "warning")
    summary = pick(loc, f"{errors} error(s), {warnings} warning(s), {len(findings)} finding(s) in all",
                   f"{errors} 个错误，{warnings} 个警告，共 {len(findings)} 条")  # fmt: skip
    answer: dict[str, Any] = {
        "profile": dialect or DEFAULT_DIALECT,
        "summary": summary,
        "errors": errors,
        "warnings": warnings,
        "total": len(findings),
        "findings": findings[:MAX_FINDINGS],
        "cut": len(findings) > MAX_FINDINGS,
    }
    if said:  # what check says on standard error: the files it did not read, notes on the machine file
        answer["messages"] = said
    return answer


def _check_path(path: str, dialect: str | None, locale: str, max_blocks: int | None) -> tuple[list[Any], list[str]]:
    """``check_paths``'s JSON findings and what it said on standard error (files not read, notes on
    the machine file). A path that gives nothing to check (missing, binary, a bad machine file) is a
    ``ToolInputError``; a folder in which some files were not read gives its findings and names
    those files."""
    out, err = io.StringIO(), io.StringIO()
    status = check_paths([path], out, err, "json", dialect=dialect, locale=locale, max_blocks=max_blocks)
    said = [line for line in err.getvalue().splitlines() if line.strip()]
    written = out.getvalue()
    if status == 2 and (not written or not Path(path).is_dir()):
        raise ToolInputError("\n".join(said) or f"cannot check {shown_text(path)}")
    findings: list[Any] = json.loads(written) if written else []
    return findings, said


def _check_text(text: str, path: str | None, dialect: str | None, locale: str,
                max_blocks: int | None) -> list[Diagnostic]:  # fmt: skip
    """The diagnostics of ``text``, analysed as ``check`` analyses a file: under ``path``'s name,
    folder and machine file when one is given, else alone with the default settings."""
    if path is None or not path.strip():
        name, settings, folders = TEXT_NAME, None, []
    else:
        name = path
        try:
            settings = machine_settings(Path(path))
        except SetupError as e:
            raise ToolInputError(in_language(e.args[0], is_chinese(locale))) from None
        folders = callee_folders([], [Path(path)])
    workspace: Callable[[], WorkspaceAnalysis] = partial(
        WorkspaceAnalysis, settings=settings, dialect=dialect, search_paths=folders, locale=locale,
        max_blocks=max_blocks, severities=settings.severity if settings else None, workspace_folders=folders,
    )  # fmt: skip
    found = analyse_files([(Path(name), text)], workspace, locale)
    return sorted((d for d in found if d.severity != "hint"), key=Diagnostic.sort_key)


# ---------------------------------------------------------------- run
def run_program(
    path: str | None = None,
    text: str | None = None,
    profile: str | None = None,
    locale: str | None = None,
    max_blocks: int | None = None,
    max_moves: int | None = None,
    presets: list[str] | None = None,
) -> dict[str, Any]:
    """``cncmacro run --json --no-save``'s answer, bounded: a summary, the first ``max_moves``
    moves, the variables, the alarm, the output and the cycle time."""
    dialect, loc = tool_profile(profile), tool_locale(locale)
    _budget(max_blocks)
    _program(path, text)
    if max_moves is not None and max_moves < 0:
        raise ToolInputError("max_moves must be 0 or more")
    shown_moves = min(MAX_MOVES if max_moves is None else max_moves, MAX_MOVES_ASKED)
    chinese = is_chinese(loc)
    try:
        values = dict(parse_preset(s) for s in presets or [])
        if path is None or not path.strip():
            assert text is not None
            notes = []
            machine = prepare_text_run(text, TEXT_NAME, dialect=dialect, presets=values, max_blocks=max_blocks,
                                       m99_ends_main=True)  # fmt: skip
        else:
            data = None if text is None else text.encode("utf-8", errors="surrogateescape")
            prepared = prepare_run(Path(path), dialect=dialect, presets=values, max_blocks=max_blocks, data=data,
                                   saving=False, m99_ends_main=True, typed=True)  # fmt: skip
            machine, notes = prepared.machine, [in_language(n, chinese) for n in prepared.notes]
    except ValueError as e:  # SetupError, a bad preset
        said = e.args[0] if e.args else str(e)
        if path and text is None and Path(path).is_dir():
            said = pick(loc, f"{path} is a folder: run one program in it, or check the folder",
                        f"{path} 是文件夹：请运行其中的一个程序，或检查整个文件夹")  # fmt: skip
        raise ToolInputError(in_language(said, chinese)) from None
    program = machine.frames[0].name if machine.frames else Path(path or TEXT_NAME).name
    timed_out = _run_bounded(machine, machine.settings.max_blocks)
    answer = _run_answer(machine, program, Path(path or TEXT_NAME).name, loc, shown_moves, timed_out)
    answer["messages"] = [*notes, *answer["messages"]]  # what to know of the machine file first
    return answer


def _run_bounded(machine: Machine, budget: int) -> bool:
    """Run to the end, an alarm, the block budget or ``MAX_SECONDS``; pauses (``M00``, ``#3006``)
    go on as ``cncmacro run`` goes on. True when the clock stopped it."""
    deadline = time.monotonic() + MAX_SECONDS
    while True:
        left = budget - machine.blocks
        if left <= 0:
            machine.status = RunStatus.LIMIT
            return False
        status = machine.run(min(CHUNK, left), is_limit=False)
        if status != RunStatus.PAUSED:
            return False
        machine.resume()
        if time.monotonic() > deadline:
            machine.status = RunStatus.LIMIT
            return True


def _run_answer(machine: Machine, program: str, name: str, locale: str, shown_moves: int,
                timed_out: bool) -> dict[str, Any]:  # fmt: skip
    """``run --json``'s object with the moves and variables cut to what one answer lists, and a summary."""
    result = machine.result()
    dialect = machine.dialect
    body = result_json(result, dialect.axes, locale)
    moves = list(islice(body.pop("moves"), shown_moves))
    total = len(result.moves)
    variables = body.pop("variables")
    cycle = cycle_json(machine, program, locale)
    summary = _run_summary(result.status, result.blocks, total, cycle["text"], timed_out, locale)
    answer: dict[str, Any] = {**machine_json(dialect), "summary": summary}
    answer.update(body)
    answer["status"] = str(result.status)
    answer["cycle"] = cycle
    answer["movesTotal"] = total
    answer["moves"] = moves
    answer["movesCut"] = total > len(moves)
    answer["variables"] = dict(islice(variables.items(), MAX_VARIABLES))
    answer["variablesCut"] = len(variables) > MAX_VARIABLES
    if machine.ended_by_main_m99:
        answer["messages"].append(subprogram_text(Path(name), locale, "cncmacro run --repeat"))
    return answer


def _run_summary(status: str, blocks: int, moves: int, cycle: str, timed_out: bool, locale: str) -> str:
    """One sentence for the run: how it ended, after how many blocks, how many moves, its cycle time."""
    ran = f"{blocks} block" + ("" if blocks == 1 else "s")
    made = f"{moves} move" + ("" if moves == 1 else "s")
    if timed_out:
        return pick(locale, f"stopped after {MAX_SECONDS:g} s and {ran} (an endless loop?); {made}",
                    f"运行 {MAX_SECONDS:g} 秒、{blocks} 个程序段后停止（是否有死循环？）；{moves} 段运动")  # fmt: skip
    if status == RunStatus.LIMIT:
        return pick(locale, f"stopped after {ran}: the block budget ran out (an endless loop?); {made}",
                    f"执行 {blocks} 个程序段后停止：已达到程序段数上限（是否有死循环？）；{moves} 段运动")  # fmt: skip
    return pick(locale, f"{status} after {ran}; {made}; cycle time {cycle}",
                f"状态：{STATUS_ZH.get(RunStatus(status), status)}，共执行 {blocks} 个程序段；{moves} 段运动；"
                f"加工时间 {cycle}")  # fmt: skip


# ---------------------------------------------------------------- explain
def explain(subject: str, profile: str | None = None, locale: str | None = None) -> dict[str, Any]:
    """What the profile's tables say of a variable (``#5001``), a G or M code (``G71``), a GSK
    ``G65 Hm`` command (``H01``) or a function or macro word (``ATAN``, ``WHILE``)."""
    loc = tool_locale(locale)
    dialect = get_dialect(tool_profile(profile))
    said = subject.strip().upper()
    head: dict[str, Any] = {"subject": said, "profile": dialect.name, "title": dialect.title}
    found = _explain_variable(said, dialect, loc) or _explain_word(said, dialect, loc)
    if found is None:
        raise ToolInputError(
            f"{dialect.title} ({dialect.name}) documents nothing called {subject!r}: ask of a variable (#5001), "
            "a G or M code (G71, M98) or a function or macro word (ATAN, WHILE)"
        )
    return {**head, **found}


def _explain_variable(said: str, dialect: Dialect, locale: str) -> dict[str, Any] | None:
    match = _VARIABLE.fullmatch(said)
    if match is None:
        return None
    number = int(match.group(1))
    kind = describe.variable_class(number, dialect)
    answer: dict[str, Any] = {"subject": f"#{number}", "kind": kind}
    if kind == describe.SYSTEM:
        doc = describe.describe_system_variable(dialect, number, locale)
        if doc is None:
            alarm = dialect.alarm_said(VARIABLE_NUMBER)
            answer["kind"] = describe.UNDEFINED
            answer["text"] = pick(locale, f"no such variable on this control: using it raises {alarm}",
                                  f"该系统中不存在此变量：使用它会引发{alarm.zh}")  # fmt: skip
            return answer
        answer.update(text=doc.text, unit=doc.unit, access=doc.access, axis=doc.axis, group=doc.group,
                      range=[doc.first, doc.last])  # fmt: skip
    elif kind == describe.LOCAL:
        spec1, spec2 = letters_for_local(number)
        answer["text"] = pick(locale, "a local variable of the program or macro running",
                              "正在运行的程序或宏程序的局部变量")  # fmt: skip
        # the argument letter of a G65 call that fills it, in argument specification I and II
        answer["arguments"] = {"I": spec1 or None, "II": spec2 or None}
    elif kind in (describe.COMMON, describe.PERSISTENT):
        kept = kind == describe.PERSISTENT
        answer["text"] = pick(locale, f"a common variable, {'kept' if kept else 'cleared'} at power-off",
                              f"公共变量（断电{'保持' if kept else '清除'}）")  # fmt: skip
    elif kind == describe.NULL:
        answer["text"] = pick(locale, "#0: always vacant (null)", "#0：始终为空")
    else:
        alarm = dialect.alarm_said(VARIABLE_NUMBER)
        answer["text"] = pick(locale, f"no such variable on this control: using it raises {alarm}",
                              f"该系统中不存在此变量：使用它会引发{alarm.zh}")  # fmt: skip
    return answer


def _explain_word(said: str, dialect: Dialect, locale: str) -> dict[str, Any] | None:
    code = _CODE.fullmatch(said)
    if code is not None:
        doc = describe.code_doc(dialect, code.group(1), float(code.group(2)))
        if doc is None:
            return None
        return {"subject": doc.code, "kind": "code", "text": pick(locale, doc.en, doc.zh),
                "modalGroup": doc.group or None}  # fmt: skip
    h = _H_CODE.fullmatch(said)
    if h is not None and dialect.h_codes:
        name = f"H{int(h.group(1)):02d}"
        for row in GSK_H_CODES:
            if row.name == name:
                return {"subject": f"G65 {name}", "kind": "statement", "signature": row.signature,
                        "text": pick(locale, row.en, row.zh)}  # fmt: skip
        return None
    docs = describe.function_docs(dialect, said)
    if not docs:
        return None
    return {"subject": said, "kind": docs[0].kind,
            "forms": [{"signature": d.signature, "text": pick(locale, d.en, d.zh)} for d in docs]}  # fmt: skip


# ---------------------------------------------------------------- profiles
def list_profiles() -> dict[str, Any]:
    """``cncmacro profiles --json``: each profile's name, aliases, title, what machine it is."""
    return {"profiles": profile_facts()}
