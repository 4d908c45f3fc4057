"""Scene files: a planar linkage, what drives it and what the user wants from it.

A scene is TOML (``format = 1``).  Links carry their points in *local*
coordinates: the origin is the link's first axis point, the x axis points to
its second axis point (or, for a one-point slider, along its guide).  The frame
is the link whose local coordinates are the global ones.  Everything is
converted to SI here; nothing downstream sees millimetres.
"""

from __future__ import annotations

import cmath
import math
import os
from dataclasses import field, replace
from typing import TYPE_CHECKING, Any

from plans.errors import Said
from plans.io import loads_toml, read_toml
from plans.reader import Reader, did_you_mean, show
from plans.records import frozen
from plans.scene.options import OUTPUTS, read_branches, read_outputs, read_scales, read_title  # noqa: F401
from plans.scene.positions import Placing, read_placing, wanted
from plans.units import LENGTH_UNITS, LENGTH_WARN, SPEED_WARN, rpm_to_rad_s

if TYPE_CHECKING:
    from pathlib import Path

#: F_ij conventions: seed 003 (force on link i from link j) or seed 000 (of link i on link j).
FIJ_CONVENTIONS = ("on_i_from_j", "of_i_on_j")


@frozen
class Guide:
    """A straight line fixed to link ``link``: through local point ``origin``, at local angle ``angle``."""

    link: int
    origin: complex
    angle: float

    @property
    def direction(self) -> complex:
        return cmath.exp(1j * self.angle)


@frozen
class Joint:
    """A lower pair.  ``R``: links share ``point``.  ``P``: ``point`` of the slider link
    moves along ``guide`` (carried by the other link), and the two links keep their
    relative angle."""

    kind: str
    links: tuple[int, int]
    point: str
    guide: Guide | None = None
    slider_angle: float = 0.0  # direction of sliding in the slider's own local frame

    @property
    def name(self) -> str:
        return f"{self.kind}{self.links[0]}{self.links[1]}:{self.point}"

    def other(self, link: int) -> int:
        return self.links[1] if self.links[0] == link else self.links[0]

    @property
    def slider(self) -> int:
        assert self.guide is not None
        return self.other(self.guide.link)


@frozen
class Link:
    """A link of the mechanism: its points in its own coordinates, mass and inertia."""

    id: int
    name: str
    axis: tuple[str, ...]
    length: float | None
    points: dict[str, complex]  # local coordinates (m), axis points included
    mass: float = 0.0
    inertia: float = 0.0  # I_S about the centre of mass, kg m²
    centre: str | None = None  # name of the centre of mass point (S2, ...)


@frozen
class Driver:
    """The initial link: θ1 = φ_ref + sense·φ (see :meth:`rotation`), ω1 = sense·|ω|, ε1 = sense·ε."""

    link: int
    pivot: str
    omega: float  # signed, counter-clockwise positive
    eps: float
    phi_ref: float
    sense: int
    phis_deg: tuple[float, ...]
    #: ``phi_start``: the positions start at the output's extreme ("extreme", "extreme_idle"),
    #: whose strokes are ``strokes`` (plans.kinematics.extreme.Strokes); "" and None otherwise
    start: str = ""
    strokes: Any = None
    #: positions asked for by the piston's travel or from the output's extreme, not placed
    #: yet (``phis_deg`` is empty until :func:`plans.kinematics.placing.place`); None: placed
    placing: Placing | None = None

    def rotation(self, phi_deg: Any) -> Any:
        """e^{iθ1}, with θ1 reduced in degrees by whole quarter turns first, so that the
        crank angle near a dead centre (90°, 180°, ...) keeps its small offset exactly."""
        import numpy as np

        phi = np.fmod(np.asarray(phi_deg, dtype=float), 360.0)  # exact, even for 1e21 degrees
        t = math.degrees(self.phi_ref) + self.sense * phi
        q = np.round(t / 90.0)
        r = t - 90.0 * q
        quarter = np.array([1, 1j, -1, -1j])[q.astype(int) % 4]
        return quarter * np.exp(1j * np.radians(r))


