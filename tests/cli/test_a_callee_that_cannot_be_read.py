"""A called program whose file is there but cannot be read is not "neither in this file nor found
near it": the finding and the run's alarm 76 say which file could not be read and why. On a shop's
Windows PC the usual cause is the DNC program holding the file open while it sends it to the
control; a binary file saved under a program's name is the same case here."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

MAIN = "O0001\nM98 P1234\nM30\n"


def cncmacro(folder: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "cncmacro", *args], cwd=folder, capture_output=True, text=True,
                          encoding="utf-8", timeout=120)  # fmt: skip


def test_a_callee_saved_as_a_binary_file_is_named_with_the_reason(tmp_path: Path) -> None:
    (tmp_path / "O0001.nc").write_text(MAIN, encoding="utf-8")
    (tmp_path / "O1234.nc").write_bytes(b"O1234\n\x00\x01\x02 G01 X1.\n")  # a NUL at offset 6
    done = cncmacro(tmp_path, "check", "O0001.nc")
    assert done.returncode == 1, done.stderr
    said = done.stdout.strip()
    assert said.startswith("O0001.nc:2:5: error: M98 calls O1234, not found: ")
    assert "O1234.nc: binary file (byte at offset 6 is not program text), not a program (alarm 76)" in said
    run = cncmacro(tmp_path, "run", "--no-save", "O0001.nc")
    assert "ALARM 76: program O1234 not found: " in run.stdout + run.stderr
    assert "O1234.nc: binary file" in run.stdout + run.stderr


@pytest.mark.skipif(
    sys.platform != "win32", reason="Windows only: a file held open without sharing (runs on the Windows runner)"
)
def test_a_callee_a_dnc_program_holds_open_is_named_with_the_systems_reason(tmp_path: Path) -> None:
    import ctypes
    from ctypes import wintypes

    kernel32 = ctypes.WinDLL("kernel32", use_last_error=True)
    kernel32.CreateFileW.restype = wintypes.HANDLE
    kernel32.CreateFileW.argtypes = [wintypes.LPCWSTR, wintypes.DWORD, wintypes.DWORD, wintypes.LPVOID,
                                     wintypes.DWORD, wintypes.DWORD, wintypes.HANDLE]  # fmt: skip
    (tmp_path / "O0001.nc").write_text(MAIN, encoding="utf-8")
    callee = tmp_path / "O1234.nc"
    callee.write_text("O1234\nG01 X1. F100\nM99\n", encoding="utf-8")
    generic_read, no_sharing, open_existing = 0x80000000, 0, 3
    handle = kernel32.CreateFileW(str(callee), generic_read, no_sharing, None, open_existing, 0, None)
    assert handle not in (None, wintypes.HANDLE(-1).value), ctypes.get_last_error()
    try:
        done = cncmacro(tmp_path, "check", "O0001.nc")
    finally:
        kernel32.CloseHandle(handle)
    assert done.returncode == 1, done.stderr
    assert "M98 calls O1234, not found: " in done.stdout and "O1234.nc could not be read: " in done.stdout
    assert "Traceback" not in done.stderr
