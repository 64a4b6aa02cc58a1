"""A program deeper than Windows's 260-character path limit (a shop's archive of part folders
inside customer folders inside years). Where the system allows long paths it is checked and run
as any other; where it does not, the file is named with the system's reason. Never a traceback.
Windows only: the limit is Windows's; runs on the Windows runner."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.skipif(sys.platform != "win32", reason="Windows only: MAX_PATH (runs on the Windows runner)")


def _deep_folder(root: Path) -> Path:
    folder = root
    k = 0
    while len(str(folder)) < 300:
        folder = folder / f"customer_{k:02d}_part_folder_2026"
        k += 1
    # the \\?\ prefix makes a folder of any length, whatever the system's setting
    subprocess.run(["cmd", "/c", "mkdir", "\\\\?\\" + str(folder)], check=True, capture_output=True)
    return folder


def test_a_program_past_the_path_limit_is_checked_or_named_with_the_reason(tmp_path: Path) -> None:
    folder = _deep_folder(tmp_path.resolve())
    program = folder / "O0001.nc"
    with open("\\\\?\\" + str(program), "w", encoding="utf-8") as f:
        f.write("O0001\n#1=1/0\nM30\n")
    assert len(str(program)) > 260
    done = subprocess.run([sys.executable, "-m", "cncmacro", "check", str(program)], capture_output=True, text=True,
                          encoding="utf-8", timeout=120)  # fmt: skip
    assert "Traceback" not in done.stderr, done.stderr
    if done.returncode == 1:  # long paths allowed: the program's finding
        assert "division-by-zero" in done.stdout
    else:  # not allowed: the file named with the system's reason, status 2
        assert done.returncode == 2 and "O0001.nc" in done.stderr, (done.returncode, done.stdout, done.stderr)
