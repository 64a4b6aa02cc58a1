"""Run a command that meets file permissions as any user does, also when the tests run as root.

``python unprivileged.py PROGRAM ARG...`` executes ``PROGRAM``. Root reads every file and enters
every folder whatever its mode, so a test of a folder that cannot be entered would test nothing
there: as root on Linux, the two capabilities that allow it (``CAP_DAC_OVERRIDE``,
``CAP_DAC_READ_SEARCH``) are first dropped from the bounding set, which takes them from the
program executed. ``permissions_hold`` tells a test whether that worked here.
"""

from __future__ import annotations

import ctypes
import os
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve()
_PR_CAPBSET_DROP = 24
_CAP_DAC_OVERRIDE = 1
_CAP_DAC_READ_SEARCH = 2


def command(*args: str) -> list[str]:
    """``args`` run through this script."""
    return [sys.executable, str(HERE), *args]


def permissions_hold(shut: Path) -> bool:
    """Whether a command run through this script is refused the folder ``shut`` (mode 000)."""
    probe = command(sys.executable, "-c", f"import os; os.listdir({str(shut)!r})")
    return subprocess.run(probe, capture_output=True, timeout=60).returncode != 0


def main() -> None:
    if sys.platform.startswith("linux") and os.geteuid() == 0:
        libc = ctypes.CDLL(None, use_errno=True)
        for capability in (_CAP_DAC_OVERRIDE, _CAP_DAC_READ_SEARCH):
            libc.prctl(_PR_CAPBSET_DROP, capability, 0, 0, 0)
    os.execv(sys.argv[1], sys.argv[1:])


if __name__ == "__main__":
    main()
