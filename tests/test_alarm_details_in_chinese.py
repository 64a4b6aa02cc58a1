"""Alarm details and notes in Chinese (docs/semantics.md §6 "Alarms and messages"): every text the
interpreter writes for an alarm or a note has its Chinese beside it, and ``cncmacro check``,
``cncmacro run``, the analysis and the debugger show the Chinese under a Chinese locale while
English stays exactly as it was. Named after the section each alarm belongs to."""

from __future__ import annotations

import ast
import copy
import io
import json
import pickle
import re
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

import cncmacro.machine
from analysis_helpers import analyse_files
from bilingual_checks import CJK, PROSE, called_name, detail_problems
from cncmacro.bilingual import detail, in_language
from cncmacro.dap.protocol import MessageWriter, Request
from cncmacro.dap.session import Session
from cncmacro.dialects import get_dialect
from running import run

MACHINE_DIR = Path(cncmacro.machine.__file__).parent
TITLES = tuple(get_dialect(name).title for name in ("fanuc", "gsk980tdi"))  # product names stay as they are

# ---------------------------------------------------------------- every site has its Chinese

MESSAGE_ARGUMENT = {"MacroAlarm": 1, "raiser": 1, "Note": 1, "note": 1, "pause": 0, "StopRequest": 0}
NOTE_LISTS = ("notes", "remarks")  # lists whose items the machine turns into notes


def message_sites(tree: ast.AST) -> Iterator[tuple[str, int, ast.expr]]:
    """(what, line, message expression) of every alarm and note the code constructs."""
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        name = called_name(node)
        if name in MESSAGE_ARGUMENT:
            k = MESSAGE_ARGUMENT[name]
            given = [kw.value for kw in node.keywords if kw.arg == "message"]
            arg = node.args[k] if len(node.args) > k else given[0] if given else None
            if arg is not None:
                yield name, node.lineno, arg
        elif name == "append" and isinstance(node.func, ast.Attribute) and node.args:
            owner = node.func.value
            owner_name = owner.id if isinstance(owner, ast.Name) else getattr(owner, "attr", None)
            arg = node.args[0]
            if owner_name in NOTE_LISTS and not (isinstance(arg, ast.Call) and called_name(arg) == "Note"):
                yield f"{owner_name}.append", node.lineno, arg


def english_outside_detail(expr: ast.expr) -> list[str]:
    """Literal text with English words in ``expr`` that is not inside a ``detail(en, zh)``."""
    found: list[str] = []

    def visit(n: ast.AST) -> None:
        if isinstance(n, ast.Call) and called_name(n) == "detail":
            return
        if isinstance(n, ast.Constant) and isinstance(n.value, str) and re.search(r"[A-Za-z]{2,}", n.value):
            found.append(n.value)
        for child in ast.iter_child_nodes(n):
            visit(child)

    visit(expr)
    return found


def problems_in(source: str, file: str) -> tuple[int, list[str]]:
    tree = ast.parse(source)
    sites = 0
    out = []
    for what, line, expr in message_sites(tree):
        sites += 1
        for text in english_outside_detail(expr):
            out.append(f"{file}:{line}: {what} message {text!r} has no Chinese (write detail(en, zh))")
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and called_name(node) == "detail":
            out += [f"{file}:{node.lineno}: {p}" for p in detail_problems(node)]
    return sites, out


def test_6_alarms_every_alarm_and_note_text_of_the_interpreter_has_chinese():
    sites = 0
    problems: list[str] = []
    for path in sorted(MACHINE_DIR.glob("*.py")):
        n, found = problems_in(path.read_text(encoding="utf-8"), path.name)
        sites += n
        problems += found
    assert problems == []
    assert sites >= 80  # the walk really sees the MacroAlarm, raiser, Note and note sites


