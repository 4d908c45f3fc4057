"""Checking a hand-drawn sheet: the check file (what a student measured and wrote),
the exact value of each written quantity, the draftsman's tolerance, the consistency
findings and the marked report.

Owns: :mod:`.checkfile` (reading check files), :mod:`.providers` (the exact value of a
written quantity), :mod:`.tolerance` (the draftsman's tolerance propagated through the
construction), :mod:`.findings` and :mod:`.relations` (the student's own work: repeats,
symmetry, π, scales, swapped segments, arithmetic), :mod:`.report` (the comparison, the
report, ``plans check``).  May import :mod:`plans.kinematics`, :mod:`plans.forces`,
:mod:`plans.scene`.  Read first: :func:`plans.check.report.check`.
"""
