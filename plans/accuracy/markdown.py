"""The benchmark's report in Markdown (``bench.md``): summary, ratios, goals, hand drawing, stability."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from plans.accuracy.oracles import Record
from plans.messages_bench import words
from plans.phrases import Phrase, number, phrase, say

if TYPE_CHECKING:  # mpmath is an optional dependency (the ``bench`` extra): imported where used
    pass

# --------------------------------------------------------------------------- report


def fmt(x: float | None, unit: str = "", lang: str = "en") -> str:
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "–"
    if unit == "s":
        for u, f in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6), ("ns", 1e-9)):
            if x >= f or u == "ns":
                return say("bu_3g", lang, v=x / f, unit=u)
    return number(x, ".2e", lang)


def _head(key: str, align: str, lang: str, **values: Any) -> list[str]:
    """A Markdown table's head: its cells (the catalogue's, joined by " | ") and alignments."""
    return ["| " + say(key, lang, **values) + " |", "|" + "|".join(align.split()) + "|"]


#: The mechanisms the summary and the full table show (every other sample: its own short table).
MAIN_SCENES = ("slider-crank (offset)", "four-bar", "v_engine")


def summary_table(records: list[Record], lang: str = "en") -> str:
    """One line per method on the reference mechanisms at 360 positions (Markdown)."""
    lines = _head("bh_summary", "--- --- ---: --- ---: ---: ---:", lang)
    for r in records:
        if r.scene not in MAIN_SCENES:
            continue
        if r.method in ("exact", "construction", "newton", "forces exact") and r.positions in (1, 360) or \
           r.method == "finite differences" and r.param in ("h=1e-02 deg", "h=1e-03 deg") or \
           r.method == "newton tol sweep" and r.positions == 12 and r.param in ("tol=1e-02", "tol=1e-06",
                                                                                "tol=1e-14"):
            err = say("bc_oracle", lang) if r.note == "is the oracle" else fmt(r.error, "", lang)
            lines.append(f"| {words(r.method, lang)} | {words(r.scene, lang)} | {r.positions} | "
                         f"{words(r.param, lang)} | {err} | {fmt(r.time, 's', lang)} | "
                         f"{fmt(r.time_per_position, 's', lang)} |")
    return "\n".join(lines)


def ratio_table(records: list[Record], lang: str = "en") -> str:
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
    lines = ["| " + say("bh_ratio", lang) + " | "
             + " | ".join(say("bh_over_exact", lang, method=words(c, lang)) for c in cols) + " |",
             "|---|---:|---:|" + "---:|" * len(cols)]
    for (scene, n), d in sorted(rows.items(), key=lambda kv: (kv[0][0], kv[0][1])):
        cells = " | ".join(number(d[c], ".3g", lang) + "×" if c in d else "–" for c in cols)
        lines.append(f"| {words(scene, lang)} | {n} | {fmt(exact[(scene, n)], 's', lang)} | {cells} |")
    return "\n".join(lines)


def markdown(result: dict[str, Any], lang: str = "en") -> str:
    """The report in ``lang``; the words of the records and the goals' phrases in it too (a
    result read back from bench.json has the goals' English alone)."""
    recs = [Record.from_json(r) for r in result["records"]]
    m = result["meta"]
    machine = m["machine"]
    if lang != "en" and machine.endswith(" CPUs"):  # "x86_64, 2 CPUs", as the run wrote it
        head, _, n = machine[:-5].rpartition(", ")
        machine = say("br_cpus", lang, machine=head, n=n)
    out = [say("br_title", lang, quick=" --quick" if m["quick"] else ""), "",
           say("br_meta", lang, python=m["python"], numpy=m["numpy"], shapely=m["shapely"], machine=machine,
               threads=m.get("OPENBLAS_NUM_THREADS") or say("br_unset", lang), wall=m["wall_s"]), "",
           say("br_error", lang), "",
           say("br_summary", lang), "", summary_table(recs, lang), "",
           say("br_cost", lang), "", say("br_cost_text", lang), "",
           ratio_table(recs, lang), ""]
    out += goals_section(result.get("goals", []), lang)
    out += [say("br_all", lang), "", *_head("bh_all", "--- --- ---: --- ---: ---: ---: ---: ---", lang)]
    for r in recs:
        if r.scene not in MAIN_SCENES:
            continue
        out.append(f"| {words(r.method, lang)} | {words(r.scene, lang)} | {r.positions} | {words(r.param, lang)} | "
                   f"{fmt(r.error, '', lang)} | {fmt(r.time, 's', lang)} | {fmt(r.time_per_position, 's', lang)} | "
                   f"{fmt(r.cond, '', lang)} | {words(r.note, lang)} |")
    others = [r for r in recs if r.scene not in MAIN_SCENES and not r.scene.startswith("chain")
              and r.scene != "-" and r.positions == max((rr.positions for rr in recs if rr.scene == r.scene
                                                          and rr.method == "construction"), default=-1)
              and r.method in ("construction", "newton", "forces exact")]
    if others:
        out += ["", say("br_others", lang), "", *_head("bh_others", "--- --- ---: ---: ---: ---:", lang)]
        out += [f"| {words(r.method, lang)} | {r.scene} | {r.positions} | {fmt(r.error, '', lang)} | "
                f"{fmt(r.time_per_position, 's', lang)} | {fmt(r.cond, '', lang)} |" for r in others]
    if result.get("performance"):
        from plans.accuracy import speed

        out += ["", say("br_speed", lang), "", say("br_speed_text", lang), "",
                speed.markdown(result["performance"], lang)]
    out += ["", say("br_chain", lang), "", *_head("bh_chain", "---: ---: ---: ---: ---: ---: ---:", lang)]
    by_n: dict[int, dict[str, Record]] = {}
    for r in recs:
        if r.scene.startswith("chain"):
            by_n.setdefault(r.dyads, {})[r.method] = r
    for n in sorted(by_n):
        d = by_n[n]
        out.append(f"| {n} | {fmt(d['exact'].time_per_position, 's', lang)} | {fmt(d['construction'].time, 's', lang)} | "
                   f"{fmt(d['newton'].time_per_position, 's', lang)} | {fmt(d['newton'].error, '', lang)} | "
                   f"{fmt(d['construction'].error, '', lang)} | {fmt(d['newton'].cond, '', lang)} |")
    out += hand_drawing_section(result.get("draftsman", {}), lang)
    st = result.get("stability", [])
    if st:
        out += [say("br_stability", lang), "", *_head("bh_stability", "--- ---: ---: ---: ---: ---", lang)]
        for row in st:
            out.append(f"| {words(row['case'], lang)} | {fmt(row.get('exact'), '', lang)} | "
                       f"{fmt(row.get('construction'), '', lang)} | {fmt(row.get('newton'), '', lang)} | "
                       f"{fmt(row.get('cond'), '', lang)} | {words(row.get('error', ''), lang)} |")
    sl = result.get("stiff_loads", [])
    if sl:
        out += ["", say("br_stiff", lang), "", say("br_stiff_text", lang), "",
                *_head("bh_stiff", "--- ---: ---: ---", lang)]
        for row in sl:
            out.append(f"| {words(row['case'], lang)} | {fmt(row.get('lever'), '', lang)} | "
                       f"{fmt(row.get('power'), '', lang)} | {words(row.get('error', ''), lang)} |")
    if result.get("warnings"):
        out += ["", say("br_warnings", lang), ""] + [f"- {words(w, lang)}" for w in result["warnings"]]
    out += ["", say("br_plot", lang), ""]
    return "\n".join(out)


