"""Helpers for the interpreter tests: run a small program and look at how it ended."""

from __future__ import annotations

from pathlib import Path

from cncmacro.dialects import Dialect, get_dialect
from cncmacro.library.machine_file import MachineSettings
from cncmacro.library.programs import ProgramLibrary
from cncmacro.machine import Machine

FIXED_CLOCK = {"date": 20261122, "time": 80000}


def machine(
    text: str,
    dialect: str | Dialect = "fanuc",
    presets: dict[int, float] | None = None,
    folder: Path | None = None,
    max_blocks: int = 100_000,
    **settings: object,
) -> Machine:
    """A machine with ``text`` loaded as its main program (in ``folder`` when given, so that
    the programs it calls are found there)."""
    opts = {**FIXED_CLOCK, "max_blocks": max_blocks, **settings}
    m = Machine(dialect, MachineSettings(**opts), ProgramLibrary())  # type: ignore[arg-type]
    m.apply_presets(presets or {})
    path = str((folder or Path("/nonexistent-test-folder")) / "MAIN.nc")
    m.start_file(path, text)
    return m


def run(text: str, dialect: str | Dialect = "fanuc", **kw: object) -> Machine:
    """Run ``text`` to its end (resuming past M00 and #3006) and return the machine."""
    m = machine(text, dialect, **kw)  # type: ignore[arg-type]
    while m.run() == "paused":
        m.resume()
    return m


def final(text: str, dialect: str | Dialect = "fanuc", **kw: object) -> dict[int, float]:
    """The variables of a run that must complete without an alarm."""
    m = run(text, dialect, **kw)
    assert m.status == "completed", f"{m.status}: {m.alarm}"
    return m.variables()


def alarm(text: str, dialect: str | Dialect = "fanuc", **kw: object) -> tuple[int, int]:
    """(alarm number, 1-based line) of a run that must alarm."""
    m = run(text, dialect, **kw)
    assert m.status == "alarm", f"expected an alarm, the run ended {m.status} with {m.variables()}"
    assert m.alarm is not None
    return m.alarm.number, m.alarm.line + 1


def lines(*text: str) -> str:
    return "\n".join(text) + "\n"


def haas_switched(base: str = "fanuc") -> Dialect:
    """``base`` with the two Haas capabilities switched on, as the ``haas`` profile sets
    them (docs/semantics.md §5 "M97", §8 "G154"): ``M97 P n`` local subprogram calls and
    ``G154 P1``–``P99`` / ``G110``–``G129`` extra work offsets. The offsets stay at ``base``'s
    numbers (#7001…), which its table has."""
    return get_dialect(base).configured(
        local_subprogram_code=97.0,
        extra_offset_code=154.0,
        extra_offset_aliases=tuple(float(g) for g in range(110, 130)),
        extra_offset_count=99,
    )