@frozen(weakref_slot=True)
class Scene:
    """A linkage scene as read from its file, in SI: links, joints, driver, positions, outputs."""

    path: str
    title: str
    frame: int
    frame_points: dict[str, complex]
    links: dict[int, Link]
    joints: tuple[Joint, ...]
    driver: Driver
    branches: dict[str, int]
    outputs: frozenset[str]
    scales: dict[str, float]  # "length", "velocity", "acceleration", "force": mm per SI unit
    scale_style: str  # the notation's token (plans.scene.notation): the scales' letter and direction, the pole
    fij: str
    raw: dict[str, Any] = field(repr=False, default_factory=dict)
    titles: dict[str, str] = field(default_factory=dict)  # per sheet language: {"ru": ..., "en": ...}
    #: the target lengths of the plans, polygons and lever as a fraction of the A1 ones: a
    #: smaller sheet's (``plans.solve(scene, fit=...)``; never read from a file)
    fit: float = 1.0
    #: the other tables as typed records (:mod:`plans.tables`): ``[loads]``
    #: (plans.forces.loads.Loads), ``[dynamics]`` and ``[diagrams]`` (plans.cycle.spec) read by
    #: ``plans.solve`` (then ``tables`` is True), None where the file neither gives nor needs
    #: them; ``[sheet]`` is validated with the file and read as :attr:`sheet`
    loads: Any = field(default=None, repr=False)
    dynamics_spec: Any = field(default=None, repr=False)
    diagrams_spec: Any = field(default=None, repr=False)
    #: the pairs' friction (plans.scene.friction.FrictionSpec), read with the other tables
    #: (None: the scene states none)
    friction_spec: Any = field(default=None, repr=False)
    tables: bool = field(default=False, repr=False)
    # what the exact analysis derives once per scene (its structure, the solver's constants)
    # is kept beside it (plans.records.derived), so a changed scene (dataclasses.replace) derives its own

    def title_in(self, lang: str) -> str:
        """The title in a sheet's language (the plain title where none is given for it)."""
        return self.titles.get(lang, self.title)

    @property
    def sheet(self) -> Any:
        """``[sheet]`` as a typed record (plans.scene.paper.SheetSpec), validated with the file."""
        from plans.scene.sheet import sheet_for

        return sheet_for(self)

    def sheet_for(self, **override: Any) -> Any:
        """``[sheet]`` with what a command overrides (format, orientation, language = ...)."""
        from plans.scene.sheet import sheet_for

        return sheet_for(self, **override)

    def wants(self, output: str) -> bool:
        return output in self.outputs

    def point_links(self, name: str) -> list[int]:
        """The links that carry point ``name`` (the frame included)."""
        out = [lid for lid, link in self.links.items() if name in link.points]
        if name in self.frame_points:
            out.append(self.frame)
        return out


# --------------------------------------------------------------------------- parsing


#: The most crank positions one scene may ask for (a position every 0.1°); beyond it the
#: tables, JSON and sheets would run to gigabytes.
MAX_POSITIONS = 3600

#: Keys of each table of a linkage scene (the readers of loads and [sheet] check their own).
TOP_KEYS = {"format", "kind", "title", "unit", "frame", "points", "links", "joints", "driver", "branches",
            "outputs", "scales", "fij", "loads", "sheet", "diagrams", "dynamics",
            "friction"}  # [friction]: plans.scene.friction
LINK_KEYS = {"name", "axis", "length", "points", "mass", "inertia", "centre"}
JOINT_KEYS = {"kind", "links", "point", "guide", "slider_angle_deg",
              "f", "pin_radius", "friction_circle"}  # friction: plans.scene.friction
GUIDE_KEYS = {"link", "through", "toward", "angle_deg", "offset"}
DRIVER_KEYS = {"link", "omega", "omega_rpm", "sense", "eps", "phi_ref_deg", "phi_deg", "positions", "phi0_deg",
               "s_mm", "s_fraction", "s_stroke", "piston",  # positions by the piston's travel: scene.positions
               "phi_start", "extreme_of"}  # positions from the output's extreme: scene.positions
#: ω at most 1e6 rad/s, and 0 or at least 1e-6 rad/s (a slower crank makes plan scales overflow).
OMEGA_LIMIT = 1e6


def check_format(r: Reader, data: dict[str, Any]) -> None:
    """``format = 1`` exactly (an integer, not ``true`` nor ``1.0``)."""
    fmt = data.get("format")
    if isinstance(fmt, bool) or not isinstance(fmt, int) or fmt != 1:
        raise r.fail("format", Said("e_format", got=Said("e_nothing") if fmt is None else show(fmt)))


