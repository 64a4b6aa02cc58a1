"""Syntax problems and the command line's own words in Chinese (docs/semantics.md §1 "Text and
blocks"): every message the parser writes for a line it cannot read has its Chinese beside it;
``cncmacro check --locale zh-CN`` and the analysis in a Chinese locale show it, ``cncmacro run
--locale zh-CN`` writes its whole text output in Chinese, and English stays exactly as it was."""

from __future__ import annotations

import ast
import io
import logging
import pickle
import re
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

import cncmacro.syntax
from bilingual_checks import CJK, PROSE, QUOTED, called_name, detail_problems, literal_parts
from cncmacro.analysis.indexes.call_index import CallIndex
from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.bilingual import in_language
from cncmacro.cli.check import check_paths
from cncmacro.dialects import choices_text
from cncmacro.library.machine_file import MachineSettings
from cncmacro.syntax.block_parser import parse_block
from cncmacro.syntax.nodes import Block, Problem

SYNTAX_DIR = Path(cncmacro.syntax.__file__).parent

# ---------------------------------------------------------------- every message has its Chinese

MAKERS = {"Problem": 0, "BlockError": 0}  # what takes a message, and the position of the message


def _detail_names(tree: ast.Module) -> set[str]:
    """Names that hold a ``Detail``: names every assignment of which is a ``detail(...)`` (alone
    or in a tuple), and parameters annotated ``Detail``."""
    made: dict[str, bool] = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Assign):
            v = node.value
            parts = v.elts if isinstance(v, ast.Tuple) else [v]
            for target in node.targets:
                if isinstance(target, ast.Name):
                    ok = all(called_name(p) in ("detail", "Detail") for p in parts)
                    made[target.id] = made.get(target.id, True) and ok
    names = {name for name, ok in made.items() if ok}
    for node in ast.walk(tree):
        if isinstance(node, ast.arg) and node.annotation is not None and ast.unparse(node.annotation) == "Detail":
            names.add(node.arg)
    return names


def message_sites(tree: ast.Module) -> Iterator[tuple[int, ast.expr]]:
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in MAKERS:
            k = MAKERS[node.func.id]
            given = [kw.value for kw in node.keywords if kw.arg == "message"]
            arg = node.args[k] if len(node.args) > k else given[0] if given else None
            if arg is not None:
                yield node.lineno, arg


def problems_in(source: str, file: str) -> tuple[int, list[str]]:
    """(how many messages are made, what is wrong with them) in one module of the syntax layer."""
    tree = ast.parse(source)
    held = _detail_names(tree)
    sites = 0
    out: list[str] = []
    for line, arg in message_sites(tree):
        sites += 1
        ok = (
            called_name(arg) == "detail"
            or (isinstance(arg, ast.Name) and arg.id in held)
            or (isinstance(arg, ast.Attribute) and arg.attr == "message")  # a BlockError's, checked below
        )
        if not ok:
            out.append(f"{file}:{line}: message {ast.unparse(arg)} has no Chinese (write detail(en, zh))")
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and called_name(node) == "detail":
            out += [f"{file}:{node.lineno}: {p}" for p in detail_problems(node)]
        elif isinstance(node, ast.Call) and called_name(node) == "Detail":
            for a in node.args:
                lit = literal_parts(a)
                if lit is not None and PROSE.search(lit[0]):
                    out.append(f"{file}:{node.lineno}: write detail(en, zh) for {ast.unparse(a)}")
        elif isinstance(node, ast.Dict):  # a table of names, such as the terminals lark expects
            for v in node.values:
                lit = literal_parts(v) if v is not None else None
                if lit is not None and PROSE.search(lit[0]):
                    out.append(f"{file}:{v.lineno}: {ast.unparse(v)} has no Chinese (write detail(en, zh))")
        elif isinstance(node, ast.ClassDef) and node.name == "BlockError":
            init = next(f for f in node.body if isinstance(f, ast.FunctionDef) and f.name == "__init__")
            message = next(a for a in init.args.args if a.arg == "message")
            if message.annotation is None or ast.unparse(message.annotation) != "Detail":
                out.append(f"{file}:{init.lineno}: BlockError's message must be a Detail")
    return sites, out


