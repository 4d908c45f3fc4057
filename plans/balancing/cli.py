"""``plans balance ENGINE [--json PATH]``: polygons, resultants and counterweights of an engine."""

from __future__ import annotations

import argparse
import sys

from plans.io import atomic_write, dumps


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("balance", help="engine balancing: force and moment polygons, counterweights")
    p.add_argument("engine", help="engine file (TOML, kind = \"engine\")")
    p.add_argument("--json", metavar="PATH", help="write the results as JSON ('-' for stdout)")
    p.add_argument("--quiet", action="store_true", help="no tables on stdout")
    p.set_defaults(func=_balance)


def _balance(args: argparse.Namespace) -> int:
    from plans.balancing.analysis import balance, report
    from plans.balancing.engine import load_engine

    engine = load_engine(args.engine)
    b = balance(engine)
    data = b.to_json()
    text = report(b)
    if engine.lam > 0:
        from plans.balancing.exact import exact_check

        chk = exact_check(engine)
        data["exact_check"] = chk.to_json()
        how = "the engine as one linkage" if chk.linkages == 1 else f"{chk.linkages} linkages, one per cylinder"
        text += (f"\nexact check (kinetostatics of {how}, {len(chk.alpha)} positions): largest shaking force "
                 f"{chk.max_exact:.6g} N, harmonic truncation error {chk.max_error:.6g} N; largest shaking "
                 f"moment {chk.max_moment:.6g} N*m, truncation error {chk.max_moment_error:.6g} N*m")
    if args.json == "-":
        sys.stdout.write(dumps(data))
        return 0
    if args.json:
        atomic_write(args.json, dumps(data))
    if not args.quiet:
        print(text)
    return 0
