"""Long fuzz runs: random and mutated programs through parse, check, run and every LSP handler.

    .venv/bin/python benchmarks/fuzz.py --minutes 30 [--seed N] [--crashes DIR]

Each case is checked against the invariants of ``fuzzing.py`` (no uncaught exception, every
run within its budget, every diagnostic range inside the document, every answer one the protocol
allows for its request) and must end within ``CASE_SECONDS`` (a hang). As root on Linux the run
goes on without the capabilities that let root into a folder whatever its mode, so the closed
folders of the odd workspaces are met as a user meets them. A case that breaks one is
saved to the crashes folder (``crash-<n>.nc`` with the traceback beside it as ``.txt``) and
the run goes on. Every few hundred cases one oversized input is tried too (long lines, deep
brackets, many lines, operator chains and numbers thousands of characters long). At the end
it prints the cases run, the crashes, the largest inputs
tried and the slowest case; SIGINT or SIGTERM ends the run early with the same figures.
"""

from __future__ import annotations

import argparse
import os
import random
import signal
import sys
import time
import traceback
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from fuzzing import DIALECTS, LspTarget, cases, corpus_texts, random_program, run_case


def oversized(rnd: random.Random, k: int) -> str:
    """A large input of one of several shapes, growing with ``k``."""
    size = min(200_000, 2_000 * (1 + k))
    shape = k % 5  # 3: an endless loop of many lines, or (every other time) a very long chain or number
    if shape == 0:
        return "G01 " + "X1.5 " * (size // 5) + "\n"
    if shape == 1:
        depth = min(5_000, size // 10)
        return "#1=" + "[" * depth + "1" + "]" * depth + "\nIF[" + "[" * depth + "\n"
    if shape == 4:
        depth = min(5_000, size // 10)
        return "O0001\nG01 X" + "[" * depth + "1.5" + "]" * depth + " Y#[" * depth + "1" + "]" * depth + "\nM30\n"
    if shape == 2:
        return "\n".join(random_program(rnd, 40) for _ in range(size // 2_000))
    if shape == 3 and k % 2:
        n = min(20_000, size // 4)
        body = rnd.choice(["#1=1" + "+1" * n, "#1=" + "-" * n + "1", "N" + "9" * n, "GOTO" + "9" * n,
                           "#1=" + "SQRT[" * n + "1" + "]" * n])  # fmt: skip
        return f"O0001\n{body}\nM30\n"
    return "O0001\nWHILE[1 EQ 1]DO1\n" + "#100=#100+1\n" * (size // 12) + "END1\nM30\n"


CASE_SECONDS = 300  # a case still running after this hung somewhere a request's own limit cannot see


class CaseHung(Exception):
    """A case ran past ``CASE_SECONDS``."""


def _hung(signum: int, frame: object) -> None:
    raise CaseHung(f"the case ran past {CASE_SECONDS} s (a blocking read, or a loop without end)")


def as_any_user() -> None:
    """Root enters every folder whatever its mode, so the odd workspaces' closed folders would
    test nothing: as root on Linux, run again through ``tests/hardening/unprivileged.py``, which
    drops the capabilities that let root past a folder's mode."""
    if not sys.platform.startswith("linux") or os.geteuid() != 0 or os.environ.get("CNCMACRO_FUZZ_AS_USER"):
        return
    os.environ["CNCMACRO_FUZZ_AS_USER"] = "1"
    script = Path(__file__).resolve().parent.parent / "tests" / "hardening" / "unprivileged.py"
    if script.is_file():
        os.execv(sys.executable, [sys.executable, str(script), sys.executable, *sys.argv])


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--minutes", type=float, default=1.0)
    ap.add_argument("--seed", type=int, default=int(time.time()))
    ap.add_argument("--crashes", default="fuzz-crashes", help="folder for the inputs that break an invariant")
    args = ap.parse_args(argv)
    rnd = random.Random(args.seed)
    lsp = LspTarget()
    seeds = corpus_texts()
    crashes_dir = Path(args.crashes)
    deadline = time.monotonic() + args.minutes * 60
    n = crashes = big = 0
    largest_chars = largest_lines = 0
    slowest = (0.0, "")
    source = cases(rnd, seeds)
    print(f"seed {args.seed}, {len(seeds)} corpus programs, {args.minutes:g} minutes", flush=True)
    report = time.monotonic() + 60
    stop: list[int] = []  # SIGINT or SIGTERM: finish the case and print the figures
    signal.signal(signal.SIGINT, lambda sig, frame: stop.append(sig))
    signal.signal(signal.SIGTERM, lambda sig, frame: stop.append(sig))
    signal.signal(signal.SIGALRM, _hung)
    while time.monotonic() < deadline and not stop:
        if n % 500 == 499:
            text = oversized(rnd, big)
            big += 1
        else:
            text = next(source)
        dialect = rnd.choice(DIALECTS)
        t0 = time.perf_counter()
        signal.setitimer(signal.ITIMER_REAL, CASE_SECONDS)
        try:
            run_case(text, dialect, lsp, rnd)
        except Exception:
            crashes += 1
            crashes_dir.mkdir(parents=True, exist_ok=True)
            stem = crashes_dir / f"crash-{crashes}"
            stem.with_suffix(".nc").write_text(text, "utf-8", errors="surrogatepass")
            stem.with_suffix(".txt").write_text(f"dialect {dialect}\n{traceback.format_exc()}", "utf-8")
            print(f"crash {crashes}: {traceback.format_exc().strip().splitlines()[-1]} -> {stem}.nc", flush=True)
            lsp = LspTarget()  # a fresh server after a failure
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
        took = time.perf_counter() - t0
        if took > slowest[0]:
            slowest = (took, f"{len(text)} chars, {text.count(chr(10)) + 1} lines")
        n += 1
        largest_chars = max(largest_chars, len(text))
        largest_lines = max(largest_lines, text.count("\n") + 1)
        if time.monotonic() > report:
            print(f"  {n} cases, {crashes} crashes", flush=True)
            report = time.monotonic() + 60
    print(f"cases run: {n}")
    print(f"crashes: {crashes}" + (f" (inputs in {crashes_dir}/)" if crashes else ""))
    print(f"oversized inputs: {big}; largest input: {largest_chars} characters; most lines: {largest_lines}")
    print(f"slowest case: {slowest[0]:.2f} s ({slowest[1]})")
    return 1 if crashes else 0


if __name__ == "__main__":
    as_any_user()
    sys.exit(main())
