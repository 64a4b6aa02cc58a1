"""``cncmacro check`` of a big folder: its peak memory and time, and when the first finding comes.

Generates a folder of small programs in a temporary folder (each a few lines that divide by
zero and jump to a missing label: two findings a file, no program calling another) and runs a
real ``cncmacro check`` on it, reading its standard output as it comes. Prints the time to the
first finding and to the end, the findings, and the process's peak resident memory (Linux's
``ru_maxrss`` of the child). Budget (issue 34): memory that does not follow the number of files,
at most 150 MB at 20,000 files (it was 918 MB, about 45 KB a file, when every finding was held to
the end).

    python benchmarks/check_folder.py [--files 20000]
"""

from __future__ import annotations

import argparse
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BUDGET_MB = 150.0
PROGRAM = "%\nO{n:05d}\n#1=#2/0\nG01 X[#1+{n}] Y10 F100\nGOTO 99\nM30\n%\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--files", type=int, default=20_000)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp) / "programs"
        folder.mkdir()
        for n in range(1, args.files + 1):
            (folder / f"O{n:05d}.nc").write_text(PROGRAM.format(n=n), encoding="utf-8")
        start = time.monotonic()
        with subprocess.Popen([sys.executable, "-m", "cncmacro", "check", str(folder)], stdout=subprocess.PIPE,
                              text=True, encoding="utf-8") as checker:  # fmt: skip
            assert checker.stdout is not None
            first = checker.stdout.readline()
            first_at = time.monotonic() - start
            findings = 1 + sum(1 for _ in checker.stdout) if first else 0
        done_at = time.monotonic() - start
    peak_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    verdict = "within" if peak_mb <= BUDGET_MB else "OVER"
    print(f"cncmacro check of {args.files:,} files: {findings:,} findings, exit status {checker.returncode}")
    print(f"  first finding after {first_at:.2f} s, all after {done_at:.2f} s")
    print(f"  peak resident memory {peak_mb:.0f} MB ({peak_mb * 1024 / args.files:.1f} KB a file); "
          f"budget {BUDGET_MB:.0f} MB: {verdict}")  # fmt: skip


if __name__ == "__main__":
    main()
