"""The language servers the modules share: one per workspace and locale for the whole run, which each
module sees as a fresh one (``lsp_session.module_view``)."""

from collections.abc import AsyncIterator

import pytest_asyncio
from pytest_lsp import LanguageClient

from .lsp_session import CALLS, FANUC, GSK, HAAS, module_view, shared_server

fanuc_en_server = shared_server(FANUC, "en")
fanuc_zh_server = shared_server(FANUC, "zh-CN")
gsk_en_server = shared_server(GSK, "en")
gsk_zh_server = shared_server(GSK, "zh-CN")
haas_en_server = shared_server(HAAS, "en")
haas_zh_server = shared_server(HAAS, "zh-CN")
calls_en_server = shared_server(CALLS, "en")


@pytest_asyncio.fixture(scope="module", loop_scope="session")
async def fanuc_en(fanuc_en_server: LanguageClient) -> AsyncIterator[LanguageClient]:
    async for client in module_view(fanuc_en_server):
        yield client


@pytest_asyncio.fixture(scope="module", loop_scope="session")
async def fanuc_zh(fanuc_zh_server: LanguageClient) -> AsyncIterator[LanguageClient]:
    async for client in module_view(fanuc_zh_server):
        yield client


@pytest_asyncio.fixture(scope="module", loop_scope="session")
async def gsk_en(gsk_en_server: LanguageClient) -> AsyncIterator[LanguageClient]:
    async for client in module_view(gsk_en_server):
        yield client


@pytest_asyncio.fixture(scope="module", loop_scope="session")
async def gsk_zh(gsk_zh_server: LanguageClient) -> AsyncIterator[LanguageClient]:
    async for client in module_view(gsk_zh_server):
        yield client


@pytest_asyncio.fixture(scope="module", loop_scope="session")
async def haas_en(haas_en_server: LanguageClient) -> AsyncIterator[LanguageClient]:
    async for client in module_view(haas_en_server):
        yield client


@pytest_asyncio.fixture(scope="module", loop_scope="session")
async def haas_zh(haas_zh_server: LanguageClient) -> AsyncIterator[LanguageClient]:
    async for client in module_view(haas_zh_server):
        yield client


@pytest_asyncio.fixture(scope="module", loop_scope="session")
async def calls_en(calls_en_server: LanguageClient) -> AsyncIterator[LanguageClient]:
    async for client in module_view(calls_en_server):
        yield client
