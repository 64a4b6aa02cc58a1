"""A real editor: headless Neovim 0.7 starts ``cncmacro lsp``, opens an example program with two
planted mistakes, and receives the diagnostics: the syntax error in the open file and the macro
alarm that the analysis run finds in the called macro (a file Neovim never opened)."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "fanuc"

SCRIPT = r"""
local main, macro, out = os.getenv("CNC_MAIN"), os.getenv("CNC_MACRO"), os.getenv("CNC_OUT")
vim.cmd("edit " .. vim.fn.fnameescape(main))
local buf = vim.api.nvim_get_current_buf()
local id = vim.lsp.start_client({
  name = "cncmacro",
  cmd = { os.getenv("CNC_PYTHON"), "-m", "cncmacro", "lsp" },
  root_dir = os.getenv("CNC_ROOT"),
})
vim.lsp.buf_attach_client(buf, id)
local macro_buf = vim.uri_to_bufnr(vim.uri_from_fname(macro))
vim.wait(30000, function()
  return #vim.diagnostic.get(buf) > 0 and #vim.diagnostic.get(macro_buf) > 0
end, 50)
local found = {}
for _, b in ipairs({ buf, macro_buf }) do
  for _, d in ipairs(vim.diagnostic.get(b)) do
    local lsp = d.user_data and d.user_data.lsp or {}
    table.insert(found, { file = vim.api.nvim_buf_get_name(b), line = d.lnum, severity = d.severity,
                          code = d.code or lsp.code, message = d.message })
  end
end
vim.fn.writefile({ vim.fn.json_encode(found) }, out)
vim.lsp.stop_client(id)
vim.wait(2000, function() return vim.lsp.get_client_by_id(id) == nil end, 50)
vim.cmd("qa!")
"""


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="Neovim is installed by the Linux test setup only")
def test_neovim_receives_the_diagnostics_of_an_example_file(tmp_path: Path) -> None:
    nvim = shutil.which("nvim")
    assert nvim is not None, "nvim is missing: install Debian's 'neovim' package (the test setup does)"
    main = tmp_path / "bolt_circle.nc"
    text = (EXAMPLES / "bolt_circle.nc").read_text("utf-8")
    planted = text.replace("R60. A0 H8 Z-15.", "R60. A0 H0 Z-15.")  # no holes: the macro's alarm 3005
    assert planted != text
    main.write_text(planted + "#1=[2+3\n", "utf-8")  # and a syntax error on the last line
    shutil.copy(EXAMPLES / "O9100.nc", tmp_path / "O9100.nc")
    script = tmp_path / "check.lua"
    script.write_text(SCRIPT, "utf-8")
    out = tmp_path / "found.json"
    env = dict(os.environ, CNC_MAIN=str(main), CNC_MACRO=str(tmp_path / "O9100.nc"), CNC_OUT=str(out),
               CNC_PYTHON=sys.executable, CNC_ROOT=str(tmp_path), HOME=str(tmp_path),
               XDG_CONFIG_HOME=str(tmp_path / "config"), XDG_DATA_HOME=str(tmp_path / "data"),
               XDG_STATE_HOME=str(tmp_path / "state"), XDG_CACHE_HOME=str(tmp_path / "cache"))  # fmt: skip
    subprocess.run([nvim, "--headless", "-u", "NONE", "-i", "NONE", "-n", "-c", f"luafile {script}"],
                   env=env, cwd=tmp_path, timeout=90, check=True, stdin=subprocess.DEVNULL)  # fmt: skip
    found = json.loads(out.read_text("utf-8"))
    by_code = {(Path(d["file"]).name, d["code"]): d for d in found}
    syntax = by_code[("bolt_circle.nc", "syntax")]
    assert syntax["line"] == len(planted.splitlines()) and syntax["severity"] == 1  # 1 is ERROR
    alarm = by_code[("O9100.nc", "macro-alarm")]
    assert "3005" in alarm["message"] and "O1000" in alarm["message"] and alarm["severity"] == 2  # WARN
