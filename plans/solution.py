"""One solved scene that every reader takes: the JSON, the table, the sheets, the checker.

``plans.solve(scene_or_path, fit=...)`` makes a :class:`Solution`; each part (structure,
kinematics, plans, forces, lever, cycle, dynamics, diagrams, and what the sheets read: the
mechanism over a revolution, the force polygons and the lever at a position, the plans of
velocity analogues) is computed the first time it is read and kept, so a part the scene does
not ask for costs nothing and none is computed twice.  Readers never call a solver: they
read the Solution.

``fit`` is the drawing's paper: the target lengths of the plans, polygons and lever as a
fraction of the A1 ones (``drawings`` passes √(sheet / A1) for a smaller sheet, the scales
still round, and up to ``MAX_FIT`` for longer plans on a sheet with room for them).  It changes
only scales, never a value: :meth:`Solution.at_fit` gives the same scene at another fit, which
makes its plans, polygons and lever (and the tables read off the plans) again and shares every
other part with the solution it came from (the exact analysis, the reactions, the cycle's
dynamics and diagrams...), solved once for every fit.

Values by their textbook names (``F_12^τ``, ``v_B``, ``omega_3``...) are read with
:meth:`Solution.value`, signed as :mod:`plans.quantities` documents (docs/quantities.md).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from pathlib import PurePath
from typing import TYPE_CHECKING, Any, NamedTuple, overload

from plans.errors import ConstructionError, PlansError
from plans.tolerances import SAME_ANGLE_DEG

if TYPE_CHECKING:
    from plans.cycle.diagrams import Diagrams
    from plans.cycle.dynamics import Dynamics
    from plans.cycle.results import CycleResult
    from plans.forces.lever import LeverAnalysis, Reading
    from plans.forces.loads import Loads
    from plans.forces.polygons import ForceAnalysis, ForcePolygon
    from plans.kinematics.centres import Centre, CentreVelocity
    from plans.kinematics.construction import PositionPlans
    from plans.kinematics.exact import Kinematics
    from plans.kinematics.plan import Plan
    from plans.kinematics.structure import Structure
    from plans.scene.model import Scene

#: The crank angles of "a revolution" the sheets read (the plan of positions' paths every
#: 2.5°, the sliders' strokes every 5°, the mechanism's size every 10°: every 2nd and 4th).
REVOLUTION = 145


class Forces(NamedTuple):
    """The force analysis of a scene: the Bruevich polygons' reactions and the Zhukovsky lever."""

    analysis: ForceAnalysis
    lever: LeverAnalysis


class Revolution(NamedTuple):
    """The mechanism's positions over a revolution: every ``step``-th angle of ``kinematics``."""

    kinematics: Kinematics
    step: int

    @property
    def phi_deg(self) -> Any:
        return self.kinematics.phi_deg[::self.step]

    def point(self, name: str) -> Any:
        """r of a named point at each angle (m, complex)."""
        return self.kinematics.point(name)[0][::self.step]

    def point_on(self, link: int, z: complex) -> Any:
        """r of the point at local ``z`` on ``link`` at each angle (m, complex)."""
        import numpy as np

        return np.asarray(self.kinematics.point_on(link, z)[0])[::self.step]


#: The longest plans a sheet with room asks for: this many times the A1 target lengths.
MAX_FIT = 2.5


