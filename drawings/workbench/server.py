"""The workbench's server: the page and a small JSON API over one project folder.

``POST /api/solve`` (a scene's TOML) answers the JSON of ``plans solve --json``, or 422 with
``{"error": the engine's one-line message, "field": the key it names}``; ``GET /api/files``
lists the folder's files by kind; ``GET``/``PUT /api/file?path=`` read and write one;
``POST /api/check`` answers the JSON of ``plans check --json``; ``POST /api/draw?format=``
answers the sheets (one file, or a zip of several); ``POST /api/demo`` the demonstration
page (``plans demo``); ``POST /api/forces`` the force polygons and the lever over the turn;
``GET /api/template?path=`` a blank check file for a scene; ``POST /api/design`` a synthesis
file designed (the scene and ``plans design --json``); ``POST /api/note`` the explanatory
note (``plans note``, DOCX); ``POST /api/edit`` sets values in a TOML text and adds or removes
its tables keeping its comments and order (the form's edits, :mod:`.edits`), with
``?solve=1`` the edited scene solved in the same answer; ``GET /api/samples`` is the
gallery. The page asks for what it draws (``view=page``) and for the position on its slider
first (``at=K``); solutions are kept per text (:mod:`.solving`).

Safe as a local server: only the Host names it listens as are answered (DNS rebinding), a
request from another site's page is refused (Origin, Sec-Fetch-Site), no path leaves the
folder (resolved, symlinks followed), bodies and files are bounded, and every failure is a
4xx with one line of text, never a traceback.
"""

from __future__ import annotations

import json
import time
import tomllib
from importlib import resources
from pathlib import Path
from typing import Any

from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.requests import Request
from starlette.responses import JSONResponse, Response
from starlette.routing import Route

from plans.errors import ConstructionError, InputError, PlansError, Said, one_line

from .outputs import demo_page, design_json, draw_file, jsonable, note_file

#: Largest request body and largest file read or written (a scene is a few kilobytes).
MAX_BODY = 1 << 20
#: At most this many files listed (a folder of a whole group's checks stays well below).
MAX_FILES = 2000
#: The gallery: the course's mechanisms as the samples show them.
GALLERY = ("slider_crank", "offset_slider_crank", "v_engine", "four_bar", "shaper", "six_bar",
           "scotch_yoke", "synthesis/offset_slider_crank", "synthesis/crank_rocker", "synthesis/shaper",
           "synthesis/seed000_v_engine")
#: A mechanism to build from nothing (the gallery's first card).
EMPTY = """# A new mechanism: its fixed pivots, links, joints and driver added in the form.
format = 1
title = { ru = "Новый механизм", en = "New mechanism" }
unit = "mm"
frame = 4                    # the frame's link number (the textbook numbers it last)
outputs = ["positions", "velocity_plan", "acceleration_plan"]
"""
#: The page's own files: its style and its script's modules (ES modules, no build step).
_STATIC = {"app.css": "text/css; charset=utf-8", **{f"{m}.js": "text/javascript; charset=utf-8" for m in (
    "main", "words", "dom", "gallery", "form", "structure", "solve", "check", "draw", "views", "files")}}
_CSP = ("default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' data:; "
        "connect-src 'self'; base-uri 'none'; form-action 'none'; frame-ancestors 'none'")


class Refused(Exception):
    """A request answered with a 4xx and one line."""

    def __init__(self, status: int, message: str | Said, field: str | None = None) -> None:
        super().__init__(str(message))
        self.status, self.message, self.field = status, message, field


def _error(status: int, message: str | Said, field: str | None = None, **extra: Any) -> JSONResponse:
    """One line (and, for a sentence of the catalogue, the line in each language the page
    may speak)."""
    if isinstance(message, Said):
        extra["errors"] = {lang: message.text(lang) for lang in ("ru", "en")}
    return JSONResponse({"error": str(message), "field": field, **extra}, status_code=status)


def _engine_fields(exc: PlansError) -> dict[str, Any]:
    out: dict[str, Any] = {"error": one_line(exc), "field": getattr(exc, "field", None),
                           "errors": {lang: one_line(exc, lang) for lang in ("ru", "en")}}  # the page's language
    if isinstance(exc, ConstructionError):
        out.update(group=exc.group, point=exc.point, phi_deg=exc.phi_deg)
    return out


