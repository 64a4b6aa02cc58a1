"""Which words are jumps (docs/semantics.md §4, §5) is the interpreter's rule
(``machine/jump_words.py``, on the call ``recognise_call`` finds): the label the editor's
searches find in a block (go to definition, references, rename, renumbering) is the label a run
of that block lands on, under each profile and machine file. Each case runs the block and looks
whether the run reached ``N10``."""

from __future__ import annotations

import pytest

from cncmacro.analysis.editing.sequence_numbers import renumber
from cncmacro.analysis.indexes.sites import jump_sites
from cncmacro.dialects import get_dialect
from cncmacro.library.machine_file import CallCode
from cncmacro.syntax.block_parser import parse_block
from cncmacro.syntax.program import build_program
from running import lines, run

_M97_CALLS_A_MACRO = {"M97": CallCode(9097)}

# (profile, the machine file's call codes, the block, whether it names N10 as a label)
CASES = [
    ("fanuc", {}, "M99 P10", True),  # a main program goes on from N10
    ("fanuc", {}, "M98 Q10", True),  # the program itself from N10
    ("fanuc", {}, "M198 Q10", True),  # as M98
    ("fanuc", {}, "G65 H81 P10 Q1 R1", False),  # a macro call of O0010 with the argument H
    ("fanuc", {}, "G65 P9010 M99. Q10", False),  # M and Q are arguments of the macro call
    ("fanuc", {}, "M97 P10", False),  # no local call on FANUC: a plain M code
    ("gsk980tdi", {}, "G65 H80 P10", True),  # macro A: an unconditional branch
    ("gsk980tdi", {}, "G65 H81 P10 Q1 R1", True),
    ("gsk980tdi", {}, "G65 H01 P#5 Q10", False),  # arithmetic: P is the result variable
    ("haas", {}, "M97 P10", True),  # a local subprogram call
    ("haas", _M97_CALLS_A_MACRO, "M97 P10", False),  # the machine file makes M97 a macro call
    ("haas", {}, "[#1 EQ 1] M99 P10", True),  # Haas's conditional jump, a GOTO
]


@pytest.mark.parametrize(("profile", "calls", "text", "jumps"), CASES, ids=[f"{p}: {t}" for p, _, t, _ in CASES])
def test_4_5_a_word_is_a_jump_where_the_run_jumps_by_it(
    profile: str, calls: dict[str, CallCode], text: str, jumps: bool
) -> None:
    m = run(lines("O0100", "#1=1", text, "#2=2", "M30", "N10 #3=3", "M30"), profile, calls=calls)
    assert (3 in m.variables()) == jumps, (m.status, m.alarm)
    labels = [j.label for j in jump_sites(parse_block(text), get_dialect(profile), calls)]
    assert labels == ([10] if jumps else [])


def test_4_5_renumbering_a_fanuc_program_leaves_the_program_number_of_g65_h81_alone() -> None:
    text = lines("O0100", "N10 #1=1", "G65 H81 P10 Q1 R1", "N20 M30")
    rows = text.split("\n")
    plan = renumber(build_program([parse_block(x) for x in rows]), get_dialect("fanuc"), start=100, step=100)
    assert plan.error is None and not plan.blockers
    assert all(c.line != 2 for c in plan.changes)  # P10 calls O0010: it is no label to follow