def test_1_text_and_blocks_every_syntax_message_has_chinese():
    sites = 0
    problems: list[str] = []
    for path in sorted(SYNTAX_DIR.glob("*.py")):
        n, found = problems_in(path.read_text(encoding="utf-8"), path.name)
        sites += n
        problems += found
    assert problems == []
    assert sites >= 20  # the walk really sees the Problem and BlockError sites


def test_1_text_and_blocks_the_walk_catches_a_message_without_chinese():
    source = (
        "_NAMES = {'NUMBER': 'a number', 'HASH': \"'#'\", 'FUNC': detail('a function', '函数')}\n"
        "_GOOD = detail('comment not closed', '注释没有结束')\n"
        "class BlockError(Exception):\n"
        "    def __init__(self, message: str, start: int, end: int) -> None:\n"
        "        self.message = message\n"
        "def f(code, n, said: Detail, err):\n"
        "    a = Problem('the block does not parse', 0, 1)\n"
        "    b = Problem(f'unexpected {code}', 0, 1)\n"
        "    c = Problem(detail(f'column {n}', f'第 {n} 列 column'), 0, 1)\n"
        "    d = Problem(detail(f'column {n}', '第几列'), 0, 1)\n"
        "    e = Problem(detail('the end', 'the end'), 0, 1)\n"
        "    raise BlockError(detail(f'at {code}', f'位于 {code.zh}'), 0, 1)\n"
        "    return [Problem(_GOOD, 0, 1), Problem(said, 0, 1), Problem(err.message, 0, 1), Detail('one word', '')]\n"
    )
    sites, problems = problems_in(source, "x.py")
    assert sites == 9
    assert sorted(problems) == sorted([
        "x.py:7: message 'the block does not parse' has no Chinese (write detail(en, zh))",
        "x.py:8: message f'unexpected {code}' has no Chinese (write detail(en, zh))",
        "x.py:9: English words left in f'第 {n} 列 column'",
        "x.py:10: f'column {n}' and '第几列' show different values",
        "x.py:11: no Chinese in 'the end'",
        "x.py:11: English words left in 'the end'",
        "x.py:13: write detail(en, zh) for 'one word'",
        "x.py:1: 'a number' has no Chinese (write detail(en, zh))",
        "x.py:4: BlockError's message must be a Detail",
    ])  # fmt: skip


# ---------------------------------------------------------------- malformed lines in both languages

