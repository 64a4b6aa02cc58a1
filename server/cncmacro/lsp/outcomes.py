"""A finished analysis made ready to publish, on the worker thread.

The results of the analyses (one per machine file, ``analysis_groups.py``) are merged: each
open file's findings and values taken from its own analysis (a program of another machine's
folder is read there as saved), those of a file that is not open from every analysis that
reached it. Each finding is then turned into its protocol form and its JSON text, which is what
is published (``CncMacroProtocol.send_diagnostics``). ``ProtocolForms`` keeps both from one
analysis to the next: an edit changes a few findings, and the others, with the text of their
lines unchanged, keep their converted forms; a file whose findings did not change keeps its
whole list.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from lsprotocol import types

from ..analysis import Diagnostic
from ..analysis.runs.cycle_lenses import FileTiming
from ..analysis.workspace import WorkspaceAnalysis
from ..analysis.workspace_result import AnalysisResult, Value
from .documents import OpenDocument
from .positions import Encoding
from .protocol_diagnostics import to_lsp

LineValues = dict[int, list[tuple[int, Value]]]
Results = list[tuple[Path | None, WorkspaceAnalysis, AnalysisResult]]  # per machine file, its analysis's result


@dataclass(slots=True)
class Outcome:
    """One finished analysis, made ready on the worker thread: per file URI the version it
    was analysed at (None for a file that is not open), its diagnostics, their protocol form,
    and the values the runs left on its lines."""

    generation: int
    versions: dict[str, int | None]
    found: dict[str, list[Diagnostic]]
    items: dict[str, list[types.Diagnostic]]
    values: dict[str, LineValues]
    payloads: dict[str, list[str]]  # the items encoded as JSON text, as published
    on_disk: list[str] = field(default_factory=list)  # files changed on disk: nothing analysed, read them first
    timing: dict[str, FileTiming] = field(default_factory=dict)  # per URI, the cycle time (cycle_lenses.py)
    partial: bool = False  # some runs were cut short by their time slice: their files are left out

    def without(self, uris: set[str]) -> None:
        """Leave out the files of ``uris`` (their runs did not end yet): this outcome is partial."""
        for table in (self.versions, self.found, self.items, self.values, self.payloads, self.timing):
            for uri in uris:
                table.pop(uri, None)
        self.partial = True


class ProtocolForms:
    """See the module docstring."""

    def __init__(self) -> None:
        # per file the diagnostics last converted, and per diagnostic (with the text of its
        # lines) its protocol form and JSON form
        self._converted: dict[str, tuple[list[Diagnostic], list[types.Diagnostic], list[str]]] = {}
        self._forms: dict[tuple[object, ...], tuple[types.Diagnostic, str]] = {}

    def outcome(self, generation: int, docs: list[OpenDocument], results: Results, encoding: Encoding,
                uri_of: Callable[[str], str], unstructure: Callable[[Any], Any]) -> Outcome:  # fmt: skip
        """The outcome of ``results``, the analyses of the open ``docs``, in the client's
        ``encoding``; ``uri_of`` names a file that is not open, ``unstructure`` turns a
        protocol object into JSON data."""
        by_path = {d.path: d for d in docs}
        result, owner = _merged(by_path, results)
        versions: dict[str, int | None] = {}
        found: dict[str, list[Diagnostic]] = {}
        for path, diags in result.diagnostics.items():
            uri = by_path[path].uri if path in by_path else uri_of(path)
            versions[uri] = by_path[path].version if path in by_path else None
            found[uri] = diags
        for d in docs:
            versions.setdefault(d.uri, d.version)
            found.setdefault(d.uri, [])

        def line_text(file: str, line: int) -> str:
            ws = owner.get(file) or next((a for _, a, _ in results if a.document(file) is not None), results[0][1])
            parsed = ws.document(file)
            lines = parsed.lines if parsed is not None else _disk_lines(ws, file)
            return lines[line] if 0 <= line < len(lines) else ""

        forms = self._forms
        used: dict[tuple[object, ...], tuple[types.Diagnostic, str]] = {}
        items: dict[str, list[types.Diagnostic]] = {}
        payloads: dict[str, list[str]] = {}
        for uri, diags in found.items():
            cached = self._converted.get(uri)
            if cached is not None and cached[0] == diags:
                items[uri], payloads[uri] = cached[1], cached[2]
                continue
            converted, payload = [], []
            for x in diags:
                # an edit changes a few findings: the others keep their converted forms
                key = (x, encoding, line_text(x.file, x.line), line_text(x.file, x.end_line),
                       *(line_text(r.file, r.line) for r in x.related))  # fmt: skip
                form = used.get(key) or forms.get(key)
                if form is None:
                    item = to_lsp(x, line_text, encoding, uri_of)
                    form = (item, json.dumps(unstructure(item)))
                used[key] = form
                converted.append(form[0])
                payload.append(form[1])
            items[uri], payloads[uri] = converted, payload
            self._converted[uri] = (diags, converted, payload)
        if used:  # only the forms of the findings of now are kept
            self._forms = used
        for uri in [u for u in self._converted if u not in found]:
            del self._converted[uri]  # a closed document, or a file without findings now
        values = {by_path[p].uri: v for p, v in result.values.items() if p in by_path}
        timing = {by_path[p].uri: t for p, t in result.timing.items() if p in by_path}
        return Outcome(generation, versions, found, items, values, payloads, timing=timing)


def _merged(by_path: dict[str, OpenDocument], results: Results) -> tuple[AnalysisResult, dict[str, WorkspaceAnalysis]]:
    """The results of the analyses as one, and per file the analysis whose findings it shows:
    an open file's own (its machine file's), a file that is not open the first that reached it
    (the findings of the others added, each once)."""
    if len(results) == 1:
        _, analysis, result = results[0]
        return result, dict.fromkeys(result.diagnostics, analysis)
    owner: dict[str, WorkspaceAnalysis] = {}
    diagnostics: dict[str, list[Diagnostic]] = {}
    values: dict[str, dict[int, list[tuple[int, Value]]]] = {}
    timing: dict[str, FileTiming] = {}
    for machine_file, analysis, result in results:
        for path, diags in result.diagnostics.items():
            doc = by_path.get(path)
            if doc is not None and doc.machine_file != machine_file:
                continue  # an open file of another machine, read here as saved
            if path not in diagnostics:
                owner[path], diagnostics[path] = analysis, list(diags)
            elif doc is None:
                kept = diagnostics[path]
                kept += [x for x in diags if x not in kept]
                kept.sort(key=Diagnostic.sort_key)
        for path, lines in result.values.items():
            doc = by_path.get(path)
            if doc is not None and doc.machine_file == machine_file:
                values[path] = lines
        for path, t in result.timing.items():
            doc = by_path.get(path)
            if doc is not None and doc.machine_file == machine_file:
                timing[path] = t
    return AnalysisResult(results[0][2].version, diagnostics, values, timing), owner


def _disk_lines(ws: WorkspaceAnalysis, path: str) -> list[str]:
    loaded = ws.library.load(path)
    return loaded.lines if loaded is not None else []
