"""How reconcile picks between readings: an ambiguous second effect is left unnamed, and a
hysteresis + housing spring pair that reads the same as one slip element in series says so.

The Preisach cases come from suite C (``truths/truth_c.py``), written by a helper from the
contract only: a weighted sum of relays (Mayergoyz 1986) whose output adds to the gear's
twist, so the loop carries its own slip compliance. Friction in parallel (Bouc–Wen) plus a
spring of compliance z_sat/T_s is term for term that series element; reconcile fits the pair
with a spring equal to the loop's z_sat/T_s (to 2 %, seed 7), so both readings are reported.
The Bouc–Wen + housing pair of suite B (``truths/truth_b.py``) has a spring of its own: no
series reading.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from hdcad.reconcile.search import Candidate, Gate, _unless_ambiguous, ambiguous_second

ROOT = Path(__file__).resolve().parents[1]


def _cand(effects, dbic, passes=True):
    return Candidate(tuple(effects), fit=None, gate=Gate(dbic, 0.5, 10.0, 0.9), passes=passes)


def test_a_second_that_a_rival_explains_about_as_well_is_not_named():
    single = _cand(["hysteresis"], 800.0)
    best = _cand(["hysteresis", "housing_compliance"], 1000.0)
    rival = _cand(["hysteresis", "backlash"], 960.0)         # within 5 % of the best
    passing = [single, best, rival]
    assert ambiguous_second(best, passing) == ("hysteresis", ("housing_compliance",
                                                              "backlash"))
    chosen = _unless_ambiguous(best, passing)
    assert chosen.effects == ("hysteresis",)
    assert chosen.undecided == ("housing_compliance", "backlash")


def test_a_clearly_better_second_or_a_failing_rival_keeps_the_pair():
    single = _cand(["hysteresis"], 800.0)
    best = _cand(["hysteresis", "housing_compliance"], 1000.0)
    for rival in (_cand(["hysteresis", "backlash"], 900.0),):   # 10 % below: decided
        assert _unless_ambiguous(best, [single, best, rival]) is best
    # a rival pair that does not pass its gates is not in the passing list
    assert _unless_ambiguous(best, [single, best]) is best
    # the shared member must pass alone to fall back to it
    rival = _cand(["hysteresis", "backlash"], 990.0)
    assert _unless_ambiguous(best, [best, rival]) is best


def _cases(suite: str, category: str, word: str, seed: int = 7):
    sys.path.insert(0, str(ROOT / "benchmarks"))
    import bench_truth_suites as bench
    cases = bench.load_suite(ROOT / "truths" / f"truth_{suite}.py").generate_cases(
        seed, bench.CATALOG_DIR, 2)
    return bench, [c for c in cases if c.kind == "torsion" and c.category == category
                   and word in c.name]


def _series_reading(result) -> bool:
    return any(r.get("reading") == "series_slip" for r in result["equivalent_readings"])


@pytest.mark.parametrize("index", [0, 1])
def test_preisach_loop_is_reported_with_its_series_slip_reading(index):
    bench, cases = _cases("c", "single", "preisach")
    assert len(cases) == 2
    result = bench.reconcile_case(cases[index])
    assert result["missing_effects"][0] == "hysteresis"
    if "housing_compliance" in result["missing_effects"]:
        assert _series_reading(result)
    assert result["rmse_after"] <= 1.2 * cases[index].noise_rms


def test_a_housing_spring_of_its_own_gets_no_series_reading():
    bench, cases = _cases("b", "pair", "hysteresis+housing_compliance")
    result = bench.reconcile_case(cases[0])
    assert set(result["missing_effects"]) == {"hysteresis", "housing_compliance"}
    assert not _series_reading(result)