def test_6_alarms_the_walk_catches_a_message_without_chinese():
    source = (
        "def f(n):\n"
        "    raise MacroAlarm(112, 'division by zero')\n"
        "def g(m, n):\n"
        "    m.note('call', f'L{n} is clamped', 3)\n"
        "    notes.append(detail(f'L{n} is above 9999', '超过 9999'))\n"
        "    return raiser(114, detail('illegal expression', 'illegal expression'))\n"
    )
    sites, problems = problems_in(source, "x.py")
    assert sites == 4
    assert problems == [
        "x.py:2: MacroAlarm message 'division by zero' has no Chinese (write detail(en, zh))",
        "x.py:4: note message ' is clamped' has no Chinese (write detail(en, zh))",
        "x.py:5: f'L{n} is above 9999' and '超过 9999' show different values",
        "x.py:6: no Chinese in 'illegal expression'",
        "x.py:6: English words left in 'illegal expression'",
    ]


def test_6_alarms_a_detail_is_english_wherever_it_goes_and_keeps_its_chinese():
    m = run("#1=0\n#2=5/#1\nM30\n")
    message = m.result().alarm.message
    assert message == "division by zero" and json.dumps(message) == '"division by zero"'
    for kept in (copy.deepcopy(message), pickle.loads(pickle.dumps(message)), m.snapshot().alarm.message):
        assert in_language(kept, True) == "除数为零" and in_language(kept, False) == "division by zero"
    assert type(in_language(message, False)) is str and in_language("NO TOOL", True) == "NO TOOL"
    assert in_language(detail("a", "甲"), True) == "甲"


# ---------------------------------------------------------------- the analysis in both languages


def analyse(tmp_path: Path, files: dict[str, str], dialect: str, locale: str) -> list[tuple[str, int, str]]:
    """(code, 1-based line, message) of each error and warning the analysis finds."""
    found = analyse_files(tmp_path, files, dialect, locale=locale)
    return [(d.code, d.line + 1, d.message) for d in found if d.severity in ("error", "warning")]


def assert_chinese(text: str) -> None:
    """Chinese, with no English prose left (codes, numbers, variables and product names aside)."""
    assert CJK.search(text), text
    rest = text
    for title in TITLES:
        rest = rest.replace(title, "")
    assert not PROSE.search(rest), text


