"""Kinematics: structure (the initial link and the class-II Assur groups), the exact
analysis (closed-form positions, 2×2 systems for velocities and accelerations,
vectorised over positions), the construction of the velocity and acceleration plans as
a draftsman draws them, and the frozen plan objects they produce.

Owns: :mod:`.structure`, :mod:`.exact`, :mod:`.plan`, and the construction written once:
:mod:`.dyads` (the scheme, the builder, the :class:`~plans.kinematics.dyads.Pencil` that
draws and the perfect one), :mod:`.velocities` and :mod:`.accelerations` (one function
per dyad kind, over arrays of positions or drawings), :mod:`.construction` (the plans of
every position built together; plan objects, readings and protocol made when asked for).
May import :mod:`plans.scene` and the shared modules; never :mod:`plans.forces`; no
shapely (intersections in closed form).  Read first: :func:`plans.kinematics.exact.solve`,
then :func:`plans.kinematics.construction.build_all`, then :func:`plans.kinematics.velocities.velocity_plan`.
"""

from plans.kinematics.exact import Kinematics, solve
from plans.kinematics.plan import ConstructionLine, Plan, PlanPoint, Segment, Step
from plans.kinematics.structure import Group, Structure, analyse

__all__ = ["ConstructionLine", "Group", "Kinematics", "Plan", "PlanPoint", "Segment", "Step",
           "Structure", "analyse", "solve"]
