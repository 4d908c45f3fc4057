"""Tables across positions: quantities as rows, positions as columns (seed 004's table 1.1).

Each quantity read off a plan gives two rows, its segment on the plan in mm and its
value; scenes without plans give the coordinates of their points.  The dynamics adds the
plans of analogues (segments at μ of the analogue plan and v/ω1), the reduced moment of
inertia term by term (table 1.2) and the reduced moment of forces load by load (table 1.4).
"""

from __future__ import annotations

import io
import math
from collections.abc import Sequence
from dataclasses import field
from typing import Any

import numpy as np

from plans.records import frozen
from plans.units import DUST


@frozen
class TableRow:
    """One quantity across the positions of a cycle table."""

    key: str  # machine name: "v_B", "v_B:mm", "I_pr", ...
    label: str  # as printed: "p_v b", "v_B", "m_2 (v_S2/ω_1)^2"
    unit: str  # "mm", "m/s", "kg*m^2", ...
    values: tuple[float | None, ...]  # one per position (None: not at this position)


@frozen
class CycleTable:
    """A table of quantities across the positions of the cycle."""

    title: str  # in English; ``said`` writes it in either language
    phi_deg: tuple[float, ...]
    rows: tuple[TableRow, ...]
    said: Any = field(default=None, repr=False, compare=False)  # a plans.phrases.Phrase

    def row(self, key: str) -> TableRow:
        for r in self.rows:
            if r.key == key:
                return r
        raise KeyError(key)

    def title_in(self, lang: str) -> str:
        """The table's title in ``lang``."""
        if self.said is not None:
            return str(self.said.say(lang))
        if lang != "ru":
            return self.title
        from plans.language import TERMS

        return {en: ru for en, ru in (TERMS["y_plans"], TERMS["y_positions"])}.get(self.title, self.title)

    def to_json(self, lang: str = "en") -> dict[str, Any]:
        """The table as JSON: its keys and units as the program names them, its title and
        labels in ``lang`` (the textbook's symbols in Russian)."""
        if lang != "ru":
            return {"title": self.title, "phi_deg": list(self.phi_deg),
                    "rows": [{"key": r.key, "label": r.label, "unit": r.unit, "values": list(r.values)}
                             for r in self.rows]}
        from plans.language import symbols

        return {"title": self.title_in(lang), "phi_deg": list(self.phi_deg),
                "rows": [{"key": r.key, "label": symbols(r.label, lang), "unit": r.unit, "values": list(r.values)}
                         for r in self.rows]}


def _clean(x: Any) -> float | None:
    if x is None:
        return None
    v = float(x)
    return v if math.isfinite(v) else None


def plan_table(plans: Sequence[Any], title: str = "Plans over the cycle") -> CycleTable | None:
    """Segments (mm) and values read off the velocity and acceleration plans, per position."""
    if len(plans) < 2:
        return None
    order: list[tuple[str, str | None, str]] = []
    seen: set[str] = set()
    cells: dict[tuple[str, str], list[float | None]] = {}
    n = len(plans)
    for k, pp in enumerate(plans):
        for r in pp.readings:
            if r.quantity not in seen:
                seen.add(r.quantity)
                order.append((r.quantity, r.segment, r.unit))
            if r.length_mm is not None:
                cells.setdefault((r.quantity, "mm"), [None] * n)[k] = _clean(r.length_mm)
            cells.setdefault((r.quantity, "value"), [None] * n)[k] = _clean(r.value)
    rows: list[TableRow] = []
    for q, seg, unit in order:
        if (q, "mm") in cells:
            rows.append(TableRow(f"{q}:mm", seg or q, "mm", tuple(cells[(q, "mm")])))
        rows.append(TableRow(q, q, unit, tuple(cells[(q, "value")])))
    return CycleTable(title, tuple(float(pp.phi_deg) for pp in plans), tuple(rows))


def position_table(kin: Any, title: str = "Positions over the cycle") -> CycleTable | None:
    """Coordinates of the points (m) and angles of the links (deg) when no plan is drawn."""
    if kin.n < 2:
        return None
    rows: list[TableRow] = []
    for nm in kin.point_names():
        r = kin.point(nm)[0]
        rows.append(TableRow(f"x_{nm}", f"x_{nm}", "m", tuple(_clean(x) for x in r.real)))
        rows.append(TableRow(f"y_{nm}", f"y_{nm}", "m", tuple(_clean(x) for x in r.imag)))
    for lid in sorted(kin.scene.links):
        th = np.degrees(kin.theta(lid))
        rows.append(TableRow(f"theta_{lid}", f"θ_{lid}", "deg", tuple(_clean(x) for x in th)))
    return CycleTable(title, tuple(float(x) for x in kin.phi_deg), tuple(rows))


# --------------------------------------------------------------------------- printing


def _cell(v: float | None) -> str:
    if v is None:
        return "-"
    if v == 0 or (abs(v) >= 1e-3 and abs(v) < 1e6):
        return f"{v:.4g}" if abs(v) < 1000 else f"{v:.1f}"
    return f"{v:.3e}"


def text(table: CycleTable, columns: int = 7, lang: str = "en") -> str:
    """Blocks of ``columns`` positions, numbered 1..N as the course numbers them; in ``lang``."""
    from plans.language import TERMS, symbols

    ru = lang == "ru"
    lines = [table.title_in(lang)]
    n = len(table.phi_deg)
    heads = [f"{r.label}, {r.unit}" if r.unit else r.label for r in table.rows]
    if ru:
        heads = [symbols(h, lang) for h in heads]
    wlab = max([len(f"{r.label}, {r.unit}") for r in table.rows] + [14])
    for start in range(0, n, columns):
        ks = range(start, min(n, start + columns))
        lines.append(f"  {TERMS['y_position'][ru]:<{wlab}}" + "".join(f"{k + 1:>11d}" for k in ks))
        lines.append(f"  {TERMS['y_phi'][ru]:<{wlab}}"
                     + "".join(_comma(f"{table.phi_deg[k]:>11.6g}", ru) for k in ks))
        for r, head in zip(table.rows, heads, strict=True):
            big = max([abs(v) for v in r.values if v is not None] + [0.0])
            cells = [None if v is None else (0.0 if abs(v) <= DUST * big else v) for v in r.values]
            lines.append(f"  {head:<{wlab}}" + "".join(_comma(f"{_cell(cells[k]):>11s}", ru) for k in ks))
        lines.append("")
    return "\n".join(lines)


def _comma(cell: str, ru: bool) -> str:
    return cell.replace(".", ",") if ru else cell


def csv_text(tables: Sequence[CycleTable], lang: str = "en") -> str:
    """One CSV: a header of crank angles per table, then one line per quantity; in ``lang``
    (in Russian: the headings, the textbook's symbols and units, a decimal comma; the keys as
    the program names them)."""
    import csv  # loaded by ``--csv`` alone

    from plans.language import TERMS, UNITS_RU, symbols

    ru = lang == "ru"
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    for t in tables:
        w.writerow([TERMS["y_csv_table"][ru], t.title_in(lang)])
        w.writerow([TERMS[k][ru] for k in ("y_csv_quantity", "y_csv_label", "y_csv_unit")]
                   + [_comma(f"{p:.10g}", ru) for p in t.phi_deg])
        for r in t.rows:
            label, unit = (symbols(r.label, lang), UNITS_RU.get(r.unit, r.unit)) if ru else (r.label, r.unit)
            w.writerow([r.key, label, unit] + ["" if v is None else _comma(repr(float(v)), ru) for v in r.values])
    return buf.getvalue()