# semantics.md section and what: (dialect, files, code, line, English message, Chinese title or None, Chinese detail)
CASES = {
    "5_calls_l0_repeat_count_found_by_running": (
        "fanuc",
        {"O0001.nc": "O0001\n#1=0\nG65 P9001 L#1\nM30\nO9001\nM99\n"},
        "repeat-count-range",
        3,
        "L0: the repeat count must be 1 to 9999 (alarm 119)",
        None,
        "L0：重复次数必须在 1～9999 之间（报警 119）",
    ),
    "5_calls_l0_repeat_count_written_in_the_call": (
        "fanuc",
        {"O0001.nc": "O0001\nG65 P9001 L0\nM30\nO9001\nM99\n"},
        "repeat-count-range",
        2,
        "L0: the repeat count must be 1 to 9999 (alarm 119)",
        None,
        "L0：重复次数必须在 1～9999 之间（报警 119）",
    ),
    "5_calls_l_above_9999_clamped_on_gsk980tdi_is_a_note": (
        "gsk980tdi",
        {"O0001.nc": "O0001\n#1=12000\nG65 P9001 L#1\nM30\nO9001\nM99\n"},
        "repeat-count-range",
        3,
        "L12000 is above 9999; the control runs it 9999 times",
        None,
        "L12000 超过 9999，系统按 9999 次执行",
    ),
    "4_control_flow_goto_to_a_missing_sequence_number": (
        "fanuc",
        {"O0001.nc": "O0001\n#1=99\nGOTO #1\nM30\n"},
        "undefined-label",
        3,
        "N99 not found in O0001 (alarm 128)",
        None,
        "O0001 中未找到 N99（报警 128）",
    ),
    "5_calls_macro_nesting_too_deep": (
        "fanuc",
        {"O0001.nc": "O0001\nG65 P9001\nM30\n", "O9001.nc": "O9001\nG65 P9001\nM99\n"},
        "nesting-depth",
        2,
        "more than 4 nested macro calls (G65/G66) (alarm 122); reached from O0001:2 (G65) → O9001:2 (G65) → "
        "O9001:2 (G65) → O9001:2 (G65), at block 5 of the run",
        None,
        "宏程序调用（G65/G66）嵌套超过 4 层（报警 122）；调用路径 O0001:2（G65）→O9001:2（G65）→O9001:2（G65）→"
        "O9001:2（G65），运行的第 5 个程序段",
    ),
    "3_expressions_division_by_a_vacant_divisor": (
        "fanuc",
        {"O0001.nc": "O0001\n#2=5/#1\nM30\n"},
        "division-by-zero",
        2,
        "division by zero (the divisor is vacant) (alarm 112)",
        None,
        "除数为零（除数为空变量）（报警 112）",
    ),
    "8_simulated_machine_write_to_a_read_only_system_variable": (
        "fanuc",
        {"O0001.nc": "O0001\n#1=5001\n#[#1]=1\nM30\n"},
        "write-protected",
        3,
        "#5001 is read-only (alarm 116)",
        None,
        "#5001 是只读变量，不能写入（报警 116）",
    ),
    "2_values_and_variables_a_variable_number_that_does_not_exist": (
        "fanuc",
        {"O0001.nc": "O0001\n#1=50\n#[#1]=1\nM30\n"},
        "variable-number",
        3,
        "#50 does not exist on FANUC 0i Custom Macro B (alarm 115)",
        None,
        "FANUC 0i Custom Macro B 没有变量 #50（报警 115）",
    ),
    "5_calls_more_than_ten_i_arguments": (
        "fanuc",
        {"O0001.nc": "O0001\nG65 P9001 I1 I2 I3 I4 I5 I6 I7 I8 I9 I10 I11\nM30\nO9001\nM99\n"},
        "argument-address",
        2,
        "more than 10 I arguments (alarm 129)",
        None,
        "自变量 I 超过 10 个（报警 129）",
    ),
    "5_calls_program_number_too_long_for_gsk980tdi": (
        "gsk980tdi",
        {"O0001.nc": "O0001\nG65 P12345\nM30\n"},
        "program-number",
        2,
        "P12345: a program number has at most 4 digits on GSK980TDi (alarm 291)",
        None,
        "P12345：程序号最多 4 位（GSK980TDi，报警 291）",
    ),
    "7_gsk_macro_a_h05_division_by_zero": (
        "gsk980tdi",
        {"O0001.nc": "O0001\n#1=0\nG65 H05 P#100 Q10 R#1\nM30\n"},
        "division-by-zero",
        3,
        "G65 H05: division by zero (R is 0) (alarm 112)",
        None,
        "G65 H05：除数为零（R 为 0）（报警 112）",
    ),
    "7_gsk_macro_a_h99_user_alarm": (
        "gsk980tdi",
        {"O0001.nc": "O0001\n#1=1\nIF[#1 EQ 1] GOTO 5\nM30\nN5 G65 H99 P15\nM30\n"},
        "macro-alarm",
        5,
        "the run reaches macro alarm 5915: G65 H99 P15: user alarm 5915",
        "运行到宏程序报警 5915",
        "G65 H99 P15：用户报警 5915",
    ),
}


@pytest.mark.parametrize("case", list(CASES))
def test_alarm_detail_reads_in_chinese_and_english_is_unchanged(tmp_path: Path, case: str) -> None:
    dialect, files, code, line, en, title, zh = CASES[case]
    english = analyse(tmp_path, files, dialect, "en")
    assert english == [(code, line, en)]
    [(zh_code, zh_line, message)] = analyse(tmp_path, files, dialect, "zh-CN")
    assert (zh_code, zh_line) == (code, line)
    if title is not None:
        assert message.startswith(title + "："), message
        message = message[len(title) + 1 :]
    assert message == zh
    assert_chinese(message)


# ---------------------------------------------------------------- the command line


def cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "cncmacro", *args], capture_output=True, text=True, timeout=120, encoding="utf-8"
    )


