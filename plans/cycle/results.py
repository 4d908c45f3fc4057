"""The cycle's part of a solved scene: its tables, dynamics and diagrams, as asked for."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from plans.records import frozen

from .table import CycleTable, csv_text, plan_table, position_table, text

if TYPE_CHECKING:  # loaded when a scene asks for them: a linkage's solve does not pay for them
    from .diagrams import Diagrams
    from .dynamics import Dynamics


@frozen(slots=False)
class CycleResult:
    """What the cycle adds to a solve: its tables, dynamics and diagrams (as asked)."""

    tables: tuple[CycleTable, ...]
    dynamics: Dynamics | None
    diagrams: Diagrams | None


def solve_cycle(kin: Any, plans: Any, dyn: Dynamics | None, dia: Diagrams | None) -> CycleResult | None:
    """Tables over the positions (several positions), with the dynamics and the diagrams as
    solved (None where the scene does not ask for them): a Solution solves those once for
    every fit, the tables read the plans at its own."""
    tables: list[CycleTable] = []
    base = plan_table(plans) if plans else position_table(kin)
    if base is not None:
        tables.append(base)
    if dyn is not None:
        from .output import dynamics_tables

        tables += dynamics_tables(dyn)
    if not tables and dyn is None and dia is None:
        return None
    return CycleResult(tuple(tables), dyn, dia)


def _l(a: Any) -> list[float]:
    return [float(x) for x in np.asarray(a, float)]


def diagrams_json(d: Diagrams) -> dict[str, Any]:
    out = []
    for g in d.diagrams:
        out.append({"name": g.name, "subject": g.subject, "quantity": g.quantity, "unit": g.unit,
                    "phi_deg": _l(g.phi_deg), "values": _l(g.values),
                    "exact": _l(np.interp(g.phi_deg, g.exact_phi_deg, g.exact)),
                    "scale": g.scale, "scale_formula": g.scale_formula, "pole_mm": g.pole_mm,
                    "error_max_pct": g.error_max_pct, "error_rms_pct": g.error_rms_pct,
                    "integral": None if g.integral is None else _l(g.integral),
                    "integral_error_max_pct": g.integral_error_max_pct})
    return {"method": d.spec.method, "omega": d.omega, "mu_phi": d.mu_phi, "pole_mm": d.pole_mm,
            "pole2_mm": d.pole2_mm,
            "nodes_deg": _l(d.nodes_deg), "diagrams": out}


def cycle_json(cr: CycleResult, lang: str = "en") -> dict[str, Any]:
    """Top-level JSON blocks: ``cycle`` (tables, their titles and labels in ``lang``),
    ``dynamics``, ``diagrams``."""
    out: dict[str, Any] = {}
    if cr.tables:
        out["cycle"] = {"tables": [t.to_json(lang) for t in cr.tables]}
    if cr.dynamics is not None:
        from .output import dynamics_json

        out["dynamics"] = dynamics_json(cr.dynamics, lang)
    if cr.diagrams is not None:
        out["diagrams"] = diagrams_json(cr.diagrams)
    return out


def cycle_text(cr: CycleResult, lang: str = "en") -> str:
    parts = [text(t, lang=lang) for t in cr.tables]
    if cr.diagrams is not None:
        d = cr.diagrams
        from plans.language import symbols
        from plans.phrases import PHRASES, say

        method = say(f"y_{d.spec.method}", lang) if f"y_{d.spec.method}" in PHRASES else d.spec.method
        lines = [say("y_diagrams", lang, method=method, h1=d.pole_mm, h2=d.pole2_mm, mu=d.mu_phi)]
        for g in d.diagrams:
            integ = "" if g.integral_error_max_pct is None else say("y_integ", lang, mx=g.integral_error_max_pct)
            lines.append(say("y_diagram", lang, name=g.name, formula=_comma(symbols(g.scale_formula, lang), lang),
                             mx=g.error_max_pct, rms=g.error_rms_pct, integ=integ))
        parts.append("\n".join(lines) + "\n")
    if cr.dynamics is not None:
        from .output import dynamics_text

        parts.append(dynamics_text(cr.dynamics, lang) + "\n")
    return "\n".join(parts)


def _comma(text: str, lang: str) -> str:
    """A formula's numbers with a decimal comma in Russian."""
    if lang != "ru":
        return text
    import re

    return re.sub(r"(\d)\.(\d)", r"\1,\2", text)


def cycle_csv(cr: CycleResult, lang: str = "en") -> str:
    return csv_text(cr.tables, lang)
