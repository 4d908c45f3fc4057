"""Scales of the plans as a draftsman picks them: round numbers, each plan within its length.

Every default scale is 1, 2, 2.5, 4 or 5 × 10^k (this set is closed under 1/x, so μ and
K = 1/μ are both round).  One scale serves every position while the longest vector of
each plan stays within ``LONGEST_MM``; a position whose plan would run longer gets a round
scale of its own.  ``[scales] velocity = { known_mm = 100 }`` keeps the course habit of a
given length for the known vector (pa = 100 mm) instead.  A drawing on a smaller sheet is
solved with ``plans.solve(scene, fit=...)`` (the scene's ``fit``): every target length is that
fraction of the A1 one.
"""

from __future__ import annotations

import math
from typing import Any

from plans.kinematics.exact import Kinematics
from plans.tolerances import AGREE_REL, ROUND_OFF_REL

#: Round mantissas of a scale (either direction of the ratio).
ROUND = (1.0, 2.0, 2.5, 4.0, 5.0)
#: The known vector (crank pin) is drawn at most this long (mm) at the common scale.
KNOWN_MM = 100.0
#: No plan's longest vector runs longer than this (mm); longer ones get their own scale.
LONGEST_MM = 150.0


def fit(scene: Any) -> float:
    """The factor of the target lengths (1 on A1): the scene's ``fit``, as it was solved."""
    return float(scene.fit)


def round_scale(longest: float, target_mm: float = KNOWN_MM, mantissas: tuple[float, ...] = ROUND) -> float:
    """μ (mm per unit), round in both directions (K = 1/μ one of ``mantissas`` × 10^k), the
    largest that draws ``longest`` within ``target_mm``; 1 for a zero, subnormal or non-finite
    length (no scale from a zero vector).  The one picker of the plans', polygons', lever's
    and every diagram's round scales."""
    if not (longest > 0 and math.isfinite(longest)):
        return 1.0
    k_min = longest / target_mm  # K may not be smaller than this
    if k_min <= 0:  # a subnormal longest vector: nothing to draw at any scale
        return 1.0
    m, e = _up(k_min, mantissas)
    inverse = 10.0 / m  # μ = (10/m) × 10^(−e−1), written as the round number it is
    if inverse * m != 10.0 or not -300 < e < 300:
        return 1.0 / (m * 10.0**e)
    n = -e - 1
    return inverse * 10.0**n if n >= 0 else inverse / 10.0**-n


def _up(x: float, mantissas: tuple[float, ...]) -> tuple[float, int]:
    """(m, e): the smallest m × 10^e not below ``x`` (to rounding), m one of ``mantissas`` or 10."""
    e = math.floor(math.log10(x))
    for m in mantissas + (10.0,):
        if m * 10.0**e >= x * (1 - ROUND_OFF_REL):
            return m, e
    return 10.0, e  # pragma: no cover (10 × 10^e is above x)


def round_up(x: float, mantissas: tuple[float, ...] = ROUND) -> float:
    """The smallest ``mantissas`` × 10^k not below ``x`` (x > 0): a diagram's division."""
    m, e = _up(x, mantissas)
    return m * 10.0**e


def round_down(x: float, mantissas: tuple[float, ...] = ROUND) -> float:
    """The largest ``mantissas`` × 10^k not above ``x`` (x > 0)."""
    e = math.floor(math.log10(x))
    for m in sorted(mantissas, reverse=True):
        if m * 10.0**e <= x * (1 + ROUND_OFF_REL):
            return m * 10.0**e
    return 10.0 ** (e - 1) * max(mantissas)


#: A diagram's divisions: 1, 2, 2.5, 5 × 10^k (a ruler's; the plans' 4 is not among them).
DIVISIONS = (1.0, 2.0, 2.5, 5.0)

#: A drawing's length scales (paper mm per m ÷ 1000), GOST 2.302's round ones: 10:1 … 1:100.
RATIOS = (10.0, 5.0, 4.0, 2.5, 2.0, 1.0, 0.5, 0.4, 0.25, 0.2, 0.1, 0.05, 0.04, 0.025, 0.02, 0.01)


