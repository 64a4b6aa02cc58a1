"""The fuzzing targets and invariants shared by ``benchmarks/fuzz.py`` and ``tests/hardening/``.

A case is a program text and a dialect. ``run_case`` sends it through every layer a user can
reach: the parser, ``WorkspaceAnalysis`` (the static checks and the bounded runs), a bounded
``Machine`` run (as ``cncmacro run`` does, without touching a persistent file), the editing
commands (formatting, renumbering, adding and removing sequence numbers), and every
request handler of the language server, called in-process on a server that holds the text as
an open document, its client counting columns in one of the three position encodings (UTF-8,
UTF-16, UTF-32), picked at random for each case. Now and then (``ODD_WORKSPACES``) the case is
also written into a folder of odd file names (not UTF-8, control characters, 240 digits) with
unreadable and deeply nested folders, a pipe, circular and dangling links or a hostile machine
file (``hostile_machine_file``: values beyond any machine, names that name nothing, numbers of
thousands of digits), and ``cncmacro check`` (text, JSON, SARIF) and the server's index go
through it. Programs also get huge repeats (a drilling cycle's ``K9999``, ``M98 L9999``).

The invariants: no exception escapes; every run ends within its block budget; every diagnostic
range lies inside the document (in the protocol strictly, counted in the client's encoding; an
analysis diagnostic may mark the one column just past a line's end, where a block ends too
early); after every edit the server's text is the text the client holds; ``check`` exits with
0, 1 or 2 and prints valid UTF-8 and valid JSON. A broken invariant raises ``InvariantError``
naming it. ``random_program`` writes programs from macro fragments and noise, long operator
chains and huge literals; ``mutate`` damages a text the way hands and tools do (deleted,
doubled and swapped characters, bracket runs, control bytes, CJK text, line-break changes).
"""

from __future__ import annotations

import asyncio
import inspect
import io
import json
import os
import random
import tempfile
from collections.abc import Iterator
from pathlib import Path

from lsprotocol import types
from pygls.exceptions import JsonRpcException

from cncmacro.analysis.editing.sequence_numbers import add_sequence_numbers, remove_unused_sequence_numbers, renumber
from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.cli.check import check_paths
from cncmacro.dialects import DIALECTS as ALL_PROFILES
from cncmacro.dialects import get_dialect
from cncmacro.library.machine_file import MachineSettings
from cncmacro.library.programs import ProgramLibrary
from cncmacro.lsp.positions import UTF8, UTF16, UTF32
from cncmacro.lsp.server import CncMacroServer, build_server
from cncmacro.machine import Machine, RunStatus
from cncmacro.syntax.document import ParsedDocument, split_lines
from cncmacro.syntax.formatting import COMPACT, SPACED, FormatOptions, format_lines

ROOT = Path(__file__).resolve().parent.parent
DIALECTS = ALL_PROFILES
REQUEST_SECONDS = 60.0  # a request or analysis still unanswered after this is a hang
RUN_BUDGET = 3000  # blocks per fuzzed run: enough to loop and call, small enough to stay fast
ODD_WORKSPACES = 0.1  # the share of cases also written into a folder of odd names and modes
_FOLDER = Path(tempfile.gettempdir()) / "cncmacro-fuzz-workspace"


class InvariantError(AssertionError):
    """A fuzzed case broke an invariant; the message says which."""


# ---------------------------------------------------------------- generating programs

_ATOMS = ["1", "0", "2.5", "-3", ".5", "1.", "#1", "#24", "#100", "#500", "#0", "#3000", "#5021", "#[#1]", "#9100"]
_OPS = ["+", "-", "*", "/", " AND ", " OR ", " XOR ", " MOD "]
_FUNCS = ["SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ABS", "LN", "EXP", "ROUND", "FIX", "FUP", "BIN", "BCD"]
_RELS = [" EQ ", " NE ", " GT ", " GE ", " LT ", " LE ", "==", "<", ">="]
_NC = ["G00", "G01", "G02", "G03", "G90", "G91", "G54", "G43 H1", "G81 R2 Z-5", "G80", "M03 S1000", "M05", "T0101"]
_NOISE = ["", "(", ")", "[", "]", "#", "=", ";", "%", "/", "\t", "  ", "O", "N", "P[", "G65", "\x00", "\x1b", "中文",
          "（注释）", "\ufeff", "\r", "..", "/../"]  # fmt: skip


