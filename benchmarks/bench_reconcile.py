"""Confusion matrix of `hdcad reconcile` on hidden-effect data, and its time on 100,000 rows.

Data come from the independent truth simulator ``tests/reconcile_truth.py``. Seeds start at
1000, so these cases are not the ones the proof tests (seeds 0…19) use. Prints plain-text
tables: per kind, rows = hidden effect(s) (``none`` and the pairs included), columns = how
often each effect was named; then identification rate, median RMSE reduction, share of
cases with reconciled RMSE ≤ 1.15 × noise RMS; then the wall time of ``read_data`` +
``reconcile`` on a 100,000-row CSV per kind.

Run: python benchmarks/bench_reconcile.py [--cases N] [--rows N] [--no-timing]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import reconcile_truth as truth  # noqa: E402
from reconcile_cases import run_case  # noqa: E402
from hdcad.models import resolve  # noqa: E402
from hdcad.reconcile import COLUMNS, KINDS, read_data, reconcile  # noqa: E402

FIRST_SEED = 1000     # out of the proof tests' seed range
RMSE_FACTOR = 1.15    # issue: reconciled RMSE within 15 % of the noise RMS
VIBRATION_PAIR = ("vibration", ("te_1x", "te_2x"))   # shown here only, not in the tests


def scenarios(kind: str) -> list[tuple[str, ...]]:
    rows = [()] + [e for k, e in truth.SINGLE_SCENARIOS if k == kind]
    rows += [e for k, e in truth.COMBO_SCENARIOS + [VIBRATION_PAIR] if k == kind]
    return rows


def run(kind: str, effects: tuple[str, ...], seed: int) -> dict:
    case = run_case(kind, effects, seed)
    result = case["result"]
    return {"named": case["named"], "before": result["rmse_before"],
            "after": result["rmse_after"], "noise": case["truth"]["noise_rms"]}


def confusion(kind: str, cases: int) -> None:
    rows = scenarios(kind)
    columns = sorted({e for r in rows for e in r})
    results = {r: [run(kind, r, FIRST_SEED + s) for s in range(cases)] for r in rows}
    others = ["other"] if any(set(x["named"]) - set(columns)
                              for rs in results.values() for x in rs) else []
    labels = columns + others + ["(nothing)"]
    width = max(len(c) for c in labels) + 2
    head = f"{'hidden':28s}" + "".join(f"{c:>{width}s}" for c in labels)
    print(f"\n{kind}: {cases} cases per row; cells = cases in which the effect was named")
    print(head + f"{'exact':>8s}{'med.gain':>10s}{'≤1.15σ':>8s}")
    for hidden, res in results.items():
        counts = [sum(c in x["named"] for x in res) for c in columns]
        counts += [sum(bool(set(x["named"]) - set(columns)) for x in res)] if others else []
        counts += [sum(not x["named"] for x in res)]
        exact = sum(set(x["named"]) == set(hidden) for x in res) / len(res)
        gains = [1 - x["after"] / x["before"] for x in res if set(hidden) <= set(x["named"])]
        gain = f"{statistics.median(gains):.0%}" if hidden and gains else "-"
        close = sum(x["after"] <= RMSE_FACTOR * x["noise"] for x in res) / len(res)
        label = "+".join(hidden) or "none"
        print(f"{label:28s}" + "".join(f"{n:{width}d}" for n in counts)
              + f"{exact:8.0%}{gain:>10s}{close:8.0%}")


def write_csv(path: Path, kind: str, data: dict) -> None:
    table = np.column_stack([data[c] for c in COLUMNS[kind]])
    np.savetxt(path, table, delimiter=",", header=",".join(COLUMNS[kind]), comments="",
               fmt="%.17g")


def timing(rows: int) -> None:
    print(f"\nwall time on a {rows:,}-row CSV (one effect hidden, first seed)")
    print(f"{'kind':14s}{'effect':22s}{'generate [s]':>14s}{'read_data [s]':>15s}"
          f"{'reconcile [s]':>15s}{'named':>30s}")
    catalog = truth.default_catalog()
    with tempfile.TemporaryDirectory() as folder:
        for kind in KINDS:
            effect = truth.NOISE_REFERENCE[kind][0]
            code = truth.proof_model(kind, (effect,), 0)
            start = time.perf_counter()
            data, hidden = truth.make_case(kind, code, (effect,), FIRST_SEED, rows=rows)
            generated = time.perf_counter() - start
            path = Path(folder) / f"{kind}.csv"
            write_csv(path, kind, data)
            start = time.perf_counter()
            loaded = read_data(kind, path)
            read = time.perf_counter() - start
            start = time.perf_counter()
            result = reconcile(kind, loaded, resolve(code, catalog), catalog,
                               load_inertia_kgm2=hidden.get("load_inertia_kgm2"))
            spent = time.perf_counter() - start
            named = ",".join(result.as_dict()["missing_effects"]) or "(nothing)"
            print(f"{kind:14s}{effect:22s}{generated:14.2f}{read:15.2f}{spent:15.2f}"
                  f"{named:>30s}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=int, default=20, help="cases per hidden scenario")
    parser.add_argument("--rows", type=int, default=100_000, help="rows of the timing file")
    parser.add_argument("--no-timing", action="store_true")
    args = parser.parse_args()
    for kind in KINDS:
        confusion(kind, args.cases)
    if not args.no_timing:
        timing(args.rows)


if __name__ == "__main__":
    main()
