"""The cam file (TOML, ``format = 1``, ``kind = "cam"``) and the frozen :class:`Cam` it
describes.

.. code-block:: toml

    format = 1
    kind = "cam"
    unit = "mm"
    follower = "translating"   # or "oscillating" (arm, pivot)
    base_radius = 35           # of the theoretical profile (roller centre)
    offset = 0
    roller = 5                 # or face = "flat"
    omega_rpm = 650
    sense = "ccw"
    [[phases]]
    kind = "rise"              # rise, dwell, return
    angle_deg = 65
    stroke = 10                # swing_deg for an oscillating follower
    law = "harmonic"           # harmonic, cycloidal, constant_acceleration, poly345, table

Inside everything is SI (m, rad); an oscillating follower's lift is its swing angle ψ (rad).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from plans.errors import InputError, Said
from plans.io import read_toml
from plans.reader import Reader, check_keys, show
from plans.scene.sheet import own_title
from plans.units import LENGTH_UNITS, rpm_to_rad_s

from .laws import LAWS, Law, table_law

TOP_KEYS = {"format", "kind", "title", "unit", "follower", "base_radius", "offset", "roller", "face",
            "arm", "pivot", "omega_rpm", "sense", "pressure_angle_rise_deg",
            "pressure_angle_return_deg", "step_deg", "phases", "sheet"}
PHASE_KEYS = {"kind", "angle_deg", "stroke", "swing_deg", "law", "table"}
PHASE_KINDS = ("rise", "dwell", "return")
LAW_NAMES = (*LAWS, "table")
_TOL = 1e-9


@dataclass(frozen=True, slots=True)
class Phase:
    """One phase of the cycle: starts at ``start`` (rad, cam angle), lasts ``angle`` (rad),
    moves the follower from ``lift0`` by ``stroke`` (signed: negative on a return)."""

    kind: str
    start: float
    angle: float
    lift0: float
    stroke: float
    law_name: str
    law: Law


@dataclass(frozen=True, slots=True)
class Cam:
    """A cam and its follower, SI units."""

    path: str
    title: str
    unit: str  # the file's length unit, for output
    follower: str  # translating | oscillating
    base_radius: float
    offset: float  # translating: x of the follower's line, cam centre at the origin, follower up
    roller: float  # 0 for a flat face
    flat: bool
    arm: float  # oscillating: arm length (roller centre to pivot)
    pivot: float  # oscillating: cam centre to pivot distance (pivot on +x)
    omega: float  # rad/s, magnitude
    sense: int  # +1 ccw, −1 cw
    alpha_rise: float  # permissible pressure angles, rad
    alpha_return: float
    step_deg: float
    phases: tuple[Phase, ...]
    h: float  # the largest lift (stroke or swing)
    raw: dict[str, Any]

    @property
    def scale(self) -> float:
        """Metres per file unit."""
        return LENGTH_UNITS[self.unit]


def load_cam(path: str | Path) -> Cam:
    data = read_toml(path)
    return cam_from_dict(data, str(path))


def _number(data: dict[str, Any], key: str, path: str, where: str = "", *, default: float | None = None,
            positive: bool = False, at_least: float | None = None, below: float | None = None) -> float:
    if key not in data:
        if default is None:
            raise InputError(Said("cm_missing_number"), file=path, field=f"{where}{key}")
        return default
    # finite, at most 1e12 and, when positive, at least 1e-12
    v = Reader(path).value(data[key], f"{where}{key}", positive=positive,
                           floor=0.0 if at_least is not None else None)
    if at_least is not None and v < at_least:
        raise InputError(Said("cm_least_least", at_least=at_least, v=v), file=path, field=f"{where}{key}")
    if below is not None and v >= below:
        raise InputError(Said("cm_less_than_below", below=below, v=v), file=path, field=f"{where}{key}")
    return v


def _length(data: dict[str, Any], key: str, unit: str, path: str, where: str = "", *,
            default: float | None = None, positive: bool = False, at_least: float | None = None) -> float:
    if key not in data:
        if default is None:
            raise InputError(Said("cm_missing_length"), file=path, field=f"{where}{key}")
        return default
    v = Reader(path).length(data[key], f"{where}{key}", unit, positive=positive)  # finite, 1 µm .. 10 km (or 0)
    if at_least is not None and v < at_least:
        raise InputError(Said("cm_least_least2", at_least=at_least, got=show(data[key])), file=path, field=f"{where}{key}")
    return v


def _choice(data: dict[str, Any], key: str, choices: Iterable[str], path: str, where: str = "",
            default: str | None = None) -> str:
    choices = tuple(choices)
    v = data.get(key, default)
    if v is None:
        raise InputError(Said("cm_missing_one", v=', '.join(map(repr, choices))), file=path,
                         field=f"{where}{key}")
    if v not in choices:
        raise InputError(Said("gm_one", v=', '.join(map(repr, choices)), got=show(v)), file=path,
                         field=f"{where}{key}")
    return str(v)


def cam_from_dict(data: dict[str, Any], path: str) -> Cam:
    """Validate a cam file's table: every problem is one InputError line naming the key."""
    from plans.kinds import check_top

    check_top(data, path, "cam", TOP_KEYS)
    unit = _choice(data, "unit", LENGTH_UNITS, path, default="mm")
    follower = _choice(data, "follower", ("translating", "oscillating"), path)
    osc = follower == "oscillating"
    r0 = _length(data, "base_radius", unit, path, positive=True)
    flat = False
    if "face" in data:
        _choice(data, "face", ("flat", "roller"), path)
        flat = data["face"] == "flat"
    if flat:
        if "roller" in data:
            raise InputError(Said("cm_flat_face_has"),
                             file=path, field="roller")
        if osc:
            raise InputError(Said("cm_flat_face_read"), file=path, field="face")
        roller = 0.0
    else:
        roller = _length(data, "roller", unit, path, default=0.0, at_least=0.0)
        if roller >= r0:
            raise InputError(Said("cm_roller_must_smaller", got=show(data['roller']), got2=show(data['base_radius'])), file=path, field="roller")
    offset = _length(data, "offset", unit, path, default=0.0)
    if not osc and abs(offset) >= r0:
        raise InputError(Said("cm_offset_must_smaller", got=show(data.get('offset')), got2=show(data['base_radius'])), file=path, field="offset")
    arm = pivot = 0.0
    if osc:
        for key in ("arm", "pivot"):
            if key not in data:
                raise InputError(Said("cm_missing_oscillating_follower"),
                                 file=path, field=key)
        arm = _length(data, "arm", unit, path, positive=True)
        pivot = _length(data, "pivot", unit, path, positive=True)
        if not abs(arm - r0) < pivot < arm + r0:
            raise InputError(Said("cm_base_circle_cannot"), file=path, field="pivot")
    # ω from 1e-6 to 1e6 rad/s, as every crank's (ω² stays finite, 1/ω too)
    omega = rpm_to_rad_s(_number(data, "omega_rpm", path, positive=True, at_least=1e-5, below=1e7))
    sense = _choice(data, "sense", ("ccw", "cw"), path, default="ccw")
    a_rise = _number(data, "pressure_angle_rise_deg", path, default=45.0 if osc else 30.0,
                     positive=True, at_least=1.0, below=90)  # below 1° tan α vanishes in the bounds
    a_ret = _number(data, "pressure_angle_return_deg", path, default=70.0, positive=True, at_least=1.0,
                    below=90)
    step = _number(data, "step_deg", path, default=1.0, positive=True, at_least=0.01)
    if step > 30 or abs(360 / step - round(360 / step)) > 1e-9:
        raise InputError(Said("cm_divisor_above_step", step=step), file=path, field="step_deg")
    phases = _phases(data, path, unit, osc)
    h = max(p.lift0 + max(p.stroke, 0.0) for p in phases)
    if osc and h >= math.pi / 2:
        raise InputError(Said("cm_swing_must_stay"), file=path, field="phases")
    title = own_title(data.get("title", Path(path).stem))
    if not isinstance(title, str):
        raise InputError(Said("cm_string", got=show(title)), file=path, field="title")
    return Cam(path, title, unit, follower, r0, offset, roller, flat, arm,
               pivot, omega, 1 if sense == "ccw" else -1, math.radians(a_rise), math.radians(a_ret), step,
               phases, h, data)


