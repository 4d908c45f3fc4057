"""Friction in the kinematic pairs of a scene: what each pair loses to friction.

.. code-block:: toml

    [friction]                 # defaults for every pair (all optional)
    f = 0.1                    # coefficient of friction: of a slide, and the reduced f' of a pin
    pin_radius = 10            # r of the pins (file unit); a pin's friction circle is ρ = f'·r
    friction_circle = 1        # or ρ itself for every turning pair (file unit)
    tolerance = 1e-10          # the successive approximation stops when no reaction changes
                               # by more than this times the position's largest reaction
    max_iterations = 200

    [[joints]]                 # per pair, over the defaults
    kind = "R"
    links = [1, 2]
    point = "A"
    f = 0.12                   # with pin_radius (here or in [friction]), or
    friction_circle = 1.5      # ρ directly (a turning pair only)

A slide takes ``f`` only.  A pin's ρ: its own ``friction_circle``, else ``f``·``pin_radius``
(each from the joint or else from [friction]), else the default ``friction_circle``.
"""

from __future__ import annotations

from typing import Any

from plans.errors import Said
from plans.reader import Reader
from plans.records import frozen
from plans.scene.model import Joint, Scene
from plans.units import LENGTH_UNITS

#: The keys a [[joints]] entry may carry for friction.
JOINT_FRICTION_KEYS = ("f", "pin_radius", "friction_circle")
TABLE_KEYS = (*JOINT_FRICTION_KEYS, "tolerance", "max_iterations")
#: The successive approximation's defaults.
TOLERANCE = 1e-10
MAX_ITERATIONS = 200


@frozen
class PairFriction:
    """One pair's friction: the friction circle's radius ρ (m) of a turning pair, the
    coefficient f of a slide."""

    joint: Joint
    rho: float = 0.0
    f: float = 0.0

    @property
    def coefficient(self) -> float:
        """What multiplies the reaction: ρ (m) for a pin, f for a slide."""
        return self.rho if self.joint.kind == "R" else self.f


@frozen
class FrictionSpec:
    """Every pair's friction, in the order of ``[[joints]]``, and the approximation's stop."""

    pairs: tuple[PairFriction, ...]
    tolerance: float
    max_iterations: int

    def of(self, joint: Joint) -> PairFriction | None:
        return next((p for p in self.pairs if p.joint is joint), None)


def has_friction(scene: Scene) -> bool:
    """Whether the scene speaks of friction at all (a [friction] table or a pair's keys)."""
    raw = scene.raw
    joints = raw.get("joints")
    return "friction" in raw or (isinstance(joints, list) and any(
        isinstance(b, dict) and any(k in b for k in JOINT_FRICTION_KEYS) for b in joints))


def parse_friction(scene: Scene) -> FrictionSpec | None:
    """The scene's friction, or None where it states none; InputError naming the field.  The
    record the scene holds once solved (``plans.solve`` reads it once, :mod:`plans.tables`),
    else read now."""
    if scene.tables:
        return scene.friction_spec
    return _parse(scene) if has_friction(scene) else None


def _parse(scene: Scene) -> FrictionSpec:
    r = Reader(scene.path)
    raw = scene.raw
    unit = raw.get("unit", "mm")
    unit = unit if unit in LENGTH_UNITS else "mm"
    table = r.table(raw, "friction", "", required=False)
    r.keys(table, TABLE_KEYS, "friction.")

    def coefficient(body: dict[str, Any], where: str) -> float | None:
        return r.number(body, "f", where, nonneg=True, limit=10.0) if "f" in body else None

    def length(body: dict[str, Any], key: str, where: str) -> float | None:
        if key not in body:
            return None
        value = r.length(body[key], f"{where}{key}", unit)
        if value < 0:
            raise r.fail(f"{where}{key}", Said("sf_length", v=body[key]))
        return value

    f0 = coefficient(table, "friction.")
    r0 = length(table, "pin_radius", "friction.")
    rho0 = length(table, "friction_circle", "friction.")
    tol = r.number(table, "tolerance", "friction.", default=TOLERANCE, positive=True, limit=1e-3, floor=1e-15)
    most = r.integer(table, "max_iterations", "friction.", default=MAX_ITERATIONS, at_least=1, at_most=10000)
    pairs = []
    for k, (joint, body) in enumerate(zip(scene.joints, raw.get("joints", []), strict=True)):
        where = f"joints[{k}]."
        f = coefficient(body, where)
        pin = length(body, "pin_radius", where)
        circle = length(body, "friction_circle", where)
        if joint.kind == "P":
            for key in ("pin_radius", "friction_circle"):
                if key in body:
                    raise r.fail(f"{where}{key}", Said("sf_slide_kind_has"))
            pairs.append(PairFriction(joint, f=(f0 or 0.0) if f is None else f))
            continue
        if circle is not None:
            if f is not None or pin is not None:
                raise r.fail(f"{where}friction_circle", Said("sf_give_friction_circle"))
            rho = circle
        elif f is not None or pin is not None:
            fr = f if f is not None else f0
            rr = pin if pin is not None else r0
            if fr is None or rr is None:
                missing = "pin_radius" if rr is None else "f"
                raise r.fail(f"{where}{missing}", Said("sf_pin_friction_circle", missing=missing))
            rho = fr * rr
        elif rho0 is not None:
            rho = rho0
        elif f0 is not None and r0 is not None:
            rho = f0 * r0
        elif f0:
            raise r.fail("friction.pin_radius", Said("sf_reaches_turning_pairs", f0=f0, point=joint.point, k=k))
        else:
            rho = 0.0
        pairs.append(PairFriction(joint, rho=rho))
    return FrictionSpec(tuple(pairs), tol, most)