def engine_error(exc: PlansError) -> JSONResponse:
    """The engine's one-line error and the key it names (a construction names its group,
    point and angle instead)."""
    return JSONResponse(_engine_fields(exc), status_code=422)


class Guard:
    """ASGI middleware: Host and Origin checked before anything else runs."""

    def __init__(self, app: Any, hosts: set[str]) -> None:
        self.app, self.hosts = app, hosts

    async def __call__(self, scope: dict, receive: Any, send: Any) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        headers = {k.decode("latin-1").lower(): v.decode("latin-1") for k, v in scope["headers"]}
        host = headers.get("host", "")
        origin = headers.get("origin")
        why: Said | None = None
        if host.lower() not in self.hosts:
            why = Said("wr_host", host=host, hosts=", ".join(sorted(self.hosts)))
        elif origin is not None and origin.lower() not in {f"http://{h}" for h in self.hosts}:
            why = Said("wr_origin", origin=origin)
        elif headers.get("sec-fetch-site") == "cross-site":
            why = Said("wr_cross_site")
        if why is not None:
            await _error(403, why)(scope, receive, send)
            return
        await self.app(scope, receive, send)


class Workbench:
    """The routes over one folder."""

    def __init__(self, root: str | Path) -> None:
        self.root = Path(root).resolve()

    # ----------------------------------------------------------------- helpers
    def path(self, rel: str | None, *, must_exist: bool = True) -> Path:
        """The file ``rel`` names inside the folder; anything leading outside is refused."""
        if not rel:
            raise Refused(400, Said("wr_missing_path_file"), "path")
        if "\x00" in rel or len(rel) > 1000:
            raise Refused(400, Said("wr_path_file_name"), "path")
        target = (self.root / rel).resolve()
        if not target.is_relative_to(self.root):
            raise Refused(403, Said("wr_refused_rel_outside", rel=rel), "path")
        if target.suffix.lower() != ".toml":
            raise Refused(400, Said("wr_rel_toml_file", rel=rel), "path")
        if must_exist and not target.is_file():
            raise Refused(404, Said("wr_rel_such_file", rel=rel), "path")
        return target

    def rel(self, p: Path) -> str:
        return p.relative_to(self.root).as_posix()

    async def body(self, request: Request) -> bytes:
        size = request.headers.get("content-length")
        if size is not None and (not size.isdigit() or int(size) > MAX_BODY):
            raise Refused(413, Said("wr_request_larger_than", MAX_BODY=MAX_BODY))
        chunks, total = [], 0
        async for chunk in request.stream():
            total += len(chunk)
            if total > MAX_BODY:
                raise Refused(413, Said("wr_request_larger_than", MAX_BODY=MAX_BODY))
            chunks.append(chunk)
        return b"".join(chunks)

    async def text(self, request: Request) -> str:
        try:
            return (await self.body(request)).decode("utf-8")
        except UnicodeDecodeError:
            raise Refused(400, Said("wr_body_utf_text")) from None

    def source_name(self, request: Request) -> str:
        """The name errors give the text: its file when the page says which, else <scene>."""
        rel = request.query_params.get("path")
        if rel:
            try:
                return self.rel(self.path(rel, must_exist=False))
            except Refused:
                return "<scene>"
        return "<scene>"

    # ----------------------------------------------------------------- routes
    async def index(self, request: Request) -> Response:
        text = resources.files(__package__).joinpath("static/index.html").read_text(encoding="utf-8")
        return Response(text, media_type="text/html; charset=utf-8", headers={"Content-Security-Policy": _CSP})

    async def static(self, request: Request) -> Response:
        name = request.path_params["name"]
        if name not in _STATIC:
            raise Refused(404, Said("wr_name_such_file", name=name))
        data = resources.files(__package__).joinpath("static", name).read_bytes()
        return Response(data, media_type=_STATIC[name], headers={"Cache-Control": "no-cache"})

    async def files(self, request: Request) -> Response:
        return JSONResponse(await run_in_threadpool(self._files))

    def _files(self) -> dict[str, Any]:
        out: dict[str, list[dict[str, Any]]] = {}
        for n, p in enumerate(sorted(self.root.rglob("*.toml"))):
            if n >= MAX_FILES:
                break
            try:
                if not p.resolve().is_relative_to(self.root) or p.stat().st_size > MAX_BODY:
                    continue
                data = tomllib.loads(p.read_text(encoding="utf-8"))
            except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError):
                continue
            kind = _kind(data)
            out.setdefault(kind, []).append({"path": self.rel(p), "title": _title(data, p.stem),
                                             "titles": _titles(data)})
        return {"folder": self.root.name, "files": out}

    async def samples(self, request: Request) -> Response:
        return JSONResponse(await run_in_threadpool(_samples))

    async def read(self, request: Request) -> Response:
        p = self.path(request.query_params.get("path"))
        if p.stat().st_size > MAX_BODY:
            raise Refused(413, Said("wr_larger_than_max", v=self.rel(p), MAX_BODY=MAX_BODY))
        try:
            text = p.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            raise Refused(422, Said("wr_utf_text", v=self.rel(p))) from None
        return JSONResponse({"path": self.rel(p), **_parsed(text, self.rel(p))})

    async def write(self, request: Request) -> Response:
        p = self.path(request.query_params.get("path"), must_exist=False)
        text = await self.text(request)
        try:
            tomllib.loads(text)
        except tomllib.TOMLDecodeError as exc:
            raise Refused(422, Said("wr_toml_exc_nothing", v=self.rel(p), exc=exc)) from None
        if not p.parent.is_dir():
            raise Refused(404, Said("wr_such_folder_project", v=self.rel(p.parent)), "path")
        from plans.io import atomic_write

        await run_in_threadpool(atomic_write, p, text.encode("utf-8"))
        return JSONResponse({"path": self.rel(p), "bytes": len(text.encode("utf-8"))})

    async def edit(self, request: Request) -> Response:
        try:
            req = json.loads(await self.body(request))
            text, sets = req["text"], req.get("set", [])
            ops = {k: req[k] for k in ("put", "append", "delete") if k in req}
            if not isinstance(text, str) or not isinstance(sets, list):
                raise TypeError
        except (ValueError, KeyError, TypeError, AttributeError):
            raise Refused(400, Said("wr_text_toml_text")) from None
        t0 = time.perf_counter()
        if request.query_params.get("solve") == "1":  # the edit and its solve in one answer
            steps = request.query_params.get("steps", "1") != "0"
            data, cpu = await run_in_threadpool(_cpu, _edit_solve, text, sets, ops, self.source_name(request), steps,
                                                _view(request), _at(request))
            return Response(data, media_type="application/json", headers=_timing(t0, cpu))
        return JSONResponse(await run_in_threadpool(_edit, text, sets, ops), headers=_timing(t0))

    async def solve(self, request: Request) -> Response:
        text, name = await self.text(request), self.source_name(request)
        steps = request.query_params.get("steps", "1") != "0"
        t0 = time.perf_counter()
        data, cpu = await run_in_threadpool(_cpu, _solve, text, name, steps, _view(request), _at(request))
        return Response(data, media_type="application/json", headers=_timing(t0, cpu))

    async def check(self, request: Request) -> Response:
        text = await self.text(request)
        rel = request.query_params.get("path")
        where = self.path(rel, must_exist=False) if rel else self.root / "check.toml"
        lang, names = _language(request), request.query_params.get("names") == "1"
        return Response(await run_in_threadpool(self._check, text, where, lang, names), media_type="application/json")

    def _check(self, text: str, where: Path, lang: str = "en", names: bool = False) -> bytes:
        """The report of ``plans check --json`` in the page's language; with ``names``, the
        textbook's name of each quantity in it too (ω1 for omega_1 on a Russian page)."""
        from plans.check.checkfile import check_from_dict
        from plans.check.report import check
        from plans.io import loads_toml

        name = self.rel(where)
        data = loads_toml(text, name)
        scene = data.get("scene")
        if isinstance(scene, str):  # the scene it names must be a file of the folder too
            target = (where.parent / scene).resolve()
            if not target.is_relative_to(self.root):
                raise Refused(403, Said("wr_refused_scene_scene", scene=scene), "scene")
        report = check(check_from_dict(data, str(where)))
        from plans.language import quantity_name

        out = report.to_json(lang)
        if names:
            out["names"] = {it["quantity"]: quantity_name(it["quantity"], lang) for it in out.get("items", [])}
        return json.dumps(out, ensure_ascii=False, allow_nan=False).encode("utf-8")

    async def template(self, request: Request) -> Response:
        """A blank check file for a scene of the folder (``plans check --template``), to sit
        beside it: ``{"path": suggested name, "text"}``."""
        scene = self.path(request.query_params.get("path"))
        return JSONResponse(await run_in_threadpool(self._template, scene))

    def _template(self, scene: Path) -> dict[str, Any]:
        from plans.check.forms import template_toml
        from plans.kinematics.placing import load_scene

        text = template_toml(load_scene(scene), scene.name)
        name = scene.with_name(f"{scene.stem}_check.toml")
        n = 2
        while name.exists():
            name = scene.with_name(f"{scene.stem}_check{n}.toml")
            n += 1
        return {"path": self.rel(name), **_parsed(text, self.rel(name))}

    async def design(self, request: Request) -> Response:
        text, name = await self.text(request), self.source_name(request)
        return Response(await run_in_threadpool(design_json, text, name), media_type="application/json")

    async def forces(self, request: Request) -> Response:
        text, name = await self.text(request), self.source_name(request)
        return Response(await run_in_threadpool(_forces, text, name), media_type="application/json")

    async def demo(self, request: Request) -> Response:
        text = await self.text(request)
        name = self.source_name(request)
        stem = Path(name).stem.strip("<>") or "scene"
        lang = request.query_params.get("language") and _language(request)
        page = await run_in_threadpool(demo_page, text, name, lang)
        return Response(page, media_type="text/html; charset=utf-8",
                        headers={"Content-Disposition": f'attachment; filename="{stem}.html"'})

    async def note(self, request: Request) -> Response:
        """The explanatory note of the file (``plans note``), as DOCX."""
        lang = request.query_params.get("language") and _language(request)  # none: the file's, else the locale's
        text = await self.text(request)
        stem = Path(self.source_name(request)).stem.strip("<>") or "scene"
        data = await run_in_threadpool(note_file, text, stem, lang)
        return Response(data, media_type=_MEDIA["docx"],
                        headers={"Content-Disposition": f'attachment; filename="{stem}.docx"'})

    async def draw(self, request: Request) -> Response:
        fmt = request.query_params.get("format", "svg").lower()
        from drawings.paper.export import FORMATS

        if fmt not in FORMATS:
            raise Refused(400, Said("wr_format_fmt_one", fmt=fmt, v=', '.join(FORMATS)), "format")
        text = await self.text(request)
        stem = Path(self.source_name(request)).stem.strip("<>") or "scene"
        data, name = await run_in_threadpool(draw_file, text, stem, fmt)
        return Response(data, media_type=_MEDIA.get(name.rsplit(".", 1)[-1], "application/octet-stream"),
                        headers={"Content-Disposition": f'attachment; filename="{name}"'})


