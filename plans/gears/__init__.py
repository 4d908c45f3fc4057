"""Involute spur gears and gear trains (seed 001, chapter 2; the course's §4).

This room owns:

- :mod:`plans.gears.model`: the gear file (TOML, ``format = 1``, ``kind = "gears"``): gears,
  shafts, meshes, speeds, a planetary synthesis request.
- :mod:`plans.gears.involute`: the involute function, its inverse, the involute drawn the
  draftsman's way (a line rolled on the base circle) and tooth thickness at a radius.
- :mod:`plans.gears.shifts`: profile-shift coefficients chosen by a rule.
- :mod:`plans.gears.geometry`: one external or internal pair: working pressure angle, centre
  distance, y and Δy, radii, tip pressure angles, contact ratio, tip thickness, the checks.
- :mod:`plans.gears.train`: speeds of an ordinary, planetary or differential train by Willis'
  formula, and the same by the velocity plan (triangles of linear velocities and the ray
  diagram of angular velocities, Smirnov's method).
- :mod:`plans.gears.synthesis`: numbers of teeth of a 2K-H train for a given ratio.
- :mod:`plans.gears.meshing`: the meshing drawing's construction in paper millimetres (the
  profiles, the line of action, the active part B1B2 measured on the drawing).
- :mod:`plans.gears.solve` and :mod:`plans.gears.cli`: the pipeline, the JSON and
  ``plans gears FILE [--json PATH]``.

It may import numpy, shapely and the shared modules ``plans.errors``, ``plans.io``,
``plans.units``; nothing of the linkage rooms, and never ``drawings``.
"""
