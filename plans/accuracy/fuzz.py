"""Fuzzing the promise on input files: ``plans bench --fuzz N``.

Every file under ``samples/`` (any kind: linkage scenes, check files, engines, gears,
cams) is parsed, mutated as a hostile user would (hostile numbers, wrong types, misspelt
and unknown keys, control characters and markup in names, files that are not UTF-8,
truncated TOML) and run through its command in-process.  A case keeps the promise when

* the command accepts it (status 0) and every number it printed or wrote is finite, or
* it refuses it with status 2 and exactly one line ``plans: error: ...`` on stderr,
  having written nothing and changed no input.

Either may say on stderr, one line each, what looks implausible in the file (``plans:
warning: ...``, a resisting load on the fast stroke, say): the file's own advice, not a
failure.  Anything else (an exception that escapes, another status, a Python warning, NaN or inf
in an output) is a failure, reported with the file that caused it.  The same mutations
drive the Hypothesis test in the test suite (a fixed budget, derandomized).
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import os
import random
import re
import shutil
import sys
import tempfile
import time
import tomllib
import traceback
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from plans.accuracy.mutations import mutate, mutate_bytes, to_toml

__all__ = ["mutate", "mutate_bytes", "to_toml"]  # read from here too

SAMPLES = Path(__file__).resolve().parents[2] / "samples"

# --------------------------------------------------------------------------- running one case


@dataclass
class Sample:
    """A sample file as the fuzzer starts from it."""

    path: Path
    data: dict[str, Any]
    argv: Callable[[str, str | None], list[str]]  # (input file, JSON output or None) -> the command line
    rel: str
    json: bool = True  # the command takes --json PATH
    kind: str = "linkage"  # the file's kind ("check" for a check file)


def _kind_argv(kind: str, is_check: bool) -> Callable[[str, str | None], list[str]]:
    """The command line: with ``out`` the JSON goes there, without it the table to stdout."""
    from plans.kinds import KINDS

    cmd = "check" if is_check else KINDS[kind][0]
    quiet = ["--quiet"] if cmd in ("check", "solve") else []
    return lambda f, out: [cmd, f, "--json", out, *quiet] if out else [cmd, f]


def _absolute_paths(data: dict[str, Any], folder: Path) -> dict[str, Any]:
    """A check file's ``scene = "../x.toml"`` made absolute, so a copy elsewhere still finds it."""
    if isinstance(data.get("scene"), str) and not Path(data["scene"]).is_absolute():
        data = dict(data, scene=str((folder / data["scene"]).resolve()))
    return data


def _few_positions(data: dict[str, Any]) -> dict[str, Any]:
    """A linkage sample with many positions fuzzed at two of them: the same paths, faster
    (a mutation may still ask for more)."""
    driver = data.get("driver")
    if isinstance(driver, dict) and isinstance(driver.get("positions"), int) and driver["positions"] > 2:
        data = json.loads(json.dumps(data))
        data["driver"]["positions"] = 2
    if isinstance(driver, dict) and isinstance(driver.get("phi_deg"), list) and len(driver["phi_deg"]) > 2:
        data = json.loads(json.dumps(data))
        data["driver"]["phi_deg"] = data["driver"]["phi_deg"][:2]
    return data


def load_samples(root: Path = SAMPLES) -> list[Sample]:
    """Every ``*.toml`` under ``root`` that its own command accepts as it is."""
    from plans.kinds import kind_of

    out = []
    for p in sorted(root.rglob("*.toml")):
        try:
            data = tomllib.loads(p.read_text(encoding="utf-8"))
            kind = kind_of(data, str(p))
        except Exception:  # noqa: BLE001 - a sample that does not read is simply not fuzzed
            continue
        is_check = "checks" in p.relative_to(root).parts or ("student" in data and "positions" in data)
        sample = Sample(p, _few_positions(_absolute_paths(data, p.parent)), _kind_argv(kind, is_check),
                        str(p.relative_to(root)), kind="check" if is_check else kind)
        for with_json in (True, False):  # a command of another kind may have no --json
            sample.json = with_json
            with tempfile.TemporaryDirectory() as tmp:
                res = run_case(sample, to_toml(sample.data).encode("utf-8"), Path(tmp))
            if res.ok and res.status == 0:
                out.append(sample)
                break
    return out


