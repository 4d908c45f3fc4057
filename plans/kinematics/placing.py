"""A scene's positions placed where the file asks for them by what the mechanism does, and
the scene files read with their positions placed (``plans.load_scene``).

The scene room reads ``[driver] s_mm``/``s_fraction`` (the piston's travel) or ``phi_start``
(the output's extreme) as a request and validates it with the file
(:mod:`plans.scene.positions`); the angles come from the exact analysis, so they are placed
here (:mod:`.travel`, :mod:`.extreme`), above both, before anything reads them.  Every reader
of a scene file reads it through :func:`load_scene`, :func:`parse_scene` or
:func:`scene_from_dict`: the scene room's readers of the same names, then :func:`place`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from plans.scene import model
from plans.scene.model import Scene
from plans.scene.positions import ByTravel

if TYPE_CHECKING:
    from pathlib import Path


def place(scene: Scene) -> Scene:
    """The scene with the positions its driver asks for placed (itself when they are given)."""
    request = scene.driver.placing
    if request is None:
        return scene
    if isinstance(request, ByTravel):
        from plans.kinematics.travel import by_travel

        return by_travel(scene, request)
    from plans.kinematics.extreme import start_scene

    return start_scene(scene, request)


def load_scene(path: str | Path) -> Scene:
    """A scene file read, validated and placed; an implausible one is warned about on stderr
    once it is (:func:`plans.scene.model.warn_implausible`)."""
    from plans.io import read_toml

    return model.warn_implausible(scene_from_dict(read_toml(path), str(path)), path)


def parse_scene(text: str, path: str = "<scene>") -> Scene:
    """A scene's TOML text read, validated and placed."""
    return place(model.parse_scene(text, path))


def scene_from_dict(data: dict[str, Any], path: str = "<scene>") -> Scene:
    """A scene file's table read, validated and placed."""
    return place(model.scene_from_dict(data, path))
