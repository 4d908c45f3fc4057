"""The force analysis a scene asks for: loads, Bruevich polygons, then the Zhukovsky lever.

The one place that runs the polygons and the lever together (the lever depends on the
polygons' analysis, the polygons never on the lever).
"""

from __future__ import annotations

from plans.forces.lever import LeverAnalysis, zhukovsky_lever
from plans.forces.loads import parse_loads
from plans.forces.polygons import ForceAnalysis, analyse_forces
from plans.kinematics.exact import Kinematics
from plans.scene.friction import parse_friction
from plans.scene.model import Scene


def kinetostatics(scene: Scene, kin: Kinematics) -> tuple[ForceAnalysis, LeverAnalysis] | None:
    """Force analysis and Zhukovsky lever if the scene asks for them, else None (nothing computed)."""
    fa = force_analysis(scene, kin)
    return None if fa is None else (fa, zhukovsky_lever(fa))


def force_analysis(scene: Scene, kin: Kinematics) -> ForceAnalysis | None:
    """The Bruevich polygons' analysis (with friction where the pairs have it) if the scene
    asks for polygons or the lever, else None: what no fit changes (the lever's scale does)."""
    if not (scene.wants("force_polygons") or scene.wants("lever")):
        return None
    loads = parse_loads(scene)
    spec = parse_friction(scene)
    if spec is not None:  # the successive approximation with friction in the pairs
        from plans.errors import Said
        from plans.forces.friction import friction_analysis

        kin.structure.no_triad(scene.path, Said("ks_w_friction"))
        return friction_analysis(scene, kin, loads, spec)
    return analyse_forces(scene, kin, loads)
