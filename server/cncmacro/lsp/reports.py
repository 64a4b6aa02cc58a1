"""What the language server could not use in the workspace, told where a person sees it.

A machine file (``.cncmacro.toml``) in use (a workspace folder's, or an open document's) that
cannot be used is an error diagnostic on that file, with the code ``machine-file``, on the line
the problem is on where it is known: the Problems panel lists it whether the file is open or not,
while the analysis goes on with the defaults; it is cleared once the file is right again (or
gone). A machine file that can be used but declares common ranges beyond its profile's list
shows which, as ``cncmacro check`` notes them: an information diagnostic with the code
``machine-file-note`` on its ``common`` line. The editor's ``severity`` setting can change or
switch off either code, as any other. Folders and files that the workspace index did not read (a
folder that cannot be read, a file larger than the limit, one that is not a regular file, a
search cut short by its limits) are named in one warning (``window/showMessage``) per scan, and
each of them (up to ``LOGGED``) in the log (``window/logMessage``, the "CNC Macro Server"
output).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from lsprotocol import types

from ..analysis.codes import default_severity
from ..analysis.severity import OFF
from ..bilingual import Detail, in_language, is_chinese
from ..library.files import shown_text
from ..library.machine_file import common_note, standard_calls_note
from ..library.machine_files import MachineFileState
from .protocol_diagnostics import SEVERITY
from .texts import t

if TYPE_CHECKING:
    from .server import CncMacroServer

MACHINE_FILE_CODE = "machine-file"
MACHINE_FILE_NOTE_CODE = "machine-file-note"
NAMED = 3  # how many of the skipped the warning names
LOGGED = 100  # how many the log names, one line each


def _chinese(server: CncMacroServer) -> bool:
    return is_chinese(server.locale)


def publish_machine_file(server: CncMacroServer, machine: MachineFileState) -> str | None:
    """Publish on the machine file its problem, or the common ranges it adds to its profile
    (``common_note``, the text ``cncmacro check`` prints); the URI that now shows it (None: it
    has neither, or the code is off). The server clears what it showed before and shows no longer."""
    if machine.path is None:
        return None
    shown: list[tuple[str, str, int, Detail]] = []  # (code, its default severity, line, text)
    if machine.problem is not None:
        default = default_severity(MACHINE_FILE_CODE)
        shown.append((MACHINE_FILE_CODE, default, machine.problem.line or 0, machine.problem.args[0]))
    elif machine.settings is not None:
        settings = machine.settings
        profile = settings.dialect or server.documents.setting_dialect
        note = common_note(settings, machine.path.name, profile)
        if note is not None:
            default = default_severity(MACHINE_FILE_NOTE_CODE)
            shown.append((MACHINE_FILE_NOTE_CODE, default, settings.common_line or 0, note))
        calls = standard_calls_note(settings, machine.path.name, profile)
        if calls is not None:
            shown.append(
                (MACHINE_FILE_NOTE_CODE, default_severity(MACHINE_FILE_NOTE_CODE), settings.calls_line or 0, calls)
            )
    items = []
    for code, default, line, text in shown:
        level = server.settings.severity.get(code, default)
        level = level if level in SEVERITY or level == OFF else default  # a bad value is logged where it is read
        if level == OFF:
            continue
        items.append(types.Diagnostic(
            range=types.Range(types.Position(line, 0), types.Position(line + 1, 0)),
            message=shown_text(in_language(text, _chinese(server))),
            severity=SEVERITY[level],
            code=code,
            source="cncmacro",
        ))  # fmt: skip
    if not items:
        return None
    uri = server.uri_for_path(str(machine.path))
    server.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=items))
    return uri


def log_skipped(server: CncMacroServer, problem: Detail) -> str:
    """Name one folder or file that was not read in the log; the text it was named with."""
    text = shown_text(in_language(problem, _chinese(server)))
    server.window_log_message(types.LogMessageParams(type=types.MessageType.Warning, message=text))
    return text


def report_skipped(server: CncMacroServer, skipped: list[Detail]) -> None:
    """Name what a scan of the workspace folders did not read (nothing when it read all)."""
    if not skipped:
        return
    texts = [log_skipped(server, s) for s in skipped[:LOGGED]]
    if len(skipped) > LOGGED:
        more = len(skipped) - LOGGED
        text = t("more_not_read", server.locale, more=more)
        server.window_log_message(types.LogMessageParams(type=types.MessageType.Warning, message=text))
    named = "; ".join(texts[:NAMED])
    more = len(skipped) - NAMED
    message = t("not_read_one" if len(skipped) == 1 else "not_read", server.locale, count=len(skipped), named=named)
    message += t("more_in_output", server.locale, more=more) if more > 0 else ""
    server.window_show_message(types.ShowMessageParams(type=types.MessageType.Warning, message=message))
