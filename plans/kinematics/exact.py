"""Exact kinematic analysis, vectorised over crank positions.

Written independently of the graphical construction (:mod:`plans.construction`):
positions in closed form per group, velocities and accelerations from the
vector loop of each group as a 2×2 linear system (Cramer's rule).  Plane
vectors are complex numbers: ``1j * z`` is z turned 90° counter-clockwise
(``k × z``), ``cross(a, b) = Im(conj(a)·b)``.

For a point X of link k (origin r0, angle θ, rates ω, ε):
    r_X = r0 + e^{iθ} z_X,   v_X = v0 + iω (r_X − r0),   a_X = a0 + (iε − ω²)(r_X − r0).

The group solvers (:mod:`plans.kinematics.assur`, one per kind of Assur group; the usual
crank with RRR/RRP dyads takes :mod:`plans.kinematics.fast` first) are written once and
run two ways: on numpy arrays over all positions
at once, and, for a handful of positions (what a demonstration or a GUI asks for), on plain
Python numbers position by position, where numpy's per-call cost would dominate
(:data:`SCALAR_MAX`).  Both give the same numbers to rounding.
"""

from __future__ import annotations

import copy
import math
from functools import cached_property
from typing import Any

import numpy as np

from plans.kinematics import fast, fast_arrays
from plans.kinematics.assur import program
from plans.kinematics.context import SCA, VEC, Context, Motion
from plans.kinematics.structure import Structure, analyse
from plans.scene.model import Scene

# numpy arrays over positions; typed loosely because numpy's operator stubs do not
# follow Optional fields that the order of analysis fills in.
C = Any  # complex128 array, shape (N,)
R = Any  # float64 array, shape (N,)

#: Up to this many positions are solved one by one in plain Python numbers.
SCALAR_MAX = 4


