"""``cncmacro check``'s text output is one finding per line whatever a file is named: a line feed
or tab in a file name is written ``\\x0a``/``\\x09``, and a mark that reorders what the terminal
shows (U+202E, the right-to-left override) ``\\u202e``, so a file name can neither forge a
finding line nor disguise itself (docs/cli.md)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="Windows file names cannot hold a line feed")

DIVIDES_BY_ZERO = "O0001\n#1=1/0\nM30\n"


def check(folder: Path) -> list[str]:
    done = subprocess.run([sys.executable, "-m", "cncmacro", "check", str(folder)], capture_output=True,
                          text=True, encoding="utf-8", timeout=60)  # fmt: skip
    assert done.returncode == 1, done.stderr
    return done.stdout.splitlines()


def test_a_line_feed_in_a_file_name_cannot_forge_a_finding(tmp_path: Path) -> None:
    (tmp_path / "a.nc\nO9.nc:1:1: error: forged [syntax]\n.nc").write_text(DIVIDES_BY_ZERO, encoding="utf-8")
    [line] = check(tmp_path)  # one file, one finding, one line
    assert line.endswith("a.nc\\x0aO9.nc:1:1: error: forged [syntax]\\x0a.nc:2:1: error: division by zero "
                         "(alarm 112) [division-by-zero]")  # fmt: skip


def test_a_right_to_left_override_in_a_file_name_is_shown_escaped(tmp_path: Path) -> None:
    (tmp_path / "evil\u202egnp.nc").write_text(DIVIDES_BY_ZERO, encoding="utf-8")
    [line] = check(tmp_path)
    assert "\u202e" not in line and "evil\\u202egnp.nc:2:1: error: division by zero" in line
