"""A production program's own guard on a value only the machine has (docs/semantics.md §2,
"Unknown, not vacant", the guard of a production program; machine/guards.py): where one side of a
branch on an unknown value is nothing but the program's own macro alarm, the analysis run goes on
along the other side, as the machine does on every production cycle, with an ``unknown-value``
hint on the guard; what follows is checked, so a certain alarm after it is an error. A branch
whose sides are anything else still stops the run, and ``cncmacro run`` (vacant values) is as before."""

from __future__ import annotations

import json
from pathlib import Path

from cli_capture import check_findings, cli

PASSED = (
    "hint: the analysis run goes on past this guard, on the side that does not raise the program's own alarm, as "
    "the machine passes it in production: the condition depends on {names}, which the machine keeps; this folder "
    "does not give it; set it under [variables] in .cncmacro.toml (or in the persistent file it names) to check "
    "further [unknown-value]"
)
STOPS = (
    "hint: the analysis run stops here: this block depends on #500, which the machine keeps; this folder does not "
    "give it; set it under [variables] in .cncmacro.toml (or in the persistent file it names) to check further "
    "[unknown-value]"
)
DIVISION = "error: division by zero (alarm 112) [division-by-zero]"


def check(folder: Path, text: str, *extra: str) -> tuple[int, list[str]]:
    """``check_findings`` of ``text`` with the command line's ``extra`` words."""
    return check_findings(folder, text, None, *extra)


# a batch counter's guard at the top (a public shop program's shape): #3901 parts done, #3902
# parts required, both set on the machine; a certain division by zero comes later
BATCH = (
    "O0100 (BATCH CONTROL)\n"
    "IF [#3901 GE #3902] THEN #3000=10 (BATCH COMPLETE)\n"
    "#1=#3902-#3901\n"  # unknown - unknown: unknown, no alarm
    "G00 X10.\n"
    "#3=10./0.\n"  # 10 / 0: alarm 112 on every cycle
    "M30\n"
)


def test_a_guard_then_macro_alarm_is_passed_and_a_sure_alarm_after_it_is_an_error(tmp_path: Path) -> None:
    code, found = check(tmp_path, BATCH)
    assert code == 1
    assert found == [
        "2:1: " + PASSED.format(names="#3901, #3902"),
        "5:1: " + DIVISION,
        "6:1: hint: no analysis run reaches this block [not-executed]",  # the M30 after the alarm
    ]


def test_a_guard_goto_to_a_macro_alarm_falls_through(tmp_path: Path) -> None:
    # the jump lands on N999, nothing but the program's alarm: the run goes on at line 3;
    # #1 = 10 / #500 is unknown (no alarm), #3 = 5 / #2 = 5 / 0 is alarm 112. N999 is not
    # faded: the machine jumps there when #500 is 0
    text = "O0100\nIF [#500 EQ 0] GOTO 999\n#1=10./#500\n#2=0\n#3=5./#2\nM30\nN999 #3000=2 (SET #500)\nM30\n"
    code, found = check(tmp_path, text)
    assert code == 1
    assert found == ["2:1: " + PASSED.format(names="#500"), "5:1: " + DIVISION]


def test_a_guard_goto_over_a_macro_alarm_jumps(tmp_path: Path) -> None:
    # the block after the branch is nothing but the program's alarm: the run jumps to N10;
    # #3 = 5 / #2 = 5 / 0 is alarm 112, and the M30 after it is not reached
    text = "O0100\nIF [#500 NE 0] GOTO 10\n#3000=2 (SET #500)\nN10 #1=10./#500\n#2=0\n#3=5./#2\nM30\n"
    code, found = check(tmp_path, text)
    assert code == 1
    assert found == [
        "2:1: " + PASSED.format(names="#500"),
        "6:1: " + DIVISION,
        "7:1: hint: no analysis run reaches this block [not-executed]",
    ]


def test_a_guard_in_a_block_if_takes_the_branch_without_the_alarm(tmp_path: Path) -> None:
    # Mazak EIA (no alarm numbers shown) and Mitsubishi M70 have the block IF. ELSE holds only the
    # alarm: the THEN branch runs (#1 = 1), then 5 / [#1 - 1] = 5 / 0 is a division by zero;
    # the other way round, THEN holds only the alarm: the ELSE branch runs
    for dialect, branches in (("mazak-eia", "#1=1\nELSE\n#3000=1 (SET THE LOT SIZE)\n"),
                              ("mitsubishi-m70", "#3000=1 (SET THE LOT SIZE)\nELSE\n#1=1\n")):  # fmt: skip
        text = f"O0100\nIF [#600 GT 0] THEN\n{branches}ENDIF\n#3=5/[#1-1]\nM30\n"
        code, found = check(tmp_path, text, "--dialect", dialect)
        assert code == 1
        assert found[0] == "2:1: " + PASSED.format(names="#600")
        assert found[1].startswith("7:1: error: division by zero (alarm") and len(found) == 3


def test_a_gsk_h_code_guard_over_g65_h99_jumps(tmp_path: Path) -> None:
    # G65 H82 P10 Q#500 R0 jumps to N10 when #500 is not 0 (GSK980TDi §3.28.2); the block after
    # it is G65 H99 P15, the program's alarm 5915: the run jumps, and 5 / 0 is alarm 112
    text = "O0100 (cncmacro: dialect=gsk980tdi)\nG65 H82 P10 Q#500 R0\nG65 H99 P15\nN10 #1=10/#500\n#3=5/0\nM30\n"
    code, found = check(tmp_path, text)
    assert code == 1
    assert found == [
        "2:1: " + PASSED.format(names="#500"),
        "5:1: " + DIVISION,
        "6:1: hint: no analysis run reaches this block [not-executed]",
    ]


