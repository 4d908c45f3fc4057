"""The scene's other tables, read once with the scene: ``[sheet]``, ``[loads]``, ``[dynamics]``,
``[diagrams]``.  Each is validated when the file is read, so a bad table fails ``plans
solve``, ``plans draw`` and ``plans check`` alike (one line, exit 2), and every reader takes
the typed record the scene holds instead of reading the raw table again.

The parsers of ``[loads]`` and of the cycle's tables live with the rooms that use them
(:mod:`plans.forces.loads`, :mod:`plans.cycle.spec`); they are imported here only when the
file has such a table or asks for what needs it, so a scene of plans alone loads neither.
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from plans.scene.sheet import sheet_spec

if TYPE_CHECKING:
    from plans.scene.model import Scene


def with_tables(scene: Scene) -> Scene:
    """``scene`` holding its tables, each read and validated (InputError naming the field)."""
    raw = scene.raw
    sheet = sheet_spec(raw, scene.path, scene.title_in(_language(raw)))
    loads = dynamics = diagrams = None
    if "loads" in raw or scene.wants("force_polygons") or scene.wants("lever") or scene.wants("dynamics"):
        from plans.forces.loads import parse_loads

        loads = parse_loads(scene)
    if "dynamics" in raw or scene.wants("dynamics"):
        from plans.cycle import spec

        if scene.wants("dynamics"):
            dynamics = spec.dynamics_spec(scene)
        else:  # a check file's scene gives the rotor alone, without a flywheel to find
            spec.rotor_inertia(scene)
    if "diagrams" in raw or scene.wants("diagrams"):
        from plans.cycle import spec

        if scene.wants("diagrams"):
            diagrams = spec.diagrams_spec(scene)
        else:
            spec.check_table(scene, "diagrams")
    out = replace(scene, sheet=sheet, loads=loads, dynamics_spec=dynamics, diagrams_spec=diagrams)
    if loads is not None:
        out.memo["loads"] = loads  # what plans.forces.loads.parse_loads reads back: parsed once
    return out


def _language(raw: dict) -> str:
    """The sheet's language as the file gives it (its title is the scene's in that language)."""
    sheet = raw.get("sheet")
    lang = sheet.get("language") if isinstance(sheet, dict) else None
    return lang if lang in ("ru", "en") else "ru"


__all__ = ["with_tables"]
