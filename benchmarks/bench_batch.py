"""Batch packets: `hdcad select --design-top 4` against the same four `hdcad design` runs
one after another, as fresh processes; prints a table and the ratio (target ≤ 0.6 on two
cores).

The four candidates are the seed example duty's four smallest passing models; the 2A-GR
housing among them needs outline tables the seeds lack, so both runs take the invented test
overlay (tests/data/overlay_2a_gr_TEST_DATA_NOT_CATALOG.yaml) and build all four.

Run: python benchmarks/bench_batch.py [RUNS]
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DUTY = str(ROOT / "examples" / "duty_seed_example.yaml")
OVERLAY = str(ROOT / "tests" / "data" / "overlay_2a_gr_TEST_DATA_NOT_CATALOG.yaml")
N = 4


def _hdcad(*args: str) -> str:
    done = subprocess.run([sys.executable, "-m", "hdcad.cli", *args, "--catalog-overlay",
                           OVERLAY], capture_output=True, text=True)
    if done.returncode not in (0, 1):
        raise SystemExit(f"hdcad {' '.join(args)} failed: {done.stderr.strip()}")
    return done.stdout


def candidates() -> list[str]:
    rows = [line.split() for line in _hdcad("select", "--duty", DUTY).splitlines()]
    return [r[0] for r in rows if len(r) > 1 and r[1] == "PASS"][:N]


def _timed(fn) -> float:
    start = time.perf_counter()
    fn()
    return time.perf_counter() - start


def main(runs: int = 3) -> None:
    codes = candidates()
    seq, par = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(runs):
            seq.append(_timed(lambda: [_hdcad("design", c, "--duty", DUTY, "--out",
                                              f"{tmp}/s{i}") for c in codes]))
            par.append(_timed(lambda: _hdcad("select", "--duty", DUTY, "--design-top", str(N),
                                             "--out", f"{tmp}/p{i}")))
        built = len([p for p in Path(f"{tmp}/p0").iterdir() if p.is_dir()])
    print(f"candidates: {', '.join(codes)} ({built} packets built per batch); "
          f"cores: {len(os.sched_getaffinity(0))}")
    print(f"{'run':44s} {'min [s]':>8s} {'median [s]':>10s} {'max [s]':>8s}")
    for name, t in ((f"{N} × hdcad design, one after another", seq),
                    (f"hdcad select --design-top {N} (process pool)", par)):
        print(f"{name:44s} {min(t):8.2f} {statistics.median(t):10.2f} {max(t):8.2f}")
    ratios = [p / s for p, s in zip(par, seq)]
    print(f"{'ratio batch / one after another':44s} {min(ratios):8.3f} "
          f"{statistics.median(ratios):10.3f} {max(ratios):8.3f}   (target ≤ 0.6)")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 3)