class Kinematics:
    """Positions (and, if asked, velocities and accelerations) of every link and point.

    Not a frozen record: the object that owns what one exact solve gave and the readings
    made of it, each when first read and then kept here: the fast path's numbers made into
    arrays (:attr:`motion`, :attr:`slides`, :attr:`conditions`, and one position's
    :attr:`phi_deg`), the points as they are read (:meth:`point_on`: forces and the lever
    read the same points many times), the reach."""

    scene: Scene
    structure: Structure
    order: int  # 0 positions, 1 + velocities, 2 + accelerations

    def __init__(self, scene: Scene, structure: Structure, phi_deg: R | None, order: int,
                 motion: dict[int, Motion] | None = None, slides: dict[str, tuple[R, R]] | None = None,
                 conditions: dict[str, R] | None = None, *, raw: tuple[dict, dict, dict] | None = None,
                 phi: float | None = None) -> None:
        """The solve's motions, slides and conditions (a fast path's: ``raw``, made readings
        when first read; one position's angle: ``phi`` instead of ``phi_deg``)."""
        self.scene = scene
        self.structure = structure
        self.order = order
        self._raw = raw
        self._phi = phi
        self._points: dict[tuple[int, complex], tuple[C, C, C]] = {}
        self._homes: dict[str, int] = {}
        self._reach: float | None = None
        #: group name -> a class III group's special point over the positions and the leashes
        #: that give it (plans.kinematics.triad_plans.assur_points_json), found when first read
        self.special_points: dict[str, Any] = {}
        if phi_deg is not None:  # else made when first read (the cached properties below)
            self.phi_deg = phi_deg
        if motion is not None:
            self.motion = motion
        if slides is not None:
            self.slides = slides
        if conditions is not None or raw is None:
            self.conditions = {} if conditions is None else conditions

    def __repr__(self) -> str:
        return f"Kinematics({self.scene.path!r}, {self.n} positions, order {self.order})"

    def on_paper(self, scene: Scene) -> Kinematics:
        """This solve read with ``scene``, the same mechanism at another fit (the plans' target
        lengths, :func:`plans.kinematics.scales.fit`): nothing solved again, every array and
        reading made so far and made later shared by both."""
        if scene is self.scene:
            return self
        if scene.links is not self.scene.links or scene.driver is not self.scene.driver:
            raise ValueError("Kinematics.on_paper takes the same scene at another fit")
        other = copy.copy(self)  # the readings' tables (points, homes, special points) are the same objects
        other.scene = scene
        return other

    @cached_property
    def phi_deg(self) -> R:
        """The crank angles (degrees), an array over the positions."""
        return np.array((self._phi,))

    @cached_property
    def motion(self) -> dict[int, Motion]:
        """Link number -> its motion (arrays over the positions)."""
        assert self._raw is not None
        return _columns(len(self.phi_deg), self._raw[0])

    @cached_property
    def slides(self) -> dict[str, tuple[R, R]]:
        """P joint name -> (ṡ, s̈) over the positions."""
        assert self._raw is not None
        return {nm: (np.array((sd,)), None if sdd is None else np.array((sdd,)))
                for nm, (sd, sdd) in self._raw[1].items()}

    @cached_property
    def conditions(self) -> dict[str, R]:
        """Group name -> the condition number of its velocity/acceleration system per position:
        |c1||c2| / |c1 × c2| = 1 / sin(angle between the two construction lines)."""
        assert self._raw is not None
        if self._phi is not None:
            return {g: np.array((c,)) for g, c in self._raw[2].items()}
        return {g: c() if type(c) is fast.Later else c for g, c in self._raw[2].items()}

    @property
    def n(self) -> int:
        return len(self.phi_deg)

    def home(self, name: str) -> int:
        """The link a named point is read from (lowest number, frame last)."""
        homes = self._homes
        got = homes.get(name)
        if got is None:
            links = self.scene.point_links(name)
            if not links:
                raise KeyError(name)
            moving = [k for k in links if k != self.scene.frame]
            got = homes[name] = min(moving) if moving else self.scene.frame
        return got

    def local(self, link: int, name: str) -> complex:
        if link == self.scene.frame:
            return self.scene.frame_points[name]
        return self.scene.links[link].points[name]

    def point_on(self, link: int, z: complex) -> tuple[C, C, C]:
        """r, v, a of the point with local coordinates z on ``link`` (computed once)."""
        key = (link, z) if isinstance(z, complex | float | int) else None  # arrays: a point moving on the link
        done = None if key is None else self._points.get(key)
        if done is None:
            m = self.motion[link]
            if type(m) is _Cols:  # what is the same at every position stays a number here
                rot, r0, w, v0, e, a0 = m.raw()
            else:
                rot, r0, w, v0, e, a0 = m.rot, m.r0, m.omega, m.v0, m.eps, m.a0
            if key is not None and not z:  # the link's origin: its own motion
                r, v, a = r0, None if w is None else v0, None if e is None else a0
            else:
                rel = rot * z
                r = r0 + rel
                v = None if w is None else v0 + 1j * w * rel
                a = None if e is None else a0 + (1j * e - w * w) * rel
            done = (r, v, a) if type(r) is np.ndarray and (w is None or type(v) is np.ndarray) and \
                (e is None or type(a) is np.ndarray) else self._arrays(r, v, a)
            if key is not None:
                self._points[key] = done
        return done

    def _arrays(self, r: Any, v: Any, a: Any) -> tuple:
        """r, v, a as arrays over the positions (a number: the same at each)."""
        n = self.n

        def arr(x: Any) -> Any:
            if x is None or type(x) is np.ndarray:
                return x
            return np.array((x,), dtype=complex) if n == 1 else _full(n, x, complex)
        return arr(r), arr(v), arr(a)

    def point(self, name: str, link: int | None = None) -> tuple[C, C, C]:
        k = self.home(name) if link is None else link
        return self.point_on(k, self.local(k, name))

    def omega(self, link: int) -> R:
        m = self.motion[link]
        assert m.omega is not None
        return m.omega

    def eps(self, link: int) -> R:
        m = self.motion[link]
        assert m.eps is not None
        return m.eps

    def theta(self, link: int) -> R:
        return self.motion[link].theta

    def reach(self) -> float:
        """The mechanism's reach from the origin (m) over the positions: the largest |r| of
        its points (1 where all are at the origin), worked out once."""
        got = self._reach
        if got is None:
            got = self._reach = max((float(np.maximum.reduce(np.abs(self.point(nm)[0]))) for nm in self.point_names()),
                                    default=1.0) or 1.0
        return got

    def point_names(self) -> list[str]:
        names: list[str] = []
        for link in [self.scene.links[k] for k in sorted(self.scene.links)]:
            for nm in link.points:
                if nm not in names:
                    names.append(nm)
        return names


