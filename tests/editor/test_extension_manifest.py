"""The VS Code extension's manifest and packaging, checked without an editor: the libraries
bundled into the .vsix are pinned to exactly the versions pyproject.toml installs, every string
the manifest or the client shows has an English and a Chinese text, the language contribution
claims the file names the checker treats as programs (docs/cli.md "cncmacro check"), and the
extension's page is whole: license, icon, changelog of this version, where the project lives,
and the README's pictures, all inside the .vsix."""

from __future__ import annotations

import json
import re
import sys
from fnmatch import fnmatch
from pathlib import Path

import pytest

if sys.version_info >= (3, 11):
    import tomllib
else:
    import tomli as tomllib

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
    dependencies = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]["dependencies"]
    project = _pins([d.split(";")[0] for d in dependencies])  # with or without a Python marker
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


# First lines of files: programs as controls and DNC folders keep them, and ordinary text
FIRST_LINES = [
    "%", "% ", "O1234", "O0810 (DRILL)", "o0040", "O1234(MAIN)", "  O9100", "<CUT-1.NC>", "(PART 12) O0100",
    "O123456789", "G00 X0", "%PDF-1.4", "% of the parts", "O1st operation", "O12.5", "Setup notes for O1000",
    "README", "<html>", "<?xml version='1.0'?>", "(A COMMENT ALONE)", "", "O",
]  # fmt: skip


def test_a_txt_file_opens_as_a_program_exactly_when_its_first_line_starts_one(tmp_path: Path) -> None:
    """The manifest's ``firstLine`` (which VS Code reads for files of no known ending, and the
    client for plain-text ``.txt`` files) takes a first line exactly when the server's rule of
    which files are programs (``files.starts_like_program``) takes a file of that one line."""
    first_line = re.compile(_manifest()["contributes"]["languages"][0]["firstLine"])
    taken = []
    for k, line in enumerate(FIRST_LINES):
        path = tmp_path / f"{k}.txt"
        path.write_text(line + "\n", encoding="utf-8")
        assert bool(first_line.match(line)) == is_program_file(path), line
        taken += [line] if first_line.match(line) else []
    assert taken == ["%", "% ", "O1234", "O0810 (DRILL)", "o0040", "O1234(MAIN)", "  O9100", "<CUT-1.NC>",
                     "(PART 12) O0100", "O123456789"]  # fmt: skip


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


def _png_size(path: Path) -> tuple[int, int]:
    """The width and height in a PNG's header; fails on a file that is not a PNG."""
    head = path.read_bytes()[:24]
    assert head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR", f"{path.name} is not a PNG"
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


def _shipped(path: str) -> bool:
    """Whether .vscodeignore lets ``path`` into the .vsix: its last matching rule is a ``!`` one."""
    kept = True
    for rule in (ROOT / ".vscodeignore").read_text(encoding="utf-8").splitlines():
        rule = rule.strip()
        if not rule or rule.startswith("#"):
            continue
        negated = rule.startswith("!")
        if fnmatch(path, rule.lstrip("!")):
            kept = negated
    return kept


def _pyproject_version() -> str:
    found = re.search(r'^version = "([^"]+)"', (ROOT / "pyproject.toml").read_text(encoding="utf-8"), re.M)
    assert found is not None
    return found.group(1)


def test_the_extension_is_mit_licensed_and_ships_its_license() -> None:
    manifest = _manifest()
    assert manifest["license"] == "MIT"
    text = (ROOT / "LICENSE").read_text(encoding="utf-8")
    assert text.startswith("MIT License") and "Copyright (c) 2026 cncmacro contributors" in text
    assert "--skip-license" not in manifest["scripts"]["package"]
    assert _shipped("LICENSE")


def test_the_icon_is_a_128_pixel_png_that_the_vsix_carries() -> None:
    icon = _manifest()["icon"]
    assert _png_size(ROOT / icon) == (128, 128)
    assert _shipped(icon)


def test_the_changelog_describes_the_version_of_the_manifest_and_the_package() -> None:
    version = _manifest()["version"]
    assert version == _pyproject_version()
    changelog = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    assert re.search(rf"^## \[?{re.escape(version)}\]?\b", changelog, re.M), f"CHANGELOG.md has no {version}"
    assert _shipped("CHANGELOG.md")


