"""``cncmacro mcp`` through the Model Context Protocol SDK's own client over stdio: the server is
started as an assistant's editor starts it (``python -m cncmacro mcp``), and every answer is read
as the client reads it (its structured content, or an error result's text)."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from pathlib import Path
from typing import Any

import pytest
from mcp.client.session import ClientSession
from mcp.client.stdio import StdioServerParameters, stdio_client


@asynccontextmanager
async def mcp_session(cwd: Path) -> AsyncIterator[ClientSession]:
    server = StdioServerParameters(
        command=sys.executable, args=["-m", "cncmacro", "mcp"], cwd=cwd, env={"LANG": "C.UTF-8"}
    )
    with open(os.devnull, "w") as quiet:
        async with stdio_client(server, errlog=quiet) as (read, write), ClientSession(read, write) as session:
            await session.initialize()
            yield session


async def answer(session: ClientSession, tool: str, **arguments: Any) -> dict[str, Any]:
    """A tool's structured answer; the call must not be an error."""
    result = await session.call_tool(tool, arguments)
    assert not result.is_error, result.content
    assert isinstance(result.structured_content, dict)
    return result.structured_content


async def error_text(session: ClientSession, tool: str, **arguments: Any) -> str:
    """The text of a call that must be an error result."""
    result = await session.call_tool(tool, arguments)
    assert result.is_error, result.structured_content
    return " ".join(getattr(c, "text", "") for c in result.content)


@pytest.mark.asyncio
async def test_the_server_offers_four_read_only_tools(tmp_path: Path) -> None:
    async with mcp_session(tmp_path) as session:
        tools = (await session.list_tools()).tools
    assert sorted(t.name for t in tools) == ["check", "explain", "profiles", "run"]
    for tool in tools:
        assert tool.annotations is not None and tool.annotations.read_only_hint, tool.name
        assert tool.description
    run = next(t for t in tools if t.name == "run")
    assert {"path", "text", "profile", "max_moves"} <= set(run.input_schema["properties"])


@pytest.mark.asyncio
async def test_run_returns_a_10_mm_feed_move_at_600_mm_min_taking_1_s(tmp_path: Path) -> None:
    # G91 G01 X10. F600: 10 mm at 600 mm/min = 10 mm/s -> 1 s; nothing else moves or takes time
    async with mcp_session(tmp_path) as session:
        got = await answer(session, "run", text="O1000\nG91 G01 X10. F600\nM30\n")
    assert got["status"] == "completed" and got["alarm"] is None
    assert got["movesTotal"] == 1 and not got["movesCut"]
    [move] = got["moves"]
    assert (move["line"], move["mode"], move["kind"]) == (2, "G01", "feed")
    assert move["from"]["X"] == 0 and move["to"]["X"] == 10 and move["time"] == pytest.approx(1.0)
    assert got["cycle"]["seconds"] == pytest.approx(1.0) and got["cycle"]["cut"] == pytest.approx(10.0)
    assert got["dialect"] == "fanuc-0i"
    assert got["summary"] == "completed after 2 blocks; 1 move; cycle time ≈ 1.0 s · 10 mm cut · 0 mm rapid"


@pytest.mark.asyncio
async def test_run_of_a_file_lists_the_first_max_moves_and_says_it_cut_them(tmp_path: Path) -> None:
    # five passes of G91 G01 X2. F600: five moves, X 0 -> 10, each 2 mm / 10 mm/s = 0.2 s, 1 s in all;
    # #1 counts the passes to 5; only the first two moves are listed
    program = tmp_path / "O2000.nc"
    program.write_text("O2000\n#1=0\nWHILE[#1LT5]DO1\nG91 G01 X2. F600\n#1=#1+1\nEND1\nM30\n")
    async with mcp_session(tmp_path) as session:
        got = await answer(session, "run", path="O2000.nc", max_moves=2)
    assert got["movesTotal"] == 5 and got["movesCut"]
    assert [m["to"]["X"] for m in got["moves"]] == [2, 4]
    assert got["variables"] == {"1": 5}
    assert got["cycle"]["seconds"] == pytest.approx(1.0)
    assert not (tmp_path / ".cncmacro-vars.json").exists()  # nothing written beside the program


