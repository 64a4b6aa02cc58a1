"""Helpers for the tests of findings made by running: analyse a few program files together, as
the editor does with open documents, and take the diagnostics of the first one's analysis."""

from __future__ import annotations

from pathlib import Path

from cncmacro.analysis.diagnostics import Diagnostic
from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.library.machine_file import MachineSettings


def analyse_files(tmp_path: Path, files: dict[str, str], dialect: str = "fanuc", **kw: object) -> list[Diagnostic]:
    """Every diagnostic of analysing the first of ``files`` (name -> text, written to ``tmp_path``
    and opened); ``kw`` goes to ``WorkspaceAnalysis`` (``locale``, ``max_blocks``...)."""
    ws = WorkspaceAnalysis(settings=MachineSettings(date=20261122, time=80000), dialect=dialect, **kw)  # type: ignore[arg-type]
    paths = []
    for name, text in files.items():
        p = tmp_path / name
        p.write_text(text, encoding="utf-8")
        ws.open(str(p), text, 1)
        paths.append(str(p))
    result = ws.analyze(paths[0])
    assert result is not None
    return [d for diags in result.diagnostics.values() for d in diags]
