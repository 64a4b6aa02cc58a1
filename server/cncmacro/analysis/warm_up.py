"""A short program analysed once as a language server starts, before the first document opens.

The first analysis in a process pays for what later ones find ready: the patterns of the
profile's static checks are compiled, the plain-line reading learns its G words, and Python
specialises the interpreter's hot loops. On a 2,000-line CAM program that is about 2 ms of the
30 ms the editor's first open may take (docs/benchmarks.md), so the server spends them while it
starts instead (``warm_up``). The program is analysed in a workspace of its own, from no folder,
under the settings the workspace's documents will be read with; nothing of it is published, and
nothing of it stays but what any analysis leaves in the process's caches.
"""

from __future__ import annotations

import logging

from ..library.machine_file import MachineSettings
from ..syntax.document import ParsedDocument
from .workspace import WorkspaceAnalysis

log = logging.getLogger(__name__)

# a path no program file has: the analysis reads nothing from disk for it
WARM_UP_PATH = "<cncmacro warm-up>.nc"
# the forms of a CAM program and of a macro: plain and numbered moves, arcs, assignments with
# functions, a condition, a loop and a jump
WARM_UP_PROGRAM = "\n".join(
    (
        "O0001",
        "G90 G17 G21 G40 G49 G80",
        "#100=12.5",
        "#101=[#100+2.]*SIN[30.]/COS[#100]-SQRT[4.]+FIX[#100*10.]/10.",
        "#102=0",
        "G00 X0. Y0. Z5.",
        "N1 G01 X1. Y2. Z-1. F500",
        "G01 X2. Y3.",
        "G02 X4. Y3. R1.",
        "G03 X2. Y3. I-1. J0.",
        "IF [#101 GT 999999.] GOTO 2",
        "WHILE [#102 LT 2] DO1",
        "G01 X#100 Y#101",
        "#102=#102+1",
        "END1",
        "N2 G00 Z50.",
        "M05",
        "M30",
        "%",
    )
)


def warm_up(settings: MachineSettings, dialect: str | None, locale: str) -> None:
    """Analyse ``WARM_UP_PROGRAM`` under ``settings`` and the ``dialect`` setting (module
    docstring). A failure is logged and costs nothing else: the documents are analysed as ever."""
    try:
        analysis = WorkspaceAnalysis(settings=settings, dialect=dialect, locale=locale)
        analysis.open(WARM_UP_PATH, ParsedDocument(WARM_UP_PROGRAM), 0)
        analysis.analyze(WARM_UP_PATH)
    except Exception:
        log.exception("the warm-up analysis failed")
