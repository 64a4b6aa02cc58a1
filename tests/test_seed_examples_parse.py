"""Every concrete example block of the seed manuals parses without error (SEMANTICS.md §1–§7)."""

from __future__ import annotations

import pytest

import seed_examples  # the catalogue of the manuals' examples
from cncmacro.syntax import parse_block
from cncmacro.syntax.document import ParsedDocument

ALL = list(seed_examples.SEED_BLOCKS) + list(getattr(seed_examples, "SEED_003_RESTORED", []))


@pytest.mark.parametrize("seed, where, dialect, text", ALL, ids=[f"{s}:{w}:{t}" for s, w, _d, t in ALL])
def test_seed_block_parses(seed, where, dialect, text):
    b = parse_block(text)
    assert not b.has_error, (seed, where, text, b.problems)


@pytest.mark.parametrize("name", sorted(seed_examples.SEED_PROGRAMS))
def test_seed_program_parses(name):
    doc = ParsedDocument(seed_examples.SEED_PROGRAMS[name])
    assert not any(b.has_error for b in doc.blocks)
    assert doc.program.units[0].number == int(name[1:])
