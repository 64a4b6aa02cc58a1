"""The persistent variables are state that runs share, through ``cncmacro run``: runs that
start together take turns, so no update is lost; a save keeps the file's permissions and
writes through a link to it; a machine file's ``persistent_file`` cannot lead out of its
folder through a link; a value no control variable can hold, a file nested too deeply or a
FIFO is refused with a message, never a hang or a traceback; values the profile does not hold
stay in the file; and what a program writes reaches the terminal with its control characters
escaped."""

from __future__ import annotations

import json
import os
import stat
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

posix_only = pytest.mark.skipif(sys.platform == "win32", reason="POSIX links, modes, FIFOs and flock")

# each run adds 1 to #500, then keeps the machine busy for a while (about 0.2 s)
ADD_ONE = "O0001\n#500=#500+1\n#1=0\nWHILE[#1 LT 200000]DO1\n#1=#1+1\nEND1\nM30\n"


def cli(*args: str, timeout: float = 60, **kw: object) -> subprocess.CompletedProcess[str]:
    return subprocess.run(  # type: ignore[call-overload]
        [sys.executable, "-m", "cncmacro", *args], capture_output=True, text=True, timeout=timeout, **kw
    )


def start(*args: str) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, "-m", "cncmacro", *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )


def stored(path: Path) -> dict[str, float]:
    return json.loads(path.read_text("utf-8"))["variables"]


@pytest.fixture
def program(tmp_path: Path) -> Path:
    path = tmp_path / "O0001.nc"
    path.write_text("O0001\n#500=#500+1\nM30\n", encoding="utf-8")
    return path


def test_runs_started_together_each_add_their_one(tmp_path: Path) -> None:
    program = tmp_path / "O0001.nc"
    program.write_text(ADD_ONE, encoding="utf-8")
    runs = [start("run", str(program)) for _ in range(4)]
    for r in runs:
        _, err = r.communicate(timeout=60)
        assert r.returncode == 0, err
    assert stored(tmp_path / ".cncmacro-vars.json") == {"500": 4.0}


@posix_only
def test_runs_that_keep_nothing_leave_no_lock_file_and_never_let_two_runs_in(tmp_path: Path) -> None:
    # a run that keeps nothing deletes the lock file it made; a run that was waiting on that file
    # locks the path anew, so a third run still waits for it
    from cncmacro.library.persistence_lock import PersistentLockError, lock_persistent

    path = tmp_path / ".cncmacro-vars.json"
    first = lock_persistent(path)
    waited: list[object] = []
    second_run = threading.Thread(target=lambda: waited.append(lock_persistent(path, wait=10)))
    second_run.start()
    time.sleep(0.3)  # the second run has opened the lock file and waits on it
    first.remove()
    second_run.join(10)
    second = waited[0]
    with pytest.raises(PersistentLockError):
        lock_persistent(path, wait=0.3)
    second.remove()  # type: ignore[attr-defined]
    assert list(tmp_path.iterdir()) == []
    quiet = tmp_path / "O0002.nc"
    quiet.write_text("O0002\n#1=0\nWHILE[#1 LT 200000]DO1\n#1=#1+1\nEND1\nM30\n", encoding="utf-8")
    counting = tmp_path / "O0001.nc"
    counting.write_text(ADD_ONE, encoding="utf-8")
    runs = [start("run", str(quiet if k % 2 else counting)) for k in range(6)]
    for r in runs:
        _, err = r.communicate(timeout=60)
        assert r.returncode == 0, err
    assert stored(tmp_path / ".cncmacro-vars.json") == {"500": 3.0}


@pytest.mark.skipif(sys.platform == "win32", reason="fcntl.flock")
def test_a_run_that_waits_in_vain_says_so_and_changes_nothing(tmp_path: Path, program: Path) -> None:
    import fcntl

    vars_file = tmp_path / ".cncmacro-vars.json"
    vars_file.write_text('{"variables": {"500": 7.0}}\n', encoding="utf-8")
    with open(tmp_path / ".cncmacro-vars.json.cncmacro-lock", "w") as held:  # another run has the file
        fcntl.flock(held, fcntl.LOCK_EX)
        held.write(f"{os.getpid()}\n")
        held.flush()
        began = time.monotonic()
        r = cli("run", "--wait", "0.3", str(program))
        assert r.returncode == 2 and r.stdout == ""
        assert "in use by another run or debug session" in r.stderr and f"process {os.getpid()}" in r.stderr
        assert "--no-save" in r.stderr and time.monotonic() - began < 10
        looked = cli("run", "--no-save", "--json", str(program))  # a run that saves nothing does not wait
        assert looked.returncode == 0 and json.loads(looked.stdout)["variables"] == {"500": 8.0}
    assert stored(vars_file) == {"500": 7.0}
    assert cli("run", str(program)).returncode == 0
    assert stored(vars_file) == {"500": 8.0}


