"""The profiles' tables of cycle words (``Dialect.cycle_words``): every letter says what it means
in English and in Chinese, a form names each letter once, and the letters that make a block a
two-block cycle's second are letters of that second block; each table describes codes the
profile's G-code table has."""

from __future__ import annotations

import pytest

from bilingual_checks import CJK, PROSE
from cncmacro.dialects import DIALECTS, get_dialect
from cncmacro.dialects.describe import code_doc

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
