"""Whether every run of a main program reaches the macro alarm the analysis run reached.

A ``#3000=`` (or GSK ``G65 H99``) alarm that a run reaches is the program's own stop. Where
the run went there on nothing but what the program set itself, the control goes the same way
every time and stops there on every cycle: an error (docs/semantics.md §6, "Macro alarms the
program surely reaches"). Where the path may depend on what the machine knows and the folder
does not, the analysis run only guessed it (a ``macro-alarm`` warning):

- the run did not start at a main program: a subprogram or macro checked alone, without the
  caller that would pass its arguments (``unknown_stops.runs_as_macro``: it returns with ``M99``
  and has no ``M30`` or ``M02``), is run with them unknown; the caller decides. Where its path
  read anything it did not set itself (``surely_reached`` with ``arguments_of`` its file is
  false: an argument read in that file before it was written, the caller's modal state or
  position, any other system variable, a common), the alarm is the caller's to reach or not:
  only information;
- a line the run went through, the alarm's included, reads a value the program did not set:
  a system variable (offsets, positions, parameters, inputs, the clock), a persistent common
  (``#500``–, kept at power-off: a value in the folder's variable file may not be the one the
  machine holds when the program runs), an extended common,
  anything through ``#[..]`` or a ``#_`` name, or a common variable before any line the run
  went through wrote it (the operator or an earlier program may have left a value there);
- a line the run went through draws a random number (``RAND``, ``SRAND``, GSK980TDi): the
  control draws another on each run, and a guard on it (machine/guards.py), which the run went
  past on the side without the program's alarm, raises that alarm on some draws instead.

Locals count as set by the program: a main program's start vacant, a macro's come from its
caller's arguments, which the run went through. A variable is set by the program where a line
assigns it (``#100=3``) or, on a control with macro A, where a ``G65 Hm P#n`` operation writes it
(``G65 H01 P#100 Q3``, ``machine/blocks.py``'s ``h_code_destination``). The lines are read as
text (``line_reads.py``), in the order the run first ran them.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

from ...machine.blocks import h_code_destination
from ...machine.expressions import VariableKinds
from ...syntax.block_parser import parse_block
from ...syntax.nodes import Number
from .line_reads import INDIRECT, code_of, draws, reads, written


def surely_reached(
    path: Iterable[tuple[str, int]],
    line_text: Callable[[str, int], str],
    kinds: VariableKinds,
    arguments_of: str | None = None,
) -> bool:
    """Whether the run of a main program, through the (file, line) of ``path`` in the order it
    first ran them (the alarm's line last), reached its alarm on values the program set itself
    (see the module docstring). With ``arguments_of`` (the file of a macro run without its
    caller) a local that a line of that file reads before the path wrote it is an argument the
    caller passes, not set by the program."""
    set_by_program: set[int] = set()
    for file, line in path:
        code = code_of(line_text(file, line))
        if draws(code):  # a draw no run can foresee: another run may go another way
            return False
        target, destination_at = _target(code, kinds)
        for number in reads(code, destination_at):
            if number == INDIRECT:
                return False
            kind = kinds.kind(number)
            if kind in ("common", "local") and number not in set_by_program:
                if kind == "common" or file == arguments_of:
                    return False
            if kind not in ("local", "vacant", "common"):
                return False
        if target is not None and target != INDIRECT:
            set_by_program.add(target)
    return True


def _target(code: str, kinds: VariableKinds) -> tuple[int | None, int | None]:
    """The variable the line ``code`` (comments left out) sets, and the column of the ``#`` of a
    macro A block's ``P#n`` where it is written and not read (an H26 reads its P too), or None."""
    target = written(code)
    if target is not None or not kinds.dialect.h_codes or "65" not in code:
        return target, None
    block = parse_block(code)
    destination = h_code_destination(block, kinds.dialect)
    if destination is None:
        return None, None
    # H26 sets #i to #i * #j / #k: it reads its P as well
    reads_it = any(w.letter == "H" and isinstance(w.value, Number) and w.value.value == 26.0 for w in block.words)
    return destination.number, None if reads_it else destination.start
