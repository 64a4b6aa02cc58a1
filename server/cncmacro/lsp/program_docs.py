"""What hover and signature help say of a program kept on the control that the profile documents
(``Dialect.program_doc``: Haas's probing macros): its title, what it does, the G65 arguments it
reads (those the call gives marked) and the variables it writes, in the client's language."""

from __future__ import annotations

from collections.abc import Collection

from lsprotocol import types

from ..bilingual import pick
from ..dialects.tables import ProgramDoc
from .texts import t


def doc_lines(doc: ProgramDoc, locale: str, given: Collection[str] = ()) -> list[str]:
    """The Markdown of ``doc``: title, description, arguments (``given`` marked), results."""
    lines = [f"**O{doc.number:04d}** — {pick(locale, doc.title, doc.title_zh)}", "", pick(locale, doc.en, doc.zh)]
    if doc.arguments:
        lines += ["", f"{t('arguments', locale)}:"]
        for letter, en, zh in doc.arguments:
            mark = f" *({t('given', locale)})*" if letter in given else ""
            lines.append(f"- **{letter}** — {pick(locale, en, zh)}{mark}")
    if doc.results:
        lines += ["", f"{t('results', locale)}:"]
        lines += [f"- **#{number}** — {pick(locale, en, zh)}" for number, en, zh in doc.results]
    return lines


def signature(doc: ProgramDoc, locale: str, active: int | None) -> types.SignatureHelp:
    """Signature help for a G65 call to ``doc``'s program: its argument letters, the one being
    typed (the ``active``-th) active."""
    letters = [letter for letter, _, _ in doc.arguments]
    params = [
        types.ParameterInformation(label=letter, documentation=pick(locale, en, zh)) for letter, en, zh in doc.arguments
    ]
    sig = types.SignatureInformation(
        label=f"O{doc.number:04d}(" + ", ".join(letters) + ")",
        documentation=f"{pick(locale, doc.title, doc.title_zh)}: {pick(locale, doc.en, doc.zh)}",
        parameters=params,
        active_parameter=active,
    )
    return types.SignatureHelp(signatures=[sig], active_signature=0, active_parameter=active)
