"""The Haas corpus reads the probing macros' results where the ``haas`` profile documents them
(``dialects/haas_programs_data.py``, docs/profiles.md "Probing macros on the control"): after a
``G65 P98xx`` call, every common #100–#199 a program reads that it did not set itself is a
result one of the macros it called documents, and the stub that stands in for a macro kept on
the control (``O09812.nc``) writes only that macro's documented results. Hover on the call then
names every variable the program goes on to read."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import pytest

from cncmacro.dialects import get_dialect
from cncmacro.lsp.program_docs import doc_lines
from cncmacro.syntax.block_parser import parse_block
from cncmacro.syntax.nodes import Assign, Number, Var
from cncmacro.syntax.walk import iter_nodes
from test_corpus import CORPUS

HAAS = CORPUS / "haas"
PROFILE = get_dialect("haas")
COMMONS = range(100, 200)  # where Inspection Plus leaves its results


@dataclass
class Line:
    """What one line of a program does with the commons #100–#199, and the G65 call it makes."""

    number: int
    called: int | None = None
    reads: set[int] = field(default_factory=set)
    writes: set[int] = field(default_factory=set)


def _lines(path: Path) -> list[Line]:
    out: list[Line] = []
    for number, text in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
        block = parse_block(text)
        line = Line(number)
        letters = {w.letter: w.value.value for w in block.words if isinstance(w.value, Number)}
        if letters.get("G") == 65 and "P" in letters:
            line.called = int(letters["P"])
        targets = {id(n.target) for n in iter_nodes(block) if isinstance(n, Assign)}
        for node in iter_nodes(block):
            if isinstance(node, Var) and node.number in COMMONS:
                (line.writes if id(node) in targets else line.reads).add(node.number)
        out.append(line)
    return out


def _documented(number: int) -> set[int]:
    doc = PROFILE.program_doc(number)
    return {n for n, _, _ in doc.results} if doc is not None else set()


def _unexplained_reads(path: Path) -> list[tuple[int, int]]:
    """(line, #n) of each common read after a documented macro's call that neither the program set
    before nor any macro it called documents as a result."""
    called: list[int] = []
    results: set[int] = set()
    written: set[int] = set()
    wrong: list[tuple[int, int]] = []
    for line in _lines(path):
        if called:
            wrong += [(line.number, n) for n in sorted(line.reads - written - results)]
        written |= line.writes
        if line.called is not None and PROFILE.program_doc(line.called) is not None:
            called.append(line.called)
            results |= _documented(line.called)
    return wrong


PROBING = sorted(p.name for p in HAAS.glob("*.nc") if any(line.called in (9811, 9812) for line in _lines(p)))


def test_the_corpus_has_probing_programs_to_check() -> None:
    assert PROBING == ["probe_bore_g154.nc", "probe_vise_wips.nc"]


@pytest.mark.parametrize("name", PROBING)
def test_a_probing_program_reads_only_the_results_its_macros_document(name: str) -> None:
    assert _unexplained_reads(HAAS / name) == []


def test_the_o9812_stub_writes_only_the_results_the_profile_documents_for_o9812() -> None:
    lines = _lines(HAAS / "O09812.nc")
    written = set().union(*(line.writes for line in lines))
    assert written == {185, 186, 188, 190, 191, 193}  # X, Y, size, X error, Y error, size error
    assert written <= _documented(9812)


@pytest.mark.parametrize(("name", "macro"), [("probe_bore_g154.nc", 9812), ("probe_vise_wips.nc", 9811)])
def test_hover_on_the_g65_call_lists_every_result_the_program_reads(name: str, macro: int) -> None:
    lines = _lines(HAAS / name)
    reads = set().union(*(line.reads for line in lines)) - set().union(*(line.writes for line in lines))
    doc = PROFILE.program_doc(macro)
    assert doc is not None and reads
    for locale in ("en", "zh-CN"):
        hover = "\n".join(doc_lines(doc, locale))
        assert all(f"- **#{n}** — " in hover for n in reads), (locale, reads)


def test_a_read_of_the_fanuc_style_result_numbers_is_caught(tmp_path: Path) -> None:
    # the numbers Inspection Plus uses on a FANUC (#135 X ... #149 probe error) are not Haas's
    old = tmp_path / "old.nc"
    old.write_text("%\nO01008\nG65 P9812 X50.\nIF [#149 EQ 1] #3000 = 30\n#101 = #135\n#102 = #185\nM30\n%\n")
    assert _unexplained_reads(old) == [(4, 149), (5, 135)]
