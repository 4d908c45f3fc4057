"""Synthesis: the mechanism sized from the task's data (K, the stroke, the swing, the
permissible angles) by the course's graphical construction, proven by measuring the
designed mechanism's own motion, and written as a linkage scene.

:mod:`.model` reads the synthesis file; :mod:`.design` holds the slider-cranks, the coulisse,
the V-engine and the proof's verdict, :mod:`.four_bar` the crank-rocker; :mod:`.record` is the
designed mechanism; :mod:`.proof` measures it (:mod:`.numeric`: Brent's roots and minima);
:mod:`.scene` writes its scene (:mod:`.toml_out`); :mod:`.cli` is ``plans design``.
"""
