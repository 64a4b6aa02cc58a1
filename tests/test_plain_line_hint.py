"""A plain CAM line (``Block.plain``) is looked at by the per-line checks only when it holds a
word they say they look at (``call_checks.words_looked_at``, made into one search by
``machine/word_sets.plain_search``): the search may look at a line for nothing, but never pass
over one that a check finds something on. A check that looks at a word it does not declare (an
``M00`` finding, say, that fires on ``G0X1.M00``, which is parsed, but not on ``G0 X1 M00``)
fails here."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cncmacro.analysis.checks.call_checks import check_words
from cncmacro.analysis.checks.line_facts import LineFacts
from cncmacro.analysis.checks.static_checks import line_context
from cncmacro.dialects import BY_NAME
from cncmacro.library.machine_file import CallCode, MachineSettings
from cncmacro.syntax.block_parser import parse_block
from strategies import plain_line

# machine files with no calls, and with a G, an M and a T code made calls
MACHINES = [
    MachineSettings(),
    MachineSettings(calls={"G150": CallCode(9150)}),
    MachineSettings(calls={"M100": CallCode(9100, "subprogram"), "M97": CallCode(9097)}),
    MachineSettings(calls={"T": CallCode(9000, "subprogram")}),
]


def _missed(lines: list[str], dialect: str, machine: MachineSettings) -> list[str]:
    """The plain lines of ``lines`` that a check finds something on and the search passes over."""
    ctx = line_context(BY_NAME[dialect], machine)
    out = []
    for line in lines:
        block = parse_block(line)
        assert block.plain is not None, line
        facts = LineFacts()
        check_words(block, ctx, facts)  # every check of a plain line, without the search before it
        if facts and not ctx.plain_hint(line):
            out.append(line)
    return out


# every address with every code to 999, written plainly, with a leading zero and a point, with a
# fraction that rounds up, and in lower case
EVERY_WORD = [
    spelled
    for letter in "ABCDEFGHIJKLMPQRSTUVWXYZ"
    for code in range(1000)
    for spelled in (f"{letter}{code}", f"{letter}0{code}.", f"{letter.lower()}{code}.5")
]


@pytest.mark.parametrize("dialect", sorted(BY_NAME))
def test_every_word_a_check_finds_something_on_is_looked_at(dialect: str) -> None:
    for machine in MACHINES:
        assert _missed(EVERY_WORD, dialect, machine) == []


@settings(max_examples=600, deadline=None)
@given(plain_line(), st.sampled_from(sorted(BY_NAME)), st.sampled_from(range(len(MACHINES))))
def test_a_plain_line_a_check_finds_something_on_is_never_passed_over(line, dialect, machine):
    assert _missed([line], dialect, MACHINES[machine]) == []


def test_the_search_passes_over_the_lines_of_a_cam_program_and_looks_at_the_others():
    ctx = line_context(BY_NAME["fanuc-0i"], MACHINES[1])
    passed = ["G01 X12.5 Y-3.", "G1 X1. F200.", "G02 X0 Y10. R5.", "X3.25 Y-1.", "G0 Z50.", "M03 S1200", "M08"]
    looked = ["M98 P1000", "M99", "G65 P9000 A1.", "M30.", "G150 X1.", "G07.9 X1.", "M097.6", "M2.5", "G-1 X1"]
    assert [x for x in passed if ctx.plain_hint(x)] == []
    assert [x for x in looked if not ctx.plain_hint(x)] == []
