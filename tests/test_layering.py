"""plans/ is the pure engine: it never imports the renderer or its libraries."""

from __future__ import annotations

import ast
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
