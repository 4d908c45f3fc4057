"""The workbench (``plans serve``): its JSON API and its safety over plain HTTP, and the page
driven in real headless Chromium (Debian's ``chromium`` through Playwright) against a server
running in this process on a free loopback port."""

from __future__ import annotations

import cmath
import json
import math
import shutil
import threading
import time
import urllib.error
import urllib.request
from pathlib import Path

import pytest

pytest.importorskip("starlette")
pytest.importorskip("uvicorn")

from drawings.workbench.server import MAX_BODY, bind, hosts_for, make_app  # noqa: E402
from plans.errors import PlansError, one_line  # noqa: E402
from plans.kinematics.placing import parse_scene  # noqa: E402
from plans.results import solve_scene, to_json  # noqa: E402

SAMPLES = Path(__file__).resolve().parents[1] / "samples"


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    """A workbench over a fresh folder (a four-bar in it), on a free loopback port."""
    import uvicorn

    root = tmp_path_factory.mktemp("project")
    shutil.copy(SAMPLES / "slider_crank.toml", root / "slider_crank.toml")
    (root / "outside.toml").write_text("format = 1\n", encoding="utf-8")
    sock = bind("127.0.0.1", 0)
    port = sock.getsockname()[1]
    srv = uvicorn.Server(uvicorn.Config(make_app(root / "", hosts_for("127.0.0.1", port)), log_level="error"))
    (root / "sub").mkdir()
    th = threading.Thread(target=srv.run, kwargs={"sockets": [sock]}, daemon=True)
    th.start()
    t0 = time.monotonic()
    while not srv.started and time.monotonic() - t0 < 10:
        time.sleep(0.02)
    yield root, f"http://127.0.0.1:{port}"
    srv.should_exit = True
    th.join(5)


def _req(url: str, method: str = "GET", body: bytes | None = None, headers: dict | None = None):
    rq = urllib.request.Request(url, data=body, method=method, headers=headers or {})
    try:
        with urllib.request.urlopen(rq, timeout=120) as r:
            return r.status, r.headers.get("Content-Type", ""), r.read()
    except urllib.error.HTTPError as e:
        return e.code, e.headers.get("Content-Type", ""), e.read()


def _engine_error(text: str, name: str = "<scene>") -> str:
    try:
        solve_scene(parse_scene(text, name))
    except PlansError as exc:
        return one_line(exc)
    raise AssertionError("the scene solved")


