"""The demonstration page: one self-contained HTML file (inline SVG, CSS and a small script,
no network) that replays the construction of a position step by step, runs the mechanism
over the cycle with its plans following, and shows what classic mistakes do.

The page solves nothing: every number and coordinate comes from :func:`plans.demo.lesson`,
embedded as JSON; the script only draws and interpolates.  ``plans demo SCENE -o page.html``
writes it; in Jupyter a :class:`Demo` displays inline.
"""

from __future__ import annotations

import argparse
import html
import json
from importlib import resources
from pathlib import Path
from typing import Any

from plans.demo import FRAMES, lesson
from plans.errors import InputError, Said
from plans.io import atomic_write
from plans.kinematics.placing import load_scene
from plans.scene.model import Scene

WORDS = {
    "en": {
        "steps": "Step by step", "cycle": "The cycle", "back": "◀ Back", "next": "Next ▶", "play": "▶ Play",
        "pause": "❚❚ Pause", "mistakes_title": "Typical mistakes", "scheme": "Scheme",
        "velocity_plan": "Velocity plan", "acceleration_plan": "Acceleration plan", "chart": "Balancing load",
        "keys": "Keys: ← → step, Home / End; in the cycle ← → turn the crank, space plays.",
        "panel_titles": {"velocity": "velocity plan", "acceleration": "acceleration plan",
                         "force": "force polygon, group", "lever": "Zhukovsky lever",
                         "crank": "initial link"},
        "mistakes": {"coriolis": "Coriolis vector reversed", "normal": "normal component from the wrong point",
                     "couple": "inertia couple with the wrong sign", "pi": "π = 3.14"},
        "position": "position", "forces": "Forces over the cycle", "decimal": ".",
        "units": {"m/s^2": "m/s²"}, "labels": {},
    },
    "ru": {
        "steps": "По шагам", "cycle": "Цикл", "back": "◀ Назад", "next": "Далее ▶", "play": "▶ Пуск",
        "pause": "❚❚ Пауза", "mistakes_title": "Типичные ошибки", "scheme": "Схема",
        "velocity_plan": "План скоростей", "acceleration_plan": "План ускорений", "chart": "Уравновешивающая нагрузка",
        "keys": "Клавиши: ← → шаг, Home / End; в цикле ← → поворот кривошипа, пробел — пуск.",
        "panel_titles": {"velocity": "план скоростей", "acceleration": "план ускорений",
                         "force": "план сил группы", "lever": "рычаг Жуковского",
                         "crank": "начальное звено"},
        "mistakes": {"coriolis": "кориолисово ускорение в обратную сторону",
                     "normal": "нормальная составляющая не от той точки",
                     "couple": "момент сил инерции с неверным знаком", "pi": "π = 3,14"},
        "position": "положение", "forces": "Силы за цикл", "decimal": ",",
        "units": {"mm/(m/s)": "мм/(м/с)", "mm/(m/s²)": "мм/(м/с²)", "mm/N": "мм/Н", "N": "Н", "N·m": "Н·м",
                  "J": "Дж", "rad/s": "рад/с", "rad/s²": "рад/с²", "kg·m²": "кг·м²", "m": "м", "m/s": "м/с",
                  "m/s²": "м/с²", "m/s^2": "м/с²", "mm": "мм", "s": "с"},
        "labels": {"F_bal": "F_ур", "M_bal": "M_ур", "M_pr": "M_пр", "I_pr": "I_пр", "Ff": "F_тр", "Mf": "M_тр"},
        "points": {"p_v": "p", "p_a": "π"},  # the poles as a Russian course names them
    },
}

