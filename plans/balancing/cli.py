"""``plans balance ENGINE [--json PATH]``: polygons, resultants and counterweights of an engine."""

from __future__ import annotations

import argparse

from plans.io import dumps, json_out
from plans.language import file_command


def register(sub: argparse._SubParsersAction) -> None:
    p = file_command(sub, "balance", "engine balancing: force and moment polygons, counterweights", "engine",
                     "engine file (TOML, kind = \"engine\")", "write the results as JSON ('-' for stdout)",
                     "no tables on stdout")
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
    if json_out(args.json, dumps(data)):
        return 0
    if not args.quiet:
        print(text)
    return 0
