"""plans/ is the pure engine: it never imports the renderer or its libraries."""

from __future__ import annotations

import ast
import json
import subprocess
import sys
from pathlib import Path

FORBIDDEN = {"drawings", "svgwrite", "cairosvg", "cairocffi"}


def test_plans_never_imports_drawings_or_renderers():
    root = Path(__file__).resolve().parent.parent / "plans"
    for path in root.rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            names = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                names = [node.module]
            elif isinstance(node, ast.Call) and getattr(node.func, "attr", "") == "import_module":
                names = [a.value for a in node.args if isinstance(a, ast.Constant) and isinstance(a.value, str)]
            for n in names:
                assert n.split(".")[0] not in FORBIDDEN, f"{path.name} imports {n}"


def _run(code: str) -> subprocess.CompletedProcess:
    root = Path(__file__).resolve().parent.parent
    return subprocess.run([sys.executable, "-c", code], cwd=root, capture_output=True, text=True, timeout=120)


def test_import_plans_loads_no_renderer_and_no_shapely():
    got = _run("import sys, plans; print(sorted(m for m in ('svgwrite', 'cairosvg', 'shapely', 'drawings') "
               "if m in sys.modules))")
    assert got.returncode == 0, got.stderr
    assert got.stdout.strip() == "[]"


def test_solve_runs_without_the_renderer():
    """``python -m plans solve``: the plans, the forces and the lever, and nothing of the
    renderer loaded."""
    got = _run("import runpy, sys\n"
               "sys.argv = ['plans', 'solve', 'samples/slider_crank.toml']\n"
               "try:\n    runpy.run_module('plans', run_name='__main__')\n"
               "except SystemExit as exc:\n    assert not exc.code, exc.code\n"
               "print('loaded:', sorted(m for m in ('svgwrite', 'cairosvg', 'drawings', 'ezdxf') "
               "if m in sys.modules))")
    assert got.returncode == 0, got.stderr
    assert got.stdout.rstrip().endswith("loaded: []"), got.stdout[-300:]
    assert "p_v" in got.stdout or "v_" in got.stdout


def test_plans_solve_of_every_linkage_sample_loads_no_shapely_and_no_renderer():
    """``plans solve`` as the installed console command runs it (drawings.console), each
    linkage sample with its table: the force polygons close in closed form, so neither
    shapely nor the renderer's libraries nor the sheets are ever loaded."""
    got = _run("import contextlib, io, sys\n"
               "from pathlib import Path\n"
               "from drawings.console import main\n"
               "from plans.kinds import read_kind\n"
               "for path in sorted(Path('samples').glob('*.toml')):\n"
               "    if read_kind(path)[0] != 'linkage':\n"
               "        continue\n"
               "    sys.argv = ['plans', 'solve', str(path)]\n"
               "    out = io.StringIO()\n"
               "    with contextlib.redirect_stdout(out):\n"
               "        assert main() == 0, path\n"
               "    assert 'phi = ' in out.getvalue(), path\n"
               "    loaded = [m for m in ('shapely', 'svgwrite', 'cairosvg', 'drawings.paper.sheet') if m in sys.modules]\n"
               "    print(path.name, 'loaded:', loaded)\n")
    assert got.returncode == 0, got.stderr
    lines = got.stdout.splitlines()
    assert len(lines) >= 8 and any(line.startswith("v_engine.toml") for line in lines), got.stdout
    assert all(line.endswith("loaded: []") for line in lines), got.stdout


def test_plans_of_every_position_need_no_shapely():
    got = _run("import sys\n"
               "from plans.scene.model import load_scene\n"
               "from plans.kinematics.exact import solve\n"
               "from plans.kinematics.construction import build_all\n"
               "plans = build_all(solve(load_scene('samples/shaper.toml'), order=2))\n"
               "assert plans[0].velocity.protocol() and plans[-1].readings\n"
               "print('shapely' in sys.modules)")
    assert got.returncode == 0, got.stderr
    assert got.stdout.strip() == "False"


def test_kinematics_never_imports_shapely():
    """The construction intersects in closed form; shapely stays where it earns its place."""
    root = Path(__file__).resolve().parent.parent / "plans" / "kinematics"
    for path in root.rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                assert all(a.name.split(".")[0] != "shapely" for a in node.names), path.name
            elif isinstance(node, ast.ImportFrom) and node.module:
                assert node.module.split(".")[0] != "shapely", path.name