@dataclass
class Result:
    ok: bool
    status: int | None
    why: str = ""
    nonfinite: bool = False


_NONFINITE = re.compile(r"(?<![A-Za-z_])(nan|inf|infinity)(?![A-Za-z_])", re.IGNORECASE)


def _finite_json(text: str) -> bool:
    bad = []

    def const(name: str) -> float:
        bad.append(name)
        return 0.0

    json.loads(text, parse_constant=const)
    return not bad


def _snapshot(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*"))
            if p.is_file() and not p.is_symlink()}


_PARSERS: dict[str, argparse.ArgumentParser] = {}


def _main() -> Callable[[list[str]], int]:
    """The full ``plans`` command when the renderer is loaded (``draw`` included), else the
    engine's own (this package never imports the renderer); its parser built once."""
    from plans import cli

    module: Any = sys.modules.get("drawings.cli") or cli
    if module.__name__ not in _PARSERS:
        _PARSERS[module.__name__] = module.build_parser()
    parser = _PARSERS[module.__name__]

    def main(argv: list[str]) -> int:
        return cli.run(parser.parse_args(argv))

    return main


#: The spellings of the input file a hostile ``--json`` may give (none may overwrite it).
SPELLINGS = ("same", "dot", "absolute", "symlink", "hardlink", "folder-link")
#: Every command that reads a file of the family, to run one kind's file through another's.
COMMANDS = ("solve", "check", "balance", "gears", "cam")


def _spelling(src: Path, how: str) -> str:
    """``src`` spelt another way: ./x, x/../x, a symbolic or hard link, a linked folder."""
    folder = src.parent
    if how == "dot":
        return f"{folder}/./out/../{src.name}"
    if how == "absolute":
        return str(src.resolve())
    if how == "symlink":
        link = folder / "link.json"
        link.symlink_to(src.name)
        return str(link)
    if how == "hardlink":
        link = folder / "hard.json"
        os.link(src, link)
        return str(link)
    if how == "folder-link":
        link = folder / "here"
        link.symlink_to(".", target_is_directory=True)
        return str(link / src.name)
    return str(src)


def run_case(sample: Sample, raw: bytes, tmp: Path, draw: bool = False, json_out: bool = True,
             command: str | None = None, over_input: str | None = None) -> Result:
    """Run the sample's command (or ``command``) on ``raw`` in-process; whether the promise was
    kept (with ``draw``, and the renderer loaded, its SVG sheets are drawn and checked too;
    with ``over_input``, ``--json`` names the input file spelt that way: it must be refused)."""
    main = _main()

    src = tmp / sample.path.name
    src.write_bytes(raw)
    out_json = tmp / "out" / "result.json"
    out_json.parent.mkdir(exist_ok=True)
    target = str(out_json) if json_out and sample.json else None
    if over_input is not None:
        target = _spelling(src, over_input)
    before = _snapshot(tmp)
    argv = sample.argv(str(src), target)
    if command is not None:
        argv = [command, str(src), *(["--json", target] if target else [])]
    stdout, stderr = io.StringIO(), io.StringIO()
    with warnings.catch_warnings(record=True) as caught, contextlib.redirect_stdout(stdout), \
            contextlib.redirect_stderr(stderr):
        warnings.simplefilter("always")
        try:
            status: int | None = main(argv)
        except SystemExit as exc:
            status = exc.code if isinstance(exc.code, int) else 1
        except Exception as exc:  # noqa: BLE001 - this is what the fuzzer looks for
            tb = traceback.extract_tb(exc.__traceback__)[-1]
            return Result(False, None, f"{type(exc).__name__}: {exc} (at {Path(tb.filename).name}:{tb.lineno})")
    err = _without_advice(stderr.getvalue())
    if caught:
        w = caught[0]
        return Result(False, status, f"warning printed: {w.category.__name__}: {w.message} "
                                     f"({Path(w.filename).name}:{w.lineno})")
    if status == 2:
        lines = err.splitlines()
        if len(lines) != 1 or not lines[0].startswith(("plans: error: ", "plans: ошибка: ")) or "Traceback" in err:
            return Result(False, status, f"refusal is not one line: {err[:300]!r}")
        if _snapshot(tmp) != before:
            return Result(False, status, "refused, but files were written or changed")
        return Result(True, 2)
    if status != 0:
        return Result(False, status, f"status {status}: {err[:300]!r}")
    if over_input is not None:
        return Result(False, status, f"--json spelt as the input ({over_input}) was accepted")
    # an implausible file may be warned about (plans.plausible); nothing else is said
    if any(not line.startswith(("plans: warning: ", "plans: внимание: ")) for line in err.splitlines()):
        return Result(False, status, f"accepted, but printed on stderr: {err[:300]!r}")
    if src.read_bytes() != raw:
        return Result(False, status, "the input file was changed")
    if _NONFINITE.search(stdout.getvalue()):
        return Result(False, status, "non-finite number printed", nonfinite=True)
    if out_json.exists():
        try:
            if not _finite_json(out_json.read_text(encoding="utf-8")):
                return Result(False, status, "non-finite number in the JSON", nonfinite=True)
        except ValueError as exc:
            return Result(False, status, f"the JSON does not parse: {exc}")
    if draw and "drawings.cli" in sys.modules:
        return _draw(src, tmp, main)
    return Result(True, 0)


