"""The rules of ARCHITECTURE.md, checked on the source: who may import whom, and what each layer
may touch.

The package ``server/cncmacro`` is read statically: every module is parsed with ``ast`` (nothing
is imported or run) and every ``import`` in it is resolved, relative ones too, wherever it
stands: at the top, inside a function, or under ``if TYPE_CHECKING:``. A type-only import counts
like any other: it still ties the module to the layer it names (a type annotation that needs a
layer above is a sign the code sits in the wrong layer), and no module today needs an
exception. The same reading finds the calls that open a file (``open()``, ``os.open()``,
``io.open()``, ``.read_text()``/``.read_bytes()`` and their ``write`` twins; not ``Path.open``,
whose name is shared with too much else), ``eval``/``exec``/``compile``, DAP's
``request_seq``, a test of a locale for Chinese (``"zh"`` compared with or looked for in a
string), the classes each module defines and the Chinese text its strings hold. A module loaded
by name (``importlib.import_module`` in ``dialects/``, and ``lsp/server.py``'s ``FEATURES``) is not
seen. Each broken rule is reported
as ``server/cncmacro/<file>:<line>: what [rule] the rule``.

``LAYERS`` and ``RULES`` are the one place the rules are written for the test; ARCHITECTURE.md
states the same order and the same rule ids, and a test below holds the two together. Run as a
script (``python tests/test_architecture.py``), it prints each layer's boundary: the names the
layers above import from it.
"""

from __future__ import annotations

import ast
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "server" / "cncmacro"
CLIENT = ROOT / "client" / "src"
DOC = ROOT / "ARCHITECTURE.md"

# Bottom first. A module may import its own layer and the layers below it. A part is a
# sub-package of cncmacro (``syntax``) or a top-level module (``bilingual``; ``__init__`` is the
# package itself, which holds ``__version__``; ``__main__`` is ``python -m cncmacro``).
LAYERS: tuple[tuple[str, ...], ...] = (
    ("bilingual", "__init__"),
    ("syntax",),
    ("dialects",),
    ("library",),
    ("planner",),
    ("machine",),
    ("analysis", "debugging"),
    ("ide",),
    ("cli", "lsp", "dap"),
    ("__main__",),
)

RULES: dict[str, str] = {
    "L1": "a module imports only its own layer and the layers below it",
    "L2": "bilingual.py and the package's __init__.py import nothing of the package",
    "L3": "dialects/ imports nothing of the package but bilingual.py: a profile is data",
    "L4": "cli/, lsp/ and dap/ do not import one another; only cli/main.py starts the servers, "
          "from inside its functions",
    "L5": "third-party packages only where they belong: lark in syntax/, pygls and lsprotocol in lsp/, "
          "tomli in library/machine_file.py, mcp and mcp_types in cli/mcp_server.py; everything else is the "
          "standard library",
    "L6": "nothing in the package imports tests or benchmarks",
    "L7": "the Debug Adapter Protocol is spoken only in dap/: dap/protocol.py frames it and only "
          "dap/session.py uses that",
    "L8": "files are opened in library/files.py, which reads every program file and the machine file, "
          "and nowhere else but the places OPENS_ALLOWED names with their reasons",
    "L9": "no eval, exec or compile of Python text",
    "L10": "only bilingual.py tells whether a locale is Chinese (is_chinese, pick); no other module "
           "tests a locale for zh",
    "L11": "analysis/ and debugging/ do not import one another: each stands on machine/ by itself",
    "L12": "a public class name is defined once in the package: one name, one meaning",
    "L13": "the language server's own words are written in lsp/texts.py, in English and Chinese side by side: "
           "no other module of lsp/ holds Chinese text",
    "L14": "the editor's features answered in ide/ are only converted in lsp/: a module of lsp/ imports "
           "nothing of syntax/ but those LSP_READS_SYNTAX names (features not yet moved to ide/, and the "
           "parse the server holds), a list that only shrinks",
    "C1": "the toolpath's geometry and page, the server's start-up and the Python probe "
          "(toolpathGeometry.ts, toolpathView.ts, serverProcess.ts, pythonProbe.ts) do not import vscode",
    "C2": "the client knows no G code: no code of client/src names one or reads a number out of a "
          "move's mode; what a move is (kind, plane, legs) comes from the planner",
}  # fmt: skip

