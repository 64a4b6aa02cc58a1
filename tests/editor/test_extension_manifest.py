"""The VS Code extension's manifest and packaging, checked without an editor: the libraries
bundled into the .vsix are pinned to exactly the versions pyproject.toml installs, every string
the manifest or the client shows has an English and a Chinese text, and the language
contribution claims the file names the checker treats as programs (README "cncmacro check")."""

from __future__ import annotations

import json
import re
from pathlib import Path

from cncmacro.library.files import PROGRAM_SUFFIXES, is_program_file

ROOT = Path(__file__).resolve().parents[2]


def _manifest() -> dict:
    return json.loads((ROOT / "package.json").read_text(encoding="utf-8"))


def _pins(lines: list[str]) -> dict[str, str]:
    out = {}
    for line in lines:
        m = re.fullmatch(r"\s*([A-Za-z0-9_.-]+)==(\S+)\s*", line.split("#")[0])
        if m:
            out[m.group(1).lower().replace("_", "-")] = m.group(2)
    return out


def test_bundled_libraries_are_pinned_to_the_versions_pyproject_installs() -> None:
    text = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    block = re.search(r"^dependencies = \[(.*?)\]", text, re.S | re.M)
    assert block is not None
    project = _pins(re.findall(r'"([^"]+)"', block.group(1)))
    bundle_lines = (ROOT / "requirements-bundle.txt").read_text(encoding="utf-8").splitlines()
    bundle = _pins(bundle_lines)
    assert project, "pyproject.toml pins its dependencies"
    for name, version in project.items():
        assert bundle.get(name) == version, f"{name}: pyproject {version}, bundle {bundle.get(name)}"
    unpinned = [x for x in bundle_lines if x.split("#")[0].strip() and "==" not in x]
    assert unpinned == []


def test_every_manifest_string_has_english_and_chinese_text() -> None:
    keys = set(re.findall(r'"%([A-Za-z0-9_.]+)%"', (ROOT / "package.json").read_text(encoding="utf-8")))
    assert {"command.runProgram", "config.dialect", "debug.program"} <= keys
    for name in ("package.nls.json", "package.nls.zh-cn.json"):
        texts = json.loads((ROOT / name).read_text(encoding="utf-8"))
        assert keys - texts.keys() == set(), name
        assert texts.keys() - keys == set(), f"{name} has texts nothing uses"


def test_every_runtime_string_of_the_client_has_a_chinese_text() -> None:
    pattern = re.compile(r"l10n\.t\(\s*(['\"])((?:\\.|(?!\1).)*)\1", re.S)
    used = set()
    for source in (ROOT / "client" / "src").glob("*.ts"):
        used |= {m.group(2).replace('\\"', '"') for m in pattern.finditer(source.read_text(encoding="utf-8"))}
    assert "Open Settings" in used
    bundle = json.loads((ROOT / "l10n" / "bundle.l10n.zh-cn.json").read_text(encoding="utf-8"))
    assert sorted(used - bundle.keys()) == []
    for english, chinese in bundle.items():
        placeholders = sorted(re.findall(r"\{\d\}", english))
        assert sorted(re.findall(r"\{\d\}", chinese)) == placeholders, english


def test_the_language_claims_the_file_names_the_checker_reads() -> None:
    language = _manifest()["contributes"]["languages"][0]
    assert language["id"] == "cnc-macro"
    assert {"CNC Macro", "FANUC Macro B", "GSK Macro"} <= set(language["aliases"])
    extensions = {e.lower() for e in language["extensions"]}
    assert extensions == set(PROGRAM_SUFFIXES)
    for pattern in language["filenamePatterns"]:
        digits = pattern.count("[0-9]")
        assert is_program_file(Path("O" + "1" * digits))
    first_line = re.compile(language["firstLine"])
    assert first_line.match("%") and first_line.match("O1234 (MAIN)") and not first_line.match("G00 X0")


def test_the_debugger_documents_every_launch_attribute_the_adapter_reads() -> None:
    debugger = _manifest()["contributes"]["debuggers"][0]
    attributes = debugger["configurationAttributes"]["launch"]["properties"]
    launch = (ROOT / "server" / "cncmacro" / "dap" / "launch.py").read_text(encoding="utf-8")
    read = set(re.findall(r'args\.get\("([A-Za-z]+)"', launch))
    assert read and read <= attributes.keys()
    assert all(a.get("description") for a in attributes.values())
    assert debugger["initialConfigurations"][0]["type"] == "cnc-macro"


def test_the_manifest_offers_exactly_the_profiles_the_server_knows() -> None:
    """The dialect setting's and the debugger's enum are the server's profile list
    (``dialects/registry.py``), in its order, with the server's default; the client itself
    learns the list from ``cncmacro/profiles``."""
    from cncmacro.dialects import DEFAULT_DIALECT, DIALECTS

    manifest = _manifest()
    setting = manifest["contributes"]["configuration"]["properties"]["cncMacro.dialect"]
    assert setting["enum"] == list(DIALECTS) and setting["default"] == DEFAULT_DIALECT
    assert len(setting["enumDescriptions"]) == len(DIALECTS)
    launch = manifest["contributes"]["debuggers"][0]["configurationAttributes"]["launch"]["properties"]
    assert launch["dialect"]["enum"] == list(DIALECTS)
    client = (ROOT / "client" / "src").glob("*.ts")
    hard_coded = [p.name for p in client if re.search(r"'gsk980tdi'|'fanuc'", p.read_text(encoding="utf-8"))]
    assert hard_coded == [], "the client names profiles itself instead of asking the server"


def _grammar_scopes() -> set[str]:
    grammar = (ROOT / "syntaxes" / "cnc-macro.tmLanguage.json").read_text(encoding="utf-8")
    return set(re.findall(r'"name": "([a-z.-]+\.cnc-macro)"', grammar))


def test_the_server_s_tokens_take_the_colours_of_the_grammar_s_scopes() -> None:
    """Each token type of the server's legend, and each variable class, is mapped to the scope
    the grammar gives the same words (``keyword`` to the ``keyword.control`` of IF, THEN, WHILE
    and GOTO), so a theme colours a word the same before and after the server's tokens arrive."""
    from cncmacro.lsp.semantic_tokens import TOKEN_MODIFIERS, TOKEN_TYPES

    contributes = _manifest()["contributes"]
    (mapping,) = contributes["semanticTokenScopes"]
    assert mapping["language"] == "cnc-macro"
    scopes: dict[str, list[str]] = mapping["scopes"]
    classes = [m for m in TOKEN_MODIFIERS if m != "readonly"]
    assert set(scopes) == set(TOKEN_TYPES) | {f"variable.{m}" for m in classes}
    grammar = _grammar_scopes()
    for selector, (scope,) in scopes.items():
        stem = scope.removesuffix(".cnc-macro")
        assert any(g == scope or g.startswith(stem + ".") for g in grammar), f"{selector}: {scope} is no grammar scope"
    assert scopes["keyword"] == ["keyword.control.cnc-macro"]  # IF THEN, WHILE DO END and GOTO in the grammar:
    assert {"keyword.control.conditional.cnc-macro", "keyword.control.loop.cnc-macro"} <= grammar
    assert "keyword.control.goto.cnc-macro" in grammar
    assert {m["id"] for m in contributes["semanticTokenModifiers"]} == set(classes)
