"""``cncmacro check``: report the diagnostics of program files, as text or JSON.

Exit status: 0 when no error was found, 1 when one was, 2 on bad usage or unreadable input
(a missing path, a binary file). Unreadable files are named on standard error; the others
are still checked.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import TextIO

from ..analysis import Diagnostic, syntax_diagnostics
from ..library.files import BinaryFileError, find_program_files, read_program
from ..syntax.document import ParsedDocument


def check_paths(paths: list[str], out: TextIO, err: TextIO, fmt: str = "text") -> int:
    """Check every program file under ``paths``; print the findings; return the exit status."""
    diagnostics: list[Diagnostic] = []
    unreadable = False
    for arg in paths:
        root = Path(arg)
        if not root.exists():
            print(f"cncmacro: {arg}: no such file or folder", file=err)
            unreadable = True
            continue
        for path in find_program_files(root):
            try:
                source = read_program(path)
            except BinaryFileError as e:
                print(f"cncmacro: {e}", file=err)
                unreadable = True
                continue
            except OSError as e:
                print(f"cncmacro: {path}: cannot read: {e.strerror or e}", file=err)
                unreadable = True
                continue
            doc = ParsedDocument(source.text)
            diagnostics += syntax_diagnostics(doc.program, str(path))
    diagnostics.sort(key=Diagnostic.sort_key)
    if fmt == "json":
        json.dump([_as_json(d) for d in diagnostics], out, ensure_ascii=False, indent=2)
        out.write("\n")
    else:
        for d in diagnostics:
            out.write(f"{d.file}:{d.line + 1}:{d.column + 1}: {d.severity}: {d.message} [{d.code}]\n")
    if unreadable:
        return 2
    return 1 if any(d.severity == "error" for d in diagnostics) else 0


def _as_json(d: Diagnostic) -> dict[str, object]:
    """The CLI contract's JSON object: 1-based lines and columns, end column exclusive."""
    return {
        "file": d.file,
        "line": d.line + 1,
        "column": d.column + 1,
        "endLine": d.end_line + 1,
        "endColumn": d.end_column + 1,
        "severity": d.severity,
        "code": d.code,
        "message": d.message,
    }


def main_check(args: object) -> int:
    return check_paths(args.paths, sys.stdout, sys.stderr, args.format)  # type: ignore[attr-defined]
