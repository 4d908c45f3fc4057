"""From a solved scene to sheets: which panels the scene asks for, drawn and laid out.

Everything drawn is read off one :class:`plans.solution.Solution` (``plans.solve``): the
sheets compute nothing of the mechanism themselves.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from plans.errors import InputError
from plans.kinematics.exact import Kinematics
from plans.scene.model import Scene, load_scene
from plans.solution import Solution
from plans.solution import solve as solve_scene

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
from .sheet import Sheet, SheetSpec, compose


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


def _fitting_positions(sol: Solution, mu: float, lang: str, bold: list[int], strokes: Any,
                       spec: SheetSpec) -> Any:
    """The plan of positions as it fits the sheet: in full; else with its angles in brief; else
    (when its scale is not the file's own) at the next smaller standard scales."""
    from .sheet import fits_empty

    panel = positions_panel(sol, mu, lang, bold, strokes, spec.trace, first=spec.first_position)
    if fits_empty(panel, spec.format, spec.orientation):
        return panel
    panel = positions_panel(sol, mu, lang, bold, strokes, spec.trace, brief=True, first=spec.first_position)
    if sol.scene.scales.get("length"):
        return panel  # the student's scale is kept: a panel that does not fit says so
    from .panels import STANDARD_RATIOS

    for r in STANDARD_RATIOS:
        if fits_empty(panel, spec.format, spec.orientation):
            break
        if 1000.0 * r < mu:
            panel = positions_panel(sol, 1000.0 * r, lang, bold, strokes, spec.trace, brief=True, first=spec.first_position)
    return panel


def build_panels(sol: Solution, spec: SheetSpec) -> tuple[list[Panel], float]:
    """Every panel the scene asks for, in the order they go on the sheet."""
    metrics()  # fail early, with the font's name, if it is missing
    scene = sol.scene
    lang, style = spec.language, scene.scale_style
    kin = sol.kinematics
    ks = _positions(scene, kin, spec)
    size = cycle_size(sol)
    w, _h = spec.size  # schemes about 230 mm across on A1, proportionally less on smaller sheets
    mu_l = scene.scales.get("length") or auto_length_scale(size, 230.0 * min(1.0, max(w, _h) / 841.0))
    strokes = strokes_over_cycle(sol)
    plans_at: dict[int, Any] = dict(enumerate(sol.plans))
    forces = _force_panels(sol, spec, ks, plans_at, mu_l) if (
        scene.wants("force_polygons") or scene.wants("lever")) else {}
    panels: list[Panel] = []
    # Many positions: one plan of positions (all of them overlaid) and schemes of its own
    # only for the positions studied in detail (listed, or the first two).
    overlay = kin.n > 1 and scene.wants("positions") and _wants(spec, "positions")
    schemes = set(ks if spec.positions is not None or not overlay else ks[:2])
    if overlay:  # the plan of positions at the largest standard scale that fits 2/5 of the sheet
        mu_pos = scene.scales.get("length") or auto_length_scale(size, 0.4 * (w - 37.0))
        panels.append(_fitting_positions(sol, mu_pos, lang, sorted(schemes), strokes, spec))
    for k in ks:
        if scene.wants("positions") and _wants(spec, "scheme") and k in schemes:
            panels.append(scheme_panel(scene, kin, k, mu_l, lang, strokes))
        if scene.wants("instant_centres") and _wants(spec, "centres") and k in schemes:
            from .centres import centres_panels

            panels.extend(centres_panels(sol, k, mu_l, lang, strokes))
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


def fit_for(spec: SheetSpec) -> float:
    """The fraction of the A1 target lengths the plans, polygons and lever are solved at for
    ``spec``'s paper (:attr:`plans.scene.sheet.SheetSpec.fit`), the scales still round."""
    return spec.fit


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


def _force_panels(sol: Solution, spec: SheetSpec, ks: list[int], plans_at, mu_l: float) -> dict:
    """Force panels (group free bodies and polygons, crank, lever) when plans.forces exists."""
    try:
        from . import forces_panels
    except ImportError:  # pragma: no cover - the force panels are optional
        return {}
    return forces_panels.build(sol, spec, ks, plans_at, mu_l)


def draw(source: Solution | Scene | str | Path, *, format: str | None = None, orientation: str | None = None,
         language: str | None = None) -> Drawing:
    """The sheets of a solved scene (a :class:`Solution`), or of a Scene or the path of its
    file, solved once here at the paper's fit.  A Solution is drawn at the scales it was
    solved with (``plans.solve(scene, fit=...)``)."""
    if isinstance(source, Solution):
        sol = source
        spec = sol.scene.sheet_for(format=format, orientation=orientation, language=language)
    else:
        sc = source if isinstance(source, Scene) else load_scene(source)
        spec = sc.sheet_for(format=format, orientation=orientation, language=language)
        sol = solve_scene(sc, fit=fit_for(spec))
    panels, mu_l = build_panels(sol, spec)
    sc = sol.scene
    numbers = {float(phi): k + spec.first_position for k, phi in enumerate(sc.driver.phis_deg)}
    sheets = compose(panels, spec, None, sc.path, numbers)  # each sheet's scale: its main image's
    if sc.wants("diagrams") or sc.wants("dynamics"):  # the cycle's sheets follow
        from .cycle import extend

        sheets = extend(sol, spec, sheets, None)
    return Drawing(sc, spec, tuple(panels), tuple(sheets), mu_l)
