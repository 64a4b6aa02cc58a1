"""A lathe cycle's passes are timed the same whether its moves are kept (``cncmacro run``, the
debugger, the toolpath) or not (the analysis behind the editor's cycle-time lenses and the
diagnostics, planner/cycle_passes.py): the clock, the cut and the rapid path agree to the
nanosecond and the micrometre on every multiple repetitive cycle, under G96 and the G50 S clamp.
The times themselves are worked by hand in test_lathe_threads_and_grooves.py and
tests/lsp/test_lsp_cycle_time.py."""

from __future__ import annotations

import pytest

from running import lines, machine

PROFILES = ("gsk980tdi", "fanuc-0i-lathe")

# every cycle that makes passes, from several start points, under G96 (the spindle's speed
# changes along each pass) clamped by G50 S2000, then #3001 (ms) kept in #100
CYCLES = lines(
    "O0001",
    "G50 S2000",
    "G99 G96 S180 M03",
    "G00 X62. Z2.",
    "G71 U1.5 R0.5",
    "G71 P10 Q20 U0.4 W0.1 F0.25",
    "N10 G00 X20.",
    "G01 Z0 F0.1",
    "X24. Z-2.",
    "Z-18.",
    "G02 X32. Z-22. R4.",
    "G01 Z-35.",
    "N20 X62.",
    "G70 P10 Q20",
    "G00 X64. Z2.",
    "G72 W2. R0.5",
    "G72 P30 Q40 U0.2 W0.1 F0.2",
    "N30 G00 Z-12.",
    "G01 X40. F0.1",
    "Z-4.",
    "N40 X64. Z2.",
    "G00 X70. Z5.",
    "G73 U4. W1. R3",
    "G73 P50 Q60 U0.4 W0.1 F0.2",
    "N50 G00 X30. Z2.",
    "G01 Z-20. F0.1",
    "N60 X70. Z-30.",
    "G00 X0 Z2.",
    "G74 R0.5",
    "G74 Z-11. Q3000 F0.1",
    "G00 X42. Z-10.",
    "G75 R0.5",
    "G75 X30. Z-14. P3000 Q2000 F0.05",
    "G97 S600",
    "G00 X22. Z5.",
    "G76 P010060 Q100 R0.05",
    "G76 X18.05 Z-30. P975 Q400 F1.5",
    "#100=#3001",
    "M30",
)


# the spindle and feed modes the cycles above run under: G96 (the rate changes along a pass), a
# fixed speed per revolution, and per minute (the feeds read as mm/min)
FEED_MODES = {"G96": "G99 G96 S180 M03", "G97": "G99 G97 S800 M03", "G98": "G98 G97 S800 M03"}


@pytest.mark.parametrize("feed_mode", FEED_MODES)
@pytest.mark.parametrize("profile", PROFILES)
def test_a_cycles_passes_take_the_same_time_whether_its_moves_are_kept_or_not(profile: str, feed_mode: str) -> None:
    text = CYCLES.replace("O0001", f"O0001 (cncmacro: dialect={profile})", 1)
    text = text.replace("G99 G96 S180 M03", FEED_MODES[feed_mode], 1)
    kept, timed = machine(text, profile), machine(text, profile)
    timed.planner.record_moves = False
    for m in (kept, timed):
        assert m.run() == "completed", m.alarm
    assert [mv.pass_of for mv in kept.planner.moves if mv.pass_of] and not timed.planner.moves
    assert timed.planner.clock == pytest.approx(kept.planner.clock, abs=1e-9)
    assert timed.planner.clock > 20.0  # the cycles ran: minutes of cutting, not a few rapids
    assert timed.planner.cut_length == pytest.approx(kept.planner.cut_length, abs=1e-6)
    assert timed.planner.rapid_length == pytest.approx(kept.planner.rapid_length, abs=1e-6)
    assert timed.variables()[100] == pytest.approx(kept.variables()[100], abs=1e-6)  # #3001 reads the same
