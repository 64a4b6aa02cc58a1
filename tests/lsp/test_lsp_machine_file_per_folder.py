"""Each program is read with the machine file nearest above it, in the editor as in
``cncmacro check`` (docs/machine-file.md): a workspace of two folders, a mill whose
``.cncmacro.toml`` has the commons #100-#199 and a GSK980TDi lathe whose commons are
#100-#149 and #500-#999, gives the same program its own findings in each folder, the ones
``cncmacro check`` gives it; a machine file edited (or broken) on disk changes the findings of
the files below it only, and its problem is shown on it."""

from __future__ import annotations

import asyncio
import io
import json
from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient, client_capabilities

from cncmacro.cli.check import check_paths

from .lsp_session import accept_registrations, config, open_file, published_where

pytestmark = pytest.mark.asyncio

PROGRAM = "O0001\n#150=1\nG0 X#150\nM30\n"  # #150: a common on the mill, none on the lathe
MILL = 'base = "fanuc-0i"\ncommon = [[100, 199]]\n'
LATHE = 'base = "gsk980tdi"\ncommon = [[100, 149], [500, 999]]\n'
TIMEOUT = 30.0

Finding = tuple[int, int, str, str]  # line, column (0-based), severity, code
_LEVELS = {1: "error", 2: "warning", 3: "information", 4: "hint"}


@pytest_lsp.fixture(config=config())
async def client(lsp_client: LanguageClient):  # type: ignore[no-untyped-def]
    """A server not yet initialised: each test makes its workspace first."""
    yield
    await lsp_client.shutdown_session()


def two_machines(root: Path) -> tuple[Path, Path]:
    """``root/mill`` and ``root/lathe``, each with its machine file and the same program."""
    mill, lathe = root / "mill", root / "lathe"
    for folder, machine in ((mill, MILL), (lathe, LATHE)):
        folder.mkdir()
        (folder / ".cncmacro.toml").write_text(machine, "utf-8")
        (folder / "O0001.nc").write_text(PROGRAM, "utf-8")
    return mill, lathe


async def start_on(client: LanguageClient, folders: list[Path]) -> None:
    """``initialize`` (VS Code's capabilities) with ``folders`` as the workspace folders."""
    accept_registrations(client)
    await client.initialize_session(
        types.InitializeParams(
            capabilities=client_capabilities("visual-studio-code"),
            root_uri=folders[0].as_uri(),
            workspace_folders=[types.WorkspaceFolder(uri=f.as_uri(), name=f.name) for f in folders],
            locale="en",
        )
    )


def in_editor(items: list[types.Diagnostic]) -> list[Finding]:
    return sorted((d.range.start.line, d.range.start.character, _LEVELS[d.severity or 1], str(d.code)) for d in items)


def by_check(paths: list[Path]) -> dict[str, list[Finding]]:
    """What ``cncmacro check --hints --format json`` finds, per file."""
    out, err = io.StringIO(), io.StringIO()
    check_paths([str(p) for p in paths], out, err, "json", hints=True)
    found: dict[str, list[Finding]] = {}
    for d in json.loads(out.getvalue()):
        found.setdefault(d["file"], []).append((d["line"] - 1, d["column"] - 1, d["severity"], d["code"]))
    return {file: sorted(items) for file, items in found.items()}


def changed_on_disk(client: LanguageClient, path: Path, text: str) -> None:
    path.write_text(text, "utf-8")
    client.workspace_did_change_watched_files(
        types.DidChangeWatchedFilesParams([types.FileEvent(path.as_uri(), types.FileChangeType.Changed)])
    )


def common_150(findings: list[Finding]) -> list[int]:
    return [line for line, _, _, code in findings if code == "variable-number"]


async def test_each_folder_gets_the_findings_check_gives_it_with_its_own_machine_file(
    client: LanguageClient, tmp_path: Path
) -> None:
    mill, lathe = two_machines(tmp_path)
    await start_on(client, [mill, lathe])
    mill_uri, lathe_uri = open_file(client, mill / "O0001.nc"), open_file(client, lathe / "O0001.nc")
    got = await published_where(client, {mill_uri: lambda d: True, lathe_uri: lambda d: True}, TIMEOUT)
    cli = by_check([mill, lathe])
    assert common_150(in_editor(got[lathe_uri])) == [1, 2]  # the lathe has no #150
    assert common_150(in_editor(got[mill_uri])) == []
    assert in_editor(got[lathe_uri]) == cli[str(lathe / "O0001.nc")]
    assert in_editor(got[mill_uri]) == cli.get(str(mill / "O0001.nc"), [])
    for uri, name in ((mill_uri, "fanuc-0i"), (lathe_uri, "gsk980tdi")):
        said = await client.protocol.send_request_async("cncmacro/documentDialect", {"uri": uri})
        assert (said.dialect, said.source) == (name, "workspace")


async def test_editing_one_machine_file_changes_the_findings_below_it_only(
    client: LanguageClient, tmp_path: Path
) -> None:
    mill, lathe = two_machines(tmp_path)
    await start_on(client, [mill, lathe])
    mill_uri, lathe_uri = open_file(client, mill / "O0001.nc"), open_file(client, lathe / "O0001.nc")
    await published_where(client, {mill_uri: lambda d: True, lathe_uri: lambda d: True}, TIMEOUT)
    before_mill = in_editor(client.diagnostics[mill_uri])

    changed_on_disk(client, lathe / ".cncmacro.toml", 'base = "gsk980tdi"\ncommon = [[100, 199], [500, 999]]\n')
    got = await published_where(client, {lathe_uri: lambda d: not common_150(in_editor(d))}, TIMEOUT)
    assert in_editor(got[lathe_uri]) == by_check([lathe]).get(str(lathe / "O0001.nc"), [])
    assert in_editor(client.diagnostics[mill_uri]) == before_mill

    changed_on_disk(client, mill / ".cncmacro.toml", "common = [[100, 149]]\n")
    got = await published_where(client, {mill_uri: lambda d: common_150(in_editor(d)) == [1, 2]}, TIMEOUT)
    assert in_editor(got[mill_uri]) == by_check([mill])[str(mill / "O0001.nc")]
    await asyncio.sleep(0.5)  # whatever else the change made is published by now
    assert not common_150(in_editor(client.diagnostics[lathe_uri]))


async def test_a_broken_machine_file_of_a_second_folder_is_shown_on_it(client: LanguageClient, tmp_path: Path) -> None:
    mill, lathe = two_machines(tmp_path)
    await start_on(client, [mill, lathe])
    mill_uri, lathe_uri = open_file(client, mill / "O0001.nc"), open_file(client, lathe / "O0001.nc")
    await published_where(client, {mill_uri: lambda d: True, lathe_uri: lambda d: True}, TIMEOUT)
    machine = lathe / ".cncmacro.toml"
    changed_on_disk(client, machine, 'base = "gsk980tdi"\ncommon = "many"\n')
    got = await published_where(client, {machine.as_uri(): lambda d: bool(d)}, TIMEOUT)
    [problem] = got[machine.as_uri()]
    assert (problem.code, problem.range.start.line) == ("machine-file", 1)
    # the lathe goes on with the defaults (fanuc-0i has #150), the mill keeps its own file
    await published_where(client, {lathe_uri: lambda d: not common_150(in_editor(d))}, TIMEOUT)
    assert not common_150(in_editor(client.diagnostics[mill_uri]))
    changed_on_disk(client, machine, LATHE)  # made right again
    again = {machine.as_uri(): lambda d: not d, lathe_uri: lambda d: bool(common_150(in_editor(d)))}
    await published_where(client, again, TIMEOUT)