def _expr(rnd: random.Random, depth: int = 0) -> str:
    k = rnd.random()
    if depth > 4 or k < 0.35:
        return rnd.choice(_ATOMS)
    if k < 0.6:
        return _expr(rnd, depth + 1) + rnd.choice(_OPS) + _expr(rnd, depth + 1)
    if k < 0.75:
        return f"[{_expr(rnd, depth + 1)}]"
    if k < 0.9:
        f = rnd.choice(_FUNCS)
        if f == "ATAN" and rnd.random() < 0.5:
            return f"ATAN[{_expr(rnd, depth + 1)}]/[{_expr(rnd, depth + 1)}]"
        return f"{f}[{_expr(rnd, depth + 1)}]"
    return f"#[{_expr(rnd, depth + 1)}]"


def _cond(rnd: random.Random) -> str:
    one = f"{_expr(rnd, 2)}{rnd.choice(_RELS)}{_expr(rnd, 2)}"
    if rnd.random() < 0.2:
        return f"[{one}] {rnd.choice(['AND', 'OR'])} [{_expr(rnd, 3)}{rnd.choice(_RELS)}{_expr(rnd, 3)}]"
    return one


def _var(rnd: random.Random) -> str:
    return rnd.choice(["#1", "#2", "#24", "#26", "#100", "#101", "#150", "#500", "#999", "#3000", "#3006", "#[#100]"])


def _statement(rnd: random.Random, labels: list[int], programs: list[int]) -> str:
    k = rnd.randrange(17)
    label = rnd.choice(labels) if labels else rnd.randint(1, 99)
    if k < 4:
        return f"{_var(rnd)}={_expr(rnd)}"
    if k == 4:
        return f"IF[{_cond(rnd)}]GOTO{label}"
    if k == 5:
        return f"IF[{_cond(rnd)}]THEN{_var(rnd)}={_expr(rnd)}"
    if k == 6:
        return f"GOTO{rnd.choice([str(label), '#1', '[#100+1]', '0', '100000'])}"
    if k == 7:
        n = rnd.randint(1, 4)
        return f"WHILE[{_cond(rnd)}]DO{n}\n#100=#100+1\nEND{n}"
    if k == 8:
        p = rnd.choice(programs) if programs else rnd.randint(1, 9999)
        return f"G65 P{p} L{rnd.choice(['', '2', '0', '99999', '#1'])} A{_expr(rnd, 3)} X{_expr(rnd, 3)}"
    if k == 9:
        p = rnd.choice(programs) if programs else rnd.randint(1, 9999)
        return f"M98 P{p}{rnd.choice(['', ' L3', ' Q5'])}"
    if k == 10:
        return f"G66 P{rnd.choice(programs) if programs else 9} A1"
    if k == 11:
        return rnd.choice(["M99", "M30", "M02", "G67", "M00", f"M99 P{label}", "#3000=1(ALARM)", "DPRNT[X#1[53]]"])
    if k == 12:
        return f"G65 H{rnd.randint(1, 99):02d} P#{rnd.randint(100, 199)} Q{rnd.randint(-9, 9)} R{rnd.randint(0, 9)}"
    if k == 13:
        return f"{rnd.choice(_NC)} X{_expr(rnd, 3)} Z{rnd.choice(['#1', '-2.5', '[#24+1]'])}"
    if k == 14:
        return f"G65 P[{rnd.choice(['CUT', '切削', '../../etc/passwd', '/etc/passwd', 'O1004', '..'])}]"
    if k == 16 and rnd.random() < 0.5:  # huge repeats: thousands of holes or calls from one block
        p = rnd.choice(programs) if programs else rnd.randint(1, 9999)
        return rnd.choice(
            [
                f"G91 G81 X0.1 Z-1. R-1. F100 K{rnd.choice([9999, 10000, 0])}",
                f"M98 P{p} L9999",
                f"G65 P{p} L{rnd.choice([9999, 99999])}",
                "G80",
            ]
        )
    if k == 15 and rnd.random() < 0.5:
        return long_chain(rnd, rnd.randint(20, 600))
    if k == 15:
        return huge_literal(rnd)
    return rnd.choice(_NOISE) * rnd.randint(1, 3)


