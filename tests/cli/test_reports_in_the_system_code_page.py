"""A report written in the system's code page. A Chinese Windows writes a redirected report
(``cncmacro check DIR > report.txt``, a task's output) in GBK, which has no ``✓`` or emoji: a
file name or a message with one ended ``check`` and ``run`` in an encoding error. What GBK lacks
is now written as JSON's ``\\uNNNN`` escapes, the Chinese text as GBK, and the JSON output still
reads back as the same text. ``PYTHONIOENCODING=cp936`` gives Python the same stream here as
that Windows does."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

NAME = "O0001_\u2713\U0001f600.nc"  # a check mark and an emoji: neither is in GBK
ESCAPED = "O0001_\\u2713\\ud83d\\ude00.nc"
PROGRAM = "O0001 (PART \u2713)\n#1=1/0\nM30\n"


def cncmacro(folder: Path, *args: str) -> tuple[int, str, str]:
    env = dict(os.environ, PYTHONIOENCODING="cp936")
    done = subprocess.run([sys.executable, "-m", "cncmacro", *args], cwd=folder, env=env, capture_output=True,
                          timeout=120)  # fmt: skip
    return done.returncode, done.stdout.decode("gbk"), done.stderr.decode("gbk")


def test_check_writes_what_the_code_page_lacks_as_escapes_and_its_chinese_as_gbk(tmp_path: Path) -> None:
    (tmp_path / NAME).write_text(PROGRAM, encoding="utf-8")
    code, out, err = cncmacro(tmp_path, "check", NAME)
    assert (code, err) == (1, "")
    assert out == f"{ESCAPED}:2:1: error: division by zero (alarm 112) [division-by-zero]\n"
    code, out, err = cncmacro(tmp_path, "check", "--locale", "zh-cn", NAME)
    assert (code, err) == (1, "")
    assert out == f"{ESCAPED}:2:1: error: 除数为零（报警 112） [division-by-zero]\n"


def test_run_names_the_alarms_file_in_the_code_page(tmp_path: Path) -> None:
    (tmp_path / NAME).write_text(PROGRAM, encoding="utf-8")
    code, out, err = cncmacro(tmp_path, "run", "--no-save", NAME)
    assert code == 1 and "Traceback" not in err
    assert f"ALARM 112: division by zero\n  at {ESCAPED}:2\n" in out + err


def test_the_json_report_in_the_code_page_reads_back_as_the_same_names(tmp_path: Path) -> None:
    (tmp_path / NAME).write_text(PROGRAM, encoding="utf-8")
    code, out, err = cncmacro(tmp_path, "check", "--format", "json", NAME)
    assert (code, err) == (1, "")
    [finding] = json.loads(out)
    assert (finding["file"], finding["line"], finding["code"]) == (NAME, 2, "division-by-zero")
