"""The command line called in-process for the tests of ``cncmacro run``: ``cli(*args)`` gives the
exit status, standard output and standard error a user would see (the ``examples`` fixture, a
copy of the bundled examples to run them in, is in conftest.py)."""

from __future__ import annotations

import io
import sys

from cncmacro.cli.main import main


def cli(*args: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    old = sys.stdout, sys.stderr
    sys.stdout, sys.stderr = out, err
    try:
        code = main(list(args))
    except SystemExit as e:  # argparse usage errors
        code = int(e.code or 0)
    finally:
        sys.stdout, sys.stderr = old
    return code, out.getvalue(), err.getvalue()