def long_chain(rnd: random.Random, n: int) -> str:
    """An expression of ``n`` chained operators: binary, unary signs or nested functions."""
    shape = rnd.randrange(4)
    if shape == 0:
        return "#1=1" + "".join(rnd.choice(_OPS) + rnd.choice(["1", "#1", "2.5"]) for _ in range(n))
    if shape == 1:
        return "#1=" + "-" * n + "1"
    if shape == 2:
        return "#1=" + "ABS[" * n + "1" + "]" * n
    return f"IF[#1{rnd.choice(_RELS)}" + "+".join(["1"] * n) + "]GOTO1"


def huge_literal(rnd: random.Random) -> str:
    """A number of tens to hundreds of digits where a control takes a few."""
    digits = "9" * rnd.choice([16, 25, 40, 309, 400])
    return rnd.choice([f"N{digits}", f"O{digits}", f"GOTO{digits}", f"G{digits}", f"M{digits}", f"T{digits}",
                       f"M98 P{digits}", f"G65 P{digits}", f"#1={digits}.5", f"#{digits}=1", f"X{digits}",
                       f"#1=1.{digits}", f"#1={digits}E5", f"L{digits}"])  # fmt: skip


def random_program(rnd: random.Random, max_lines: int = 40) -> str:
    """A program of O units with labels, loops, calls, alarms and some noise."""
    programs = [rnd.randint(1, 9999) for _ in range(rnd.randint(1, 3))]
    out: list[str] = []
    for number in programs:
        out.append(f"O{number:04d} ({rnd.choice(['MAIN', '主程序', 'SUB'])})")
        labels: list[int] = [rnd.randint(1, 200) for _ in range(rnd.randint(0, 4))]
        for _ in range(rnd.randint(1, max(1, max_lines // len(programs)))):
            prefix = f"N{labels.pop()} " if labels and rnd.random() < 0.3 else ""
            out.append(prefix + _statement(rnd, labels or [rnd.randint(1, 200)], programs))
        out.append(rnd.choice(["M30", "M99", "M02", ""]))
    if rnd.random() < 0.3:
        out.insert(0, "(cncmacro: dialect=gsk980tdi)")
    sep = rnd.choice(["\n", "\n", "\r\n", "\r"])
    return sep.join(out) + rnd.choice(["", sep])


def mutate(text: str, rnd: random.Random, rounds: int = 3) -> str:
    """``text`` damaged a few times."""
    for _ in range(rnd.randint(1, rounds)):
        if not text:
            text = rnd.choice(_NOISE)
            continue
        i = rnd.randrange(len(text) + 1)
        j = min(len(text), i + rnd.randint(0, 12))
        k = rnd.randrange(9)
        if k == 0:
            text = text[:i] + text[j:]
        elif k == 1:
            text = text[:i] + text[i:j] * rnd.randint(2, 5) + text[j:]
        elif k == 2:
            text = text[:i] + rnd.choice(_NOISE) + text[i:]
        elif k == 3:
            n = rnd.randint(1, 40)
            text = text[:i] + "[" * n + "1" + "]" * rnd.randint(0, n) + text[i:]
        elif k == 4:
            text = text[:i] + chr(rnd.randint(0, 0x3000)) + text[i:]
        elif k == 5:
            text = text.replace("\n", rnd.choice(["\r\n", "\r", "\n\n"]))
        elif k == 6:
            text = text[:i] + str(rnd.choice([0, -1, 1e308, 99999999, 1e-300, 10**30])) + text[j:]
        elif k == 7:
            text = text[:i] + text[j:] + text[i:j]
        else:
            text = text[:i] + rnd.choice(["#", "G65 P", "GOTO", "END1", "DO1", "WHILE[", "IF[", "M98 P"]) + text[i:]
    return text


def corpus_texts() -> list[str]:
    """The example programs and the test corpus, as seeds for mutation."""
    out = []
    for folder in (ROOT / "examples", ROOT / "tests" / "corpus"):
        for p in sorted(folder.rglob("*")):
            if p.is_file() and p.suffix.lower() in (".nc", ".cnc", ".mac"):
                out.append(p.read_text("utf-8", errors="replace"))
    return out


def cases(rnd: random.Random, seeds: list[str]) -> Iterator[str]:
    """An endless mix of generated programs, mutated corpus programs and mutated generated ones."""
    while True:
        k = rnd.random()
        if k < 0.4 or not seeds:
            yield random_program(rnd)
        elif k < 0.8:
            yield mutate(rnd.choice(seeds), rnd)
        else:
            yield mutate(random_program(rnd), rnd, rounds=6)


# ---------------------------------------------------------------- the invariants


def _inside(lines: list[str], line: int, col: int, end_line: int, end_col: int, what: str) -> None:
    n = len(lines)
    if not (0 <= line <= end_line < n):
        raise InvariantError(f"{what}: lines {line}..{end_line} outside a document of {n} lines")
    # a mark right after a line's last character (a block that ends too early) is one column wide
    if not (0 <= col <= len(lines[line]) and 0 <= end_col <= len(lines[end_line]) + 1):
        raise InvariantError(f"{what}: columns {col}..{end_col} outside lines {line}/{end_line}")
    if (line, col) > (end_line, end_col):
        raise InvariantError(f"{what}: range ends before it starts")


def check_analysis(text: str, dialect: str, path: str, budget: int = RUN_BUDGET) -> int:
    """Analyse ``text`` as the checker does; return the number of diagnostics."""
    ws = WorkspaceAnalysis(dialect=dialect, max_blocks=budget)
    ws.open(path, text, 1)
    result = ws.analyze(path)
    if result is None:
        raise InvariantError("analysis returned no result without being cancelled")
    lines = split_lines(text)
    count = 0
    for file, diags in result.diagnostics.items():
        for d in diags:
            count += 1
            if file == path:
                _inside(lines, d.line, d.column, d.end_line, d.end_column, f"diagnostic {d.code}")
    for run in ws.runs.values():
        if run.machine.blocks > budget:
            raise InvariantError(f"an analysis run executed {run.machine.blocks} blocks, over its budget {budget}")
    return count


def check_editing(text: str, dialect: str) -> int:
    """The editing commands on ``text``: formatting (both spacings, comments aligned) and the
    three sequence-number edits, each planned and applied without an exception, each line they
    write still one line. The number of lines they changed."""
    lines = split_lines(text)
    program = ParsedDocument(text).program
    profile = get_dialect(dialect)
    changed = 0
    for options in (FormatOptions(SPACED, False), FormatOptions(COMPACT, True)):
        new = format_lines(lines, 0, len(lines) - 1, options, program.read_end)
        if any("\n" in t or "\r" in t for t in new.values()):
            raise InvariantError("formatting wrote a line break into a line")
        changed += len(new)
    for plan in (renumber(program, profile, step=10, keep_computed=True),
                 add_sequence_numbers(program, profile, step=5, keep_computed=True),
                 remove_unused_sequence_numbers(program, profile, keep_computed=True)):  # fmt: skip
        for c in plan.changes:
            if not 0 <= c.line < len(lines) or not 0 <= c.start <= c.end <= len(lines[c.line]):
                raise InvariantError(f"a sequence-number edit outside its line: {c}")
        changed += len(plan.changes)
    return changed


def check_run(text: str, dialect: str, path: str, budget: int = RUN_BUDGET) -> str:
    """Run ``text`` on the machine as ``cncmacro run`` does (no persistent file); its status."""
    m = Machine(get_dialect(dialect), MachineSettings(), ProgramLibrary([]))
    m.start_file(path, text)
    while True:
        status = m.run(budget - m.blocks)
        if status != RunStatus.PAUSED:
            break
        m.resume()
    if m.blocks > budget:
        raise InvariantError(f"a run executed {m.blocks} blocks, over its budget {budget}")
    return status


class LspTarget:
    """A language server in this process, driven through its registered handlers: documents
    are opened, edited and closed by the notification handlers (the analysis runs as it does
    in the editor), every request handler is called at a few positions, and what the server
    publishes is caught instead of sent and checked against the document it is for."""

    def __init__(self) -> None:
        self.encoding = "utf-16"  # the columns this client counts in (``ENCODINGS``)
        self.server: CncMacroServer = build_server()
        self.server.settings_ready.set()
        self.server.protocol.client_capabilities = types.ClientCapabilities()  # what initialize would set
        self.features = self.server.protocol.fm.features
        self.published: list[types.PublishDiagnosticsParams] = []
        self.server.text_document_publish_diagnostics = self.published.append  # type: ignore[method-assign]
        self.logged: list[types.LogMessageParams] = []  # e.g. a file of the workspace it cannot read
        self.server.window_log_message = self.logged.append  # type: ignore[method-assign]
        protocol = self.server.protocol
        convert = protocol._converter  # the diagnostics already in JSON form, read back

        def prepared(method: str, params: dict[str, object]) -> None:
            if method == types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS:
                self.published.append(convert.structure(params, types.PublishDiagnosticsParams))

        protocol.send_prepared = prepared  # type: ignore[attr-defined]
        self.loop = asyncio.new_event_loop()

    def close(self) -> None:
        self.loop.close()

    async def scan(self, folder: Path) -> None:
        """Index ``folder`` as the workspace, announce each file in it as changed on disk, and
        ask for the workspace's symbols."""
        try:
            self.server.index.scan([str(folder)])
            names = os.listdir(os.fsencode(folder))
            events = [types.FileEvent(uri=Path(os.fsdecode(os.path.join(os.fsencode(folder), n))).as_uri(),
                                      type=types.FileChangeType.Changed) for n in names]  # fmt: skip
            changed = types.DidChangeWatchedFilesParams(changes=events)
            await self._call(types.WORKSPACE_DID_CHANGE_WATCHED_FILES, changed)
            await self._call(types.WORKSPACE_SYMBOL, types.WorkspaceSymbolParams(query=""))
            await self._settle()
        finally:
            self.server.index.scan([])  # the next case starts from an empty workspace
            self.published.clear()
            self.logged.clear()

    def check(self, text: str, uri: str, positions: list[tuple[int, int]]) -> int:
        """Open ``text``, ask every request at ``positions``, edit at each, check what was
        published; close it. The number of requests answered."""
        return self.loop.run_until_complete(self._check(text, uri, positions))

    async def _call(self, method: str, params: object) -> object:
        handler = self.features.get(method)
        if handler is None:
            return None
        try:
            got = handler(params)
            if inspect.isawaitable(got):
                got = await asyncio.wait_for(got, REQUEST_SECONDS)
        except JsonRpcException:  # a request the server refuses on purpose (RequestFailed): answered
            return None
        self._conforms(method, got)
        return got

    def _conforms(self, method: str, got: object) -> None:
        """The answer to a request is what the protocol allows for ``method``: it becomes JSON
        (no NaN or infinity) and reads back as the method's response type."""
        entry = types.METHOD_TO_TYPES.get(method)
        if entry is None or entry[1] is None:
            return  # a notification: nothing is answered
        convert = self.server.protocol._converter
        try:
            raw = convert.unstructure(got)
            json.dumps(raw, allow_nan=False)
            convert.structure({"jsonrpc": "2.0", "id": 1, "result": raw}, entry[1])
        except Exception as error:
            raise InvariantError(f"{method}: the answer is not what the protocol allows: {error!r}") from error

    async def _settle(self) -> None:
        """Let the scheduled analyses finish."""
        for _ in range(1000):
            await asyncio.sleep(0)
            pending = [t for t in asyncio.all_tasks(self.loop) if t is not asyncio.current_task()]
            if not pending:
                return
            await asyncio.wait(pending, timeout=REQUEST_SECONDS)
        raise InvariantError("the server's analysis tasks never settled")

    def _check_published(self, uri: str, lines: list[str], version: int) -> None:
        """Everything published for ``uri`` since the last check is for ``version`` (no edit
        let an analysis run in between) and lies inside its ``lines``."""
        for p in self.published:
            if p.uri != uri:
                continue
            if p.version is not None and p.version != version:
                raise InvariantError(f"diagnostics of version {p.version} published after version {version}")
            for d in p.diagnostics:
                r = d.range
                _inside_client(lines, r.start.line, r.start.character, r.end.line, r.end.character, d.code,
                               self.encoding)  # fmt: skip
        self.published.clear()

    async def _check(self, text: str, uri: str, points: list[tuple[int, int]]) -> int:
        self.server.documents.encoding = _ENCODERS[self.encoding]
        ident = types.TextDocumentIdentifier(uri)
        model: list[str] | None = split_lines(text)  # the text as the client holds it, edited alongside
        positions = [client_position(model, line, cp, self.encoding) for line, cp in points]
        item = types.TextDocumentItem(uri=uri, language_id="cncmacro", version=1, text=text)
        await self._call(types.TEXT_DOCUMENT_DID_OPEN, types.DidOpenTextDocumentParams(text_document=item))
        calls = 0
        try:
            await self._settle()
            doc = self.server.documents.get(uri)
            self._check_published(uri, doc.lines, 1)
            whole = types.Range(types.Position(0, 0), types.Position(len(doc.lines), 0))
            refs = types.ReferenceContext(include_declaration=True)
            requests: list[tuple[str, object]] = [
                (types.TEXT_DOCUMENT_DOCUMENT_SYMBOL, types.DocumentSymbolParams(text_document=ident)),
                (types.TEXT_DOCUMENT_FOLDING_RANGE, types.FoldingRangeParams(text_document=ident)),
                (types.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL, types.SemanticTokensParams(text_document=ident)),
                (types.TEXT_DOCUMENT_SEMANTIC_TOKENS_RANGE,
                 types.SemanticTokensRangeParams(text_document=ident, range=whole)),
                (types.TEXT_DOCUMENT_INLAY_HINT, types.InlayHintParams(text_document=ident, range=whole)),
                (types.WORKSPACE_SYMBOL, types.WorkspaceSymbolParams(query="O")),
                (types.TEXT_DOCUMENT_DIAGNOSTIC, types.DocumentDiagnosticParams(text_document=ident)),
                (types.TEXT_DOCUMENT_FORMATTING, types.DocumentFormattingParams(text_document=ident, options=_FORMAT)),
                (types.TEXT_DOCUMENT_RANGE_FORMATTING,
                 types.DocumentRangeFormattingParams(text_document=ident, range=whole, options=_FORMAT)),
            ]  # fmt: skip
            for line, col in positions:
                pos = types.Position(line, col)
                ctx = types.CodeActionContext(diagnostics=[])
                requests += [
                    (types.TEXT_DOCUMENT_HOVER, types.HoverParams(text_document=ident, position=pos)),
                    (types.TEXT_DOCUMENT_DEFINITION, types.DefinitionParams(text_document=ident, position=pos)),
                    (types.TEXT_DOCUMENT_REFERENCES,
                     types.ReferenceParams(text_document=ident, position=pos, context=refs)),
                    (types.TEXT_DOCUMENT_PREPARE_RENAME, types.PrepareRenameParams(text_document=ident, position=pos)),
                    (types.TEXT_DOCUMENT_RENAME,
                     types.RenameParams(text_document=ident, position=pos, new_name="N77")),
                    (types.TEXT_DOCUMENT_COMPLETION, types.CompletionParams(text_document=ident, position=pos)),
                    (types.TEXT_DOCUMENT_SIGNATURE_HELP, types.SignatureHelpParams(text_document=ident, position=pos)),
                    (types.TEXT_DOCUMENT_CODE_ACTION,
                     types.CodeActionParams(text_document=ident, range=types.Range(pos, pos), context=ctx)),
                ]  # fmt: skip
            for method, params in requests:
                await self._call(method, params)
                calls += 1
            for version, (line, cp) in enumerate(points, start=2):  # an edit of 3 characters at each position
                lines = self.server.documents.get(uri).lines
                start = client_position(lines, line, cp, self.encoding)
                end = client_position(lines, line, cp + 3, self.encoding)
                change = types.DidChangeTextDocumentParams(
                    text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
                    content_changes=[types.TextDocumentContentChangePartial(
                        range=types.Range(types.Position(*start), types.Position(*end)), text="#1=[")],
                )  # fmt: skip
                await self._call(types.TEXT_DOCUMENT_DID_CHANGE, change)
                if model is not None and line < len(model):
                    was = model[line]
                    model[line] = was[: min(cp, len(was))] + "#1=[" + was[min(cp + 3, len(was)) :]
                    if self.server.documents.get(uri).lines != model:
                        raise InvariantError(f"after an edit in {self.encoding} columns at line {line} "
                                             f"column {cp}, the server's text is not the editor's")  # fmt: skip
                else:
                    model = None  # an edit past the last line: where it lands is the server's choice
                where = types.Position(*start)
                await self._call(types.TEXT_DOCUMENT_HOVER, types.HoverParams(text_document=ident, position=where))
                calls += 1
            await self._settle()
            doc = self.server.documents.get(uri)
            self._check_published(uri, doc.lines, doc.version)
        finally:
            await self._call(types.TEXT_DOCUMENT_DID_CLOSE,
                             types.DidCloseTextDocumentParams(text_document=ident))  # fmt: skip
            await self._settle()
            self.published.clear()
        return calls


ENCODINGS = ("utf-8", "utf-16", "utf-32")
_FORMAT = types.FormattingOptions(tab_size=4, insert_spaces=True)
_ENCODERS = {"utf-8": UTF8, "utf-16": UTF16, "utf-32": UTF32}


def client_units(text: str, encoding: str) -> int:
    """The length of ``text`` in the client's units, counted here independently of the server."""
    if encoding == "utf-8":
        return len(text.encode("utf-8", "surrogatepass"))
    if encoding == "utf-16":
        return len(text.encode("utf-16-le", "surrogatepass")) // 2
    return len(text)


def client_position(lines: list[str], line: int, cp: int, encoding: str) -> tuple[int, int]:
    """The client's (line, column) of code-point column ``cp`` on ``line``; past the line's end
    (or past the last line) the extra columns stay as they are."""
    text = lines[line] if 0 <= line < len(lines) else ""
    inside = min(cp, len(text))
    return line, client_units(text[:inside], encoding) + (cp - inside)


def _inside_client(lines: list[str], line: int, col: int, end_line: int, end_col: int, what: object,
                   encoding: str = "utf-16") -> None:  # fmt: skip
    """A protocol range (in the client's columns) inside the document."""
    wide = [client_units(x, encoding) for x in lines]
    n = len(lines)
    if not (0 <= line <= end_line < n):
        raise InvariantError(f"protocol diagnostic {what}: lines {line}..{end_line} outside {n} lines")
    if not (0 <= col <= wide[line] and 0 <= end_col <= wide[end_line]):
        raise InvariantError(f"protocol diagnostic {what}: columns {col}..{end_col} outside the line")


def positions_in(text: str, rnd: random.Random, count: int = 4) -> list[tuple[int, int]]:
    """Cursor positions in ``text``: inside lines, at their ends and past them."""
    lines = split_lines(text) or [""]
    out = []
    for _ in range(count):
        line = rnd.randrange(len(lines) + 1)  # one past the end too
        width = len(lines[line]) if line < len(lines) else 0
        out.append((line, rnd.randint(0, width + 2)))
    return out


_ODD_NAMES = [
    b"O0001.nc", b"\xb3\xcc\xd0\xf2.nc", b"O 0002.nc", b"-O0003.nc", "中文程序.nc".encode(), b"O0004.NC",
    b"line\nbreak.nc", b"\x1b[31mred.nc", b"O" + b"9" * 240 + b".nc", b"%00.nc", b"O0005", b"O0006.nc.bak",
    b"trailing .nc", "🔧.nc".encode(), b"\xff\xfe.mac", b"O#1.nc",
]  # fmt: skip


def odd_workspace(text: str, rnd: random.Random) -> Path:
    """A folder holding ``text`` under odd file names (not UTF-8, control characters, very long),
    with unreadable and nested folders, a pipe and links that lead nowhere or in a circle."""
    folder = Path(tempfile.mkdtemp(prefix="cncmacro-fuzz-names-"))
    raw = os.fsencode(folder)
    for name in rnd.sample(_ODD_NAMES, rnd.randint(1, 5)):
        with open(os.path.join(raw, name), "wb") as f:
            f.write(text.encode("utf-8", "surrogatepass") if rnd.random() < 0.8 else text.encode("gbk", "replace"))
    extras = rnd.sample(["closed", "listed", "deep", "pipe", "dangling", "loop", "toml"], rnd.randint(0, 3))
    if "closed" in extras or "listed" in extras:
        sub = folder / "sub"
        sub.mkdir()
        (sub / "O0100.nc").write_text("O0100\nM99\n", "utf-8")
        sub.chmod(0o000 if "closed" in extras else 0o644)
    if "deep" in extras:
        deep = folder
        for _ in range(rnd.choice([50, 300, 1100])):  # one at a time: os.makedirs recurses
            deep = deep / "d"
            deep.mkdir()
        (deep / "O0200.nc").write_text("O0200\nM99\n", "utf-8")
    if "pipe" in extras and hasattr(os, "mkfifo"):
        os.mkfifo(folder / "O1234.nc")
    if "dangling" in extras:
        (folder / "O0300.nc").symlink_to(folder / "missing.nc")
    if "loop" in extras:
        (folder / "around").symlink_to(folder)
    if "toml" in extras:
        (folder / ".cncmacro.toml").write_text(rnd.choice([
            "a=" + "{a=" * 2000 + "1" + "}" * 2000, '[calls]\n"G²"=9000\n', "base = 7\n", "\x00\x01",
            "[" + "a." * 3000 + "a]\n", 'base = "fanuc-30i"\ncommons = [[100, 499]]\n', hostile_machine_file(rnd)]),
            "utf-8")  # fmt: skip
    return folder


_HOSTILE_KEYS = [
    "[timing]\ntool_change = 1e308\n", "[timing]\nrapid = { X = 1e300 }\n", "[timing.m_codes]\nM08 = -1\n",
    "[timing]\nmax_spindle_speed = 0\n", "[variables]\n500 = 1e50\n", "[variables]\n100 = -1e308\n",
    "[variables]\n5001 = 1\n", "[limits]\nfeed = -1\n", "[limits]\ntravel = { X = [1e300, 0] }\n",
    "[limits]\ntools = [24, 1]\n", "[limits]\nspindle = 1e12\n", "max_blocks = 0\n", 'dialect = "hass"\n',
    "max_blocks = " + "9" * 5000 + "\n", '[severity]\nmacro-alrm = "off"\n', '[severity]\nmacro-alarm = "loud"\n',
    'persistent_file = "../outside.json"\n', 'persistent_file = "yarn"\n', "date = -1\n", "arc_tolerance = 1e999\n",
]  # fmt: skip


def hostile_machine_file(rnd: random.Random) -> str:
    """A machine file of a few keys a shop could get wrong or an attacker could write: values
    beyond any machine, names that name nothing, numbers of thousands of digits."""
    return "".join(rnd.sample(_HOSTILE_KEYS, rnd.randint(1, 3)))


def remove_tree(folder: Path) -> None:
    """Remove what ``odd_workspace`` made (folder modes, pipes, links, 1,100 levels of folders),
    without recursion."""
    folders, pending = [], [os.fsencode(folder)]
    while pending:
        here = pending.pop()
        os.chmod(here, 0o755)
        folders.append(here)
        with os.scandir(here) as listing:
            for entry in listing:
                if entry.is_dir(follow_symlinks=False):
                    pending.append(entry.path)
                else:
                    os.unlink(entry.path)
    for here in reversed(folders):
        os.rmdir(here)


def check_workspace(folder: Path, lsp: LspTarget) -> None:
    """``cncmacro check`` in every format and the language server's index on ``folder``: no
    exception, an exit status of 0, 1 or 2, output that is valid UTF-8 (and valid JSON where it
    is JSON), and the server still answering afterwards."""
    for fmt in ("text", "json", "sarif"):
        out, err = io.StringIO(), io.StringIO()
        status = check_paths([str(folder)], out, err, fmt, max_blocks=RUN_BUDGET)
        if status not in (0, 1, 2):
            raise InvariantError(f"check --format {fmt} exited with {status}")
        try:
            printed = out.getvalue().encode("utf-8")
            err.getvalue().encode("utf-8")
        except UnicodeEncodeError as e:
            raise InvariantError(f"check --format {fmt} printed text that is not UTF-8: {e}") from e
        if fmt != "text" and (printed or status != 2):  # 2 with nothing printed: refused, said on stderr
            try:
                json.loads(printed)
            except ValueError as e:
                raise InvariantError(f"check --format {fmt} printed invalid JSON: {e}") from e
    lsp.loop.run_until_complete(lsp.scan(folder))


def run_case(text: str, dialect: str, lsp: LspTarget, rnd: random.Random, odd: bool | None = None) -> None:
    """Every target on one case; raises on a broken invariant or an uncaught exception."""
    _FOLDER.mkdir(exist_ok=True)
    path = str(_FOLDER / "O0001.nc")
    ParsedDocument(text)
    check_analysis(text, dialect, path)
    check_run(text, dialect, path)
    check_editing(text, dialect)
    lsp.encoding = rnd.choice(ENCODINGS)
    lsp.check(text, (_FOLDER / "O0001.nc").as_uri(), positions_in(text, rnd))
    if odd if odd is not None else rnd.random() < ODD_WORKSPACES:
        folder = odd_workspace(text, rnd)
        try:
            check_workspace(folder, lsp)
        finally:
            remove_tree(folder)