# ------------------------------------------------------------------ the API over HTTP
def test_solve_answers_the_json_of_plans_solve(server):
    _, url = server
    text = (SAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    status, ctype, body = _req(url + "/api/solve", "POST", text.encode())
    assert status == 200 and ctype.startswith("application/json")
    full = json.loads(json.dumps(to_json(solve_scene(parse_scene(text)))))
    assert json.loads(body) == full
    status, _, body = _req(url + "/api/solve?steps=0", "POST", text.encode())  # the page's: no protocol text
    for pos in full["positions"]:
        del pos["steps"]
    assert status == 200 and json.loads(body) == full


def test_solve_errors_are_the_engines_line_and_the_field_it_names(server):
    _, url = server
    text = (SAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    bad = text.replace("length = 80\n", "length = -4\n", 1)
    status, _, body = _req(url + "/api/solve", "POST", bad.encode())
    assert status == 422
    got = json.loads(body)
    assert {k: got[k] for k in ("error", "field")} == {"error": _engine_error(bad), "field": "links.1.length"}
    assert got["errors"]["en"] == got["error"] and got["errors"]["ru"].endswith("ожидалась положительная длина, а записано -4")
    far = text.replace("length = 80\n", "length = 400\n", 1)
    status, _, body = _req(url + "/api/solve", "POST", far.encode())
    got = json.loads(body)
    assert status == 422 and got["error"] == _engine_error(far) and "group" in got["error"]
    status, _, body = _req(url + "/api/solve", "POST", b"format = 1\n[points\n")
    assert status == 422 and "Traceback" not in body.decode() and json.loads(body)["error"]


def test_foreign_host_and_origin_are_refused(server):
    _, url = server
    port = url.rsplit(":", 1)[1]
    text = (SAMPLES / "four_bar.toml").read_bytes()
    assert _req(url + "/api/files", headers={"Host": f"evil.example:{port}"})[0] == 403  # DNS rebinding
    assert _req(url + "/api/solve", "POST", text, {"Origin": "http://evil.example"})[0] == 403
    assert _req(url + "/api/files", headers={"Sec-Fetch-Site": "cross-site"})[0] == 403
    assert _req(url + "/api/files", headers={"Origin": url})[0] == 200
    assert _req(url + "/api/files")[0] == 200


def test_no_path_outside_the_folder_is_read_or_written(server, tmp_path):
    root, url = server
    secret = tmp_path / "secret.toml"
    secret.write_text("format = 1\n", encoding="utf-8")
    link = root / "sub" / "link.toml"
    if not link.exists():
        link.symlink_to(secret)
    for path in ("../secret.toml", str(secret), "sub/../../secret.toml", "sub/link.toml", "%2e%2e/secret.toml"):
        q = urllib.request.quote(path)
        assert _req(f"{url}/api/file?path={q}")[0] in (403, 404), path
        assert _req(f"{url}/api/file?path={q}", "PUT", b"format = 1\n")[0] in (403, 404), path
    assert secret.read_text(encoding="utf-8") == "format = 1\n"
    assert _req(f"{url}/api/file?path=slider_crank.py")[0] == 400
    status, _, body = _req(f"{url}/api/files")
    assert "link.toml" not in body.decode()


def test_bad_requests_are_4xx_with_one_line(server):
    root, url = server
    import http.client

    conn = http.client.HTTPConnection(url.split("//")[1], timeout=10)  # a body announced too large
    conn.putrequest("POST", "/api/solve")
    conn.putheader("Content-Length", str(MAX_BODY + 1))
    conn.endheaders()
    r = conn.getresponse()
    assert r.status == 413 and "larger than" in json.loads(r.read())["error"]
    conn.close()
    assert _req(url + "/api/edit", "POST", b"{not json")[0] == 400
    assert _req(url + "/api/draw?format=tiff", "POST", b"format = 1\n")[0] == 400
    assert _req(url + "/api/file")[0] == 400
    status, _, body = _req(url + "/api/file?path=slider_crank.toml", "PUT", b"[points\n")
    assert status == 422 and "nothing written" in json.loads(body)["error"]
    assert (root / "slider_crank.toml").read_bytes() == (SAMPLES / "slider_crank.toml").read_bytes()


def test_draw_passes_the_format_through_to_the_sheets(server):
    from drawings.paper.export import FORMATS

    _, url = server
    if "dxf" not in FORMATS:
        pytest.skip("DXF sheets not in this installation")
    text = (SAMPLES / "slider_crank.toml").read_bytes()
    status, ctype, body = _req(url + "/api/draw?format=dxf&path=slider_crank.toml", "POST", text)
    assert status == 200
    if ctype == "application/zip":
        import io
        import zipfile

        names = zipfile.ZipFile(io.BytesIO(body)).namelist()
        assert names and all(n.endswith(".dxf") for n in names)
    else:
        assert b"SECTION" in body[:2000] and b"EOF" in body[-100:]


def test_two_tabs_solve_at_once(server):
    from concurrent.futures import ThreadPoolExecutor

    _, url = server
    texts = [(SAMPLES / n).read_text(encoding="utf-8") for n in ("four_bar.toml", "shaper.toml")] * 2
    with ThreadPoolExecutor(4) as ex:
        answers = list(ex.map(lambda t: _req(url + "/api/solve?steps=0", "POST", t.encode()), texts))
    assert [a[0] for a in answers] == [200] * 4
    assert [json.loads(a[2])["title"] for a in answers] == [
        json.loads(json.dumps(to_json(solve_scene(parse_scene(t)))))["title"] for t in texts]


def test_edit_keeps_comments_and_order(server):
    _, url = server
    text = (SAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    status, _, body = _req(url + "/api/edit", "POST", json.dumps(
        {"text": text, "set": [[["links", "1", "length"], 100], [["points", "D"], [310, 5]]]}).encode())
    assert status == 200
    new = json.loads(body)["text"]
    assert new == text.replace("length = 80\n", "length = 100\n", 1).replace("D = [300, 0]", "D = [310, 5]")


# ------------------------------------------------------------------ the page in Chromium
def _four_bar_b(phi: float, a: float, b: float = 260.0, c: float = 200.0, d: float = 300.0) -> complex:
    """B of the sample four-bar (O at 0, D at d mm) by two circles, the upper assembly."""
    A = a * cmath.exp(1j * phi)
    D = complex(d, 0)
    s = abs(D - A)
    x = (b * b - c * c + s * s) / (2 * s)
    y = math.sqrt(b * b - x * x)
    u = (D - A) / s
    return A + u * complex(x, y)


def _plan_points(page, svg: str) -> dict[str, tuple[float, float]]:
    return page.eval_on_selector_all(
        f"#{svg} circle[data-name]",
        "cs => Object.fromEntries(cs.map(c => [c.dataset.name, [Number(c.getAttribute('cx')), -Number(c.getAttribute('cy'))]]))")


def _solved(page, before: str | None) -> str:
    page.wait_for_function("b => document.body.dataset.solved && document.body.dataset.solved !== b", arg=before)
    return page.get_attribute("body", "data-solved")


def test_page_builds_edits_saves_and_reloads_a_four_bar(browser, server):
    root, url = server
    pg = browser.new_page(viewport={"width": 1366, "height": 768})
    errors: list[str] = []
    pg.on("pageerror", lambda e: errors.append(str(e)))
    requests: list[str] = []
    pg.on("request", lambda r: requests.append(r.url))
    pg.goto(url + "/")
    pg.wait_for_selector("body[data-ready='gallery']")
    pg.click("[data-sample='four_bar'] button")
    seq = _solved(pg, None)
    field = pg.locator("#f-links\\.1\\.length-0")
    assert field.input_value() == "80"

    # the crank 100 mm long: the plan's points go where the closed-form four-bar puts them
    field.fill("100")
    field.press("Enter")
    seq = _solved(pg, seq)
    omega = 120 * 2 * math.pi / 60
    mu = float(pg.get_attribute("#vel", "data-scale"))
    pts = _plan_points(pg, "vel")
    h = 1e-6
    vb = (_four_bar_b(h, 100) - _four_bar_b(-h, 100)) / (2 * h) * omega / 1000  # m/s at phi = 0
    assert math.hypot(pts["b"][0] - vb.real * mu, pts["b"][1] - vb.imag * mu) < 0.1
    assert math.hypot(pts["a"][0] - 0, pts["a"][1] - omega * 0.1 * mu) < 0.1
    # the scheme at scale: B where the two circles meet
    bx, by = pg.eval_on_selector("#scheme circle[data-point='B']", "c => [Number(c.getAttribute('cx')), -Number(c.getAttribute('cy'))]")
    B = _four_bar_b(0.0, 100)
    assert math.hypot(bx - B.real, by - B.imag) < 0.1

    # an impossible crank: the engine's own line beside the field
    field.fill("400")
    field.press("Enter")
    seq = _solved(pg, seq)
    shown = pg.text_content("#e-links\\.1\\.length")
    four = (SAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    assert shown == _engine_error(four.replace("length = 80\n", "length = 400\n", 1))
    field.fill("100")
    field.press("Enter")
    seq = _solved(pg, seq)
    assert pg.text_content("#e-links\\.1\\.length") == ""

    # drag the rocker's pivot D: the file's D follows, the mechanism is solved again
    d0 = pg.locator("#scheme circle[data-point='D']").bounding_box()
    pg.mouse.move(d0["x"] + d0["width"] / 2, d0["y"] + d0["height"] / 2)
    pg.mouse.down()
    pg.mouse.move(d0["x"] + d0["width"] / 2 + 15, d0["y"] + d0["height"] / 2, steps=3)
    pg.mouse.up()
    pg.wait_for_selector("body[data-drag='done']")
    dx = float(pg.input_value("#f-points\\.D-0"))
    assert 300 < dx < 360
    # the structure box lists the pivot where it was dragged to
    shown_x = pg.input_value("#f-points\\.D-0")
    assert pg.text_content("[data-item='pivot-D'] span").startswith(f"D = [{shown_x}, ")

    # the force polygons of the current position: the coupler's weight m2·g straight down at μF
    pg.click("#show-forces")
    pg.wait_for_selector("#force-panels figure[data-panel='group-2-3'] line")
    mu_f = float(pg.get_attribute("#force-group-2-3", "data-scale"))
    x1, y1, x2, y2 = pg.eval_on_selector(
        "#force-group-2-3 line[data-label='G2']", "l => ['x1', 'y1', 'x2', 'y2'].map(a => Number(l.getAttribute(a)))")
    assert abs(x2 - x1) < 0.01 and abs((y2 - y1) - 2.6 * 9.81 * mu_f) < 0.01  # SVG's y points down
    # the diagrams over the cycle: one node per position of the scene
    pg.click("#show-plans")
    pg.click("#show-cycle")
    pg.wait_for_selector("#cycle-chart path.curve", state="attached")
    assert pg.locator("#cycle-chart circle").count() == 12
    pg.click("#show-plans2")

    # save, reload, the same scene (and the sample's comments kept)
    pg.fill("#save-path", "mine.toml")
    pg.click("#save")
    pg.wait_for_selector("body[data-saved='mine.toml']")
    saved = (root / "mine.toml").read_text(encoding="utf-8")
    assert saved.startswith("# Crank-rocker four-bar") and "length = 100\n" in saved
    pg.reload()
    _solved(pg, None)
    assert pg.input_value("#f-links\\.1\\.length-0") == "100"
    assert float(pg.input_value("#f-points\\.D-0")) == dx
    assert all(r.startswith(url) for r in requests), "the page reached outside its server"
    assert errors == []
    pg.close()


def test_check_answers_plans_check_and_keeps_to_the_folder(server):
    root, url = server
    text = (SAMPLES / "checks" / "v_engine_coursework.toml").read_text(encoding="utf-8")
    status, _, body = _req(url + "/api/check?path=coursework.toml", "POST", text.encode())
    assert status == 403 and json.loads(body)["field"] == "scene"  # ../v_engine.toml is outside
    status, _, body = _req(url + "/api/check?path=sub/coursework.toml", "POST",
                           text.replace('"../v_engine.toml"', '"../../v_engine.toml"').encode())
    assert status == 403
    shutil.copy(SAMPLES / "v_engine.toml", root / "v_engine.toml")
    (root / "checks").mkdir(exist_ok=True)
    (root / "checks" / "coursework.toml").write_text(text, encoding="utf-8")
    status, _, body = _req(url + "/api/check?path=checks/coursework.toml", "POST", text.encode())
    from plans.check.report import check_file

    assert status == 200
    assert json.loads(body) == json.loads(json.dumps(check_file(root / "checks" / "coursework.toml").to_json()))


def test_page_check_mode_marks_a_wrong_row_and_downloads_open(browser, server):
    root, url = server
    (root / "checks").mkdir(exist_ok=True)
    shutil.copy(SAMPLES / "v_engine.toml", root / "v_engine.toml")
    text = (SAMPLES / "checks" / "v_engine_coursework.toml").read_text(encoding="utf-8")
    (root / "checks" / "coursework.toml").write_text(text, encoding="utf-8")
    from plans.check.report import check_file

    exact = check_file(root / "checks" / "coursework.toml")
    item = exact.item("v_S2A", 45.0)
    assert item.verdict == "pass" and item.field == "positions[0].measured.v_S2A"
    pg = browser.new_page(viewport={"width": 1366, "height": 768})
    errors: list[str] = []
    pg.on("pageerror", lambda e: errors.append(str(e)))
    pg.goto(url + "/")
    pg.wait_for_selector("body[data-ready='gallery']")
    pg.click("a[data-path='checks/coursework.toml']")
    seq = _solved(pg, None)
    row = pg.locator("tr[data-field='positions[0].measured.v_S2A']")
    assert row.get_attribute("class") == "pass"
    # ab·AS2/AB measured 19.8 mm: 40 mm is far off the exact segment
    field = pg.locator("#f-positions\\.0\\.measured\\.v_S2A\\.mm-0")
    assert field.input_value() == "19.8"
    field.fill("40")
    field.press("Enter")
    _solved(pg, seq)
    assert row.get_attribute("class") == "fail"
    assert "fail" in pg.locator("#e-positions\\.0\\.measured\\.v_S2A\\.mm").locator("..").get_attribute("class")
    with pg.expect_download() as dl:
        pg.click("#dl-json")
    report = json.loads(Path(dl.value.path()).read_text(encoding="utf-8"))
    assert report["summary"]["failed"] == exact.failed + 1
    pg.close()

    # the sheets of a scene download as the draw command writes them
    pg = browser.new_page(viewport={"width": 1366, "height": 768})
    pg.goto(url + "/#file=slider_crank.toml")
    _solved(pg, None)
    with pg.expect_download(timeout=30000) as dl:
        pg.click("#downloads button[data-format='svg']")
    data = Path(dl.value.path()).read_bytes()
    assert data.startswith(b"PK") or b"<svg" in data[:2000]
    with pg.expect_download(timeout=30000) as dl:
        pg.click("#dl-demo")
    page = Path(dl.value.path()).read_text(encoding="utf-8")
    assert page.startswith("<!DOCTYPE html>") and 'id="lesson"' in page

    # a blank check file for the scene: the student's v_A typed in is checked at once
    seq = pg.get_attribute("body", "data-solved")
    pg.click("#new-check")
    seq = _solved(pg, seq)
    assert pg.input_value("#save-path") == "slider_crank_check.toml"
    for sel, value in (("#f-scales\\.velocity\\.mu-0", "50"), ("#f-positions\\.0\\.measured\\.v_A-0", "500")):
        pg.fill(sel, value)
        pg.press(sel, "Enter")
        seq = _solved(pg, seq)
    assert pg.get_attribute("tr[data-field='positions[0].measured.v_A']", "class") == "fail"
    pg.close()
    assert errors == []


def test_serve_is_listed_without_loading_the_server_and_bad_arguments_are_one_line(tmp_path):
    import subprocess
    import sys

    code = ("import sys; from drawings.cli import build_parser; build_parser(['draw', 'x.toml']); "
            "build_parser(None); "
            "assert not [m for m in sys.modules if m.split('.')[0] in ('starlette', 'uvicorn', 'tomlkit')], "
            "sorted(m for m in sys.modules if m.split('.')[0] in ('starlette', 'uvicorn', 'tomlkit'))")
    root = Path(__file__).resolve().parents[1]
    p = subprocess.run([sys.executable, "-c", code], cwd=root, capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    for argv in (["serve", str(tmp_path / "absent")], ["serve", str(tmp_path), "--port", "70000"]):
        p = subprocess.run([sys.executable, "-c", "from drawings.cli import main; raise SystemExit(main())", *argv],
                           cwd=root, capture_output=True, text=True, timeout=30)
        assert p.returncode == 2 and len(p.stderr.strip().splitlines()) == 1 and "Traceback" not in p.stderr


def test_page_designs_a_crank_rocker_from_the_gallery(browser, server):
    """A synthesis model: the task in the form, the designed mechanism drawn; its rocker's
    swing, read off the drawn scheme's extreme positions, is the task's 40°."""
    _, url = server
    pg = browser.new_page(viewport={"width": 1366, "height": 768})
    pg.goto(url + "/")
    pg.wait_for_selector("body[data-ready='gallery']")
    pg.click("[data-sample='synthesis_crank_rocker'] button")
    _solved(pg, None)
    assert "K = 1.2" in pg.text_content("#design-summary")
    angles = []
    n = int(pg.get_attribute("#phi", "max")) + 1
    for k in range(n):
        pg.eval_on_selector("#phi", f"e => {{ e.value = {k}; e.dispatchEvent(new Event('input')); }}")
        bx, by = pg.eval_on_selector("#scheme circle[data-point='B']", "c => [Number(c.getAttribute('cx')), -Number(c.getAttribute('cy'))]")
        dx, dy = pg.eval_on_selector("#scheme circle[data-point='D']", "c => [Number(c.getAttribute('cx')), -Number(c.getAttribute('cy'))]")
        angles.append(math.degrees(math.atan2(by - dy, bx - dx)))
    # the design starts the turn at an extreme position: the first position is one end of the swing
    swing = max(abs(a - angles[0]) for a in angles)
    assert abs(swing - 40.0) < 2.0  # 12 positions sample the far end to within a few degrees
    pg.close()


def test_the_host_names_answered_are_the_servers_own():
    import socket

    assert hosts_for("127.0.0.1", 8765) == {"127.0.0.1:8765", "localhost:8765", "[::1]:8765"}
    every = hosts_for("0.0.0.0", 8765)
    assert f"{socket.gethostname().lower()}:8765" in every and "127.0.0.1:8765" in every
    assert not any(h.startswith("evil") for h in every)
    assert hosts_for("192.168.1.5", 80) == {"192.168.1.5:80"}