def test_a_branch_on_an_unknown_whose_side_is_more_than_an_alarm_still_stops(tmp_path: Path) -> None:
    # the target N999 moves before its alarm, and #3006 is a stop with a message, not an alarm:
    # neither side is the program's own alarm alone, so the run stops as before (nothing after
    # is judged, nothing is faded)
    for text in (
        "O0100\nIF [#500 EQ 0] GOTO 999\nG00 X10.\n#3=5./0\nM30\nN999 G00 X0\n#3000=2 (SET #500)\nM30\n",
        "O0100\nIF [#500 EQ 0] THEN #3006=1 (CHECK #500)\n#3=5./0\nM30\n",
        # both sides an alarm: no side passes the guard
        "O0100\nIF [#500 EQ 0] GOTO 999\n#3000=1 (ONE)\nN999 #3000=2 (TWO)\nM30\n",
    ):
        assert check(tmp_path, text) == (0, ["2:1: " + STOPS])


def test_a_guard_given_in_variables_is_decided_as_the_control_decides(tmp_path: Path) -> None:
    # 3901 = 500 >= 3902 = 500: the condition holds and the shop's own alarm is reached
    (tmp_path / ".cncmacro.toml").write_text("[variables]\n3901 = 500\n3902 = 500\n", encoding="utf-8")
    code, found = check(tmp_path, BATCH)
    assert code == 0  # a warning: the path read the counters
    assert found[0] == "2:1: warning: the run reaches macro alarm 3010: BATCH COMPLETE [macro-alarm]"


def test_cncmacro_run_reads_the_guard_with_vacant_values_as_before(tmp_path: Path) -> None:
    # run simulates one machine with #500 vacant: [#500 EQ 0] is false (vacant is not 0 in EQ on
    # FANUC, docs/semantics.md §2), so it falls through to #1 = 10 / #500: alarm 112 on line 3
    text = "O0100\nIF [#500 EQ 0] GOTO 999\n#1=10./#500\nM30\nN999 #3000=2 (SET #500)\nM30\n"
    (tmp_path / "O0100.nc").write_text(text, encoding="utf-8")
    code, out, _ = cli("run", "--json", "--no-save", str(tmp_path / "O0100.nc"))
    result = json.loads(out)
    assert code != 0 and result["alarm"]["number"] == 112 and result["alarm"]["line"] == 3


# GSK980TDi §3.29.1: "0 到#j 之间产生随机数 #i = RAND[#j]。（不包括 0）": #1 is a draw above 0 up to 10
RANDOM_GUARD = (
    "hint: the analysis run goes on past this guard, on the side that does not raise the program's own alarm: the "
    "condition depends on a random number (RAND, SRAND) (line 2), which the control draws as the program runs, so "
    "the control takes either side: it raises the program's own alarm on some draws and goes on on others; what "
    "follows is checked as the draws that go on run it [unknown-value]"
)


def test_a_guard_on_a_random_number_says_the_draw_takes_either_side(tmp_path: Path) -> None:
    # IF [#1 GT 5] THEN #3000=1: a draw above 5 raises 5901, one of 5 or less goes on; the run
    # follows the side that goes on, and 10 / 0 there is alarm 112 on every such draw: an error
    text = "O0100 (cncmacro: dialect=gsk980tdi)\n#1=RAND[10]\nIF [#1 GT 5] THEN #3000=1 (HIGH)\n#3=10/0\nM30\n"
    code, found = check(tmp_path, text)
    assert code == 1
    assert found == [
        "3:1: " + RANDOM_GUARD,
        "4:1: " + DIVISION,
        "5:1: hint: no analysis run reaches this block [not-executed]",
    ]
    # it is not a value the machine keeps: nothing of production, nor "not judged", is said of it
    assert "production" not in found[0] and "not judged" not in found[0]
    code, found = check(tmp_path, text, "--locale", "zh-CN")
    assert found[0].startswith("3:1: ") and "随机数（RAND、SRAND）（第 2 行）" in found[0]
    assert "某些随机值触发程序自身报警" in found[0] and "生产" not in found[0]


def test_a_macro_alarm_after_a_guard_on_a_random_number_is_not_sure(tmp_path: Path) -> None:
    # the run reaches #3000=2 (5902) only on the draws of 5 or less; a draw above 5 stops at 5901
    # first: not every run reaches 5902, so it is a warning, not an error (exit 0)
    text = "O0100 (cncmacro: dialect=gsk980tdi)\n#1=RAND[10]\nIF [#1 GT 5] THEN #3000=1 (HIGH)\n#3000=2 (LOW)\nM30\n"
    code, found = check(tmp_path, text)
    assert code == 0
    assert found == [
        "3:1: " + RANDOM_GUARD,
        "4:1: warning: the run reaches macro alarm 5902: LOW [macro-alarm]",
        "5:1: hint: no analysis run reaches this block [not-executed]",
    ]


def test_a_while_loop_on_a_random_number_says_its_count_is_not_judged(tmp_path: Path) -> None:
    # WHILE [#1 LT 5]: #1 is a new draw each pass; the run goes through the loop once and leaves it
    text = "O0100 (cncmacro: dialect=gsk980tdi)\n#1=RAND[10]\nWHILE [#1 LT 5] DO1\n#1=RAND[10]\nEND1\nM30\n"
    code, found = check(tmp_path, text)
    assert code == 0
    assert found == [
        "3:1: hint: the analysis run goes through this WHILE loop once and then leaves it, so that its body and "
        "what follows are checked; the machine repeats it as its condition says, which depends on a random number "
        "(RAND, SRAND) (line 2), which the control draws as the program runs; no check can foresee how many times "
        "the loop runs [unknown-value]"
    ]