def _draw(src: Path, tmp: Path, main: Callable[[list[str]], int]) -> Result:
    """Draw the accepted file as SVG: refused in one line, or well-formed sheets without NaN."""
    import xml.etree.ElementTree as ET

    out = tmp / "sheets"
    stderr = io.StringIO()
    with warnings.catch_warnings(record=True) as caught, contextlib.redirect_stdout(io.StringIO()), \
            contextlib.redirect_stderr(stderr):
        warnings.simplefilter("always")
        try:
            status = main(["draw", str(src), "-o", str(out)])
        except Exception as exc:  # noqa: BLE001
            tb = traceback.extract_tb(exc.__traceback__)[-1]
            return Result(False, None, f"draw: {type(exc).__name__}: {exc} (at {Path(tb.filename).name}:{tb.lineno})")
    if caught:
        return Result(False, status, f"draw: warning printed: {caught[0].message}")
    if status == 2:
        lines = _without_advice(stderr.getvalue()).splitlines()
        ok = len(lines) == 1 and lines[0].startswith(("plans: error: ", "plans: ошибка: "))
        return Result(ok, 2, "" if ok else f"draw: refusal is not one line: {stderr.getvalue()[:300]!r}")
    if status != 0:
        return Result(False, status, f"draw: status {status}")
    for p in sorted(out.glob("*.svg")):
        text = p.read_text(encoding="utf-8")
        try:
            ET.fromstring(text)
        except ET.ParseError as exc:
            return Result(False, 0, f"draw: {p.name} is not well-formed XML: {exc}")
        if re.search(r'="[^"]*\b(nan|inf)\b', text, re.IGNORECASE):
            return Result(False, 0, f"draw: {p.name} holds NaN or inf in an attribute", nonfinite=True)
    shutil.rmtree(out, ignore_errors=True)
    return Result(True, 0)


def _read(kind: str, data: dict[str, Any], path: str) -> None:
    """The reader of a file of ``kind`` (what its command reads before it solves)."""
    if kind == "linkage":
        from plans.kinematics.placing import scene_from_dict

        scene = scene_from_dict(data, path)
        if "loads" in data:
            from plans.forces.loads import parse_loads

            parse_loads(scene)
        if "dynamics" in data:
            from plans.cycle.spec import dynamics_spec

            dynamics_spec(scene)
        if "diagrams" in data:
            from plans.cycle.spec import diagrams_spec

            diagrams_spec(scene)
    elif kind != "check":  # every other kind by the reader it registers (plans.kinds.READERS)
        import importlib

        from plans.kinds import READERS

        module, name = READERS[kind].split(":")
        getattr(importlib.import_module(module), name)(data, path)
    elif isinstance(data.get("cycle"), dict) and "positions" not in data:
        from plans.check.cycle import check_cycle

        check_cycle(path)
    else:
        from plans.check.checkfile import check_from_dict

        check_from_dict(data, path)


