"""Scale-aware tolerances, in one place.

Every comparison in the engine is relative to the size of what is compared
(a link length, a plan's extent), never an absolute literal.
"""

#: |sin| of the angle between two construction lines below which they count as parallel.
LOCK_SIN = 1e-12
#: Construction lines closer to parallel than this are not intersected: the draftsman
#: takes the exact point (no pencil resolves 1e-6 rad).
NEAR_PARALLEL_SIN = 1e-6
#: Relative slack for "just reaches" in assembly (tangent circle/line, straight toggle).
ASSEMBLY_REL = 1e-12
#: A plan point closer than this fraction of the plan's extent to another coincides with it.
COINCIDE_REL = 1e-9

#: An exact value within this fraction of the plan's reference is zero up to rounding: a
#: vanishing quantity (v_B at a dead centre) read as 0, a force through the point its moment
#: is taken about given no arm.
EXACT_ZERO_REL = 1e-12

#: Two crank angles (degrees) closer than this are one position: a position named by its
#: angle (a check file's ``phi_deg``, ``--phi``, a value read at φ) is found among the scene's.
SAME_ANGLE_DEG = 1e-9

#: A value at the edge of its tolerance passes: the edge widened by this fraction for the
#: rounding of the tolerance's own arithmetic (the checker's verdicts).
VERDICT_REL = 1e-9

#: A group whose construction lines meet at less than ~1e-6 rad is reported as ill-conditioned.
ILL_CONDITIONED = 1e6

#: A value computed exactly in double precision is at a bound when within this fraction of it
#: (a few dozen operations lose ~1e-14; 1e-12 leaves a margin and is still far below anything
#: drawn or measured): a round scale that is the value, a stroke's end reached, a tooth's tip
#: on its base circle, two modules the same.
ROUND_OFF_REL = 1e-12

#: Two results of different exact computations of one thing (a point met by two routes, a
#: train's equations, the cuts of a quadrature, a check's two exact values) agree within this
#: fraction of their size: a cycle's sums and iterations lose more than one operation's
#: round-off, and far less than 1e-9.
AGREE_REL = 1e-9

#: A polygon of forces or moments (an engine's balance) closes when its resultant is within
#: this fraction of its largest vector: a sum of a few dozen exact terms.
CLOSED_REL = 1e-9
