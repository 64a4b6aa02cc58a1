"""docs/debugging.md, stack frames: a call repeated by its L (``M98 P2100 L2``, ``G65 P9001 L3``)
says in its frame's name which pass is running, ``O2100 (M98, main's locals, pass 2 of 2)``; a
call made once says nothing more (``O9001 (G65, level 1)``)."""

from __future__ import annotations

from pathlib import Path

from cncmacro.dap.presentation import stack_frames
from cncmacro.debugging.breakpoints import Asked, Breakpoints
from cncmacro.debugging.history import History
from cncmacro.debugging.stepping import CONTINUE, Stepper
from running import lines, machine

FILES = {
    "MAIN.nc": lines("O0001", "#100=0", "M98 P2100 L2", "G65 P9001 L3 A1.", "G65 P9001 A2.", "M30"),
    "O2100.nc": lines("O2100", "#100=#100+1", "M99"),  # line 2: a breakpoint
    "O9001.nc": lines("O9001", "#101=#1", "M99"),  # line 2: a breakpoint
}


def test_each_pass_of_a_repeated_call_is_named_in_its_frame(tmp_path: Path) -> None:
    for name, text in FILES.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    m = machine(FILES["MAIN.nc"], folder=tmp_path)
    history = History(interval=3)
    history.reset(m)
    bps = Breakpoints()
    bps.bind(m)
    bps.set_lines(str(tmp_path / "O2100.nc"), [Asked(1)])
    bps.set_lines(str(tmp_path / "O9001.nc"), [Asked(1)])
    s = Stepper(m, bps, history, lambda _text, _category: None)
    seen = []
    while s.run(CONTINUE).reason == "breakpoint":
        seen.append((stack_frames(m)[0]["name"], m.C[100]))
    # L2: two passes of O2100 (#100 still 0, then 1 when the breakpoint is reached); L3: three of
    # O9001; the last G65 without L runs once and says no pass
    assert seen == [
        ("O2100 (M98, main's locals, pass 1 of 2)", 0.0),
        ("O2100 (M98, main's locals, pass 2 of 2)", 1.0),
        ("O9001 (G65, level 1, pass 1 of 3)", 2.0),
        ("O9001 (G65, level 1, pass 2 of 3)", 2.0),
        ("O9001 (G65, level 1, pass 3 of 3)", 2.0),
        ("O9001 (G65, level 1)", 2.0),
    ]


def test_a_step_back_into_an_earlier_pass_names_that_pass(tmp_path: Path) -> None:
    for name, text in FILES.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    m = machine(FILES["MAIN.nc"], folder=tmp_path)
    history = History(interval=3)  # checkpoints every 3 blocks: going back restores copied frames
    history.reset(m)
    bps = Breakpoints()
    bps.bind(m)
    bps.set_lines(str(tmp_path / "O2100.nc"), [Asked(1)])
    s = Stepper(m, bps, history, lambda _text, _category: None)
    s.run(CONTINUE)
    s.run(CONTINUE)
    assert stack_frames(m)[0]["name"] == "O2100 (M98, main's locals, pass 2 of 2)"
    assert s.reverse().reason == "breakpoint"
    assert (stack_frames(m)[0]["name"], m.C[100]) == ("O2100 (M98, main's locals, pass 1 of 2)", 0.0)
