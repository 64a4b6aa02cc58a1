"""The profiles' tables of cycle words (``Dialect.cycle_words``): every letter says what it means
in English and in Chinese, a form names each letter once, and the letters that make a block a
two-block cycle's second are letters of that second block; each table describes codes the
profile's G-code table has."""

from __future__ import annotations

import pytest

from bilingual_checks import CJK, PROSE
from cncmacro.dialects import DIALECTS, get_dialect
from cncmacro.dialects.describe import code_doc
from running import run

WITH_WORDS = [name for name in DIALECTS if get_dialect(name).cycle_words]


def test_both_lathes_and_the_fanuc_mills_describe_their_cycle_words() -> None:
    assert {"gsk980tdi", "fanuc-0i-lathe", "fanuc-0i", "fanuc-30i"} <= set(WITH_WORDS)
    assert 71.0 in get_dialect("gsk980tdi").cycle_words and 71.0 not in get_dialect("fanuc-0i").cycle_words


@pytest.mark.parametrize("profile", WITH_WORDS)
def test_every_cycle_word_has_its_chinese_and_each_form_names_a_letter_once(profile: str) -> None:
    dialect = get_dialect(profile)
    for number, cycle in dialect.cycle_words.items():
        assert code_doc(dialect, "G", number) is not None, f"{profile}: {cycle.code} is not in its G-code table"
        for form in cycle.forms:
            letters = [w.letter for w in form.words]
            assert len(letters) == len(set(letters)), f"{profile} {cycle.code}: {letters}"
            for w in form.words:
                assert w.en and CJK.search(w.zh), f"{profile} {cycle.code} {w.letter}: {w.zh!r}"
                assert not PROSE.search(w.zh.replace("mm", "").replace("µm", "")), f"{w.zh!r}"
        if len(cycle.forms) == 2:
            second = {w.letter for w in cycle.forms[1].words}
            assert cycle.second_marks and cycle.second_marks <= second, cycle.code


# a first and a second block of the roughing cycles, and a finishing shape each can rough
ROUGHING = {
    71.0: ("G71 U2. R1.", "G71 P10 Q20 U0.5 W0.1 F0.2", "N10 G00 X20.\nG01 Z-20.\nN20 X40."),
    72.0: ("G72 W2. R1.", "G72 P10 Q20 U0.5 W0.1 F0.2", "N10 G00 Z-10.\nG01 X20.\nN20 Z2."),
    73.0: ("G73 U3. W1. R3", "G73 P10 Q20 U0.5 W0.1 F0.2", "N10 G00 X20.\nG01 Z-20.\nN20 X40."),
}


@pytest.mark.parametrize("profile", ["gsk980tdi", "fanuc-0i-lathe"])
@pytest.mark.parametrize("code", sorted(ROUGHING))
def test_the_block_the_editor_calls_second_is_the_one_the_run_roughs_with(profile: str, code: float) -> None:
    cycle = get_dialect(profile).cycle_words[code]
    first, second, shape = ROUGHING[code]
    m = run(f"O0001\nG00 X40. Z2.\n{first}\n{second}\n{shape}\nM30\n", profile)
    assert not cycle.is_second([w[0] for w in first.split()[1:]])
    assert cycle.is_second([w[0] for w in second.split()[1:]])
    assert m.planner.cycle_params[code]["R"] in (1.0, 3.0)  # the first block set the parameters
    passes = {move.line for move in m.planner.moves if move.pass_of == cycle.code}
    assert passes == {3}  # the passes are moves of the second block (line 3)