def solve(scene: Scene, phi_deg=None, order: int | None = None,
          structure: Structure | None = None) -> Kinematics:
    """Exact analysis at the scene's crank angles (or ``phi_deg``).

    ``order`` is what to compute: 0 positions, 1 velocities, 2 accelerations;
    by default what the scene's outputs need.
    """
    st = structure or analyse(scene)
    if order is None:
        order = 0
        if scene.wants("velocity_plan"):
            order = 1
        if scene.wants("acceleration_plan"):
            order = 2
    if phi_deg is None:
        if scene.driver.placing is not None:
            raise ValueError(f"{scene.path}: the positions are asked for by the piston's travel or from the "
                             "output's extreme and not placed yet: read the scene with plans.load_scene "
                             "(plans.kinematics.placing)")
        phi_deg = scene.driver.phis_deg
    fp = fast.plan_for(scene, st)
    if fp is not None and type(phi_deg) in (list, tuple) and len(phi_deg) == 1:
        # one position (a demonstration, a GUI): no numpy until a reading is asked for
        phi = phi_deg[0]
        if type(phi) is float or type(phi) is int:
            res = fast.solve_one(fp, phi, order)
            if res is not None:
                return Kinematics(scene, st, None, order, raw=res, phi=float(phi))
    if type(phi_deg) is np.ndarray and phi_deg.dtype == float and phi_deg.ndim == 1:
        phis = phi_deg  # as np.asarray gives it
    else:
        phis = np.atleast_1d(np.asarray(phi_deg, dtype=float))
    if fp is not None:
        res = _fast_runs(fp, phis, order) if len(phis) <= SCALAR_MAX else fast_arrays.solve(fp, phis, order)
        if res is not None:
            return Kinematics(scene, st, phis, order, slides=res[1], raw=res)
    steps = program(scene, st)
    if len(phis) <= SCALAR_MAX:
        return _solve_scalar(scene, st, steps, phis, order)
    ctx = Context(scene, VEC, phis, order, solve)
    n = len(phis)
    zeros = np.zeros(n)
    czeros = np.zeros(n, dtype=complex)
    ctx.motion[scene.frame] = Motion(np.ones(n, dtype=complex), czeros, zeros, czeros, zeros, czeros)
    _drive(ctx, _rotation(scene.driver, phis), np.full(n, scene.driver.omega), np.full(n, scene.driver.eps))
    for fn, g, k in steps:
        fn(ctx, g, k)
    return Kinematics(scene, st, phis, order, ctx.motion, ctx.slides, ctx.conditions)


def _columns(n: int, motion: dict) -> dict:
    return {lid: _Cols(n, m) for lid, m in motion.items()}


def _fast_runs(fp: fast.Plan, phis: Any, order: int) -> tuple[dict, dict, dict] | None:
    """A few positions by the fast path one by one, the numbers of each quantity listed."""
    runs = []
    for phi in phis.tolist():
        res = fast.solve_one(fp, phi, order)
        if res is None:
            return None
        runs.append(res)
    first = runs[0]
    motion = {lid: [None if m[f] is None else [r[0][lid][f] for r in runs] for f in range(6)]
              for lid, m in first[0].items()}
    slides = {nm: (np.array([r[1][nm][0] for r in runs], dtype=float),
                   None if sdd is None else np.array([r[1][nm][1] for r in runs], dtype=float))
              for nm, (_, sdd) in first[1].items()}
    conditions = {g: np.array([r[2][g] for r in runs], dtype=float) for g in first[2]}
    return motion, slides, conditions


# --------------------------------------------------------------------------- two ways to run


def _drive(ctx: Context, rot1, omega, eps) -> None:
    z = ctx.zpivot
    if z:
        rel = -rot1 * z  # the crank's origin from its pivot
        m1 = Motion(rot1, ctx.pivot + rel)
        if ctx.order >= 1:
            m1.omega, m1.v0 = omega, ctx.W * rel
            if ctx.order >= 2:
                m1.eps, m1.a0 = eps, ctx.E * rel
    else:  # the usual crank: its origin is the pivot
        m0 = ctx.motion[ctx.frame]
        m1 = Motion(rot1, m0.r0 + ctx.pivot if ctx.pivot else m0.r0)
        if ctx.order >= 1:
            m1.omega, m1.v0 = omega, m0.v0
            if ctx.order >= 2:
                m1.eps, m1.a0 = eps, m0.a0
    ctx.motion[ctx.crank] = m1


