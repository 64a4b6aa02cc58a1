"""Signature help on G65/G66: ``ide/signature_help.py``'s signature of the called macro as the
protocol's ``SignatureHelp``, in the client's language (a documented program through
``program_docs.py``); in a cycle block (``G71 P10 Q20 U0.5``), ``ide/cycle_words.py``'s letters of
the block being typed, the one under the cursor active."""

from __future__ import annotations

from typing import TYPE_CHECKING

from lsprotocol import types

from ..bilingual import pick
from ..ide.cycle_words import CycleSignature, cycle_signature
from ..ide.signature_help import DocumentedSignature, signature_help
from .cursor import cursor_at
from .program_docs import signature
from .texts import t

if TYPE_CHECKING:
    from .server import CncMacroServer


def register(server: CncMacroServer) -> None:
    @server.feature(
        types.TEXT_DOCUMENT_SIGNATURE_HELP,
        types.SignatureHelpOptions(trigger_characters=[" "], retrigger_characters=[" "]),
    )
    def signature_help_(ls: CncMacroServer, params: types.SignatureHelpParams) -> types.SignatureHelp | None:
        cur = cursor_at(ls, params.text_document.uri, params.position)
        if cur is None:
            return None
        found = signature_help(cur.doc, ls.index, cur.line, cur.column)
        if found is None:
            cycle = cycle_signature(cur.doc, cur.line, cur.column)
            return None if cycle is None else cycle_help(cycle, ls.locale)
        if isinstance(found, DocumentedSignature):
            return signature(found.doc, ls.locale, found.active)
        pieces = [f"#{a.local} ({a.letter})" for a in found.arguments]
        parameters = [
            types.ParameterInformation(
                label=piece, documentation=f"{t('spec2', ls.locale)}: {a.second}" if a.second else None
            )
            for piece, a in zip(pieces, found.arguments, strict=True)
        ]
        sig = types.SignatureInformation(
            label=f"{found.program}(" + ", ".join(pieces) + ")",
            documentation=f"{t('reads', ls.locale)}: {found.title}" if found.title else None,
            parameters=parameters,
            active_parameter=found.active,
        )
        return types.SignatureHelp(signatures=[sig], active_signature=0, active_parameter=found.active)


def cycle_help(cycle: CycleSignature, locale: str) -> types.SignatureHelp:
    """A cycle block's letters as a signature: ``G71 P(ns) Q(nf) U(Δu) W(Δw) F`` with each
    letter's meaning, named after the block it is (first or second)."""
    label = cycle.code
    parameters = []
    for w in cycle.form.words:
        start = len(label) + 1
        label += " " + w.piece
        parameters.append(types.ParameterInformation(label=(start, len(label)), documentation=pick(locale, w.en, w.zh)))
    name = pick(locale, *cycle.form.name)
    sig = types.SignatureInformation(
        label=label, documentation=name or None, parameters=parameters, active_parameter=cycle.active
    )
    return types.SignatureHelp(signatures=[sig], active_signature=0, active_parameter=cycle.active)
