"""The language server's own words (``lsp/texts.py``, ARCHITECTURE.md rule L13): each written in
English and in Chinese, the Chinese showing every value the English shows (it may show more:
``把WH写全为WHILE`` names the word it expands, where "Write WHILE in full" does not need to)."""

from __future__ import annotations

import string

import pytest

from bilingual_checks import CJK
from cncmacro.lsp.texts import TEXTS, t


def _places(text: str) -> set[str]:
    return {name for _, name, _, _ in string.Formatter().parse(text) if name}


@pytest.mark.parametrize("key", sorted(TEXTS))
def test_every_editor_text_has_its_chinese_showing_the_values_of_the_english(key: str) -> None:
    en, zh = TEXTS[key]
    assert en.strip() and CJK.search(zh), key
    assert _places(en) <= _places(zh), key


def test_a_text_is_picked_by_the_locale_and_its_values_filled_in() -> None:
    assert t("refused", "en", label="Renumber", text="N10") == "Renumber: refused. N10"
    assert t("refused", "zh-CN", label="重新编排顺序号", text="N10") == "重新编排顺序号：已拒绝。N10"
    assert t("reading_lines", "zh-cn", lines=1_000_000) == "读取 1,000,000 行"
