"""The cycle: what a course draws over a whole revolution of the crank.

Tables across positions (quantities as rows, positions as columns: plan segments in mm
and values), kinematic diagrams s(φ), v(φ), a(φ) by graphical differentiation and
integration against the exact curves, and machine dynamics: velocity analogues, the
reduced moment of inertia I_pr(φ) and of forces M_pr(φ), work and kinetic-energy
diagrams, the Wittenbauer energy–mass diagram, the flywheel (graphical, Merkalov's and
exact) and the motion ω(φ) it gives over the steady cycle.

Owns: :mod:`.spec` (``[dynamics]``, ``[diagrams]``), :mod:`.table`, :mod:`.diagrams`,
:mod:`.dynamics`, :mod:`.quadrature` (the exact work and the flywheel's extremes over the
cycle, 360° or 720°), :mod:`.output` (JSON, terminal, CSV), :mod:`.bench`; the cycle tables
of a hand-drawn sheet are checked by :mod:`plans.check.cycle`.  May import :mod:`plans.scene`,
:mod:`plans.kinematics`, :mod:`plans.forces` and the shared modules; nothing it imports
imports it back.  Read first: :func:`plans.cycle.dynamics.dynamics`.
"""
