"""The engine file (TOML, ``format = 1``, ``kind = "engine"``): cylinders, cranks, masses.

.. code-block:: toml

    format = 1
    kind = "engine"
    title = "Inline-4, four-stroke"
    unit = "mm"              # lengths below (r, z, reference_z): mm | cm | m
    r = 50                   # crank radius
    lambda = 0.25            # r / l, 0 <= lambda < 1
    omega = 300              # rad/s (or omega_rpm = 3000)
    strokes = 4              # 2 or 4: the firing interval is 360/n or 720/n degrees
    firing_order = [1, 3, 4, 2]   # instead of every crank_deg: even firing in this order
    reference_z = 0          # plane the moments are taken about (default 0)
    m_rot = 1.2              # default masses of every cylinder (kg), a cylinder may override
    m_rec = 1.0
    [[cylinders]]            # one table per cylinder, in order along the shaft
    crank_deg = 0            # crank angle of this cylinder relative to cylinder 1
    z = 0                    # axial position along the shaft
    bank_deg = 0             # cylinder axis from the vertical (V engines: ±γ/2)
    m_rot = 1.2              # kg, rotating mass at the crank pin
    m_rec = 1.0              # kg, reciprocating mass at the piston pin
    [counterweights]         # optional
    planes = [0, 300]        # one or two planes for the counterweights (default: the end cylinders)
    radius = 50              # radius of the counterweights' centres (default r)

Angles (crank_deg, bank_deg and every phase) are measured from the vertical in the
direction of rotation.  With ``firing_order`` the cylinder that fires k-th (k = 0, 1, ...)
reaches its top dead centre k·δ after cylinder 1 (δ = 720°/n four-stroke, 360°/n
two-stroke), so its crank is β = (γ_i − γ_1) − k·δ ahead of crank 1.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from plans.errors import Said
from plans.io import loads_toml, read_toml
from plans.reader import LENGTH_LIMIT, NUMBER_LIMIT, Reader, check_keys, reduce_deg, show
from plans.scene.sheet import own_title
from plans.tolerances import SAME_LAYOUT
from plans.units import LENGTH_UNITS, rpm_to_rad_s

TOP_KEYS = {"format", "kind", "title", "unit", "r", "lambda", "omega", "omega_rpm", "strokes",
            "firing_order", "crank_deg", "reference_z", "m_rot", "m_rec", "cylinders",
            "counterweights", "sheet"}
CYLINDER_KEYS = {"name", "crank_deg", "z", "bank_deg", "m_rot", "m_rec"}
COUNTERWEIGHT_KEYS = {"planes", "radius"}


@dataclass(frozen=True, slots=True)
class Cylinder:
    """One crank-slider unit: its crank β, plane z and bank γ (SI, radians), its masses."""

    number: int  # 1-based, order along the shaft
    name: str
    crank: float  # β_i, rad, ahead of crank 1 in the direction of rotation
    z: float  # m
    bank: float  # γ_i, rad, from the vertical in the direction of rotation
    m_rot: float  # kg
    m_rec: float  # kg

    @property
    def crank_deg(self) -> float:
        return math.degrees(self.crank)

    @property
    def bank_deg(self) -> float:
        return math.degrees(self.bank)


@dataclass(frozen=True, slots=True)
class Engine:
    path: str
    title: str
    unit: str
    r: float  # m
    lam: float  # λ = r / l
    omega: float  # rad/s
    strokes: int
    firing_order: tuple[int, ...] | None
    cylinders: tuple[Cylinder, ...]
    reference_z: float  # m
    cw_planes: tuple[float, ...] | None  # m
    cw_radius: float  # m
    raw: dict[str, Any]

    @property
    def n(self) -> int:
        return len(self.cylinders)

    @property
    def rod_length(self) -> float:
        """Connecting-rod length (m); infinite for λ = 0."""
        return self.r / self.lam if self.lam > 0 else math.inf

    @property
    def is_inline(self) -> bool:
        """All cylinders on one bank: forces along one line, the seed's classic polygons."""
        return all(abs(c.bank - self.cylinders[0].bank) < SAME_LAYOUT for c in self.cylinders)

    @property
    def is_planar(self) -> bool:
        """One crank throw: the engine is a planar linkage (single cylinder, V-twin)."""
        return all(abs(wrap(c.crank)) < SAME_LAYOUT for c in self.cylinders)

    @property
    def arm_unit(self) -> float:
        """l_ц, the unit of the dimensionless arms: the mean spacing of the cylinder planes
        (the crank radius when every cylinder is in one plane)."""
        zs = sorted({round(c.z, 12) for c in self.cylinders})
        if len(zs) < 2:
            return self.r
        return (zs[-1] - zs[0]) / (len(zs) - 1)


