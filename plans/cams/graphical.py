"""Graphical integration of a(φ) as a course does it, on the division points of the cycle.

On each interval the ordinate of the integrand at the interval's middle is projected onto
the axis; the ray from the pole (H mm left of the origin) gives the chord's slope, the chords
are chained from zero.  The ordinate at the middle is the integrand's mean to O(Δφ²), so the
chain meets the exact integral at the nodes to that order.  The integrated diagram's scale is
k = k_y′·k_φ/H (mm per unit), k_φ in mm per radian.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .analysis import motion
from .base_radius import division_points
from .model import Cam


def integrate(nodes: np.ndarray, mid: np.ndarray, start: float = 0.0) -> np.ndarray:
    """The chord chain: values at the nodes from the interval mid-ordinates."""
    return start + np.concatenate([[0.0], np.cumsum(mid * np.diff(nodes))])


def integral_scale(k_y: float, k_phi: float, H: float) -> float:
    """Scale of the integral diagram (mm per unit) from the integrand's scale k_y, the
    abscissa's k_φ (mm per rad) and the pole distance H (mm)."""
    return k_y * k_phi / H


@dataclass(frozen=True, slots=True)
class Integration:
    """The two integrations over the cycle: nodes (rad), mid-ordinates of d²s/dφ², the chained
    ds/dφ at the nodes, the mid-ordinates read off that chain (chord middles) and the chained s."""

    nodes: np.ndarray
    a_mid: np.ndarray
    v_nodes: np.ndarray
    v_mid: np.ndarray
    s_nodes: np.ndarray


def integrate_cam(cam: Cam) -> Integration:
    nodes = np.append(division_points(cam), 2 * np.pi)
    mids = (nodes[:-1] + nodes[1:]) / 2
    a_mid = motion(cam, mids).s2
    v = integrate(nodes, a_mid)
    v_mid = (v[:-1] + v[1:]) / 2
    s = integrate(nodes, v_mid)
    return Integration(nodes, a_mid, v, v_mid, s)