_CSS = """
:root { --ink: #1b1b1b; --hi: #c0392b; --bad: #d35400; --thin: #7f8c8d; --bg: #fdfdfb; }
* { box-sizing: border-box; }
body { margin: 0; font: clamp(14px, 1.6vw, 22px)/1.35 "DejaVu Sans", Arial, sans-serif; color: var(--ink);
       background: var(--bg); }
header { display: flex; align-items: center; gap: 1em; padding: .4em .8em; border-bottom: 1px solid #ccc; }
header h1 { font-size: 1.1em; margin: 0; flex: 1; }
header button.on, .tab.on { background: var(--ink); color: #fff; }
button { font: inherit; padding: .25em .7em; border: 1px solid #888; background: #fff; border-radius: 4px;
         cursor: pointer; }
button:disabled { opacity: .4; cursor: default; }
main { padding: .4em .8em; }
.stage { display: grid; grid-template-columns: 1fr 1fr; gap: .6em; }
.cycle .stage { grid-template-columns: 1.3fr 1fr 1fr; }
.cycle .stage.two { grid-template-columns: 1fr 1fr; }
.cycle .stage.one { grid-template-columns: 1fr; }
figure { margin: 0; border: 1px solid #ddd; background: #fff; }
figcaption { font-size: .8em; padding: .1em .4em; border-bottom: 1px solid #eee; }
svg { width: 100%; height: auto; max-height: 58vh; display: block; }
.forces { display: grid; grid-template-columns: repeat(auto-fit, minmax(12em, 1fr)); gap: .6em; margin-bottom: .6em; }
.cycle .stage svg { max-height: 40vh; }
.forces svg { max-height: 30vh; aspect-ratio: 25 / 28; }
.charts { display: grid; grid-template-columns: repeat(auto-fit, minmax(18em, 1fr)); gap: .6em; }
svg.chart { max-height: 22vh; }
.node { fill: #fff; stroke: #2c3e50; stroke-width: .4; }
.controls { display: flex; align-items: center; gap: .6em; margin: .4em 0; flex-wrap: wrap; }
#tabs { display: flex; gap: .3em; flex-wrap: wrap; margin: .3em 0; }
.tab { font-size: .75em; }
#step-text { font-size: 1.05em; min-height: 2.8em; margin: .3em 0; padding: .3em .5em; background: #f4f4ef;
             border-left: 4px solid var(--hi); }
#mistakes { font-size: .85em; display: flex; gap: 1.2em; flex-wrap: wrap; }
#mistake-text { color: var(--bad); font-size: .9em; }
.keys { color: var(--thin); font-size: .7em; }
input[type=range] { flex: 1; min-width: 12em; }
.link { stroke: var(--ink); fill: rgba(0,0,0,.03); stroke-linejoin: round; }
.link.hi, .slider.hi { stroke: var(--hi); }
.slider { fill: #fff; stroke: var(--ink); }
.guide { stroke: var(--thin); stroke-dasharray: 3 2; }
.ground { fill: none; stroke: var(--ink); }
.joint { fill: #fff; stroke: var(--ink); }
.joint.hi, .pt.hi { fill: var(--hi); stroke: var(--hi); }
.pt { fill: var(--ink); }
.label { fill: var(--ink); font-family: "DejaVu Sans", Arial, sans-serif; }
.label.hi { fill: var(--hi); font-weight: bold; }
.label.bad { fill: var(--bad); }
.seglabel { fill: #555; font-style: italic; }
.cline { stroke: var(--thin); stroke-dasharray: 2 1.5; }
.cline.hi { stroke: var(--hi); }
.arm { stroke: var(--hi); stroke-dasharray: 1.5 1; }
.armfoot { fill: var(--hi); }
.armlabel { fill: var(--hi); font-style: italic; }
.fline { stroke: var(--thin); stroke-dasharray: 4 1.5 1 1.5; }
.seg { stroke: var(--ink); }
.lever { fill: rgba(0,0,0,.04); stroke: var(--thin); stroke-linejoin: round; }
.seg.rel, .seg.nrm, .seg.tan, .seg.cor, .seg.sld { stroke: #2c3e50; stroke-dasharray: 4 1.5; }
.seg.cor { stroke: #8e44ad; }
.seg.cls { stroke: #16a085; }
.seg.hi { stroke: var(--hi); stroke-dasharray: none; }
.seg.bad, .wrong { stroke: var(--bad); }
.wrongpt { fill: none; stroke: var(--bad); }
.arrow { fill: var(--ink); } .arrow.hi { fill: var(--hi); } .arrow.bad { fill: var(--bad); }
.axis { stroke: var(--thin); } .curve { stroke: #2c3e50; } .cursor { stroke: var(--hi); }
@media (max-width: 900px) { .stage, .cycle .stage, .cycle .stage.two { grid-template-columns: 1fr; } }
@media print {
  header nav, .controls, #tabs, #mistakes, .keys, #cycle-view { display: none !important; }
  body { background: #fff; font-size: 11pt; }
  svg { max-height: none; }
}
"""

