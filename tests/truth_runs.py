"""The truth suites' sample (``truths/truth_*.py``, 1 case per cell, seed 11) reconciled once
per test session and shared by the tests that read it (``bench_truth_suites`` runs and
scores the same cases)."""

from __future__ import annotations

import functools
import sys
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))

import bench_truth_suites as bench  # noqa: E402

SUITES = sorted((ROOT / "truths").glob("truth_*.py"))
SEED, PER_CELL = 11, 1


@functools.lru_cache(maxsize=None)
def suite_cases(path: Path, seed: int = SEED, per_cell: int = PER_CELL) -> list:
    """The cases of the suite at ``path`` (generating one takes up to half a minute)."""
    return bench.load_suite(path).generate_cases(seed, bench.CATALOG_DIR, per_cell)


def suite_path(suite: str) -> Path:
    return ROOT / "truths" / f"truth_{suite}.py"


@functools.lru_cache(maxsize=None)
def suite_runs(path: Path) -> tuple[list, list[dict]]:
    """(cases, reconcile results) of the suite at ``path``, in the suite's order."""
    cases = suite_cases(path)
    jobs = list(enumerate(cases))
    with ProcessPoolExecutor(2) as pool:
        results = dict(pool.map(bench._run, jobs, chunksize=4))
    return cases, [results[i] for i in range(len(cases))]


def case_run(suite: str, name: str) -> tuple[object, dict]:
    """(case, result) of the case called ``name`` in suite ``suite`` (b, c, d, e)."""
    cases, results = suite_runs(suite_path(suite))
    index = next(i for i, c in enumerate(cases) if c.name == name)
    return cases[index], results[index]
