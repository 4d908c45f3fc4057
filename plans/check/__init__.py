"""Checking a hand-drawn sheet: the check file (what a student measured and wrote),
the exact value of each written quantity, the draftsman's tolerance, the consistency
findings and the marked report.

Owns: :mod:`.checkfile` (reading check files), :mod:`.providers` (the exact value of a
written quantity), :mod:`.tolerance` (the draftsman's tolerance propagated through the
construction), :mod:`.findings` and :mod:`.relations` (the student's own work: repeats,
symmetry, π, scales, swapped segments, arithmetic), :mod:`.report` (the comparison, the
report), :mod:`.cycle` (the cycle tables of a dynamics sheet against :mod:`plans.cycle`).
``plans check`` itself, which also takes the group's gradebook and gears and cam sheets, is
:mod:`plans.check_command`, above this room and :mod:`plans.group`.  May import
:mod:`plans.kinematics`, :mod:`plans.forces`, :mod:`plans.cycle`, :mod:`plans.scene` and
the composer :mod:`plans.solution` (never :mod:`plans.group`, nor
:mod:`plans.accuracy`, which read this room).  Read first: :func:`plans.check.report.check`.
"""
