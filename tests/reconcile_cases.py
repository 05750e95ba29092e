"""One hidden-effect case: generate it with the truth simulator, reconcile it once.

Shared by the proof tests and ``benchmarks/bench_reconcile.py``. Kept apart from
``reconcile_truth`` because the simulator must not import ``hdcad.reconcile``.
"""

from __future__ import annotations

from concurrent.futures import ProcessPoolExecutor

import reconcile_truth as truth
from hdcad.models import resolve
from hdcad.reconcile import reconcile, validate_data


_DONE: dict[tuple, dict] = {}
JOBS = 2   # worker processes for a batch of cases (the fits are single-threaded)


def run_cases(kind: str, effects: tuple[str, ...], seeds) -> list[dict]:
    """``run_case`` for many seeds, the ones not yet run in ``JOBS`` worker processes."""
    seeds = list(seeds)
    missing = [s for s in seeds if (kind, effects, s) not in _DONE]
    if len(missing) > 1:
        with ProcessPoolExecutor(JOBS) as pool:
            for seed, out in zip(missing, pool.map(_case, [(kind, effects, s)
                                                           for s in missing])):
                _DONE[(kind, effects, seed)] = out
    return [run_case(kind, effects, s) for s in seeds]


def _case(args) -> dict:
    return _reconcile(*args)


def run_case(kind: str, effects: tuple[str, ...], seed: int) -> dict:
    """Generate one case, reconcile it once per session; truth, result (``as_dict``) and
    the names."""
    key = (kind, effects, seed)
    if key not in _DONE:
        _DONE[key] = _reconcile(kind, effects, seed)
    return _DONE[key]


def _reconcile(kind: str, effects: tuple[str, ...], seed: int) -> dict:
    code = truth.proof_model(kind, effects, seed)
    data, hidden = truth.make_case(kind, code, effects, seed)
    catalog = truth.default_catalog()
    result = reconcile(kind, validate_data(kind, data), resolve(code, catalog), catalog,
                       load_inertia_kgm2=hidden.get("load_inertia_kgm2")).as_dict()
    return {"truth": hidden, "result": result, "named": tuple(result["missing_effects"]),
            "seed": seed, "model": code}
