"""Every Chinese text of the project reads as a Chinese machinist expects (the mechanical part of
it): no ASCII comma or semicolon between Chinese words (``第 19、20 行``, not ``第 19, 20 行``), no
space beside full-width punctuation (``（G65）没有``) or between two Chinese characters (``秒时开始``,
not ``秒 开始``), no word said twice in a row (``除数为零（报警 112）：除数为零``), and an alarm
number written the same in both languages (``alarm 76`` is ``报警 76``, not ``报警 076``).

The texts are read where they are written (every string of ``server/cncmacro`` with Chinese in it,
``f``-string places shown as ``{}``, and the client's ``l10n`` and ``package.nls`` tables) and as
the user meets them: the messages ``cncmacro check`` and ``cncmacro run`` write for a set of
programs, in both languages, compared finding by finding."""

from __future__ import annotations

import ast
import json
import re
import subprocess
import sys
from collections.abc import Iterator
from itertools import pairwise
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
CJK = "\u3400-\u4dbf\u4e00-\u9fff"
FULL = "（）：，。；、！？“”"
FAULTS = {
    # an ASCII comma or semicolon used as prose between Chinese words (with numbers or codes around
    # it); one followed by a letter is a code (``,C`` the chamfer word) and stays
    "an ASCII comma or semicolon between Chinese words": re.compile(
        f"[{CJK}{FULL}][ \\d#.\\-–~～]*[,;] [ \\d#.\\-–~～]*[{CJK}{FULL}]"
    ),
    "a space beside full-width punctuation": re.compile(f"[^\\s] [{FULL}]|[{FULL}] [^\\s]"),
    "a space between two Chinese characters": re.compile(f"[{CJK}] +[{CJK}]"),
    "a word said twice in a row": re.compile(f"([{CJK}]{{2,}})(?:[\\s（）：，、；]|报警\\s*\\d+)*\\1"),
}
ALARM_EN = re.compile(r"\b[Aa]larms? (\d+(?:\s*(?:/|,|or|and)\s*\d+)*)")
ALARM_ZH = re.compile(r"报警\s*(\d+(?:\s*[/、，或和]\s*\d+)*)|(\d+)\s*号报警")


def faults(text: str) -> list[str]:
    """What is wrong with the Chinese ``text``, each fault with the words around it."""
    found = []
    for name, rule in FAULTS.items():
        for m in rule.finditer(text):
            found.append(f"{name}: {text[max(0, m.start() - 12) : m.end() + 12]!r}")
    return found


def alarm_numbers(rule: re.Pattern[str], text: str) -> list[str]:
    """The alarm numbers ``text`` names, as written (``076`` is not ``76``)."""
    out: list[str] = []
    for m in rule.finditer(text):
        out += re.findall(r"\d+", next(g for g in m.groups() if g))
    return sorted(out)


def _literal(node: ast.AST) -> str | None:
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.JoinedStr):
        return "".join(v.value if isinstance(v, ast.Constant) else "{}" for v in node.values)
    return None


def _docstrings(tree: ast.AST) -> set[int]:
    return {
        id(n.value)
        for n in ast.walk(tree)
        if isinstance(n, ast.Expr) and isinstance(n.value, ast.Constant) and isinstance(n.value.value, str)
    }