@pytest.mark.skipif(sys.platform != "win32", reason="Windows only: msvcrt.locking (runs on the Windows runner)")
def test_a_run_waits_in_vain_for_a_lock_held_with_msvcrt_and_changes_nothing(tmp_path: Path, program: Path) -> None:
    import msvcrt

    vars_file = tmp_path / ".cncmacro-vars.json"
    vars_file.write_text('{"variables": {"500": 7.0}}\n', encoding="utf-8")
    with open(tmp_path / ".cncmacro-vars.json.cncmacro-lock", "w") as held:  # another run has the file
        held.write(f"{os.getpid()}\n")
        held.flush()
        held.seek(0)
        msvcrt.locking(held.fileno(), msvcrt.LK_NBLCK, 1)  # byte 0, as the runs lock it
        try:
            r = cli("run", "--wait", "0.3", str(program))
        finally:
            held.seek(0)
            msvcrt.locking(held.fileno(), msvcrt.LK_UNLCK, 1)
        assert r.returncode == 2 and r.stdout == ""
        assert "in use by another run or debug session" in r.stderr and "--no-save" in r.stderr
    assert stored(vars_file) == {"500": 7.0}
    assert cli("run", str(program)).returncode == 0  # the lock let go: the run saves
    assert stored(vars_file) == {"500": 8.0}


@posix_only
def test_a_save_keeps_a_group_shared_files_mode(tmp_path: Path, program: Path) -> None:
    vars_file = tmp_path / ".cncmacro-vars.json"
    vars_file.write_text('{"variables": {"500": 1.0}}\n', encoding="utf-8")
    vars_file.chmod(0o664)
    assert cli("run", str(program)).returncode == 0
    assert stored(vars_file) == {"500": 2.0}
    assert stat.S_IMODE(vars_file.stat().st_mode) == 0o664
    vars_file.unlink()  # a new file gets the mode any new file gets: 0666 less the umask
    assert cli("run", str(program), preexec_fn=lambda: os.umask(0o002)).returncode == 0
    assert stat.S_IMODE(vars_file.stat().st_mode) == 0o664


@posix_only
def test_a_linked_file_is_written_through_its_link(tmp_path: Path, program: Path) -> None:
    shared = tmp_path / "shared"
    shared.mkdir()
    target = shared / "machine-vars.json"
    target.write_text('{"variables": {"500": 10.0}}\n', encoding="utf-8")
    link = tmp_path / ".cncmacro-vars.json"
    link.symlink_to(target)
    assert cli("run", str(program)).returncode == 0
    assert cli("run", str(program)).returncode == 0
    assert link.is_symlink() and stored(target) == {"500": 12.0}
    assert sorted(p.name for p in shared.iterdir()) == ["machine-vars.json"]  # the lock file went with the run
    target.unlink()  # a link to nothing is refused, not followed to make a file there
    r = cli("run", str(program))
    assert r.returncode == 2 and "is a link to" in r.stderr and "does not exist" in r.stderr
    assert not target.exists() and link.is_symlink()
    assert cli("run", "--no-save", str(program)).returncode == 0  # a run that only reads finds #500 vacant


@posix_only
@pytest.mark.parametrize("linked", ["folder", "file"])
def test_persistent_file_cannot_lead_out_of_the_machine_files_folder_through_a_link(
    tmp_path: Path, linked: str
) -> None:
    workspace, outside = tmp_path / "workspace", tmp_path / "outside"
    workspace.mkdir()
    outside.mkdir()
    (outside / "vars.json").write_text('{"variables": {"500": 1.0}}\n', encoding="utf-8")
    if linked == "folder":
        (workspace / "state").symlink_to(outside, target_is_directory=True)
    else:
        (workspace / "state").mkdir()
        (workspace / "state" / "vars.json").symlink_to(outside / "vars.json")
    (workspace / ".cncmacro.toml").write_text('persistent_file = "state/vars.json"\n', encoding="utf-8")
    main = workspace / "O0001.nc"
    main.write_text("O0001\n#500=#500+1\nM30\n", encoding="utf-8")
    r = cli("run", str(main))
    assert r.returncode == 2 and "persistent_file" in r.stderr and "outside the machine file's folder" in r.stderr
    assert sorted(p.name for p in outside.iterdir()) == ["vars.json"]
    assert stored(outside / "vars.json") == {"500": 1.0}


