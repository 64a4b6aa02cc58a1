"""The syntax layer: one line of text becomes a ``Block``; a document becomes a ``Program``.

Nothing here knows what a block does when it runs; that is the machine layer's job.
"""

from .block_parser import BlockCache, parse_block
from .nodes import Block, Problem

__all__ = ["Block", "BlockCache", "Problem", "parse_block"]
