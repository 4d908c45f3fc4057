"""``from drawings import draw`` is the function that draws a file of any kind (a linkage's
through ``drawings.linkage.draw``), whatever was imported before it (the package loads its
names on first use)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

CHECK = ("import types\n"
         "import drawings\n"
         "from drawings import draw\n"
         "import drawings.linkage as linkage\n"
         "assert isinstance(draw, types.FunctionType), type(draw)\n"
         "assert isinstance(linkage.draw, types.FunctionType), type(linkage.draw)\n"
         "assert draw is drawings.draw and draw.__module__ == 'drawings'\n"
         "print('ok')\n")


@pytest.mark.parametrize("before", ["", "import drawings.linkage\n", "import drawings\n",
                                    "from drawings.linkage import Drawing\n"],
                         ids=["fresh", "after-linkage", "after-package", "after-from-linkage"])
def test_from_drawings_import_draw_is_the_function(before):
    got = subprocess.run([sys.executable, "-c", before + CHECK], cwd=ROOT, capture_output=True, text=True)
    assert got.returncode == 0, got.stderr
    assert got.stdout.strip() == "ok"


def test_the_linkage_kind_draws_with_drawings_linkage():
    import importlib

    from plans.kinds import KINDS

    module = importlib.import_module(KINDS["linkage"][1])
    from drawings import draw
    from drawings.linkage import draw as linkage_draw

    assert module.__name__ == "drawings.linkage"
    assert module.draw is linkage_draw
    scene = str(ROOT / "samples" / "slider_crank.toml")
    one, other = draw(scene), linkage_draw(scene)  # the dispatcher draws a linkage as its module does
    assert [s.svg() for s in one.sheets] == [s.svg() for s in other.sheets]
