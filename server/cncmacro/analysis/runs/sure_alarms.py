"""Whether every run of a main program reaches the macro alarm the analysis run reached.

A ``#3000=`` (or GSK ``G65 H99``) alarm that a run reaches is the program's own stop. Where
the run went there on nothing but what the program set itself, the control goes the same way
every time and stops there on every cycle: an error (docs/semantics.md §6, "Macro alarms the
program surely reaches"). Where the path may depend on what the machine knows and the folder
does not, the analysis run only guessed it (a ``macro-alarm`` warning):

- the run did not start at a main program: a subprogram or macro checked alone, without the
  caller that would pass its arguments, is run with them vacant. A main program is one whose
  lines end it with ``M30`` or ``M02`` and have no ``M99`` (a main program that ends in ``M99``
  cannot be told from a subprogram by its text);
- a line the run went through, the alarm's included, reads a value the program did not set:
  a system variable (offsets, positions, parameters, inputs, the clock), a persistent common
  (``#500``–, kept at power-off; the check never reads the variable file), an extended common,
  anything through ``#[..]`` or a ``#_`` name, or a common variable before any line the run
  went through wrote it (the operator or an earlier program may have left a value there).

Locals count as set by the program: a main program's start vacant, a macro's come from its
caller's arguments, which the run went through. The lines are read as text
(``line_reads.py``), in the order the run first ran them.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable

from ...machine.expressions import VariableKinds
from .line_reads import INDIRECT, code_of, reads, written

_MAIN_END = re.compile(r"(?<![A-Z])M\s*0*(?:30|2)(?!\d)", re.I)
_M99 = re.compile(r"(?<![A-Z])M\s*0*99(?!\d)", re.I)


def is_main_program(lines: Iterable[str]) -> bool:
    """Whether the program of ``lines`` ends itself with M30 or M02 and has no M99."""
    code = [code_of(text) for text in lines]
    return any(_MAIN_END.search(c) for c in code) and not any(_M99.search(c) for c in code)


def surely_reached(
    entry_lines: Iterable[str],
    path: Iterable[tuple[str, int]],
    line_text: Callable[[str, int], str],
    kinds: VariableKinds,
) -> bool:
    """Whether the run from the program of ``entry_lines``, through the (file, line) of
    ``path`` in the order it first ran them (the alarm's line last), reached its alarm on
    values the program set itself (see the module docstring)."""
    if not is_main_program(entry_lines):
        return False
    set_by_program: set[int] = set()
    for file, line in path:
        code = code_of(line_text(file, line))
        for number in reads(code):
            if number == INDIRECT:
                return False
            kind = kinds.kind(number)
            if kind == "common" and number not in set_by_program:
                return False
            if kind not in ("local", "vacant", "common"):
                return False
        target = written(code)
        if target is not None and target != INDIRECT:
            set_by_program.add(target)
    return True