@pytest.mark.asyncio
async def test_run_with_presets_and_an_alarm_names_the_alarm_and_its_line(tmp_path: Path) -> None:
    # #100 = 5 preset; #3000 = 1 raises macro alarm 3001 (3000 + 1 on a FANUC 0i) at line 3
    text = "O3000\nIF[#100EQ5]GOTO9\nN9 #3000=1(STOP)\nM30\n"
    async with mcp_session(tmp_path) as session:
        got = await answer(session, "run", text=text, presets=["100=5"])
    assert got["status"] == "alarm"
    assert got["alarm"]["number"] == 3001 and got["alarm"]["line"] == 3
    assert got["variables"]["100"] == 5


@pytest.mark.asyncio
async def test_check_finds_the_planted_mistake_at_its_line(tmp_path: Path) -> None:
    folder = tmp_path / "programs"
    folder.mkdir()
    (folder / "O4000.nc").write_text("O4000\nG90 G00 X0 Y0\n#1=#2+\nM30\n")  # line 3 ends in the middle of a sum
    (folder / "O4001.nc").write_text("O4001\nG91 G01 X10. F600\nM30\n")  # nothing wrong
    async with mcp_session(tmp_path) as session:
        by_file = await answer(session, "check", path="programs/O4000.nc")
        by_folder = await answer(session, "check", path="programs")
        by_text = await answer(session, "check", text="O4000\nG90 G00 X0 Y0\n#1=#2+\nM30\n")
    for got in (by_file, by_folder, by_text):
        [finding] = got["findings"]
        assert (finding["line"], finding["severity"], finding["code"]) == (3, "error", "syntax")
        assert got["errors"] == 1 and got["total"] == 1 and not got["cut"]
    assert by_folder["findings"][0]["file"].endswith("O4000.nc")
    assert by_text["findings"][0]["file"] == "program.nc"


@pytest.mark.asyncio
async def test_explain_reads_the_profile_tables(tmp_path: Path) -> None:
    async with mcp_session(tmp_path) as session:
        x_end = await answer(session, "explain", subject="#5001", profile="fanuc-0i")
        g71 = await answer(session, "explain", subject="G71", profile="gsk980tdi")
        local = await answer(session, "explain", subject="#1")
        chinese = await answer(session, "explain", subject="#5001", profile="fanuc-0i", locale="zh-CN")
    # FANUC 0i: #5001 is the X axis's block end position in work coordinates, in mm, read only
    assert x_end["kind"] == "system" and x_end["axis"] == "X" and x_end["unit"] == "mm" and x_end["access"] == "r"
    assert "block end" in x_end["text"]
    assert "程序段终点" in chinese["text"]
    # GSK980TDi: G71 is the axial rough turning cycle
    assert g71["kind"] == "code" and g71["profile"] == "gsk980tdi" and "rough turning" in g71["text"].lower()
    # #1 is filled by argument A in both argument specifications
    assert local["kind"] == "local" and local["arguments"] == {"I": "A", "II": "A"}


@pytest.mark.asyncio
async def test_profiles_lists_every_control_with_its_machine(tmp_path: Path) -> None:
    async with mcp_session(tmp_path) as session:
        got = await answer(session, "profiles")
    by_name = {p["name"]: p for p in got["profiles"]}
    assert {"fanuc-0i", "fanuc-30i", "haas", "gsk980tdi", "fanuc-0i-lathe"} <= set(by_name)
    assert by_name["gsk980tdi"]["lathe"] and not by_name["haas"]["lathe"]
    assert by_name["fanuc-0i"]["default"] and "fanuc" in by_name["fanuc-0i"]["aliases"]