def load_scene(path: str | Path) -> Scene:
    """Read and validate a scene file; an implausible one (a unit slip, look-alike names) is
    warned about on stderr (:mod:`plans.plausible`).  Positions asked for by the piston's
    travel or from the output's extreme are left to place (``driver.placing``):
    ``plans.load_scene`` (:mod:`plans.kinematics.placing`) reads and places them."""
    return warn_implausible(scene_from_dict(read_toml(path), str(path)), path)


def warn_implausible(scene: Scene, path: str | Path) -> Scene:
    """The scene, warned about on stderr when implausible (:mod:`plans.plausible`)."""
    if _implausible(scene):
        from plans.plausible import warn_scene

        warn_scene(scene, str(scene.raw.get("unit", "mm")), str(path))
    return scene


def _implausible(scene: Scene) -> bool:
    """Whether :mod:`plans.plausible` has something to warn about (found here cheaply: that
    module is loaded only then): a link or a crank-pin speed beyond machines', a name with
    letters outside ASCII (a look-alike may hide in it)."""
    if any(not n.isascii() for n in scene.frame_points):
        return True
    for link in scene.links.values():
        pts = list(link.points.values())
        if (link.length or 0.0) > LENGTH_WARN or any(abs(a - b) > LENGTH_WARN for a in pts for b in pts):
            return True
        if any(not n.isascii() for n in link.points):
            return True
    crank = scene.links.get(scene.driver.link)
    if crank is not None and len(crank.axis) == 2:
        r = abs(crank.points[crank.axis[1]] - crank.points[crank.axis[0]])
        return abs(scene.driver.omega) * r > SPEED_WARN
    return False


def _stem(path: str) -> str:
    """The file's name without its last suffix, as ``pathlib.PurePath.stem`` (without
    loading pathlib on the way to a solve)."""
    name = os.path.basename(path)
    i = name.rfind(".")
    return name[:i] if 0 < i < len(name) - 1 else name


def parse_scene(text: str, path: str = "<scene>") -> Scene:
    return scene_from_dict(loads_toml(text, path), path)


def scene_from_dict(data: dict[str, Any], path: str = "<scene>") -> Scene:
    """The scene of a file's table, validated; positions by travel or from an extreme are
    a request (``driver.placing``) for :func:`plans.kinematics.placing.place`."""
    r = Reader(path)
    from plans.kinds import check_top

    check_top(data, path, "linkage", TOP_KEYS)
    unit = r.choice(data, "unit", "", sorted(LENGTH_UNITS), "mm")
    title, titles = read_title(r, data.get("title", _stem(path)))
    r.string(title, "title", limit=2000)
    for lang, text in titles.items():
        r.string(text, f"title.{lang}", limit=2000)
    frame = data.get("frame")
    if isinstance(frame, bool) or not isinstance(frame, int) or not 0 < frame < 1_000_000:
        raise r.fail("frame", Said("e_frame"))

    frame_points = _frame_points(r, data, unit)
    links_raw = r.table(data, "links", "")
    links = {}
    links_raw_key: dict[int, str] = {}
    for key, body in links_raw.items():
        lid = _link_id(r, key)
        if lid == frame:
            raise r.fail(f"links.{key}", Said("e_link_is_frame", link=lid))
        if not isinstance(body, dict):
            raise r.fail(f"links.{key}", Said("e_table"))
        if lid in links:
            raise r.fail(f"links.{key}", Said("e_link_twice", link=lid, a=links_raw_key[lid], b=key))
        links_raw_key[lid] = key
        links[lid] = _link(r, lid, body, unit)
    if not links:
        raise r.fail("links", Said("e_no_links"))

    joints = _joints(r, data, unit, frame, frame_points, links)
    links = _orient_sliders(r, links, joints)
    _shared_points(r, frame, frame_points, links, joints)
    driver = _driver(r, data, frame, frame_points, links)
    branches = read_branches(r, data)
    outputs = read_outputs(r, data)
    scales, style = read_scales(r, data)
    fij = r.choice(data, "fij", "", FIJ_CONVENTIONS, "on_i_from_j")
    if "sheet" in data:  # without one, every field takes its default: nothing to check
        from plans.scene.sheet import check_sheet

        check_sheet(data, path)  # the record is made when a reader asks for it (Scene.sheet)
    if wanted(data["driver"]):  # no angle in the file: the kinematics places them
        driver = replace(driver, phis_deg=(), placing=read_placing(r, data["driver"], joints, frame))
    return Scene(path=path, title=title, frame=frame, frame_points=frame_points, links=links,
                 joints=joints, driver=driver, branches=branches, outputs=outputs,
                 scales=scales, scale_style=style, fij=fij, raw=data, titles=titles)