def ratio_scale(size_m: float, target_mm: float, ratios: tuple[float, ...] = RATIOS) -> float | None:
    """μl (paper mm per m) of the largest of ``ratios`` that draws ``size_m`` within
    ``target_mm`` (a mechanism, a train, a cam at a standard drawing scale); None where
    none does."""
    for r in ratios:
        if size_m * 1000.0 * r <= target_mm:
            return 1000.0 * r
    return None


def is_round(mu: float) -> bool:
    """True for 1, 2, 2.5, 4, 5 × 10^k."""
    if not (mu > 0 and math.isfinite(mu)):
        return False
    e = math.floor(math.log10(mu))
    m = mu / 10.0**e
    return any(abs(m - r) < AGREE_REL * r for r in ROUND + (10.0,))


def known_vectors(kin: Kinematics) -> tuple[float, float]:
    """|v_A| and |a_A| of the crank pin (SI): the known vectors of the plans."""
    d = kin.scene.driver
    l1 = abs(kin.scene.links[d.link].points[kin.scene.links[d.link].axis[1]])
    return abs(d.omega) * l1, l1 * math.hypot(d.omega**2, d.eps)


def common_scales(kin: Kinematics) -> tuple[float, float]:
    """μv and μa for every position: the scene's, the known-vector length it gives, or round."""
    va, aa = known_vectors(kin)
    sc = kin.scene.scales
    out = []
    for key, known in (("velocity", va), ("acceleration", aa)):
        if key in sc:
            out.append(sc[key])
        elif f"{key}_known_mm" in sc and known > 0:
            out.append(sc[f"{key}_known_mm"] / known)
        else:
            out.append(round_scale(known, KNOWN_MM * fit(kin.scene)))
    return out[0], out[1]


def refit(kin: Kinematics, plans: list, build, only: Any = None) -> list:
    """``plans`` built at the common scales, each position whose plan would run past
    ``LONGEST_MM`` rebuilt at a round scale of its own (a scale the scene gives is kept).
    ``only``: the positions that may run past it (the others are not looked at, so their
    plan objects are not made)."""
    sc = kin.scene.scales
    longest = LONGEST_MM * fit(kin.scene)
    out = list(plans)
    for k in range(len(plans)) if only is None else only:
        pp = plans[k]
        v, a = pp.velocity, pp.acceleration
        mv = v.scale if v is not None else None
        ma = a.scale if a is not None else None
        mv2, ma2 = mv, ma
        if v is not None and mv and not _given(sc, "velocity") and v.extent > longest:
            mv2 = round_scale(v.extent / mv, longest)
        if a is not None and ma and not _given(sc, "acceleration") and a.extent > longest:
            ma2 = round_scale(a.extent / ma, longest)
        if (mv2, ma2) != (mv, ma):
            out[k] = build(kin, k, velocity_scale=mv2, acceleration_scale=ma2)
    return out


def _given(sc: dict[str, float], key: str) -> bool:
    return key in sc or f"{key}_known_mm" in sc


def fitted(kin: Kinematics, k: int, mv: float, ma: float, build):
    """Plans at position ``k`` at the common scales, rebuilt at a round scale of their own
    where a plan's longest vector would exceed ``LONGEST_MM`` (a scale the scene gives is kept)."""
    pp = build(kin, k, velocity_scale=mv, acceleration_scale=ma)
    sc = kin.scene.scales
    longest = LONGEST_MM * fit(kin.scene)
    mv2, ma2 = mv, ma
    if pp.velocity is not None and not _given(sc, "velocity") and pp.velocity.extent > longest:
        mv2 = round_scale(pp.velocity.extent / mv, longest)
    if pp.acceleration is not None and not _given(sc, "acceleration") and pp.acceleration.extent > longest:
        ma2 = round_scale(pp.acceleration.extent / ma, longest)
    if (mv2, ma2) != (mv, ma):
        pp = build(kin, k, velocity_scale=mv2, acceleration_scale=ma2)
    return pp


__all__ = ["DIVISIONS", "RATIOS", "ROUND", "fit", "round_scale", "round_up", "round_down", "ratio_scale", "is_round", "common_scales", "fitted", "refit", "known_vectors"]
