"""Drawing-wide panels: the plan of positions (the mechanism at every crank angle of the
scene overlaid, positions numbered, a point's trajectory traced) and the legend of line
styles.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Iterable, Sequence

import numpy as np

from drawings.linkage.panels import (
    BLOCK_H,
    BLOCK_L,
    JOINT_R,
    LABEL_SIZE,
    SMALL_SIZE,
    VECTOR_STYLES,
    Panel,
    finish,
    fixed_pivot,
    link_shape,
    ratio_text,
    scale_text,
)
from drawings.paper.backend import Recording, Style, Transform
from drawings.paper.common import Placer, angle, arrow, coincident_positions, dot, fmt, ident
from drawings.paper.i18n import tr
from drawings.paper.text import layout, point_label
from plans.errors import InputError, PlansError, Said

POS_THIN = Style(width=0.25, stroke="#000", cls="position")
POS_BOLD = Style(width=0.6, stroke="#000", cls="position bold")
PATH = Style(width=0.25, stroke="#000", cls="path")  # trajectory of a numbered pin
TRACE = Style(width=0.3, stroke="#a35200", dash=(4.0, 1.0, 1.0, 1.0, 1.0, 1.0), cls="trace")  # dash-dot-dot
NUMBER_SIZE = SMALL_SIZE + 0.3


def _points_at(scene, kin, k: int) -> dict[str, complex]:
    """Every named point of the mechanism at position k (world m)."""
    out: dict[str, complex] = dict(scene.frame_points)
    for lid in sorted(scene.links):
        for name, z in scene.links[lid].points.items():
            out.setdefault(name, complex(kin.point_on(lid, z)[0][k]))
    return out


def _edges(scene, kin, k: int, pts: dict[str, complex]) -> tuple[list[tuple[str, str]], dict[str, complex]]:
    """The mechanism at position k as a graph: link outlines, and the stretch of every moving
    guide (a slot) from the carrier's points to the slider's pin."""
    edges: list[tuple[str, str]] = []
    extra: dict[str, complex] = {}
    for lid in sorted(scene.links):
        kind, names = link_shape(scene, lid)
        if kind == "line":
            edges.append((names[0], names[1]))
        elif kind == "polygon":
            edges.extend((names[i], names[(i + 1) % len(names)]) for i in range(len(names)))
    for jt in scene.joints:
        if jt.kind != "P" or jt.guide is None or jt.guide.link == scene.frame:
            continue
        g = jt.guide
        u = cmath.exp(1j * (float(kin.theta(g.link)[k]) + g.angle))
        G = complex(kin.point_on(g.link, g.origin)[0][k])
        on_line: list[tuple[float, str]] = [(((pts[jt.point] - G) * u.conjugate()).real, jt.point)]
        for n in scene.links[g.link].points:
            if n.startswith("S") and n != scene.links[g.link].axis[0]:
                continue
            s = ((pts[n] - G) * u.conjugate()).real
            foot = G + s * u
            if abs(foot - pts[n]) > 1e-9 * max(abs(pts[n]), 1.0):
                fid = f"{n}>{jt.point}"
                extra[fid] = foot
                edges.append((n, fid))
                on_line.append((s, fid))
            else:
                on_line.append((s, n))
        on_line.sort()
        edges.extend((a[1], b[1]) for a, b in zip(on_line[:-1], on_line[1:], strict=False) if a[1] != b[1])
    return edges, extra


def _walks(edges: Iterable[tuple[str, str]]) -> list[list[str]]:
    """One walk per connected part that draws every edge (a tree's edges twice: there and
    back), deterministic: neighbours in sorted order."""
    adj: dict[str, list[str]] = {}
    for a, b in edges:
        if a == b:
            continue
        adj.setdefault(a, []).append(b)
        adj.setdefault(b, []).append(a)
    for v in adj.values():
        v.sort()
    used: set[frozenset[str]] = set()
    seen: set[str] = set()
    out: list[list[str]] = []
    for start in sorted(adj):
        if start in seen:
            continue
        path: list[str] = [start]
        stack = [(start, iter(adj[start]))]
        seen.add(start)
        while stack:
            node, it = stack[-1]
            nxt = next((v for v in it if frozenset((node, v)) not in used), None)
            if nxt is None:
                stack.pop()
                if stack:
                    path.append(stack[-1][0])
                continue
            used.add(frozenset((node, nxt)))
            seen.add(nxt)
            path.append(nxt)
            stack.append((nxt, iter(adj[nxt])))
        while len(path) > 2 and path[-1] == path[-3]:  # no need to walk back home
            path.pop()
        out.append(path)
    return out


def numbered_points(scene) -> list[str]:
    """Where positions get their numbers: the crank pin, the pins between moving links and
    the sliders' pins on fixed guides."""
    d = scene.driver
    out = [scene.links[d.link].axis[1]]
    for jt in scene.joints:
        moving = all(lid != scene.frame for lid in jt.links)
        slider = jt.kind == "P" and jt.guide is not None and jt.guide.link == scene.frame
        if (moving or slider) and jt.point not in out and jt.point not in scene.frame_points:
            out.append(jt.point)
    return out


