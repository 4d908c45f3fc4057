"""The benchmark's report in Markdown (``bench.md``): summary, ratios, goals, hand drawing, stability."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from plans.accuracy.oracles import Record

if TYPE_CHECKING:  # mpmath is an optional dependency (the ``bench`` extra): imported where used
    pass

# --------------------------------------------------------------------------- report


def fmt(x: float | None, unit: str = "") -> str:
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "–"
    if unit == "s":
        for u, f in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6), ("ns", 1e-9)):
            if x >= f or u == "ns":
                return f"{x / f:.3g} {u}"
    return f"{x:.2e}"


#: The mechanisms the summary and the full table show (every other sample: its own short table).
MAIN_SCENES = ("slider-crank (offset)", "four-bar", "v_engine")


def summary_table(records: list[Record]) -> str:
    """One line per method on the reference mechanisms at 360 positions (Markdown)."""
    lines = ["| method | mechanism | positions | param | error (max rel.) | time | per position |",
             "|---|---|---:|---|---:|---:|---:|"]
    for r in records:
        if r.scene not in MAIN_SCENES:
            continue
        if r.method in ("exact", "construction", "newton", "forces exact") and r.positions in (1, 360) or \
           r.method == "finite differences" and r.param in ("h=1e-02 deg", "h=1e-03 deg") or \
           r.method == "newton tol sweep" and r.positions == 12 and r.param in ("tol=1e-02", "tol=1e-06",
                                                                                "tol=1e-14"):
            err = "(oracle)" if r.note == "is the oracle" else fmt(r.error)
            lines.append(f"| {r.method} | {r.scene} | {r.positions} | {r.param} | {err} | "
                         f"{fmt(r.time, 's')} | {fmt(r.time_per_position, 's')} |")
    return "\n".join(lines)


def ratio_table(records: list[Record]) -> str:
    """Time per position of each method over the exact analysis's, same mechanism and number of
    positions, same run (Markdown)."""
    exact = {(r.scene, r.positions): r.time_per_position for r in records if r.method == "exact"}
    rows: dict[tuple[str, int], dict[str, float]] = {}
    for r in records:
        key = (r.scene, r.positions)
        if r.scene not in MAIN_SCENES or key not in exact or not math.isfinite(r.time_per_position):
            continue
        if r.method in ("construction", "newton", "forces exact", "force polygons"):
            rows.setdefault(key, {})[r.method] = r.time_per_position / exact[key]
        elif r.method == "finite differences" and r.param == "h=1e-03 deg":
            rows.setdefault(key, {})[r.method] = r.time_per_position / exact[key]
    cols = ["construction", "newton", "finite differences", "forces exact", "force polygons"]
    lines = ["| mechanism | positions | exact per position | " + " | ".join(f"{c} / exact" for c in cols) + " |",
             "|---|---:|---:|" + "---:|" * len(cols)]
    for (scene, n), d in sorted(rows.items(), key=lambda kv: (kv[0][0], kv[0][1])):
        cells = " | ".join(f"{d[c]:.3g}×" if c in d else "–" for c in cols)
        lines.append(f"| {scene} | {n} | {fmt(exact[(scene, n)], 's')} | {cells} |")
    return "\n".join(lines)


def markdown(result: dict[str, Any]) -> str:
    recs = [Record.from_json(r) for r in result["records"]]
    m = result["meta"]
    out = [f"# plans bench{' --quick' if m['quick'] else ''}", "",
           f"Python {m['python']}, numpy {m['numpy']}, shapely {m['shapely']}, {m['machine']}, "
           f"OPENBLAS_NUM_THREADS={m.get('OPENBLAS_NUM_THREADS') or 'unset'}; total {m['wall_s']:.1f} s.", "",
           "Error: largest over positions and quantities of |x − x_ref| / (size of the known vector "
           "of that kind: l1, ω1·l1, ω1²·l1, ω1, ω1²); reference: mpmath at 50 digits for the "
           "slider-crank and the four-bar, the exact analysis elsewhere.", "",
           "## Summary", "", summary_table(recs), "",
           "## Cost relative to the exact analysis (same run)", "",
           "Time per position over the exact analysis's time per position at the same number of "
           "positions (the exact analysis is vectorised over positions, the construction and the "
           "polygons are built position by position, Newton continues from position to position).", "",
           ratio_table(recs), ""]
    out += goals_section(result.get("goals", []))
    out += ["## All methods by number of positions", "",
            "| method | mechanism | positions | param | error | time | per position | cond | note |",
            "|---|---|---:|---|---:|---:|---:|---:|---|"]
    for r in recs:
        if r.scene not in MAIN_SCENES:
            continue
        out.append(f"| {r.method} | {r.scene} | {r.positions} | {r.param} | {fmt(r.error)} | "
                   f"{fmt(r.time, 's')} | {fmt(r.time_per_position, 's')} | {fmt(r.cond)} | {r.note} |")
    others = [r for r in recs if r.scene not in MAIN_SCENES and not r.scene.startswith("chain")
              and r.scene != "-" and r.positions == max((rr.positions for rr in recs if rr.scene == r.scene
                                                          and rr.method == "construction"), default=-1)
              and r.method in ("construction", "newton", "forces exact")]
    if others:
        out += ["", "## Other samples (against the exact analysis)", "",
                "| method | sample | positions | error | per position | cond |", "|---|---|---:|---:|---:|---:|"]
        out += [f"| {r.method} | {r.scene} | {r.positions} | {fmt(r.error)} | {fmt(r.time_per_position, 's')} | "
                f"{fmt(r.cond)} |" for r in others]
    if result.get("performance"):
        from plans.accuracy import speed

        out += ["", "## Speed goals and open peers", "",
                "Each goal measured in this run, side by side with what it is compared to; ratio: "
                "measured over the goal's bound (at most 1 when met).", "",
                speed.markdown(result["performance"])]
    out += ["", "## Cost against mechanism size (chain of N RRR dyads)", "",
            "| N | exact, per position (360) | construction, 1 position | Newton, per position (12) | "
            "Newton error | construction error | Newton cond |", "|---:|---:|---:|---:|---:|---:|---:|"]
    by_n: dict[int, dict[str, Record]] = {}
    for r in recs:
        if r.scene.startswith("chain"):
            by_n.setdefault(r.dyads, {})[r.method] = r
    for n in sorted(by_n):
        d = by_n[n]
        out.append(f"| {n} | {fmt(d['exact'].time_per_position, 's')} | {fmt(d['construction'].time, 's')} | "
                   f"{fmt(d['newton'].time_per_position, 's')} | {fmt(d['newton'].error)} | "
                   f"{fmt(d['construction'].error)} | {fmt(d['newton'].cond)} |")
    out += hand_drawing_section(result.get("draftsman", {}))
    st = result.get("stability", [])
    if st:
        out += ["## Stability", "", "| case | exact | construction | newton | Newton cond | error raised |",
                "|---|---:|---:|---:|---:|---|"]
        for row in st:
            out.append(f"| {row['case']} | {fmt(row.get('exact'))} | {fmt(row.get('construction'))} | "
                       f"{fmt(row.get('newton'))} | {fmt(row.get('cond'))} | {row.get('error', '')} |")
    sl = result.get("stiff_loads", [])
    if sl:
        out += ["", "## Stiff loads (V-engine, 72 positions)", "",
                "Balancing load by the Zhukovsky lever and by the power balance against kinetostatics, "
                "relative to the largest |F_bal| of the cycle.", "",
                "| case | lever | power | error raised |", "|---|---:|---:|---|"]
        for row in sl:
            out.append(f"| {row['case']} | {fmt(row.get('lever'))} | {fmt(row.get('power'))} | "
                       f"{row.get('error', '')} |")
    if result.get("warnings"):
        out += ["", "## Warnings", ""] + [f"- {w}" for w in result["warnings"]]
    out += ["", "![error against run time](bench.svg)", ""]
    return "\n".join(out)


def _qorder(q: str) -> tuple[int, str]:
    return ({"v": 0, "o": 1, "a": 2, "e": 3}.get(q[0], 4), q)



def goal_line(g: dict[str, Any], lang: str = "en") -> str:
    """``goal: <what> ≤ 300 µs: 212 µs, met`` (a time) or ``≥ 20×: 31×, met`` (a speed-up);
    the frame of the line in ``lang`` (the goal's own name as the bench names it)."""
    if g["unit"] == "s":
        want, got = f"≤ {fmt(g['limit'], 's')}", fmt(g["value"], "s")
    elif g["unit"] == "× cost":
        want, got = f"≤ {g['limit']:g}×", f"{g['value']:.2f}×"
    else:
        want, got = f"≥ {g['limit']:g}×", f"{g['value']:.1f}×"
    if lang != "en":
        from plans.phrases import say

        return say("bn_goal", lang, goal=g["goal"], want=want, got=got, state=say("bn_met" if g["met"] else "bn_not_met", lang))
    return f"goal: {g['goal']} {want}: {got}, {'met' if g['met'] else 'not met'}"


def goals_section(goals: list[dict[str, Any]]) -> list[str]:
    """The performance goals, each with what this run measured, and where the time goes
    for a goal not met."""
    if not goals:
        return []
    out = ["## Performance goals", "", "| goal | limit | measured | met |", "|---|---:|---:|---|"]
    for g in goals:
        if g["unit"] == "s":
            out.append(f"| {g['goal']} | ≤ {fmt(g['limit'], 's')} | {fmt(g['value'], 's')} | "
                       f"{'yes' if g['met'] else 'no'} |")
        elif g["unit"] == "× cost":
            out.append(f"| {g['goal']} | ≤ {g['limit']:g}× | {g['value']:.2f}× | {'yes' if g['met'] else 'no'} |")
        else:
            out.append(f"| {g['goal']} | ≥ {g['limit']:g}× | {g['value']:.1f}× | {'yes' if g['met'] else 'no'} |")
    out.append("")
    for g in goals:
        if "together_s" in g:
            out += [f"Built together: {fmt(g['together_s'], 's')} for 360 positions; one position at a time: "
                    f"{fmt(g['one_by_one_s'], 's')}; the readings of the two differ by at most "
                    f"{g['readings_apart']:.1e} of the plan.", ""]
    for g in goals:
        if "profile" in g:
            out += [f"Where the time goes ({g['goal']}, own time per run):", "",
                    "| function | calls | own µs | cum µs |", "|---|---:|---:|---:|"]
            out += [f"| `{p['function']}` | {p['calls_per_run']:.0f} | {p['own_us_per_run']:.1f} | "
                    f"{p['cum_us_per_run']:.1f} |" for p in g["profile"]]
            out.append("")
    return out


def hand_drawing_section(dm: dict[str, Any]) -> list[str]:
    """The Monte Carlo's 95th percentiles per reading, sheet by sheet."""
    if not dm:
        return []
    out: list[str] = []
    out += ["", "## Hand drawing (Monte Carlo)", "",
            f"Pencil ±{dm['model']['pencil_mm']} mm, protractor ±{dm['model']['protractor_deg']}°, "
            f"{dm['samples']} drawings per sheet; the 95th percentile of each reading's error.", ""]
    for sc_name, sheets in dm["scenes"].items():
        names = sorted(next(iter(sheets.values())).keys(), key=_qorder)
        heads = list(sheets)
        out += [f"### {sc_name}, φ = {dm['phi_deg']}°", "",
                "| quantity | exact | " + " | ".join(f"{h}: p95 rel. | {h}: p95 abs. | {h}: p95 mm"
                                                    for h in heads) + " |",
                "|---|---:|" + "---:|---:|---:|" * len(heads)]
        for q in names:
            e0 = sheets[heads[0]][q]
            cells = " | ".join(f"{sheets[h][q]['p95_rel'] * 100:.2f} % | {sheets[h][q]['p95_abs']:.3g} "
                               f"{sheets[h][q]['unit']} | {sheets[h][q]['p95_mm']:.2f}" for h in heads)
            out.append(f"| {q} | {e0['exact']:.5g} {e0['unit']} | {cells} |")
        out.append("")
    return out