_MEDIA = {"svg": "image/svg+xml", "pdf": "application/pdf", "png": "image/png", "zip": "application/zip",
          "dxf": "image/vnd.dxf", "docx": "application/vnd.openxmlformats-officedocument.wordprocessingml.document"}


def _kind(data: dict[str, Any]) -> str:
    kind = data.get("kind")
    if isinstance(kind, str):
        return kind
    if "student" in data or ("scene" in data and "links" not in data):
        return "check"
    return "linkage"


def _title(data: dict[str, Any], default: str) -> str:
    t = data.get("title")
    if isinstance(t, dict):
        t = t.get("ru") or t.get("en") or next(iter(t.values()), None)
    return t if isinstance(t, str) else default


def _titles(data: dict[str, Any]) -> dict[str, str] | None:
    t = data.get("title")
    return {str(k): v for k, v in t.items() if isinstance(v, str)} if isinstance(t, dict) else None


def _parsed(text: str, name: str) -> dict[str, Any]:
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        return {"text": text, "data": None, "kind": None, "error": f"{name}: not TOML: {exc}"}
    return {"text": text, "data": jsonable(data), "kind": _kind(data)}


def _samples_dir() -> Path | None:
    here = Path(__file__).resolve().parents[2] / "samples"
    return here if here.is_dir() else None


