"""The sequence-number commands (``workspace/executeCommand``): renumber the N labels of a file or
a selection with a step, add sequence numbers to the blocks without one, remove the ones nothing
jumps to. The analysis (``analysis/editing/sequence_numbers.py``) decides every change; this module asks
the editor whether to keep the labels a computed jump could reach when one refuses the edit
(``window/showMessageRequest``), applies the result (``workspace/applyEdit``) and answers with
what it did, for a client that wants to say more.

Arguments, one object: ``uri``, ``step`` (renumber and add; 10 when missing), ``range`` (an LSP
range: its lines; the whole file when missing) and ``keepComputed`` (true: keep those labels
without asking; false: refuse without asking).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from lsprotocol import types

from ..analysis.editing.outside_jumps import outside_jumps
from ..analysis.editing.sequence_numbers import (
    MAX_SEQUENCE_NUMBER,
    SequencePlan,
    add_sequence_numbers,
    remove_unused_sequence_numbers,
    renumber,
)
from ..bilingual import listed
from .cursor import doc_range
from .documents import OpenDocument
from .navigation import machine_calls
from .texts import t

if TYPE_CHECKING:
    from .server import CncMacroServer

RENUMBER = "cncmacro.server.renumberSequenceNumbers"
ADD = "cncmacro.server.addSequenceNumbers"
REMOVE = "cncmacro.server.removeSequenceNumbers"
COMMANDS = (RENUMBER, ADD, REMOVE)

_LABELS = {RENUMBER: "renumber", ADD: "add_numbers", REMOVE: "remove_numbers"}  # a command -> its title's key


def _whole(value: Any, default: int) -> int | None:
    """A whole number given as a number or a string of digits; None for anything else."""
    if value is None:
        return default
    if isinstance(value, bool):
        return None
    if isinstance(value, int | float) and value == int(value):
        return int(value)
    if isinstance(value, str) and value.strip().isdigit():
        return int(value.strip())
    return None


def _lines(arg: dict[str, Any]) -> range | None:
    """The lines of the ``range`` argument (all of them when it is missing or malformed)."""
    r = arg.get("range")
    if not isinstance(r, dict) or not isinstance(r.get("start"), dict) or not isinstance(r.get("end"), dict):
        return None
    first, last = _whole(r["start"].get("line"), 0), _whole(r["end"].get("line"), 0)
    character = _whole(r["end"].get("character"), 0)
    if first is None or last is None or last < first:
        return None
    if last > first and character == 0:
        last -= 1  # a selection that ends at the start of a line does not hold it
    return range(first, last + 1)


def plan_for(
    ls: CncMacroServer, command: str, arg: dict[str, Any], keep: bool
) -> tuple[OpenDocument, SequencePlan] | None:
    """The document's edit, or None when it is not open (closed while the editor was asked)."""
    doc = ls.documents.get(str(arg.get("uri")))
    if doc is None:
        return None
    program = doc.parsed.program
    calls = machine_calls(ls, doc.path)
    outside = outside_jumps(ls.index, doc, ls.documents.dialect_for, lambda p: machine_calls(ls, p))
    common: dict[str, Any] = {
        "lines": _lines(arg),
        "keep_computed": keep,
        "locale": ls.locale,
        "calls": calls,
        "outside": outside,
    }
    step = _whole(arg.get("step"), 10)
    if step is None or not 1 <= step <= MAX_SEQUENCE_NUMBER:
        step = 0  # the analysis refuses it with its message
    if command == RENUMBER:
        return doc, renumber(program, doc.dialect, step=step, **common)
    if command == ADD:
        return doc, add_sequence_numbers(program, doc.dialect, step=step, **common)
    return doc, remove_unused_sequence_numbers(program, doc.dialect, **common)


def workspace_edit(ls: CncMacroServer, doc: OpenDocument, plan: SequencePlan) -> types.WorkspaceEdit:
    encoding = ls.documents.encoding
    edits = [types.TextEdit(doc_range(doc, c.line, c.start, c.end, encoding), c.text) for c in plan.changes]
    caps = ls.client_capabilities.workspace
    if caps is None or caps.workspace_edit is None or not caps.workspace_edit.document_changes:
        return types.WorkspaceEdit(changes={doc.uri: list(edits)})  # a client without versioned edits
    return types.WorkspaceEdit(
        document_changes=[
            types.TextDocumentEdit(types.OptionalVersionedTextDocumentIdentifier(doc.uri, doc.version), edits)
        ]
    )


async def run_command(ls: CncMacroServer, command: str, arg: dict[str, Any]) -> dict[str, Any] | None:
    loc = ls.locale
    keep_arg = arg.get("keepComputed")
    planned = plan_for(ls, command, arg, keep_arg is True)
    if planned is None:
        return None
    doc, plan = planned
    cancelled = False
    if keep_arg is None and plan.error is None and any(b.keepable for b in plan.blockers):
        lines = "; ".join(b.message for b in plan.blockers[:3])
        more = len(plan.blockers) - 3
        if more > 0:
            lines += t("and_more", loc, more=more)
        question = t("refused", loc, label=t(_LABELS[command], loc), text=lines)
        keep, cancel = t("keep_labels", loc), t("cancel", loc)
        answer = await ls.window_show_message_request_async(
            types.ShowMessageRequestParams(
                types.MessageType.Warning, question, [types.MessageActionItem(keep), types.MessageActionItem(cancel)]
            )
        )
        if answer is not None and answer.title == keep:
            planned = plan_for(ls, command, arg, True)
            if planned is None:  # closed meanwhile
                return None
            doc, plan = planned
        else:
            cancelled = True
    result: dict[str, Any] = {
        "applied": False,
        "changes": len(plan.changes),
        "kept": [i + 1 for i in plan.kept],
        "refused": [{"line": b.line + 1, "message": b.message} for b in plan.blockers],
    }
    if plan.error is not None:
        ls.window_show_message(types.ShowMessageParams(types.MessageType.Error, plan.error))
        result["error"] = plan.error
        return result
    if plan.blockers:
        if not cancelled:  # say why nothing changed
            text = "; ".join(b.message for b in plan.blockers[:3])
            refused = t("refused", loc, label=t(_LABELS[command], loc), text=text)
            ls.window_show_message(types.ShowMessageParams(types.MessageType.Warning, refused))
        return result
    if not plan.changes:
        ls.window_show_message(types.ShowMessageParams(types.MessageType.Info, t("nothing_to_change", loc)))
        return result
    label = t(_LABELS[command], loc)
    applied = await ls.workspace_apply_edit_async(
        types.ApplyWorkspaceEditParams(workspace_edit(ls, doc, plan), label=label)
    )
    result["applied"] = bool(applied and applied.applied)
    if plan.kept and result["applied"]:
        ls.window_show_message(
            types.ShowMessageParams(
                types.MessageType.Info,
                t("labels_kept", loc, label=label, lines=listed(loc, result["kept"])),
            )
        )
    return result


def register(server: CncMacroServer) -> None:
    for name in COMMANDS:

        def make(command: str) -> Any:
            async def handler(ls: Any, *args: Any) -> dict[str, Any] | None:  # pygls reads these hints
                arg = args[0] if args and isinstance(args[0], dict) else None
                if arg is None or not isinstance(arg.get("uri"), str) or arg["uri"] not in ls.documents.by_uri:
                    return None
                return await run_command(ls, command, arg)

            return handler

        server.command(name)(make(name))