def _rotation(d: Any, phis: Any) -> C:
    """e^{iθ1} over positions (:func:`plans.kinematics.fast.rotation`)."""
    return fast.rotation(math.degrees(d.phi_ref), d.sense, phis)


def _rotation1(d: Any, phi: float) -> complex:
    """e^{iθ1} of one position (:func:`plans.kinematics.fast.rotation1`)."""
    return fast.rotation1(math.degrees(d.phi_ref), d.sense, phi)


def _solve_scalar(scene: Scene, st: Structure, steps: list, phis: Any, order: int) -> Kinematics:
    """Position by position in Python numbers; the motions stacked into arrays at the end
    (two numpy calls: numpy's per-call cost is what this path avoids)."""
    d = scene.driver
    runs = []
    for phi in phis.tolist():
        ctx = Context(scene, SCA, [phi], order, solve)
        ctx.motion[scene.frame] = Motion(1 + 0j, 0j, 0.0, 0j, 0.0, 0j)
        _drive(ctx, _rotation1(d, phi), d.omega, d.eps)
        for fn, g, k in steps:
            fn(ctx, g, k)
        runs.append(ctx)
    return _stack(scene, st, phis, order, runs)


def _stack(scene: Scene, st: Structure, phis: Any, order: int, runs: list) -> Kinematics:
    """The runs' numbers as arrays over positions; a motion's arrays are made when first
    read (each array costs about as much as a group's whole solution in Python numbers)."""
    first = runs[0]
    k = min(order, 2)
    n = len(runs)
    motion: dict[int, Motion] = {}
    for lid in first.motion:
        ms = [r.motion[lid] for r in runs]
        motion[lid] = _Cols(n, [[getattr(m, f) for m in ms] if i < _WIDTH[k] else None
                                for i, f in enumerate(_FIELDS)])
    motion[scene.frame] = _Cols(n, [1 + 0j, 0j, 0.0, 0j, 0.0, 0j])  # the frame's rates are known whatever is asked
    slides = {}
    for nm, (sd, _) in first.slides.items():
        if sd is not None:
            slides[nm] = (np.array([r.slides[nm][0] for r in runs], dtype=float),
                          np.array([r.slides[nm][1] for r in runs], dtype=float) if k == 2 else None)
    conditions = {g: np.array([r.conditions[g] for r in runs], dtype=float) for g in first.conditions}
    return Kinematics(scene, st, phis, order, motion, slides, conditions)


def _full(n: int, x: Any, dtype: Any) -> Any:
    """np.full(n, x, dtype) without its Python wrapper."""
    out = np.empty(n, dtype)
    out.fill(x)
    return out


_FIELDS = ("rot", "r0", "omega", "v0", "eps", "a0")
_WIDTH = (2, 4, 6)  # fields known at each order
_DTYPES = (complex, complex, float, complex, float, complex)


class _Cols(Motion):
    """A motion whose quantities become arrays over the ``n`` positions when first read:
    each is an array already, a list of numbers (one per position), one number (the same
    at every position: the frame, the crank's ω, a slider's angle) or None (not asked for)."""

    __slots__ = ("_n", "_vals")

    def __init__(self, n: int, vals: list) -> None:  # noqa: D107 - fields live in _vals
        self._n = n
        self._vals = vals

    def raw(self) -> list:
        """The six quantities as held: arrays, or numbers where the same at every position
        (lists of numbers made arrays first)."""
        vals = self._vals
        for i, v in enumerate(vals):
            if type(v) is list or type(v) is fast.Later:
                self._get(i)
        return vals

    def _get(self, i: int) -> Any:
        v = self._vals[i]
        if v is None or type(v) is np.ndarray:
            return v
        if type(v) is fast.Later:
            v = v()
        elif type(v) is list:
            v = np.array(v, dtype=_DTYPES[i])
        elif self._n == 1:
            v = np.array((v,), dtype=_DTYPES[i])
        else:
            v = _full(self._n, v, _DTYPES[i])
        self._vals[i] = v
        return v


def _field(i: int) -> property:
    def get(self: _Cols) -> Any:
        return self._get(i)

    def put(self: _Cols, value: Any) -> None:
        self._vals[i] = value
    return property(get, put)


for _i, _f in enumerate(_FIELDS):
    setattr(_Cols, _f, _field(_i))
