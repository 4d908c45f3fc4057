"""The workbench: ``plans serve [DIR]``, a local web page to build, edit, solve, check and
export a mechanism without typing TOML.  The server (Starlette on uvicorn) is imported only
by this command, so every other command starts as fast as before."""

from __future__ import annotations

import argparse

from plans.errors import Said

LOOPBACK = ("127.0.0.1", "localhost", "::1")


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("serve", help="the workbench: edit, solve, check and export a mechanism in the browser")
    p.add_argument("folder", nargs="?", default=".", help="the project folder (default: the current one)")
    p.add_argument("--port", type=int, default=8765, help="the port (default 8765; 0 picks a free one)")
    p.add_argument("--host", default="127.0.0.1",
                   help="the address to listen on (default 127.0.0.1: this computer only)")
    p.add_argument("--open", action="store_true", help="open the page in the web browser")
    from plans.language import add_option

    add_option(p)
    p.set_defaults(func=_command)


def _command(args: argparse.Namespace) -> int:
    from pathlib import Path

    from plans.errors import InputError, warn

    root = Path(args.folder)
    if not root.is_dir():
        raise InputError(Said("wb_folder_folder_project", folder=args.folder), field="folder")
    if not (0 <= args.port <= 65535):
        raise InputError(Said("wb_port_out_range", port=args.port), field="--port")
    if args.host not in LOOPBACK:
        warn(Said("w_serving", host=args.host, root=str(root.resolve())))
    from .server import serve

    serve(root, host=args.host, port=args.port, open_browser=args.open)
    return 0
