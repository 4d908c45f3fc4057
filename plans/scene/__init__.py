"""Scene files: the mechanism as the file describes it (links, joints, guides, driver,
positions, scales, outputs), read and validated into SI units.

Owns: :mod:`plans.scene.model` (the frozen :class:`Scene` and its reader),
:mod:`plans.scene.sheet` (the ``[sheet]`` table, read with the file) and
:mod:`plans.scene.tables` (``[loads]``, ``[dynamics]``, ``[diagrams]`` read for a solve).
May import only the shared modules (:mod:`plans.errors`, :mod:`plans.io`,
:mod:`plans.units`); ``tables`` alone calls the parsers the forces and the cycle rooms keep
for their own tables, imported when a scene is solved.  Read first: :func:`load_scene`.
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
