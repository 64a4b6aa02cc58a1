"""Signature help on G65/G66: ``ide/signature_help.py``'s signature of the called macro as the
protocol's ``SignatureHelp``, in the client's language (a documented program through
``program_docs.py``)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from lsprotocol import types

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
            return None
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
