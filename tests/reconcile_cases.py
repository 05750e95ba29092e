"""One hidden-effect case: generate it with the truth simulator, reconcile it once.

Shared by the proof tests and ``benchmarks/bench_reconcile.py``. Kept apart from
``reconcile_truth`` because the simulator must not import ``hdcad.reconcile``.
"""

from __future__ import annotations

from functools import lru_cache

import reconcile_truth as truth
from hdcad.models import resolve
from hdcad.reconcile import reconcile, validate_data


@lru_cache(maxsize=None)
def run_case(kind: str, effects: tuple[str, ...], seed: int) -> dict:
    """Generate one case, reconcile it once; truth, result (``as_dict``) and the names."""
    code = truth.proof_model(kind, effects, seed)
    data, hidden = truth.make_case(kind, code, effects, seed)
    catalog = truth.default_catalog()
    result = reconcile(kind, validate_data(kind, data), resolve(code, catalog), catalog,
                       load_inertia_kgm2=hidden.get("load_inertia_kgm2")).as_dict()
    return {"truth": hidden, "result": result, "named": tuple(result["missing_effects"]),
            "seed": seed, "model": code}