# What: (the line, English message, Chinese message). Each is line 2 of a small program.
CASES = {
    "unclosed_bracket": (
        "#1=[1+2", "expected ']' to close the '[' at column 4", "缺少 ']'：第 4 列的 '[' 没有闭合",
    ),
    "closing_bracket_without_an_opening_one": (
        "#2=1+2]", "']' without a matching '['", "']' 没有与之配对的 '['",
    ),
    "address_without_a_value": (
        "G01 X1.0 Y-", "the block ends too early; expected a value (a number, #variable or [expression])",
        "程序段提前结束；应为数值（数字、#变量或 [表达式]）",
    ),
    "value_without_an_address": (
        "G01 5", "unexpected number '5': an address letter such as X must come before a value",
        "此处不应出现数值 '5'：数值之前必须有地址字母，如 X",
    ),
    "assignment_without_equals": (
        "G01 X1 #1", "the block ends too early; expected '='", "程序段提前结束；应为 '='",
    ),
    "line_too_long": (
        "X1 " * 1400, "block of 4200 characters is too long to be a program line (at most 4096); not read",
        "程序段长 4200 个字符，超出一行程序的上限（最多 4096 个字符），未读取",
    ),
    "unknown_function": (
        "#4=FOO[1]", "unexpected 'F'; expected a value (a number, #variable or [expression])",
        "此处不应出现 'F'；应为数值（数字、#变量或 [表达式]）",
    ),
    "do_without_a_number": (
        "WHILE[#1 LT 3] DO", "the block ends too early; expected a number", "程序段提前结束；应为数值",
    ),
    "stray_character": (
        "G01 X1 @", "unexpected '@'; expected another word or statement", "此处不应出现 '@'；应为其他代码字或宏语句",
    ),
    "hash_without_a_number": (
        "#=1", "unexpected '='; expected '['", "此处不应出现 '='；应为 '['",
    ),
    "comparison_outside_a_condition": (
        "#5=1 GT 2", "the comparison 'GT' is allowed only inside the [ ] of an IF or WHILE condition",
        "关系运算符 'GT' 只能用在 IF 或 WHILE 条件的 [ ] 中",
    ),
    "comparison_in_brackets_outside_a_condition": (
        "#1=[1 LT 2]", "the comparison 'LT' is allowed only in an IF or WHILE condition (alarm 114)",
        "关系运算符 'LT' 只能用在 IF 或 WHILE 的条件中（报警 114）",
    ),
    "conditions_joined_without_brackets": (
        "IF[#1 GT 1 AND #2 LT 3] GOTO 10", "unexpected comparison 'LT': join conditions as [[a EQ b] AND [c EQ d]]",
        "此处不应出现关系运算符 'LT'：多个条件应写成 [[a EQ b] AND [c EQ d]]",
    ),
    "condition_without_a_comparison": (
        "IF[#1] GOTO 5", "the condition needs a comparison such as [#1 GT 0] (EQ NE GT GE LT LE)",
        "条件中需要关系运算，例如 [#1 GT 0]（EQ NE GT GE LT LE）",
    ),
    "condition_joined_to_a_bare_value": (
        "IF[[#1 GT 1] AND #2] GOTO 5",
        "conditions are joined with AND/OR only when each side is bracketed: [[#1 EQ 0] OR [#2 LT 0]]",
        "用 AND/OR 连接条件时，每个条件都要加方括号：[[#1 EQ 0] OR [#2 LT 0]]",
    ),
    "sequence_number_with_decimals": (
        "N1.5 G01 X1", "a sequence number must be a whole number written without a decimal point",
        "顺序号必须是不带小数点的整数",
    ),
    "second_block_after_the_end_of_block_mark": (
        "X1 ; Y2", "text after the end-of-block ';': one line holds one block, so this text is not read",
        "程序段结束符 ';' 之后还有内容：一行只能写一个程序段，这些内容不会被读取",
    ),
    "unclosed_comment": (
        "G01 X1 F100 (CHECK", "comment not closed: ')' is missing", "注释没有结束：缺少 ')'",
    ),
    "full_width_end_of_block": (
        "G01 X1 F100；", "full-width '；' read as the end-of-block ';'", "全角 '；' 按程序段结束符 ';' 处理",
    ),
}  # fmt: skip
# A byte that neither UTF-8 nor GB18030 decodes is kept (as U+DC80+byte) and is a stray character.
GBK_LINE = "G01 X1 ".encode("ascii") + b"\xff"
GBK_MESSAGES = (
    "unexpected character U+DCFF; expected another word or statement",
    "此处不应出现字符 U+DCFF；应为其他代码字或宏语句",
)
PROGRAM_NUMBER_LINE = ("O#1", "a program number must be written as a number, not a variable or expression",
                       "程序号必须直接写成数字，不能使用变量或表达式")  # fmt: skip


def assert_chinese(text: str) -> None:
    """Chinese, with no English prose left (codes, numbers, variables and quoted source aside)."""
    assert CJK.search(text), text
    assert not PROSE.search(QUOTED.sub("", text)), text


def analyse(tmp_path: Path, text: str, locale: str) -> list[tuple[int, str, str, str]]:
    """(1-based line, code, severity, message) of each diagnostic the analysis finds in ``text``."""
    ws = WorkspaceAnalysis(settings=MachineSettings(), dialect="fanuc", locale=locale)
    path = tmp_path / "O0001.nc"
    ws.open(str(path), text, 1)
    result = ws.analyze(str(path))
    assert result is not None
    found = [d for diags in result.diagnostics.values() for d in diags if d.severity != "hint"]
    return [(d.line + 1, d.code, d.severity, d.message) for d in found]


@pytest.mark.parametrize("case", list(CASES))
def test_1_text_and_blocks_a_line_that_does_not_parse_reads_in_chinese(tmp_path: Path, case: str) -> None:
    line, en, zh = CASES[case]
    text = f"O0001\n{line}\nM30\n"
    [(number, code, severity, english)] = analyse(tmp_path, text, "en")
    assert (number, code, english) == (2, "syntax", en)
    assert analyse(tmp_path, text, "zh-CN") == [(2, "syntax", severity, zh)]
    assert_chinese(zh)