def test_lever_depends_on_polygons_never_the_reverse():
    src = (Path(__file__).resolve().parent.parent / "plans" / "forces" / "polygons.py").read_text(encoding="utf-8")
    tree = ast.parse(src)
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module:
            assert node.module not in ("plans.forces.lever", "plans.forces.analysis"), node.module


#: What solves a linkage (the exact analysis, the plans' construction, the force analysis,
#: the lever, the cycle): the engine's, read by the sheets off one plans.solve.
SOLVERS = {
    "plans.kinematics.exact": {"solve"},
    "plans.kinematics.construction": {"build", "build_all", "build_many"},
    "plans.kinematics.structure": {"analyse"},
    "plans.forces.analysis": {"kinetostatics"},
    "plans.forces.polygons": {"analyse_forces", "force_polygons"},
    "plans.forces.lever": {"zhukovsky_lever", "lever_plan", "force_rows"},
    "plans.cycle.results": {"solve_cycle"},
    "plans.cycle.diagrams": {"diagrams"},
    "plans.cycle.dynamics": {"dynamics"},
    "plans.kinematics.extreme": {"strokes"},
    "plans.forces.loads": {"ignition", "parse_loads"},
    "plans.kinematics.centres": {"centres_at", "velocities_at", "kennedy", "primary"},
    "plans.forces.friction": {"friction_analysis", "cycle_efficiency", "efficiency_json"},
}

#: What solves a file of the other kinds: each room's, read by its sheets off the room's
#: solved object (plans.solve: EngineSolution, GearsSolution, CamSolution, DesignSolution).
ROOM_SOLVERS = {
    "plans.balancing.analysis": {"balance"},
    "plans.balancing.banks": {"analyse_banks"},
    "plans.balancing.exact": {"exact_check", "frame_force", "truncation_table"},
    "plans.gears.solve": {"solve_gears", "choose_shifts"},
    "plans.gears.meshing": {"meshing", "drawn_contact_ratios"},
    "plans.gears.train": {"willis", "layout", "velocity_plan"},
    "plans.cams.analysis": {"motion", "profile", "findings", "undercuts"},
    "plans.cams.base_radius": {"min_base_radius", "allowed_region", "division_points", "bounds",
                               "roller_base_radius"},
    "plans.cams.graphical": {"integrate_cam"},
    "plans.cams.rocker": {"diagram", "region", "points"},
    "plans.synthesis.design": {"design", "slider_crank", "v_engine", "coulisse"},
    "plans.synthesis.proof": {"measure"},
    "plans.synthesis.numeric": {"roots", "fmin", "minimum", "wrap"},
}