# L5: the third-party packages of pyproject.toml and the parts (or files) that may import them
THIRD_PARTY = {
    "lark": ("syntax/",),
    "pygls": ("lsp/",),
    "lsprotocol": ("lsp/",),
    "tomli": ("library/machine_file.py",),  # tomllib's twin for Python 3.10
    # the Model Context Protocol SDK (cncmacro[mcp]) and its types: only the server that speaks it
    "mcp": ("cli/mcp_server.py",),
    "mcp_types": ("cli/mcp_server.py",),
}
STDLIB = frozenset(sys.stdlib_module_names) | {"tomllib"}  # tomllib: a 3.11 name, not in 3.10's list
NOT_THE_PACKAGE = ("tests", "benchmarks", "conftest")

# L4: the imports across the front ends that are allowed, by importing file (inside a function only)
FRONT_END_STARTS = {"cli/main.py": ("cncmacro.lsp.server", "cncmacro.dap.session")}

# L7
DAP_WIRE = "cncmacro.dap.protocol"
DAP_WIRE_USERS = ("dap/session.py",)
DAP_ONLY_STRING = "request_seq"  # the key of every DAP response; JSON-RPC (the LSP) has none

# L8: files that open a file themselves, and why
OPENS_ALLOWED = {
    "library/files.py": "the one place program files and the machine file are read",
    "syntax/grammar.py": "reads its own grammar, block.lark, from the package (importlib.resources)",
    "lsp/collector.py": "reads /proc/self/statm, the server's own memory, not a file of the workspace",
    "library/persistence.py": "writes the persistent-variable file atomically (a temporary file, fsync, "
                              "rename); it reads the file through library.files.read_bytes",
    "library/persistence_lock.py": "creates and locks <file>.cncmacro-lock beside the persistent-variable file",
}  # fmt: skip
_OPEN_METHODS = {"read_text", "read_bytes", "write_text", "write_bytes"}

# L10: the one module that may test a locale for Chinese, and how a test of one is spotted: a
# string starting with "zh" compared with (==, !=, in) or passed to startswith/endswith
LOCALE_TESTER = "bilingual.py"
_ZH = re.compile(r"zh", re.I)
_STRING_TESTS = {"startswith", "endswith"}

# L13: the one module of lsp/ that may hold Chinese text, and how Chinese is spotted (a CJK ideograph)
EDITOR_TEXTS = "lsp/texts.py"
_CHINESE = re.compile(r"[\u3400-\u4dbf\u4e00-\u9fff]")

# L14: the modules of lsp/ that still import syntax/, and why. A feature moved to ide/ leaves this
# list; an entry whose module no longer imports syntax/ is reported, so that the list only shrinks.
LSP_READS_SYNTAX = {
    "lsp/code_actions.py": "the quick fixes: a feature not yet moved to ide/",
    "lsp/conditional_m99.py": "the quick fix of Haas's conditional M99: a feature not yet moved to ide/",
    "lsp/formatting.py": "formatting: a feature not yet moved to ide/",
    "lsp/hover.py": "hover: a feature not yet moved to ide/",
    "lsp/navigation.py": "definition, references and rename: a feature not yet moved to ide/",
    "lsp/semantic_tokens.py": "semantic tokens: a feature not yet moved to ide/",
    "lsp/cursor.py": "the cursor holds the block under it, for the features not yet moved",
    "lsp/documents.py": "an open document holds its parse (ParsedDocument), updated by each edit",
    "lsp/diagnostics.py": "parses a huge file's first screen before its analysis",
    "lsp/collector.py": "weighs the parser's block cache between edits",
    "lsp/server.py": "warms the parser up at start",
}  # fmt: skip

# C1
CLIENT_WITHOUT_VSCODE = ("toolpathGeometry.ts", "toolpathView.ts", "serverProcess.ts", "pythonProbe.ts")


@dataclass(frozen=True, slots=True)
class Import:
    """One imported module: ``target`` is absolute (``cncmacro.machine.calls``, ``lark``);
    ``names`` the names taken from it (empty for ``import x``)."""

    line: int
    target: str
    names: tuple[str, ...]
    in_function: bool


@dataclass(slots=True)
class Module:
    """What the checks need of one module's source."""

    name: str  # cncmacro.syntax.nodes
    path: str  # syntax/nodes.py, relative to the package
    imports: list[Import] = field(default_factory=list)
    opens: list[tuple[int, str]] = field(default_factory=list)  # (line, what) for L8
    evals: list[tuple[int, str]] = field(default_factory=list)  # (line, what) for L9
    locale_tests: list[tuple[int, str]] = field(default_factory=list)  # (line, what) for L10
    strings: dict[str, int] = field(default_factory=dict)  # string constant -> first line
    classes: list[tuple[int, str]] = field(default_factory=list)  # (line, name) for L12