#: The lines a command may print about an implausible file it accepts (its advice, in
#: either language): not a failure.
ADVICE = ("plans: warning: ", "plans: внимание: ")


def _without_advice(err: str) -> str:
    """stderr without the advice lines."""
    return "".join(line for line in err.splitlines(keepends=True) if not line.startswith(ADVICE))


def read_case(sample: Sample, raw: bytes, tmp: Path) -> Result:
    """The fast half of a case: only the reader of the file's kind.  It keeps the promise when
    it accepts the file or refuses it with one InputError naming the file, and prints no
    warning; anything else is a failure."""
    from plans.errors import InputError, PlansError, one_line
    from plans.io import loads_toml

    src = tmp / sample.path.name
    src.write_bytes(raw)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            try:
                text = raw.decode("utf-8")
            except UnicodeDecodeError:
                return Result(True, 2)
            _read(sample.kind, loads_toml(text, str(src)), str(src))
        except InputError as exc:
            line = one_line(exc)
            if "\n" in line or not line.startswith(str(src)):
                return Result(False, 2, f"refusal does not name the file in one line: {line[:200]!r}")
            return Result(True, 2)
        except PlansError:  # a construction error found while reading (strokes of loads)
            return Result(True, 2)
        except Exception as exc:  # noqa: BLE001 - this is what the fuzzer looks for
            tb = traceback.extract_tb(exc.__traceback__)[-1]
            return Result(False, None, f"{type(exc).__name__}: {exc} (at {Path(tb.filename).name}:{tb.lineno})")
    if caught:
        w = caught[0]
        return Result(False, 0, f"warning printed: {w.category.__name__}: {w.message}")
    return Result(True, 0)


def case_bytes(sample: Sample, rng: random.Random) -> bytes:
    """One fuzzed file: mostly a mutated table, sometimes damaged bytes."""
    if rng.random() < 0.08:
        return mutate_bytes(to_toml(sample.data), rng)
    return to_toml(mutate(sample.data, rng)).encode("utf-8")


# --------------------------------------------------------------------------- the long run


@dataclass
class Summary:
    cases: int = 0
    accepted: int = 0
    refused: int = 0
    failures: dict[str, str] = field(default_factory=dict)  # distinct reason -> first case file
    nonfinite: int = 0
    foreign: int = 0
    kinds: dict[str, int] = field(default_factory=dict)  # cases per file kind


