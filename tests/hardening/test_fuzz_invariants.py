"""Fuzzing in the suite: random, mutated and hypothesis-written programs go through parse,
check, run and every language-server handler, and keep the invariants of
``benchmarks/fuzzing.py``: no uncaught exception, every run within its budget, every
diagnostic range inside the document, nothing stale published. The example counts are
bounded; ``benchmarks/fuzz.py --minutes N`` runs the same targets for as long as wanted."""

from __future__ import annotations

import random

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import fuzzing
from cncmacro.lsp.positions import UTF16
from fuzzing import DIALECTS, InvariantError, LspTarget, _inside_client, corpus_texts, mutate, random_program, run_case
from strategies import line

SETTINGS = settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
CORPUS = corpus_texts()


@SETTINGS
@given(seed=st.integers(0, 2**32 - 1), dialect=st.sampled_from(DIALECTS))
def test_random_programs_keep_every_invariant(lsp_target: LspTarget, seed: int, dialect: str) -> None:
    rnd = random.Random(seed)
    run_case(random_program(rnd), dialect, lsp_target, rnd)


@SETTINGS
@given(seed=st.integers(0, 2**32 - 1), dialect=st.sampled_from(DIALECTS))
def test_mutated_corpus_programs_keep_every_invariant(lsp_target: LspTarget, seed: int, dialect: str) -> None:
    rnd = random.Random(seed)
    run_case(mutate(rnd.choice(CORPUS), rnd, rounds=5), dialect, lsp_target, rnd)


@SETTINGS
@given(lines=st.lists(line(), min_size=1, max_size=12), dialect=st.sampled_from(DIALECTS), seed=st.integers(0, 99))
def test_hypothesis_written_lines_keep_every_invariant(
    lsp_target: LspTarget, lines: list[str], dialect: str, seed: int
) -> None:
    text = "\n".join(["O0001", *lines, "M30"])
    run_case(text, dialect, lsp_target, random.Random(seed))


def test_the_invariant_check_catches_a_range_past_the_line() -> None:
    """The fuzzing oracle itself: a protocol range one column past a line's end is reported."""
    _inside_client(["G01 X1"], 0, 0, 0, 6, "ok")
    with pytest.raises(InvariantError):
        _inside_client(["G01 X1"], 0, 6, 0, 7, "syntax")
    with pytest.raises(InvariantError):
        _inside_client(["G01 X1"], 1, 0, 1, 1, "syntax")


def test_a_block_that_ends_too_early_is_marked_inside_its_line(lsp_target: LspTarget) -> None:
    """The first bug the fuzzer found: an unclosed '[' at a line's end was published one
    column past the line (a protocol range outside the document)."""
    rnd = random.Random(0)
    for text in ("IF[#111", "O0001\n#1=[#2+3\nM30", "#1=SIN[", "G01 X[[[1"):
        run_case(text, "fanuc", lsp_target, rnd)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_odd_workspaces_keep_every_invariant(lsp_target: LspTarget, seed: int) -> None:
    """Odd file names, unreadable and deep folders, pipes, looping links, hostile machine files:
    check in every format and the server's index go through them."""
    rnd = random.Random(seed)
    run_case(random_program(rnd), rnd.choice(DIALECTS), lsp_target, rnd, odd=True)


def test_the_edit_oracle_catches_columns_read_in_another_encoding(
    lsp_target: LspTarget, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The fuzzing oracle itself: a server that reads a UTF-8 client's columns as UTF-16 puts an
    edit after Chinese text in the wrong place, and the check says so."""
    monkeypatch.setitem(fuzzing._ENCODERS, "utf-8", UTF16)
    lsp_target.encoding = "utf-8"
    text = "O0001\n(中文)#100=1\nM30\n"
    with pytest.raises(InvariantError, match="the server's text is not the editor's"):
        lsp_target.check(text, (fuzzing._FOLDER / "O0001.nc").as_uri(), [(1, 8)])