def module_name(path: str) -> str:
    """``syntax/nodes.py`` -> ``cncmacro.syntax.nodes``; ``syntax/__init__.py`` -> ``cncmacro.syntax``."""
    parts = ["cncmacro", *Path(path).with_suffix("").parts]
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def part_of(name: str) -> str:
    """The part a module of the package belongs to: ``cncmacro.syntax.nodes`` -> ``syntax``,
    ``cncmacro.bilingual`` -> ``bilingual``, ``cncmacro`` -> ``__init__``."""
    pieces = name.split(".")
    return pieces[1] if len(pieces) > 1 else "__init__"


def layer_of(part: str) -> int:
    for i, parts in enumerate(LAYERS):
        if part in parts:
            return i
    raise KeyError(f"{part!r} is in no layer of LAYERS: put it in one (and in ARCHITECTURE.md)")


class _Reader(ast.NodeVisitor):
    def __init__(self, module: Module, is_package: bool, known: set[str]) -> None:
        self.m = module
        self.package = module.name if is_package else module.name.rpartition(".")[0]
        self.known = known
        self.depth = 0

    def _function(self, node: ast.AST) -> None:
        self.depth += 1
        self.generic_visit(node)
        self.depth -= 1

    visit_FunctionDef = visit_AsyncFunctionDef = visit_Lambda = _function

    def visit_Import(self, node: ast.Import) -> None:
        for alias in node.names:
            self.m.imports.append(Import(node.lineno, alias.name, (), self.depth > 0))

    def visit_ImportFrom(self, node: ast.ImportFrom) -> None:
        if node.level:
            base = self.package.split(".")
            base = base[: len(base) - (node.level - 1)]
            source = ".".join(base + ([node.module] if node.module else []))
        else:
            source = node.module or ""
        names = tuple(a.name for a in node.names)
        plain = [n for n in names if f"{source}.{n}" not in self.known]
        if plain:
            self.m.imports.append(Import(node.lineno, source, tuple(plain), self.depth > 0))
        for n in names:  # ``from . import describe``: the module itself is imported
            if f"{source}.{n}" in self.known:
                self.m.imports.append(Import(node.lineno, f"{source}.{n}", (), self.depth > 0))

    def visit_Call(self, node: ast.Call) -> None:
        f = node.func
        if isinstance(f, ast.Name) and f.id in ("eval", "exec", "compile"):
            self.m.evals.append((node.lineno, f"{f.id}()"))
        elif isinstance(f, ast.Name) and f.id == "open":
            self.m.opens.append((node.lineno, "open()"))
        elif isinstance(f, ast.Attribute):
            owner = f.value.id if isinstance(f.value, ast.Name) else None
            if owner in ("os", "io") and f.attr in ("open", "fdopen"):
                self.m.opens.append((node.lineno, f"{owner}.{f.attr}()"))
            elif f.attr in _OPEN_METHODS:
                self.m.opens.append((node.lineno, f".{f.attr}()"))
            if f.attr in _STRING_TESTS and any(_zh_constant(a) for a in node.args):
                self.m.locale_tests.append((node.lineno, f".{f.attr}() of a zh string"))
        self.generic_visit(node)

    def visit_ClassDef(self, node: ast.ClassDef) -> None:
        self.m.classes.append((node.lineno, node.name))
        self.generic_visit(node)

    def visit_Compare(self, node: ast.Compare) -> None:
        if any(_zh_constant(n) for n in (node.left, *node.comparators)):
            self.m.locale_tests.append((node.lineno, "a comparison with a zh string"))
        self.generic_visit(node)

    def visit_Constant(self, node: ast.Constant) -> None:
        if isinstance(node.value, str):
            self.m.strings.setdefault(node.value, node.lineno)


def _zh_constant(node: ast.expr) -> bool:
    """A string constant (or a tuple of them) that starts with ``zh``: a locale being tested."""
    if isinstance(node, ast.Tuple):
        return any(_zh_constant(e) for e in node.elts)
    return isinstance(node, ast.Constant) and isinstance(node.value, str) and bool(_ZH.match(node.value))


