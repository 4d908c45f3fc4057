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
    from plans.language import add_option

    add_option(p)
    p.set_defaults(func=_balance)


def _balance(args: argparse.Namespace) -> int:
    from plans.balancing.analysis import report
    from plans.balancing.solution import solve_engine
    from plans.language import file_language
    from plans.phrases import say

    es = solve_engine(args.engine)
    b = es.balance
    lang = file_language(getattr(args, "language", None), args.engine)
    data = b.to_json(lang)
    text = report(b, lang)
    chk = es.exact
    if chk is not None:
        data["exact_check"] = chk.to_json()
        how = say("b_one_linkage", lang) if chk.linkages == 1 else say("b_linkages", lang, n=chk.linkages)
        text += say("b_exact", lang, how=how, n=len(chk.alpha), f=chk.max_exact, fe=chk.max_error, m=chk.max_moment,
                    me=chk.max_moment_error)
    if args.json == "-":
        sys.stdout.write(dumps(data))
        return 0
    if args.json:
        atomic_write(args.json, dumps(data))
    if not args.quiet:
        print(text)
    return 0
