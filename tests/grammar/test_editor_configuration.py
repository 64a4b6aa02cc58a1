"""The static editor files of the VS Code extension, held to what a user sees.

The snippets (``snippets/cnc-macro.code-snippets``) must insert programs that ``cncmacro check``
accepts, and the macro-header snippet's argument checks must raise their alarms. The language
configuration (``language-configuration.json``) must fold ``WHILE .. DO n`` with its ``END n``
and an ``O`` program with its ``M99``/``M30``, indent a loop body, and keep ``#100`` and ``N100``
whole as words. Its regular expressions are written for JavaScript; they use only syntax that
Python's ``re`` reads the same way, so they are tried here. The TextMate grammar itself is tested
by the ``*.test.nc`` files beside this one (``npm run test:grammar``).
"""

from __future__ import annotations

import io
import json
import re
from pathlib import Path

import pytest

from cncmacro.cli.check import check_paths

ROOT = Path(__file__).resolve().parent.parent.parent
SNIPPETS = json.loads((ROOT / "snippets" / "cnc-macro.code-snippets").read_text(encoding="utf-8"))
CONFIG = json.loads((ROOT / "language-configuration.json").read_text(encoding="utf-8"))

_PLACEHOLDER = re.compile(r"\$\{(\d+):([^${}]*)\}|\$\{(\d+)\|([^|]*)\|\}")


def expand(body: list[str]) -> str:
    """The text a snippet inserts when every placeholder keeps its default (or first choice)."""
    text = "\n".join(body)
    values: dict[str, str] = {}
    while m := _PLACEHOLDER.search(text):
        if m.group(1):
            number, value = m.group(1), m.group(2)
        else:
            number, value = m.group(3), m.group(4).split(",")[0]
        values[number] = value
        text = text[: m.start()] + value + text[m.end() :]
    text = re.sub(r"\$\{(\d+)\}", lambda m: values[m.group(1)], text)
    return re.sub(r"\$\d+", "", text)


def check(folder: Path) -> list[dict[str, object]]:
    """The findings of ``cncmacro check`` on a folder, as JSON objects."""
    out, err = io.StringIO(), io.StringIO()
    check_paths([str(folder)], out, err, "json")
    assert err.getvalue() == ""
    return json.loads(out.getvalue())


# What each snippet needs around it to be a whole program: text before and after it.
CONTEXT = {
    "G65 macro call": ("O1001\n", " Z-5.\nM30\n"),
    "WHILE loop": ("O1002\n#11=3\n", "\nM30\n"),
    "IF GOTO": ("O1003\n#1=1\n", "\nN10 M30\n"),
    "IF THEN": ("O1004\n#1=1\n", "\nM30\n"),
    "M98 subprogram call": ("O1005\n", "\nM30\n"),
    "G66 modal macro call": ("O1006\n", "\nM30\n"),
    "Bolt circle": ("O1007\n", "\nM30\n"),
}


def test_every_snippet_has_a_prefix_a_body_and_an_english_description() -> None:
    assert len(SNIPPETS) >= 8
    for name, snippet in SNIPPETS.items():
        assert snippet["prefix"], name
        assert snippet["body"], name
        description = snippet["description"]
        assert len(description) > 20 and description.isascii(), name


def test_snippets_insert_programs_the_checker_accepts(tmp_path: Path) -> None:
    # the called programs: the header snippet is O9100; O0040 and O9110 are plain subprograms
    (tmp_path / "O9100.nc").write_text(expand(SNIPPETS["Macro header with argument checks"]["body"]) + "\n")
    (tmp_path / "O0040.nc").write_text("O0040\nG91 G01 X1. F100.\nM99\n")
    (tmp_path / "O9110.nc").write_text("O9110\nG81 Z#26 R#18 F#9\nG80\nM99\n")
    assert set(CONTEXT) | {"Macro header with argument checks"} == set(SNIPPETS)
    for i, (name, (before, after)) in enumerate(CONTEXT.items()):
        (tmp_path / f"main{i}.nc").write_text(before + expand(SNIPPETS[name]["body"]) + after)
    findings = check(tmp_path)
    assert [f for f in findings if f["severity"] in ("error", "warning")] == []


