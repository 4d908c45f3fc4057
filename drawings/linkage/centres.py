"""Instant centres on the sheet: the scheme with every centre P_ij and Kennedy's lines that
fixed the secondary ones, and the circle diagram (links on a circle; a solid edge for a
centre at a pair, a dashed one for a centre found by Kennedy's theorem)."""

from __future__ import annotations

import cmath
import math
from types import SimpleNamespace

from drawings.linkage.panels import LABEL_SIZE, SMALL_SIZE, Panel, finish, scheme_panel, table_panel
from drawings.paper.backend import THIN, Recording, Style
from drawings.paper.common import Placer, angle, arrow, fmt, ident, phi_tag
from drawings.paper.text import layout
from plans.kinematics.centres import Centre, CentreVelocity, all_links

_WORDS = {
    "title": ("Мгновенные центры скоростей", "Instant centres"),
    "diagram": ("Круговая диаграмма (теорема Кеннеди)", "Circle diagram (Kennedy's theorem)"),
    "off": ("вне чертежа", "off the drawing"),
    "coincide": ("не определён: прямые Кеннеди совпадают", "undetermined: Kennedy's lines coincide"),
    "unreached": ("не определён: нет двух прямых Кеннеди", "undetermined: no two Kennedy lines reach it"),
    "infinity": ("в бесконечности", "at infinity"),
}

KENNEDY = Style(width=0.18, stroke="#555", dash=(3.0, 1.5), cls="construction")
PRIMARY = Style(width=0.5, cls="edge primary")
SECONDARY = Style(width=0.35, dash=(2.5, 1.5), cls="edge secondary")


def _w(key: str, lang: str) -> str:
    ru, en = _WORDS[key]
    return ru if lang == "ru" else en


def _label(c: Centre) -> str:
    i, j = c.links
    return f"P_{{{i}{j}}}" if max(i, j) < 10 else f"P_{{{i},{j}}}"


def _plain(c: Centre) -> str:
    return c.label


def centres_panels(sol, k: int, mu_l: float, lang: str, strokes: dict) -> list[Panel]:
    """The centres on the scheme at position k, and the circle diagram (``Solution.centres``)."""
    scene, kin = sol.scene, sol.kinematics
    centres, velocities = sol.centres(k)
    return [scheme_panel(scene, kin, k, mu_l, lang, strokes, overlay=_overlay(scene, kin, k, centres, lang)),
            diagram_panel(kin, k, centres, lang), velocity_table(scene, kin, k, velocities, mu_l, lang)]


def velocity_table(scene, kin, k: int, velocities: list[CentreVelocity], mu_l: float, lang: str) -> Panel:
    """v = ω_j·|P_jf Q| for every named point, the arm measured on the scheme at μl, next to
    the exact value (what the velocity plan reads too)."""
    phi = float(kin.phi_deg[k])
    ref = abs(scene.driver.omega) * kin.reach()
    rows = []
    for cv in velocities:
        if cv.v is None:
            continue
        if cv.centre is None:  # a translating link: every point moves as P_1j
            seg, mm, sc = None, None, None
        else:
            i, j = cv.centre
            seg, mm, sc = f"P{i}{j} {cv.point}", (cv.distance or 0.0) * mu_l, mu_l
        rows.append(SimpleNamespace(quantity=f"v_{cv.point}", segment=seg, length_mm=mm, scale=sc, value=abs(cv.v),
                                    exact=abs(cv.exact), unit="m/s", ref=ref))
    return table_panel(rows, lang, scene.scale_style, phi, pid=f"centre-table-{phi_tag(phi)}",
                       title_key="centre_table")


