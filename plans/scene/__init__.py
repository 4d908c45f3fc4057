"""Scene files: the mechanism as the file describes it (links, joints, guides, driver,
positions, scales, outputs), read and validated into SI units.

Owns: :mod:`plans.scene.model` (the frozen :class:`Scene` and its reader),
:mod:`plans.scene.positions` (positions asked for by the piston's travel or from the
output's extreme, read as a request that :mod:`plans.kinematics.placing` places: read a
scene file with ``plans.load_scene`` to have them placed) and :mod:`plans.scene.sheet` (the
``[sheet]`` table, read with the file); ``[loads]``,
``[dynamics]``, ``[diagrams]`` are read for a solve by :mod:`plans.tables`, which calls the
parsers the forces and the cycle rooms keep for their own tables.
May import only the shared modules (:mod:`plans.errors`, :mod:`plans.io`,
:mod:`plans.units`).  Read first: :func:`load_scene`.
"""

from plans.scene.model import (
    Driver,
    Guide,
    Joint,
    Link,
    Scene,
    load_scene,
    parse_scene,
    scene_from_dict,
)

__all__ = ["Driver", "Guide", "Joint", "Link", "Scene", "load_scene", "parse_scene", "scene_from_dict"]
