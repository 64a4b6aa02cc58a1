"""A 309-digit number (more than a float holds) after N, O, GOTO, G, M, T, P, an axis or ``#``
is a syntax error on its line, at the number: the checker reads every other line and file, the
language server keeps the document open (later edits apply) and answers hovers elsewhere."""

from __future__ import annotations

import io
import json
from pathlib import Path

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from cncmacro.cli.check import check_paths
from lsp.lsp_session import FANUC, close_file, diagnostics_for, edit, hover_text, open_file, session_fixture

fanuc_en = session_fixture(FANUC, "en")

BIG = "9" * 309
LINES = [f"N{BIG} X1.", f"O{BIG}", f"GOTO{BIG}", f"G{BIG}", f"M{BIG}", f"T{BIG}", f"M98 P{BIG}", f"X1.{BIG}",
         f"#1={BIG}", f"#{BIG}=1"]  # fmt: skip


@pytest.mark.parametrize("line", LINES, ids=[line[:5] for line in LINES])
def test_a_309_digit_number_is_a_syntax_error_and_the_rest_is_checked(tmp_path: Path, line: str) -> None:
    (tmp_path / "O0001.nc").write_text(f"O0001\n#5=1\n{line}\nM30\n", encoding="utf-8")
    (tmp_path / "O0002.nc").write_text("O0002\n#1=1/0\nM30\n", encoding="utf-8")
    out, err = io.StringIO(), io.StringIO()
    check_paths([str(tmp_path)], out, err, "json")
    found = [(Path(str(d["file"])).name, d["line"], d["code"]) for d in json.loads(out.getvalue())]
    assert ("O0001.nc", 3, "syntax") in found
    assert not any(code == "internal-error" for _, _, code in found)
    assert ("O0002.nc", 2, "division-by-zero") in found


@pytest.mark.asyncio(loop_scope="session")
async def test_a_document_with_a_309_digit_label_stays_open_and_hovers_go_on(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "HUGE.nc", f"O0001\nN{BIG} X1.\nGOTO{BIG}\n#1=2\nM30\n")
    first = await diagnostics_for(fanuc_en, uri, 1)
    errors = [(d.range.start.line, d.code) for d in first.diagnostics if d.severity == types.DiagnosticSeverity.Error]
    assert errors == [(1, "syntax"), (2, "syntax")]
    edit(fanuc_en, uri, 2, 1, 0, 400, "N10 X1.")  # the document is open: the edit applies
    edit(fanuc_en, uri, 3, 2, 0, 400, "GOTO10")
    later = await diagnostics_for(fanuc_en, uri, 3)
    assert not [d for d in later.diagnostics if d.severity == types.DiagnosticSeverity.Error]
    other = open_file(fanuc_en, FANUC / "OTHER.nc", "O0002\n#100=1\nM30\n")
    assert "#100" in await hover_text(fanuc_en, other, 1, 2)
    close_file(fanuc_en, other)
    close_file(fanuc_en, uri)


@pytest.mark.asyncio(loop_scope="session")
async def test_a_document_uri_with_a_nul_is_analysed_and_stops_nothing(fanuc_en: LanguageClient) -> None:
    odd = (FANUC / "NUL.nc").as_uri().replace("NUL.nc", "N%00L.nc")
    fanuc_en.text_document_did_open(
        types.DidOpenTextDocumentParams(types.TextDocumentItem(odd, "cncmacro", 1, "O0001\n#1=1/0\nM30\n"))
    )
    found = await diagnostics_for(fanuc_en, odd, 1)
    assert "division-by-zero" in [d.code for d in found.diagnostics]
    other = open_file(fanuc_en, FANUC / "OTHER2.nc", "O0002\n#2=1/0\nM30\n")
    assert "division-by-zero" in [d.code for d in (await diagnostics_for(fanuc_en, other, 1)).diagnostics]
    close_file(fanuc_en, other)
    close_file(fanuc_en, odd)


def _run(*args: str) -> tuple[int, str]:
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-m", "cncmacro", "run", *args], capture_output=True, text=True, timeout=60)
    return done.returncode, done.stderr


MOVE_TO_500 = "O0001\nG01 X#500 F100\nM30\n"


@pytest.mark.parametrize(
    ("where", "words"),
    [
        ("set", "#500 = 1e+50 is beyond what a variable holds (±1e+47)"),
        ("machine file", "'variables.500' must be a finite number a variable holds (±1e+47 at most) (line 2)"),
        ("persistent file", "#500 holds 1e+50, which no variable of a control can hold"),
    ],
)
def test_a_value_beyond_what_a_variable_holds_is_refused_where_it_comes_in(tmp_path: Path, where: str, words: str):
    # a program that computes such a value gets alarm 111; one given from outside used to end the
    # run in an OverflowError traceback when the program moved to it
    program = tmp_path / "O0001.nc"
    program.write_text(MOVE_TO_500, encoding="utf-8")
    args = [str(program)]
    if where == "set":
        args += ["--set", "#500=1e50"]
    elif where == "machine file":
        (tmp_path / ".cncmacro.toml").write_text("[variables]\n500 = 1e50\n", encoding="utf-8")
    else:
        (tmp_path / ".cncmacro-vars.json").write_text('{"variables": {"500": 1e50}}', encoding="utf-8")
    code, err = _run(*args)
    assert code == 2 and words in err and "Traceback" not in err
