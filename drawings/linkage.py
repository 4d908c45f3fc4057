"""From a scene to sheets: which panels the scene asks for, built and laid out."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from plans.errors import InputError
from plans.kinematics.exact import Kinematics, solve
from plans.kinematics.scales import FIT
from plans.scene.model import Scene, load_scene

from .fonts import metrics
from .overview import legend_kinds, legend_panel, positions_panel
from .panels import (
    Panel,
    auto_length_scale,
    cycle_size,
    plan_panel,
    scheme_panel,
    strokes_over_cycle,
    table_panel,
)
from .sheet import Sheet, SheetSpec, compose, sheet_spec


@dataclass(frozen=True)
class Drawing:
    """Everything drawn for one scene: the sheets and the panels on them."""

    scene: Scene
    spec: SheetSpec
    panels: tuple[Panel, ...]
    sheets: tuple[Sheet, ...]
    mu_l: float

    def _repr_svg_(self) -> str:
        return self.sheets[0].svg()


def _positions(scene: Scene, kin: Kinematics, spec: SheetSpec) -> list[int]:
    if spec.positions is None:
        return list(range(kin.n))
    out = []
    for phi in spec.positions:
        hits = [k for k in range(kin.n) if abs(float(kin.phi_deg[k]) - phi) < 1e-9]
        if not hits:
            raise InputError(f"crank angle {phi:g}° is not among the scene's positions "
                             f"{[float(x) for x in kin.phi_deg]}", file=scene.path, field="sheet.positions")
        out.append(hits[0])
    return out


def _wants(spec: SheetSpec, kind: str) -> bool:
    return spec.panels is None or kind in spec.panels


def build_panels(scene: Scene, spec: SheetSpec) -> tuple[list[Panel], float]:
    """Every panel the scene asks for, in the order they go on the sheet."""
    metrics()  # fail early, with the font's name, if it is missing
    scene = for_sheet(scene, spec)
    lang, style = spec.language, scene.scale_style
    kin = solve(scene)
    ks = _positions(scene, kin, spec)
    size = cycle_size(scene)
    w, _h = spec.size  # schemes about 230 mm across on A1, proportionally less on smaller sheets
    mu_l = scene.scales.get("length") or auto_length_scale(size, 230.0 * min(1.0, max(w, _h) / 841.0))
    strokes = strokes_over_cycle(scene)
    plans_at: dict[int, Any] = {}
    if scene.wants("velocity_plan"):
        from plans.kinematics.construction import build_all

        plans_at = dict(enumerate(build_all(kin)))
    forces = _force_panels(scene, kin, spec, ks, plans_at, mu_l) if (
        scene.wants("force_polygons") or scene.wants("lever")) else {}
    panels: list[Panel] = []
    # Many positions: one plan of positions (all of them overlaid) and schemes of its own
    # only for the positions studied in detail (listed, or the first two).
    overlay = kin.n > 1 and scene.wants("positions") and _wants(spec, "positions")
    schemes = set(ks if spec.positions is not None or not overlay else ks[:2])
    if overlay:  # the plan of positions at the largest standard scale that fits 2/5 of the sheet
        mu_pos = scene.scales.get("length") or auto_length_scale(size, 0.4 * (w - 37.0))
        panels.append(positions_panel(scene, kin, mu_pos, lang, sorted(schemes), strokes, spec.trace))
    for k in ks:
        if scene.wants("positions") and _wants(spec, "scheme") and k in schemes:
            panels.append(scheme_panel(scene, kin, k, mu_l, lang, strokes))
        if scene.wants("instant_centres") and _wants(spec, "centres") and k in schemes:
            from .centres import centres_panels

            panels.extend(centres_panels(scene, kin, k, mu_l, lang, strokes))
        pp = plans_at.get(k)
        if pp is not None:
            if pp.velocity is not None and _wants(spec, "velocity"):
                panels.append(plan_panel(pp.velocity, lang, style))
            if pp.acceleration is not None and _wants(spec, "acceleration"):
                panels.append(plan_panel(pp.acceleration, lang, style))
        panels.extend(forces.get(k, []))
        if pp is not None and pp.readings and _wants(spec, "table"):
            extra = forces.get(("table", k), [])
            panels.append(table_panel(_rows(scene, pp.readings), lang, style, float(kin.phi_deg[k]),
                                      extra=extra))
    panels.extend(forces.get("efficiency", []))  # η(φ) and its table, with friction over a turn
    kinds = legend_kinds(panels)
    if _wants(spec, "legend") and any(k not in ("trace",) for k in kinds):
        panels.append(legend_panel(kinds, lang))
    return panels, mu_l


def for_sheet(scene: Scene, spec: SheetSpec) -> Scene:
    """The scene whose plans, polygons and lever are drawn for ``spec``'s paper: on a smaller
    sheet every target length shrinks by the square root of the ratio of the sheets' sizes
    (A3 about 0.7 of A1: smaller, still readable), the scales still round."""
    w, h = spec.size
    factor = min(1.0, math.sqrt(max(w, h) / 841.0))
    if factor >= 1.0 or FIT in scene.scales:
        return scene
    return replace(scene, scales={**scene.scales, FIT: factor})


def _rows(scene: Scene, readings) -> list:
    """Readings worth a row: not the rates of links that only slide on the frame."""
    fixed_sliders = {jt.slider for jt in scene.joints
                     if jt.kind == "P" and jt.guide is not None and jt.guide.link == scene.frame
                     and len(scene.links[jt.slider].axis) == 1}
    out = []
    for r in readings:
        head, _, rest = r.quantity.partition("_")
        if head in ("omega", "eps") and rest.isdigit() and int(rest) in fixed_sliders:
            continue
        out.append(r)
    return out


def _force_panels(scene: Scene, kin: Kinematics, spec: SheetSpec, ks: list[int], plans_at,
                  mu_l: float) -> dict:
    """Force panels (group free bodies and polygons, crank, lever) when plans.forces exists."""
    try:
        from . import forces_panels
    except ImportError:  # pragma: no cover - the force panels are optional
        return {}
    return forces_panels.build(scene, kin, spec, ks, plans_at, mu_l)


def draw(scene: Scene | str | Path, *, format: str | None = None, orientation: str | None = None,
         language: str | None = None) -> Drawing:
    """Build the sheets of a scene (a Scene or a path to its TOML file)."""
    sc = scene if isinstance(scene, Scene) else load_scene(scene)
    lang = language or (sc.raw.get("sheet", {}).get("language") if isinstance(sc.raw.get("sheet"), dict) else None)
    spec = sheet_spec(sc.raw, sc.path, sc.title_in(lang if lang in ("ru", "en") else "ru"), format=format,
                      orientation=orientation, language=language)
    panels, mu_l = build_panels(sc, spec)
    numbers = {float(phi): k for k, phi in enumerate(sc.driver.phis_deg)}
    sheets = compose(panels, spec, None, sc.path, numbers)  # each sheet's scale: its main image's
    if sc.wants("diagrams") or sc.wants("dynamics"):  # the cycle's sheets follow
        from .cycle import extend

        sheets = extend(sc, spec, sheets, None)
    return Drawing(sc, spec, tuple(panels), tuple(sheets), mu_l)
