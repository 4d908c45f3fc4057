"""Checking a hand-drawn sheet: the check file (what a student measured and wrote),
the exact value of each written quantity, the draftsman's tolerance, the consistency
findings and the marked report.

Owns: :mod:`.checkfile` (reading check files), :mod:`.report` (providers, tolerances,
findings, report).  May import :mod:`plans.kinematics`, :mod:`plans.forces`,
:mod:`plans.scene`.  Read first: :func:`plans.check.report.check_file`.
"""
