"""Submissions made from a variant's answer key: the key itself (a perfect student) or the
key with one slip a student makes, carried through as the student would carry it.

``key_submission(variant_dir, target, student, group, slip)`` returns a check file (a dict)
that stands at ``target``; ``slip``:

* None: every figure of the key, exact (every mark full);
* ``"scale"``, ``"coriolis_reversed"``, ``"arithmetic"`` (a linkage): the examiner's
  planted student (:mod:`plans.check.planted`), read without noise;
* ``"shift_coefficient"`` (gears): x of the first gear written 0.25 off and every figure
  after it worked out from it;
* ``"base_radius"`` (a cam): the cam drawn on a base circle 8 mm larger.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

SLIPS = ("scale", "coriolis_reversed", "arithmetic", "shift_coefficient", "base_radius")


def _rel(path: Path, target: Path) -> str:
    return Path(os.path.relpath(path.resolve(), target.resolve().parent)).as_posix()


def _positions(values: dict[str, dict[str, float]]) -> list[dict[str, Any]]:
    phis = sorted({float(p) for v in values.values() for p in v})
    return [{"phi_deg": phi, "values": {q: v[f"{phi:g}"] for q, v in values.items() if f"{phi:g}" in v}}
            for phi in phis]


def key_submission(variant_dir: str | Path, target: str | Path, student: str, group: str,
                   slip: str | None = None, seed: int = 0, sheet: str | None = None) -> dict[str, Any]:
    """``sheet``: of a synthesis variant, ``"synthesis"`` (the design) or None (its scene's sheets)."""
    from plans.io import read_toml

    folder, target = Path(variant_dir), Path(target)
    key = json.loads((folder / "key.json").read_text(encoding="utf-8"))
    kind, name = key["kind"], key["file"]
    src = folder / name
    head: dict[str, Any] = {"format": 1, "student": student, "group": group, "variant": key["variant"]}
    values = key["values"]
    if kind == "synthesis" and sheet == "synthesis":
        syn = {q: v for q, v in values.items() if q in _synthesis_names(folder)}
        return {**head, "synthesis": _rel(src, target), "scales": {"length": {"mu": 1}}, "positions": _positions(syn)}
    if kind == "synthesis":
        kind, src = "linkage", folder / key["scene"]
        values = {q: v for q, v in values.items() if q not in _synthesis_names(folder)}
    if kind == "linkage":
        if slip is not None:
            return _planted(src, target, head, slip, seed)
        return {**head, "scene": _rel(src, target), "scales": key["scales"], "positions": _positions(values)}
    part = read_toml(src)
    if slip == "shift_coefficient" and kind == "gears":
        from plans.group.sheets import gears_values

        x1 = float(values["x_1"]["0"]) + 0.25
        part = {**part, "gears": [{**g, "x": x1} if str(g.get("name")) == "1" else g for g in part["gears"]]}
        got, _ = gears_values(part, str(src))
        values = {q: {"0": v} for q, v in got.items()}
    elif slip == "base_radius" and kind == "cam":
        from plans.group.sheets import cam_values

        r0 = float(values["r0"]["0"]) + 8.0
        got2 = cam_values(part, str(src), r0=r0)
        values = {}
        for (q, phi), v in got2.items():
            values.setdefault(q, {})[f"{phi:g}"] = v
    elif slip is not None:
        raise ValueError(f"no slip {slip!r} on a {kind} sheet")
    mu = 50 if kind == "engine" else 1
    return {**head, kind: _rel(src, target), "scales": {"length": {"mu": mu}}, "positions": _positions(values)}


def _synthesis_names(folder: Path) -> set[str]:
    import re

    form = (folder / "synthesis.check.toml").read_text(encoding="utf-8")
    return set(re.findall(r'^"([^"]+)" = ""', form, flags=re.M))


def _planted(src: Path, target: Path, head: dict[str, Any], slip: str, seed: int) -> dict[str, Any]:
    import numpy as np

    from plans.check.planted import Scenario, submission

    sc = Scenario.of(src)
    phis = tuple(sc.scene.driver.phis_deg)[:2]
    data, _ = submission(sc, (phis[0], phis[-1]), slip, np.random.default_rng(seed), noise_mm=0.0)
    return {**data, **head, "scene": _rel(src, target)}