@pytest.mark.asyncio
async def test_bad_input_gets_an_error_result_and_the_server_goes_on(tmp_path: Path) -> None:
    (tmp_path / "image.nc").write_bytes(b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR")
    async with mcp_session(tmp_path) as session:
        missing_check = await error_text(session, "check", path="nowhere/O1.nc")
        missing_run = await error_text(session, "run", path="nowhere/O1.nc")
        binary_check = await error_text(session, "check", path="image.nc")
        binary_run = await error_text(session, "run", path="image.nc")
        unknown = await error_text(session, "run", text="G01 X1. F100\n", profile="hass")
        nothing = await error_text(session, "check")
        unknown_code = await error_text(session, "explain", subject="G999", profile="haas")
        still = await answer(session, "profiles")
    assert "no such file" in missing_check and "no file" in missing_run
    assert "binary" in binary_check and "binary" in binary_run
    assert "Did you mean haas?" in unknown
    assert "path" in nothing and "text" in nothing
    assert "G999" in unknown_code
    assert still["profiles"]


@pytest.mark.asyncio
async def test_an_endless_loop_stops_at_the_block_budget_in_bounded_time(tmp_path: Path) -> None:
    # WHILE[1EQ1] never ends: after #1=0 (1 block) each pass runs WHILE, #1=#1+1 and END1 (3 blocks),
    # so a budget of 10,000 blocks stops after (10,000 - 1) / 3 = 3,333 passes with #1 = 3333
    text = "O5000\n#1=0\nWHILE[1EQ1]DO1\n#1=#1+1\nEND1\nM30\n"
    async with mcp_session(tmp_path) as session:
        start = time.monotonic()
        small = await answer(session, "run", text=text, max_blocks=10_000)
        default = await answer(session, "run", text=text)
        took = time.monotonic() - start
        checked = await answer(session, "check", text=text)
    assert small["status"] == "limit" and "endless loop" in small["summary"]
    assert small["blocks"] == 10_000 and small["variables"] == {"1": 3333}
    assert default["status"] == "limit" and default["blocks"] == 1_000_000
    assert took < 60
    assert any(f["code"] in ("endless-loop", "run-limit") for f in checked["findings"])


def test_without_the_mcp_package_the_command_says_how_to_install_it() -> None:
    hide = "import sys; sys.modules['mcp'] = None; from cncmacro.cli.main import main; sys.exit(main(['mcp']))"
    done = subprocess.run([sys.executable, "-c", hide], capture_output=True, text=True, timeout=60,
                          env={**os.environ, "LANG": "C.UTF-8"})  # fmt: skip
    assert done.returncode == 2
    assert "pip install 'cncmacro[mcp]'" in done.stderr and "Traceback" not in done.stderr


@pytest.mark.asyncio
async def test_a_program_ending_in_m99_runs_one_pass_and_says_so(tmp_path: Path) -> None:
    # one pass: the G91 move of 1 mm, then M99 at level 0 ends the run (a subprogram run on its own)
    async with mcp_session(tmp_path) as session:
        got = await answer(session, "run", text="O9000\nG91 G01 X1. F600\nM99\n")
    assert got["status"] == "completed" and got["movesTotal"] == 1
    assert any("ends in M99" in m for m in got["messages"])


def test_a_run_past_the_time_limit_stops_after_its_chunk_and_says_so(monkeypatch: pytest.MonkeyPatch) -> None:
    # with no time left the run stops at the first look at the clock: after one chunk of 100,000 blocks
    from cncmacro.cli import assistant_tools

    monkeypatch.setattr(assistant_tools, "MAX_SECONDS", 0.0)
    got = assistant_tools.run_program(text="O5000\nWHILE[1EQ1]DO1\nEND1\nM30\n")
    assert got["status"] == "limit" and got["blocks"] == assistant_tools.CHUNK == 100_000
    assert got["summary"].startswith("stopped after 0 s")


@pytest.mark.asyncio
async def test_a_profile_asked_for_wins_over_the_machine_file_and_says_so(tmp_path: Path) -> None:
    shop = tmp_path / "shop"
    shop.mkdir()
    (shop / ".cncmacro.toml").write_text('base = "haas"\n')
    (shop / "O0001.nc").write_text("O0001\nG00 X1.\nM30\n")
    (shop / "O0002.nc").write_bytes(b"O0002\n\0\0\0")  # binary: not read, the rest still checked
    async with mcp_session(tmp_path) as session:
        ran = await answer(session, "run", path="shop/O0001.nc", profile="fanuc-0i")
        checked = await answer(session, "check", path="shop", profile="fanuc-0i")
    assert ran["dialect"] == "fanuc-0i"
    assert any("overrides haas" in m for m in ran["messages"])
    assert any("O0002.nc" in m and "binary" in m for m in checked["messages"])
    assert any("overrides haas" in m for m in checked["messages"])
    assert checked["errors"] == 0
