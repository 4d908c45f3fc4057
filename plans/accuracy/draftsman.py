"""The hand-drawing Monte Carlo: the construction drawn at sheet scale with a pencil and a
protractor that err, repeated over many drawings; the spread of each reading."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from plans.accuracy.oracles import norms
from plans.kinematics import exact as kinematics
from plans.kinematics.construction import nice_scale
from plans.scene.model import Scene

if TYPE_CHECKING:  # mpmath is an optional dependency (the ``bench`` extra): imported where used
    pass

#: Linear size of a sheet relative to A1 (A4 is A1 halved three times in area).
SHEETS = {"A1": 1.0, "A2": 2**-0.5, "A3": 0.5, "A4": 2**-1.5}

# --------------------------------------------------------------------------- the draftsman


@dataclass(frozen=True)
class DraftsmanModel:
    """What a careful hand drawing gets wrong, per primitive (uniform in ±value):

    * ``pencil_mm``: a marked point (each coordinate), a length laid off or read with the rule;
    * ``protractor_deg``: a direction drawn with set square or protractor;
    the directions ⟂ link / ∥ guide are also transferred from the scheme drawn at its
    own scale, whose two end points carry the pencil error."""

    pencil_mm: float = 0.25
    protractor_deg: float = 0.25


@dataclass(frozen=True)
class ExpectedError:
    """The spread of one quantity read off hand-drawn plans (Monte Carlo)."""

    quantity: str
    unit: str
    exact: float
    mean: float  # mean signed error (SI)
    std: float
    p95_abs: float  # 95 % of drawings are within this absolute error (SI)
    p95_rel: float  # ... and within this relative error (|error| / max(|exact|, known vector))
    p95_mm: float  # ... which is this many millimetres on the plan (0 for ω, ε)
    max_abs: float


class _Sheet:
    """One Monte Carlo batch of drawings of both plans at one position (arrays over samples)."""

    def __init__(self, kin: kinematics.Kinematics, k: int, mus: tuple[float, float, float],
                 model: DraftsmanModel, samples: int, rng: np.random.Generator) -> None:
        self.kin, self.k, self.model, self.M, self.rng = kin, k, model, samples, rng
        self.mul, self.muv, self.mua = mus
        self.scene = kin.scene

    def u(self, half: float) -> np.ndarray:
        return self.rng.uniform(-half, half, self.M)

    def mark(self, z: np.ndarray | complex) -> np.ndarray:
        """A point marked with the pencil."""
        p = self.model.pencil_mm
        return z + self.u(p) + 1j * self.u(p)

    def rule(self, length: np.ndarray | float) -> np.ndarray:
        return np.abs(length + self.u(self.model.pencil_mm))

    def direction(self, d: complex, length_on_scheme: float) -> np.ndarray:
        """Unit direction of a line drawn ∥ d (d taken from the scheme, length in m)."""
        p = self.model.pencil_mm
        ang = np.radians(self.u(self.model.protractor_deg))
        if length_on_scheme > 0:
            ang = ang + (self.u(p) - self.u(p)) / (length_on_scheme * self.mul)
        return (d / abs(d)) * np.exp(1j * ang)

    def pos(self, link: int, name: str) -> complex:
        r, _, _ = self.kin.point(name, link)
        return complex(r[self.k])


def _intersect(p1: np.ndarray, d1: np.ndarray, p2: np.ndarray, d2: np.ndarray) -> np.ndarray:
    """Intersection of the lines p1 + s d1 and p2 + t d2 (arrays)."""
    den = (d1.conjugate() * d2).imag
    s = ((p2 - p1).conjugate() * d2).imag / den
    return p1 + s * d1


def draftsman_errors(scene: Scene, phi_deg: float, sheet: str | float = "A1",
                     model: DraftsmanModel | None = None, samples: int = 2000,
                     seed: int = 0, scales: tuple[float, float, float] | None = None) -> dict[str, ExpectedError]:
    """Monte Carlo of hand-drawn velocity and acceleration plans at one crank angle.

    The scheme is drawn at μl (the scene's length scale on A1, or the mechanism's
    extent at about 200 mm) times the sheet factor; the plans at the draftsman's nice
    scales for a 100 mm known vector times the same factor.  Every marked point, laid-off
    or read length and drawn direction carries the model's error; each drawing is
    built as the construction builds it (lines ⟂ link and ∥ guide, intersections,
    similarity; normal and Coriolis components from ω and v_r read off the drawn velocity
    plan), its readings compared with the exact values.  ``scales`` = (μl, μv, μa) draws
    at a given sheet's scales instead (the checker's: a student's).  All five class-II dyads, on fixed
    and moving guides.  Quantities are named as the plans name them (``v_A3``,
    ``v_A2A3``, ``a^k_A3A2``, ``a^r_A3A2``, ``omega_3``, ``eps_3``).
    """
    model = model or DraftsmanModel()
    factor = SHEETS[sheet] if isinstance(sheet, str) else float(sheet)
    kin = kinematics.solve(scene, [phi_deg], order=2)
    nm = norms(scene)
    extent = max(abs(complex(z)) for name in kin.point_names() for z in kin.point(name)[0]) or nm["r"]
    mul = scene.scales.get("length") or nice_scale(extent, 200.0)
    mul *= factor
    muv = nice_scale(nm["v"], 100.0 * factor)
    mua = nice_scale(nm["a"], 100.0 * factor)
    if scales is not None:  # a given sheet (a student's μl, μv, μa in mm per unit): no sheet factor
        mul, muv, mua = scales
    rng = np.random.default_rng(seed)
    sh = _Sheet(kin, 0, (mul, muv, mua), model, samples, rng)
    readings: dict[str, tuple[np.ndarray, float, str, float]] = {}  # q -> (values, exact, unit, mm per unit)
    _draw(sh, readings)
    out = {}
    for q, (vals, exact, unit, mm) in readings.items():
        err = vals - exact
        if q.startswith(("omega_", "eps_")):  # the plan's size in this unit: v_A / l_k, a_A / l_k
            link = scene.links[int(q.split("_")[1])]
            lk = link.length or nm["r"]
            ref = (nm["v"] if q.startswith("omega") else nm["a"]) / lk
        else:
            ref = nm[q[0]]
        a = np.abs(err)
        p95 = float(np.quantile(a, 0.95))
        out[q] = ExpectedError(q, unit, exact, float(np.mean(err)), float(np.std(err)), p95,
                               p95 / max(abs(exact), ref), p95 * mm, float(np.max(a)))
    return out


def expected_errors(scene: Scene, phi_deg: float, sheet: str | float = "A1",
                    model: DraftsmanModel | None = None, samples: int = 2000,
                    seed: int = 0, scales: tuple[float, float, float] | None = None
                    ) -> dict[str, tuple[float, float]]:
    """For the checker: ``{quantity: (relative, absolute)}`` that 95 % of careful hand
    drawings of this scene at ``phi_deg`` on ``sheet`` (or at ``scales``) stay within."""
    res = draftsman_errors(scene, phi_deg, sheet, model, samples, seed, scales)
    return {q: (e.p95_rel, e.p95_abs) for q, e in res.items()}


class _Drawing:
    """One Monte Carlo batch of hand drawings of both plans, group by group, as
    :mod:`plans.construction` builds them: every laid-off length carries the pencil error,
    every drawn direction the protractor error (plus the pencil error of the two end points it
    is transferred from on the scheme), every point found by intersection or similarity the
    pencil error of marking it.  ω and the relative velocities the acceleration plan needs
    (normal and Coriolis components) are *read off the drawn velocity plan*, so their errors
    carry over.  All five class-II dyads; guides fixed or moving (Coriolis)."""

    def __init__(self, sh: _Sheet, readings: dict) -> None:
        self.sh, self.kin, self.scene, self.k = sh, sh.kin, sh.scene, sh.k
        self.readings = readings
        self.zero = np.zeros(sh.M, complex)
        # link -> (anchor image, anchor position, similarity factor), per plan
        self.vimg: dict[int, tuple[np.ndarray, complex, np.ndarray]] = {}
        self.aimg: dict[int, tuple[np.ndarray, complex, np.ndarray]] = {}
        self.omega_read: dict[int, np.ndarray] = {}
        self.vrel: dict[str, np.ndarray] = {}  # sliding velocity as drawn (plan mm), by joint name

    # -- the scheme and exact values
    def gpos(self, name: str) -> complex:
        return complex(self.kin.point(name)[0][self.k])

    def rates_on(self, link: int, X: complex) -> tuple[complex, complex]:
        """Exact v, a of the point of ``link`` at global X (the coincident point)."""
        if link == self.scene.frame:
            return 0j, 0j
        m = self.kin.motion[link]
        k = self.k
        w, e = float(m.omega[k]), float(m.eps[k])
        rel = X - complex(m.r0[k])
        return complex(m.v0[k]) + 1j * w * rel, complex(m.a0[k]) + (1j * e - w * w) * rel

    def guide(self, jt: Any) -> tuple[complex, float]:
        """Direction of a guide now, and the length it is transferred over on the scheme
        (0 for the frame's: drawn with the protractor alone)."""
        g = jt.guide
        assert g is not None
        if g.link == self.scene.frame:
            return g.direction, 0.0
        rot = complex(self.kin.motion[g.link].rot[self.k])
        link = self.scene.links[g.link]
        span = abs(link.length) if link.length else 0.0
        return rot * g.direction, span

    def line_dir(self, d: complex, span: float) -> np.ndarray:
        return self.sh.direction(d, span)

    def turned(self, vec: np.ndarray, sense: float) -> np.ndarray:
        """The direction of a drawn vector turned 90° with the set square (protractor error)."""
        ang = np.radians(self.sh.u(self.sh.model.protractor_deg))
        n = np.abs(vec)
        unit = np.where(n > 0, vec / np.where(n > 0, n, 1.0), 1.0)
        return unit * 1j * (sense or 1.0) * np.exp(1j * ang)

    def slide(self, jt: Any) -> tuple[float, float]:
        sd, sdd = self.kin.slides[jt.name]
        return float(sd[self.k]), (0.0 if sdd is None else float(sdd[self.k]))

    def read(self, q: str, vals: np.ndarray, exact: float, unit: str, mm: float) -> None:
        self.readings[q] = (vals, exact, unit, mm)

    # -- images
    @staticmethod
    def image(img: dict, link: int, X: complex) -> np.ndarray:
        anc, pos, f = img[link]
        return anc + f * (X - pos)

    def coincident(self, img: dict, link: int, X: complex) -> np.ndarray:
        """Image of the point of ``link`` under X (similarity, then marked); the pole on the frame."""
        if link == self.scene.frame:
            return self.zero
        return self.sh.mark(self.image(img, link, X))

    # -- velocity plan
    def velocity(self) -> None:
        sh, scene = self.sh, self.scene
        d = scene.driver
        O, An = scene.links[d.link].axis
        Opos, Apos = self.gpos(O), self.gpos(An)
        l1 = abs(Apos - Opos)
        self.vimg[scene.frame] = (self.zero, 0j, self.zero)
        a_xy = sh.rule(abs(d.omega) * l1 * sh.muv) * sh.direction(1j * np.sign(d.omega or 1.0) * (Apos - Opos), l1)
        self.vimg[d.link] = (a_xy, Apos, a_xy / (Apos - Opos))
        self.omega_read[d.link] = np.full(sh.M, float(d.omega))
        self.omega_read[scene.frame] = np.zeros(sh.M)
        for g in self.kin.structure.groups:
            getattr(self, f"_v_{g.kind.lower()}")(g)
        for name in self.kin.point_names():
            link = self.kin.home(name)
            img = self.image(self.vimg, link, self.gpos(name))
            if name not in (j.point for j in scene.joints):
                img = sh.mark(img)  # a similarity point is marked by dividing the segment
            self.read(f"v_{name}", sh.rule(np.abs(img)) / sh.muv, abs(self.rates_on(link, self.gpos(name))[0]),
                      "m/s", sh.muv)

    def _omega(self, lid: int, rel: np.ndarray, length: float) -> None:
        """ω of a link: its relative segment measured, over μv·l, with the sense the plan shows."""
        ex = float(self.kin.omega(lid)[self.k])
        self.omega_read[lid] = np.sign(ex) * self.sh.rule(np.abs(rel)) / (self.sh.muv * length)
        self.read(f"omega_{lid}", self.omega_read[lid], ex, "rad/s", 0.0)

    def _sliding_v(self, q: str, vec: np.ndarray, jt: Any) -> None:
        self.vrel[jt.name] = vec
        self.read(q, self.sh.rule(np.abs(vec)) / self.sh.muv, abs(self.slide(jt)[0]), "m/s", self.sh.muv)

    def _v_rrr(self, g: Any) -> None:
        sh = self.sh
        i, j = g.links
        j1, j2, j3 = g.joints
        p, q = g.known
        P1, B, P3 = self.gpos(j1.point), self.gpos(j2.point), self.gpos(j3.point)
        x1, x3 = self.image(self.vimg, p, P1), self.image(self.vimg, q, P3)
        b = sh.mark(_intersect(x1, sh.direction(1j * (B - P1), abs(B - P1)),
                               x3, sh.direction(1j * (B - P3), abs(B - P3))))
        self.vimg[i] = (b, B, (b - x1) / (B - P1))
        self.vimg[j] = (b, B, (b - x3) / (B - P3))
        self._omega(i, b - x1, abs(B - P1))
        self._omega(j, b - x3, abs(B - P3))

    def _v_rrp(self, g: Any) -> None:
        sh = self.sh
        i, j = g.links
        j1, j2, j3 = g.joints
        p, q = g.known
        P1, B = self.gpos(j1.point), self.gpos(j2.point)
        x1 = self.image(self.vimg, p, P1)
        xq = self.coincident(self.vimg, q, B)
        u, span = self.guide(j3)
        b = sh.mark(_intersect(x1, sh.direction(1j * (B - P1), abs(B - P1)), xq, self.line_dir(u, span)))
        self.vimg[i] = (b, B, (b - x1) / (B - P1))
        self.vimg[j] = (b, B, self.vimg[q][2])
        self._omega(i, b - x1, abs(B - P1))
        self.omega_read[j] = self.omega_read[q]
        if q != self.scene.frame:
            self._sliding_v(f"v_{j2.point}{j}{j2.point}{q}", b - xq, j3)
            self.read(f"v_{j2.point}{q}", sh.rule(np.abs(xq)) / sh.muv, abs(self.rates_on(q, B)[0]), "m/s", sh.muv)

    def _v_rpr(self, g: Any) -> None:
        sh = self.sh
        i, j = g.links
        j1, j2, j3 = g.joints
        p, q = g.known
        A, C = self.gpos(j1.point), self.gpos(j3.point)
        xa, xc = self.image(self.vimg, p, A), self.image(self.vimg, q, C)
        u, _ = self.guide(j2)
        a3 = sh.mark(_intersect(xc, sh.direction(1j * (A - C), abs(A - C)), xa, sh.direction(u, abs(A - C))))
        f = (a3 - xc) / (A - C)
        self.vimg[j] = (a3, A, f)
        self.vimg[i] = (xa, A, f)
        self._omega(j, a3 - xc, abs(A - C))
        self.omega_read[i] = self.omega_read[j]
        self.read(f"v_{j1.point}{j}", sh.rule(np.abs(a3)) / sh.muv, abs(self.rates_on(j, A)[0]), "m/s", sh.muv)
        self._sliding_v(f"v_{j1.point}{i}{j1.point}{j}", xa - a3, j2)

    def _v_prp(self, g: Any) -> None:
        sh = self.sh
        i, j = g.links
        j1, j2, j3 = g.joints
        p, q = g.known
        B = self.gpos(j2.point)
        x1, x3 = self.coincident(self.vimg, p, B), self.coincident(self.vimg, q, B)
        u1, s1 = self.guide(j1)
        u3, s3 = self.guide(j3)
        b = sh.mark(_intersect(x1, self.line_dir(u1, s1), x3, self.line_dir(u3, s3)))
        self.vimg[i] = (b, B, self.vimg[p][2])
        self.vimg[j] = (b, B, self.vimg[q][2])
        self.omega_read[i], self.omega_read[j] = self.omega_read[p], self.omega_read[q]
        for x, jt, carrier, link in ((x1, j1, p, i), (x3, j3, q, j)):
            if carrier != self.scene.frame:
                self._sliding_v(f"v_{j2.point}{link}{j2.point}{carrier}", b - x, jt)
                self.read(f"v_{j2.point}{carrier}", sh.rule(np.abs(x)) / sh.muv,
                          abs(self.rates_on(carrier, B)[0]), "m/s", sh.muv)

    def _v_rpp(self, g: Any) -> None:
        sh = self.sh
        i, j = g.links
        j1, j2, j3 = g.joints
        p, q = g.known
        A = self.gpos(j1.point)
        xa = self.image(self.vimg, p, A)
        xq = self.coincident(self.vimg, q, A)
        u2, s2 = self.guide(j2)
        u3, s3 = self.guide(j3)
        aj = sh.mark(_intersect(xq, self.line_dir(u3, s3), xa, self.line_dir(u2, s2)))
        self.vimg[j] = (aj, A, self.vimg[q][2])
        self.vimg[i] = (xa, A, self.vimg[q][2])
        self.omega_read[i] = self.omega_read[j] = self.omega_read[q]
        self.read(f"v_{j1.point}{j}", sh.rule(np.abs(aj)) / sh.muv, abs(self.rates_on(j, A)[0]), "m/s", sh.muv)
        self._sliding_v(f"v_{j1.point}{i}{j1.point}{j}", xa - aj, j2)
        if q != self.scene.frame:
            self._sliding_v(f"v_{j1.point}{j}{j1.point}{q}", aj - xq, j3)

    # -- acceleration plan
    def acceleration(self) -> None:
        sh, scene = self.sh, self.scene
        d = scene.driver
        O, An = scene.links[d.link].axis
        Opos, Apos = self.gpos(O), self.gpos(An)
        l1 = abs(Apos - Opos)
        w1, e1 = d.omega, d.eps
        self.aimg[scene.frame] = (self.zero, 0j, self.zero)
        a_xy = sh.rule(w1 * w1 * l1 * sh.mua) * sh.direction(Opos - Apos, l1)
        if e1:
            a_xy = a_xy + sh.rule(abs(e1) * l1 * sh.mua) * sh.direction(1j * np.sign(e1) * (Apos - Opos), l1)
        self.aimg[d.link] = (a_xy, Apos, a_xy / (Apos - Opos))
        for g in self.kin.structure.groups:
            getattr(self, f"_a_{g.kind.lower()}")(g)
        for name in self.kin.point_names():
            link = self.kin.home(name)
            img = self.image(self.aimg, link, self.gpos(name))
            if name not in (j.point for j in scene.joints):
                img = sh.mark(img)
            self.read(f"a_{name}", sh.rule(np.abs(img)) / sh.mua, abs(self.rates_on(link, self.gpos(name))[1]),
                      "m/s^2", sh.mua)

    def _normal(self, x: np.ndarray, link: int, P: complex, X: complex) -> np.ndarray:
        """From the image of P, a_XP^n = ω²·l (ω read off the velocity plan) toward P."""
        lx = abs(X - P)
        return x + self.sh.rule(self.omega_read[link] ** 2 * lx * self.sh.mua) * self.sh.direction(P - X, lx)

    def _coriolis(self, x: np.ndarray, carrier: int, jt: Any, sign: float, q: str) -> np.ndarray:
        """a^k = 2 ω v_r: both read off the velocity plan, laid off from x with v_r turned 90°
        in the sense of ω (the drawn v_r's direction, turned with the set square)."""
        sh = self.sh
        vr = sign * self.vrel[jt.name]  # the relative velocity the Coriolis term is of (plan mm)
        w = self.omega_read[carrier]
        length = sh.rule(2 * np.abs(w) * sh.rule(np.abs(vr)) / sh.muv * sh.mua)
        vec = length * self.turned(vr, float(np.sign(float(self.kin.omega(carrier)[self.k]))))
        self.read(q, np.abs(vec) / sh.mua, abs(2 * float(self.kin.omega(carrier)[self.k]) * self.slide(jt)[0]),
                  "m/s^2", sh.mua)
        return x + vec

    def _eps(self, lid: int, tang: np.ndarray, length: float) -> None:
        ex = float(self.kin.eps(lid)[self.k])
        self.read(f"eps_{lid}", np.sign(ex) * self.sh.rule(np.abs(tang)) / (self.sh.mua * length), ex,
                  "rad/s^2", 0.0)

    def _sliding_a(self, q: str, vec: np.ndarray, jt: Any) -> None:
        self.read(q, self.sh.rule(np.abs(vec)) / self.sh.mua, abs(self.slide(jt)[1]), "m/s^2", self.sh.mua)

    def _a_rrr(self, g: Any) -> None:
        sh = self.sh
        i, j = g.links
        j1, j2, j3 = g.joints
        p, q = g.known
        P1, B, P3 = self.gpos(j1.point), self.gpos(j2.point), self.gpos(j3.point)
        x1, x3 = self.image(self.aimg, p, P1), self.image(self.aimg, q, P3)
        n1, n3 = self._normal(x1, i, P1, B), self._normal(x3, j, P3, B)
        b = sh.mark(_intersect(n1, sh.direction(1j * (B - P1), abs(B - P1)),
                               n3, sh.direction(1j * (B - P3), abs(B - P3))))
        self.aimg[i] = (b, B, (b - x1) / (B - P1))
        self.aimg[j] = (b, B, (b - x3) / (B - P3))
        self._eps(i, b - n1, abs(B - P1))
        self._eps(j, b - n3, abs(B - P3))

    def _a_rrp(self, g: Any) -> None:
        sh = self.sh
        i, j = g.links
        j1, j2, j3 = g.joints
        p, q = g.known
        P1, B = self.gpos(j1.point), self.gpos(j2.point)
        x1 = self.image(self.aimg, p, P1)
        n1 = self._normal(x1, i, P1, B)
        start = self.coincident(self.aimg, q, B)
        if q != self.scene.frame:
            start = self._coriolis(start, q, j3, 1.0, f"a^k_{j2.point}{j}{j2.point}{q}")
        u, span = self.guide(j3)
        b = sh.mark(_intersect(n1, sh.direction(1j * (B - P1), abs(B - P1)), start, self.line_dir(u, span)))
        self.aimg[i] = (b, B, (b - x1) / (B - P1))
        self.aimg[j] = (b, B, self.aimg[q][2])
        self._eps(i, b - n1, abs(B - P1))
        if q != self.scene.frame:
            self._sliding_a(f"a^r_{j2.point}{j}{j2.point}{q}", b - start, j3)

    def _a_rpr(self, g: Any) -> None:
        sh = self.sh
        i, j = g.links
        j1, j2, j3 = g.joints
        p, q = g.known
        A, C = self.gpos(j1.point), self.gpos(j3.point)
        xa, xc = self.image(self.aimg, p, A), self.image(self.aimg, q, C)
        mc = self._normal(xc, j, C, A)
        # a_Aj = a_Ai + a^k + a^r: the Coriolis term of Aj relative to Ai (v from a to aj)
        mk = self._coriolis(xa, j, j2, -1.0, f"a^k_{j1.point}{j}{j1.point}{i}")
        u, _ = self.guide(j2)
        a3 = sh.mark(_intersect(mc, sh.direction(1j * (A - C), abs(A - C)), mk, sh.direction(u, abs(A - C))))
        f = (a3 - xc) / (A - C)
        self.aimg[j] = (a3, A, f)
        self.aimg[i] = (xa, A, f)
        self._eps(j, a3 - mc, abs(A - C))
        self._sliding_a(f"a^r_{j1.point}{j}{j1.point}{i}", a3 - mk, j2)
        self.read(f"a_{j1.point}{j}", sh.rule(np.abs(a3)) / sh.mua, abs(self.rates_on(j, A)[1]), "m/s^2", sh.mua)

    def _a_prp(self, g: Any) -> None:
        sh = self.sh
        i, j = g.links
        j1, j2, j3 = g.joints
        p, q = g.known
        B = self.gpos(j2.point)
        ends = []
        for jt, carrier, link in ((j1, p, i), (j3, q, j)):
            x = self.coincident(self.aimg, carrier, B)
            if carrier != self.scene.frame:
                x = self._coriolis(x, carrier, jt, 1.0, f"a^k_{j2.point}{link}{j2.point}{carrier}")
            ends.append(x)
        u1, s1 = self.guide(j1)
        u3, s3 = self.guide(j3)
        b = sh.mark(_intersect(ends[0], self.line_dir(u1, s1), ends[1], self.line_dir(u3, s3)))
        self.aimg[i] = (b, B, self.aimg[p][2])
        self.aimg[j] = (b, B, self.aimg[q][2])
        for x, jt, carrier, link in ((ends[0], j1, p, i), (ends[1], j3, q, j)):
            if carrier != self.scene.frame:
                self._sliding_a(f"a^r_{j2.point}{link}{j2.point}{carrier}", b - x, jt)

    def _a_rpp(self, g: Any) -> None:
        sh = self.sh
        i, j = g.links
        j1, j2, j3 = g.joints
        p, q = g.known
        A = self.gpos(j1.point)
        xa = self.image(self.aimg, p, A)
        s3 = self.coincident(self.aimg, q, A)
        if q != self.scene.frame:
            s3 = self._coriolis(s3, q, j3, 1.0, f"a^k_{j1.point}{j}{j1.point}{q}")
        s2 = xa
        if q != self.scene.frame or float(self.kin.omega(j)[self.k]) != 0.0:
            s2 = self._coriolis(xa, j, j2, -1.0, f"a^k_{j1.point}{j}{j1.point}{i}")
        u2, sp2 = self.guide(j2)
        u3, sp3 = self.guide(j3)
        aj = sh.mark(_intersect(s3, self.line_dir(u3, sp3), s2, self.line_dir(u2, sp2)))
        self.aimg[j] = (aj, A, self.aimg[q][2])
        self.aimg[i] = (xa, A, self.aimg[q][2])
        self.read(f"a_{j1.point}{j}", sh.rule(np.abs(aj)) / sh.mua, abs(self.rates_on(j, A)[1]), "m/s^2", sh.mua)
        self._sliding_a(f"a^r_{j1.point}{j}{j1.point}{i}", aj - s2, j2)


def _draw(sh: _Sheet, readings: dict) -> None:
    dr = _Drawing(sh, readings)
    dr.velocity()
    dr.acceleration()
    for q in [q for q in readings if q.startswith(("v_", "a_"))]:
        if q[2:] in sh.scene.frame_points:  # fixed points are the pole itself
            del readings[q]



