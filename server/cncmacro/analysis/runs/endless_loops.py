"""How sure an endless loop is: what the control would do with the loop the run found.

A run stops where it comes back to a jump back with every variable and position unchanged
(``run_checks.EntryRun.look``). The simulated machine is deterministic, so such a loop never
ends in the simulation; whether it never ends on the machine depends on what decides it
(docs/semantics.md §4, "Endless loops"):

- ``CERTAIN``: a ``WHILE`` loop, or an ``IF [...] GOTO`` back, whose lines read only local
  variables (``#1``–``#33``) and constants and call no program. Nothing but those lines can
  change a local, and they do not: the control never leaves the loop. An error.
- ``SHARED``: the same, but the lines read common variables (``#100``–, ``#500``–, extended
  commons) too: the program does not change them, yet another path of a multi-path control
  (FANUC shares commons between paths) or the operator could, so the loop may be a wait for
  them. A warning.
- ``None``: anything else stays the run's note (``run-limit``, information): an unconditional
  ``GOTO`` back, ``DO`` without ``WHILE`` and an ``M99`` loop are endless on purpose (warm-up,
  bar feeders); a loop that reads a system variable (an input signal, the clock, a position,
  an offset) or reads through ``#[...]`` waits for the machine, which the simulation cannot
  see change; a loop that calls a program may be fed by what that program reads from the
  machine (a probing cycle).

The lines are read as text (``line_reads.py``).
"""

from __future__ import annotations

import re
from collections.abc import Callable

from ...machine.expressions import VariableKinds
from .line_reads import INDIRECT, code_of, reads

CERTAIN = "certain"
SHARED = "shared"

_CALL = re.compile(r"(?<![A-Z_])(?:G\s*0*6[56]|M\s*0*9[78])(?!\d)", re.I)
_WHILE = re.compile(r"(?<![A-Z])WHILE\s*\[", re.I)
_END = re.compile(r"(?<![A-Z])END\s*\d", re.I)
_IF_GOTO = re.compile(r"(?<![A-Z])IF\s*\[.*GOTO", re.I)
_SHARED_KINDS = ("common", "persistent", "extended", "indirect9")


def loop_certainty(line_text: Callable[[int], str], line: int, to: int, kinds: VariableKinds) -> str | None:
    """``CERTAIN``, ``SHARED`` or None (see the module docstring) for the loop that jumps back
    from ``line`` to ``to`` in one file (``line_text`` gives a line of it); ``line`` -1 (the
    run came back through a call or a return) is None."""
    if line < 0 or to > line:
        return None
    jump = code_of(line_text(line))
    head = code_of(line_text(to))
    if not (_IF_GOTO.search(jump) or (_END.search(jump) and _WHILE.search(head))):
        return None
    shared = False
    for k in range(to, line + 1):
        code = code_of(line_text(k))
        if _CALL.search(code):
            return None
        for number in reads(code):
            kind = "indirect" if number == INDIRECT else kinds.kind(number)
            if kind in _SHARED_KINDS:
                shared = True
            elif kind not in ("local", "vacant"):
                return None  # a system variable, #[...] or a #_NAME: the machine's, or anything
    return SHARED if shared else CERTAIN


def waits_for_the_machine(line_text: Callable[[int], str], line: int, to: int, kinds: VariableKinds) -> bool:
    """Whether the loop that jumps back from ``line`` to ``to`` reads a system variable (a timer,
    an input signal, a position), whose value the machine changes while the simulation cannot:
    ``#3001=0`` / ``N10 IF [#3001 LT 3000] GOTO 10`` waits three seconds on the control."""
    if line < 0 or to > line:
        return False
    return any(
        number != INDIRECT and kinds.kind(number) == "system"
        for k in range(to, line + 1)
        for number in reads(code_of(line_text(k)))
    )
