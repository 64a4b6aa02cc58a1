"""What a compiled core would give: the package's hot modules built with mypyc, beside the pure package.

Copies ``server/cncmacro`` into a temporary folder, makes there the few changes mypyc needs
(``EDITS``: docs/benchmarks.md, "A compiled core: measured"), builds ``COMPILED`` in place with
mypyc's setuptools build (mypy and setuptools as ``pyproject.toml``'s test extras pin them, and
a C compiler), then runs the same work on the pure and the compiled copy, each in a fresh
process, and prints user CPU seconds side by side with whether the findings and the cycle time
agree: the analysis of a 20k-line CAM program, of the 20k-line lathe program of
``lathe_cycles.py`` and of a 100k-line CAM program (in-process, best of 3), ``cncmacro check`` of
the 100k-line program (best of 3) and the 600k-statement loop of ``interp.py`` (best of 3).
Nothing here is part of the package's build; no test runs it. The build takes a few minutes.

    python benchmarks/compiled_core.py [--jobs 2] [--keep FOLDER]
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import NamedTuple

sys.path.insert(0, str(Path(__file__).resolve().parent))

from camgen import cam_program
from lathe_cycles import long_program

ROOT = Path(__file__).resolve().parents[1]

# the modules built: every module of these folders but the package markers and LEFT_OUT
COMPILED = ("planner", "machine", "syntax", "analysis/checks", "analysis/runs")
LEFT_OUT = {
    # they import lark, which stays interpreted
    "syntax/tokens.py", "syntax/messages.py", "syntax/block_parser.py", "syntax/grammar.py",
    # ``Items`` subclasses ``list``: a native class cannot
    "syntax/assemble.py",
    # its dataclass names ``RunState`` of ``run_checks``, which imports it: the cycle crashes at import
    "analysis/runs/run_convergence.py",
}  # fmt: skip

MYPY_INI = "[mypy]\nstrict = True\n\n[mypy-tomli]\nignore_missing_imports = True\n"
SETUP = """
import sys
from setuptools import setup
from mypyc.build import mypycify
paths = open("modules.txt", encoding="utf-8").read().split()
setup(name="cncmacro-compiled-core", packages=[], script_args=["build_ext", "--inplace", "-j", sys.argv[1]],
      ext_modules=mypycify([*paths, "--config-file", "mypy.ini"], opt_level="3", multi_file=True))
"""

# the child's work: analyse a program in-process, best of 3; its findings and clocks as digests
ANALYSE = """
import hashlib, json, sys, time
sys.path.insert(0, sys.argv[1])
from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.library.machine_file import MachineSettings
text = open(sys.argv[2], encoding="utf-8").read()
times = []
for _ in range(3):
    t = time.process_time()
    ws = WorkspaceAnalysis(settings=MachineSettings(date=20260101, time=0))
    ws.open("bench/O0001.nc", text, 0)
    r = ws.analyze("bench/O0001.nc")
    times.append(time.process_time() - t)
assert r is not None
found = sorted((d for ds in r.diagnostics.values() for d in ds), key=lambda d: d.sort_key())
rows = [(d.line, d.column, d.end_line, d.end_column, d.severity, d.code, d.message) for d in found]
clocks = sorted((f, sorted(t.elapsed.items())) for f, t in r.timing.items())
digest = hashlib.sha256(repr((rows, clocks)).encode()).hexdigest()[:12]
print(json.dumps({"seconds": min(times), "findings": len(rows), "digest": digest}))
"""
LOOP = """
import json, sys, time
sys.path.insert(0, sys.argv[1])
from cncmacro.library.machine_file import MachineSettings
from cncmacro.machine import Machine
text = "O0001\\n#1=0\\n#2=0\\nWHILE[#2 LT 200000]DO1\\n#1=#1+#2*2\\n#2=#2+1\\nEND1\\nM30\\n"
times = []
for _ in range(3):
    t = time.process_time()
    m = Machine("fanuc", MachineSettings(max_blocks=10_000_000, date=20260101, time=0))
    m.start_file("bench.nc", text)
    status = m.run()
    times.append(time.process_time() - t)
