"""A name that names nothing is said, never passed over in silence, through the language server:
a ``(cncmacro: dialect=hass)`` comment gets an ``unknown-profile`` warning on the comment naming
the profile the file is read in and the nearest valid name (and no profile suggestion asking for
the comment that is already there); an editor setting ``cncMacro.dialect = "klingon"`` or a
severity for a code that does not exist is shown to the person once, naming the nearest name."""

from __future__ import annotations

import asyncio

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, diagnostics_for, open_file, session_fixture

pytestmark = pytest.mark.asyncio(loop_scope="session")

wrong_settings = session_fixture(FANUC, "en", {"dialect": "hass", "severity": {"macro-alrm": "warning"}})

# M97 P100 calls the program's own N100 only on Haas: read as fanuc-0i, a suggestion would name haas
HAAS_ONLY = "O0001 (cncmacro: dialect=hass)\nM97 P100\nM30\nN100 G01 X1. F100\nM99\n"


async def test_a_dialect_comment_naming_no_profile_is_a_warning_on_the_comment(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "UNKNOWN_PROFILE.nc", HAAS_ONLY)
    params = await diagnostics_for(fanuc_en, uri, 1)
    [found] = [d for d in params.diagnostics if d.code == "unknown-profile"]
    assert found.severity == types.DiagnosticSeverity.Warning
    assert (found.range.start.line, found.range.start.character, found.range.end.character) == (
        0,
        6,
        30,
    )  # "O0001 " then 24 characters of comment
    assert "'hass' is not a profile" in found.message and "read as fanuc-0i" in found.message
    assert "did you mean 'haas'?" in found.message
    assert not [d for d in params.diagnostics if d.code == "profile-suggestion"]


async def test_an_editor_setting_naming_nothing_is_shown_once_with_the_nearest_name(
    wrong_settings: LanguageClient,
) -> None:
    for _ in range(50):  # the settings are pulled after initialized
        if len(wrong_settings.messages) >= 2:
            break
        await asyncio.sleep(0.1)
    shown = [m.message for m in wrong_settings.messages if m.type == types.MessageType.Warning]
    assert any("cncMacro.dialect: 'hass' is not a profile" in m and "Did you mean 'haas'?" in m for m in shown)
    assert any("'macro-alrm' is not a diagnostic code: did you mean 'macro-alarm'?" in m for m in shown)
    assert len(shown) == len(set(shown))  # each once, though the settings came twice (start and pull)
