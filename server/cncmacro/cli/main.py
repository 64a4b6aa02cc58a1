"""The ``cncmacro`` command: parses the command line and hands each subcommand to its module.

Usage mistakes exit with status 2 (argparse's own convention, which docs/design.md's contract
shares).
"""

from __future__ import annotations

import argparse
import sys

from .. import __version__
from ..bilingual import is_chinese, pick
from ..dialects.registry import all_profiles
from .check import main_check
from .check_jobs import jobs_argument, shard_argument
from .locale_option import add_locale_option, environment_locale, locale_argument
from .process_end import keep_to_the_end
from .profiles import add_dialect_option, add_profiles_parser
from .run import add_run_parser
from .terminal import tolerant


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="cncmacro",
        description="Check CNC custom-macro programs before they reach a machine. Controls: "
        + "; ".join(f"{d.title} ({d.name})" for d in all_profiles())
        + " (cncmacro profiles lists them).",
    )
    parser.add_argument("--version", action="version", version=f"cncmacro {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    check = sub.add_parser(
        "check", help="report problems in program files", description="Report problems in program files."
    )
    check.add_argument("paths", nargs="+", metavar="PATH", help="program files, or folders to search for them")
    add_dialect_option(check, "over the machine file's (a file's own dialect comment still wins)")
    check.add_argument(
        "--format", choices=("text", "json", "sarif"), default="text", help="output format (default text)"
    )
    check.add_argument(
        "--path", action="append", default=[], metavar="DIR", help="another folder where called programs are looked up"
    )
    add_locale_option(check, "the messages")
    check.add_argument(
        "--max-blocks", type=int, metavar="N", help="block budget of each analysis run (default 1000000)"
    )
    check.add_argument("--machine", metavar="FILE", help="machine settings (default: the nearest .cncmacro.toml)")
    check.add_argument("--hints", action="store_true", help="also report hints (blocks no analysis run reached)")
    check.add_argument(
        "-j", "--jobs", type=jobs_argument, metavar="N",
        help="check in N processes side by side, with the same output as one (default: the number of processors)",
    )  # fmt: skip
    check.add_argument(
        "--shard", type=shard_argument, metavar="K/N",
        help="check only the Kth of N shards of the files, whole call groups each (one CI machine's part)",
    )  # fmt: skip
    check.set_defaults(handler=main_check)
    add_run_parser(sub)
    add_profiles_parser(sub)
    lsp = sub.add_parser(
        "lsp", help="language server (LSP on stdio)", description="Run the language server on stdio, or on TCP."
    )
    lsp.add_argument("--tcp", action="store_true", help="listen on TCP instead of stdio (for debugging)")
    lsp.add_argument("--host", default="127.0.0.1", help="TCP host (default 127.0.0.1)")
    lsp.add_argument("--port", type=int, default=2087, help="TCP port (default 2087)")
    lsp.set_defaults(handler=main_lsp)
    dap = sub.add_parser(
        "dap", help="debug adapter (Debug Adapter Protocol on stdio)", description="Run the debug adapter on stdio."
    )
    dap.set_defaults(handler=main_dap)
    mcp = sub.add_parser(
        "mcp",
        help="Model Context Protocol server on stdio: check, run and explain for an AI assistant",
        description="Run a Model Context Protocol server on stdio whose tools check and run programs, explain a "
        "variable or code and list the profiles; it reads only the paths it is given and writes nothing. "
        "Needs the mcp package: pip install 'cncmacro[mcp]'.",
    )
    mcp.set_defaults(handler=main_mcp)
    return parser


def main_dap(args: argparse.Namespace) -> int:
    from ..dap.session import serve

    return serve()


def main_mcp(args: argparse.Namespace) -> int:
    try:
        from .mcp_server import serve
    except ModuleNotFoundError as e:
        if (e.name or "").partition(".")[0] not in ("mcp", "mcp_types"):
            raise
        print(pick(environment_locale(),
                   "cncmacro mcp: the Model Context Protocol package is not installed in this Python: "
                   "install it with pip install 'cncmacro[mcp]'",
                   "cncmacro mcp：此 Python 中没有安装 Model Context Protocol 软件包："
                   "请用 pip install 'cncmacro[mcp]' 安装"), file=sys.stderr)  # fmt: skip
        return 2
    return serve()


def main_lsp(args: argparse.Namespace) -> int:
    from ..lsp.server import serve

    return serve(tcp=args.tcp, host=args.host, port=args.port)


def main(argv: list[str] | None = None) -> int:
    given = sys.argv[1:] if argv is None else argv
    tolerant(sys.stdout)  # a report redirected on a Chinese Windows is written in GBK
    tolerant(sys.stderr)
    try:
        args = build_parser().parse_args(argv)
    except SystemExit as e:
        if e.code == 2 and given and given[-1] == "--set":
            print(_set_hint(given), file=sys.stderr)
        raise
    args.ends_process = argv is None  # the process's own command: it ends when the command does
    try:
        return int(args.handler(args))
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        return 0
    finally:
        if args.ends_process:
            keep_to_the_end()


def _set_hint(given: list[str]) -> str:
    """What to say when ``--set`` is the last thing the command got: a shell took the ``#`` of an
    unquoted ``--set #3026=1`` for the start of a comment and dropped the rest of the line."""
    chinese = is_chinese(locale_in(given) or environment_locale())
    return pick(
        "zh-CN" if chinese else "en",
        "cncmacro run: --set got no variable: a shell reads an unquoted '#' as the start of a comment and "
        "drops the rest of the line; leave the '#' out (--set 3026=1) or quote it (--set '#3026=1')",
        "cncmacro run：--set 没有收到变量：shell 把未加引号的 '#' 当作注释开始，忽略了该行其余部分；"
        "请省略 '#'（--set 3026=1）或加引号（--set '#3026=1'）",
    )


def locale_in(given: list[str]) -> str | None:
    """The language a ``--locale`` among ``given`` asks for, if one does and it is known."""
    for i, a in enumerate(given):
        text = (
            a.partition("=")[2]
            if a.startswith("--locale=")
            else (given[i + 1] if a == "--locale" and i + 1 < len(given) else None)
        )
        if text is not None:
            try:
                return locale_argument(text)
            except argparse.ArgumentTypeError:
                return None
    return None


if __name__ == "__main__":
    sys.exit(main())
