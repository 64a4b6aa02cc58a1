"""Every concrete example in the seed manuals parses without error (docs/semantics.md §1–§7).

Blocks are parsed as printed. A few examples are not blocks but pieces of one (a variable
``#105``, a condition ``#1 EQ #0``); they are parsed where the manual uses them, inside an
assignment or an IF. Seed 003's printed text lost ``=`` signs and brackets in extraction,
so its examples are parsed in their restored form.
"""

from __future__ import annotations

import re

import pytest

import seed_examples  # the catalogue of the manuals' examples
from cncmacro.syntax import parse_block
from cncmacro.syntax.document import ParsedDocument

_RELATION = re.compile(r"EQ|NE|GT|GE|LT|LE", re.I)

ALL = [e for e in seed_examples.SEED_BLOCKS if e[0] != "003"] + list(seed_examples.SEED_003_RESTORED)


def in_context(text: str) -> str:
    """A fragment as the manual uses it; a whole block as it is."""
    stripped = text.strip()
    if stripped.startswith(("#", "[")) and "=" not in stripped:
        if _RELATION.search(stripped):
            cond = stripped if stripped.startswith("[") else f"[{stripped}]"
            return f"IF{cond}GOTO1"
        return f"#1={stripped}"
    return text


@pytest.mark.parametrize("seed, where, dialect, text", ALL, ids=[f"{s}:{t}" for s, _w, _d, t in ALL])
def test_seed_example_parses(seed, where, dialect, text):
    b = parse_block(in_context(text))
    assert not b.has_error, (seed, where, text, b.problems)


def test_every_catalogued_example_is_checked():
    assert len(ALL) >= 100
    assert {e[0] for e in ALL} >= {"000", "001", "002", "003"}


@pytest.mark.parametrize("name", sorted(seed_examples.SEED_PROGRAMS))
def test_seed_program_parses(name):
    doc = ParsedDocument(seed_examples.SEED_PROGRAMS[name])
    assert not any(b.has_error for b in doc.blocks), [b.problems for b in doc.blocks if b.has_error]
    assert doc.program.units[0].number == int(name[1:])
