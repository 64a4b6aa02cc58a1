"""§6 alarm numbers in what a check says: Haas documents none of FANUC's alarm numbers, so on the
``haas`` profile every message names its alarm as "alarm" ("报警") alone, in English and Chinese,
while the same program on ``fanuc-0i`` keeps each number as before (docs/semantics.md §6,
docs/profiles.md "haas").

``PROGRAM`` hits each message that writes an alarm into its text and that a program can reach
on Haas: the block rules, the parser's two rules with an alarm, the loop, variable, call and
label checks, a duplicate O number. ``FANUC_SAYS`` is, for each of them, the words the 0i check
writes, the number read off the FANUC 0i alarm list the message names.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from cli_capture import cli
from cncmacro.dialects import get_dialect

PROGRAM = """\
%
O2000
G00 X1. #1=2
X1. G65 P9000 A1.
G65 G01 P9000
G65 P9000 O5
G65 A1.
M30.
M98
M98 P1234
#1=[1 LT 2]
#2=1234567890123456789012345678
WH [#1 LT 2] DO1
END1
DO4
END4
DO2
#0=1
#3=#12000
#4=[[[[[[[1]]]]]]]
#5=#_ABC
IF [#1 == 2] GOTO 5
GOTO 99999
M30
O2000
M30
%
"""

# (1-based line, what the fanuc-0i check writes there): each number is the FANUC 0i alarm of the rule
FANUC_SAYS = [
    (3, "the NC word G and a macro statement in one block (alarm 127)"),
    (4, "X before G65: only N may precede G65 in its block; FANUC 0i Custom Macro B stops with alarm 127"),
    (5, "G after G65: a G code cannot be an argument (alarm 129)"),
    (6, "G65 may not share its block with an O word (alarm 127)"),
    (7, "G65 needs P: the program to call (alarm 76)"),
    (8, "M30.: an M code takes no decimal point (alarm 007 illegal use of decimal point); write M30"),
    (9, "M98 needs P (the program), or Q to call the current program (alarm 76)"),
    (10, "M98 calls O1234, which is neither in this file nor found near it (alarm 76)"),
    (11, "the comparison 'LT' is allowed only in an IF or WHILE condition (alarm 114)"),
    (12, "a number of 28 digits is too long to read: at most 24 (alarm 003)"),
    (15, "DO 4: the loop number must be 1, 2 or 3 (alarm 126)"),
    (17, "DO 2 has no END 2 (alarm 124)"),
    (18, "#0 is always vacant and cannot be written (alarm 116)"),
    (20, "brackets nested 7 deep; at most 5 are allowed (alarm 118)"),
    (22, "'==' is not a relation on FANUC 0i Custom Macro B; write EQ (alarm 114)"),
    (23, "GOTO 99999: there is no N99999 in O2000 (alarm 128)"),
    (25, "(loading it is FANUC alarm 073)"),
]
# the Haas messages of the same lines: "alarm" alone where the number was, the alarm's text kept
HAAS_SAYS = [
    (3, "the NC word G and a macro statement in one block (alarm)"),
    (4, "X before G65: only N may precede G65 in its block; Haas NGC mill stops with alarm"),
    (8, "M30.: an M code takes no decimal point (alarm: illegal use of decimal point); write M30"),
    (12, "a number of 28 digits is too long to read: at most 24 (alarm)"),
    (13, "a FANUC feature that Haas NGC mill does not have; the control stops here with alarm; write WHILE"),
    (19, "#12000 does not exist on Haas NGC mill (alarm)"),
    (21, "#_ABC: system variable names are not a feature of this control; on Haas NGC mill write the variable"),
    (21, "write the variable number (alarm)"),
    (25, "(loading it is an alarm)"),
]
HAAS_SAYS_ZH = [
    (3, "NC代码 G 与宏语句在同一程序段（报警）"),
    (4, "G65 之前只允许出现 N，不能有 X：Haas NGC mill 报警（停止运行）"),
    (8, "M30.：M代码只能写整数（报警：小数点使用不当）；请写作 M30"),
    (13, "系统执行到此处报警；请写作 WHILE"),
    (25, "（输入时报警）"),
]
# an alarm followed by its number: "alarm 127", "alarm 007", "报警 127", "127号报警"
NUMBERED = re.compile(r"alarm\s*\d|报警\s*\d|\d\s*号报警", re.IGNORECASE)


def check(folder: Path, profile: str, locale: str) -> list[tuple[int, str]]:
    """(1-based line, message) of each finding ``cncmacro check`` writes for ``PROGRAM``."""
    path = folder / "O2000.nc"
    path.write_text(PROGRAM, encoding="utf-8")
    code, out, err = cli("check", "--dialect", profile, "--locale", locale, str(path))
    assert code == 1, err  # errors found
    found = []
    for row in out.splitlines():
        _, line, _, rest = row.split(":", 3)
        found.append((int(line), rest.strip()))
    return found


def said_on(found: list[tuple[int, str]], line: int, words: str) -> bool:
    return any(n == line and words in message for n, message in found)


@pytest.mark.parametrize("locale", ["en", "zh-CN"])
def test_6_alarms_a_haas_check_names_no_alarm_number(tmp_path: Path, locale: str) -> None:
    found = check(tmp_path, "haas", locale)
    assert len(found) >= len(FANUC_SAYS)
    assert [m for _, m in found if NUMBERED.search(m)] == []
    says = HAAS_SAYS if locale == "en" else HAAS_SAYS_ZH
    assert [(n, w) for n, w in says if not said_on(found, n, w)] == []


def test_6_alarms_the_same_program_on_fanuc_0i_names_each_alarm_number(tmp_path: Path) -> None:
    found = check(tmp_path, "fanuc-0i", "en")
    assert [(n, w) for n, w in FANUC_SAYS if not said_on(found, n, w)] == []
    chinese = check(tmp_path, "fanuc-0i", "zh-CN")
    # the same numbers in Chinese: line 3 (127), 8 (007, with its text), 11 (114), 17 (124), 25 (073)
    for line, words in [(3, "（报警 127）"), (8, "（报警 007 小数点使用不当）"), (11, "（报警 114）"),
                        (17, "（报警 124）"), (25, "（FANUC 输入时报警 073）")]:  # fmt: skip
        assert said_on(chinese, line, words), (line, words)


def test_6_alarms_a_block_that_does_not_parse_stops_the_run_with_the_alarm_its_message_names(tmp_path: Path) -> None:
    path = tmp_path / "O3000.nc"
    path.write_text("O3000\n#1=[1 LT 2]\n#2=1234567890123456789012345678\nM30\n", encoding="utf-8")
    # FANUC: the comparison outside a condition is alarm 114, said once, in front of the message
    _, out, _ = cli("run", "--no-save", "--dialect", "fanuc-0i", str(path))
    said = "ALARM 114: the block does not parse: the comparison 'LT' is allowed only in an IF or WHILE condition\n"
    assert said in out
    # Haas: the same alarm, without the number
    _, out, _ = cli("run", "--no-save", "--dialect", "haas", str(path))
    assert "ALARM: the block does not parse: the comparison 'LT'" in out and not NUMBERED.search(out)
    # a number of 28 digits is FANUC's alarm 003 (too many digits), which the run now raises
    path.write_text("O3000\n#2=1234567890123456789012345678\nM30\n", encoding="utf-8")
    _, out, _ = cli("run", "--no-save", "--dialect", "fanuc-0i", str(path))
    assert "ALARM 3: the block does not parse: a number of 28 digits is too long to read: at most 24\n" in out


def test_6_alarms_haas_function_texts_name_no_alarm_number_fanucs_do() -> None:
    haas = {f.name: f for f in get_dialect("haas").functions()}
    fanuc = {f.name: f for f in get_dialect("fanuc-0i").functions()}
    assert [f.name for f in haas.values() if NUMBERED.search(f.en) or NUMBERED.search(f.zh)] == []
    assert haas["SQRT"].en == "Square root of a; a negative is alarm" and haas["SQRT"].zh == "平方根；a为负时为报警"
    assert fanuc["SQRT"].en == "Square root of a; a negative is alarm 119"
    assert fanuc["SQRT"].zh == "平方根；a为负时为报警 119"
    assert fanuc["MOD"].en.endswith("b = 0 is alarm 112") and fanuc["GOTO"].en.endswith("not found is alarm 128")
    assert all("{alarm}" not in f.en + f.zh for f in (*haas.values(), *fanuc.values()))
