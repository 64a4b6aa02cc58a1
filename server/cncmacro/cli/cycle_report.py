"""``cncmacro run``'s cycle time: the totals of the program run and of each tool.

The machine times every move, dwell, tool change and M code (planner/cycle_time.py); this
module reads its clock, path lengths and tool changes after the run and writes them in the
text output (``cycle time O1000: ≈ 3 min 12 s · 1,842 mm cut · 6,300 mm rapid``, then one line
per tool change) and the JSON (``cycle``: ``seconds``, ``cut``, ``rapid``, their ``unit`` and
``tools``): the path in the program's unit, inches for a ``G20`` program.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..analysis.runs.cycle_summary import ToolPart, Totals, end_totals, tool_name, tool_parts, totals_text
from ..bilingual import is_chinese
from ..machine import Machine
from ..machine.status import RunStatus
from .terminal import TextOut


def run_totals(machine: Machine) -> tuple[Totals, list[ToolPart]]:
    """The run's totals and each tool's part."""
    end = end_totals(machine.planner)
    changes = [(c.file, c.line, c.tool, Totals(c.clock, c.cut, c.rapid)) for c in machine.planner.tool_changes]
    return end, tool_parts(changes, end)


def cycle_json(machine: Machine, program: str, locale: str | None = None) -> dict[str, Any]:
    """``cycle`` of ``--json``: seconds, the cut and rapid path in ``unit`` (the program's: mm, or
    in for a ``G20`` program), for the program and per tool, and the program's as a person reads
    them (``text``, in ``locale``: the toolpath's legend)."""
    end, parts = run_totals(machine)
    cut, rapid = end.shown()
    return {
        "program": program,
        "seconds": end.seconds,
        "cut": cut,
        "rapid": rapid,
        "unit": end.unit,
        "text": totals_text(end, locale),
        "tools": [
            {
                "tool": p.tool,
                "file": p.file,
                "line": p.line + 1,
                "seconds": p.totals.seconds,
                "cut": p.totals.shown()[0],
                "rapid": p.totals.shown()[1],
            }
            for p in parts
        ],
    }


def write_cycle_text(machine: Machine, program: str, out: TextOut, locale: str | None = None) -> None:
    """The totals for a machinist: the program's, then each tool's from its change; nothing for
    a run that did not complete (an alarm, the block budget), whose time is not the program's, nor
    for one that took no time (no move, dwell or tool change: a macro that only computes)."""
    end, parts = run_totals(machine)
    if machine.status != RunStatus.COMPLETED or (not end.seconds and not parts):
        return
    zh = is_chinese(locale)
    print(f"加工时间 {program}：{totals_text(end, locale)}" if zh
          else f"cycle time {program}: {totals_text(end, locale)}", file=out)  # fmt: skip
    for p in parts:
        where = f"{Path(p.file).name}:{p.line + 1}"
        tool = tool_name(p.tool, machine.dialect.lathe)
        print(f"  {tool}（{where}）：{totals_text(p.totals, locale)}" if zh
              else f"  {tool} ({where}): {totals_text(p.totals, locale)}", file=out)  # fmt: skip
