"""Accuracy: how far each way of getting velocities and accelerations can be trusted and
what it costs.  Independent oracles (mpmath references, a Newton–Raphson loop solver),
the hand-drawing Monte Carlo, the benchmark runner and the stability suite.

Owns: :mod:`.reference` (mpmath, 50 digits), :mod:`.newton` (a second solver, written
separately), :mod:`.oracles` (what an answer is compared with, how an error is measured,
the cases), :mod:`.draftsman` (the hand-drawing Monte Carlo), :mod:`.stability`,
:mod:`.speed` (the performance goals), :mod:`.markdown` (``bench.md``) and :mod:`.bench`
(the runner and ``plans bench``).  May import every other room; nothing imports it but
the CLI, the tests and the renderer's plot of the bench (``drawings.bench_plot``).  Read
first: :func:`plans.accuracy.bench.run_bench`.
"""