def _samples() -> list[dict[str, Any]]:
    folder = _samples_dir()
    titles = {"ru": "Новый механизм", "en": "New mechanism"}
    out: list[dict[str, Any]] = [{"name": "new", "title": titles["en"], "titles": titles, "text": EMPTY,
                                  "kind": "linkage"}]
    for name in GALLERY:
        p = folder / f"{name}.toml" if folder else None
        if p is None or not p.is_file():
            continue
        text = p.read_text(encoding="utf-8")
        data = tomllib.loads(text)
        out.append({"name": name.replace("/", "_"), "title": _title(data, name), "titles": _titles(data),
                    "text": text, "kind": _kind(data)})
    return out


def _edit(text: str, sets: list, ops: dict[str, list] | None = None) -> dict[str, Any]:
    """Set each ``[key path, value]`` in the TOML text with tomlkit (and the structure's
    operations ``ops``, :mod:`.edits`): the comments, the order and the layout of everything
    else stay as they were."""
    return _parsed(_edited(text, sets, ops), "<scene>")


def _edited(text: str, sets: list, ops: dict[str, list] | None = None) -> str:
    from .edits import EditError, edit

    try:
        return edit(text, {**(ops or {}), "set": sets})
    except EditError as exc:
        raise Refused(exc.status, exc.message, exc.field) from None


