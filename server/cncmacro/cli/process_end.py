"""A command that ends its process: what it holds is left to the end of the process.

``cncmacro run`` keeps a run's records until it has written them, and then the process ends.
Hundreds of thousands of small objects (a 100k-block run's moves; four times as many under
cutter radius compensation, each move with its tool centre path) would otherwise be walked by
the garbage collector after the run, and again by the interpreter's last collections at exit,
only to have the operating system free them: about 0.2 s after a 100k-block run and 0.5 s after
a compensated one (docs/benchmarks.md, "Cutter radius compensation").
"""

from __future__ import annotations

import gc


def keep_to_the_end() -> None:
    """What the process holds now stays until it ends: moved out of the garbage collector's
    reach (``gc.freeze``), so that no later collection walks it. Only for a command that ends
    its process (``main`` called without arguments: ``args.ends_process``), never for one
    called by a process that goes on, where it would keep those objects for good."""
    gc.freeze()