def test_the_manifest_says_where_the_project_lives_and_how_to_find_it() -> None:
    manifest = _manifest()
    assert manifest["repository"] == {"type": "git", "url": "https://github.com/cncmacro/cncmacro.git"}
    assert manifest["homepage"].startswith("https://github.com/cncmacro/cncmacro")
    assert manifest["bugs"]["url"] == "https://github.com/cncmacro/cncmacro/issues"
    assert {"Programming Languages", "Linters", "Debuggers"} <= set(manifest["categories"])
    keywords = set(manifest["keywords"])
    assert {"cnc", "gcode", "fanuc", "30i", "gsk980tdi", "数控", "宏程序"} <= keywords
    assert len(manifest["keywords"]) <= 30, "the Marketplace takes at most 30 keywords"
    assert "--allow-missing-repository" not in manifest["scripts"]["package"]


def test_every_picture_of_the_readme_exists_and_goes_into_the_vsix_readme() -> None:
    # the .vsix carries client/scripts/vsix-readme.mjs's README, each picture inlined in it (VS
    # Code's extension page shows pictures from https: or data: only); make test's release check
    # and tests/editor/extension_page.test.mjs look at the built package and its page
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    pictures = re.findall(r"!\[[^\]]*\]\(([^)\s]+)\)", readme)
    names = {"problems.png", "hover-5001.png", "debug-g65.png", "toolpath.png"}
    assert {f"docs/images/{name}" for name in names} <= set(pictures)
    for picture in pictures:
        assert not picture.startswith(("/", "http:")), f"{picture}: a relative link or https"
        if picture.startswith("https:"):
            continue
        width, height = _png_size(ROOT / picture)
        assert width > 0 and height > 0
    package = json.loads((ROOT / "package.json").read_text(encoding="utf-8"))["scripts"]["package"]
    assert "node client/scripts/vsix-readme.mjs && vsce package" in package
    assert "--readme-path .cache/vsix/README.md" in package


def test_the_pages_variables_stay_variables_in_the_vsix() -> None:
    """The README and the changelog are full of macro variables (``#5001``, ``#24 (X)``); the
    packager would link each ``#number`` to a GitHub issue of that number, inside code too."""
    assert re.search(r"#\d+", (ROOT / "README.md").read_text(encoding="utf-8"))
    assert "--no-gitHubIssueLinking" in _manifest()["scripts"]["package"]


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


def test_the_mcp_server_the_client_offers_is_declared_and_wakes_the_extension() -> None:
    """VS Code starts an extension's MCP servers only for a provider id the manifest declares,
    and asks for them through the activation event of that id (docs/cli.md, ``cncmacro mcp``)."""
    source = (ROOT / "client" / "src" / "mcpServer.ts").read_text(encoding="utf-8")
    (provider_id,) = re.findall(r"export const MCP_PROVIDER_ID = '([^']+)'", source)
    manifest = _manifest()
    assert [p["id"] for p in manifest["contributes"]["mcpServerDefinitionProviders"]] == [provider_id]
    assert f"onMcpCollection:{provider_id}" in manifest["activationEvents"]
    assert "['-m', 'cncmacro', 'mcp']" in source and "cncmacroCommand(python, ['mcp'])" in source


EDITOR_PRODUCT = ROOT / "tests" / "node_modules" / "code-server" / "lib" / "vscode" / "product.json"


@pytest.mark.skipif(not EDITOR_PRODUCT.exists(), reason="the editor tests' VS Code is installed by make setup")
def test_the_oldest_vs_code_the_extension_accepts_is_the_one_the_editor_tests_run() -> None:
    # an engines floor below the tested editor would promise editors nothing has tried
    manifest = _manifest()
    floor = manifest["engines"]["vscode"].lstrip("^")
    tested = json.loads(EDITOR_PRODUCT.read_text(encoding="utf-8"))["version"]
    assert floor.split(".")[:2] == tested.split(".")[:2], f"engines ^{floor}, the editor tests run VS Code {tested}"
    assert manifest["devDependencies"]["@types/vscode"] == floor  # the API the client compiles against