def _phases(data: dict[str, Any], path: str, unit: str, osc: bool) -> tuple[Phase, ...]:
    raw = data.get("phases")
    if not isinstance(raw, list) or not raw or not all(isinstance(p, dict) for p in raw):
        raise InputError(Said("cm_phases_tables_rise"), file=path, field="phases")
    lift_key = "swing_deg" if osc else "stroke"
    out: list[Phase] = []
    start = lift = 0.0
    for i, ph in enumerate(raw):
        where = f"phases[{i}]."
        check_keys(ph, PHASE_KEYS, file=path, where=where)
        kind = _choice(ph, "kind", PHASE_KINDS, path, where)
        angle_deg = _number(ph, "angle_deg", path, where, positive=True)
        angle = math.radians(angle_deg)
        wrong = "stroke" if osc else "swing_deg"
        if wrong in ph:
            raise InputError(Said("cm_follower_lift_lift", v='n oscillating' if osc else ' translating', lift_key=lift_key), file=path, field=f"{where}{wrong}")
        if kind == "dwell":
            for key in (lift_key, "law", "table"):
                if key in ph:
                    raise InputError(Said("cm_dwell_has_lift"), file=path, field=f"{where}{key}")
            out.append(Phase(kind, start, angle, lift, 0.0, "dwell", _dwell))
            start += angle
            continue
        if kind == "rise":
            if osc:
                stroke = math.radians(_number(ph, lift_key, path, where, positive=True))
            else:
                stroke = _length(ph, lift_key, unit, path, where, positive=True)
        else:
            if lift_key not in ph:
                stroke = lift
            elif osc:
                stroke = math.radians(_number(ph, lift_key, path, where, positive=True))
            else:
                stroke = _length(ph, lift_key, unit, path, where, positive=True)
            if stroke > lift * (1 + _TOL) + 1e-15 or lift <= 0:
                raise InputError(Said("cm_return_longer_than"), file=path,
                                 field=f"{where}{lift_key}")
            stroke = -min(stroke, lift)
        name = _choice(ph, "law", LAW_NAMES, path, where)
        if name == "table":
            law = _table(ph, path, where, abs(stroke), angle_deg, unit, osc)
        else:
            if "table" in ph:
                raise InputError(Said("cm_table_read_only"), file=path, field=f"{where}table")
            law = LAWS[name]
        out.append(Phase(kind, start, angle, lift, stroke, name, law))
        start += angle
        lift += stroke
    total = math.degrees(start)
    if abs(total - 360.0) > 1e-6:
        raise InputError(Said("cm_phases_angle_deg", total=total), file=path, field="phases")
    if abs(lift) > 1e-12:
        raise InputError(Said("cm_phases_leave_follower"),
                         file=path, field="phases")
    return tuple(out)