def _link_id(r: Reader, key: str) -> int:
    """``[links.2]``: a positive number written plainly (``01``, ``+1``, ``1_0`` would
    merge or hide links)."""
    if not (key.isascii() and key.isdigit()) or key != str(int(key)) or len(key) > 6:
        raise r.fail(f"links.{key}", Said("e_link_number"))
    lid = int(key)
    if lid <= 0:
        raise r.fail(f"links.{key}", Said("e_link_positive"))
    return lid


def _xy(r: Reader, value: Any, field: str, unit: str) -> complex:
    if not (isinstance(value, list) and len(value) == 2):
        raise r.fail(field, Said("e_point_xy"))
    return complex(r.length(value[0], f"{field}[0]", unit), r.length(value[1], f"{field}[1]", unit))


def _frame_points(r: Reader, data: dict[str, Any], unit: str) -> dict[str, complex]:
    pts = r.table(data, "points", "")
    return {r.name(name, f"points.{name}"): _xy(r, value, f"points.{name}", unit) for name, value in pts.items()}


def _link(r: Reader, lid: int, body: dict[str, Any], unit: str) -> Link:
    where = f"links.{lid}."
    r.keys(body, LINK_KEYS, where)
    axis = body.get("axis")
    if not (isinstance(axis, list) and 1 <= len(axis) <= 2 and all(isinstance(a, str) for a in axis)):
        raise r.fail(f"{where}axis", Said("e_axis"))
    for k, a in enumerate(axis):
        r.name(a, f"{where}axis[{k}]")
    if len(axis) == 2 and axis[0] == axis[1]:
        raise r.fail(f"{where}axis", Said("e_axis_same"))
    length = None
    points: dict[str, complex] = {axis[0]: 0j}
    if len(axis) == 2:
        if "length" not in body:
            raise r.fail(f"{where}length", Said("e_missing_length", ab=f"{axis[0]}{axis[1]}"))
        length = r.length(body["length"], f"{where}length", unit, positive=True)
        points[axis[1]] = complex(length, 0.0)
    elif "length" in body:
        raise r.fail(f"{where}length", Said("e_slider_length"))
    extra = body.get("points", {})
    if not isinstance(extra, dict):
        raise r.fail(f"{where}points", Said("e_points_table"))
    for name, spec in extra.items():
        f = f"{where}points.{name}"
        r.name(name, f)
        if name in points:
            raise r.fail(f, Said("e_point_on_axis"))
        if not isinstance(spec, dict):
            raise r.fail(f, Said("e_point_spec"))
        r.keys(spec, ("ratio", "along", "across"), f + ".")
        if "ratio" in spec and ({"along", "across"} & set(spec)):
            raise r.fail(f, Said("e_point_both"))
        if "ratio" in spec:
            if length is None:
                raise r.fail(f, Said("e_ratio_axis"))
            ratio = r.number(spec, "ratio", f + ".", limit=1e6)
            points[name] = complex(ratio * length, 0.0)
        else:
            along = r.length(spec.get("along", 0), f + ".along", unit)
            across = r.length(spec.get("across", 0), f + ".across", unit)
            points[name] = complex(along, across)
    mass = r.number(body, "mass", where, default=0.0, nonneg=True)
    inertia = r.number(body, "inertia", where, default=0.0, nonneg=True)
    centre = body.get("centre")
    if centre is not None and (not isinstance(centre, str) or centre not in points):
        raise r.fail(f"{where}centre", Said("e_unknown_point", point=show(centre), link=lid,
                                            hint=did_you_mean(centre, points) if isinstance(centre, str) else ""))
    name = r.string(body.get("name", f"link {lid}"), f"{where}name")
    return Link(id=lid, name=name, axis=tuple(axis), length=length, points=points,
                mass=mass, inertia=inertia, centre=centre)