print(json.dumps({"seconds": min(times), "findings": m.blocks, "digest": str(status)}))
"""


def _with_trait(text: str, cls: str) -> str:
    """``cls`` a mypyc trait (``Machine`` inherits from four such mixins), its class-body
    declarations under ``if TYPE_CHECKING:`` made methods (mypyc takes no statement there)."""
    text = _once(text, "from __future__ import annotations\n",
                 "from __future__ import annotations\n\nfrom mypy_extensions import trait\n")  # fmt: skip
    text = _once(text, f"\nclass {cls}:", f"\n@trait\nclass {cls}:")

    def methods(block: re.Match[str]) -> str:
        body = block.group(1).replace("\n        def ", "\n    def ")
        return re.sub(r"(\n    def [^\n]*?) \.\.\.\n", r"\1\n        raise NotImplementedError\n", body)

    return re.sub(r"\n    if TYPE_CHECKING:\n((?:\n        def [^\n]*\.\.\.\n)+)", methods, text)


def _observer(text: str) -> str:
    """``EntryRun`` and the tests subclass ``RunObserver`` in interpreted code."""
    text = _once(text, "from __future__ import annotations\n",
                 "from __future__ import annotations\n\nfrom mypy_extensions import mypyc_attr\n")  # fmt: skip
    return _once(text, "\nclass RunObserver", "\n@mypyc_attr(allow_interpreted_subclasses=True)\nclass RunObserver")


def _of_plain(text: str) -> str:
    """``Block.of_plain`` makes its block with ``object.__new__``, which a native class refuses."""
    new, n = re.subn(r"    @classmethod\n    def of_plain\(.*?\n(?=    @property\n)",
                     "    @classmethod\n    def of_plain(cls, line: str) -> Block:\n        return cls(plain=line)\n\n",
                     text, flags=re.S)  # fmt: skip
    if n != 1:
        raise SystemExit("compiled_core.py: Block.of_plain has changed: update EDITS")
    return new


EDITS: dict[str, Callable[[str], str]] = {
    "machine/variables.py": lambda t: _with_trait(t, "VariableAccess"),
    "machine/variable_sets.py": lambda t: _with_trait(t, "VariableSets"),
    "machine/call_stack.py": lambda t: _with_trait(t, "CallStack"),
    "machine/run_loop.py": lambda t: _with_trait(t, "RunLoop"),
    "machine/observer.py": _observer,
    "syntax/nodes.py": _of_plain,
}


def _once(text: str, old: str, new: str) -> str:
    if text.count(old) != 1:
        raise SystemExit(f"compiled_core.py: {old.strip()!r} is no longer found once: update EDITS")
    return text.replace(old, new)


def build(work: Path, jobs: int) -> float:
    """The compiled copy in ``work/server``; returns the build's CPU seconds."""
    package = work / "server" / "cncmacro"
    shutil.copytree(ROOT / "server" / "cncmacro", package, ignore=shutil.ignore_patterns("__pycache__"))
    for name, edit in EDITS.items():
        path = package / name
        path.write_text(edit(path.read_text(encoding="utf-8")), encoding="utf-8")
    modules = sorted(
        str(p.relative_to(work / "server")).replace(os.sep, "/")
        for folder in COMPILED
        for p in (package / folder).glob("*.py")
        if p.name != "__init__.py" and f"{folder}/{p.name}" not in LEFT_OUT
    )
    (work / "server" / "modules.txt").write_text("\n".join(modules) + "\n", encoding="utf-8")
    (work / "server" / "mypy.ini").write_text(MYPY_INI, encoding="utf-8")
    print(f"building {len(modules)} modules with mypyc (a few minutes)…", flush=True)
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
    done = subprocess.run([sys.executable, "-c", SETUP, str(jobs)], cwd=work / "server",
                          capture_output=True, text=True)  # fmt: skip
    if done.returncode != 0:
        tail = "\n".join((done.stdout + done.stderr).splitlines()[-20:])
        raise SystemExit(f"compiled_core.py: the mypyc build failed:\n{tail}")
    return resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before


class Figure(NamedTuple):
    seconds: float  # user CPU, best of 3
    findings: int  # how many (the loop: blocks run)
    digest: str  # of the findings and the clocks (the loop: its status; the check: its report)


def child(code: str, *args: str) -> Figure:
    done = subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"compiled_core.py: a run failed:\n{done.stderr[-3000:]}")
    r = json.loads(done.stdout.strip().splitlines()[-1])
    return Figure(float(r["seconds"]), int(r["findings"]), str(r["digest"]))


def check(server: Path, program: Path) -> Figure:
    """``cncmacro check`` of ``program``: best of 3 user CPU seconds, and its report's digest."""
    env = {**os.environ, "PYTHONPATH": str(server)}
    times, report = [], ""
    for _ in range(3):
        before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
        done = subprocess.run([sys.executable, "-m", "cncmacro", "check", str(program)], env=env,
                              capture_output=True, text=True)  # fmt: skip
        times.append(resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before)
        report = done.stdout
    return Figure(min(times), len(report.splitlines()), hashlib.sha256(report.encode()).hexdigest()[:12])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--jobs", type=int, default=2, help="C files compiled at once")
    ap.add_argument("--keep", type=Path, help="build in this (new) folder and keep it")
    args = ap.parse_args()
    work = args.keep or Path(tempfile.mkdtemp(prefix="cncmacro-compiled-"))
    try:
        work.mkdir(parents=True, exist_ok=True)
        seconds = build(work, args.jobs)
        print(f"built in {seconds:.0f} s of CPU", flush=True)
        programs = {"CAM, 20k lines": cam_program(20_000), "lathe, 20k lines": long_program(20_000),
                    "CAM, 100k lines": cam_program(100_000)}  # fmt: skip
        paths = {}
        for k, (name, text) in enumerate(programs.items()):
            folder = work / "programs" / str(k)  # each alone: a check reads its folder
            folder.mkdir(parents=True)
            paths[name] = folder / "O0001.nc"
            paths[name].write_text(text, encoding="utf-8")
        trees = {"pure": ROOT / "server", "compiled": work / "server"}
        rows: list[tuple[str, Callable[[Path], Figure]]] = [
            *((f"analysis, {name}", lambda s, p=p: child(ANALYSE, str(s), str(p))) for name, p in paths.items()),
            ("cncmacro check, CAM, 100k lines", lambda s: check(s, paths["CAM, 100k lines"])),
            ("600k-statement WHILE loop", lambda s: child(LOOP, str(s))),
        ]
        print(f"load average {os.getloadavg()[0]:.1f}")
        print(f"{'user CPU, best of 3':<36} {'pure':>8} {'compiled':>9} {'gain':>6}  same result")
        for label, run in rows:
            pure, comp = run(trees["pure"]), run(trees["compiled"])
            same = pure[1:] == comp[1:]
            print(f"{label:<36} {pure.seconds:8.3f} {comp.seconds:9.3f} {pure.seconds / comp.seconds:5.2f}x  "
                  f"{'yes' if same else 'NO'} ({comp.findings})", flush=True)  # fmt: skip
        print(f"load average {os.getloadavg()[0]:.1f}")
    finally:
        if args.keep is None:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