CLI_PROGRAMS = {
    "L0.nc": "O0001\n#1=0\nG65 P9001 L#1\nM30\nO9001\nM99\n",
    "GOTO.nc": "O0002\n#1=99\nGOTO #1\nM30\n",
    "NEST.nc": "O0003\nG65 P0003\nM30\n",
    "DIVIDE.nc": "O0004\n#1=0\n#2=5/#1\nM30\n",
    "READONLY.nc": "O0005\n#1=5001\n#[#1]=1\nM30\n",
    "NUMBER.nc": "O0006\n#1=50\n#[#1]=1\nM30\n",
    "ARGS.nc": "O0007\nG65 P9007 I1 I2 I3 I4 I5 I6 I7 I8 I9 I10 I11\nM30\nO9007\nM99\n",
    "H05.nc": "(cncmacro: dialect=gsk980tdi)\nO0008\n#1=0\nG65 H05 P#100 Q10 R#1\nM30\n",
}


def test_6_alarms_check_with_locale_zh_cn_writes_the_details_in_chinese(tmp_path: Path) -> None:
    for name, text in CLI_PROGRAMS.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    chinese = cli("check", "--locale", "zh-CN", str(tmp_path))
    english = cli("check", str(tmp_path))
    assert chinese.returncode == english.returncode == 1
    pattern = re.compile(r"^(.+?):(\d+):\d+: error: (.*) \[([a-z-]+)\]$")
    zh_lines = [pattern.match(line) for line in chinese.stdout.splitlines()]
    en_lines = [pattern.match(line) for line in english.stdout.splitlines()]
    assert all(zh_lines) and all(en_lines) and len(zh_lines) == len(CLI_PROGRAMS)
    zh = {Path(m.group(1)).name: (m.group(4), m.group(3)) for m in zh_lines if m}
    en = {Path(m.group(1)).name: (m.group(4), m.group(3)) for m in en_lines if m}
    assert en["L0.nc"] == ("repeat-count-range", "L0: the repeat count must be 1 to 9999 (alarm 119)")
    assert en["DIVIDE.nc"] == ("division-by-zero", "division by zero (alarm 112)")
    assert en["H05.nc"] == ("division-by-zero", "G65 H05: division by zero (R is 0) (alarm 112)")
    # the detail says what the alarm is, and the number follows it as in English: no title before it
    assert zh["L0.nc"] == ("repeat-count-range", "L0：重复次数必须在 1～9999 之间（报警 119）")
    assert zh["GOTO.nc"] == ("undefined-label", "O0002 中未找到 N99（报警 128）")
    assert zh["H05.nc"] == ("division-by-zero", "G65 H05：除数为零（R 为 0）（报警 112）")
    assert zh["DIVIDE.nc"] == ("division-by-zero", "除数为零（报警 112）")  # said once
    for name, (code, message) in zh.items():
        assert en[name][0] == code
        assert_chinese(message)
        _, _, after_title = message.partition("）：")  # the alarm's title, then its detail
        assert_chinese(after_title or message)


def test_6_alarms_run_with_locale_zh_cn_shows_the_alarm_and_notes_in_chinese(tmp_path: Path) -> None:
    f = tmp_path / "O0001.nc"
    f.write_text("(cncmacro: dialect=gsk980tdi)\nO0001\n#1=12000\nG65 P9001 L#1\n#2=0\n#3=1/#2\nM30\n"
                 "O9001\nM99\n", encoding="utf-8")  # fmt: skip
    text = cli("run", "--no-save", "--max-blocks", "100000", "--locale", "zh-CN", str(f))
    assert text.returncode == 1
    assert "提示（O0001.nc:4）：L12000 超过 9999，系统按 9999 次执行\n" in text.stdout
    assert "报警 112：除数为零\n" in text.stdout
    plain = cli("run", "--no-save", "--max-blocks", "100000", "--json", str(f))
    result = json.loads(plain.stdout)
    assert result["alarm"]["message"] == "division by zero"
    assert result["messages"] == ["L12000 is above 9999; the control runs it 9999 times"]
    localized = json.loads(cli("run", "--no-save", "--max-blocks", "100000", "--json", "--locale", "zh-CN",
                               str(f)).stdout)  # fmt: skip
    assert localized["alarm"]["message"] == "除数为零"
    assert localized["messages"] == ["L12000 超过 9999，系统按 9999 次执行"]


