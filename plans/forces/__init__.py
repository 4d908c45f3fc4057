"""Forces: the loads a scene applies (gravity, gas pressure, indicator diagrams, inertia,
external and resisting forces), the force polygon of each Assur group by the Bruevich
method, the crank and its balancing force or moment, and the Zhukovsky lever with the
power balance.

Owns: :mod:`.loads`, :mod:`.polygons`, :mod:`.lever`, :mod:`.shared` (μF, the ruler, small vector
helpers both import), :mod:`.friction` (the successive approximation with friction in the pairs,
the efficiency), :mod:`.analysis` (runs the polygons, with friction when the scene states it,
then the lever).  May import :mod:`plans.kinematics`
and :mod:`plans.scene`.  The lever depends on the polygons, never the reverse.  Read
first: :func:`plans.forces.analysis.kinetostatics`, then :func:`plans.forces.polygons.analyse_forces`.
"""
