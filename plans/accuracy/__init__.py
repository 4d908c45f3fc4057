"""Accuracy: how far each way of getting velocities and accelerations can be trusted and
what it costs.  Independent oracles (mpmath references, a Newton–Raphson loop solver),
the hand-drawing Monte Carlo, the benchmark runner and the stability suite.

Owns: :mod:`.reference`, :mod:`.newton`, :mod:`.bench`.  May import every other room;
nothing imports it but the CLI and the tests.  Read first: :func:`plans.accuracy.bench.run_bench`.
"""
