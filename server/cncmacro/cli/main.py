"""The ``cncmacro`` command: parses the command line and hands each subcommand to its module.

Usage mistakes exit with status 2 (argparse's own convention, which DESIGN.md's contract
shares).
"""

from __future__ import annotations

import argparse
import sys

from ..dialects import DIALECTS
from .check import main_check
from .run import add_run_parser


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="cncmacro",
        description="Check CNC custom-macro programs (FANUC 0i Macro B, GSK980TDi) "
        "before they reach a machine.",
    )
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    check = sub.add_parser(
        "check", help="report problems in program files", description="Report problems in program files."
    )
    check.add_argument("paths", nargs="+", metavar="PATH", help="program files, or folders to search for them")
    check.add_argument("--dialect", choices=DIALECTS, help="dialect when a file does not name one (default fanuc)")
    check.add_argument("--format", choices=("text", "json"), default="text", help="output format (default text)")
    check.add_argument(
        "--path", action="append", default=[], metavar="DIR", help="another folder where called programs are looked up"
    )
    check.set_defaults(handler=main_check)
    add_run_parser(sub)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return int(args.handler(args))
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        return 0


if __name__ == "__main__":
    sys.exit(main())
