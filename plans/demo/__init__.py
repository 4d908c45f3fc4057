"""The demonstration: a scene as a lesson (plain data a page or a notebook replays).

Owns: :mod:`.lesson` (the construction of one position step by step, the cycle's frames)
and :mod:`.mistakes` (classic mistakes and how far each moves the result).  May import
every room of the analysis (scene, kinematics, forces); nothing imports it but the
demonstration page in ``drawings``.  Read first: :func:`plans.demo.lesson.lesson`.
"""

from plans.demo.lesson import FRAMES, MAX_FRAMES, lesson

__all__ = ["FRAMES", "MAX_FRAMES", "lesson"]