def test_header_snippet_raises_its_alarm_when_an_argument_is_missing(tmp_path: Path) -> None:
    (tmp_path / "O9100.nc").write_text(expand(SNIPPETS["Macro header with argument checks"]["body"]) + "\n")
    (tmp_path / "main.nc").write_text("O1000\nG65 P9100 X1. Y2.\nM30\n")
    alarms = [f for f in check(tmp_path) if f["code"] == "macro-alarm"]
    assert alarms and all("Z MISSING" in str(f["message"]) for f in alarms)


def fold(lines: list[str]) -> list[tuple[int, int]]:
    """Folding ranges as VS Code builds them from the markers: each end closes the latest start."""
    start = re.compile(CONFIG["folding"]["markers"]["start"])
    end = re.compile(CONFIG["folding"]["markers"]["end"])
    open_lines: list[int] = []
    ranges = []
    for n, line in enumerate(lines, 1):
        if start.search(line):
            open_lines.append(n)
        elif end.search(line) and open_lines:
            ranges.append((open_lines.pop(), n))
    return sorted(ranges)


def test_folding_pairs_loops_with_their_end_and_programs_with_m99_or_m30() -> None:
    program = [
        "O9100 (BOLT CIRCLE)",  # 1
        "IF[#11 EQ #0] THEN #3000=1(HOLES MISSING)",
        "N5 WHILE[#30 LT #11] DO1",  # 3
        "while [#1 le 3] do 2 (lower case)",  # 4
        "#1=#1+1 (END1 IN A COMMENT)",
        "END 2",  # 6
        "#30=#30+1",
        "N9 END1;",  # 8
        "M99",  # 9
        "O1000",  # 10
        "G65 P9100 H6",
        "DO3",  # 12
        "END3",  # 13
        "M30 (END)",  # 14
    ]
    assert fold(program) == [(1, 9), (3, 8), (4, 6), (10, 14), (12, 13)]


def test_folding_ignores_m_codes_that_only_start_with_99_or_30() -> None:
    assert fold(["O1", "M300", "M990", "M99 P20"]) == [(1, 4)]


@pytest.mark.parametrize(
    ("line", "increase", "decrease"),
    [
        ("WHILE[#1LE10]DO1", True, False),
        ("N20 WHILE [#2 LT 5] DO 2 (PASSES)", True, False),
        ("/1 DO3;", True, False),
        ("END1", False, True),
        ("  N30 end 2", False, True),
        ("#1=#1+1 (DO1)", False, False),
        ("IF[#1 GT 0] GOTO 10", False, False),
    ],
)
def test_indentation_grows_after_do_and_shrinks_at_end(line: str, increase: bool, decrease: bool) -> None:
    rules = CONFIG["indentationRules"]
    assert bool(re.search(rules["increaseIndentPattern"], line)) is increase
    assert bool(re.search(rules["decreaseIndentPattern"], line)) is decrease


@pytest.mark.parametrize(
    ("line", "words"),
    [
        ("N941#3000=1(MSG)", ["N941", "#3000", "1", "MSG"]),
        ("IF[#1GT#100]GOTO10", ["IF", "#1", "GT", "#100", "GOTO", "10"]),
        ("G01X10.Y-#5", ["G01", "X10.", "Y", "#5"]),
        ("WHILE[#1LE10]DO1", ["WHILE", "#1", "LE", "10", "DO", "1"]),
        ("M98 P30040", ["M98", "P30040"]),
    ],
)
def test_word_pattern_keeps_variables_labels_and_words_whole(line: str, words: list[str]) -> None:
    assert re.findall(CONFIG["wordPattern"], line) == words


def test_comments_and_brackets_are_configured_for_cnc_text() -> None:
    assert CONFIG["comments"] == {"blockComment": ["(", ")"]}
    assert CONFIG["brackets"] == [["[", "]"]]
    assert {(p["open"], p["close"]) for p in CONFIG["autoClosingPairs"]} == {("[", "]"), ("(", ")")}
    assert sorted(map(tuple, CONFIG["surroundingPairs"])) == [("(", ")"), ("[", "]")]