class Solution:
    """Everything computed for a scene, each part once, when first read."""

    __slots__ = ("scene", "fit", "_parts", "_common")

    def __init__(self, scene: Scene, fit: float = 1.0) -> None:
        """``scene`` with its ``[loads]``, ``[dynamics]`` and ``[diagrams]`` read and validated now
        (an InputError naming the field, before anything is solved), at the paper's ``fit``."""
        from plans.tables import with_tables

        if not (isinstance(fit, int | float) and not isinstance(fit, bool) and 0.0 < fit <= MAX_FIT):
            raise ValueError(f"fit is the fraction of the A1 target lengths, 0 < fit <= {MAX_FIT:g}; got {fit!r}")
        self.scene: Scene = with_tables(scene, **({} if fit == scene.fit else {"fit": float(fit)}))
        self.fit = float(fit)
        self._parts: dict[Any, Any] = {}  # the parts at this fit
        self._common: dict[Any, Any] = {}  # the parts no fit changes: the same scene's at every fit (at_fit)

    def __repr__(self) -> str:
        return f"Solution({self.scene.path!r}, fit={self.fit:g}, outputs={sorted(self.scene.outputs)})"

    def at_fit(self, fit: float) -> Solution:
        """The same scene at another paper's ``fit`` (longer or shorter plans): its plans,
        polygons and lever (and the tables read off the plans) made at their own round scales
        when read, every other part (the structure, the exact analysis, the reactions, the
        efficiency, dynamics and diagrams, a revolution, the strokes, the instant centres,
        the analogues) this one's, solved once for both."""
        if fit == self.fit:
            return self
        self._common.setdefault(("at fit", self.fit), self)

        def make() -> Solution:
            other = Solution(self.scene, fit)
            other._common = self._common
            return other

        got: Solution = self._shared(("at fit", float(fit)), make)  # one Solution per fit, however often asked
        return got

    def _part(self, key: Any, make: Callable[[], Any]) -> Any:
        """A part at this fit, made once; a construction without an answer names the scene's file."""
        return self._kept(self._parts, key, make)

    def _shared(self, key: Any, make: Callable[[], Any]) -> Any:
        """A part no fit changes, made once for the scene at every fit."""
        return self._kept(self._common, key, make)

    def _kept(self, parts: dict[Any, Any], key: Any, make: Callable[[], Any]) -> Any:
        try:
            return parts[key]
        except KeyError:
            pass
        try:
            got = make()
        except ConstructionError as exc:
            exc.source = self.scene.path
            raise
        parts[key] = got
        return got

    # -- the parts the scene asks for
    @property
    def structure(self) -> Structure:
        """The initial link and the Assur groups."""
        from plans.kinematics.structure import analyse

        return self._shared("structure", lambda: analyse(self.scene))

    @property
    def kinematics(self) -> Kinematics:
        """Exact positions (and velocities, accelerations as the outputs need) at the scene's angles."""
        from plans.kinematics.exact import solve

        return self._part("kinematics", lambda: self._shared(
            "kinematics", lambda: solve(self.scene, structure=self.structure)).on_paper(self.scene))

    def kinematics_to(self, order: int) -> Kinematics:
        """The exact analysis at the scene's positions to at least ``order`` (2: accelerations):
        :attr:`kinematics` where the scene's outputs ask for as much, else solved once more
        at ``order`` and kept (the checker reads accelerations of any scene)."""
        wanted = 2 if self.scene.wants("acceleration_plan") else 1 if self.scene.wants("velocity_plan") else 0
        if wanted >= order:
            return self.kinematics
        from plans.kinematics.exact import solve

        return self._part(("kinematics", order), lambda: self._shared(
            ("kinematics", order), lambda: solve(self.scene, order=order, structure=self.structure)).on_paper(self.scene))

    def plans_at(self, ks: tuple[int, ...], velocity_scale: float | None = None,
                 acceleration_scale: float | None = None) -> tuple[PositionPlans, ...]:
        """Both plans at the positions ``ks`` at the given scales (a student's μv, μa; None: the
        engine's own), built on the exact analysis of order 2, made once per request."""
        def make() -> tuple[PositionPlans, ...]:
            from plans.kinematics.construction import build_many

            return tuple(build_many(self.kinematics_to(2), list(ks), velocity_scale=velocity_scale,
                                    acceleration_scale=acceleration_scale))

        return self._part(("plans at", tuple(ks), velocity_scale, acceleration_scale), make)

    def frictionless(self) -> tuple[Loads, ForceAnalysis]:
        """The loads and the Bruevich force analysis without friction at the exact analysis of
        order 2, whatever the outputs ask for: what a hand-drawn sheet's forces are checked
        against."""
        def make() -> tuple[Loads, ForceAnalysis]:
            from plans.forces.loads import parse_loads
            from plans.forces.polygons import analyse_forces

            loads = self.scene.loads or parse_loads(self.scene)
            return loads, analyse_forces(self.scene, self.kinematics_to(2), loads)

        def here() -> tuple[Loads, ForceAnalysis]:
            loads, fa = self._shared("frictionless", make)
            return loads, fa.on_paper(self.scene)

        return self._part("frictionless", here)

    @property
    def plans(self) -> tuple[PositionPlans, ...]:
        """The velocity and acceleration plans of every position (none unless asked for)."""
        def make() -> tuple[PositionPlans, ...]:
            if not self.scene.wants("velocity_plan"):
                return ()
            from plans.kinematics.construction import build_all

            return tuple(build_all(self.kinematics))

        return self._part("plans", make)

    @property
    def forces(self) -> Forces | None:
        """The force analysis and the lever (None unless the scene asks for polygons or the lever);
        ``fa, lv = sol.forces`` as before."""
        def make() -> Forces | None:
            if not (self.scene.wants("force_polygons") or self.scene.wants("lever")):
                return None
            from plans.forces.analysis import force_analysis
            from plans.forces.lever import zhukovsky_lever

            fa = self._shared("reactions", lambda: force_analysis(self.scene, self.kinematics))
            if fa is None:
                return None
            fa = fa.on_paper(self.scene)
            return Forces(fa, zhukovsky_lever(fa))

        return self._part("forces", make)

    @property
    def efficiency(self) -> dict[str, Any] | None:
        """η over the cycle and η(φ) with friction (the JSON's ``efficiency``): None without
        friction, or where the positions are not a whole turn at equal steps."""
        def make() -> dict[str, Any] | None:
            f = self.forces
            if f is None or f.analysis.friction is None:
                return None
            from plans.forces.friction import efficiency_json

            return efficiency_json(f.analysis)

        return self._shared("efficiency", make)

    @property
    def lever(self) -> LeverAnalysis | None:
        f = self.forces
        return None if f is None else f.lever

    @property
    def cycle(self) -> CycleResult | None:
        """Tables over the positions, the dynamics and the kinematic diagrams (as asked)."""
        def make() -> CycleResult | None:
            from plans.cycle.results import solve_cycle

            return solve_cycle(self.kinematics, self.plans, self.dynamics, self.diagrams)

        return self._part("cycle", make)

    @property
    def dynamics(self) -> Dynamics | None:
        """Machine dynamics and the flywheel (None unless asked for)."""
        if not self.scene.wants("dynamics"):
            return None
        from plans.cycle.dynamics import dynamics

        return self._shared("dynamics", lambda: dynamics(self.scene))

    def dynamics_drawn(self, axis_mm: float, height: float) -> Dynamics:
        """The dynamics with its graphical part (Wittenbauer's diagram, the flywheel read off
        it) drawn at another φ axis and diagram height (shorter and lower on a small sheet,
        longer and taller where an A1 sheet has room): the same dynamics at other scales."""
        d = self.dynamics
        assert d is not None, "a scene with dynamics"
        return self._shared(("dynamics", axis_mm, height), lambda: d.at(axis_mm, height))

    def diagrams_drawn(self, length_mm: float) -> Diagrams | None:
        """The kinematic diagrams drawn at a shorter φ axis (μφ = L/2π), for a sheet too small
        for the scene's; made once per length (None unless asked for)."""
        if not self.scene.wants("diagrams"):
            return None
        from plans.cycle.spec import diagrams_spec

        return self._shared(("diagrams", length_mm), lambda: self._diagrams_of(
            replace(diagrams_spec(self.scene), length_mm=length_mm)))

    def output_diagrams(self, length_mm: float = 240.0) -> Diagrams | None:
        """The output's kinematic diagrams a course's kinematics sheet draws by default
        (:func:`plans.cycle.spec.output_diagrams_spec`) at a φ axis of ``length_mm``; made
        once per length (None where the scene has no slider or rocker on the frame)."""
        def make() -> Diagrams | None:
            from plans.cycle.spec import output_diagrams_spec

            spec = output_diagrams_spec(self.scene, length_mm)
            return None if spec is None else self._diagrams_of(spec)

        return self._shared(("output diagrams", length_mm), make)

    @property
    def diagrams(self) -> Diagrams | None:
        """Kinematic diagrams by graphical differentiation (None unless asked for)."""
        if not self.scene.wants("diagrams"):
            return None
        from plans.cycle.spec import diagrams_spec

        return self._shared("diagrams", lambda: self._diagrams_of(diagrams_spec(self.scene)))

    def _diagrams_of(self, spec: Any) -> Diagrams:
        """The diagrams of ``spec`` drawn off the exact motion over its grid, solved once for
        every φ axis, pole and scale (:func:`plans.cycle.diagrams.motion_key`) and every fit."""
        from plans.cycle.diagrams import diagrams, exact_motions, motion_key

        exact = self._shared(("diagram motions", *motion_key(spec)), lambda: exact_motions(self.scene, spec))
        return diagrams(self.scene, spec, exact)

    def solve_all(self) -> Solution:
        """Every part the scene asks for, now, in the order of the method (the first part
        without an answer stops it, before anything is written)."""
        for part in ("plans", "forces", "cycle"):
            getattr(self, part)
        return self

    # -- what the sheets read besides
    def revolution(self, n: int = REVOLUTION) -> Revolution:
        """Positions only at ``n`` crank angles evenly over one revolution, 0° and 360° both
        included; where ``n - 1`` divides :data:`REVOLUTION`'s steps they are read off that one
        solve.  PlansError where the mechanism does not turn through them all."""
        def own() -> Revolution:
            return Revolution(_revolution(self, n), 1)

        step = (REVOLUTION - 1) // (n - 1) if n > 1 and (REVOLUTION - 1) % (n - 1) == 0 else 0
        if not step or self._common.get("no revolution"):
            return self._shared(("revolution", n), own)
        try:
            whole = self._shared(("revolution", REVOLUTION), lambda: _revolution(self, REVOLUTION))
        except PlansError:  # it may turn through the coarser angles all the same
            self._common["no revolution"] = True  # (not tried again)
            return self._shared(("revolution", n), own)
        return Revolution(whole, step)

    def force_polygons(self, k: int) -> tuple[ForcePolygon, ...]:
        """The Bruevich polygons of position ``k`` (groups, then the crank), at μF for the paper."""
        def make() -> tuple[ForcePolygon, ...]:
            from plans.forces.polygons import force_polygons

            f = self.forces
            return () if f is None else force_polygons(f.analysis, k)

        return self._part(("polygons", k), make)

    def lever_plan(self, k: int) -> Plan:
        """The Zhukovsky lever of position ``k`` (the velocity plan turned 90°, loads at their images)."""
        from plans.forces.lever import lever_plan

        lv = self.lever
        assert lv is not None, "the scene asks for no lever"
        return self._part(("lever", k), lambda: lever_plan(lv, k))

    def force_rows(self, k: int) -> list[Reading]:
        """The balancing load three ways and δ at position ``k`` (rows of the results table)."""
        from plans.forces.lever import force_rows

        lv = self.lever
        assert lv is not None, "the scene asks for no lever"
        return self._part(("rows", k), lambda: force_rows(lv, k))

    def centres(self, k: int) -> tuple[dict[tuple[int, int], Centre], list[CentreVelocity]]:
        """The instant centres at position ``k`` (all n(n−1)/2, by Kennedy's theorem) and the
        named points' velocities read off them."""
        def make() -> tuple[dict[tuple[int, int], Centre], list[CentreVelocity]]:
            from plans.kinematics.centres import centres_at, velocities_at

            got = centres_at(self.kinematics, k)
            return got, velocities_at(self.kinematics, k, got)

        return self._shared(("centres", k), make)

    def analogue_plans(self) -> tuple[Plan, ...]:
        """Plans of velocity analogues at the dynamics table's positions: velocity plans at
        μ_v = μ/|ω1|, so that each segment is the analogue v/ω1 at μ (mm per m)."""
        def make() -> tuple[Plan, ...]:
            import numpy as np

            from plans.kinematics.construction import build
            from plans.kinematics.exact import solve

            d = self.dynamics
            if d is None:
                return ()
            scene = replace(d.scene, outputs=d.scene.outputs | {"velocity_plan"})
            phis = np.asarray(d.spec.phi_deg, float)
            phis = phis[phis < phis[0] + 360.0 - SAME_ANGLE_DEG]  # the second revolution of 720° repeats the first's plans
            kin = solve(scene, phis, order=1)
            mu_v = d.scales.analogue / abs(d.scene.driver.omega)
            out = []
            for k in range(kin.n):
                pp = build(kin, k, velocity_scale=mu_v)
                if pp.velocity is not None:
                    out.append(pp.velocity)
            return tuple(out)

        return self._shared("analogues", make)

    def strokes(self) -> Any:
        """The output link's extreme positions, the working and idle strokes and θ
        (:class:`plans.kinematics.extreme.Strokes`) with the mechanism at both extremes (a
        Kinematics of positions only at [working_deg, idle_deg]), for the plan of positions;
        None where the output has no two extremes (the crank does not turn round, a link
        that turns all the way)."""
        def make() -> Any:
            from plans.kinematics.exact import solve
            from plans.kinematics.extreme import strokes

            try:
                st = strokes(self.scene)
                at = solve(self.scene, [st.working_deg, st.idle_deg], order=0, structure=self.structure)
            except PlansError:
                return None
            return st, at

        return self._shared("strokes", make)

    # -- values by their textbook names (plans.quantities)
    def value(self, name: str, phi: float | None = None) -> float:
        """The quantity ``name`` (``"F_12^τ"``, ``"v_B"``, ``"omega_3"``, ``"F_bal"``...) at the
        crank angle ``phi`` in degrees (one of the scene's; None: its only or first one), in SI,
        signed as docs/quantities.md says.  KeyError naming what is known for an unknown name."""
        from plans.quantities import value

        return value(self, name, phi)

    def values(self, name: str) -> list[float]:
        """The quantity ``name`` at every position of the scene, in order."""
        from plans.quantities import values

        return values(self, name)

    def names(self) -> list[str]:
        """Every quantity name this solution can read."""
        from plans.quantities import names

        return names(self)