_BODY = """<header><h1>{title}</h1><nav><button id="mode-steps" class="on">{steps}</button>
<button id="mode-cycle">{cycle}</button></nav></header>
<main>
<section id="steps-view">
<div class="stage"><figure><figcaption>{scheme}, φ = {phi}°</figcaption><svg id="scheme" role="img"></svg></figure>
<figure><figcaption id="panel-title"></figcaption><svg id="panel" role="img"></svg></figure></div>
<div class="controls"><button id="back">{back}</button><span id="counter"></span><button id="next">{next}</button></div>
<div id="tabs"></div>
<p id="step-text"></p>
<fieldset id="mistakes"><legend>{mistakes_title}</legend></fieldset>
<p id="mistake-text"></p>
<p class="keys">{keys}</p>
</section>
<section id="cycle-view" class="cycle" hidden>
<div class="stage"><figure><figcaption>{scheme}</figcaption><svg id="cyc-scheme" role="img"></svg></figure>
<figure><figcaption>{velocity_plan}</figcaption><svg id="cyc-vel" role="img"></svg></figure>
<figure><figcaption>{acceleration_plan}</figcaption><svg id="cyc-acc" role="img"></svg></figure></div>
<div class="controls"><button id="play">{play}</button><input id="phi" type="range" min="0" step="0.01" value="0">
<output id="phi-out"></output></div>
<div id="cyc-forces" class="forces" aria-label="{forces}"></div>
<div id="cyc-charts" class="charts"></div>
</section>
</main>"""


def _script_json(data: Any) -> str:
    """JSON safe inside <script>: no '</script>' or '<!--' can close or confuse the element."""
    text = json.dumps(data, ensure_ascii=False, separators=(",", ":"), allow_nan=False)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def _language(scene: Scene, language: str | None) -> str:
    if language is not None:
        if language not in WORDS:
            raise InputError(Said("dd_one_language", v=', '.join(WORDS), language=language), field="--language")
        return language
    return scene.sheet.language  # the scene's [sheet], else the locale's; validated with it


#: The page's type for each of the sheets' fonts (``[sheet] font``, ``--font``): the GOST one
#: first where it asks for it, the browser taking DejaVu Sans for a letter osifont lacks (ё, э).
FAMILIES = {"dejavu": '"DejaVu Sans", Arial, sans-serif', "gost": 'osifont, "DejaVu Sans", Arial, sans-serif'}


def page(scene: Scene | str | Path, *, language: str | None = None, frames: int = FRAMES,
         phi_deg: float | None = None, font: str | None = None) -> str:
    """The whole page as text (its type ``font``, None: the scene's ``[sheet] font``)."""
    sc = scene if isinstance(scene, Scene) else load_scene(scene)
    lang = _language(sc, language)
    family = FAMILIES[sc.sheet_for(language=lang, font=font).font]
    data = lesson(sc, phi_deg=phi_deg, frames=frames, language=lang)
    words = WORDS[lang]
    esc = {k: html.escape(v) for k, v in words.items() if isinstance(v, str)}
    phi = f"{data['phi_deg']:g}".replace(".", str(words["decimal"]))
    body = _BODY.format(title=html.escape(data["title"]), phi=phi, **esc)
    script = resources.files("drawings").joinpath("demo_page.js").read_text(encoding="utf-8")
    return (f'<!DOCTYPE html>\n<html lang="{lang}"><head><meta charset="utf-8">'
            f'<meta name="viewport" content="width=device-width, initial-scale=1">'
            f'<meta http-equiv="Content-Security-Policy" content="default-src \'none\'; '
            f'style-src \'unsafe-inline\'; script-src \'unsafe-inline\'; img-src data:">'
            f"<title>{html.escape(data['title'])}</title><style>{_CSS.replace(FAMILIES['dejavu'], family)}</style>"
            f"</head>\n<body>\n{body}\n"
            f'<script id="lesson" type="application/json">{_script_json(data)}</script>\n'
            f'<script id="words" type="application/json">{_script_json(words)}</script>\n'
            f"<script>{script}</script>\n</body></html>\n")