# ---------------------------------------------------------------- the debugger


def debug(program: Path, locale: str, *then: tuple[str, dict]) -> tuple[list[dict], dict]:
    """Run ``program`` in a debug session with ``locale`` until it stops, then send the requests
    ``then``: all the messages, and the exception info."""
    out = io.BytesIO()
    session = Session(MessageWriter(out))
    session.handle(Request(1, "initialize", {"locale": locale}))
    session.handle(Request(2, "launch", {"program": str(program), "noSave": True}))
    session.handle(Request(3, "configurationDone", {}))
    assert session.worker is not None
    session.worker.join(timeout=60)
    session.handle(Request(4, "exceptionInfo", {"threadId": 1}))
    for seq, (command, arguments) in enumerate(then, start=5):
        session.handle(Request(seq, command, arguments))
    messages = []
    data = out.getvalue()
    while data:
        header, _, rest = data.partition(b"\r\n\r\n")
        length = int(header.split(b":")[1])
        messages.append(json.loads(rest[:length].decode("utf-8")))
        data = rest[length:]
    info = next(m for m in messages if m.get("command") == "exceptionInfo")
    return messages, info["body"]


def test_6_alarms_the_debugger_stops_on_an_alarm_with_its_detail_in_the_client_language(tmp_path: Path) -> None:
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\n#1=0\nG65 P9001 L#1\nM30\nO9001\nM99\n", encoding="utf-8")
    messages, info = debug(f, "zh-CN")
    [stopped] = [m for m in messages if m.get("event") == "stopped"]
    assert stopped["body"]["reason"] == "exception"
    # the headline as `cncmacro run --locale zh-CN` prints it (one function for both)
    assert stopped["body"]["text"] == "报警 119：L0：重复次数必须在 1～9999 之间"
    assert info["description"] == "报警 119：L0：重复次数必须在 1～9999 之间"
    assert info["details"]["message"] == "L0：重复次数必须在 1～9999 之间"
    _, english = debug(f, "en")
    assert english["description"] == "ALARM 119: L0: the repeat count must be 1 to 9999"


def test_6_alarms_the_debugger_console_answers_in_the_client_language(tmp_path: Path) -> None:
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\n#1=0\nG65 P9001 L#1\nM30\nO9001\nM99\n", encoding="utf-8")
    asked = [("evaluate", {"expression": text, "context": "repl"}) for text in ("10/#1", "1+[2", "#5001=1")]

    def answers(locale: str) -> list[str]:
        messages, _ = debug(f, locale, *asked)
        return [m["message"] for m in messages if m.get("command") == "evaluate"]

    assert answers("zh-CN") == [
        "报警 112：除数为零",
        "缺少 ']'：第 3 列的 '[' 没有闭合",
        "报警 116：#5001 是只读变量，不能写入",
    ]
    assert answers("en") == [
        "alarm 112: division by zero",
        "expected ']' to close the '[' at column 3",
        "alarm 116: #5001 is read-only",
    ]


def test_6_alarms_the_debugger_console_names_a_pause_in_the_client_language(tmp_path: Path) -> None:
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\n#3006=1(MEASURE)\nM30\n", encoding="utf-8")

    def console(locale: str) -> list[str]:
        messages, _ = debug(f, locale)
        return [m["body"]["output"] for m in messages if m.get("event") == "output"
                and m["body"].get("category") == "console" and "MEASURE" in m["body"]["output"]]  # fmt: skip

    assert console("zh-CN") == ["停止（O0001.nc:2）：MEASURE\n"]  # the program's own text as written
    assert console("en") == ["stop at O0001.nc:2: MEASURE\n"]