def _dwell(t: Any) -> tuple[Any, Any, Any]:
    import numpy as np

    z = np.zeros_like(np.asarray(t, float))
    return z, z, z


def _table(ph: dict[str, Any], path: str, where: str, stroke: float, angle_deg: float, unit: str,
           osc: bool) -> Law:
    """``table = [[deg, lift], ...]``: the lift travelled in this phase at angles within it, from
    [0, 0] to [angle_deg, stroke]; the law is the clamped cubic spline through the points."""
    rows = ph.get("table")
    field = f"{where}table"
    if not isinstance(rows, list) or len(rows) < 3 or not all(
            isinstance(r, list) and len(r) == 2 and all(isinstance(v, int | float) and not isinstance(v, bool)
                                                       and abs(v) <= 1e12 and math.isfinite(v) for v in r)
            for r in rows):
        raise InputError(Said("cm_least_rows_angle"), file=path, field=field)
    ang = [float(r[0]) for r in rows]
    scale = math.radians(1.0) if osc else LENGTH_UNITS[unit]
    lift = [float(r[1]) * scale for r in rows]
    if any(b <= a for a, b in zip(ang, ang[1:], strict=False)):
        raise InputError(Said("cm_angles_must_increase"), file=path, field=field)
    gap = 1e-6 * angle_deg  # closer rows make the spline's equations singular
    if any(b - a < gap for a, b in zip(ang, ang[1:], strict=False)):
        raise InputError(Said("cm_rows_closer_than", gap=gap),
                         file=path, field=field)
    if abs(ang[0]) > 1e-9 or abs(ang[-1] - angle_deg) > 1e-9:
        raise InputError(Said("cm_table_must_run", angle_deg=angle_deg), file=path, field=field)
    if abs(lift[0]) > 1e-12:
        raise InputError(Said("cm_table_must_start"), file=path, field=field)
    if abs(lift[-1] - stroke) > 1e-9 * max(1.0, stroke) and abs(lift[-1] - stroke) > 1e-12:
        shown = rows[-1][1]
        want = math.degrees(stroke) if osc else stroke / LENGTH_UNITS[unit]
        raise InputError(Said("cm_law_does_reach", shown=shown, want=want), file=path, field=field)
    return table_law([a / angle_deg for a in ang], [v / stroke for v in lift])