def fuzz(n: int, seed: int = 0, draw_every: int = 50, keep: Path | None = None,
         progress: Callable[[str], None] | None = None, samples: Sequence[Sample] | None = None) -> Summary:
    """Run ``n`` fuzzed cases over every sample; distinct failures are kept in ``keep``; the
    progress lines in the run's language."""
    from plans.errors import run_language
    from plans.phrases import say

    lang = run_language()
    rng = random.Random(seed)
    pool = list(samples) if samples is not None else load_samples()
    if not pool:
        raise SystemExit(say("bf_no_samples", lang))
    # a check file costs ten linkage cases: fuzzed a third as often, so the run covers more
    by_kind: dict[str, list[Sample]] = {}
    for s in pool:
        by_kind.setdefault(s.kind, []).extend([s] * (1 if s.argv("f", None)[0] == "check" else 3))
    # the kinds in turn, so that any run as long as the number of kinds fuzzes every kind
    rounds = max(len(v) for v in by_kind.values())
    schedule = [v[j] for j in range(rounds) for v in by_kind.values() if j < len(v)]
    summary = Summary()
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="plans-fuzz-") as base:
        for i in range(n):
            sample = schedule[i % len(schedule)]
            raw = case_bytes(sample, rng)
            tmp = Path(base) / f"case{i % 4}"
            shutil.rmtree(tmp, ignore_errors=True)
            tmp.mkdir()
            over = SPELLINGS[(i // 16) % len(SPELLINGS)] if i % 16 == 5 else None
            other = rng.choice(COMMANDS) if i % 16 == 9 else None
            res = run_case(sample, raw, tmp, draw=draw_every > 0 and i % draw_every == 0, json_out=i % 8 == 0,
                           command=other, over_input=over)
            summary.cases += 1
            summary.kinds[sample.kind] = summary.kinds.get(sample.kind, 0) + 1
            if res.ok:
                summary.accepted += res.status == 0
                summary.refused += res.status == 2
            else:
                summary.nonfinite += res.nonfinite
                summary.foreign += res.status is None
                reason = re.sub(r"\d+(\.\d+)?(e[-+]?\d+)?", "#", res.why.replace(str(tmp), "DIR"))[:100]
                if reason not in summary.failures:
                    name = f"fail-{len(summary.failures):03d}-{sample.path.name}"
                    summary.failures[reason] = name
                    if keep is not None:
                        keep.mkdir(parents=True, exist_ok=True)
                        (keep / name).write_bytes(raw)
                        (keep / (name + ".txt")).write_text(f"{sample.rel}\n{res.why}\n", encoding="utf-8")
                    if progress:
                        progress(say("bf_case", lang, i=i, sample=sample.rel, why=res.why))
            if progress and (i + 1) % 1000 == 0:
                progress(say("bf_progress", lang, n=i + 1, accepted=summary.accepted, refused=summary.refused,
                             failures=len(summary.failures), t=time.perf_counter() - t0))
    return summary


def report(summary: Summary, seed: int, lang: str = "en") -> str:
    from plans.group.gradebook import heading
    from plans.phrases import say

    lines = [say("bf_report", lang, n=summary.cases, seed=seed, accepted=summary.accepted, refused=summary.refused,
                 broke=summary.cases - summary.accepted - summary.refused, foreign=summary.foreign,
                 nonfinite=summary.nonfinite, distinct=len(summary.failures))]
    if summary.kinds:
        lines.append(say("bf_by_kind", lang, kinds=", ".join(f"{heading(k, lang)} {n}"
                                                             for k, n in sorted(summary.kinds.items()))))
    lines += [f"  {name}: {reason}" for reason, name in summary.failures.items()]
    return "\n".join(lines)


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The hook of ``plans bench``: ``--fuzz N`` (and its seed and folder for failures)."""
    p.add_argument("--fuzz", type=int, metavar="N", help="instead of the bench: fuzz the sample files with N "
                                                          "hostile cases and report every broken promise")
    p.add_argument("--fuzz-seed", type=int, default=0, metavar="S", help="seed of --fuzz (default 0)")
    p.add_argument("--fuzz-keep", metavar="DIR", help="keep the files of distinct failures here")


def run(args: argparse.Namespace) -> int:
    """``plans bench --fuzz N``: 0 when every case kept the promise, 1 otherwise."""
    n = int(args.fuzz)
    if n < 1:
        from plans.errors import Said, error_prefix, run_language

        print(f"{error_prefix()}--fuzz: {Said('bn_fuzz').text(run_language())}", file=sys.stderr)
        return 2
    keep = Path(args.fuzz_keep) if getattr(args, "fuzz_keep", None) else None
    seed = int(getattr(args, "fuzz_seed", 0))
    summary = fuzz(n, seed=seed, keep=keep, progress=lambda s: print(s, file=sys.stderr, flush=True))
    from plans.errors import run_language

    print(report(summary, seed, run_language()))
    return 0 if not summary.failures else 1


def main(argv: Sequence[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m plans.accuracy.fuzz")
    add_arguments(p)
    args = p.parse_args(argv)
    if args.fuzz is None:
        p.error("expected --fuzz N")
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    return run(args)


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