def wrap(a: float) -> float:
    """An angle reduced to (−π, π]."""
    return math.atan2(math.sin(a), math.cos(a))


class _Reader(Reader):
    """The shared reader (bounded numbers and lengths), with ``where`` optional."""

    def number(self, data: dict[str, Any], key: str, where: str = "", *, default: float | None = None,
               positive: bool = False, nonneg: bool = False, limit: float = NUMBER_LIMIT,
               floor: float | None = None) -> float:
        return super().number(data, key, where, default=default, positive=positive, nonneg=nonneg,
                              limit=limit, floor=floor)


def load_engine(path: str | Path) -> Engine:
    """Read and validate an engine file."""
    return engine_from_dict(read_toml(path), str(path))


def parse_engine(text: str, path: str = "<engine>") -> Engine:
    return engine_from_dict(loads_toml(text, path), path)


def engine_from_dict(data: dict[str, Any], path: str = "<engine>") -> Engine:
    """Validate an engine table; every problem is one InputError naming the key."""
    rd = _Reader(path)
    from plans.kinds import check_top

    check_top(data, path, "engine", TOP_KEYS)
    unit = rd.choice(data, "unit", "", LENGTH_UNITS, default="mm")
    title = own_title(data.get("title", Path(path).stem))
    if not isinstance(title, str):
        raise rd.fail("title", Said("gm_string"))
    if "r" not in data:
        raise rd.fail("r", Said("be_missing_crank_radius"))
    r = rd.length(data["r"], "r", unit, positive=True)
    lam = rd.number(data, "lambda")
    if not 0.0 <= lam < 1.0:
        raise rd.fail("lambda", Said("be_lambda_rod_longer", got=show(lam)))
    if lam > 0 and r / lam > LENGTH_LIMIT:  # the rod l = r/λ is a length like any other
        raise rd.fail("lambda", Said("be_rod_lambda_longer", v=r / lam, LENGTH_LIMIT=LENGTH_LIMIT, v2=r / LENGTH_LIMIT))
    if "omega" in data and "omega_rpm" in data:
        raise rd.fail("omega_rpm", Said("be_give_omega_rad"))
    if "omega_rpm" in data:
        omega = rpm_to_rad_s(rd.number(data, "omega_rpm", positive=True))
    else:
        omega = rd.number(data, "omega", positive=True)
    strokes = data.get("strokes", 4)
    if strokes not in (2, 4) or isinstance(strokes, bool):
        raise rd.fail("strokes", Said("be_msg", got=show(strokes)))
    # an engine with no rotating masses (a balanced crank, a crosshead engine's analysis) is allowed
    m_rot0 = rd.number(data, "m_rot", nonneg=True) if "m_rot" in data else None
    m_rec0 = rd.number(data, "m_rec", positive=True) if "m_rec" in data else None

    raw = data.get("cylinders")
    if not isinstance(raw, list) or not raw or not all(isinstance(c, dict) for c in raw):
        raise rd.fail("cylinders", Said("be_one_table_cylinders"))
    n = len(raw)
    for k, body in enumerate(raw):
        check_keys(body, CYLINDER_KEYS, file=path, where=f"cylinders[{k}].")
    banks = [math.radians(rd.number(body, "bank_deg", f"cylinders[{k}].", default=0.0, floor=0.0))
             for k, body in enumerate(raw)]
    for k, g in enumerate(banks):
        if not abs(g) < math.pi:
            raise rd.fail(f"cylinders[{k}].bank_deg", Said("be_angle_between_degrees"))
    cranks = _cranks(rd, data, raw, banks, int(strokes))
    cyls = []
    for k, body in enumerate(raw):
        where = f"cylinders[{k}]."
        if "z" in body:
            z = rd.length(body["z"], f"{where}z", unit)
        elif n == 1:
            z = 0.0
        else:
            raise rd.fail(f"{where}z", Said("be_missing_cylinder_position"))
        m_rot = rd.number(body, "m_rot", where, nonneg=True) if "m_rot" in body else m_rot0
        m_rec = rd.number(body, "m_rec", where, positive=True) if "m_rec" in body else m_rec0
        if m_rot is None:
            raise rd.fail(f"{where}m_rot", Said("be_missing_rotating_mass"))
        if m_rec is None:
            raise rd.fail(f"{where}m_rec", Said("be_missing_reciprocating_mass"))
        name = body.get("name", str(k + 1))
        if not isinstance(name, str) or not name:
            raise rd.fail(f"{where}name", Said("be_short_text"))
        cyls.append(Cylinder(k + 1, name, cranks[k], z, banks[k], m_rot, m_rec))
    ref = rd.length(data.get("reference_z", 0), "reference_z", unit)
    planes, radius = _counterweights(rd, data, unit, r)
    order = tuple(data["firing_order"]) if "firing_order" in data else None
    return Engine(path, title, unit, r, lam, omega, int(strokes), order, tuple(cyls), ref, planes,
                  radius, data)


