"""The cycle in ``plans solve``: JSON blocks ``cycle``, ``dynamics``, ``diagrams``, the
terminal tables and the CSV.

``dynamics`` (SI)::

    {"phi_deg": [...], "I_pr": [...], "M_pr": [...],
     "flywheel": {"delta", "omega_mean", "inertia_exact", "inertia_graphical",
                  "delta_achieved", "inertia_merkalov", "delta_achieved_exact",
                  "delta_achieved_merkalov", "graphical_error"},
     "M_driving", "M_driving_exact", "A_c", "A_d", "dT", "sign_rule",
     "rows": {"I_pr": [...], "M_pr": [...], "analogues": [...]},
     "exact": {"phi_deg", "I_pr", "M_pr", "dT", "omega", "omega_exact"},
     "scales": {"phi", "M", "H", "A", "I", "analogue"}}

I_pr includes the rotor; M_pr is the loads' power over |ω1|, positive when they drive the
crank; ``delta_achieved`` is what the graphical flywheel gives when the motion is
integrated exactly; ``inertia_*`` are what must be added at the crank on top of I_pr.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from plans.language import TERMS

from .dynamics import SIGN_RULE, Dynamics, Row
from .table import CycleTable, TableRow


def _l(a: Any) -> list[float]:
    return [float(x) for x in np.asarray(a, float)]


def _rows(rows: tuple[Row, ...], n: int) -> list[dict[str, Any]]:
    return [{"key": r.key, "label": r.label, "unit": r.unit, "link": r.link, "values": _l(r.values[:n])}
            for r in rows]


def dynamics_json(d: Dynamics, lang: str = "en") -> dict[str, Any]:
    n = len(d.spec.phi_deg)  # the table's positions (the closing 360° is the first again)
    t, f = d.table, d.flywheel
    return {
        "phi_deg": _l(t.phi_deg[:n]),
        "I_pr": _l(t.I_pr[:n]),
        "M_pr": _l(t.M_pr[:n]),
        "flywheel": {"delta": f.delta, "omega_mean": f.omega_mean, "inertia_exact": f.inertia_exact,
                     "inertia_graphical": f.inertia_graphical, "delta_achieved": f.delta_achieved,
                     "inertia_merkalov": f.inertia_merkalov, "delta_achieved_exact": f.delta_achieved_exact,
                     "delta_achieved_merkalov": f.delta_achieved_merkalov,
                     "graphical_error": f.graphical_error, "graphical_bound": f.graphical_bound,
                     "work_bound": f.work_bound},
        "cycle_deg": d.spec.cycle_deg,
        "M_driving": d.M_driving,
        "M_driving_exact": d.M_driving_exact,
        "sign_rule": SIGN_RULE if lang != "ru" else TERMS["y_sign_rule"][1].strip(),
        "A_c": _l(d.A_c[:n]),
        "A_d": _l(d.A_d[:n]),
        "dT": _l(d.dT[:n]),
        "rows": {"I_pr": _rows(t.inertia_rows, n), "M_pr": _rows(t.load_rows, n),
                 "analogues": _rows(t.analogue_rows, n)},
        "exact": {"phi_deg": _l(d.exact.phi_deg), "I_pr": _l(d.exact.I_pr), "M_pr": _l(d.exact.M_pr),
                  "dT": _l(d.dT_exact), "omega": _l(d.omega), "omega_exact": _l(d.omega_exact)},
        "scales": {"phi": d.scales.phi, "M": d.scales.M, "H": d.scales.H, "A": d.scales.A, "I": d.scales.I,
                   "analogue": d.scales.analogue},
    }


def _vals(a: Any, n: int) -> tuple[float | None, ...]:
    return tuple(float(x) for x in np.asarray(a, float)[:n])


def dynamics_tables(d: Dynamics) -> list[CycleTable]:
    """The analogues (segments at μ of the analogue plan and v/ω1), I_pr, M_pr, work and energy."""
    n = len(d.spec.phi_deg)
    phis = tuple(float(x) for x in d.table.phi_deg[:n])
    t = d.table
    mu = d.scales.analogue
    an: list[TableRow] = []
    for r in t.analogue_rows:
        if r.unit == "m":
            name = r.key[2:]
            an.append(TableRow(f"{r.key}:mm", f"p {name.lower()}", "mm", _vals(r.values * mu, n)))
            an.append(TableRow(r.key, r.label, "m", _vals(r.values, n)))
        else:
            an.append(TableRow(r.key, r.label, "", _vals(r.values, n)))
    inert = [TableRow(r.key, r.label, "kg*m^2", _vals(r.values, n)) for r in t.inertia_rows]
    inert.append(TableRow("I_pr", "I_pr", "kg*m^2", _vals(t.I_pr, n)))
    loads = [TableRow(f"M_{r.key}", f"M_pr({r.label})", "N*m", _vals(r.values, n)) for r in t.load_rows]
    loads.append(TableRow("M_pr", "M_pr", "N*m", _vals(t.M_pr, n)))
    energy = [TableRow("A_c", "A_c", "J", _vals(d.A_c, n)), TableRow("A_d", "A_d", "J", _vals(d.A_d, n)),
              TableRow("dT", "ΔT", "J", _vals(d.dT, n))]
    from plans.phrases import phrase

    said = [phrase("y_analogues", mu=mu), phrase("y_inertia"), phrase("y_forces"), phrase("y_energy")]
    return [CycleTable(t.say("en"), phis, tuple(rows), t)
            for t, rows in zip(said, (an, inert, loads, energy), strict=True)]


def dynamics_text(d: Dynamics, lang: str = "en") -> str:
    from plans.phrases import Phrase, say

    f, s = d.flywheel, d.scales
    work = say("y_work", lang, w=f.work_bound) if f.work_bound >= 1e-9 else say("y_work_fine", lang)  # no dust
    lines = [
        say("y_dynamics", lang, cycle=say("y_720", lang) if d.spec.cycle_deg == 720 else ""),
        say("y_sign_rule", lang),
        say("y_driving", lang, g=d.M_driving, e=d.M_driving_exact),
        say("y_scales", lang, phi=s.phi, M=s.M, H=s.H, A=s.A, I=s.I),
        say("y_flywheel", lang, d=f.delta, w=f.omega_mean),
        say("y_wittenbauer", lang, I=f.inertia_graphical, d=f.delta_achieved, e=100 * f.graphical_error),
        say("y_merkalov", lang, I=f.inertia_merkalov, d=f.delta_achieved_merkalov),
        say("y_exact", lang, I=f.inertia_exact, d=f.delta_achieved_exact),
        say("y_bound", lang, b=f.graphical_bound, w=work),
    ]
    lines += [say("y_note", lang, t=x.say(lang) if isinstance(x, Phrase) else x) for x in d.notes]
    return "\n".join(lines)
