"""The converters of the messages a document's opening exchanges, made while the server starts.

pygls reads each message into lsprotocol's classes and writes each reply from them with
cattrs, which writes the converting function of a message type the first time one of that type
comes or goes: one to two milliseconds each, for the ``didOpen`` read, the diagnostics sent, the
progress reported, paid by the first program the user opens (docs/benchmarks.md). The server
makes them at ``initialize`` instead (``warm_up_protocol``), for the messages an open and the
editor's first requests after it exchange; the others are made when they first come, as before.
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from typing import Any

from lsprotocol import types
from pygls.protocol import JsonRPCProtocol

log = logging.getLogger(__name__)

# what the editor sends when a program opens and right after: read, their replies written
FROM_THE_EDITOR = (
    types.TEXT_DOCUMENT_DID_OPEN,
    types.TEXT_DOCUMENT_DID_CHANGE,
    types.TEXT_DOCUMENT_DID_CLOSE,
    types.TEXT_DOCUMENT_HOVER,
    types.TEXT_DOCUMENT_CODE_LENS,
    types.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL,
    types.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL_DELTA,
    types.TEXT_DOCUMENT_DOCUMENT_SYMBOL,
    types.TEXT_DOCUMENT_FOLDING_RANGE,
    types.TEXT_DOCUMENT_INLAY_HINT,
    types.TEXT_DOCUMENT_CODE_ACTION,
)
# what the server sends meanwhile: written, the editor's replies read
TO_THE_EDITOR = (
    types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS,
    types.PROGRESS,
    types.WINDOW_WORK_DONE_PROGRESS_CREATE,
    types.WORKSPACE_CODE_LENS_REFRESH,
    types.WINDOW_LOG_MESSAGE,
)
# a progress report's value is written by the class it has when sent
PROGRESS_VALUES = (types.WorkDoneProgressBegin, types.WorkDoneProgressReport, types.WorkDoneProgressEnd)


def warm_up_protocol(protocol: JsonRPCProtocol) -> None:
    """Make the converters of the messages above (module docstring). A failure is logged and
    costs nothing else: a converter not made now is made when its message first comes."""
    converter = protocol._converter
    try:
        for method in FROM_THE_EDITOR:
            _made(converter.get_structure_hook, protocol.get_message_type(method))
            _made(converter.get_unstructure_hook, protocol.get_result_type(method))
        for method in TO_THE_EDITOR:
            _made(converter.get_unstructure_hook, protocol.get_message_type(method))
            _made(converter.get_structure_hook, protocol.get_result_type(method))
        for value in PROGRESS_VALUES:
            converter.get_unstructure_hook(value)
    except Exception:
        log.exception("making the protocol's converters at start failed")


def _made(make: Callable[[Any], object], kind: Any) -> None:
    """``make(kind)``, for a method that has such a type (a notification has no reply)."""
    if kind is not None:
        make(kind)
