"""Score `hdcad reconcile` on independently written truth suites (``truths/truth_*.py``).

Each suite was written from ``truths/CONTRACT.md`` and the physics literature without reading
``hdcad/reconcile``; this script only runs it and compares what reconcile names with what the
suite hid. Prints per suite and per kind the confusion matrix (rows: hidden gear effects or
the category, columns: effects named) and the acceptance figures:

- single: hidden effect named first;  pair: both named; or-read: both named, or the one
  not named given as a reading the data cannot tell from the one named (a housing spring
  that the stiffness scale takes within its spread, or that a loop in series with the gear
  takes as its own slip compliance, reported beside it);
- false alarm: a gear effect named on a clean or separable-decoy case;
- wrong second name: a correctly named single effect followed by another name;
- rmse_after / noise_rms on correctly named cases (share ≤ 1.2);  median gap shrink;
- equivalent decoys: reported with both readings (the effect and the nuisance);
- measurement effects named as such (rig findings) on separable decoys;
- exact: the gear effects named are the hidden ones, no more and no fewer (clean, single,
  pair and separable-decoy cases): the figure that a method naming every effect at once
  cannot win by naming more;
- misses, by why (:func:`miss_kind`): given as a reading, left undecided between two, a
  tie the data cannot break, a form the effect families lack, or a set that fits better
  turned down by a rule.

Run: python benchmarks/bench_truth_suites.py [--suite truths/truth_b.py ...] [--per-cell 4]
     [--seed 7] [--jobs 2] [--kind torsion] [--sindy]

``--sindy`` scores PySINDy's STLSQ over the same residual library beside reconcile
(``benchmarks/sindy_baseline.py``; ``pip install -e ".[bench]"``).
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import statistics
import sys
from collections import defaultdict
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

# one BLAS thread per worker: the fits' matrices are small and the workers fill the cores
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
CATALOG_DIR = ROOT / "catalog"
RMSE_FACTOR = 1.2
# A suite's own name for a measurement effect that hdcad names otherwise (the same physics):
# suite H calls the twist encoder's interpolation ripple "encoder_interpolation_error", suite
# O the output encoder's "interpolation_error" and the motor's cogging "motor_cogging".
RIG_SYNONYMS = {"encoder_interpolation_error": "encoder_interpolation",
                "interpolation_error": "encoder_interpolation",
                "motor_cogging": "drive_ripple"}
# our measurement effects that are a case of a truth's: a drift that restarts at each block
# is a thermal drift
RIG_CASE_OF = {"block_drift": "thermal_drift"}


def load_suite(path: Path):
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[path.stem] = module
    spec.loader.exec_module(module)
    return module


def reconcile_case(case) -> dict:
    """Reconcile one truth case in-process; the JSON result plus the report's extra keys."""
    from hdcad.catalog import load_catalog
    from hdcad.models import resolve_gear
    from hdcad.reconcile import reconcile, validate_data

    catalog = load_catalog()
    try:  # the model as the command line reads it
        found = reconcile(case.kind, validate_data(case.kind, case.columns),
                          resolve_gear(case.model, catalog)[0], catalog,
                          load_inertia_kgm2=case.load_inertia_kgm2)
        result = found.as_dict()
        # the gear round of the search: each set's ΔBIC over the model it was added to
        result["gear_candidates"] = [(row["effect"].split("+"), row["delta_bic"])
                                     for row in (found.candidates[-1] if found.candidates
                                                 else [])]
    except Exception as exc:  # a refusal (e.g. wrong units) is a result, not a crash
        result = {"error": f"{type(exc).__name__}: {exc}", "missing_effects": [],
                  "rmse_before": np.nan, "rmse_after": np.nan}
    return result


def _run(args):
    """(index, result) of one case; the case travels to the worker (generating a suite
    again in every worker costs as much as reconciling it)."""
    index, case, *method = args
    if method == ["sindy"]:
        from sindy_baseline import sindy_case
        return index, sindy_case(case)
    return index, reconcile_case(case)


