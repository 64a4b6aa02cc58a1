"""Signature help on G65/G66: which arguments the called macro reads, e.g. ``#24 (X)``.

The called program is found by the program library; the locals it reads are the ``#1``–``#33``
its blocks mention outside an assignment's target; the letter that fills each comes from
``machine.calls``. The active parameter is the argument being typed. A program kept on the
control that the profile documents (Haas's probing macros) shows its documented letters instead.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from lsprotocol import types

from ..analysis.indexes.call_sites import call_site
from ..analysis.indexes.sites import variable_sites
from ..library.programs import FoundProgram
from ..machine.calls import argument_targets, letters_for_local
from .cursor import cursor_at
from .program_docs import signature
from .texts import t

if TYPE_CHECKING:
    from .server import CncMacroServer


def locals_read(found: FoundProgram) -> list[int]:
    """The locals #1–#33 that the program reads, in number order."""
    seen: set[int] = set()
    blocks = found.file.program.blocks
    for i in range(found.unit.start, min(found.unit.end, len(blocks))):
        for s in variable_sites(blocks[i]):
            if not s.write and 1 <= s.number <= 33:
                seen.add(s.number)
    return sorted(seen)


def register(server: CncMacroServer) -> None:
    @server.feature(
        types.TEXT_DOCUMENT_SIGNATURE_HELP,
        types.SignatureHelpOptions(trigger_characters=[" "], retrigger_characters=[" "]),
    )
    def signature_help(ls: CncMacroServer, params: types.SignatureHelpParams) -> types.SignatureHelp | None:
        cur = cursor_at(ls, params.text_document.uri, params.position)
        if cur is None:
            return None
        site = call_site(cur.block, cur.doc.dialect)
        if site is None or site.kind == "M98":
            return None
        found = ls.index.find_program(cur.doc, site.number, site.name)
        before = [w for w in site.arguments if w.start < cur.column]
        dialect = cur.doc.dialect
        if found is None and site.number is not None and dialect.on_control(site.number):
            documented = dialect.program_doc(site.number)
            typed = before[-1].letter if before else None
            return None if documented is None else signature(documented, ls.locale, typed)
        if found is None:
            return None
        reads = locals_read(found)
        params_: list[types.ParameterInformation] = []
        pieces = []
        for n in reads:
            spec1, spec2 = letters_for_local(n)
            letter = spec1 or spec2 or "?"
            piece = f"#{n} ({letter})"
            pieces.append(piece)
            doc = f"{t('spec2', ls.locale)}: {spec2}" if spec2 and spec2 != spec1 else None
            params_.append(types.ParameterInformation(label=piece, documentation=doc))
        label = f"{found.label}(" + ", ".join(pieces) + ")"
        title = found.unit.title or ""
        active = None
        if before:
            targets = argument_targets([w.letter for w in site.arguments])
            target = targets[len(before) - 1]
            if target is not None and target in reads:
                active = reads.index(target)
        sig = types.SignatureInformation(
            label=label,
            documentation=f"{t('reads', ls.locale)}: {title}" if title else None,
            parameters=params_,
            active_parameter=active,
        )
        return types.SignatureHelp(signatures=[sig], active_signature=0, active_parameter=active)
