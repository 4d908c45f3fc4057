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

from plans.errors import InputError
from plans.io import read_toml
from plans.reader import Reader, check_keys, show
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
            raise InputError("missing; expected a number", file=path, field=f"{where}{key}")
        return default
    # finite, at most 1e12 and, when positive, at least 1e-12
    v = Reader(path).value(data[key], f"{where}{key}", positive=positive,
                           floor=0.0 if at_least is not None else None)
    if at_least is not None and v < at_least:
        raise InputError(f"expected at least {at_least:g}, got {v:g}", file=path, field=f"{where}{key}")
    if below is not None and v >= below:
        raise InputError(f"expected less than {below:g}, got {v:g}", file=path, field=f"{where}{key}")
    return v


def _length(data: dict[str, Any], key: str, unit: str, path: str, where: str = "", *,
            default: float | None = None, positive: bool = False, at_least: float | None = None) -> float:
    if key not in data:
        if default is None:
            raise InputError("missing; expected a length", file=path, field=f"{where}{key}")
        return default
    v = Reader(path).length(data[key], f"{where}{key}", unit, positive=positive)  # finite, 1 µm .. 10 km (or 0)
    if at_least is not None and v < at_least:
        raise InputError(f"expected at least {at_least:g}, got {show(data[key])}", file=path, field=f"{where}{key}")
    return v


