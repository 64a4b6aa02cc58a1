"""``cncmacro check`` of a big folder checks the files that no call connects one group after
another and prints each group's findings at once (docs/cli.md, "cncmacro check"): its memory
follows the largest group of files that call each other, not the folder, and the first files'
findings are on standard output while the rest are still being checked. Files that calls
connect are still checked together: a macro's finding that only its caller's argument causes is
reported, also when the caller names it by a computed number."""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

import pytest

ALONE = "%\nO{n:04d}\n#1=#2/0\nG01 X[#1+{n}] Y10 F100\nM30\n%\n"  # division by zero (alarm 112), line 3

# peak resident memory of a child process, in KB (ru_maxrss of the children it waited for)
PEAK = (
    "import resource, subprocess, sys\n"
    "subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)\n"
    "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n"
)


def folder_of(tmp_path: Path, name: str, files: int) -> Path:
    folder = tmp_path / name
    folder.mkdir()
    for n in range(1, files + 1):
        (folder / f"O{n:04d}.nc").write_text(ALONE.format(n=n), encoding="utf-8")
    return folder


def peak_kb(folder: Path, jobs: str) -> int:
    """The peak of the checking process and of each of its workers, whichever is highest."""
    done = subprocess.run([sys.executable, "-c", PEAK, sys.executable, "-m", "cncmacro", "check", "--jobs", jobs,
                           str(folder)], capture_output=True, text=True, timeout=300, check=True)  # fmt: skip
    return int(done.stdout)


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_check_memory_does_not_grow_with_the_number_of_unconnected_files(tmp_path: Path, jobs: str) -> None:
    small, large = folder_of(tmp_path, "small", 200), folder_of(tmp_path, "large", 3_000)
    grown_mb = (peak_kb(large, jobs) - peak_kb(small, jobs)) / 1024
    # all held to the end, as before, the 2,800 files more would cost about 45 KB each: 120 MB
    assert grown_mb < 30, f"{grown_mb:.0f} MB more for 2,800 more files"


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_check_prints_the_first_files_findings_while_the_rest_are_checked(tmp_path: Path, jobs: str) -> None:
    # each file's run counts to 2,000 (6,000 blocks) before it divides by zero: checking takes far
    # longer than listing and reading the files, after which the first group is checked and printed
    folder = tmp_path / "loops"
    folder.mkdir()
    for n in range(1, 401):
        (folder / f"O{n:04d}.nc").write_text(f"O{n:04d}\n#1=0\nWHILE[#1 LT 2000]DO1\n#1=#1+1\nEND1\n#2=#3/0\nM30\n",
                                             encoding="utf-8")  # fmt: skip
    start = time.monotonic()
    command = [sys.executable, "-m", "cncmacro", "check", "--jobs", jobs, str(folder)]
    with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                          encoding="utf-8") as checker:  # fmt: skip
        assert checker.stdout is not None
        first = checker.stdout.readline()
        first_at = time.monotonic() - start
        rest = checker.stdout.read()
    done_at = time.monotonic() - start
    assert first.endswith("O0001.nc:6:1: error: division by zero (alarm 112) [division-by-zero]\n")
    assert len(rest.splitlines()) == 399 and checker.returncode == 1
    # printed at the end, the first finding would come with the last, at about 80% of the time
    # (the rest is the interpreter's start and exit); printed as found, at about 15%
    assert first_at < 0.5 * done_at, f"first finding after {first_at:.1f} s of {done_at:.1f} s"


def test_check_runs_a_macro_through_its_caller_among_unrelated_files(tmp_path: Path) -> None:
    # O9100 divides by A-5: only its caller's A5 makes that zero (10/[5-5]); run on its own, A is
    # vacant, which counts as 0 in arithmetic: 10/[0-5] = -2, no alarm. Between them, files that
    # call nothing and nothing calls; O0002 names the macro by a computed number (#10=9100).
    folder = tmp_path / "shop"
    folder.mkdir()
    (folder / "O0001.nc").write_text("O0001\nG65 P9100 A5\nM30\n", encoding="utf-8")
    (folder / "O0002.nc").write_text("O0002\n#10=9200\nG65 P#10 A7\nM30\n", encoding="utf-8")
    for n in range(3, 40):
        (folder / f"O{n:04d}.nc").write_text(f"O{n:04d}\nG01 X{n} F100\nM30\n", encoding="utf-8")
    (folder / "O9100.nc").write_text("O9100\n#2=10/[#1-5]\nM99\n", encoding="utf-8")
    (folder / "O9200.nc").write_text("O9200\n#2=10/[#1-7]\nM99\n", encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "cncmacro", "check", str(folder)], capture_output=True,
                          text=True, encoding="utf-8", timeout=120)  # fmt: skip
    found = [line.split(str(folder))[-1] for line in done.stdout.splitlines()]
    assert found == [
        "/O9100.nc:2:1: error: division by zero (alarm 112); reached from O0001:2 (G65), at block 2 of the run "
        "[division-by-zero]",
        "/O9200.nc:2:1: error: division by zero (alarm 112); reached from O0002:3 (G65), at block 3 of the run "
        "[division-by-zero]",
    ], done.stdout
