"""Kinematics: structure (the initial link and the class-II Assur groups), the exact
analysis (closed-form positions, 2×2 systems for velocities and accelerations,
vectorised over positions), the construction of the velocity and acceleration plans as
a draftsman draws them, and the frozen plan objects they produce.

Owns: :mod:`.structure`, :mod:`.exact`, :mod:`.construction`, :mod:`.plan`.  May import
:mod:`plans.scene` and the shared modules; never :mod:`plans.forces`.  shapely is
imported by :mod:`.construction` only.  Read first: :func:`plans.kinematics.exact.solve`,
then :func:`plans.kinematics.construction.build`.
"""

from plans.kinematics.exact import Kinematics, solve
from plans.kinematics.plan import ConstructionLine, Plan, PlanPoint, Segment, Step
from plans.kinematics.structure import Group, Structure, analyse

__all__ = ["ConstructionLine", "Group", "Kinematics", "Plan", "PlanPoint", "Segment", "Step",
           "Structure", "analyse", "solve"]