def _choice(data: dict[str, Any], key: str, choices: Iterable[str], path: str, where: str = "",
            default: str | None = None) -> str:
    choices = tuple(choices)
    v = data.get(key, default)
    if v is None:
        raise InputError(f"missing; expected one of {', '.join(map(repr, choices))}", file=path,
                         field=f"{where}{key}")
    if v not in choices:
        raise InputError(f"expected one of {', '.join(map(repr, choices))}, got {show(v)}", file=path,
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
            raise InputError("a flat face has no roller; give face = \"flat\" or roller, not both",
                             file=path, field="roller")
        if osc:
            raise InputError("a flat face is read for the translating follower; give the oscillating "
                             "follower a roller", file=path, field="face")
        roller = 0.0
    else:
        roller = _length(data, "roller", unit, path, default=0.0, at_least=0.0)
        if roller >= r0:
            raise InputError(f"the roller must be smaller than the base radius ({show(data['roller'])} vs "
                             f"{show(data['base_radius'])})", file=path, field="roller")
    offset = _length(data, "offset", unit, path, default=0.0)
    if not osc and abs(offset) >= r0:
        raise InputError(f"the offset must be smaller than the base radius ({show(data.get('offset'))} "
                         f"vs {show(data['base_radius'])})", file=path, field="offset")
    arm = pivot = 0.0
    if osc:
        for key in ("arm", "pivot"):
            if key not in data:
                raise InputError("missing; an oscillating follower needs arm and pivot (lengths)",
                                 file=path, field=key)
        arm = _length(data, "arm", unit, path, positive=True)
        pivot = _length(data, "pivot", unit, path, positive=True)
        if not abs(arm - r0) < pivot < arm + r0:
            raise InputError("the base circle cannot reach the roller: need |arm − base_radius| < pivot "
                             "< arm + base_radius", file=path, field="pivot")
    # ω from 1e-6 to 1e6 rad/s, as every crank's (ω² stays finite, 1/ω too)
    omega = rpm_to_rad_s(_number(data, "omega_rpm", path, positive=True, at_least=1e-5, below=1e7))
    sense = _choice(data, "sense", ("ccw", "cw"), path, default="ccw")
    a_rise = _number(data, "pressure_angle_rise_deg", path, default=45.0 if osc else 30.0,
                     positive=True, at_least=1.0, below=90)  # below 1° tan α vanishes in the bounds
    a_ret = _number(data, "pressure_angle_return_deg", path, default=70.0, positive=True, at_least=1.0,
                    below=90)
    step = _number(data, "step_deg", path, default=1.0, positive=True, at_least=0.01)
    if step > 30 or abs(360 / step - round(360 / step)) > 1e-9:
        raise InputError(f"expected a divisor of 360 not above 30, got {step:g}", file=path, field="step_deg")
    phases = _phases(data, path, unit, osc)
    h = max(p.lift0 + max(p.stroke, 0.0) for p in phases)
    if osc and h >= math.pi / 2:
        raise InputError("the swing must stay below 90°", file=path, field="phases")
    title = data.get("title", Path(path).stem)
    if not isinstance(title, str):
        raise InputError(f"expected a string, got {show(title)}", file=path, field="title")
    return Cam(path, title, unit, follower, r0, offset, roller, flat, arm,
               pivot, omega, 1 if sense == "ccw" else -1, math.radians(a_rise), math.radians(a_ret), step,
               phases, h, data)


def _phases(data: dict[str, Any], path: str, unit: str, osc: bool) -> tuple[Phase, ...]:
    raw = data.get("phases")
    if not isinstance(raw, list) or not raw or not all(isinstance(p, dict) for p in raw):
        raise InputError("expected [[phases]] tables (rise, dwell, return)", file=path, field="phases")
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
            raise InputError(f"a {'n oscillating' if osc else ' translating'} follower's lift is "
                             f"{lift_key}", file=path, field=f"{where}{wrong}")
        if kind == "dwell":
            for key in (lift_key, "law", "table"):
                if key in ph:
                    raise InputError("a dwell has no lift and no law", file=path, field=f"{where}{key}")
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
                raise InputError("the return is longer than the lift reached so far", file=path,
                                 field=f"{where}{lift_key}")
            stroke = -min(stroke, lift)
        name = _choice(ph, "law", LAW_NAMES, path, where)
        if name == "table":
            law = _table(ph, path, where, abs(stroke), angle_deg, unit, osc)
        else:
            if "table" in ph:
                raise InputError("a table is read only with law = \"table\"", file=path, field=f"{where}table")
            law = LAWS[name]
        out.append(Phase(kind, start, angle, lift, stroke, name, law))
        start += angle
        lift += stroke
    total = math.degrees(start)
    if abs(total - 360.0) > 1e-6:
        raise InputError(f"the phases' angle_deg sum to {total:g}°; expected 360°", file=path, field="phases")
    if abs(lift) > 1e-12:
        raise InputError("the phases leave the follower lifted; the returns must bring it back to the start",
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
        raise InputError("expected at least 3 rows [angle_deg, lift] of finite numbers", file=path, field=field)
    ang = [float(r[0]) for r in rows]
    scale = math.radians(1.0) if osc else LENGTH_UNITS[unit]
    lift = [float(r[1]) * scale for r in rows]
    if any(b <= a for a, b in zip(ang, ang[1:], strict=False)):
        raise InputError("the angles must increase", file=path, field=field)
    gap = 1e-6 * angle_deg  # closer rows make the spline's equations singular
    if any(b - a < gap for a, b in zip(ang, ang[1:], strict=False)):
        raise InputError(f"rows closer than {gap:g}°; expected the angles at least {gap:g}° apart",
                         file=path, field=field)
    if abs(ang[0]) > 1e-9 or abs(ang[-1] - angle_deg) > 1e-9:
        raise InputError(f"the table must run from 0 to the phase's {angle_deg:g}°", file=path, field=field)
    if abs(lift[0]) > 1e-12:
        raise InputError("the table must start at lift 0", file=path, field=field)
    if abs(lift[-1] - stroke) > 1e-9 * max(1.0, stroke) and abs(lift[-1] - stroke) > 1e-12:
        shown = rows[-1][1]
        want = math.degrees(stroke) if osc else stroke / LENGTH_UNITS[unit]
        raise InputError(f"the law does not reach the stroke: the table ends at {shown:g}, the stroke is "
                         f"{want:g}", file=path, field=field)
    return table_law([a / angle_deg for a in ang], [v / stroke for v in lift])