def read_package(root: Path) -> dict[str, Module]:
    """Every module under ``root`` (a directory laid out as ``server/cncmacro``), by name."""
    files = sorted(p.relative_to(root).as_posix() for p in root.rglob("*.py"))
    known = {module_name(f) for f in files}
    modules = {}
    for f in files:
        m = Module(module_name(f), f)
        tree = ast.parse((root / f).read_text(encoding="utf-8"), filename=f)
        _Reader(m, f.endswith("__init__.py"), known).visit(tree)
        modules[m.name] = m
    return modules


def _in(path: str, places: tuple[str, ...]) -> bool:
    return any(path == p or (p.endswith("/") and path.startswith(p)) for p in places)


def violations(modules: dict[str, Module]) -> list[str]:
    """Every broken rule, as ``server/cncmacro/<file>:<line>: <what> [<rule>] <rule's text>``."""
    out: list[str] = []

    def report(m: Module, line: int, what: str, rule: str) -> None:
        out.append(f"server/cncmacro/{m.path}:{line}: {what} [{rule}] {RULES[rule]}")

    for m in modules.values():
        part = part_of(m.name)
        for imp in m.imports:
            top = imp.target.split(".")[0]
            if top == "cncmacro":
                target = part_of(imp.target)
                if part in ("bilingual", "__init__"):
                    report(m, imp.line, f"imports {imp.target}", "L2")
                elif layer_of(target) > layer_of(part):
                    report(m, imp.line, f"imports {imp.target}, a layer above {part}", "L1")
                elif part == "dialects" and target not in ("dialects", "bilingual"):
                    report(m, imp.line, f"imports {imp.target}", "L3")
                elif target != part and layer_of(target) == layer_of(part) and part in ("cli", "lsp", "dap"):
                    starts = FRONT_END_STARTS.get(m.path, ())
                    if imp.target not in starts or not imp.in_function:
                        report(m, imp.line, f"imports {imp.target}", "L4")
                elif target != part and layer_of(target) == layer_of(part):
                    report(m, imp.line, f"imports {imp.target}", "L11")
                if part == "lsp" and target == "syntax" and m.path not in LSP_READS_SYNTAX:
                    report(m, imp.line, f"imports {imp.target}: ask ide/", "L14")
                if imp.target == DAP_WIRE and m.path not in DAP_WIRE_USERS:
                    report(m, imp.line, f"imports {imp.target}", "L7")
            elif top in NOT_THE_PACKAGE:
                report(m, imp.line, f"imports {imp.target}", "L6")
            elif top in THIRD_PARTY:
                if not _in(m.path, THIRD_PARTY[top]):
                    report(m, imp.line, f"imports {top}", "L5")
            elif top not in STDLIB:
                report(m, imp.line, f"imports {top}, which is neither the standard library nor allowed", "L5")
        if DAP_ONLY_STRING in m.strings and m.path != "dap/protocol.py":
            report(m, m.strings[DAP_ONLY_STRING], f"writes DAP's {DAP_ONLY_STRING!r}", "L7")
        if m.path not in OPENS_ALLOWED:
            for line, what in m.opens:
                report(m, line, f"opens a file with {what}", "L8")
        for line, what in m.evals:
            report(m, line, f"calls {what}", "L9")
        if m.path != LOCALE_TESTER:
            for line, what in m.locale_tests:
                report(m, line, f"tests a locale for Chinese with {what}", "L10")
        for line, what in _chinese_texts(m):
            report(m, line, what, "L13")
    for m, line, what in _classes_defined_again(modules):
        report(m, line, what, "L12")
    return out


def needless_syntax_allowances(modules: dict[str, Module], allowed: dict[str, str] = LSP_READS_SYNTAX) -> list[str]:
    """L14: the entries of ``allowed`` whose module is gone or no longer imports syntax/."""
    reading = {
        m.path
        for m in modules.values()
        if any(part_of(i.target) == "syntax" for i in m.imports if i.target.split(".")[0] == "cncmacro")
    }
    return [
        f"server/cncmacro/{path}: imports nothing of syntax/: take it out of LSP_READS_SYNTAX [L14] {RULES['L14']}"
        for path in sorted(allowed)
        if path not in reading
    ]