def _edit_solve(text: str, sets: list, ops: dict[str, list], name: str, steps: bool, view: str = "full",
                at: int | None = None) -> bytes:
    """An edit and the scene it leaves solved, in one answer: ``{"text", "data", "kind",
    "solution"}``, or ``"solve_error"`` (the 422 body of ``/api/solve``) in place of the
    solution when the edited scene cannot be solved; the text is parsed once for both."""
    from plans.io import loads_toml

    from .solving import solve_json

    new = _edited(text, sets, ops)
    try:
        data = loads_toml(new, name)
    except PlansError:
        return _dumps(_parsed(new, name))  # the text as it is, its error said
    kind = _kind(data)
    out = _dumps({"text": new, "data": jsonable(data), "kind": kind})
    if kind != "linkage":
        return out
    try:
        sol = solve_json(new, name, steps, data, view, at)
    except PlansError as exc:
        return out[:-1] + b',"solve_error":' + _dumps(_engine_fields(exc)) + b"}"
    return out[:-1] + b',"solution":' + sol + b"}"


def _dumps(x: Any) -> bytes:
    return json.dumps(x, ensure_ascii=False, allow_nan=False, separators=(",", ":")).encode("utf-8")


def _cpu(fn: Any, *args: Any) -> tuple[Any, float]:
    """``fn(*args)`` and the processor time it took in its thread (s): on a busy computer the
    time that passed is longer, the work the same."""
    c0 = time.thread_time()
    return fn(*args), time.thread_time() - c0


def _timing(t0: float, cpu: float | None = None) -> dict[str, str]:
    """The server's share of the answer (the browser's devtools and the bench read it), and
    the processor time of its work."""
    out = f"app;dur={(time.perf_counter() - t0) * 1000:.2f}"
    if cpu is not None:
        out += f", cpu;dur={cpu * 1000:.2f}"
    return {"Server-Timing": out}


def _solve(text: str, name: str, steps: bool = True, view: str = "full", at: int | None = None) -> bytes:
    from .solving import solve_json

    return solve_json(text, name, steps, view=view, at=at)


def _at(request: Request) -> int | None:
    at = request.query_params.get("at")
    if at is None:
        return None
    if not at.isdigit() or len(at) > 6:
        raise Refused(400, Said("wr_position_number", at=at), "at")
    return int(at)


def _view(request: Request) -> str:
    view = request.query_params.get("view", "full")
    if view not in ("full", "page"):
        raise Refused(400, Said("wr_view_view_full", view=view), "view")
    return view


def _forces(text: str, name: str) -> bytes:
    """The force polygons of every group and the crank, and the lever, at every position of
    the scene (the demonstration page's drawings: one scale over the turn), or [] when the
    scene asks for no force analysis."""
    from .solving import forces_json

    return forces_json(text, name)


def _handler(fn: Any) -> Any:
    """Every failure as a 4xx with one line: never a traceback."""

    async def run(request: Request) -> Response:
        try:
            return await fn(request)
        except Refused as exc:
            return _error(exc.status, exc.message, exc.field)
        except PlansError as exc:
            return engine_error(exc)
        except RecursionError:
            return _error(422, Said("wr_file_nested_too"))
        except OSError as exc:
            return _error(500, Said("wr_cannot_read_write", v=exc.strerror or exc))
        except Exception as exc:  # noqa: BLE001 - the page shows one line, never a traceback
            return _error(500, Said("wr_internal_error_name", name=type(exc).__name__, v=' '.join(str(exc).split())[:300]))

    return run