def test_drawings_call_no_solver():
    """The sheets draw what plans.solve solved: no module under drawings/ imports a solver
    of a linkage, the cycle, an engine's balance, gears, a cam or a synthesis (lazy imports
    inside functions included)."""
    solvers = {**SOLVERS, **ROOM_SOLVERS}
    root = Path(__file__).resolve().parent.parent / "drawings"
    found = []
    for path in sorted(root.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.module in solvers:
                bad = solvers[node.module] & {a.name for a in node.names}
                found += [f"{path.name}: {node.module}.{n}" for n in sorted(bad)]
            elif isinstance(node, ast.Import):
                found += [f"{path.name}: {a.name}" for a in node.names if a.name in solvers]
    assert found == []


def test_the_solvers_the_layering_test_names_exist():
    """Each name the test above forbids is a function of its module (a renamed solver would
    otherwise pass unseen)."""
    import importlib

    for module, names in {**SOLVERS, **ROOM_SOLVERS}.items():
        got = importlib.import_module(module)
        assert all(callable(getattr(got, n, None)) for n in names), (module, names)


#: What ``plans solve`` has loaded of its own when it begins to solve (what ``plans bench``
#: times as its start): the command line, the scene's reader and the kinematics it solves
#: with.  A module added here is a cost every ``plans solve`` pays before its first result.
SOLVE_START = {
    "drawings", "drawings.cli", "drawings.console",
    "plans", "plans.cli", "plans.errors", "plans.guard", "plans.io", "plans.kinds", "plans.language",
    "plans.lines", "plans.phrases", "plans.reader", "plans.records", "plans.results", "plans.tolerances",
    "plans.units", "plans.scene", "plans.scene.model", "plans.scene.options", "plans.scene.positions",
    "plans.kinematics", "plans.kinematics.assur", "plans.kinematics.cases", "plans.kinematics.construction",
    "plans.kinematics.context", "plans.kinematics.dyads", "plans.kinematics.exact", "plans.kinematics.fast",
    "plans.kinematics.fast_arrays", "plans.kinematics.placing", "plans.kinematics.plan", "plans.kinematics.scales",
    "plans.kinematics.structure",
}


def test_plans_solve_starts_with_its_own_modules_only():
    """The installed command stopped the moment the scene, read, is handed to the solver: of
    ours exactly :data:`SOLVE_START` is loaded (no sheet reader for a scene without
    ``[sheet]``, no Solution, no forces, no cycle), and none of the heavy standard modules
    a command may need later."""
    got = _run("import os, sys\n"
               "import plans.results\n"
               "def stop(scene):\n"
               "    print(sorted(m for m in sys.modules if m.split('.')[0] in ('plans', 'drawings')))\n"
               "    print(sorted(m for m in ('json', 'shutil', 'shapely', 'subprocess', 'xml', 'zipfile') "
               "if m in sys.modules))\n"
               "    sys.stdout.flush()\n"
               "    os._exit(0)\n"
               "plans.results.solve_scene = stop\n"
               "from drawings.console import main\n"
               "sys.argv = ['plans', 'solve', 'samples/slider_crank.toml']\n"
               "main()\n")
    assert got.returncode == 0, got.stderr
    ours, heavy = got.stdout.splitlines()
    assert set(ast.literal_eval(ours)) == SOLVE_START
    assert heavy == "[]"


def test_plans_solve_whole_loads_no_temporary_files_module_nor_the_catalogues_it_does_not_say(tmp_path):
    """``plans solve --json`` to its end: the JSON written atomically without tempfile (and
    the shutil, random and compression modules it loads), no error or checker catalogue read
    when nothing goes wrong; the JSON is written all the same."""
    out = tmp_path / "x.json"
    got = _run("import sys\n"
               "from drawings.console import main\n"
               f"sys.argv = ['plans', 'solve', 'samples/slider_crank.toml', '--quiet', '--json', {str(out)!r}]\n"
               "status = main()\n"
               "print(status, sorted(m for m in ('tempfile', 'shutil', 'random', 'bz2', 'lzma', 'plans.messages', "
               "'plans.check_terms') if m in sys.modules))\n")
    assert got.returncode == 0, got.stderr
    assert got.stdout.strip() == "0 []"
    assert json.loads(out.read_text(encoding="utf-8"))["positions"]
    assert [p.name for p in tmp_path.iterdir()] == ["x.json"]


#: What the paper toolkit may read of the engine: errors, files, words and the sheet's own
#: settings (format, language, the scales' notation), nothing of a mechanism.
PAPER_MAY_IMPORT = {"plans.errors", "plans.io", "plans.language", "plans.phrases", "plans.scene.sheet", "plans.scene.notation",
                    "plans.scene.paper"}


def test_the_paper_toolkit_imports_no_room():
    """drawings/paper (sheets, frames, packing, text, backends, export) knows millimetres,
    lines and words: it imports no room of the engine and no sheets of a room (lazy imports
    included)."""
    root = Path(__file__).resolve().parent.parent / "drawings" / "paper"
    found = []
    for path in sorted(root.glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            names = ([node.module or ""] if isinstance(node, ast.ImportFrom) and node.level == 0 else
                     [a.name for a in node.names] if isinstance(node, ast.Import) else [])
            for mod in names:
                ours = mod.split(".")[0] in ("plans", "drawings")
                if ours and mod not in PAPER_MAY_IMPORT and not mod.startswith("drawings.paper") and mod != "drawings":
                    found.append(f"{path.name}: {mod}")
            if isinstance(node, ast.ImportFrom) and node.level > 0:
                found.append(f"{path.name}: a relative import")
    assert found == []
    assert len(list(root.glob("*.py"))) >= 10  # the toolkit is where this test looks