def _overlay(scene, kin, k: int, centres: dict, lang: str):
    phi = float(kin.phi_deg[k])
    pts = [complex(kin.point(nm)[0][k]) for nm in kin.point_names()] + list(scene.frame_points.values())
    xs, ys = [z.real for z in pts], [z.imag for z in pts]
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)
    box = (min(xs) - 0.6 * span, min(ys) - 0.6 * span, max(xs) + 0.6 * span, max(ys) + 0.6 * span)

    def inside(z: complex) -> bool:
        return box[0] <= z.real <= box[2] and box[1] <= z.imag <= box[3]

    def draw(rec: Recording, T, placer: Placer, pid: str) -> tuple[str, str, str]:
        notes = []
        rec.begin(f"{pid}-kennedy", "kennedy")
        for c in centres.values():  # the lines first, the centres over them
            if c.point is None or c.source in ("pair", None) or not inside(c.point):
                continue
            for pair in (c.source, c.other) if c.other is not None else (c.source,):
                ends = [centres[tuple(sorted(p))].point for p in pair] + [c.point]
                if any(e is None or not inside(e) for e in ends):
                    continue
                u = ends[1] - ends[0] if abs(ends[1] - ends[0]) > 0 else c.point - ends[0]
                if abs(u) == 0:
                    continue
                u /= abs(u)
                ss = [((e - ends[0]) * u.conjugate()).real for e in ends]
                a, b = min(ss) - 4 / T.scale, max(ss) + 4 / T.scale
                rec.line(T.z(ends[0] + a * u), T.z(ends[0] + b * u), KENNEDY,
                         f"{pid}-kennedy-{ident(c.label)}-{pair[0][0]}{pair[0][1]}{pair[1][0]}{pair[1][1]}")
        rec.end()
        rec.begin(f"{pid}-ic", "instant-centres")
        right = T.z(complex(box[2] - 0.6 * span + 0.15 * span, box[3] - 0.6 * span))
        row = 0
        for c in centres.values():
            eid = f"{pid}-ic-{ident(c.label)}"
            if c.point is not None and inside(c.point):
                p = T.z(c.point)
                rec.circle(p, 1.1, Style(width=0.3, fill="#fff", cls="instant-centre"), eid)
                rec.line((p[0] - 1.6, p[1]), (p[0] + 1.6, p[1]), THIN)
                rec.line((p[0], p[1] - 1.6), (p[0], p[1] + 1.6), THIN)
                placer.add_disc(p, 1.4)
                lab = placer.place(_label(c), p, LABEL_SIZE - 0.5, gap=1.5)
                rec.text(lab, "label", f"{eid}-label")
            elif c.point is not None:
                x, y = fmt(c.point.real, 4, lang), fmt(c.point.imag, 4, lang)
                notes.append(f"{_plain(c)} {_w('off', lang)} ({x}; {y}) м" if lang == "ru"
                             else f"{_plain(c)} {_w('off', lang)} ({x}, {y}) m")
            elif c.direction is not None:  # a direction: a double arrow beside the scheme
                d = T.direction(c.direction.real, c.direction.imag)
                mid = (right[0] + 12.0, right[1] + 9.0 * row)
                row += 1
                p0, p1 = (mid[0] - 5 * d[0], mid[1] - 5 * d[1]), (mid[0] + 5 * d[0], mid[1] + 5 * d[1])
                arrow(rec, mid, p1, THIN, f"{eid}-dir+", "instant-centre-direction", head=2.0, half=0.7)
                arrow(rec, mid, p0, THIN, f"{eid}-dir-", "instant-centre-direction", head=2.0, half=0.7)
                placer.add_line([p0, p1])
                lab = layout(f"{_label(c)} ∞", mid[0] + 7.0, mid[1], LABEL_SIZE - 0.5, "start", "middle")
                placer.add_box(lab.box)
                rec.text(lab, "label", f"{eid}-label")
            else:
                notes.append(f"{_plain(c)} {_w('coincide' if 'coincide' in c.why else 'unreached', lang)}")
        rec.end()
        return "centres", f"{_w('title', lang)}, φ = {angle(phi, lang)}°", "; ".join(notes)

    return draw


def diagram_panel(kin, k: int, centres: dict, lang: str) -> Panel:
    """Links as points on a circle; each centre found is an edge between its two links."""
    phi = float(kin.phi_deg[k])
    pid = f"circle-{phi_tag(phi)}"
    links = all_links(kin)
    n = len(links)
    R = 22.0
    at = {lid: (R * math.cos(math.pi / 2 + 2 * math.pi * m / n), -R * math.sin(math.pi / 2 + 2 * math.pi * m / n))
          for m, lid in enumerate(links)}
    rec = Recording()
    rec.begin(f"{pid}-edges", "edges")
    for (i, j), c in centres.items():
        if c.point is None and c.direction is None:
            continue  # not found: no edge
        rec.line(at[i], at[j], PRIMARY if c.source == "pair" else SECONDARY, f"{pid}-edge-{i}-{j}")
    rec.end()
    rec.begin(f"{pid}-links", "links")
    for lid, p in at.items():
        rec.circle(p, 1.0, Style(stroke=None, width=0.0, fill="#000", cls="link-point"), f"{pid}-link-{lid}")
        u = cmath.exp(1j * math.atan2(p[1], p[0]))
        lab = layout(str(lid), p[0] + 4.0 * u.real, p[1] + 4.0 * u.imag, LABEL_SIZE, "middle", "middle")
        rec.text(lab, "label", f"{pid}-label-{lid}")
    rec.end()
    y = R + 9.0
    rec.line((-R, y), (-R + 10.0, y), PRIMARY, f"{pid}-key-primary")
    rec.text(layout("в паре" if lang == "ru" else "at a pair", -R + 12.0, y, SMALL_SIZE + 0.5, "start", "middle"),
             "legend-text", f"{pid}-key-primary-text")
    rec.line((-R, y + 5.0), (-R + 10.0, y + 5.0), SECONDARY, f"{pid}-key-secondary")
    rec.text(layout("по теореме Кеннеди" if lang == "ru" else "by Kennedy's theorem", -R + 12.0, y + 5.0,
                    SMALL_SIZE + 0.5, "start", "middle"), "legend-text", f"{pid}-key-secondary-text")
    return finish(pid, "circle-diagram", phi, rec, f"{_w('diagram', lang)}, φ = {angle(phi, lang)}°")
