"""The truth suites' sample (``truths/truth_*.py``, 1 case per cell, seed 11) reconciled once
per test session and shared by the tests that read it (``bench_truth_suites`` runs and
scores the same cases). Under ``pytest -n`` the workers share it through a file per suite
(the first to need a suite reconciles it while the others wait for the file), and so the
suites' generated cases and the cases reconciled alone.

The sample is every case of the held-out suite (``HELD_OUT``, the latest written) and, of
the development suites before it, the cases on which nothing of the gear may be named
(``DEVELOPMENT_CATEGORIES``: clean data and separable decoys, the false-alarm bar the
library meets on every suite). The development suites' singles, pairs and data-equivalent
decoys are scored by ``benchmarks/bench_truth_suites.py`` (4 per cell); a test that reads
one of them reconciles that case alone (:func:`case_run`)."""

from __future__ import annotations

import fcntl
import functools
import os
import pickle
import sys
import tempfile
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))

import bench_truth_suites as bench  # noqa: E402

SUITES = sorted((ROOT / "truths").glob("truth_*.py"))
SEED, PER_CELL = 11, 1
HELD_OUT = "r"
DEVELOPMENT_CATEGORIES = ("clean", "decoy_separable")


@functools.lru_cache(maxsize=None)
def suite_cases(path: Path, seed: int = SEED, per_cell: int = PER_CELL) -> list:
    """The cases of the suite at ``path`` (generating a suite takes up to half a minute, so
    the workers share them as they share the reconciled sample)."""
    return _shared(path, f"{path.stem}-cases-{seed}-{per_cell}", lambda: suite_module(
        path).generate_cases(seed, bench.CATALOG_DIR, per_cell))


@functools.lru_cache(maxsize=None)
def suite_module(path: Path):
    """The suite's module, loaded once per process: its cases' classes must stay the ones
    the cases were made with, for the workers to pickle them."""
    return bench.load_suite(path)


def suite_path(suite: str) -> Path:
    return ROOT / "truths" / f"truth_{suite}.py"


def named_case(suite: str, name: str, seed: int, per_cell: int = 2):
    """The case called ``name`` in suite ``suite`` (b … g) drawn at ``seed``, ``per_cell``."""
    return next(c for c in suite_cases(suite_path(suite), seed, per_cell) if c.name == name)


@functools.lru_cache(maxsize=None)
def suite_runs(path: Path) -> tuple[list, list[dict]]:
    """(cases, reconcile results) of the suite at ``path``, in the suite's order."""
    return _shared(path, path.stem, lambda: _reconcile_suite(path))


def _shared(path: Path, stem: str, compute):
    """``compute()``, shared by the workers of a ``pytest -n`` run through the file
    ``stem``.pickle: the first to need it computes it while the others wait for the file.
    ``path`` is the suite whose module defines the cases' classes."""
    run = os.environ.get("PYTEST_XDIST_TESTRUNUID")
    if not run:
        return compute()
    folder = shared_folder(run)
    folder.mkdir(exist_ok=True)
    stored = folder / f"{stem}.pickle"
    with open(folder / f"{stem}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # held while one worker computes it
        if not stored.exists():
            value = compute()
            staged = stored.with_suffix(".partial")
            staged.write_bytes(pickle.dumps(value))
            staged.replace(stored)
            return value
    suite_module(path)  # the cases' classes live in the suite's module
    return pickle.loads(stored.read_bytes())


def shared_folder(run: str) -> Path:
    """Where the workers of the test run ``run`` share the samples, the generated cases
    and the cases reconciled alone."""
    return Path(tempfile.gettempdir()) / f"hdcad-truth-sample-{run}"


def sampled(path: Path) -> list:
    """The cases of the suite at ``path`` in the shared sample (the module docstring)."""
    cases = suite_cases(path)
    if path == suite_path(HELD_OUT):
        return cases
    return [c for c in cases if c.category in DEVELOPMENT_CATEGORIES]


def _reconcile_suite(path: Path) -> tuple[list, list[dict]]:
    cases = sampled(path)
    jobs = list(enumerate(cases))
    with ProcessPoolExecutor(2) as pool:
        results = dict(pool.map(bench._run, jobs, chunksize=4))
    return cases, [results[i] for i in range(len(cases))]


def case_run(suite: str, name: str) -> tuple[object, dict]:
    """(case, result) of the case called ``name`` in suite ``suite`` (b … o) at the sample's
    seed: from the shared sample when it holds the case, else reconciled alone."""
    path = suite_path(suite)
    if any(c.name == name for c in sampled(path)):
        cases, results = suite_runs(path)
        index = next(i for i, c in enumerate(cases) if c.name == name)
        return cases[index], results[index]
    return _case_alone(suite, name)


@functools.lru_cache(maxsize=None)
def _case_alone(suite: str, name: str) -> tuple[object, dict]:
    path = suite_path(suite)
    case = next(c for c in suite_cases(path) if c.name == name)
    return case, _shared(path, f"{path.stem}-alone-{name}", lambda: bench.reconcile_case(case))