def test_1_text_and_blocks_a_program_number_written_as_a_variable_reads_in_chinese(tmp_path: Path) -> None:
    line, en, zh = PROGRAM_NUMBER_LINE
    assert [(n, c, m) for n, c, _, m in analyse(tmp_path, f"{line}\nM30\n", "en")] == [(1, "syntax", en)]
    assert [(n, c, m) for n, c, _, m in analyse(tmp_path, f"{line}\nM30\n", "zh-CN")] == [(1, "syntax", zh)]


def test_1_text_and_blocks_a_problem_is_english_wherever_it_goes_and_keeps_its_chinese():
    line, en, zh = CASES["unclosed_bracket"]
    block = parse_block(line)
    assert block == Block(problems=(Problem(en, 7, 8),))  # the cache and edits compare English
    assert block.problems == parse_block(line).problems
    for kept in (block.problems[0].message, pickle.loads(pickle.dumps(block)).problems[0].message):
        assert kept == en and in_language(kept, False) == en and in_language(kept, True) == zh
        assert type(in_language(kept, False)) is str


# ---------------------------------------------------------------- cncmacro check


def write_cases(folder: Path) -> dict[str, tuple[str, str]]:
    """One file per case (line 2 the malformed line): the file name -> (English, Chinese)."""
    expected = {}
    for k, (line, en, zh) in enumerate(CASES.values(), start=1):
        name = f"O{k:04d}.nc"
        (folder / name).write_text(f"O{k:04d}\n{line}\nM30\n", encoding="utf-8")
        expected[name] = (en, zh)
    (folder / "O0100.nc").write_bytes(b"O0100\n" + GBK_LINE + b"\nM30\n")
    expected["O0100.nc"] = GBK_MESSAGES
    return expected


def cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "cncmacro", *args], capture_output=True, text=True, timeout=120, encoding="utf-8"
    )


LINE = re.compile(r"^(.+?):2:\d+: (error|warning): (.*) \[syntax\]$")


def test_1_text_and_blocks_check_with_locale_zh_cn_writes_syntax_problems_in_chinese(tmp_path: Path) -> None:
    expected = write_cases(tmp_path)
    chinese = cli("check", "--locale", "zh-CN", str(tmp_path))
    english = cli("check", str(tmp_path))
    assert chinese.returncode == english.returncode == 1
    assert chinese.stderr == english.stderr == ""
    zh_lines = [LINE.match(x) for x in chinese.stdout.splitlines()]
    en_lines = [LINE.match(x) for x in english.stdout.splitlines()]
    assert all(zh_lines) and all(en_lines)
    zh = {Path(m.group(1)).name: m.group(3) for m in zh_lines if m}
    en = {Path(m.group(1)).name: m.group(3) for m in en_lines if m}
    assert en == {name: pair[0] for name, pair in expected.items()}
    assert zh == {name: pair[1] for name, pair in expected.items()}
    for message in zh.values():
        assert_chinese(message)
    # the same lines, columns, severities and codes in both languages: only the messages differ
    assert [x.split(": ")[0:2] for x in chinese.stdout.splitlines()] == [
        x.split(": ")[0:2] for x in english.stdout.splitlines()
    ]


def test_1_text_and_blocks_check_json_keeps_english_keys_with_the_chinese_message(tmp_path: Path) -> None:
    (tmp_path / "O0001.nc").write_text("O0001\n#1=[1+2\nM30\n", encoding="utf-8")
    out, err = io.StringIO(), io.StringIO()
    assert check_paths([str(tmp_path)], out, err, "json", locale="zh-CN") == 1
    assert "\"message\": \"缺少 ']'：第 4 列的 '[' 没有闭合\"" in out.getvalue()
    assert '"severity": "error"' in out.getvalue() and '"code": "syntax"' in out.getvalue()


def test_1_text_and_blocks_check_names_a_binary_file_and_a_missing_path_in_chinese(tmp_path: Path) -> None:
    (tmp_path / "O0001.nc").write_bytes(b"O0001\n\0\0\0\n")
    missing = tmp_path / "nothing"
    out, err = io.StringIO(), io.StringIO()
    assert check_paths([str(tmp_path), str(missing)], out, err, locale="zh-CN") == 2
    assert err.getvalue() == (
        f"cncmacro：{tmp_path / 'O0001.nc'}：二进制文件（偏移 6 处的字节不是程序文本），不是程序\n"
        f"cncmacro：{missing}：文件或文件夹不存在\n"
    )
    out, err = io.StringIO(), io.StringIO()
    assert check_paths([str(tmp_path), str(missing)], out, err) == 2
    assert err.getvalue() == (
        f"cncmacro: {tmp_path / 'O0001.nc'}: binary file (byte at offset 6 is not program text), not a program\n"
        f"cncmacro: {missing}: no such file or folder\n"
    )