def score(case, result) -> dict:
    named = list(result.get("missing_effects", []))
    rig = [RIG_CASE_OF.get(m["effect"], m["effect"])
           for m in result.get("measurement_effects", [])]
    readings = {e for r in result.get("equivalent_readings", []) for e in r.get("effects", [])}
    hidden = tuple(case.gear_effects)
    out = {"named": named, "rig": rig, "category": case.category, "kind": case.kind,
           "hidden": hidden, "error": result.get("error")}
    before, after = result.get("rmse_before", np.nan), result.get("rmse_after", np.nan)
    if case.category == "single":
        out["first_right"] = bool(named) and named[0] == hidden[0]
        out["wrong_second"] = out["first_right"] and len(named) > 1
    if case.category == "pair":
        out["both"] = set(hidden) <= set(named)
        # or the one not named given as a reading the data cannot tell from the one named:
        # a nuisance's (a housing spring inside the stiffness scale's spread) or a loop's
        # in series (a loop beside a spring of its own slip compliance)
        readings_ = result.get("equivalent_readings", [])
        read = ({e for r in readings_ if r.get("nuisance") for e in r.get("effects", [])}
                | {e for r in readings_ if r.get("reading") == "series_slip"
                   for e in r.get("alternative", [])})
        out["both_or_read"] = set(hidden) <= set(named) | read
    if case.category in ("clean", "decoy_separable"):
        out["false_alarm"] = bool(named)
    if case.category == "decoy_separable" and case.measurement_effects:
        expected = {RIG_SYNONYMS.get(e, e) for e in case.measurement_effects}
        out["rig_right"] = expected <= set(rig)
        # or named as one the report says reads the same on this record (another rig
        # effect over an arc of the output; a gain the nuisance's scale or level takes)
        alike = {RIG_CASE_OF.get(a, a)
                 for m in result.get("measurement_effects", []) + result.get("nuisances", [])
                 for a in m.get("reads_as", [])}
        out["rig_or_read"] = expected <= set(rig) | alike
    if out.get("first_right") is False or out.get("wrong_second") or out.get("both") is False:
        out["miss"] = miss_kind(out, result)
    if case.category == "decoy_equivalent":
        eq = set(case.equivalent_effects)
        out["both_readings"] = bool(eq & (set(named) | readings)) and (
            bool(readings) or not named)
    if case.category in ("clean", "single", "pair", "decoy_separable"):
        out["exact"] = set(named) == set(hidden)
    if case.category in ("single", "pair") and set(hidden) <= set(named):
        out["ratio"] = after / case.noise_rms if case.noise_rms else np.nan
        out["shrink"] = 1 - after / before if before else np.nan
    return out


def miss_kind(row: dict, result: dict) -> str:
    """Why a single or a pair was missed, from the search's gear candidates (the loops in
    their parametric forms, before the named model's final form):

    - ``read``: a pair whose member not named is given as a reading of the one named, or
      the hidden set given whole as the other reading of the named one (a loop that
      carries its own compliance, in place of a loop and a spring; a play held by friction
      in place of a loop);
    - ``undecided``: the member not named is one of two the report says fit about equally
      beside the one named;
    - ``tie``: the hidden set's ΔBIC within ``BIC_MIN`` of the named set's, the margin an
      effect is named at: the data prefer neither;
    - ``named fits``: the named set fits better by more: the hidden effect, in the forms the
      search fits it in, leaves what the extra name takes (a form the families lack);
    - ``hidden fits``: the hidden set fits better by more and a rule turned it down;
    - ``?``: a set not in the candidate table (a rig effect named with it, or no table)."""
    from hdcad.reconcile.gates import BIC_MIN

    alone = {frozenset(r["alternative"]) for r in result.get("equivalent_readings", [])
             if r.get("reading") in ("loop_in_series", "held_play")}
    if row.get("both_or_read") or frozenset(row["hidden"]) in alone:
        return "read"
    rivals = {e for r in result.get("equivalent_readings", []) for e in r.get("undecided", [])}
    unnamed = set(row["hidden"]) - set(row["named"])
    if unnamed and unnamed <= rivals:
        return "undecided"
    table = {frozenset(effects): gain for effects, gain in result.get("gear_candidates", [])}
    hidden, named = frozenset(row["hidden"]), frozenset(row["named"])
    if hidden not in table or (named and named not in table):
        return "?"
    margin = table[hidden] - (table[named] if named else 0.0)
    return "tie" if abs(margin) <= BIC_MIN else ("hidden fits" if margin > 0 else "named fits")


MISS_KINDS = ("read", "undecided", "tie", "named fits", "hidden fits", "?")


def _share(rows, key):
    vals = [r[key] for r in rows if key in r]
    return (sum(vals) / len(vals), len(vals)) if vals else (np.nan, 0)