def _qorder(q: str) -> tuple[int, str]:
    return ({"v": 0, "o": 1, "a": 2, "e": 3}.get(q[0], 4), q)



def goal_said(g: dict[str, Any]) -> Phrase | str:
    """A goal of :data:`plans.accuracy.vengine_goals.GOALS` or the synthesis's as the phrase
    of its key (bench.json keeps the English), else as the goal is written."""
    from plans.messages_bench import BENCH

    key = "bq_" + str(g.get("key"))
    return phrase(key) if key in BENCH else g["goal"]


def goal_name(g: dict[str, Any], lang: str) -> str:
    """A goal's name in ``lang``."""
    return words(goal_said(g), lang)


def _want_got(g: dict[str, Any], lang: str) -> tuple[str, str]:
    """A goal's bound and what was measured: a time (≤ 300 µs: 212 µs), a cost (≤ 5×: 4.27×)
    or a speed-up (≥ 20×: 31×)."""
    if g["unit"] == "s":
        return f"≤ {fmt(g['limit'], 's', lang)}", fmt(g["value"], "s", lang)
    if g["unit"] == "× cost":
        return f"≤ {number(g['limit'], 'g', lang)}×", f"{number(g['value'], '.2f', lang)}×"
    return f"≥ {number(g['limit'], 'g', lang)}×", f"{number(g['value'], '.1f', lang)}×"