def test_1_text_and_blocks_check_says_what_is_wrong_with_a_machine_file_in_chinese(tmp_path: Path) -> None:
    (tmp_path / "O0001.nc").write_text("O0001\nM30\n", encoding="utf-8")
    machine = tmp_path / ".cncmacro.toml"
    for toml, en, zh in (
        ('dialect = "okuma"\n', f"'dialect' must be {choices_text()} (not 'okuma') (line 1)",
         f"'dialect' 必须是 {choices_text(zh=True)}（不能是 'okuma'）（第 1 行）"),
        ("[severity]\nsyntax = 3\n",
         "'severity.syntax' must be one of error, warning, information, hint, off (not 3) (line 2)",
         "'severity.syntax' 必须是 error, warning, information, hint, off 之一（不能是 3）（第 2 行）"),
        ("[calls]\nX5 = 9000\n", "'calls.X5' must be a G or M code (G100, M50) or T (line 2)",
         "'calls.X5' 必须是 G 或 M 代码（G100、M50）或 T（第 2 行）"),
    ):  # fmt: skip
        machine.write_text(toml, encoding="utf-8")
        said = {"en": f"cncmacro check: {machine}: {en}\n", "zh-CN": f"cncmacro check：{machine}：{zh}\n"}
        for locale, expected in said.items():
            out, err = io.StringIO(), io.StringIO()
            assert check_paths([str(tmp_path)], out, err, locale=locale) == 2
            assert (out.getvalue(), err.getvalue()) == ("", expected)


