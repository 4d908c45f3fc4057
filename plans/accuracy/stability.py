"""The stability suite: degenerate and stiff cases every solver must get through (dead
centres, near-locked groups, loads across many orders of magnitude)."""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from plans.accuracy import newton
from plans.accuracy.oracles import (
    Oracle,
    construction_errors,
    force_errors,
    oracle_from_reference,
    solver_errors,
    total_error,
)
from plans.errors import ConstructionError
from plans.kinematics import construction
from plans.kinematics import exact as kinematics
from plans.kinematics.placing import load_scene, scene_from_dict
from plans.scene.model import Scene

if TYPE_CHECKING:  # mpmath is an optional dependency (the ``bench`` extra): imported where used
    pass

def stiff_load_records(samples: Path) -> list[dict]:
    """Stiff loads on the V-engine: a link 1e6 times heavier than another, inertia loads
    1e8 times the gas force; the three balancing loads must still agree."""
    import copy

    f = samples / "v_engine.toml"
    if not f.exists():
        return []
    try:
        from plans.forces import analysis as forces
    except ImportError:  # pragma: no cover
        return []
    base = load_scene(f)
    phis = np.linspace(0.0, 360.0, 72, endpoint=False) + 2.5
    out = []
    variants: list[tuple[str, Callable[[dict], Any]]] = [
        ("V-engine as given", lambda d: None),
        ("rod 2 1e6 times heavier than rod 4", lambda d: d["links"]["2"].__setitem__(
            "mass", d["links"]["2"].get("mass", 1.0) * 1e6)),
        ("gas force 1e-8 of the inertia loads", lambda d: [g.__setitem__("pressure", g.get("pressure", 0) * 1e-8)
                                                          for g in d.get("loads", {}).get("gas", [])]),
        ("no masses (inertia-free, gas only)", lambda d: [lk.__setitem__("mass", 0.0) or lk.__setitem__("inertia", 0.0)
                                                          for lk in d["links"].values()]),
    ]
    for name, change in variants:
        row: dict[str, Any] = {"case": name}
        try:
            data = copy.deepcopy(base.raw)
            change(data)
            sc = scene_from_dict(data, str(f))
            kin = kinematics.solve(sc, phis, order=2)
            res = forces.kinetostatics(sc, kin)
            assert res is not None
            e_lever, e_power = force_errors(*res)
            row.update({"lever": e_lever, "power": e_power})
        except Exception as exc:  # noqa: BLE001
            row["error"] = f"{type(exc).__name__}: {exc}"
        out.append(row)
    return out


# --------------------------------------------------------------------------- stability


def stability_records() -> list[dict]:
    """The stiff and extreme cases of the stability suite, with each method's error."""
    from plans.accuracy import reference

    out: list[dict] = []

    def add(case: str, scene: Scene, oracle: Oracle, phis: np.ndarray) -> None:
        row: dict[str, Any] = {"case": case}
        try:
            kin = kinematics.solve(scene, phis, order=2)
            row["exact"] = total_error(solver_errors(scene, oracle, kin.point, kin.omega, kin.eps))
            plans = [construction.build(kin, k) for k in range(len(phis))]
            row["construction"] = total_error(construction_errors(scene, oracle, plans))
            nr = newton.solve(scene, phis, seed=newton.seed_from(kin, 0, perturb=1e-4))
            row["newton"] = total_error(solver_errors(scene, oracle, nr.point, nr.omega, nr.eps))
            row["cond"] = float(np.nanmax(nr.cond))
        except ConstructionError as exc:
            row["error"] = exc  # bench.json writes its English, the report the run's language
        out.append(row)

    for off in (0.0, 1e-12, 1e-9, 1e-6, 1e-3):
        phis = np.array([math.degrees(off), 180.0 + math.degrees(off)])
        sc = reference.slider_crank_scene(0.05, 0.2, 0.0, 100.0, phis)
        add(f"slider-crank, {off:g} rad from dead centres", sc,
            oracle_from_reference(reference.slider_crank(0.05, 0.2, 0.0, 100.0, phis)), phis)
    for lam in (1e-4, 0.01, 0.5, 0.99, 0.999999):
        phis = np.array([0.0, 45.0, 89.0, 90.0, 135.0])
        sc = reference.slider_crank_scene(0.1 * lam, 0.1, 0.0, 100.0, phis)
        add(f"slider-crank, λ = {lam:g}", sc,
            oracle_from_reference(reference.slider_crank(0.1 * lam, 0.1, 0.0, 100.0, phis)), phis)
    phis = np.array([10.0, 100.0, 250.0])
    sc = reference.slider_crank_scene(1e-6, 1e3, 0.0, 100.0, phis)
    add("slider-crank, r = 1e-6 m, l = 1e3 m", sc,
        oracle_from_reference(reference.slider_crank(1e-6, 1e3, 0.0, 100.0, phis)), phis)
    sc = reference.four_bar_scene(1e-6, 1e3, 1e3, 1e3, 100.0, phis)
    add("four-bar, crank 1e-6 m, others 1e3 m", sc,
        oracle_from_reference(reference.four_bar(1e-6, 1e3, 1e3, 1e3, 100.0, phis)), phis)
    for w in (1e-6, 1.0, 1e5):
        sc = reference.four_bar_scene(0.05, 0.2, 0.15, 0.18, w, phis)
        add(f"four-bar, ω1 = {w:g} rad/s", sc,
            oracle_from_reference(reference.four_bar(0.05, 0.2, 0.15, 0.18, w, phis)), phis)
    for alpha in (90.0, 1.0, 1e-3, 1e-5):
        sc = reference.scotch_yoke_scene(0.05, alpha, 100.0, phis)
        add(f"Scotch yoke, slot {alpha:g}° to its guide", sc,
            oracle_from_reference(reference.scotch_yoke(0.05, alpha, 100.0, phis)), phis)
    return out


