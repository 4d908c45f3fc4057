"""The loads of a scene as records: the ``[loads]`` table read (gas, forces, moments, the
balancing load) and the loads bound to the links at the positions (forces at their points,
couples), which the kinetostatics, the lever and the cycle take."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from plans.records import frozen

C = NDArray[np.complex128]
R = NDArray[np.float64]

PRESSURE_UNITS = {"Pa": 1.0, "kPa": 1e3, "MPa": 1e6, "bar": 1e5, "N/cm2": 1e4, "N/mm2": 1e6, "N/m2": 1.0}
AREA_UNITS = {"m2": 1.0, "cm2": 1e-4, "mm2": 1e-6}
G_STANDARD = 9.81  # the textbooks' g


@frozen
class GasLoad:
    """The gas force on a piston: a constant pressure or an indicator diagram by stroke."""

    link: int
    joint: str  # the prismatic joint the piston slides in
    area: float  # m²
    pressure: float | None  # Pa (constant) or None with a diagram
    diagram: dict[str, tuple[R, R]]  # "down"/"up" -> (travel m, pressure Pa)
    strokes: tuple[str, ...]
    toward_pivot: bool
    name: str
    outer: float = 0.0  # travel coordinate of the outer dead centre (diagram only), m
    stroke: float = 0.0  # H, m (diagram only)
    fires: float | None = None  # four-stroke: crank angle given for the ignition, deg
    #: four-stroke: the outer dead centre nearest to ``fires``, deg (found when the loads are read)
    ignition: float | None = None
    phi_table: tuple[R, R] | None = None  # pressure over the cycle's crank angle (deg, Pa)
    period: float = 360.0  # the cycle of phi_table, deg


@frozen
class ForceLoad:
    """An external force at a point of a link: fixed, or resisting the point's motion."""

    link: int
    point: str
    vector: complex | None  # N, fixed
    resisting: float | None  # magnitude opposite the velocity
    along: float | None  # rad, axis for the resisting force's sign
    stroke: str  # "both" | "positive" | "negative"
    name: str


@frozen
class MomentLoad:
    """An external moment on a link: fixed, or resisting its rotation."""

    link: int
    value: float | None
    resisting: float | None
    name: str
    table: tuple[R, R] | None = None  # a turning-moment diagram (φ deg, N·m)
    expression: Any = None  # or a formula of φ (rad), plans.expression.Expression
    period: float = 360.0  # the cycle the diagram covers, deg
    stroke: str = "both"  # "working" | "idle": only on that stroke of the output


@frozen
class Balancing:
    """Where the balancing load acts: a force at a point of the driving link, or a moment."""

    kind: str  # "force" | "moment"
    point: str  # on the driving link


@frozen
class Loads:
    """Everything the force analysis needs that is not geometry."""

    masses: dict[int, float]
    inertias: dict[int, float]
    centres: dict[int, str]  # link -> centre point name (links with mass or inertia)
    g: complex  # gravity vector, m/s² (0 when off)
    offset_inertia: bool
    lever_turn: int  # +1 ccw, -1 cw
    balancing: Balancing
    gas: tuple[GasLoad, ...]
    forces: tuple[ForceLoad, ...]
    moments: tuple[MomentLoad, ...]


@frozen
class AppliedForce:
    """A force bound to a point of a link (a sympy-style bound vector), over positions."""

    label: str  # "G2", "Phi2", "P3", "F_c"
    link: int
    point: str  # the point's name ("S2", "B"); "S2*" for an offset inertia force
    r: C  # global position of the point of application, m
    local: C  # its local coordinates on the link (for the lever's similarity)
    F: C  # N
    kind: str  # "gravity" | "inertia" | "gas" | "external"


@frozen
class AppliedMoment:
    """A moment on a link at every position (inertia or external)."""

    label: str  # "M_Phi2", "M_c4"
    link: int
    M: R  # N·m, ccw+
    kind: str  # "inertia" | "external"


@frozen
class AppliedLoads:
    """Every force and moment applied to the links at every position."""

    forces: tuple[AppliedForce, ...]
    moments: tuple[AppliedMoment, ...]

    def on(self, link: int) -> tuple[list[AppliedForce], list[AppliedMoment]]:
        return ([f for f in self.forces if f.link == link], [m for m in self.moments if m.link == link])

    @property
    def largest(self) -> R:
        """The largest load magnitude at each position (N, N·m/m are not mixed: forces only)."""
        if not self.forces:
            return np.zeros(0)
        return np.max(np.abs(np.stack([f.F for f in self.forces])), axis=0)


def mechanism_extent(kin: Any) -> float:
    """The mechanism's reach from the origin (m) over the positions, for what counts as dust."""
    reach = getattr(kin, "reach", None)  # worked out once by the exact analysis
    if reach is not None:
        return reach()
    return max((float(np.max(np.abs(kin.point(nm)[0]))) for nm in kin.point_names()), default=1.0) or 1.0


def local_at(n: int, z: complex) -> C:
    """A point's local coordinates at each of n positions (np.full without its Python wrapper)."""
    out = np.empty(n, complex)
    out.fill(z)
    return out
