"""What a line is to a run: whether it does anything, whether it is an O header alone, and
where a program starts (docs/semantics.md §1 "Text and blocks").

The interpreter (``CompiledFile``), the analysis (which programs are run, where a
``not-executed`` range may start and end) and the debugger (where a breakpoint stops) all ask
here, so they cannot answer apart.

- A line is *skipped* when running it does nothing: blank, comments only, a ``%`` mark, or a
  ``/`` block while the block delete switch is on. A plain line (``Block.plain``) never is.
- Nothing from the tape's end on is read: running into the closing ``%`` ends the program like
  the end of the file, so the search for the next line stops there (``Program.read_end``).
- ``M99O0810`` (one program's end and the next one's number on one line) is the last block of
  the program above it and the header alone of O0810.
- An O line is a *header alone* when it holds nothing but the O word (a title and comments
  aside): a run that enters the program starts after it, and a run never stands on it. An O
  line that holds more, a sequence number (``O100 N5``), words or statements, is the program's
  first block: a run starts on it, and a ``GOTO 5`` lands on it.
"""

from __future__ import annotations

from ..syntax.nodes import Block
from ..syntax.program import Program, ProgramUnit


def skipped(block: Block, block_delete: bool) -> bool:
    """True for a line that does nothing when run (blank, comments, a ``%`` mark, a ``/``
    block while the block delete switch is on)."""
    if block.plain is not None:
        return False
    return (
        block.is_empty
        or (block.tape and not block.code_before_mark)
        or (block_delete and block.block_delete is not None)
    )


def header_only(block: Block) -> bool:
    """True for an O line that holds nothing to run: no sequence number, words or statements; or
    whose words end the program before it (``M99O0810``, ``joined_header``)."""
    return block.program is not None and (
        (block.label is None and not block.words and not block.corners and not block.statements) or joined_header(block)
    )


def joined_header(block: Block) -> bool:
    """True for the end of one program and the next one's O number on one line (``M99O0810``,
    in a file that holds several programs): the words run as the last block of the program
    above, and the program whose number follows starts after the line."""
    span = block.program_span
    return block.program is not None and span is not None and bool(block.words) and block.words[0].start < span[0]


def passed_over(block: Block, block_delete: bool) -> bool:
    """True for a line a run never stands on: a skipped line or an O header alone."""
    return skipped(block, block_delete) or header_only(block)


def next_line(program: Program, pc: int, block_delete: bool) -> int:
    """The next line after ``pc`` that does something: the closing ``%`` or the file's end
    (``len(program.blocks)``) at worst."""
    blocks = program.blocks
    end = program.read_end
    i = pc + 1
    while i < end and skipped(blocks[i], block_delete):
        i += 1
    return i


def first_line(program: Program, pc: int, block_delete: bool) -> int:
    """``pc`` itself if it does something, else the next line that does."""
    blocks = program.blocks
    if pc < program.read_end and not skipped(blocks[pc], block_delete):
        return pc
    return next_line(program, pc, block_delete)


def entry(program: Program, unit: ProgramUnit, block_delete: bool) -> int:
    """The first line a run of ``unit`` runs: past its O header when that is a header alone."""
    start = unit.start
    if start < len(program.blocks) and header_only(program.blocks[start]):
        return next_line(program, start, block_delete)
    return first_line(program, start, block_delete)


def runnable(program: Program, unit: ProgramUnit, block_delete: bool) -> bool:
    """Whether a run of ``unit`` runs a block of its own (not only its header, blank lines,
    comments and ``%`` marks)."""
    return entry(program, unit, block_delete) < min(unit.end, program.read_end)


def stop_line(program: Program, line: int, block_delete: bool) -> int | None:
    """The first line at or after ``line`` where a run can stand (before the block there
    runs), or None when no such line comes before the tape's end."""
    blocks = program.blocks
    for k in range(max(0, line), program.read_end):
        if not passed_over(blocks[k], block_delete):
            return k
    return None
