"""The workbench: ``plans serve [DIR]``, a local web page to build, edit, solve, check and
export a mechanism without typing TOML.  The server (Starlette on uvicorn) is imported only
by this command, so every other command starts as fast as before."""

from __future__ import annotations

import argparse
import sys

LOOPBACK = ("127.0.0.1", "localhost", "::1")


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("serve", help="the workbench: edit, solve, check and export a mechanism in the browser")
    p.add_argument("folder", nargs="?", default=".", help="the project folder (default: the current one)")
    p.add_argument("--port", type=int, default=8765, help="the port (default 8765; 0 picks a free one)")
    p.add_argument("--host", default="127.0.0.1",
                   help="the address to listen on (default 127.0.0.1: this computer only)")
    p.add_argument("--open", action="store_true", help="open the page in the web browser")
    p.set_defaults(func=_command)


def _command(args: argparse.Namespace) -> int:
    from pathlib import Path

    from plans.errors import InputError

    root = Path(args.folder)
    if not root.is_dir():
        raise InputError(f"{args.folder} is not a folder; expected the project folder", field="folder")
    if not (0 <= args.port <= 65535):
        raise InputError(f"{args.port} is out of range; expected 0..65535", field="--port")
    if args.host not in LOOPBACK:
        print(f"plans: warning: serving on {args.host}: other computers on the network can read and "
              f"write the files of {root.resolve()}", file=sys.stderr)
    from .server import serve

    serve(root, host=args.host, port=args.port, open_browser=args.open)
    return 0
