"""The motion planner: NC blocks in, the one stream of moves out (ARCHITECTURE.md, ``planner/``).

The macro machine (``machine/``) hands it each NC block with its words evaluated; it keeps the
modal NC state, offsets, cycles and the time model, and records every move as a ``Move``
(``planner/moves.py``) that the front ends read.
"""