def _classes_defined_again(modules: dict[str, Module]) -> list[tuple[Module, int, str]]:
    """L12: each public class defined again after its first definition (by path), with where that is."""
    out = []
    defined: dict[str, str] = {}  # public class name -> where it is first defined
    for m in sorted(modules.values(), key=lambda m: m.path):
        for line, name in m.classes:
            if name.startswith("_"):
                continue
            if name in defined:
                out.append((m, line, f"defines class {name}, already defined in {defined[name]}"))
            else:
                defined[name] = f"{m.path}:{line}"
    return out


def _chinese_texts(m: Module) -> list[tuple[int, str]]:
    """L13: the Chinese texts of a module of lsp/ other than lsp/texts.py."""
    if not m.path.startswith("lsp/") or m.path == EDITOR_TEXTS:
        return []
    found = sorted((line, text) for text, line in m.strings.items() if _CHINESE.search(text))
    return [(line, f"holds the Chinese text {text[:30]!r}") for line, text in found]


def client_violations(client: Path) -> list[str]:
    out = []
    for name in CLIENT_WITHOUT_VSCODE:
        for n, line in enumerate((client / name).read_text(encoding="utf-8").splitlines(), 1):
            if re.search(r"""(from|require\()\s*['"]vscode['"]""", line):
                out.append(f"client/src/{name}:{n}: imports vscode [C1] {RULES['C1']}")
    return out


# C2: a G code in the client's code (not its comments, nor the texts it shows people, which are
# translated with l10n.t): a G and digits in a string, a template or a pattern, or a mode's letter
# stripped to read its number
_G_CODE = re.compile(r"""['"`/][^'"`/\n]*\bG\d|\^G|replace\(/\^G""")
_COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/|l10n\.t\('[^'\n]*'", re.S)


def client_g_codes(client: Path) -> list[str]:
    """Where the client's code names a G code (C2)."""
    out = []
    for path in sorted(client.glob("*.ts")):
        code = _COMMENT.sub(lambda m: re.sub(r"[^\n]", " ", m.group()), path.read_text(encoding="utf-8"))
        for n, text in enumerate(code.splitlines(), 1):
            if _G_CODE.search(text):
                out.append(f"client/src/{path.name}:{n}: names a G code [C2] {RULES['C2']}")
    return out


def boundaries(modules: dict[str, Module]) -> dict[str, dict[str, set[str]]]:
    """For each part, the names that other parts import from it, and which parts do."""
    out: dict[str, dict[str, set[str]]] = {}
    for m in modules.values():
        for imp in m.imports:
            if imp.target.split(".")[0] != "cncmacro" or part_of(imp.target) == part_of(m.name):
                continue
            short = imp.target.removeprefix("cncmacro.").removeprefix("cncmacro")
            for name in imp.names or ("",):
                shown = f"{short}.{name}".strip(".") if name else short
                out.setdefault(part_of(imp.target), {}).setdefault(shown, set()).add(part_of(m.name))
    return out


def layer_order_text() -> str:
    """The layer order as ARCHITECTURE.md writes it."""
    return " → ".join(" | ".join(f"`{p}`" for p in parts) for parts in LAYERS)


# ---------------------------------------------------------------------------------------- tests


def test_the_package_keeps_every_rule() -> None:
    found = violations(read_package(PACKAGE)) + client_violations(CLIENT) + client_g_codes(CLIENT)
    assert not found, "\n".join(found)


def test_the_lsp_modules_allowed_to_import_syntax_still_do() -> None:
    stale = needless_syntax_allowances(read_package(PACKAGE))
    assert not stale, "\n".join(stale)


def test_every_part_of_the_package_has_a_layer() -> None:
    parts = {part_of(name) for name in read_package(PACKAGE)}
    assert parts == {p for layer in LAYERS for p in layer}


def test_architecture_md_states_the_layers_and_rules_the_test_checks() -> None:
    text = DOC.read_text(encoding="utf-8")
    assert layer_order_text() in text, f"ARCHITECTURE.md should state the layer order as {layer_order_text()}"
    stated = set(re.findall(r"^- \*\*([A-Z]\d+)\*\*", text, re.M))
    assert stated == set(RULES), (
        f"rules in the doc only: {stated - set(RULES)}; in the test only: {set(RULES) - stated}"
    )