def _cranks(rd: _Reader, data: dict[str, Any], raw: list[dict[str, Any]], banks: list[float],
            strokes: int) -> list[float]:
    """β_i of every cylinder (rad, relative to crank 1): from crank_deg (per cylinder or a
    list at the top) or from the firing order."""
    n = len(raw)
    per = [k for k, body in enumerate(raw) if "crank_deg" in body]
    given = ["firing_order"] if "firing_order" in data else []
    given += ["crank_deg"] if "crank_deg" in data else []
    if per:
        given.append("cylinders[].crank_deg")
    if len(given) > 1:
        raise rd.fail(given[1].split("[")[0] if given[1] != "cylinders[].crank_deg"
                      else f"cylinders[{per[0]}].crank_deg",
                      Said("be_give_cranks_one", v=' or '.join(given)))
    if "firing_order" in data:
        order = data["firing_order"]
        if (not isinstance(order, list) or any(isinstance(x, bool) or not isinstance(x, int) for x in order)
                or sorted(order) != list(range(1, n + 1))):
            raise rd.fail("firing_order", Said("be_numbers_cylinders_each", n=n, got=show(order)))
        if order[0] != 1:
            raise rd.fail("firing_order", Said("be_order_start_cylinder", got=show(order)))
        delta = math.radians((720.0 if strokes == 4 else 360.0) / n)
        out = [0.0] * n
        for k, cyl in enumerate(order):
            out[cyl - 1] = (banks[cyl - 1] - banks[0]) - k * delta
        return [wrap(b) for b in out]
    if "crank_deg" in data:
        lst = data["crank_deg"]
        if not isinstance(lst, list) or len(lst) != n:
            got = len(lst) if isinstance(lst, list) else lst
            raise rd.fail("crank_deg", Said("be_one_angle_per", n=n, got=show(got)))
        degs = []
        for k, v in enumerate(lst):
            if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
                raise rd.fail(f"crank_deg[{k}]", Said("be_number_degrees", got=show(v)))
            degs.append(reduce_deg(float(v)))  # any finite angle, reduced exactly
    elif len(per) == n:
        degs = [rd.angle(body, "crank_deg", f"cylinders[{k}].") for k, body in enumerate(raw)]
    elif n == 1:
        degs = [0.0]
    else:
        missing = next(k for k in range(n) if k not in per)
        raise rd.fail(f"cylinders[{missing}].crank_deg",
                      Said("be_missing_crank_angle", n=n))
    return [wrap(math.radians(d - degs[0])) for d in degs]


def _counterweights(rd: _Reader, data: dict[str, Any], unit: str, r: float
                    ) -> tuple[tuple[float, ...] | None, float]:
    cw = data.get("counterweights", {})
    if not isinstance(cw, dict):
        raise rd.fail("counterweights", Said("be_table_counterweights"))
    check_keys(cw, COUNTERWEIGHT_KEYS, file=rd.path, where="counterweights.")
    planes = None
    if "planes" in cw:
        p = cw["planes"]
        if not isinstance(p, list) or len(p) not in (1, 2):
            raise rd.fail("counterweights.planes", Said("be_one_two_plane"))
        planes = tuple(rd.length(v, f"counterweights.planes[{k}]", unit) for k, v in enumerate(p))
        if len(planes) == 2 and abs(planes[0] - planes[1]) < SAME_LAYOUT:
            raise rd.fail("counterweights.planes", Said("be_two_different_planes"))
    radius = rd.length(cw["radius"], "counterweights.radius", unit, positive=True) if "radius" in cw else r
    return planes, radius
