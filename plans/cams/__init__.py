"""Cams: motion laws, the minimum base radius from the permissible pressure angle, the
profile by inversion.

This room owns the cam file (``kind = "cam"``, read by :mod:`plans.cams.model`), the laws
of the follower's motion (:mod:`plans.cams.laws`), the analysis over the cycle: s, ds/dφ,
d²s/dφ², v, a, the theoretical and the actual profile, pressure angle, radius of curvature,
undercut (:mod:`plans.cams.analysis`), the base radius from the ds/dφ–s diagram, graphically
and exactly (:mod:`plans.cams.base_radius`), graphical integration of a(φ) as a course does
it (:mod:`plans.cams.graphical`), and the ``plans cam`` command (:mod:`plans.cams.cli`).

It may import numpy, the standard library and the engine's shared modules (plans.errors,
plans.io, plans.units); never drawings/, nor the linkage rooms.
"""