def test_1_text_and_blocks_too_many_files_for_the_caller_search_is_said_in_chinese(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    for k in range(1, 4):
        (tmp_path / f"O{k:04d}.nc").write_text(f"O{k:04d}\nM30\n", encoding="utf-8")
    with caplog.at_level(logging.WARNING, logger="cncmacro.analysis.indexes.call_index"):
        assert CallIndex([str(tmp_path)], MachineSettings(), None, "zh-CN", max_files=2).size == 0
        assert CallIndex([str(tmp_path)], MachineSettings(), None, "en", max_files=2).size == 0
    assert [r.getMessage() for r in caplog.records] == [
        f"{tmp_path} 下的程序文件超过 2 个：不查找磁盘上调用它们的程序",
        f"more than 2 program files under {tmp_path}: callers on disk are not looked for",
    ]


# ---------------------------------------------------------------- cncmacro run

RUN_PROGRAM = (
    "O0001\nG00 X0 Z0\nG01 X10. Z-5. F100\n#3006=1(CHECK TOOL)\nPOPEN\nDPRNT[X#100[53]]\n#100=2.5\n"
    "G65 P9001 A0\nM30\nO9001\n#101=5/#1\nM99\n"
)
RUN_ENGLISH = """moves (2):
  O0001.nc:2     G00  X0.000 Z0.000 -> X0.000 Z0.000
  O0001.nc:3     G01  X0.000 Z0.000 -> X10.000 Z-5.000  F100
stop at O0001.nc:4: CHECK TOOL
DPRNT  X0.000
ALARM 112: division by zero
  at {file}:11
  called from O0001 (main) at {file}:8
status: alarm after 8 blocks
variables:
  #100 = 2.5
"""
RUN_CHINESE = """运动（2 段）：
  O0001.nc:2     G00  X0.000 Z0.000 -> X0.000 Z0.000
  O0001.nc:3     G01  X0.000 Z0.000 -> X10.000 Z-5.000  F100
停止（O0001.nc:4）：CHECK TOOL
DPRNT  X0.000
报警 112：除数为零
  位置 {file}:11
  调用自 O0001（主程序），位置 {file}:8
状态：报警，共执行 8 个程序段
变量：
  #100 = 2.5
"""
NOTE_PROGRAM = "(cncmacro: dialect=gsk980tdi)\nO0001\n#1=12000\nG65 P9001 L#1\nM30\nO9001\n#100=#100+1\nM99\n"
LOOP_PROGRAM = "O0001\nWHILE[1 EQ 1]DO1\nG01 X1 F10\nEND1\nM30\n"


def assert_no_english_words(output: str, file: Path) -> None:
    """Nothing but Chinese, codes, numbers, file names and the program's own (upper-case) texts."""
    rest = output.replace(str(file), "").replace(file.name, "")
    assert not PROSE.search(rest), output
    assert CJK.search(rest), output


def test_1_text_and_blocks_run_with_locale_zh_cn_writes_its_text_output_in_chinese(tmp_path: Path) -> None:
    f = tmp_path / "O0001.nc"
    f.write_text(RUN_PROGRAM, encoding="utf-8")
    chinese = cli("run", "--no-save", "--locale", "zh-CN", str(f))
    english = cli("run", "--no-save", str(f))
    assert chinese.returncode == english.returncode == 1
    assert english.stdout == RUN_ENGLISH.format(file=f)
    assert chinese.stdout == RUN_CHINESE.format(file=f)
    assert_no_english_words(chinese.stdout, f)


def test_1_text_and_blocks_run_with_locale_zh_cn_notes_limits_and_status_words(tmp_path: Path) -> None:
    f = tmp_path / "O0001.nc"
    f.write_text(NOTE_PROGRAM, encoding="utf-8")
    english = cli("run", "--no-save", str(f))
    chinese = cli("run", "--no-save", "--locale", "zh-CN", str(f))
    assert english.returncode == chinese.returncode == 0
    assert english.stdout == (
        "note at O0001.nc:4: L12000 is above 9999; the control runs it 9999 times\n"
        "status: completed after 20001 blocks\nvariables:\n  #1 = 12000\n  #100 = 9999\n"
    )
    assert chinese.stdout == (
        "提示（O0001.nc:4）：L12000 超过 9999，系统按 9999 次执行\n"
        "状态：完成，共执行 20001 个程序段\n变量：\n  #1 = 12000\n  #100 = 9999\n"
    )
    f.write_text(LOOP_PROGRAM, encoding="utf-8")
    english = cli("run", "--no-save", "--max-blocks", "3", str(f))
    chinese = cli("run", "--no-save", "--max-blocks", "3", "--locale", "zh-CN", str(f))
    assert english.returncode == chinese.returncode == 3
    assert english.stdout.endswith(
        "stopped after 3 blocks: the block budget ran out (an endless loop?)\nstatus: limit after 3 blocks\n"
    )
    assert chinese.stdout.endswith(
        "执行 3 个程序段后停止：已达到程序段数上限（是否有死循环？）\n状态：达到程序段数上限，共执行 3 个程序段\n"
    )
    assert_no_english_words(chinese.stdout, f)
    bad = cli("run", "--no-save", "--max-blocks", "0", "--locale", "zh-CN", str(f))
    assert (bad.returncode, bad.stderr) == (2, "cncmacro run：--max-blocks 至少为 1\n")
    bad = cli("run", "--no-save", "--set", "100=x", "--locale", "zh-CN", str(f))
    assert (bad.returncode, bad.stderr) == (
        2, "cncmacro run：--set '100=x'：'x' 不是数值；应写成“变量号=数值”，例如 --set 100=5 或 --set '#100=5'\n"
    )  # fmt: skip
    bad = cli("run", "--no-save", "--set", "100=x", str(f))
    assert (bad.returncode, bad.stderr) == (
        2,
        "cncmacro run: --set '100=x': 'x' is not a number; write it as NUMBER=VALUE, "
        "e.g. --set 100=5 or --set '#100=5'\n",
    )  # fmt: skip


def test_1_text_and_blocks_run_with_locale_zh_cn_reports_a_line_that_does_not_parse_in_chinese(
    tmp_path: Path,
) -> None:
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\n#1=[1+2\nM30\n", encoding="utf-8")
    english = cli("run", "--no-save", str(f))
    chinese = cli("run", "--no-save", "--locale", "zh-CN", str(f))
    assert english.stdout.startswith("ALARM 125: the block does not parse: expected ']' to close the '[' at column 4\n")
    assert chinese.stdout.startswith("报警 125：程序段无法解析：缺少 ']'：第 4 列的 '[' 没有闭合\n")
    assert_no_english_words(QUOTED.sub("", chinese.stdout), f)
