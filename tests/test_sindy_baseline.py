"""The side-by-side baseline of the truth-suite benchmark (PySINDy STLSQ over reconcile's
residual library) runs and behaves like a sparse regression: it names a strong hidden
effect and names nothing on clean data. The comparison itself is printed by
``benchmarks/bench_truth_suites.py --sindy``."""

from __future__ import annotations

import pytest

pytest.importorskip("pysindy")

from truth_runs import suite_cases, suite_path  # noqa: E402 (puts benchmarks/ on the path)
from sindy_baseline import sindy_case  # noqa: E402


@pytest.fixture(scope="module")
def cases():
    # suite B's cases at the shared sample's seed (11, 1 per cell; generating them takes 12 s)
    return suite_cases(suite_path("b"))


def test_strong_transmission_error_is_named(cases):
    te = [c for c in cases if c.kind == "transmission" and c.category == "single"]
    named = [sindy_case(c)["missing_effects"] for c in te]
    hits = sum(bool(n) and n[0] == c.gear_effects[0] for c, n in zip(te, named))
    assert hits >= len(te) // 2, named


def test_clean_data_gets_no_name(cases):
    clean = [c for c in cases if c.category == "clean"]
    results = [sindy_case(c) for c in clean]
    assert all(r["error"] is None for r in results)
    assert sum(bool(r["missing_effects"]) for r in results) <= 1
    assert all(r["rmse_after"] <= r["rmse_before"] + 1e-12 for r in results)