@pytest.mark.parametrize("value", ["NaN", "Infinity", "-Infinity", "1e999", '"nan"'])
def test_a_value_no_variable_can_hold_is_refused_naming_its_variable(tmp_path: Path, program: Path, value: str) -> None:
    vars_file = tmp_path / ".cncmacro-vars.json"
    text = f'{{"variables": {{"500": 1.0, "501": {value}}}}}\n'
    vars_file.write_text(text, encoding="utf-8")
    r = cli("run", "--json", str(program))
    assert r.returncode == 2 and r.stdout == ""
    assert "#501" in r.stderr and "Traceback" not in r.stderr
    assert vars_file.read_text("utf-8") == text


@pytest.mark.parametrize("table", ["[variables]\n100 = nan\n", "[variables]\n100 = -inf\n", "[skip]\nZ = inf\n"])
def test_a_machine_file_value_that_is_not_finite_is_refused(tmp_path: Path, program: Path, table: str) -> None:
    (tmp_path / ".cncmacro.toml").write_text(table, encoding="utf-8")
    r = cli("run", "--json", "--no-save", str(program))
    assert r.returncode == 2 and r.stdout == "" and "finite" in r.stderr


@pytest.mark.parametrize("name", [".cncmacro-vars.json", ".cncmacro.toml"])
def test_a_file_nested_too_deeply_is_refused(tmp_path: Path, program: Path, name: str) -> None:
    (tmp_path / name).write_text("[" * 100_000 if name.endswith(".json") else "a = " + "[" * 100_000, "utf-8")
    for command in ("run", "check"):
        r = cli(command, str(program))
        assert r.returncode == 2 and "nested too deeply" in r.stderr and "Traceback" not in r.stderr
        if name.endswith(".json"):
            break  # check never reads the persistent variables


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs")
def test_a_fifo_is_refused_at_once(tmp_path: Path, program: Path) -> None:
    os.mkfifo(tmp_path / ".cncmacro-vars.json")
    try:
        r = cli("run", str(program), timeout=10)
    except subprocess.TimeoutExpired:
        pytest.fail("cncmacro run waits for a writer on the FIFO")
    assert r.returncode == 2 and "not a regular file" in r.stderr


def test_values_the_profile_does_not_hold_stay_in_the_file(tmp_path: Path, program: Path) -> None:
    vars_file = tmp_path / ".cncmacro-vars.json"
    vars_file.write_text('{"variables": {"500": 1.0, "98000": 5.0}}\n', encoding="utf-8")  # a 30i's extended
    assert cli("run", "--dialect", "fanuc-0i", str(program)).returncode == 0
    assert stored(vars_file) == {"500": 2.0, "98000": 5.0}


CONTROLS = ["\x1b", "\x07", "\x9b", "\x08", "\r", "\x7f"]


@posix_only
def test_control_characters_reach_the_terminal_escaped(tmp_path: Path) -> None:
    name = "O\x1b[31m2.nc"
    program = tmp_path / name
    program.write_text(
        "O0002\n#3006=1(HI\x1b[31mRED\x07)\nPOPEN\nDPRNT[A\x1bMB\x08]\n#3000=1(BAD\x9b2J\x7f)\nGOTO 9\nM30\n",
        encoding="utf-8",
    )
    run = cli("run", "--no-save", str(program))
    check = cli("check", str(tmp_path))
    for r in (run, check):
        assert not any(c in r.stdout + r.stderr for c in CONTROLS), (r.stdout, r.stderr)
    assert "stop at O\\x1b[31m2.nc:2: HI\\x1b[31mRED\\x07" in run.stdout
    assert "DPRNT  A\\x1bMB\\x08" in run.stdout
    assert "BAD\\x9b2J\\x7f" in run.stdout
    shown = str(tmp_path / "O\\x1b[31m2.nc")
    assert f"{shown}:6:6: error: GOTO 9" in check.stdout and "BAD\\x9b2J\\x7f" in check.stdout
    as_json = cli("run", "--no-save", "--json", str(program))  # JSON escapes them, and reads them back
    assert not any(c in as_json.stdout for c in CONTROLS)
    result = json.loads(as_json.stdout)
    assert result["output"] == ["A\x1bMB\x08"] and "BAD\x9b2J\x7f" in result["alarm"]["message"]
    found = json.loads(cli("check", "--format", "json", str(tmp_path)).stdout)
    assert {d["file"] for d in found} == {str(program)}
