"""Time `hdcad check` and `hdcad select` over the whole catalog; print a table.

Run: python benchmarks/bench_checks.py
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import time

from hdcad.catalog import load_catalog
from hdcad.checks.run import run_checks
from hdcad.duty import load_duty
from hdcad.models import list_models, resolve
from hdcad.resources import examples_dir
from hdcad.selection import select

DUTY = examples_dir() / "duty_seed_example.yaml"


def timed(func, repeat: int = 5) -> float:
    samples = []
    for _ in range(repeat):
        start = time.perf_counter()
        func()
        samples.append(time.perf_counter() - start)
    return statistics.median(samples)


def main() -> None:
    catalog = load_catalog()
    duty = load_duty(DUTY)
    codes = list_models(catalog)
    rows = [
        ("load catalog (cached tables + overlay merge)", timed(load_catalog), 1),
        ("check, one model (in process)",
         timed(lambda: run_checks(resolve("CSF-45-120-GH", catalog), duty, catalog)), 1),
        ("check, every model (in process)",
         timed(lambda: [run_checks(resolve(c, catalog), duty, catalog) for c in codes]),
         len(codes)),
        ("select, whole catalog (in process)", timed(lambda: select(duty, catalog)), len(codes)),
    ]
    for label, args in (("`hdcad check` command (new process)",
                         ["check", "CSF-45-120-GH", "--duty", str(DUTY)]),
                        ("`hdcad select` command (new process)", ["select", "--duty", str(DUTY)])):
        rows.append((label, timed(lambda: subprocess.run(
            [sys.executable, "-m", "hdcad", *args], capture_output=True), repeat=3), 1))
    print(f"{'operation':45s} {'models':>7s} {'median [ms]':>12s} {'per model [ms]':>15s}")
    for label, seconds, n in rows:
        print(f"{label:45s} {n:7d} {seconds * 1e3:12.1f} {seconds * 1e3 / n:15.2f}")


if __name__ == "__main__":
    main()