def goal_line(g: dict[str, Any], lang: str = "en") -> str:
    """``goal: <what> ≤ 300 µs: 212 µs, met`` in ``lang``."""
    want, got = _want_got(g, lang)
    return say("bn_goal", lang, goal=goal_name(g, lang), want=want, got=got,
               state=say("bn_met" if g["met"] else "bn_not_met", lang))


def goals_section(goals: list[dict[str, Any]], lang: str = "en") -> list[str]:
    """The performance goals, each with what this run measured, and where the time goes
    for a goal not met."""
    if not goals:
        return []
    out = [say("br_goals", lang), "", *_head("bh_goals", "--- ---: ---: ---", lang)]
    for g in goals:
        met = say("bs_yes" if g["met"] else "bs_no", lang)
        want, got = _want_got(g, lang)
        out.append(f"| {goal_name(g, lang)} | {want} | {got} | {met} |")
    out.append("")
    for g in goals:
        if "together_s" in g:
            out += [say("br_together", lang, together=fmt(g["together_s"], "s", lang),
                        one=fmt(g["one_by_one_s"], "s", lang), apart=g["readings_apart"]), ""]
    for g in goals:
        if "profile" in g:
            out += [say("br_profile", lang, goal=goal_name(g, lang)), "", *_head("bh_profile", "--- ---: ---: ---:", lang)]
            out += [f"| `{p['function']}` | {number(p['calls_per_run'], '.0f', lang)} | "
                    f"{number(p['own_us_per_run'], '.1f', lang)} | {number(p['cum_us_per_run'], '.1f', lang)} |"
                    for p in g["profile"]]
            out.append("")
    return out


def hand_drawing_section(dm: dict[str, Any], lang: str = "en") -> list[str]:
    """The Monte Carlo's 95th percentiles per reading, sheet by sheet."""
    if not dm:
        return []
    out: list[str] = []
    out += ["", say("br_hand", lang), "",
            say("br_hand_text", lang, pencil=dm["model"]["pencil_mm"], protractor=dm["model"]["protractor_deg"],
                n=dm["samples"]), ""]
    for sc_name, sheets in dm["scenes"].items():
        names = sorted(next(iter(sheets.values())).keys(), key=_qorder)
        heads = list(sheets)
        out += [say("br_hand_scene", lang, scene=words(sc_name, lang), phi=dm["phi_deg"]), "",
                "| " + say("bh_hand", lang) + " | " + " | ".join(say("bh_hand_sheet", lang, h=h) for h in heads) + " |",
                "|---|---:|" + "---:|---:|---:|" * len(heads)]
        for q in names:
            e0 = sheets[heads[0]][q]
            cells = " | ".join(f"{number(sheets[h][q]['p95_rel'] * 100, '.2f', lang)} % | "
                               f"{say('bu_3g', lang, v=sheets[h][q]['p95_abs'], unit=sheets[h][q]['unit'])} | "
                               f"{number(sheets[h][q]['p95_mm'], '.2f', lang)}" for h in heads)
            out.append(f"| {_symbol(q, lang)} | {number(e0['exact'], '.5g', lang)} {_unit(e0['unit'], lang)} | {cells} |")
        out.append("")
    return out


def _symbol(q: str, lang: str) -> str:
    """A reading's name as the textbook writes it in ``lang`` (omega_2: ω2 in Russian)."""
    from plans.language import symbols

    return symbols(q, lang) if lang == "ru" else q


def _unit(unit: str, lang: str) -> str:
    from plans.language import UNITS_RU

    return UNITS_RU.get(unit, unit) if lang == "ru" else unit