class Demo:
    """A demonstration page for Jupyter: ``Demo("samples/v_engine.toml")`` in a cell shows it."""

    def __init__(self, scene: Scene | str | Path, *, language: str | None = None, frames: int = FRAMES,
                 phi_deg: float | None = None, height: int = 720) -> None:
        self.html = page(scene, language=language, frames=frames, phi_deg=phi_deg)
        self.height = height

    def _repr_html_(self) -> str:
        return (f'<iframe srcdoc="{html.escape(self.html, quote=True)}" style="width:100%;height:{self.height}px;'
                f'border:0" sandbox="allow-scripts"></iframe>')

    def save(self, path: str | Path) -> Path:
        atomic_write(path, self.html)
        return Path(path)


def page_figures(scene: str | Path, frames: int = FRAMES, repeat: int = 3) -> dict[str, Any]:
    """The page's size and build time, and (when Chromium and Playwright are there) the time
    from opening it in headless Chromium to the first step drawn: for ``plans bench``."""
    import tempfile
    import time

    from drawings.headless import chromium

    best, text = float("inf"), ""
    for _ in range(repeat):
        t0 = time.perf_counter()
        text = page(scene, frames=frames)
        best = min(best, time.perf_counter() - t0)
    out: dict[str, Any] = {"scene": str(scene), "frames": frames, "bytes": len(text.encode("utf-8")),
                           "build_s": best, "first_step_s": None}
    with chromium() as b, tempfile.TemporaryDirectory() as tmp:
        if b is None:
            return out
        f = Path(tmp) / "page.html"
        f.write_text(text, encoding="utf-8")
        times = []
        for _ in range(repeat):
            pg = b.new_page(viewport={"width": 1024, "height": 768})
            pg.goto(f.as_uri())
            pg.wait_for_selector("body[data-ready='1']")
            times.append(float(pg.get_attribute("body", "data-ready-ms") or "nan") / 1000.0)
            pg.close()
    out["first_step_s"] = min(times)
    return out


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("demo", help="a self-contained HTML page: the plans step by step, the cycle, mistakes")
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("-o", "--output", required=True, metavar="PAGE.html", help="the page to write")
    p.add_argument("--language", choices=tuple(WORDS), help="overrides [sheet] language")
    p.add_argument("--frames", type=int, default=FRAMES, help=f"positions per turn in the cycle (default {FRAMES})")
    p.add_argument("--phi", type=float, metavar="DEG", help="the position built step by step (default the first)")
    p.add_argument("--font", choices=tuple(FAMILIES),
                   help="overrides [sheet] font: gost is osifont, a GOST 2.304 type B font (apt-get install fonts-osifont)")
    p.set_defaults(func=_command)


def _command(args: argparse.Namespace) -> int:
    text = page(args.scene, language=args.language, frames=args.frames, phi_deg=args.phi,
                font=getattr(args, "font", None))
    atomic_write(args.output, text)
    print(args.output)
    return 0


__all__ = ["Demo", "WORDS", "page", "page_figures", "register"]


if __name__ == "__main__":  # ``python -m drawings.demo SCENE``: the page's figures as JSON (for the bench)
    import sys

    print(json.dumps(page_figures(sys.argv[1] if len(sys.argv) > 1 else "samples/v_engine.toml")))
