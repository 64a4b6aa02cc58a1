"""A file is read in one profile whoever reads it (docs/design.md "Dialect selection"): the
file's ``(cncmacro: dialect=..)`` comment, then its machine file's ``base``, then the setting
(``--dialect``, the editor's ``cncMacro.dialect``, a launch's ``dialect``), then fanuc, with
the machine file applied. ``cncmacro check``, the language server (its findings and the
dialect it tells the status bar) and the debugger give the same program the same profile
and the same machine (but what a person types on the command line, ``--dialect``, comes before
the machine file's ``base``: docs/cli.md "Which dialect a file is read in"): each says that
``#160`` is not a common variable of this machine, naming the profile and the machine file's
ranges, ``#100-#149, #500-#999``."""

from __future__ import annotations

import io
import json
import re
from pathlib import Path

import pytest
import pytest_lsp
from pytest_lsp import LanguageClient

from cncmacro.cli.check import check_paths
from cncmacro.dap.protocol import MessageWriter, Request
from cncmacro.dap.session import Session
from cncmacro.dialects import get_dialect

from .lsp_session import config, open_file, published_where, start

TIMEOUT = 30.0
RANGES = "#100-#149, #500-#999"  # the machine file's commons: #160 is none
MARKER = "(cncmacro: dialect=gsk980tdi)"

# case -> (the program's first line, the machine file's base, the setting; the profile and
# the link of the chain that decides)
CASES = {
    "the file's comment": (MARKER, "haas", "fanuc-30i", "gsk980tdi", "file"),
    "the machine file": ("(PART 12)", "haas", "fanuc-30i", "haas", "workspace"),
    "the setting": ("(PART 12)", None, "gsk980tdi", "gsk980tdi", "setting"),
    "the default": ("(PART 12)", None, None, "fanuc-0i", "default"),
}


@pytest_lsp.fixture(config=config())
async def client(lsp_client: LanguageClient):  # type: ignore[no-untyped-def]
    """A server not yet initialised: each test makes its workspace first."""
    yield
    await lsp_client.shutdown_session()


def shop(root: Path, first_lines: str, base: str | None) -> Path:
    """A folder with a machine file (``base`` and the commons of ``RANGES``) and O0001.nc,
    which writes #160 after ``first_lines``; the program's path."""
    folder = root / "shop"
    folder.mkdir()
    named = f'base = "{base}"\n' if base else ""
    (folder / ".cncmacro.toml").write_text(f"{named}common = [[100, 149], [500, 999]]\n", "utf-8")
    program = folder / "O0001.nc"
    program.write_bytes(f"O0001\n{first_lines}\n#160=1\nM30\n".encode())
    return program


def by_check(program: Path, setting: str | None) -> str:
    """The message of ``cncmacro check --format json [--dialect setting]`` for #160."""
    out, err = io.StringIO(), io.StringIO()
    check_paths([str(program.parent)], out, err, "json", dialect=setting)
    [found] = [d for d in json.loads(out.getvalue()) if d["code"] == "variable-number"]
    return str(found["message"])


def by_debugger(program: Path, setting: str | None) -> str:
    """What the debugger says of the alarm its run of ``program`` stops with (a launch with
    ``dialect``: ``setting``)."""
    out = io.BytesIO()
    session = Session(MessageWriter(out))
    launch: dict[str, object] = {"program": str(program), "noSave": True}
    if setting is not None:
        launch["dialect"] = setting
    session.handle(Request(1, "initialize", {"locale": "en"}))
    session.handle(Request(2, "launch", launch))
    session.handle(Request(3, "configurationDone", {}))
    assert session.worker is not None
    session.worker.join(timeout=60)
    session.handle(Request(4, "exceptionInfo", {"threadId": 1}))
    data = out.getvalue()
    while data:
        header, _, rest = data.partition(b"\r\n\r\n")
        length = int(header.split(b":")[1])
        message = json.loads(rest[:length].decode("utf-8"))
        if message.get("command") == "exceptionInfo":
            return str(message["body"]["description"])
        data = rest[length:]
    raise AssertionError("the debugger gave no exception info")


async def by_editor(client: LanguageClient, program: Path, setting: str | None) -> tuple[str, str, str]:
    """The language server's finding for #160 and the dialect it says the file is read in,
    with the link of the chain that decided (``cncmacro/documentDialect``)."""
    await start(client, program.parent, "en", {"dialect": setting} if setting else {})
    uri = open_file(client, program, program.read_bytes().decode())
    got = await published_where(client, {uri: lambda d: any(x.code == "variable-number" for x in d)}, TIMEOUT)
    [found] = [x for x in got[uri] if x.code == "variable-number"]
    said = await client.protocol.send_request_async("cncmacro/documentDialect", {"uri": uri})
    return found.message, said.dialect, said.source


@pytest.mark.asyncio
@pytest.mark.parametrize("case", list(CASES))
async def test_dialect_selection_check_the_editor_and_the_debugger_read_a_file_in_one_profile(
    client: LanguageClient, tmp_path: Path, case: str
) -> None:
    first_lines, base, setting, profile, source = CASES[case]
    program = shop(tmp_path, first_lines, base)
    machine = f"({get_dialect(profile).title}: {RANGES};"
    found, dialect, decided = await by_editor(client, program, setting)
    assert (dialect, decided) == (profile, source)
    assert machine in found
    typed = setting if source == "workspace" and setting else profile  # --dialect over the machine file
    assert f"({get_dialect(typed).title}: {RANGES};" in by_check(program, setting)
    assert machine in by_debugger(program, setting)


@pytest.mark.asyncio
async def test_dialect_selection_a_form_feed_in_a_comment_moves_no_line_for_the_debugger(
    client: LanguageClient, tmp_path: Path
) -> None:
    # the comment is on the fifth line as an editor counts lines (a form feed breaks none), so
    # it decides for the debugger too
    program = shop(tmp_path, f"(PAGE 1\f)\n(A)\n(B)\n{MARKER}", None)
    machine = f"({get_dialect('gsk980tdi').title}: {RANGES};"
    found, dialect, decided = await by_editor(client, program, None)
    assert (dialect, decided) == ("gsk980tdi", "file")
    assert machine in found
    assert machine in by_check(program, None)
    assert machine in by_debugger(program, None)


def test_dialect_selection_is_made_in_library_only() -> None:
    # check, the editor, the call index and the debugger ask library/profiles.py's
    # file_profile: no module above the library follows the chain (choose_dialect,
    # dialect_and_source) by itself, where it could forget the machine file or count lines
    # in its own way
    package = Path(__file__).resolve().parents[2] / "server" / "cncmacro"
    chain = re.compile(r"\b(?:choose_dialect|dialect_and_source)\b")
    followers = sorted(
        str(p.relative_to(package))
        for p in package.rglob("*.py")
        if p.parent.name != "library" and chain.search(p.read_text("utf-8"))
    )
    assert followers == []
