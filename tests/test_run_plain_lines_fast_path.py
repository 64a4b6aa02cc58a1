"""Plain motion lines run straight from their text exactly as through the syntax tree.

A line of whitespace-separated words (``G01 X12.5 Y-3.``) is read from its text without
building syntax nodes, and runs of such lines are carried out in one pass (docs/semantics.md §2
rounding, §8 motion). Appending a comment to every line sends the same blocks through the
general path, so the two runs must leave the same moves, clock, modal state and variables, in
each dialect and both decimal-point input modes, with blank lines, comments, canned cycles
and M codes between them, some after a sequence number. A run stopped every few blocks (as the debugger steps) must end
where one uninterrupted run ends.
"""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from running import lines, machine, run

# on haas each block also leaves every letter's last value for #4101-#4126 (docs/semantics.md §2)
AXES = {"fanuc": "XYZ", "gsk980tdi": "XZUW", "haas": "XYZ"}


@st.composite
def plain_line(draw: st.DrawFn, dialect: str) -> str:
    letters = AXES[dialect]
    words = []
    if draw(st.booleans()):
        codes = ["0", "00", "1", "01", "2", "3", "90", "91", "94", "95", "17", "18", "19", "4", "20", "21"]
        if dialect == "gsk980tdi":  # a lathe's threads (G34 declined), feed modes and constant surface speed
            codes += ["32", "34", "96", "97", "98", "99"]
        words.append("G" + draw(st.sampled_from(codes)))
    for letter in draw(st.lists(st.sampled_from(letters + "FSRIJK"), min_size=1, max_size=5)):
        whole = draw(st.integers(-500, 500))
        decimals = draw(st.sampled_from(["", ".", ".5", ".25", ".125", ".0625", ".33333"]))
        text = f"{whole}{decimals}"
        if letter == "F":
            text = text.lstrip("-") or "1"
        words.append(letter + text)
    sep = draw(st.sampled_from([" ", "  ", "\t", ""]))
    text = sep.join(words)
    if draw(st.integers(0, 3)) == 0:  # a line in ten of a CAM program has a sequence number
        text = f"N{draw(st.integers(1, 99999))}{sep}{text}"
    return text.lower() if draw(st.booleans()) else text


# Lines that are not plain, placed between plain ones: the one-pass run must stop before
# them and go on after them, and a cycle they start must take over the plain lines that follow.
OTHERS = {
    "fanuc": ["", "(a comment)", "G81 Z-2. R1. F100", "G80", "M03 S500", "G83 Z-4. R1. Q1. F80", "G00 X1 (x)"],
    "haas": ["", "(a comment)", "G81 Z-2. R1. F100", "G80", "M03 S500", "G83 Z-4. R1. Q1. F80", "G00 X1 (x)"],
    "gsk980tdi": [
        "",
        "(a comment)",
        "G90 X20. Z-5. F0.2",
        "M03 S500",
        "G71 U1. R0.5",
        "G00 X1 (x)",
        "G50 S1500",
        "G96 S120",
        "G92 X20. Z-5. R-1. F1.5",
        "G98 F0.2",
    ],
}


@st.composite
def program(draw: st.DrawFn) -> tuple[str, list[str], str]:
    dialect = draw(st.sampled_from(sorted(AXES)))
    line = st.one_of(plain_line(dialect), plain_line(dialect), st.sampled_from(OTHERS[dialect]))
    body = draw(st.lists(line, min_size=1, max_size=25))
    mode = draw(st.sampled_from(["calculator", "increment"]))
    return dialect, body, mode


def outcome(dialect: str, body: list[str], mode: str) -> tuple[object, ...]:
    m = run(lines("O0001", *body, "M30"), dialect, decimal_point=mode)
    alarm = (m.alarm.number, m.alarm.line) if m.alarm else None
    lengths = (m.planner.cut_length, m.planner.rapid_length)  # the cycle time's path (planner/cycle_time.py)
    return (
        m.status,
        alarm,
        m.planner.moves,
        m.planner.clock,
        lengths,
        dict(m.planner.modal),
        dict(m.planner.codes),
        m.variables(),
    )


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program())
def test_plain_lines_run_as_the_general_path_runs_them(case: tuple[str, list[str], str]) -> None:
    dialect, body, mode = case
    commented = [f"{text} (same block)" if text.strip() else text for text in body]
    assert outcome(dialect, body, mode) == outcome(dialect, commented, mode)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program(), st.integers(1, 7))
def test_plain_lines_run_in_short_steps_end_as_one_run(case: tuple[str, list[str], str], chunk: int) -> None:
    dialect, body, mode = case
    text = lines("O0001", *body, "M30")
    whole = run(text, dialect, decimal_point=mode)
    stepped = machine(text, dialect, decimal_point=mode)
    stops = []
    while True:
        status = stepped.run(chunk, is_limit=False)
        if status == "paused" and stepped.message is None and not stepped.finished:
            stops.append((stepped.blocks, stepped.frames[-1].pc))
            continue
        if status == "paused":
            stepped.resume()
            continue
        break
    assert all(blocks % chunk == 0 for blocks, _ in stops)  # never more than asked for
    assert all(does_something(text, pc) for _, pc in stops)  # never on a blank or comment line
    assert stepped.status == whole.status
    assert stepped.blocks == whole.blocks
    assert stepped.planner.moves == whole.planner.moves
    assert stepped.planner.clock == whole.planner.clock
    assert dict(stepped.planner.modal) == dict(whole.planner.modal)


def does_something(text: str, pc: int) -> bool:
    line = text.split("\n")[pc].strip()
    return bool(line) and not line.startswith("(")


def test_plain_lines_move_and_round_as_written() -> None:
    m = run(lines("O0001", "G90 G01 X10.5 Y-3. F200", "G91 X1.25 Y1", "X0.0004 Z2.", "M30"))
    assert m.status == "completed"
    assert [move.end for move in m.planner.moves] == [
        (10.5, -3.0, 0.0, 0.0),
        (11.75, -2.0, 0.0, 0.0),
        (11.75, -2.0, 2.0, 0.0),
    ]
    assert m.planner.moves[-1].line == 3


def test_the_last_sequence_number_is_that_of_the_last_numbered_plain_line_run() -> None:
    # #4114 reads the N of the last numbered block (FANUC): N20, not N10 nor the unnumbered after it
    m = run(lines("O0001", "G90 G00 X0 Y0", "N10 G01 X1. F100", "G01 X2.", "N20 G01 X3.", "X4.", "#1=#4114", "M30"))
    assert m.status == "completed"
    assert m.variables()[1] == 20.0
    assert [move.end[0] for move in m.planner.moves] == [0.0, 1.0, 2.0, 3.0, 4.0]
    assert [move.line for move in m.planner.moves] == [1, 2, 3, 4, 5]


def test_plain_lines_in_increment_mode_count_least_increments() -> None:
    m = run(lines("O0001", "G90 G01 X10 Y2.5 F200", "M30"), decimal_point="increment")
    assert m.planner.moves[0].end[:2] == (0.01, 2.5)
