"""Taking a run back to before the first step that a document's edits can change.

After an edit that keeps the number of lines and touches no label, O header or loop marker, a
run resumes from its last checkpoint before the first execution of a changed line (or of the
nearest line before the change, whose compiled form knows which line follows it, and of a
loop's ``DO`` where that line is its ``END``); a run that never executed them is kept whole,
and takes the rest of the run before the edit over once their states are equal
(``run_convergence.py``). An edit that adds or removes lines (Enter) resumes a run from its
last checkpoint before it first reached the line before the edit or any later line of the
file: nothing it keeps refers to a moved line, and the file is compiled afresh as it runs. An
edit that changes labels, loops or ``%`` resumes each run from before the first time it
entered the edited file.
"""

from __future__ import annotations

from collections.abc import Callable

from ...machine import block_roles
from ...machine.status import RunStatus
from ..workspace_documents import WorkspaceDocument
from .run_checks import EntryRun


def rewind(run: EntryRun, d: WorkspaceDocument, block_delete: bool, rewound: Callable[[EntryRun], None]) -> None:
    """Take ``run`` back to before the first step the edits of ``d`` can change; ``rewound``
    hears of each run taken back (the not-executed ranges follow it)."""
    path = d.path
    if run.first_step(path) is None:
        run.reset_file(path)
        return
    blocks = d.doc.blocks
    program = d.doc.program
    structural = any(e.structural for e in d.edits)
    if not structural and any(e.shifted for e in d.edits):
        structural = not _rewind_shifted(run, d, block_delete, rewound)
        if not structural:
            return
    lines: list[int] = []
    if not structural:
        end_do = {p.end_line: p.do_line for p in program.loops}
        for e in d.edits:
            lines.extend(range(e.start, e.start + e.count))
            p = e.start - 1
            while p >= 0 and block_roles.skipped(blocks[p], block_delete):
                p -= 1
            unit = program.unit_at(e.start)
            if p < unit.start or (p == unit.start and blocks[p].program is not None):
                structural = True  # where the program starts running may have moved
                break
            lines.append(p)
            if p in end_do:
                lines.append(end_do[p])
    if structural:
        step = run.first_step(path)
        assert step is not None
        run.rewind(step, avoid_file=path)
        rewound(run)
        run.reset_file(path)
        return
    step = run.first_step(path, lines)
    if step is not None or run.earlier is not None:
        run.edited(path, lines)
    if step is not None:
        run.rewind(step)
        rewound(run)
    run.forget_lines(path, lines)


def _rewind_shifted(run: EntryRun, d: WorkspaceDocument, block_delete: bool,
                    rewound: Callable[[EntryRun], None]) -> bool:  # fmt: skip
    """Lines were added or removed (no structure changed): take ``run`` back to before the
    first step at which it reached the line before the first edit or any line after it,
    so that nothing it keeps refers to a line that moved. False when that cannot be told
    (the edit is at a program's start, or the run stopped at its budget without reaching
    the edit, its stopping place perhaps moved)."""
    path = d.path
    blocks = d.doc.blocks
    start = min(e.start for e in d.edits)
    p = start - 1
    while p >= 0 and block_roles.skipped(blocks[p], block_delete):
        p -= 1
    unit = d.doc.program.unit_at(start)
    if p < unit.start or (p == unit.start and blocks[p].program is not None):
        return False
    step = run.first_reaching(path, p)
    if step is None:
        if run.machine.status == RunStatus.LIMIT or not run.finished:
            return False
    else:
        run.rewind(step, avoid_file=path)
        rewound(run)
    run.reset_file(path)
    return True
