"""``cncmacro check`` of a shop's program library, in one process and in two (``--jobs``).

Generates, with the shared benchmark generator ``gen_programs.py`` (not part of this
repository: give its path with ``--generator`` or the ``CNCMACRO_GENERATOR`` environment
variable), a folder of 10,000 CAM programs of 100 lines (``--style cam --percent end``, seed
1 to 10,000: one seed per file) and one program of 1,000,000 lines (seed 1), in a temporary
folder. Then times a real ``cncmacro check`` of the folder with ``--jobs 1`` and ``--jobs 2``
and of the 1M-line file, checks that the reports of one and two jobs are the same, and prints
the figures, the best of ``--rounds``, and the verdicts of the budget (issue 36): the folder
with two jobs in at most 1.2 times the 1M-line file's time, and at least 1.7 times as fast
with two jobs as with one. Beside each time is the processor time of the check and its
workers (user and system), which other work on the machine changes less than the wall time.

    python benchmarks/check_library.py --generator PATH/gen_programs.py [--files 10000] [--rounds 2]
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from types import ModuleType

TIME_RATIO = 1.2  # the folder with two jobs, against the 1M-line file
SPEED_UP = 1.7  # one job against two


def generator(path: str) -> ModuleType:
    """The shared generator, imported from ``path`` (its ``Gen`` makes a program's text)."""
    spec = importlib.util.spec_from_file_location("gen_programs", path)
    if spec is None or spec.loader is None:
        raise SystemExit(f"check_library.py: cannot load the generator {path}")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def program(gen: ModuleType, lines: int, seed: int) -> str:
    """What ``gen_programs.py --style cam --lines LINES --seed SEED --percent end`` writes."""
    text: str = gen.Gen("cam", lines, seed, "end").generate()
    return text


def timed(args: list[str]) -> tuple[float, float, bytes]:
    """The wall time of ``cncmacro check ARGS``, the processor time of it and its workers, and
    its standard output."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "cncmacro", "check", *args], capture_output=True, check=False)
    took = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    if done.returncode not in (0, 1):
        raise SystemExit(f"cncmacro check {' '.join(args)}: exit status {done.returncode}\n{done.stderr.decode()}")
    return took, cpu, done.stdout


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--generator", default=os.environ.get("CNCMACRO_GENERATOR"),
                        help="the shared generator gen_programs.py (default: $CNCMACRO_GENERATOR)")  # fmt: skip
    parser.add_argument("--files", type=int, default=10_000, help="programs in the library (default 10000)")
    parser.add_argument("--lines", type=int, default=100, help="lines of each (default 100)")
    parser.add_argument("--big", type=int, default=1_000_000, help="lines of the one big program (default 1000000)")
    parser.add_argument("--rounds", type=int, default=2, help="runs of each, the best counted (default 2)")
    args = parser.parse_args()
    if not args.generator:
        parser.error("give the shared generator's path: --generator PATH or CNCMACRO_GENERATOR=PATH")
    gen = generator(args.generator)
    with tempfile.TemporaryDirectory() as tmp:
        library = Path(tmp) / "library"
        library.mkdir()
        for seed in range(1, args.files + 1):
            (library / f"P{seed:05d}.nc").write_text(program(gen, args.lines, seed), encoding="ascii", newline="")
        big = Path(tmp) / "big" / "cam.nc"
        big.parent.mkdir()
        big.write_text(program(gen, args.big, 1), encoding="ascii", newline="")
        best: dict[str, float] = {}
        cpu: dict[str, float] = {}
        reports: dict[str, bytes] = {}
        for _ in range(args.rounds):
            for name, check in (("one file", [str(big)]), ("1 job", ["--jobs", "1", str(library)]),
                                ("2 jobs", ["--jobs", "2", str(library)])):  # fmt: skip
                took, used, out = timed(check)
                best[name] = min(best.get(name, took), took)
                cpu[name] = min(cpu.get(name, used), used)
                reports[name] = out
    same = reports["1 job"] == reports["2 jobs"]
    findings = reports["1 job"].count(b"\n")
    ratio = best["2 jobs"] / best["one file"]
    speed_up = best["1 job"] / best["2 jobs"]
    print(f"cncmacro check, best of {args.rounds} (load average {os.getloadavg()[0]:.2f} at the end):")
    library = f"{args.files:,} files of {args.lines} lines"
    print(f"  one file of {args.big:,} lines: {best['one file']:.2f} s ({cpu['one file']:.2f} s of CPU)")
    print(f"  {library}, --jobs 1: {best['1 job']:.2f} s ({cpu['1 job']:.2f} s of CPU, {findings:,} findings)")
    print(f"  {library}, --jobs 2: {best['2 jobs']:.2f} s ({cpu['2 jobs']:.2f} s of CPU in all processes); "
          f"the same report as one job: {'yes' if same else 'NO'}")  # fmt: skip
    print(f"  two jobs against the big file: {ratio:.2f}x (budget at most {TIME_RATIO}x): "
          f"{'within' if ratio <= TIME_RATIO else 'OVER'}")  # fmt: skip
    print(f"  speed-up from one job to two: {speed_up:.2f}x (budget at least {SPEED_UP}x): "
          f"{'within' if speed_up >= SPEED_UP else 'UNDER'}")  # fmt: skip


if __name__ == "__main__":
    main()