def modules_not_in_the_code_map(root: Path, doc: str) -> list[str]:
    """The package's modules that ARCHITECTURE.md does not name: a module is named by its path
    under ``server/cncmacro`` (`` `planner/moves.py` ``) anywhere, by its file name alone
    (`` `moves.py` ``, or a path ending in it) in its part's section (``### `planner/` ``), or,
    inside a folder below a part, by that folder written as a whole (`` `dialects/profiles/` ``:
    one module per profile)."""
    sections: dict[str, str] = {}
    for chunk in re.split(r"^### ", doc, flags=re.M)[1:]:
        for part in re.findall(r"`([a-z_]+)/`", chunk.split("\n", 1)[0]):
            sections[part] = sections.get(part, "") + chunk
    out = []
    for path in sorted(root.rglob("*.py")):
        rel = path.relative_to(root).as_posix()
        if path.name == "__init__.py" or "/" not in rel:
            continue
        part, folder = rel.split("/", 1)[0], rel.rsplit("/", 1)[0]
        named_here = re.search(rf"`(?:[\w/]*/)?{re.escape(path.name)}`", sections.get(part, ""))
        if f"`{rel}`" not in doc and not named_here and not ("/" in folder and f"`{folder}/`" in doc):
            out.append(rel)
    return out


def test_every_module_is_named_in_the_code_map() -> None:
    missing = modules_not_in_the_code_map(PACKAGE, DOC.read_text(encoding="utf-8"))
    assert not missing, f"ARCHITECTURE.md's code map names no such module: {missing}; say what each is for"


def test_a_module_missing_from_the_code_map_is_named(tmp_path: Path) -> None:
    for rel in ("planner/moves.py", "planner/new_room.py", "dialects/profiles/acme.py", "bilingual.py"):
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text("", encoding="utf-8")
    (tmp_path / "machine" / "frames.py").parent.mkdir()
    (tmp_path / "machine" / "frames.py").write_text("", encoding="utf-8")
    doc = (
        "### `planner/`\n\nthe stream (`moves.py`), one module per profile in `dialects/profiles/`\n\n"
        "### `machine/`\n\n`new_room.py` is named here, in another part's section\n"
    )
    assert modules_not_in_the_code_map(tmp_path, doc) == ["machine/frames.py", "planner/new_room.py"]


def test_the_files_architecture_md_names_exist() -> None:
    """A code map that names a file that was moved or renamed misleads the reader."""
    text = DOC.read_text(encoding="utf-8")
    bases = (ROOT, PACKAGE, CLIENT, ROOT / "tests", ROOT / "docs")
    names = {p.name for p in PACKAGE.rglob("*.py")} | {p.name for p in CLIENT.glob("*.ts")}
    missing = []
    for span in sorted(set(re.findall(r"`([\w./-]+\.(?:py|ts|md|lark|json))`", text))):
        # a path from the root, the package, client/src, tests/ or docs/; a bare name (inside
        # a layer's paragraph) names a module of the package or of the client
        if not any((b / span).exists() for b in bases) and not ("/" not in span and span in names):
            missing.append(span)
    for target in re.findall(r"\]\(([^)#\s]+)", text):
        if not target.startswith("http") and not (ROOT / target).exists():
            missing.append(target)
    assert not missing, f"ARCHITECTURE.md names files that do not exist: {missing}"


# The checker itself, on small made-up packages: it must see what breaks a rule.


def _package(tmp_path: Path, files: dict[str, str]) -> dict[str, Module]:
    for rel in ("__init__.py", "bilingual.py", *(f"{p}/__init__.py" for p in ("syntax", "machine", "dap", "lsp"))):
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text('"""stub"""\n', encoding="utf-8")
    for rel, source in files.items():
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text(source, encoding="utf-8")
    return read_package(tmp_path)


def test_a_syntax_module_that_imports_the_machine_is_reported_with_its_file_line_and_rule(tmp_path: Path) -> None:
    modules = _package(tmp_path, {
        "machine/calls.py": '"""calls"""\n',
        "syntax/nodes.py": '"""nodes"""\n\nfrom ..machine.calls import map_arguments\n',
    })  # fmt: skip
    assert violations(modules) == [
        f"server/cncmacro/syntax/nodes.py:3: imports cncmacro.machine.calls, a layer above syntax [L1] {RULES['L1']}"
    ]


def test_an_import_inside_a_function_or_for_type_checking_counts(tmp_path: Path) -> None:
    modules = _package(tmp_path, {
        "syntax/walk.py": (
            "from typing import TYPE_CHECKING\n"
            "if TYPE_CHECKING:\n"
            "    from ..machine import Machine\n"
            "def f():\n"
            "    from .. import machine\n"
        ),
    })  # fmt: skip
    assert [v.split(" [")[0] for v in violations(modules)] == [
        "server/cncmacro/syntax/walk.py:3: imports cncmacro.machine, a layer above syntax",
        "server/cncmacro/syntax/walk.py:5: imports cncmacro.machine, a layer above syntax",
    ]


