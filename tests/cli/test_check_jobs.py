"""``cncmacro check --jobs N`` (docs/cli.md, "Checking in several processes"): the call groups of
a folder are checked in N processes, and what the check writes (standard output in each format,
standard error, the exit status) is the same, byte for byte, as with one: the findings come in
the order of one job's. This holds with the ``spawn`` start method that Windows uses too. Ctrl-C
stops the check and its workers with exit status 130 and no traceback, and a worker that dies
ends the check with exit status 2; ``--jobs 1`` starts no process; a ``--jobs`` that is no
number of processes is a usage error (exit status 2). ``--shard K/N`` checks whole call groups,
and the shards together report what one check does."""

from __future__ import annotations

import concurrent.futures
import io
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from cli_capture import cli
from cncmacro.cli.check import check_paths

posix_only = pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals and process groups")

# a script that checks as ``cncmacro`` does, its worker processes started with ``spawn``
SPAWNED = (
    "import multiprocessing, sys\n"
    "from cncmacro.cli.main import main\n"
    "if __name__ == '__main__':\n"
    "    multiprocessing.set_start_method('spawn')\n"
    "    sys.exit(main())\n"
)


def shop(tmp_path: Path) -> Path:
    """A folder of several call groups with findings in several files, a binary file, and a
    subfolder under its own machine file."""
    folder = tmp_path / "shop"
    folder.mkdir()
    # O9100 divides by A-5: only its caller's A5 makes that zero (10/[5-5]), so O0001 and
    # O9100 must be one group; run on its own, A is vacant: 10/[0-5] = -2, no alarm. The same
    # for O0002 and O9200 (10/[7-7]), whose file is not named after it: its O number is in its
    # text only, written with a space (the parser reads O 9200 as O9200).
    (folder / "O0001.nc").write_text("O0001\nG65 P9100 A5\nM30\n", encoding="utf-8")
    (folder / "O0002.nc").write_text("O0002\nG65 P9200 A7\nM30\n", encoding="utf-8")
    (folder / "O9100.nc").write_text("O9100\n#2=10/[#1-5]\nM99\n", encoding="utf-8")
    (folder / "sub.nc").write_text("O 9200\n#2=10/[#1-7]\nM99\n", encoding="utf-8")
    for n in range(10, 60):  # groups of one file each, every third with a division by zero (alarm 112)
        body = "#1=#2/0\n" if n % 3 == 0 else "G01 X10 F100\n"
        (folder / f"O{n:04d}.nc").write_text(f"O{n:04d}\n{body}M30\n", encoding="utf-8")
    (folder / "O0099.nc").write_bytes(b"O0099\n\x00\x01\x02binary\n")  # named on standard error, skipped
    lathe = folder / "lathe"
    lathe.mkdir()
    # its machine file switches division-by-zero to a warning for the files under it
    (lathe / ".cncmacro.toml").write_text('[severity]\ndivision-by-zero = "warning"\n', encoding="utf-8")
    (lathe / "O0500.nc").write_text("O0500\n#1=#2/0\nM30\n", encoding="utf-8")
    return folder


def check(*args: str, script: Path | None = None) -> tuple[int, str, str]:
    command = [sys.executable, str(script)] if script else [sys.executable, "-m", "cncmacro"]
    done = subprocess.run([*command, "check", *args], capture_output=True, text=True, encoding="utf-8",
                          timeout=300)  # fmt: skip
    return done.returncode, done.stdout, done.stderr


@pytest.mark.parametrize("fmt", ["text", "json", "sarif"])
def test_jobs_write_the_same_report_as_one_job_in_every_format(tmp_path: Path, fmt: str) -> None:
    folder = shop(tmp_path)
    one = check(str(folder), "--format", fmt, "--jobs", "1")
    assert one == check(str(folder), "--format", fmt, "--jobs", "2")
    assert one == check(str(folder), "--format", fmt, "--jobs", "3")
    code, out, err = one
    assert code == 2  # the binary file
    assert "O0099.nc" in err and err.count("\n") == 1, err
    # findings in several files of several groups, the lathe's under its own machine file
    for name in ("O9100.nc", "sub.nc", "O0012.nc", "O0057.nc", "O0500.nc"):
        assert name in out, name
    if fmt == "text":
        # the groups in the order of their first file: O0001's (with O9100), O0002's (with sub.nc)
        assert out.index("O9100.nc") < out.index("sub.nc") < out.index("O0012.nc") < out.index("O0057.nc")
        assert "O0500.nc:2:1: warning: division by zero" in out
        assert "sub.nc:2:1: error: division by zero (alarm 112); reached from O0002:2 (G65)" in out


