"""``cncmacro mcp``: a Model Context Protocol server on stdio, so that an AI assistant can check,
run and look up the programs it writes with cncmacro itself.

Its four tools are ``assistant_tools``'s functions: ``check`` (a file, a folder or a program's
text: ``cncmacro check --format json``'s findings), ``run`` (moves, variables, alarm, output and
cycle time, as ``cncmacro run --json --no-save``, bounded), ``explain`` (a system variable, a G or
M code, a function on one profile, from its tables as the editor's hover) and ``profiles``. Each
is read-only: it reads only the paths it is given (and, as ``check`` and ``run`` do, the machine
file above them and the programs their calls name) and never writes a file. A mistake in the
input is an error result whose text says what to give instead; a failure of cncmacro itself is an
error result too, never the end of the server. The protocol is the ``mcp`` package's
(``cncmacro[mcp]``, docs/cli.md); ``main_mcp`` in ``cli/main.py`` says how to install it when it
is missing.
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from typing import Any

from mcp.server.mcpserver import MCPServer
from mcp.server.mcpserver.exceptions import ToolError
from mcp_types import ToolAnnotations

from .. import __version__
from ..dialects import DEFAULT_DIALECT, DIALECTS
from .assistant_tools import (
    MAX_FINDINGS,
    MAX_MOVES,
    ToolInputError,
    check_program,
    explain,
    list_profiles,
    run_program,
)

log = logging.getLogger(__name__)

INSTRUCTIONS = (
    "cncmacro checks and runs CNC custom-macro programs (FANUC Macro B, Haas, GSK980TDi) on a simulated "
    "control. Check a program before giving it to a machinist, run it to see its moves, variables, alarm and "
    "cycle time, and explain a system variable or G/M code for the control's profile. Nothing is written to "
    "disk. A profile is a control (list them with profiles); without one a program's own "
    "(cncmacro: dialect=...) comment or its machine file decides, else " + DEFAULT_DIALECT + "."
)
_COMMON = (
    "Arguments: path (a program file{folder}, relative to the server's working folder) or text (the program "
    "itself; with a path too, the text is that file's content and calls find programs in its folder); profile "
    "(optional: " + ", ".join(DIALECTS) + " or an alias); locale (optional: en or "
    "zh-CN, the messages' language); max_blocks (optional block budget, default the machine file's, "
    "1,000,000)."
)
CHECK_TEXT = (
    "Check a CNC macro program or a folder of them, as `cncmacro check --format json` does: syntax, static "
    "checks and what bounded runs find (alarms, endless loops, vacant arguments). Returns the findings (file, "
    "1-based line and column, severity, code, message; at most " + str(MAX_FINDINGS) + ", with the total and "
    "whether the list was cut) and a summary. " + _COMMON.format(folder=" or a folder")
)
RUN_TEXT = (
    "Run a CNC macro program on the simulated control, as `cncmacro run --json --no-save` does, and return a "
    "summary, its status (completed, alarm, limit), the alarm with its place, the first max_moves moves "
    "(default " + str(MAX_MOVES) + "; each with file, line, mode, kind, from, to, feed and time in seconds), "
    "movesTotal and movesCut, the final variables, DPRNT output and the cycle time. A program ending in M99 "
    "runs one pass. The persistent variables are read but never saved. "
    + _COMMON.format(folder="")
    + " Also: max_moves, and presets (a list such as ['100=5', '2001=0.5']: variables set before the run)."
)
EXPLAIN_TEXT = (
    "Explain what a control documents for a variable (#5001, #100, #1), a G or M code (G71, M98, G54.1), a "
    "GSK980TDi G65 H command (H01) or a macro function or word (ATAN, WHILE, DPRNT), on one profile "
    "(optional, default " + DEFAULT_DIALECT + "): what it is, and for a system variable its unit, access and axis. "
    "Arguments: subject, profile, locale (en or zh-CN)."
)
PROFILES_TEXT = (
    "List the control profiles cncmacro knows: name, aliases, title, a summary of the machine in English and "
    "Chinese, lathe or mill, axes, common-variable ranges and which is the default."
)
READ_ONLY = ToolAnnotations(read_only_hint=True, destructive_hint=False, idempotent_hint=True, open_world_hint=False)


def _answered(work: Callable[[], dict[str, Any]]) -> dict[str, Any]:
    """``work``'s answer; a mistake in the input is a ``ToolError`` with its text, and so is a
    failure of cncmacro itself (logged with its traceback on standard error), never an exception
    that ends the server."""
    try:
        return work()
    except ToolInputError as e:
        raise ToolError(str(e)) from None
    except Exception as e:
        log.exception("a tool failed")
        raise ToolError(f"cncmacro could not answer this ({type(e).__name__}: {e}); please report it") from None


def check(
    path: str | None = None,
    text: str | None = None,
    profile: str | None = None,
    locale: str | None = None,
    max_blocks: int | None = None,
) -> dict[str, Any]:
    return _answered(lambda: check_program(path, text, profile, locale, max_blocks))


def run(
    path: str | None = None,
    text: str | None = None,
    profile: str | None = None,
    locale: str | None = None,
    max_blocks: int | None = None,
    max_moves: int | None = None,
    presets: list[str] | None = None,
) -> dict[str, Any]:
    return _answered(lambda: run_program(path, text, profile, locale, max_blocks, max_moves, presets))


def explain_subject(subject: str, profile: str | None = None, locale: str | None = None) -> dict[str, Any]:
    return _answered(lambda: explain(subject, profile, locale))


def profiles() -> dict[str, Any]:
    return _answered(list_profiles)


def build_server() -> MCPServer[Any]:
    """The server with its four tools."""
    server: MCPServer[Any] = MCPServer(
        "cncmacro", title="cncmacro", version=__version__, instructions=INSTRUCTIONS, log_level="WARNING"
    )
    server.add_tool(check, name="check", title="Check a CNC macro program", description=CHECK_TEXT,
                    annotations=READ_ONLY)  # fmt: skip
    server.add_tool(run, name="run", title="Run a CNC macro program", description=RUN_TEXT, annotations=READ_ONLY)
    server.add_tool(explain_subject, name="explain", title="Explain a variable or code", description=EXPLAIN_TEXT,
                    annotations=READ_ONLY)  # fmt: skip
    server.add_tool(profiles, name="profiles", title="List the control profiles", description=PROFILES_TEXT,
                    annotations=READ_ONLY)  # fmt: skip
    return server


def serve() -> int:
    """Answer on stdio until the client closes it."""
    build_server().run("stdio")
    return 0