def test_each_invariant_is_reported(tmp_path: Path) -> None:
    modules = _package(tmp_path, {
        "bilingual.py": "from .syntax import nodes\n",
        "machine/hover.py": "import pygls.server\nimport numpy\nfrom tests.conftest import block\n",
        "lsp/debug.py": "from ..dap import session\nx = {'request_seq': 1}\n",
        "lsp/hover.py": "def f(n):\n    return ('a', '倒角') if n else f'{n} 行'\n",
        "lsp/texts.py": "_TEXTS = {'cancel': ('Cancel', '取消')}\n",
        "dap/session.py": "import lark\nsrc = open('O1.nc').read()\neval(src)\n",
        "syntax/nodes.py": "class Call:\n    pass\n",
        "machine/calls.py": "class Call:\n    pass\nclass _Entry:\n    pass\n",
        "machine/frames.py": "class _Entry:\n    pass\n",
    })  # fmt: skip
    rules = sorted(
        (v.split(":")[0].removeprefix("server/cncmacro/"), v.split("[")[1].split("]")[0]) for v in violations(modules)
    )
    assert rules == [
        ("bilingual.py", "L2"),
        ("dap/session.py", "L5"),
        ("dap/session.py", "L8"),
        ("dap/session.py", "L9"),
        ("lsp/debug.py", "L4"),
        ("lsp/debug.py", "L7"),
        ("lsp/hover.py", "L13"),
        ("lsp/hover.py", "L13"),
        ("machine/hover.py", "L5"),
        ("machine/hover.py", "L5"),
        ("machine/hover.py", "L6"),
        ("syntax/nodes.py", "L12"),
    ]


def test_cli_main_may_start_a_server_only_from_inside_a_function(tmp_path: Path) -> None:
    inside = _package(
        tmp_path / "a", {"cli/main.py": "def main():\n    from ..lsp.server import serve\n", "lsp/server.py": ""}
    )
    at_top = _package(tmp_path / "b", {"cli/main.py": "from ..lsp.server import serve\n", "lsp/server.py": ""})
    assert violations(inside) == []
    assert [v.split(" [")[1][:2] for v in violations(at_top)] == ["L4"]


def test_a_locale_is_tested_for_chinese_only_in_bilingual(tmp_path: Path) -> None:
    modules = _package(tmp_path, {
        "bilingual.py": "def is_chinese(locale):\n    return bool(locale) and locale.lower().startswith('zh')\n",
        "lsp/texts.py": "def t(locale):\n    return locale.lower().startswith(('zh', 'ja'))\n",
        "dap/show.py": "def f(locale):\n    return 1 if locale == 'zh-CN' else 2\n",
        "machine/alarms.py": "def f(text):\n    return alarm_text(1, 'zh') + text.startswith('Z')\n",
    })  # fmt: skip
    assert sorted(v.split(" with ")[0] for v in violations(modules)) == [
        "server/cncmacro/dap/show.py:2: tests a locale for Chinese",
        "server/cncmacro/lsp/texts.py:2: tests a locale for Chinese",
    ]


@pytest.mark.parametrize("layer", ["syntax", "dialects", "library", "planner", "machine", "analysis", "debugging"])
def test_nothing_below_the_front_ends_may_import_them(tmp_path: Path, layer: str) -> None:
    modules = _package(tmp_path, {f"{layer}/x.py": "from ..lsp import server\n", "lsp/server.py": ""})
    assert [v.split(" [")[1][:2] for v in violations(modules)] == ["L1"]


def test_the_planner_imports_nothing_of_the_macro_machine(tmp_path: Path) -> None:
    modules = _package(tmp_path, {
        "planner/planner.py": "from ..machine.frames import Frame\nfrom ..dialects import Dialect\n",
        "machine/frames.py": "", "dialects/__init__.py": "",
    })  # fmt: skip
    assert [v.split(" [")[0] for v in violations(modules)] == [
        "server/cncmacro/planner/planner.py:1: imports cncmacro.machine.frames, a layer above planner"
    ]