def summary(rows: list[dict], label: str) -> None:
    def fmt(key, invert=False):
        share, n = _share(rows, key)
        return f"{share:6.1%} of {n:3d}" if n else "     -      "
    ratios = [r["ratio"] for r in rows if "ratio" in r and np.isfinite(r["ratio"])]
    shrinks = [r["shrink"] for r in rows if "shrink" in r and np.isfinite(r["shrink"])]
    ok_ratio = sum(x <= RMSE_FACTOR for x in ratios) / len(ratios) if ratios else np.nan
    print(f"{label:16s} single-first {fmt('first_right')} | pair-both {fmt('both')} | "
          f"or-read {fmt('both_or_read')} | false-alarm {fmt('false_alarm')} | "
          f"wrong-2nd {fmt('wrong_second')} | "
          f"exact {fmt('exact')} | rig-named {fmt('rig_right')} (or read {fmt('rig_or_read')}) | equiv-both {fmt('both_readings')} | "
          f"rmse≤1.2σ {ok_ratio:6.1%} (median {statistics.median(ratios) if ratios else np.nan:.2f}) | "
          f"shrink {statistics.median(shrinks) if shrinks else np.nan:6.1%}")
    misses = [r["miss"] for r in rows if "miss" in r]
    if misses:
        print(f"{'':16s} misses {len(misses)}: " + ", ".join(
            f"{k} {misses.count(k)}" for k in MISS_KINDS if k in misses))


def confusion(rows: list[dict], kind: str) -> None:
    mine = [r for r in rows if r["kind"] == kind]
    effects = sorted({e for r in mine for e in r["named"]} | {e for r in mine for e in r["hidden"]})
    groups = defaultdict(list)
    for r in mine:
        groups["+".join(r["hidden"]) or f"({r['category']})"].append(r)
    width = max([len(e) for e in effects] + [8]) + 1
    print(f"\n  {kind}: rows = hidden, cells = cases naming the effect")
    print(f"  {'hidden':34s}{'n':>4s}" + "".join(f"{e:>{width}s}" for e in effects)
          + f"{'(none)':>{width}s}")
    for key in sorted(groups):
        g = groups[key]
        cells = [sum(e in r["named"] for r in g) for e in effects] + [sum(not r["named"] for r in g)]
        print(f"  {key:34s}{len(g):4d}" + "".join(f"{c:{width}d}" for c in cells))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--suite", action="append", type=Path)
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--per-cell", type=int, default=4)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--kind", action="append")
    parser.add_argument("--category", action="append")
    parser.add_argument("--verbose", action="store_true", help="print every miss")
    parser.add_argument("--sindy", action="store_true",
                        help="also score PySINDy STLSQ over the same residual library "
                             "(benchmarks/sindy_baseline.py; needs pip install pysindy)")
    args = parser.parse_args()
    suites = args.suite or sorted((ROOT / "truths").glob("truth_*.py"))
    for path in suites:
        cases = load_suite(path).generate_cases(args.seed, CATALOG_DIR, args.per_cell)
        chosen = [i for i, c in enumerate(cases)
                  if (not args.kind or c.kind in args.kind)
                  and (not args.category or c.category in args.category)]
        jobs = [(i, cases[i]) for i in chosen]
        with ProcessPoolExecutor(args.jobs) as pool:
            results = dict(pool.map(_run, jobs, chunksize=4))
        rows = [score(cases[i], results[i]) for i in chosen]
        print(f"\n=== suite {path.stem}: {len(rows)} cases, seed {args.seed} ===")
        summary(rows, "all")
        for kind in sorted({r["kind"] for r in rows}):
            summary([r for r in rows if r["kind"] == kind], kind)
        if args.sindy:
            with ProcessPoolExecutor(args.jobs) as pool:
                plain = dict(pool.map(_run, [j + ("sindy",) for j in jobs], chunksize=4))
            side = [score(cases[i], plain[i]) for i in chosen]
            print("  side by side: PySINDy STLSQ over the same residual library")
            summary(side, "sindy all")
            for kind in sorted({r["kind"] for r in side}):
                summary([r for r in side if r["kind"] == kind], f"sindy {kind}")
        for kind in sorted({r["kind"] for r in rows}):
            confusion(rows, kind)
        if args.verbose:
            for i, r in zip(chosen, rows):
                bad = (r.get("first_right") is False or r.get("both") is False
                       or r.get("false_alarm") or r.get("wrong_second") or r.get("error")
                       or r.get("ratio", 0) > RMSE_FACTOR)
                if bad:
                    c = cases[i]
                    ratio = f"rmse {r['ratio']:.2f}σ" if "ratio" in r else ""
                    print(f"  MISS {c.name}: hidden {r['hidden']} rig {c.measurement_effects} "
                          f"nuis {c.nuisance} → named {r['named']} rig {r['rig']} {ratio} "
                          f"{r['error'] or ''}")


if __name__ == "__main__":
    main()