def _joints(r: Reader, data: dict[str, Any], unit: str, frame: int,
            frame_points: dict[str, complex], links: dict[int, Link]) -> tuple[Joint, ...]:
    raw = data.get("joints")
    if not isinstance(raw, list) or not raw:
        raise r.fail("joints", Said("e_joints"))
    known_links = set(links) | {frame}
    out = []
    for k, body in enumerate(raw):
        where = f"joints[{k}]."
        if not isinstance(body, dict):
            raise r.fail(f"joints[{k}]", Said("e_table"))
        r.keys(body, JOINT_KEYS, where)
        kind = body.get("kind")
        if kind not in ("R", "P"):
            raise r.fail(f"{where}kind", Said("e_joint_kind", got=show(kind)))
        pair = body.get("links")
        if not (isinstance(pair, list) and len(pair) == 2
                and all(isinstance(x, int) and not isinstance(x, bool) for x in pair)):
            raise r.fail(f"{where}links", Said("e_joint_links"))
        for lid in pair:
            if lid not in known_links:
                raise r.fail(f"{where}links", Said("e_unknown_link", link=lid))
        if pair[0] == pair[1]:
            raise r.fail(f"{where}links", Said("e_joint_same"))
        point = body.get("point")
        if not isinstance(point, str):
            raise r.fail(f"{where}point", Said("e_point_name"))
        a, b = pair

        def carries(lid: int, name: str) -> bool:
            return name in (frame_points if lid == frame else links[lid].points)

        if kind == "R":
            if "guide" in body or "slider_angle_deg" in body:
                raise r.fail(f"{where}guide" if "guide" in body else f"{where}slider_angle_deg",
                             Said("e_r_guide"))
            for lid in pair:
                if not carries(lid, point):
                    from plans.plausible import not_on_link

                    raise r.fail(f"{where}point", not_on_link(point, lid, frame_points if lid == frame
                                                              else links[lid].points))
            out.append(Joint("R", (a, b), point))
            continue
        g = body.get("guide")
        if not isinstance(g, dict):
            raise r.fail(f"{where}guide", Said("e_p_guide"))
        r.keys(g, GUIDE_KEYS, f"{where}guide.")
        if "toward" in g and "angle_deg" in g:
            raise r.fail(f"{where}guide.angle_deg", Said("e_toward_angle"))
        carrier = g.get("link")
        if isinstance(carrier, bool) or not isinstance(carrier, int) or carrier not in pair:
            raise r.fail(f"{where}guide.link", Said("e_guide_link", pair=list(pair)))
        slider = b if carrier == a else a
        if not carries(slider, point):
            raise r.fail(f"{where}point", Said("e_not_on_slider", point=point, link=slider))
        through = g.get("through")
        if isinstance(through, str):
            if not carries(carrier, through):
                from plans.plausible import not_on_link

                raise r.fail(f"{where}guide.through", not_on_link(through, carrier, frame_points if carrier == frame
                                                                   else links[carrier].points))
            origin = frame_points[through] if carrier == frame else links[carrier].points[through]
        elif isinstance(through, list):
            origin = _xy(r, through, f"{where}guide.through", unit)
        else:
            raise r.fail(f"{where}guide.through", Said("e_through"))
        if "toward" in g:
            tw = g["toward"]
            if not (isinstance(tw, str) and carries(carrier, tw)):
                raise r.fail(f"{where}guide.toward", Said("e_toward", link=carrier))
            target = frame_points[tw] if carrier == frame else links[carrier].points[tw]
            if abs(target - origin) == 0:
                raise r.fail(f"{where}guide.toward", Said("e_toward_through"))
            angle = cmath.phase(target - origin)
        else:
            angle = math.radians(r.angle(g, "angle_deg", f"{where}guide."))
        offset = r.length(g.get("offset", 0), f"{where}guide.offset", unit)
        origin = origin + offset * 1j * cmath.exp(1j * angle)  # offset to the left of the direction
        slider_angle = math.radians(r.angle(body, "slider_angle_deg", where))
        out.append(Joint("P", (a, b), point, Guide(carrier, origin, angle), slider_angle))
    return tuple(out)


def _orient_sliders(r: Reader, links: dict[int, Link], joints: tuple[Joint, ...]) -> dict[int, Link]:
    """One-point links need a local x axis: the guide they slide on or carry."""
    for lid, link in links.items():
        if len(link.axis) == 2:
            continue
        as_slider = [j for j in joints if j.kind == "P" and j.slider == lid]
        as_carrier = [j for j in joints if j.kind == "P" and j.guide is not None and j.guide.link == lid]
        if not as_slider and not as_carrier:
            raise r.fail(f"links.{lid}.axis", Said("e_one_point"))
        for j in as_slider:
            if j.point != link.axis[0]:
                raise r.fail(f"links.{lid}.axis", Said("e_slider_axis", point=j.point))
    return links


