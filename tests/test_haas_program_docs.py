"""The programs the ``haas`` profile documents as kept on the control (its probing and tool-setter
macros, ``dialects/haas_programs_data.py``): each lives where the profile says programs are kept,
is described in English and Chinese, reads only letters a G65 call can give and writes only
variables the machine has; no other profile documents any (docs/profiles.md "Probing macros on
the control")."""

from __future__ import annotations

import re

import pytest

from cncmacro.dialects import DIALECTS, get_dialect
from cncmacro.dialects.dialect import ARGUMENTS_I
from cncmacro.dialects.tables import ProgramDoc

CJK = re.compile(r"[\u4e00-\u9fff]")
HAAS = get_dialect("haas")
DOCS = HAAS.program_docs()


def test_haas_documents_its_probing_macros_and_no_other_profile_documents_any() -> None:
    numbers = [d.number for d in DOCS]
    assert {9810, 9811, 9812, 9814, 9832, 9833, 9023} <= set(numbers)
    assert numbers == sorted(set(numbers))  # one record each, in number order
    for name in DIALECTS:
        if name != "haas":
            assert get_dialect(name).program_docs() == () and get_dialect(name).program_doc(9811) is None, name


@pytest.mark.parametrize("doc", DOCS, ids=lambda d: f"O{d.number}")
def test_each_program_is_on_the_control_bilingual_and_called_with_g65_letters(doc: ProgramDoc) -> None:
    assert HAAS.on_control(doc.number) and HAAS.program_doc(doc.number) is doc
    texts = [(doc.title, doc.title_zh), (doc.en, doc.zh)]
    texts += [(en, zh) for _, en, zh in doc.arguments] + [(en, zh) for _, en, zh in doc.results]
    for en, zh in texts:
        assert en and not CJK.search(en), en
        assert CJK.search(zh), zh
    letters = [letter for letter, _, _ in doc.arguments]
    assert len(letters) == len(set(letters)), letters
    assert set(letters) <= set(ARGUMENTS_I), set(letters) - set(ARGUMENTS_I)
    for number, _, _ in doc.results:  # the macros write commons the machine keeps
        assert HAAS.common_range_of(number) is not None, number
