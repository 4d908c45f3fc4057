"""Records are values: nothing in a frozen record changes once it is made, solving included;
what a solver derives from one is kept beside it (plans.records.derived), dropped with it."""

from __future__ import annotations

import dataclasses
import gc
import pickle
import weakref

import numpy as np

from plans.records import MADE, derived


def _records() -> list[type]:
    import plans.forces.analysis  # noqa: F401  (the modules whose classes are records)
    import plans.results  # noqa: F401
    import plans.solution  # noqa: F401

    return list(MADE)


def test_no_record_holds_a_table_to_fill_later():
    """A field made empty by the record itself (``init=False`` with a default factory) is a cache
    written after the record is made: none is left."""
    late = [f"{cls.__module__}.{cls.__name__}.{f.name}" for cls in _records() for f in dataclasses.fields(cls)
            if not f.init and f.default_factory is not dataclasses.MISSING]
    assert len(_records()) >= 30 and late == []


def test_solving_a_scene_and_its_forces_leaves_the_records_as_they_were():
    from plans.forces.analysis import kinetostatics
    from plans.kinematics.exact import solve
    from plans.kinematics.placing import load_scene

    scene = load_scene("samples/v_engine.toml")
    before = pickle.dumps(scene)
    kin = solve(scene, np.linspace(0.0, 360.0, 24, endpoint=False), order=2)
    fa, _ = kinetostatics(scene, kin)
    held = [getattr(fa, f.name) for f in dataclasses.fields(fa)]
    assert fa.largest_reaction > 0 and fa.balancing.shape == (24,) and not fa.balancing.flags.writeable
    assert pickle.dumps(scene) == before
    assert all(getattr(fa, f.name) is x for f, x in zip(dataclasses.fields(fa), held, strict=True))
    assert derived(scene)["structure"] is kin.structure  # derived once, kept beside the scene
    assert {"largest", "balancing", "sense"} <= set(derived(fa))


def test_what_is_derived_is_the_records_own_and_goes_with_it():
    from plans.kinematics.placing import load_scene
    from plans.kinematics.structure import analyse
    from plans.records import _KEPT

    scene = load_scene("samples/four_bar.toml")
    st = analyse(scene)
    assert analyse(scene) is st and derived(scene) is derived(scene)
    other = dataclasses.replace(scene)
    assert other == scene and derived(other) == {}  # an equal record derives its own
    assert analyse(other) is not st and analyse(other) == st
    keys, alive = (id(scene), id(other)), (weakref.ref(scene), weakref.ref(other))
    assert all(k in _KEPT for k in keys)
    del scene, other, st
    gc.collect()
    assert [r() for r in alive] == [None, None]  # what is derived does not keep the record
    assert not any(k in _KEPT and _KEPT[k][0]() is None for k in keys)
