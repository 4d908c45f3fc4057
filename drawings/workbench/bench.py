"""The workbench's figures for ``plans bench``: the server's share of an edit's round trip (a
changed length set in the TOML and the scene solved again, over loopback HTTP), the whole
round trip to the new plans drawn in headless Chromium, and the start of ``plans serve`` to
its first page.  ``python -m drawings.workbench.bench [SCENE]`` prints them as JSON."""

from __future__ import annotations

import json
import shutil
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path
from typing import Any

from drawings.headless import chromium


def _server(root: Path) -> tuple[Any, str]:
    import uvicorn

    from .server import bind, hosts_for, make_app

    sock = bind("127.0.0.1", 0)
    port = sock.getsockname()[1]
    srv = uvicorn.Server(uvicorn.Config(make_app(root, hosts_for("127.0.0.1", port)), log_level="error"))
    threading.Thread(target=srv.run, kwargs={"sockets": [sock]}, daemon=True).start()
    while not srv.started:
        time.sleep(0.01)
    return srv, f"127.0.0.1:{port}"


def server_share(scene: Path, reps: int = 15) -> dict[str, Any]:
    """Median seconds of ``POST /api/edit?solve=1`` (the crank's length set and the scene
    solved, in one answer, as the page asks), each edit a length not solved before."""
    import http.client
    import tomllib

    text = scene.read_text(encoding="utf-8")
    data = tomllib.loads(text)
    crank = str(data["driver"]["link"])
    length = float(data["links"][crank]["length"])
    with tempfile.TemporaryDirectory() as tmp:
        srv, host = _server(Path(tmp))
        conn = http.client.HTTPConnection(host, timeout=30)

        def post(path: str, body: bytes, ctype: str) -> tuple[bytes, float, float]:
            conn.request("POST", path, body=body, headers={"Content-Type": ctype})
            r = conn.getresponse()
            out = r.read()
            if r.status != 200:
                raise RuntimeError(f"{path}: {r.status} {out[:200]!r}")
            timing = dict(part.strip().split(";dur=") for part in (r.headers.get("Server-Timing") or "").split(","))
            return out, float(timing["app"]) / 1000, float(timing["cpu"]) / 1000

        times, walls, cpus = [], [], []
        for k in range(reps + 2):
            t0 = time.perf_counter()
            answer, spent, cpu = post("/api/edit?solve=1&steps=0&view=page&at=0", json.dumps(  # as the page does: each edit on the last text
                {"text": text, "set": [[["links", crank, "length"], round(length * (1 + 0.002 * (k + 1)), 6)]]}
            ).encode(), "application/json")
            got = json.loads(answer)
            if "solution" not in got:
                raise RuntimeError(f"the edit was not solved: {got.get('solve_error')}")
            text = got["text"]
            if k >= 2:  # the first two warm the imports and caches
                times.append(spent)
                cpus.append(cpu)
                walls.append(time.perf_counter() - t0)
        positions = len(got["solution"]["positions"])
        conn.close()
        srv.should_exit = True
    return {"scene": scene.name, "positions": positions, "server_s": statistics.median(times),
            "server_cpu_s": statistics.median(cpus),
            "loopback_s": statistics.median(walls), "answer_bytes": len(answer)}


def page_round_trip(scene: Path, reps: int = 7) -> float | None:
    """Median seconds from a changed length in the page to the new plans drawn (Chromium)."""
    with chromium() as b:
        if b is None:
            return None
        import tomllib

        data = tomllib.loads(scene.read_text(encoding="utf-8"))
        crank = str(data["driver"]["link"])
        length = float(data["links"][crank]["length"])
        with tempfile.TemporaryDirectory() as tmp:
            shutil.copy(scene, Path(tmp) / scene.name)
            srv, host = _server(Path(tmp))
            pg = b.new_page(viewport={"width": 1366, "height": 768})
            pg.goto(f"http://{host}/#file={scene.name}")
            pg.wait_for_selector("body[data-solved]")
            sel = f"#f-links\\.{crank}\\.length-0"
            times = []
            for k in range(reps + 1):
                before = pg.get_attribute("body", "data-solved")
                t = pg.evaluate(
                    """([sel, value, before]) => new Promise((done) => {
                        const t0 = performance.now();
                        const e = document.querySelector(sel);
                        e.value = String(value);
                        new MutationObserver((_, obs) => {
                          if (document.body.dataset.solved !== before) {
                            obs.disconnect();
                            requestAnimationFrame(() => done((performance.now() - t0) / 1000));
                          }
                        }).observe(document.body, {attributes: true});
                        e.dispatchEvent(new Event("change"));
                    })""", [sel, round(length * (1 + 0.002 * (k + 1)), 6), before])
                if k:
                    times.append(t)
            srv.should_exit = True
    return statistics.median(times)


def start_seconds(folder: Path, reps: int = 3) -> float:
    """Best seconds from starting ``plans serve`` to its first page answered."""
    import urllib.request

    best = float("inf")
    root = Path(__file__).resolve().parents[2]
    for _ in range(reps):
        t0 = time.perf_counter()
        p = subprocess.Popen([sys.executable, "-c", "from drawings.console import main; raise SystemExit(main())",
                              "serve", str(folder), "--port", "0"], cwd=root, stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, text=True)
        try:
            line = p.stdout.readline() if p.stdout else ""
            url = line.split(" at ", 1)[1].split(" ", 1)[0]
            with urllib.request.urlopen(url, timeout=10) as r:
                r.read()
            best = min(best, time.perf_counter() - t0)
        finally:
            p.terminate()
            p.wait(10)
    return best


def figures(scene: Path) -> dict[str, Any]:
    out = server_share(scene)
    out["page_s"] = page_round_trip(scene)
    out["start_s"] = start_seconds(scene.parent)
    return out


if __name__ == "__main__":
    print(json.dumps(figures(Path(sys.argv[1] if len(sys.argv) > 1 else "samples/four_bar.toml").resolve())))