def source_texts() -> Iterator[tuple[str, str]]:
    """(where, text) of every Chinese text written in the server's source and the client's tables."""
    for path in sorted((ROOT / "server" / "cncmacro").rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        docs = _docstrings(tree)
        for node in ast.walk(tree):
            if isinstance(node, ast.FormattedValue):
                continue
            text = _literal(node) if id(node) not in docs else None
            if text and re.search(f"[{CJK}]", text):
                yield f"{path.relative_to(ROOT)}:{getattr(node, 'lineno', 0)}", text
    for table in (ROOT / "l10n" / "bundle.l10n.zh-cn.json", ROOT / "package.nls.zh-cn.json"):
        for key, text in json.loads(table.read_text(encoding="utf-8")).items():
            yield f"{table.name}: {key}", text


def source_pairs() -> Iterator[tuple[str, str, str]]:
    """(where, English, Chinese) of every text written beside its translation: ``detail(en, zh)``,
    ``pick(locale, en, zh)``, a table row ``(en, zh)``, ``en=..., zh=...``."""
    for path in sorted((ROOT / "server" / "cncmacro").rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            items: list[ast.expr] = []
            if isinstance(node, ast.Call):
                items = list(node.args)
                named = {k.arg: k.value for k in node.keywords}
                if "en" in named and "zh" in named:
                    items += [named["en"], named["zh"]]
            elif isinstance(node, ast.Tuple):
                items = list(node.elts)
            for a, b in pairwise(items):
                en, zh = _literal(a), _literal(b)
                if en is not None and zh is not None and not re.search(f"[{CJK}]", en) and re.search(f"[{CJK}]", zh):
                    yield f"{path.relative_to(ROOT)}:{a.lineno}", en, zh


def test_the_rules_catch_the_faults_they_name():
    assert faults("第 19, 20 行的顺序号保持不变") and not faults("第 19、20 行的顺序号保持不变")
    assert faults("但 O1020 第 12 行（G65） 没有传递 E") and not faults("但 O1020 第 12 行（G65）没有传递 E")
    assert faults("本程序段约在第 3.1 秒 开始") and not faults("本程序段约在 3.1 秒时开始")
    assert faults("除数为零（报警 112）：除数为零") and not faults("除数为零（报警 112）")
    assert faults("（FANUC 0i：#100-#199, #500-#999；）") and not faults("只能引出 ,C（倒角）、,R 或 ,A")
    assert alarm_numbers(ALARM_ZH, "找不到（报警 076）") != alarm_numbers(ALARM_EN, "not found (alarm 76)")


def test_every_chinese_text_written_in_the_source_is_free_of_the_mechanical_faults():
    problems = [f"{where}: {fault}" for where, text in source_texts() for fault in faults(text)]
    assert problems == []


def test_every_text_and_its_translation_name_the_same_alarm_numbers():
    problems = [
        f"{where}: {en!r} / {zh!r}"
        for where, en, zh in source_pairs()
        if alarm_numbers(ALARM_EN, en) != alarm_numbers(ALARM_ZH, zh)
    ]
    assert problems == []


PROGRAMS = {
    "DIVIDE.nc": "O0001\n#1=0\n#2=5/#1\nM30\n",
    "NOTFOUND.nc": "O0002\nG65 P8123 A1.\nM30\n",
    "NOP.nc": "O0003\nM98\nM30\n",
    "COMMON.nc": "O0004\n#300=1\nM30\n",
    "VACANT.nc": "O0005\nG65 P9005 A1.\nM30\n",
    "O9005.nc": "O9005\n#2=#8\nM99\n",
    "ROOT.nc": "O0006\n#1=SQRT[-1]\nM30\n",
    "LOOP.nc": "O0007\n#1=1\nWHILE[#1 LT 3]DO1\n#2=1\nEND1\nM30\n",
    "ALARM.nc": "O0008\n#3000=1(NO TOOL)\nM30\n",
    "CROSS.nc": "O0009\nWHILE[#1 LT 3]DO1\nWHILE[#2 LT 3]DO2\nEND1\nEND2\nM30\n",
    "DECIMAL.nc": "O0010\nM30.\n",
    "NEST.nc": "O0011\nG65 P9011\nM30\n",  # a call chain of five levels in the message
    "O9011.nc": "O9011\nG65 P9011\nM99\n",
}
FOLDERS = ("examples", "tests/corpus")


def _check(locale: str, *paths: str, dialect: str = "fanuc-0i") -> dict[tuple[str, int, int, str], str]:
    r = subprocess.run(
        [sys.executable, "-m", "cncmacro", "check", "--hints", "--format", "json", "--locale", locale,
         "--dialect", dialect, *paths],
        capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    assert r.returncode in (0, 1), r.stderr
    return {(d["file"], d["line"], d["column"], d["code"]): d["message"] for d in json.loads(r.stdout)}


@pytest.fixture(scope="module")
def programs(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("texts")
    for name, text in PROGRAMS.items():
        (folder / name).write_text(text, encoding="utf-8")
    return folder


@pytest.mark.parametrize("dialect", ["fanuc-0i", "gsk980tdi", "haas"])
def test_what_check_writes_in_chinese_is_free_of_the_faults_and_names_the_alarms_of_the_english(
    programs: Path, dialect: str
) -> None:
    paths = [str(programs), *(str(ROOT / f) for f in FOLDERS)]
    english, chinese = _check("en", *paths, dialect=dialect), _check("zh-CN", *paths, dialect=dialect)
    assert english.keys() == chinese.keys() and len(chinese) > 20
    problems = []
    for key, zh in chinese.items():
        where = f"{Path(key[0]).name}:{key[1]} [{key[3]}]"
        problems += [f"{where}: {fault}" for fault in faults(zh)]
        if alarm_numbers(ALARM_EN, english[key]) != alarm_numbers(ALARM_ZH, zh):
            problems.append(f"{where}: {english[key]!r} / {zh!r}")
    assert problems == []


def test_what_run_writes_in_chinese_is_free_of_the_faults(programs: Path) -> None:
    for name in PROGRAMS:
        r = subprocess.run(
            [sys.executable, "-m", "cncmacro", "run", "--no-save", "--locale", "zh-CN", str(programs / name)],
            capture_output=True, text=True, timeout=120,
        )  # fmt: skip
        assert r.returncode in (0, 1, 3), r.stderr
        assert [f for line in (r.stdout + r.stderr).splitlines() for f in faults(line)] == [], name