def _language(request: Request, default: str = "en") -> str:
    """The page's language a request names (``?language=ru``); a refusal for another."""
    lang = request.query_params.get("language", default)
    if lang not in ("ru", "en"):
        raise Refused(400, Said("wr_language_lang_ru", lang=lang), "language")
    return lang


def hosts_for(host: str, port: int) -> set[str]:
    """The Host headers a browser sends for this server: its own names and addresses, never
    another domain's (a name that resolves here only by DNS rebinding)."""
    names = {"127.0.0.1", "localhost", "[::1]"} if host in ("127.0.0.1", "localhost", "::1", "0.0.0.0", "::") \
        else set()
    if host in ("0.0.0.0", "::"):  # every address of this computer, and its name
        import socket

        me = socket.gethostname()
        names |= {me, socket.getfqdn()}
        try:
            names |= {str(i[4][0]) for i in socket.getaddrinfo(me, None)}
        except OSError:
            pass
    else:
        names.add(host)
    return {f"[{n}]:{port}".lower() if ":" in n and not n.startswith("[") else f"{n}:{port}".lower() for n in names}


def make_app(root: str | Path, hosts: set[str]) -> Any:
    wb = Workbench(root)
    routes = [
        Route("/", _handler(wb.index), methods=["GET"]),
        Route("/static/{name}", _handler(wb.static), methods=["GET"]),
        Route("/favicon.ico", lambda request: Response(status_code=204), methods=["GET"]),  # none: no 404 logged
        Route("/api/files", _handler(wb.files), methods=["GET"]),
        Route("/api/samples", _handler(wb.samples), methods=["GET"]),
        Route("/api/file", _handler(wb.read), methods=["GET"]),
        Route("/api/file", _handler(wb.write), methods=["PUT"]),
        Route("/api/edit", _handler(wb.edit), methods=["POST"]),
        Route("/api/solve", _handler(wb.solve), methods=["POST"]),
        Route("/api/check", _handler(wb.check), methods=["POST"]),
        Route("/api/draw", _handler(wb.draw), methods=["POST"]),
        Route("/api/note", _handler(wb.note), methods=["POST"]),
        Route("/api/demo", _handler(wb.demo), methods=["POST"]),
        Route("/api/forces", _handler(wb.forces), methods=["POST"]),
        Route("/api/design", _handler(wb.design), methods=["POST"]),
        Route("/api/template", _handler(wb.template), methods=["GET"]),
    ]
    app = Starlette(routes=routes)
    return Guard(app, hosts)


def bind(host: str, port: int) -> Any:
    import socket

    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    sock = socket.socket(family, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    # every answer at once: an answer's head and body are two writes, and with Nagle's
    # algorithm the body waits for the browser's delayed acknowledgement of the head (40 ms
    # on Linux, twice the server's whole share of an edit); accepted sockets inherit it
    sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    try:
        sock.bind((host, port))
    except OSError as exc:
        sock.close()
        raise InputError(Said("ws_cannot_listen_host", host=host, port=port, strerror=exc.strerror), field="--port") from None
    sock.listen(128)  # a browser's first request waits in the queue while the server starts
    return sock


def serve(root: str | Path, *, host: str = "127.0.0.1", port: int = 8765, open_browser: bool = False) -> None:
    import uvicorn

    sock = bind(host, port)
    port = sock.getsockname()[1]
    app = make_app(root, hosts_for(host, port))
    shown = "127.0.0.1" if host in ("0.0.0.0", "::") else host
    url = f"http://{'[' + shown + ']' if ':' in shown else shown}:{port}/"
    from plans.errors import run_language
    from plans.phrases import say

    print(say("sv_serving", run_language(), root=Path(root).resolve(), url=url), flush=True)
    if open_browser:
        import webbrowser

        webbrowser.open(url)
    server = uvicorn.Server(uvicorn.Config(app, log_level="warning", access_log=False,
                                           limit_concurrency=64, timeout_keep_alive=5))
    server.run(sockets=[sock])
