"""The note of a project: its files' sections in the course's order, in one language.

Order: the task and its data; structural analysis; design (synthesis); kinematics (per
position studied, the tables over the positions, the diagrams); kinetostatics; dynamics
and the flywheel; gears; cams; balancing; conclusions.  A section appears when a file asks
for what it holds, never empty.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from typing import Any

from . import cycle, forces, linkage, others
from .model import Note, Section, TitlePage, fmt
from .source import HOOKS, Item, read
from .words import say, w


def note(paths: list[str], lang: str | None = None) -> Note:
    """Read and solve the files, then build their note in ``lang`` (None: the first file's
    ``[sheet] language``, else the locale's)."""
    if lang is None:
        from plans.io import read_toml
        from plans.language import choose

        lang = choose(None, read_toml(paths[0]))
    return build(read(paths), lang)


def build(items: list[Item], lang: str) -> Note:
    links = [it for it in items if it.kind == "linkage"]
    secs: list[Section] = []

    task = Section(w("task", lang), key="task")
    for it in links:
        linkage.task(it, lang, task)
    if not links:
        task.para(say(lang, "Проект включает: ", "The project holds: ")
                  + ", ".join(_kind_name(it.kind, lang) for it in items) + ".")
    secs.append(task)

    if links:
        st = Section(w("structure", lang), key="structure")
        for it in links:
            linkage.structure(it, lang, st)
        secs.append(st)

    for it in items:  # design: a synthesis file's section, from its own module
        if it.kind in HOOKS:
            hook = importlib.import_module(HOOKS[it.kind])
            secs.extend(hook.section(it, lang))

    def kinematics(it: Item, sec: Section) -> list[Section]:
        subs = linkage.kinematics(it, lang, sec)
        dg = cycle.diagrams(it, lang)
        return subs + ([] if dg is None else [dg])

    for sec in (
            _of_linkages("kinematics", lang, links, kinematics, say(
                lang, "Скорости и ускорения определяем методом планов; точные значения аналитического "
                      "решения совпадают с прочитанными с планов в пределах точности построения.",
                "Velocities and accelerations are found by the method of plans; the exact analytical values "
                "agree with those read off the plans to the accuracy of the construction.")),
            _of_linkages("forces", lang, links, lambda it, _: forces.forces(it, lang), say(
                lang, "Силовой расчёт выполняем методом планов сил (Бруевича) по группам Ассура, начиная с "
                      "наиболее удалённой от начального звена; уравновешивающую силу проверяем по рычагу Жуковского.",
                "The force analysis is done by force polygons (Bruevich's method) group by group, the group "
                "farthest from the initial link first; the balancing force is checked by the Zhukovsky lever.")),
            _of_linkages("dynamics", lang, links, lambda it, _: cycle.dynamics(it, lang))):
        if sec is not None:
            secs.append(sec)

    for kind, section in (("gears", others.gears), ("cam", others.cam), ("engine", others.balancing)):
        secs.extend(section(it, lang) for it in items if it.kind == kind)
    secs.append(conclusions(items, lang))
    return Note(lang, title_page(items, lang), secs, tuple(it.path for it in items),
                tuple(it.kind for it in items), w("contents", lang))


def _of_linkages(key: str, lang: str, links: list[Item], part: Callable[[Item, Section], list[Section]],
                 closing: str = "") -> Section | None:
    """The section ``key`` of every linkage's ``part`` (which may write into the section
    too), closed by ``closing``; None where no linkage has any."""
    sec = Section(w(key, lang), key=key)
    for it in links:
        sec.children += part(it, sec)
    if not sec.children:
        return None
    if closing:
        sec.para(closing)
    return sec


def _kind_name(kind: str, lang: str) -> str:
    return {"gears": say(lang, "зубчатый механизм", "gears"), "cam": say(lang, "кулачковый механизм", "a cam"),
            "engine": say(lang, "уравновешивание двигателя", "an engine's balancing"),
            "linkage": say(lang, "рычажный механизм", "a linkage")}.get(kind, kind)


def title_page(items: list[Item], lang: str) -> TitlePage:
    """From the first file's ``[sheet]`` title-block data (the same as on the sheets)."""
    sheet: dict[str, Any] = {}
    title = ""
    for it in items:
        table = it.raw.get("sheet")
        if isinstance(table, dict) and not sheet:
            sheet = table
        if not title:
            t = it.raw.get("title")
            if isinstance(t, dict):
                t = t.get(lang)
            if isinstance(t, str) and others.in_language(t, lang):
                title = t
    t = sheet.get("title")
    if isinstance(t, dict):
        t = t.get(lang)
    if isinstance(t, str) and t:
        title = t

    def s(key: str) -> str:
        v = sheet.get(key, "")
        return v if isinstance(v, str) and others.in_language(v, lang) else ""

    return TitlePage(organization=s("organization"), kind=w("note", lang), title=title or say(
        lang, "Курсовой проект по теории механизмов и машин", "Course project in the theory of machines and mechanisms"),
        subtitle=s("subtitle") or w("to_project", lang), designation=s("designation"), author=s("author"),
        group=s("group"), checked_by=s("checked_by"), date=s("date"))


def conclusions(items: list[Item], lang: str) -> Section:
    sec = Section(w("conclusions", lang), key="conclusions")
    for it in items:
        if it.kind == "linkage":
            st = it.data["structure"]
            sec.para(say(lang, f"Механизм имеет подвижность W = {st['W']}, состоит из начального звена и "
                               f"{len(st['groups'])} групп Ассура второго класса.",
                         f"The mechanism has mobility W = {st['W']}: the initial link and {len(st['groups'])} "
                         "Assur groups of class II."))
            for k in linkage.studied(it):
                b = it.data["positions"][k].get("balancing")
                if b and b.get("by_lever") is not None:
                    phi = linkage.deg(it.data["positions"][k]["phi_deg"])
                    sym = "F_ур" if lang == "ru" else "F_bal"
                    sec.para(say(lang, f"При φ = {phi}° уравновешивающая сила {sym} = {fmt(b['by_kinetostatics'], lang)} Н по планам "
                                       f"сил и {fmt(b['by_lever'], lang)} Н по рычагу Жуковского.",
                                 f"At φ = {phi}° the balancing force {sym} = {fmt(b['by_kinetostatics'], lang)} N by the force "
                                 f"polygons and {fmt(b['by_lever'], lang)} N by the Zhukovsky lever."))
            dy = it.data.get("dynamics")
            if dy:
                sec.para(say(lang, f"Для δ = {fmt(dy['flywheel']['delta'], lang)} нужен маховик с моментом инерции "
                                   f"{fmt(dy['flywheel']['inertia_graphical'], lang)} кг·м².",
                             f"For δ = {fmt(dy['flywheel']['delta'], lang)} the flywheel needs a moment of inertia of "
                             f"{fmt(dy['flywheel']['inertia_graphical'], lang)} kg·m²."))
        elif it.kind == "gears":
            for me in it.data["meshes"]:
                a, b = me["gears"]
                sec.para(say(lang, f"Передача {a}–{b}: угол зацепления {fmt(me['working_pressure_angle_deg'], lang, 6)}°, "
                                   f"коэффициент перекрытия {fmt(me['contact_ratio'], lang)}.",
                             f"Pair {a}–{b}: working pressure angle {fmt(me['working_pressure_angle_deg'], lang, 6)}°, "
                             f"contact ratio {fmt(me['contact_ratio'], lang)}."))
        elif it.kind == "cam":
            sec.para(say(lang, f"Минимальный радиус начальной шайбы кулачка {fmt(it.data['min_base_radius'], lang)} мм.",
                         f"The cam's smallest base radius is {fmt(it.data['min_base_radius'], lang)} mm."))
    return sec
