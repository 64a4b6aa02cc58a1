"""docs/debugging.md, stack frames: a macro call (G65, G66, a code that calls a macro) opens a
macro level with locals of its own, and its frame is named with that level (``O9000 (G65, level
1)``); a subprogram (M98, Haas's M97) runs in its caller's locals, and its frame says whose
(``O2100 (M98, main's locals)``, ``O9001 (M98, level 1's locals)``) instead of a level of its own
that no locals have. A G65 called from a subprogram of the main program is macro level 1 (the
second call down, but the first set of locals after the main program's)."""

from __future__ import annotations

from pathlib import Path

from cncmacro.dap.presentation import stack_frames
from cncmacro.debugging.breakpoints import Breakpoints
from cncmacro.debugging.history import History
from cncmacro.debugging.stepping import STEP_IN, Stepper
from running import lines, machine

FILES = {
    "MAIN.nc": lines("O0001", "M98 P2100", "M30"),
    "O2100.nc": lines("O2100", "G65 P9000 A1.", "M99"),
    "O9000.nc": lines("O9000", "M98 P9001", "M99"),
    "O9001.nc": lines("O9001", "#1=#1+1", "M99"),
}


def test_a_subprogram_frame_names_the_level_whose_locals_it_uses(tmp_path: Path) -> None:
    for name, text in FILES.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    m = machine(FILES["MAIN.nc"], folder=tmp_path)
    history = History(interval=4)
    history.reset(m)
    s = Stepper(m, Breakpoints(), history, lambda _text, _category: None)
    for _ in range(3):  # into M98 P2100, G65 P9000, M98 P9001
        s.run(STEP_IN)
    assert [(f["name"], f["line"]) for f in stack_frames(m)] == [
        ("O9001 (M98, level 1's locals)", 2),  # it was "O9001 (M98, level 3)"
        ("O9000 (G65, level 1)", 2),  # it was "level 2": the M98 above it has no locals of its own
        ("O2100 (M98, main's locals)", 2),  # it was "O2100 (M98, level 1)"
        ("O0001 (main)", 2),
    ]
    s.run(STEP_IN)  # #1=#1+1 writes the G65's #1 (A1. -> 2)
    assert m.frames[2].locals[1] == 2.0
