"""A WHILE loop whose condition depends on a value only the machine has (docs/semantics.md §2,
"Unknown, not vacant", a loop on such a value; machine/guards.py ``unknown_loop_pass``): the
analysis run goes through its body once and then leaves the loop, with an ``unknown-value`` hint
on the WHILE, so that the body and what follows are checked. It stopped at the WHILE before, and
nothing after it was checked."""

from __future__ import annotations

from pathlib import Path

from cli_capture import check_findings

THROUGH = (
    "hint: the analysis run goes through this WHILE loop once and then leaves it, so that its body and what "
    "follows are checked; the machine repeats it as its condition says, which depends on {names}, which the "
    "machine keeps; this folder does not give it; set it under [variables] in .cncmacro.toml (or in the persistent "
    "file it names) to check further [unknown-value]"
)
DIVISION = "error: division by zero (alarm 112) [division-by-zero]"


def check(folder: Path, text: str, *extra: str) -> tuple[int, list[str]]:
    """``check_findings`` of ``text`` with the command line's ``extra`` words."""
    return check_findings(folder, text, None, *extra)


# a shop's loop over the parts of a fixture: #500, the parts per fixture, is kept on the machine
FIXTURE = (
    "O0100\n"
    "#10=0\n"
    "WHILE [#10 LT #500] DO1\n"  # 0 < unknown: unknown
    "G00 X[#10*40.] Y0.\n"
    "#10=#10+1\n"
    "END1\n"
    "#3=10./[#10-1]\n"  # one pass: #10 = 0 + 1 = 1, so 10 / (1 - 1) = 10 / 0: alarm 112
    "M30\n"
)


def test_a_while_on_a_kept_count_runs_its_body_once_and_what_follows_is_checked(tmp_path: Path) -> None:
    code, found = check(tmp_path, FIXTURE)
    assert code == 1
    assert found == [
        "3:1: " + THROUGH.format(names="#500"),
        "7:1: " + DIVISION,
        "8:1: hint: no analysis run reaches this block [not-executed]",
    ]


def test_the_body_of_a_while_on_a_kept_count_is_checked(tmp_path: Path) -> None:
    # the first pass divides by #10 = 0: alarm 112 inside the loop, on its first iteration
    text = "O0100\n#10=0\nWHILE [#10 LT #501] DO1\n#2=5./#10\n#10=#10+1\nEND1\nM30\n"
    code, found = check(tmp_path, text)
    assert code == 1
    assert found[0] == "3:1: " + THROUGH.format(names="#501")
    assert found[1].startswith("4:1: error: division by zero (alarm 112)")


def test_a_while_whose_count_is_given_runs_as_the_control_runs_it(tmp_path: Path) -> None:
    # #500 = 3 under [variables]: three passes, #10 = 3, so 10 / (3 - 1) = 5: no alarm, no hint
    (tmp_path / ".cncmacro.toml").write_text("[variables]\n500 = 3\n", encoding="utf-8")
    assert check(tmp_path, FIXTURE) == (0, [])


def test_a_loop_on_the_machines_value_left_by_a_known_count_leaves_on_the_unknown(tmp_path: Path) -> None:
    # the count is known on entry (#1 = 2 > 0: in), the body makes it unknown (#1 = #1 - #502):
    # the run leaves at the next test, so #2 = 1 / 0 after the loop is reached
    text = "O0100\n#1=2\nWHILE [#1 GT 0] DO1\n#1=#1-#502\nEND1\n#2=1/0\nM30\n"
    code, found = check(tmp_path, text)
    assert code == 1
    assert found[0].startswith("3:1: hint: the analysis run goes through this WHILE loop once")
    assert found[1] == "6:1: " + DIVISION
