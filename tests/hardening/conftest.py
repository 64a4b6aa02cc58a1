"""Fixtures of the hardening tests: the big inputs, made once per session, and one in-process
language server for the fuzzed cases."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from camgen import cam_program
from fuzzing import LspTarget

MILLION = 1_000_000
TEN_MB = 10 * 1024 * 1024


@pytest.fixture(scope="session")
def ten_mb_line() -> str:
    """One line of 10 MB: a motion block with 2.6 million X words."""
    text = "G01 " + "X1.5 " * ((TEN_MB - 4) // 5 + 1)
    assert len(text) >= TEN_MB
    return text


@pytest.fixture(scope="session")
def million_line_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A CAM program of a million lines, alone in its workspace folder."""
    folder = tmp_path_factory.mktemp("million")
    path = folder / "O0001.nc"
    path.write_text(cam_program(MILLION), encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def lsp_target() -> Iterator[LspTarget]:
    target = LspTarget()
    yield target
    target.close()