def default_trace(scene) -> list[str]:
    """Centres of mass of the links hinged to the crank pin (the connecting rods), else the
    first centre of mass of a moving link other than the crank."""
    d = scene.driver
    pin = scene.links[d.link].axis[1]

    def centre(lid: int) -> str | None:
        link = scene.links[lid]
        return link.centre if link.centre and link.centre.startswith("S") else next(
            (n for n in link.points if n.startswith("S")), None)

    rods = [lid for lid in sorted(scene.links) if lid != d.link and pin in scene.links[lid].points]
    out = [c for c in (centre(lid) for lid in rods) if c]
    if not out:
        out = [c for c in (centre(lid) for lid in sorted(scene.links) if lid != d.link) if c][:1]
    return out


def _trajectories(sol, names: Sequence[str]) -> dict[str, list[complex]]:
    """World paths of ``names`` over one revolution, every 2.5° (empty where the mechanism locks)."""
    scene = sol.scene
    try:
        rev = sol.revolution()
    except PlansError:
        return {}
    out = {}
    for name in names:
        for lid in sorted(scene.links):
            if name in scene.links[lid].points:
                out[name] = [complex(z) for z in rev.point_on(lid, scene.links[lid].points[name])]
                break
    return out


def positions_panel(sol, mu_l: float, lang: str, bold: Sequence[int], strokes: dict[str, tuple[float, float]],
                    trace: Sequence[str] | None = None, brief: bool = False, first: int = 1) -> Panel:
    """The plan of positions: the mechanism at the positions in ``bold`` (thick), the crank
    alone at the others (thin); positions numbered ``first``, ``first`` + 1, … at the crank pin
    and the other moving pins on their trajectories (a pin whose marks come near another's is
    numbered with its letter, B_3); the trajectory of the ``trace`` points (default: the rods'
    centres of mass); the guides' axes and the fixed pivots once; the output's two extreme
    positions (thin dash-dot-dot), the working and idle strokes on the crank circle and the
    overlap angle θ (:meth:`plans.solution.Solution.strokes`)."""
    scene, kin = sol.scene, sol.kinematics
    pid = "positions"
    T = Transform(mu_l)
    rec = Recording()
    placer = Placer()
    frame = scene.frame
    n = kin.n
    names_all = {nm for lid in scene.links for nm in scene.links[lid].points}
    trace = default_trace(scene) if trace is None else list(trace)
    for t in trace:
        if t not in names_all:
            raise InputError(Said("lo_point_moving_link", t=t, v=sorted(names_all)), file=scene.path,
                             field="sheet.trace")
    at = [_points_at(scene, kin, k) for k in range(n)]
    everything = [z for pts in at for z in pts.values()]
    centre_world = sum(everything) / max(len(everything), 1)

    # once: the axes of the fixed guides over the stroke, the crank pin's circle, the pivots
    rec.begin(f"{pid}-frame", "frame")
    for jt in scene.joints:
        if jt.kind != "P" or jt.guide is None or jt.guide.link != frame:
            continue
        g = jt.guide
        u = cmath.exp(1j * g.angle)
        ss = [((pts[jt.point] - g.origin) * u.conjugate()).real for pts in at]
        lo, hi = strokes.get(jt.name, (min(ss), max(ss)))
        lo, hi = min(lo, *ss) - 10 / mu_l, max(hi, *ss) + 10 / mu_l
        a0, a1 = T.z(g.origin + lo * u), T.z(g.origin + hi * u)
        rec.line(a0, a1, Style(stroke="#333", width=0.18, dash=(6.0, 1.0, 1.0, 1.0), cls="axis"),
                 f"{pid}-axis-{ident(jt.point)}")
        placer.add_line([a0, a1])
    d = scene.driver
    crank = scene.links[d.link]
    O = scene.frame_points.get(d.pivot, at[0][d.pivot])
    pin = crank.axis[1]
    r_pin = abs(at[0][pin] - O) * mu_l
    c = T.z(O)
    rec.circle(c, r_pin, Style(width=0.18, stroke="#555", cls="crank-circle"), f"{pid}-crank-circle")
    placer.add_line([(c[0] + r_pin * math.cos(a), c[1] + r_pin * math.sin(a))
                     for a in np.linspace(0.0, 2 * math.pi, 49)])
    for jt in scene.joints:
        if jt.kind == "R" and frame in jt.links and jt.point in scene.frame_points:
            p = T.z(scene.frame_points[jt.point])
            fixed_pivot(rec, p, f"{pid}-support-{ident(jt.point)}")
            placer.add_disc((p[0], p[1] + 4.0), 4.0)
            placer.add_disc(p, JOINT_R + 0.3)
    rec.end()

    # trajectories: the traced points, and the numbered pins that neither ride the crank
    # circle nor a fixed guide's axis (the links themselves only at the bold positions)
    on_axis = {jt.point for jt in scene.joints if jt.kind == "P" and jt.guide is not None and jt.guide.link == frame}
    pins = [m for m in numbered_points(scene) if m != pin and m not in on_axis and m not in trace]
    paths = _trajectories(sol, list(trace) + pins)
    rec.begin(f"{pid}-traces", "traces")
    for name in list(trace) + pins:
        path = paths.get(name)
        if not path:
            continue
        curve = [T.z(z) for z in path]
        st = TRACE if name in trace else PATH
        rec.polyline(curve, st, f"{pid}-{'trace' if name in trace else 'path'}-{ident(name)}")
        placer.add_line(curve)
    rec.end()

    # the mechanism at each position: one walk (polyline) per connected part
    bold_set = set(bold)
    for k in range(n):
        pts = at[k]
        edges, extra = _edges(scene, kin, k, pts)
        where = {**pts, **extra}
        st = POS_BOLD if k in bold_set else POS_THIN
        rec.begin(f"{pid}-pos-{k}", "position bold" if k in bold_set else "position")
        walks = _walks(edges) if k in bold_set else [[d.pivot, pin]]  # thin: the crank alone
        for w, walk in enumerate(walks):
            line = [T.z(where[v]) for v in walk]
            rec.polyline(line, st, f"{pid}-pos-{k}" + (f"-{w}" if w else ""))
            placer.add_line(line)
        if k in bold_set:  # a position with its own scheme: slider blocks, as the scheme draws them
            for jt in scene.joints:
                if jt.kind != "P" or jt.guide is None:
                    continue
                th = 0.0 if jt.guide.link == frame else float(kin.theta(jt.guide.link)[k])
                ang = -(th + jt.guide.angle)
                c0 = T.z(pts[jt.point])
                ux, uy = math.cos(ang), math.sin(ang)
                hl, hh = BLOCK_L / 2, BLOCK_H / 2
                corners = [(c0[0] + sx * hl * ux - sy * hh * uy, c0[1] + sx * hl * uy + sy * hh * ux)
                           for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
                rec.polygon(corners, Style(width=0.5, cls="slider"), f"{pid}-slider-{ident(jt.point)}-{k}")
                placer.add_poly(corners)
        for name in trace:
            if name in pts:
                dot(rec, T.z(pts[name]), 0.45)
                placer.add_disc(T.z(pts[name]), 0.6)
        rec.end()
    c = T.z(O)
    rec.circle(c, JOINT_R, Style(width=0.35, fill="#fff", cls="joint"), f"{pid}-joint-{ident(d.pivot)}")

    made = sol.strokes()
    ends = made[0] if made is not None else None  # the output's extremes (plans.kinematics.extreme)
    if made is not None:
        _strokes(rec, placer, scene, made[0], made[1], T, O, pin, at[0][pin], lang, pid)

    # the numbers: coincident positions of a point share one label ("1, 11")
    rec.begin(f"{pid}-numbers", "numbers")
    marks = numbered_points(scene)
    lettered = _crowded(marks, pin, [{m: T.z(at[k][m]) for m in marks} for k in range(n)])
    for name in marks:
        for ks in coincident_positions([T.z(at[k][name]) for k in range(n)]):
            p = T.z(at[ks[0]][name])
            r = 0.7 if any(k in bold_set for k in ks) else 0.5
            rec.circle(p, r, Style(width=0.2, fill="#fff", cls="mark"))
            placer.add_disc(p, r + 0.2)
    for name in marks:
        for ks in coincident_positions([T.z(at[k][name]) for k in range(n)]):
            p = T.z(at[ks[0]][name])
            away = at[ks[0]][name] - (O if name == pin else centre_world)
            L = abs(away) or 1.0
            nums = [str(k + first) for k in ks]
            if name in lettered:  # beside another pin's marks: every number with its letter
                nums = [f"{name}_{{{x}}}" if name.isalpha() else f"{point_label(name)} ({x})" for x in nums]
            elif ks[0] == 0:  # the letter once, at the first position: A_1, B_1
                nums[0] = f"{name}_{{{first}}}" if name.isalpha() else f"{point_label(name)} ({first})"
            text = ", ".join(nums)
            lab = placer.place(text, p, NUMBER_SIZE, prefer=(away.real / L, -away.imag / L), gap=0.8)
            rec.text(lab, "number", f"{pid}-n-{ident(name)}-{ks[0]}")
    # the letters of the fixed pivots, the name of each traced point by its curve
    for name in list(scene.frame_points) + [t for t in trace if t in paths]:
        if name in scene.frame_points:
            z = scene.frame_points[name]
        else:
            path = paths[name]
            z = path[int(np.argmax([w.imag for w in path]))]
        away = z - centre_world
        L = abs(away) or 1.0
        lab = placer.place(point_label(name), T.z(z), LABEL_SIZE, prefer=(away.real / L, -away.imag / L), gap=2.0)
        rec.text(lab, "label" + (" trace" if name in trace else ""), f"{pid}-label-{ident(name)}",
                 fill=(TRACE.stroke or "#000") if name in trace else "#000")
    rec.end()

    phis = [float(x) for x in kin.phi_deg]
    steps = {round(b - a, 9) for a, b in zip(phis[:-1], phis[1:], strict=False)}
    if len(steps) == 1 and n > 2:
        when = f"φ_{first} = {angle(phis[0], lang)}°, Δφ = {angle(steps.pop(), lang)}°"
    elif brief and n > 2:  # a small sheet: the first and the last angle (every one is in the tables)
        when = f"φ_{first} = {angle(phis[0], lang)}°, …, φ_{{{n - 1 + first}}} = {angle(phis[-1], lang)}°"
    else:
        when = ", ".join(f"φ_{{{i + first}}} = {angle(p, lang)}°" for i, p in enumerate(phis))
    if ends is not None:
        when += f"; θ = {angle(round(ends.theta_deg, 2), lang)}°, K = {fmt(ends.K, 4, lang)}"
    bold_txt = ", ".join(str(k + first) for k in sorted(bold_set))
    if lang == "ru":
        note = f"{when}; жирно: {bold_txt}" if bold_set else when
    else:
        note = f"{when}; bold: {bold_txt}" if bold_set else when
    title = tr("positions", lang)
    return finish(pid, "positions", None, rec, title,
                  f"{scale_text('length', mu_l, scene.scale_style, lang)}  (M {ratio_text(mu_l, lang)})", note,
                  "length", mu_l)


EXTREME = Style(width=0.35, stroke="#000", dash=(6.0, 1.0, 1.0, 1.0, 1.0, 1.0), cls="extreme")  # GOST 2.303
STROKE_GAP = 5.0  # mm outside the crank circle: the arcs of the strokes


def _crowded(marks: Sequence[str], pin: str, at: Sequence[dict[str, tuple[float, float]]],
             near: float = 6.0) -> set[str]:
    """The numbered pins with a mark within ``near`` mm of another pin's mark: numbered with
    their letter there (the crank pin keeps its bare numbers), so two overlapping
    trajectories never share bare numbers."""
    out: set[str] = set()
    for i, a in enumerate(marks):
        for b in marks[i + 1:]:
            if any(math.dist(p[a], q[b]) < near for p in at for q in at):
                out |= {a, b} - {pin}
    return out


def _free_label(placer: Placer, text: str, c: tuple[float, float], r: float, angles: Sequence[float]):
    """A label just outside a circle of radius ``r`` about ``c``, at the first of ``angles``
    where it crosses no line and no label; else where the placer finds room."""
    size = SMALL_SIZE + 0.5
    for a in angles:
        ux, uy = math.cos(a), math.sin(a)
        anchor = "start" if ux > 0.35 else ("end" if ux < -0.35 else "middle")
        valign = "top" if uy > 0.35 else ("bottom" if uy < -0.35 else "middle")
        lab = layout(text, c[0] + r * ux, c[1] + r * uy, size, anchor, valign)
        soft, clash = placer._costs(np.array([[lab.box[0] - 0.3, lab.box[1] - 0.3, lab.box[2] + 0.3,
                                               lab.box[3] + 0.3]]))
        if soft[0] == 0 and not clash[0]:
            placer.boxes.append(lab.box)
            return lab
    mid = angles[0]
    return placer.place(text, (c[0] + r * math.cos(mid), c[1] + r * math.sin(mid)), size,
                        prefer=(math.cos(mid), math.sin(mid)), gap=1.0)


def _strokes(rec: Recording, placer: Placer, scene, st, ext, T: Transform, O: complex, pin: str, pin0: complex,
             lang: str, pid: str) -> None:
    """The two extreme positions of the output (the mechanism thin dash-dot-dot, the crank pin
    lettered A', A''), the working and idle strokes as arcs outside the crank circle from
    one extreme to the other in the crank's sense, and θ between the crank at the end of
    the working stroke and the crank at its start extended through the pivot."""
    rec.begin(f"{pid}-extremes", "extremes")
    pins = []
    slider = st.output.kind == "slider"
    for j, mark in enumerate(("'", "''")):  # ' where the working stroke begins, '' where the idle one does
        pts = _points_at(scene, ext, j)
        edges, extra = _edges(scene, ext, j, pts)
        where = {**pts, **extra}
        for w, walk in enumerate(_walks(edges)):
            line = [T.z(where[v]) for v in walk]
            rec.polyline(line, EXTREME, f"{pid}-extreme-{j + 1}" + (f"-{w}" if w else ""))
            placer.add_line(line)
        pins.append(pts[pin])
        out = pts.get(st.output.point) if slider else None
        for name in [st.output.point] if out is not None else []:  # the slider's two extremes: B', B''
            z = where[name]
            away = z - O
            L = abs(away) or 1.0
            text = f"{name}{mark}" if name.isalpha() else f"{point_label(name)}{mark}"
            lab = placer.place(text, T.z(z), LABEL_SIZE, prefer=(away.real / L, -away.imag / L), gap=1.2)
            rec.text(lab, "label extreme", f"{pid}-extreme-{j + 1}-{ident(name)}")
    rec.end()
    # the strokes: arcs outside the crank circle, in the crank's sense of rotation
    c = T.z(O)
    r_pin = abs(pin0 - O) * T.scale
    sense = 1 if scene.driver.sense > 0 else -1
    a_start = [math.atan2(-(z - O).imag, (z - O).real) for z in pins]  # paper angles
    rec.begin(f"{pid}-strokes", "strokes")
    for j, (key, deg) in enumerate((("working", st.working_span), ("idle", 360.0 - st.working_span))):
        a0 = a_start[j]
        sweep = -sense * math.radians(deg)  # paper y is down: counter-clockwise is negative
        r = r_pin + STROKE_GAP + 2.0 * j
        style = Style(width=0.5 if key == "working" else 0.3, stroke="#1f4e9c",
                      dash=() if key == "working" else (3.0, 1.5), cls=f"stroke {key}")
        lo, hi = (a0, a0 + sweep) if sweep > 0 else (a0 + sweep, a0)
        rec.arc(c, r, lo, hi, style, f"{pid}-stroke-{key}")
        ang = a0 + sweep
        tip = (c[0] + r * math.cos(ang), c[1] + r * math.sin(ang))
        back = ang - math.copysign(min(0.5, 7.0 / r), sweep)
        tail = (c[0] + r * math.cos(back), c[1] + r * math.sin(back))
        arrow(rec, tail, tip, Style(width=0.3, stroke="#1f4e9c"), f"{pid}-stroke-{key}-head", "stroke-head")
        placer.add_line([(c[0] + r * math.cos(t), c[1] + r * math.sin(t)) for t in np.linspace(lo, hi, 25)])
        words = tr(f"{key}_stroke", lang)
        sym = ("φ_р" if key == "working" else "φ_х") if lang == "ru" else ("φ_w" if key == "working" else "φ_i")
        text = f"{words}, {sym} = {angle(round(deg, 2), lang)}°"
        lab = _free_label(placer, text, c, r + 1.5, [a0 + sweep * t for t in (0.5, 0.35, 0.65, 0.2, 0.8, 0.1, 0.9)])
        rec.text(lab, "label stroke", f"{pid}-stroke-{key}-label", fill="#1f4e9c")
    # θ: from the start crank extended through O to the end crank
    if st.theta_deg > 0.05:
        ext = a_start[0] + math.pi
        e1 = (c[0] + r_pin * math.cos(ext), c[1] + r_pin * math.sin(ext))
        rec.line(c, e1, Style(width=0.25, stroke="#000", dash=(6.0, 1.0, 1.0, 1.0), cls="theta"), f"{pid}-theta-line")
        placer.add_line([c, e1])
        rt = 0.55 * r_pin
        d = (a_start[1] - ext + math.pi) % (2 * math.pi) - math.pi  # the short way, |d| = θ
        lo, hi = (ext, ext + d) if d > 0 else (ext + d, ext)
        rec.arc(c, rt, lo, hi, Style(width=0.3, stroke="#000", cls="theta"), f"{pid}-theta")
        mid = ext + d / 2
        lab = placer.place(f"θ = {angle(round(st.theta_deg, 2), lang)}°", (c[0] + rt * math.cos(mid),
                           c[1] + rt * math.sin(mid)), SMALL_SIZE + 0.5, prefer=(math.cos(mid), math.sin(mid)),
                           gap=1.0)
        rec.text(lab, "label theta", f"{pid}-theta-label")
    rec.end()


# --------------------------------------------------------------------------- legend

LEGEND_ORDER = ("absolute", "relative", "normal", "tangential", "coriolis", "sliding", "construction", "force",
                "closing", "arm", "trace")
_LEGEND_WORDS: dict[str, tuple[str, str]] = {
    "absolute": ("абсолютный вектор (из полюса)", "absolute vector (from the pole)"),
    "relative": ("относительный вектор (v_BA, a_BA)", "relative vector (v_BA, a_BA)"),
    "normal": ("нормальная составляющая a^n", "normal component a^n"),
    "tangential": ("касательная составляющая a^τ", "tangential component a^τ"),
    "coriolis": ("ускорение Кориолиса a^k", "Coriolis acceleration a^k"),
    "sliding": ("относительное движение (скольжение) v^r, a^r", "relative (sliding) motion v^r, a^r"),
    "construction": ("линия построения (∥, ⊥)", "construction line (∥, ⊥)"),
    "force": ("известная сила", "known force"),
    "closing": ("замыкающая (искомая) реакция", "closing (unknown) reaction"),
    "arm": ("плечо силы h", "arm h of a force"),
    "trace": ("траектория точки", "trajectory of a point"),
}


def legend_kinds(panels: Iterable[Panel]) -> list[str]:
    """The line styles the drawn panels use, in legend order."""
    found: set[str] = set()
    for panel in panels:
        for p in panel.prims:
            cls = (p.cls if p.op in ("begin", "text") else (p.style.cls if p.style else "")).split()
            if p.op == "begin" and cls[:1] == ["vector"] and len(cls) > 1:
                found.add(cls[1])
            elif p.op == "begin" and cls[:2] == ["force", "reaction"]:
                found.add("closing")
            elif p.op == "begin" and cls[:2] == ["force", "load"]:
                found.add("force")
            elif p.op in ("line", "polyline") and cls[:1] in (["construction"], ["trace"]):
                found.add(cls[0])
            elif p.op == "line" and "-arm-" in p.eid:
                found.add("arm")
    return [k for k in LEGEND_ORDER if k in found]


def legend_panel(kinds: Sequence[str], lang: str) -> Panel:
    """One row per line style: a short sample of the line (arrow for vectors) and its meaning."""
    from drawings.linkage.forces_panels import ARM

    pid = "legend"
    rec = Recording()
    row = 5.5
    x0, x1 = 0.0, 16.0
    for i, kind in enumerate(kinds):
        y = i * row
        eid = f"{pid}-{kind}"
        if kind == "construction":
            rec.line((x0, y), (x1, y), Style(width=0.18, stroke="#666", cls="construction"), eid)
        elif kind == "trace":
            rec.line((x0, y), (x1, y), TRACE, eid)
        elif kind == "arm":
            rec.line((x0, y), (x1, y), ARM, eid)
        else:
            st = VECTOR_STYLES[kind]
            arrow(rec, (x0, y), (x1, y), st, eid, f"legend-sample {kind}")
        text = _LEGEND_WORDS[kind][0 if lang == "ru" else 1]
        lab = layout(text, x1 + 3.0, y, SMALL_SIZE + 0.5, "start", "middle")
        rec.text(lab, "legend-text", f"{eid}-text")
    title = "Условные обозначения" if lang == "ru" else "Legend"
    return finish(pid, "legend", None, rec, title)


__all__ = ["positions_panel", "legend_panel", "legend_kinds", "numbered_points", "coincident_positions",
           "default_trace"]