def test_a_client_that_reads_a_g_code_is_reported(tmp_path: Path) -> None:
    (tmp_path / "geometry.ts").write_text(
        "// G02 turns clockwise: a comment may say so\n"
        "const legend = vscode.l10n.t('arc (G02/G03)');\n"
        "const n = Number(move.mode.replace(/^G/i, ''));\n"
        "if (move.mode === 'G03') ccw = true;\n"
        "const text = `${move.mode} done`;\n",
        encoding="utf-8",
    )
    assert [v.split(" [")[0] for v in client_g_codes(tmp_path)] == [
        "client/src/geometry.ts:3: names a G code",
        "client/src/geometry.ts:4: names a G code",
    ]


def test_the_analysis_and_the_debugger_do_not_import_one_another(tmp_path: Path) -> None:
    modules = _package(tmp_path, {
        "analysis/run_checks.py": "from ..debugging.history import History\n",
        "debugging/stepping.py": "from ..analysis import codes\nfrom ..machine import Machine\n",
        "analysis/codes.py": "", "debugging/history.py": "", "machine/__init__.py": "",
    })  # fmt: skip
    assert sorted(v.split(" [")[0] for v in violations(modules)) == [
        "server/cncmacro/analysis/run_checks.py:1: imports cncmacro.debugging.history",
        "server/cncmacro/debugging/stepping.py:1: imports cncmacro.analysis.codes",
    ]
    assert {v.split(" [")[1][:3] for v in violations(modules)} == {"L11"}


def test_a_public_class_name_defined_twice_is_reported_where_it_is_defined_again(tmp_path: Path) -> None:
    modules = _package(tmp_path, {
        "analysis/line_facts.py": "class CallSite:\n    pass\n",
        "analysis/call_sites.py": "from dataclasses import dataclass\n\n@dataclass\nclass CallSite:\n    pass\n",
        "machine/alarms.py": "class Alarm:\n    class _Frame:\n        pass\nclass _Frame:\n    pass\n",
    })  # fmt: skip
    assert [v.split(" [")[0] for v in violations(modules)] == [
        "server/cncmacro/analysis/line_facts.py:1: defines class CallSite, already defined in analysis/call_sites.py:4"
    ]


if __name__ == "__main__":
    found = boundaries(read_package(PACKAGE))
    for parts in LAYERS:
        for part in parts:
            print(f"{part}: used from above as")
            for name, users in sorted(found.get(part, {}).items()):
                print(f"    {name}  <- {', '.join(sorted(users))}")


def test_a_feature_moved_to_ide_that_imports_syntax_again_is_reported(tmp_path: Path) -> None:
    modules = _package(tmp_path, {
        "lsp/folding.py": "from ..ide.folding import folding_ranges\nfrom ..syntax.nodes import Block\n",
        "lsp/hover.py": "from ..syntax.walk import nodes_at\n",
        "ide/folding.py": "from ..syntax.program import Program\n",
        "syntax/nodes.py": "", "syntax/walk.py": "", "syntax/program.py": "",
    })  # fmt: skip
    assert [v.split(" [")[0] for v in violations(modules)] == [
        "server/cncmacro/lsp/folding.py:2: imports cncmacro.syntax.nodes: ask ide/"
    ]


def test_an_lsp_module_allowed_to_import_syntax_that_no_longer_does_is_reported(tmp_path: Path) -> None:
    modules = _package(tmp_path, {
        "lsp/hover.py": "from ..syntax.walk import nodes_at\n",
        "lsp/symbols.py": "from ..ide.symbols import document_symbols\n",
        "syntax/walk.py": "", "ide/symbols.py": "",
    })  # fmt: skip
    allowed = {"lsp/hover.py": "not yet moved", "lsp/symbols.py": "not yet moved", "lsp/gone.py": "deleted since"}
    assert [v.split(":")[0] for v in needless_syntax_allowances(modules, allowed)] == [
        "server/cncmacro/lsp/gone.py",
        "server/cncmacro/lsp/symbols.py",
    ]


def test_every_switch_of_a_profile_is_declared_once() -> None:
    # A dataclass takes a second declaration of a field name silently, the last type winning:
    # two switches of one name would read each other's data (Dialect.lathe_cycles was once both
    # the lathe cycles' data and their rules).
    tree = ast.parse((PACKAGE / "dialects" / "dialect.py").read_text(encoding="utf-8"))
    dialect = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "Dialect")
    names = [n.target.id for n in dialect.body if isinstance(n, ast.AnnAssign) and isinstance(n.target, ast.Name)]
    assert len(names) == len(set(names)), sorted({n for n in names if names.count(n) > 1})
