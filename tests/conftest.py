"""Shared fixtures: the samples and small scenes built in code."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from hypothesis import settings

# CI replays the same examples every run (a red CI must be reproducible); developers'
# runs keep exploring new ones.
settings.register_profile("ci", derandomize=True, deadline=None)
if os.environ.get("CI"):
    settings.load_profile("ci")

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = sorted((ROOT / "samples").glob("*.toml"))


@pytest.fixture
def english_locale(monkeypatch):
    """The environment's locale English: the default language is the locale's, and a test
    of both languages chooses it."""
    for name in ("LC_ALL", "LC_MESSAGES"):
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("LANG", "C.UTF-8")


@pytest.fixture(scope="module")
def browser():
    """Headless Chromium for the page tests (the demonstration, the workbench); skipped where
    it or Playwright is missing, a failure on CI."""
    from drawings.headless import chromium

    with chromium() as b:
        if b is None:
            if os.environ.get("CI"):
                pytest.fail("CI needs Chromium and Playwright for the page tests (.ci/run installs them)")
            pytest.skip("Chromium or Playwright not installed")
        yield b


def slider_crank_scene(r_mm: float = 50.0, l_mm: float = 180.0, e_mm: float = 0.0, *,
                       phi_deg=(30.0,), omega: float = 100.0, eps: float = 0.0, sense: str = "ccw",
                       outputs=("positions", "velocity_plan", "acceleration_plan"), unit: str = "mm") -> dict:
    """A slider-crank as a scene dict: crank OA, rod AB, slider B on the line y = e."""
    return {
        "format": 1, "title": "slider-crank", "unit": unit, "frame": 4, "outputs": list(outputs),
        "points": {"O": [0, 0]},
        "links": {
            "1": {"axis": ["O", "A"], "length": r_mm},
            "2": {"axis": ["A", "B"], "length": l_mm, "points": {"S2": {"ratio": 0.3}}},
            "3": {"axis": ["B"]},
        },
        "joints": [
            {"kind": "R", "links": [4, 1], "point": "O"},
            {"kind": "R", "links": [1, 2], "point": "A"},
            {"kind": "R", "links": [2, 3], "point": "B"},
            {"kind": "P", "links": [3, 4], "point": "B",
             "guide": {"link": 4, "through": [0, e_mm], "angle_deg": 0}},
        ],
        "driver": {"link": 1, "omega": omega, "eps": eps, "sense": sense, "phi_ref_deg": 0,
                   "phi_deg": list(phi_deg)},
    }


def four_bar_scene(a: float = 80, b: float = 260, c: float = 200, d: float = 300, *,
                   phi_deg=(30.0,), omega: float = 10.0, eps: float = 0.0, branch: int = 1,
                   outputs=("positions", "velocity_plan", "acceleration_plan")) -> dict:
    """Crank OA = a, coupler AB = b, rocker DB = c, frame OD = d (mm)."""
    return {
        "format": 1, "title": "four-bar", "unit": "mm", "frame": 4, "outputs": list(outputs),
        "points": {"O": [0, 0], "D": [d, 0]},
        "links": {
            "1": {"axis": ["O", "A"], "length": a},
            "2": {"axis": ["A", "B"], "length": b, "points": {"E": {"along": b / 2, "across": b / 4}}},
            "3": {"axis": ["D", "B"], "length": c},
        },
        "joints": [
            {"kind": "R", "links": [4, 1], "point": "O"},
            {"kind": "R", "links": [1, 2], "point": "A"},
            {"kind": "R", "links": [2, 3], "point": "B"},
            {"kind": "R", "links": [3, 4], "point": "D"},
        ],
        "branches": {"2-3": branch},
        "driver": {"link": 1, "omega": omega, "eps": eps, "sense": "ccw", "phi_ref_deg": 0,
                   "phi_deg": list(phi_deg)},
    }


@pytest.fixture(params=SAMPLES, ids=[p.stem for p in SAMPLES])
def sample_path(request) -> Path:
    return request.param