def _driver(r: Reader, data: dict[str, Any], frame: int, frame_points: dict[str, complex],
            links: dict[int, Link]) -> Driver:
    d = r.table(data, "driver", "")
    r.keys(d, DRIVER_KEYS, "driver.")
    lid = d.get("link")
    if isinstance(lid, bool) or not isinstance(lid, int) or lid not in links:
        raise r.fail("driver.link", Said("e_driver_link", links=sorted(links), got=show(lid)))
    link = links[lid]
    if len(link.axis) != 2 or link.axis[0] not in frame_points:
        raise r.fail("driver.link", Said("e_driver_axis"))
    if "omega_rpm" in d and "omega" in d:
        raise r.fail("driver.omega_rpm", Said("e_omega_both"))
    if "omega_rpm" in d:
        omega = rpm_to_rad_s(r.number(d, "omega_rpm", "driver.", nonneg=True, limit=OMEGA_LIMIT * 30 / math.pi,
                                      floor=1e-6))
    elif "omega" in d:
        omega = r.number(d, "omega", "driver.", nonneg=True, limit=OMEGA_LIMIT, floor=1e-6)
    else:
        raise r.fail("driver.omega", Said("e_omega_missing"))
    sense = 1 if r.choice(d, "sense", "driver.", ("ccw", "cw"), "ccw") == "ccw" else -1
    # ε of dust is ε = 0 to rounding (it scales with ω², 1e-12 at the slowest crank): no floor
    eps = r.number(d, "eps", "driver.", default=0.0, floor=0.0)
    phi_ref = math.radians(r.angle(d, "phi_ref_deg", "driver."))
    if "phi_deg" in d and "positions" in d:
        raise r.fail("driver.phi_deg", Said("e_phi_both"))
    if "phi0_deg" in d and "positions" not in d:
        raise r.fail("driver.phi0_deg", Said("e_phi0"))
    if "positions" in d:
        n = r.integer(d, "positions", "driver.", at_least=1)
        if n > MAX_POSITIONS:
            raise r.fail("driver.positions", Said("e_positions_many", n=n, limit=MAX_POSITIONS))
        phi0 = r.angle(d, "phi0_deg", "driver.")
        phis = tuple(phi0 + 360.0 * k / n for k in range(n))
    else:
        raw = d.get("phi_deg")
        if raw is None and ("s_mm" in d or "s_fraction" in d) and "phi_deg" not in d:
            raw = 0.0  # placed by the piston's travel (plans.scene.positions)
        if raw is None:
            raise r.fail("driver.phi_deg", Said("e_phi_missing"))
        values = raw if isinstance(raw, list) else [raw]
        if not values:
            raise r.fail("driver.phi_deg", Said("e_phi_none"))
        if len(values) > MAX_POSITIONS:
            raise r.fail("driver.phi_deg", Said("e_angles_many", n=len(values), limit=MAX_POSITIONS))
        for v in values:
            if isinstance(v, bool) or not isinstance(v, int | float):
                raise r.fail("driver.phi_deg", Said("e_degrees", got=show(v)))
        phis = tuple(r.value(v, "driver.phi_deg", limit=1e300, floor=0.0) for v in values)
    return Driver(link=lid, pivot=link.axis[0], omega=sense * omega, eps=sense * eps,
                  phi_ref=phi_ref, sense=sense, phis_deg=phis)


def _shared_points(r: Reader, frame: int, frame_points: dict[str, complex], links: dict[int, Link],
                   joints: tuple[Joint, ...]) -> None:
    """A point name carried by several links names one point: the links must be joined
    there (turning pairs, or a slider on its guide).  Two unjoined points of one name would
    silently become one."""
    carriers: dict[str, list[int]] = {}
    for lid, link in sorted(links.items()):
        for nm in link.points:
            carriers.setdefault(nm, []).append(lid)
    for nm in frame_points:
        carriers.setdefault(nm, []).append(frame)
    for nm, lids in carriers.items():
        if len(lids) < 2:
            continue
        parent = {lid: lid for lid in lids}

        def root(x: int, parent: dict[int, int] = parent) -> int:
            while parent[x] != x:
                x = parent[x]
            return x

        for j in joints:
            if j.point == nm and all(x in parent for x in j.links):
                parent[root(j.links[0])] = root(j.links[1])
        groups = {root(x) for x in lids}
        if len(groups) > 1:
            where = "points" if frame in lids else f"links.{lids[-1]}.points"
            raise r.fail(f"{where}.{nm}", Said("e_shared_point", point=nm, links=", ".join(map(str, lids))))