def test_jobs_with_the_spawn_start_method_write_the_same_report(tmp_path: Path) -> None:
    folder = shop(tmp_path)
    script = tmp_path / "cncmacro_spawned.py"
    script.write_text(SPAWNED, encoding="utf-8")
    for fmt in ("text", "sarif"):
        assert check(str(folder), "--format", fmt, "--jobs", "2", script=script) == check(
            str(folder), "--format", fmt, "--jobs", "1"
        )


def test_jobs_1_starts_no_process(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    def refused(*args: object, **kwargs: object) -> None:
        raise AssertionError("a pool was started")

    monkeypatch.setattr(concurrent.futures, "ProcessPoolExecutor", refused)
    out, err = io.StringIO(), io.StringIO()
    assert check_paths([str(shop(tmp_path))], out, err, jobs=1) == 2  # the binary file
    assert "O9100.nc:2:1: error: division by zero" in out.getvalue()


def test_a_check_of_a_few_files_starts_no_process_whatever_the_jobs(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def refused(*args: object, **kwargs: object) -> None:
        raise AssertionError("a pool was started")

    monkeypatch.setattr(concurrent.futures, "ProcessPoolExecutor", refused)
    for n in range(1, 17):  # one batch of 16 files: a worker would cost more than it saves
        (tmp_path / f"O{n:04d}.nc").write_text(f"O{n:04d}\n#1=#2/0\nM30\n", encoding="utf-8")
    out, err = io.StringIO(), io.StringIO()
    assert check_paths([str(tmp_path)], out, err, jobs=8) == 1
    assert out.getvalue().count("division by zero") == 16


@pytest.mark.parametrize("given", ["0", "-2", "two", "1.5", ""])
def test_a_jobs_that_is_no_number_of_processes_is_a_usage_error(tmp_path: Path, given: str) -> None:
    program = tmp_path / "O0001.nc"
    program.write_text("O0001\nM30\n", encoding="utf-8")
    code, out, err = cli("check", "--jobs", given, str(program))
    assert code == 2 and out == ""
    assert f"argument -j/--jobs: {given!r} is not a number of processes: give a whole number, 1 or more" in err


@posix_only
@pytest.mark.parametrize("method", ["fork", "spawn"])
def test_ctrl_c_stops_a_check_with_jobs_and_its_workers_without_a_traceback(tmp_path: Path, method: str) -> None:
    # each file's run counts to 20,000 (60,000 blocks) before it divides by zero: the check
    # of 200 of them takes far longer than the wait for its first finding
    folder = tmp_path / "loops"
    folder.mkdir()
    for n in range(1, 201):
        (folder / f"O{n:04d}.nc").write_text(f"O{n:04d}\n#1=0\nWHILE[#1 LT 20000]DO1\n#1=#1+1\nEND1\n#2=#3/0\nM30\n",
                                             encoding="utf-8")  # fmt: skip
    script = tmp_path / "cncmacro_started.py"
    script.write_text(SPAWNED.replace("'spawn'", repr(method)), encoding="utf-8")

    def own_group() -> None:
        os.setsid()  # a terminal's foreground job: Ctrl-C reaches every process in it
        signal.signal(signal.SIGINT, signal.SIG_DFL)  # not ignored, as a background job's would be

    checker = subprocess.Popen([sys.executable, str(script), "check", "--jobs", "2", str(folder)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, encoding="utf-8",
                               preexec_fn=own_group)  # fmt: skip
    try:
        assert checker.stdout is not None
        first = checker.stdout.readline()
        assert first.endswith("O0001.nc:6:1: error: division by zero (alarm 112) [division-by-zero]\n"), first
        os.killpg(checker.pid, signal.SIGINT)  # Ctrl-C
        _, err = checker.communicate(timeout=60)
    finally:
        if checker.poll() is None:
            os.killpg(checker.pid, signal.SIGKILL)
    assert checker.returncode == 130
    assert "Traceback" not in err and "KeyboardInterrupt" not in err, err
    deadline = time.monotonic() + 10
    while _group_alive(checker.pid):  # its workers are gone too
        assert time.monotonic() < deadline, "a worker outlived the check"
        time.sleep(0.1)


def _group_alive(group: int) -> bool:
    try:
        os.killpg(group, 0)
    except ProcessLookupError:
        return False
    return True


def test_shards_together_report_what_one_check_does_with_each_call_group_whole(tmp_path: Path) -> None:
    folder = shop(tmp_path)
    _, whole, _ = check(str(folder), "--jobs", "1")
    shards = [check(str(folder), "--shard", f"{k}/3") for k in (1, 2, 3)]
    lines = [line for _, out, _ in shards for line in out.splitlines()]
    assert sorted(lines) == sorted(whole.splitlines()) and len(lines) == len(whole.splitlines())
    # the groups fall to the shards by a hash of their paths, which the temporary folder's name
    # changes: of the 20 groups with a finding, a shard may (rarely) have none, never two shards
    assert sum(bool(out) for _, out, _ in shards) >= 2
    # each macro's finding is in the shard that checked it with its caller: a shard with the
    # macro but not its caller would run it alone, where A is vacant and nothing divides by zero
    assert sum("O9100.nc:2:1: error: division by zero (alarm 112); reached from O0001:2" in out
               for _, out, _ in shards) == 1  # fmt: skip
    assert sum("sub.nc:2:1: error: division by zero (alarm 112); reached from O0002:2" in out
               for _, out, _ in shards) == 1  # fmt: skip


@pytest.mark.parametrize("given", ["0/2", "3/2", "1", "a/b", "1/0"])
def test_a_shard_that_is_not_k_of_n_is_a_usage_error(tmp_path: Path, given: str) -> None:
    program = tmp_path / "O0001.nc"
    program.write_text("O0001\nM30\n", encoding="utf-8")
    code, out, err = cli("check", "--shard", given, str(program))
    assert code == 2 and out == ""
    assert f"argument --shard: {given!r} is not a shard: give K/N, the Kth of N shards" in err


@posix_only
def test_a_worker_that_dies_ends_the_check_with_status_2_instead_of_a_wait(tmp_path: Path) -> None:
    folder = tmp_path / "loops"
    folder.mkdir()
    for n in range(1, 201):  # as above: far longer to check than the wait for the first finding
        (folder / f"O{n:04d}.nc").write_text(f"O{n:04d}\n#1=0\nWHILE[#1 LT 20000]DO1\n#1=#1+1\nEND1\n#2=#3/0\nM30\n",
                                             encoding="utf-8")  # fmt: skip
    checker = subprocess.Popen([sys.executable, "-m", "cncmacro", "check", "--jobs", "2", str(folder)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, encoding="utf-8")  # fmt: skip
    try:
        assert checker.stdout is not None
        checker.stdout.readline()  # the workers are at work
        workers = subprocess.run(["pgrep", "-P", str(checker.pid)], capture_output=True, text=True, check=True)
        os.kill(int(workers.stdout.split()[0]), signal.SIGKILL)  # as the out-of-memory killer would
        _, err = checker.communicate(timeout=60)
    finally:
        if checker.poll() is None:
            checker.kill()
    assert checker.returncode == 2
    said = "cncmacro check: a checking process ended before it was done (killed, or out of memory?); check with"
    assert err == f"{said} fewer --jobs, or with --jobs 1\n"


@posix_only
def test_a_linked_program_keeps_the_machine_file_of_the_folder_its_link_leads_to(tmp_path: Path) -> None:
    # the machine file is looked for once per folder, but a link's is that of the folder it
    # leads to (find_machine_file resolves it), as when each file was looked for on its own; a
    # link that leads out of a folder is checked when it is named on the command line
    lathe, mill = tmp_path / "lathe", tmp_path / "mill"
    lathe.mkdir()
    mill.mkdir()
    (lathe / ".cncmacro.toml").write_text('[severity]\ndivision-by-zero = "warning"\n', encoding="utf-8")
    (lathe / "O0001.nc").write_text("O0001\n#1=#2/0\nM30\n", encoding="utf-8")
    (mill / "O0002.nc").write_text("O0002\n#1=#2/0\nM30\n", encoding="utf-8")
    (mill / "O0001.nc").symlink_to(lathe / "O0001.nc")
    out, err = io.StringIO(), io.StringIO()
    check_paths([str(mill / "O0001.nc"), str(mill / "O0002.nc")], out, err)
    assert out.getvalue().splitlines() == [
        f"{mill / 'O0001.nc'}:2:1: warning: division by zero (alarm 112) [division-by-zero]",
        f"{mill / 'O0002.nc'}:2:1: error: division by zero (alarm 112) [division-by-zero]",
    ], err.getvalue()
