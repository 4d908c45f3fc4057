"""The scene's other tables, each read once into the typed record the scene holds:
``[sheet]`` when the file is read (:func:`plans.scene.sheet.sheet_of`), ``[loads]``,
``[dynamics]``, ``[diagrams]`` and the pairs' friction when the scene is solved
(:func:`with_tables`, which ``plans.solve`` calls before anything is computed), whether or
not the scene asks for what they feed.  So a bad
table fails ``plans solve`` and ``plans draw`` alike (one line, exit 2), and every reader
takes the scene's record instead of reading the raw table again.

The parsers of ``[loads]`` and of the cycle's tables live with the rooms that use them
(:mod:`plans.forces.loads`, :mod:`plans.cycle.spec`, with their numpy typing and
dataclasses): loaded at the solve, not with the file, ``plans solve`` starts as fast as it did.
Read above the rooms (not in :mod:`plans.scene`), so the scene room needs none of them.
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from plans.scene.model import Scene


def with_tables(scene: Scene, **changes: Any) -> Scene:
    """``scene`` (with ``changes``) holding its ``[loads]``, ``[dynamics]`` and ``[diagrams]``,
    each read and validated (InputError naming the field); read once (``tables``)."""
    if scene.tables:
        return replace(scene, **changes) if changes else scene
    raw = scene.raw
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
    from plans.scene.friction import parse_friction

    return replace(scene, loads=loads, dynamics_spec=dynamics, diagrams_spec=diagrams,
                   friction_spec=parse_friction(scene), tables=True, **changes)


__all__ = ["with_tables"]