def _revolution(sol: Solution, n: int) -> Kinematics:
    import numpy as np

    from plans.kinematics.exact import solve

    return solve(sol.scene, phi_deg=np.linspace(0.0, 360.0, n), order=0, structure=sol.structure)


#: The other kinds of the file family, each solved by its room into one object whose parts
#: are computed when first read: kind -> (its record's module:class, the room's entry).
ROOMS: dict[str, tuple[str, str]] = {
    "engine": ("plans.balancing.engine:Engine", "plans.balancing.solution:solve_engine"),
    "gears": ("plans.gears.model:GearFile", "plans.gears.solution:solve_file"),
    "cam": ("plans.cams.model:Cam", "plans.cams.solution:solve_cam"),
    "synthesis": ("plans.synthesis.model:Task", "plans.synthesis.solution:solve_task"),
}


def _named(ref: str) -> Any:
    import importlib

    module, _, name = ref.partition(":")
    return getattr(importlib.import_module(module), name)


@overload
def solve(scene: Scene, *, fit: float = 1.0) -> Solution: ...


@overload
def solve(scene: Any, *, fit: float = 1.0) -> Any: ...


def solve(scene: Any, *, fit: float = 1.0) -> Any:
    """A scene (or the path of its file) solved: a :class:`Solution` whose parts are computed
    when first read.  ``fit`` < 1 draws the plans, polygons and lever shorter, for a smaller sheet.

    A file (or record) of another kind is solved by its room (:data:`ROOMS`): an engine into a
    :class:`plans.balancing.solution.EngineSolution`, gears into a
    :class:`plans.gears.solution.GearsSolution`, a cam into a
    :class:`plans.cams.solution.CamSolution`, a synthesis task into a
    :class:`plans.synthesis.solution.DesignSolution` (``fit`` is the linkage's alone)."""
    if hasattr(scene, "driver"):
        from plans.kinematics.placing import place

        return Solution(place(scene), fit)  # a scene read by plans.scene: its positions placed
    if isinstance(scene, str | PurePath):
        from plans.io import read_toml
        from plans.kinematics.placing import scene_from_dict

        data = read_toml(str(scene))
        kind = data.get("kind")
        if isinstance(kind, str) and kind in ROOMS:
            from plans.kinds import READERS

            return _named(ROOMS[kind][1])(_named(READERS[kind])(data, str(scene)))
        return Solution(scene_from_dict(data, str(scene)), fit)
    for record, entry in ROOMS.values():
        if isinstance(scene, _named(record)):
            return _named(entry)(scene)
    raise TypeError(f"plans.solve takes a scene, an engine, gears, a cam, a synthesis task or the path "
                    f"of its file; got {type(scene).__name__}")


__all__ = ["Forces", "REVOLUTION", "ROOMS", "Revolution", "Solution", "solve"]
