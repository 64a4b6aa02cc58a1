"""``cncmacro run`` that saves the persistent variables leaves nothing but them beside the
programs (docs/cli.md, the persistent variables of `cncmacro run`): the lock file it takes while it runs is gone
when it ends, whether it completed, stopped on an alarm, was interrupted with Ctrl-C or was
terminated; and a lock file a killed run left behind does not hold up the next run."""

from __future__ import annotations

import json
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from cli_capture import cli

posix_only = pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")

LOCK = ".cncmacro-vars.json.cncmacro-lock"


def _names(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir())


def test_a_saving_run_leaves_only_the_variable_file_beside_the_program(tmp_path):
    program = tmp_path / "O0001.nc"
    program.write_text("O0001\n#500=#500+1\nM30\n", encoding="utf-8")
    for _ in range(2):
        code, _, err = cli("run", str(program))
        assert code == 0, err
    assert _names(tmp_path) == [".cncmacro-vars.json", "O0001.nc"]
    assert json.loads((tmp_path / ".cncmacro-vars.json").read_text("utf-8"))["variables"] == {"500": 2.0}  # 0+1+1


def test_a_run_that_stops_on_an_alarm_leaves_no_lock_file_either(tmp_path):
    program = tmp_path / "O0001.nc"
    program.write_text("O0001\n#500=3\n#3000=1(STOP)\nM30\n", encoding="utf-8")
    code, out, _ = cli("run", str(program))
    assert code == 1 and "ALARM 3001: STOP" in out
    assert _names(tmp_path) == [".cncmacro-vars.json", "O0001.nc"]


def test_a_lock_file_left_by_a_killed_run_does_not_hold_up_the_next_run(tmp_path):
    program = tmp_path / "O0001.nc"
    program.write_text("O0001\n#500=#500+1\nM30\n", encoding="utf-8")
    (tmp_path / LOCK).write_text("999999\n", encoding="utf-8")  # nobody holds it any more
    began = time.monotonic()
    code, _, err = cli("run", "--wait", "5", str(program))
    assert code == 0, err
    assert time.monotonic() - began < 5  # taken at once, not after the wait
    assert _names(tmp_path) == [".cncmacro-vars.json", "O0001.nc"]


@posix_only
@pytest.mark.parametrize(("signal_number", "status"), [(signal.SIGINT, 130), (signal.SIGTERM, 128 + signal.SIGTERM)])
def test_an_interrupted_or_terminated_run_deletes_its_lock_file(tmp_path, signal_number, status):
    program = tmp_path / "O0001.nc"
    program.write_text("O0001\n#500=1\nWHILE[#500 GT 0]DO1\n#1=#1+1\nEND1\nM30\n", encoding="utf-8")
    run = subprocess.Popen(
        [sys.executable, "-m", "cncmacro", "run", "--max-blocks", "1000000000", str(program)],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        # Ctrl+C as a terminal delivers it, whatever the suite runs under: a job a shell started
        # in the background has SIGINT ignored, and so would the run it starts
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )  # fmt: skip
    try:
        deadline = time.monotonic() + 30
        while not (tmp_path / LOCK).exists():
            assert run.poll() is None and time.monotonic() < deadline, run.communicate()
            time.sleep(0.05)
        time.sleep(0.5)  # the machine is running the loop
        run.send_signal(signal_number)
        run.communicate(timeout=30)
    finally:
        if run.poll() is None:
            run.kill()
    assert run.returncode == status
    assert _names(tmp_path) == ["O0001.nc"]  # the run kept nothing: it never reached its end
