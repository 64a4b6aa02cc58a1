"""Signature help on G65/G66: which arguments the called macro reads, e.g. ``#24 (X)``.

The called program is found by the program library (the workspace index's ``find_program``);
the locals it reads are the ``#1``–``#33`` its blocks mention outside an assignment's target;
the letter that fills each comes from ``machine.calls``. The active argument is the one being
typed. A program kept on the control that the profile documents (Haas's probing macros) gives
its documented letters instead (``Dialect.program_doc``)."""

from __future__ import annotations

from dataclasses import dataclass

from ..analysis.indexes.call_sites import call_site
from ..analysis.indexes.sites import variable_sites
from ..analysis.indexes.workspace_index import WorkspaceIndex
from ..dialects.tables import ProgramDoc
from ..library.programs import FoundProgram
from ..machine.calls import argument_targets, letters_for_local
from .source import EditorDocument


@dataclass(frozen=True, slots=True)
class MacroArgument:
    """A local the macro reads, the letter that fills it (``?`` if none does) and, when it
    differs, the letter of the second argument specification that fills it too."""

    local: int
    letter: str
    second: str | None


@dataclass(frozen=True, slots=True)
class MacroSignature:
    """A called macro of the workspace: its name, title, the arguments it reads in number order,
    and the index of the one being typed (None if it reads no local that argument fills)."""

    program: str
    title: str
    arguments: tuple[MacroArgument, ...]
    active: int | None


@dataclass(frozen=True, slots=True)
class DocumentedSignature:
    """A called program kept on the control that the profile documents, and the index of the
    argument being typed among its letters."""

    doc: ProgramDoc
    active: int | None


def locals_read(found: FoundProgram) -> list[int]:
    """The locals #1–#33 that the program reads, in number order."""
    seen: set[int] = set()
    blocks = found.file.program.blocks
    for i in range(found.unit.start, min(found.unit.end, len(blocks))):
        for s in variable_sites(blocks[i]):
            if not s.write and 1 <= s.number <= 33:
                seen.add(s.number)
    return sorted(seen)


def signature_help(
    doc: EditorDocument, index: WorkspaceIndex, line: int, column: int
) -> MacroSignature | DocumentedSignature | None:
    """The signature of the macro that the G65/G66 on ``line`` calls, the argument before
    code-point ``column`` active, or None when the line calls none that can be found."""
    block = doc.block(line)
    if block is None:
        return None
    site = call_site(block, doc.dialect)
    if site is None or site.kind == "M98":
        return None
    found = index.find_program(doc, site.number, site.name)
    before = [w for w in site.arguments if w.start < column]
    if found is None and site.number is not None and doc.dialect.on_control(site.number):
        documented = doc.dialect.program_doc(site.number)
        if documented is None:
            return None
        letters = [letter for letter, _, _ in documented.arguments]
        typed = before[-1].letter if before else None
        return DocumentedSignature(documented, letters.index(typed) if typed in letters else None)
    if found is None:
        return None
    reads = locals_read(found)
    arguments = []
    for n in reads:
        spec1, spec2 = letters_for_local(n)
        arguments.append(MacroArgument(n, spec1 or spec2 or "?", spec2 if spec2 and spec2 != spec1 else None))
    active = None
    if before:
        target = argument_targets([w.letter for w in site.arguments])[len(before) - 1]
        if target is not None and target in reads:
            active = reads.index(target)
    return MacroSignature(found.label, found.unit.title or "", tuple(arguments), active)
