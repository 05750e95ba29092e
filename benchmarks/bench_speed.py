"""Speed of a design packet against its floor, as fresh processes; prints a table and the ratio.

The floor (floor_design.py) does the same kind of work the shortest way: import cadquery,
matplotlib and WeasyPrint, one flanged part to STEP and STL, three SVG plots, a ten-page PDF
of tables. `hdcad design CSF-45-120-GH` on the shipped example is timed against it, the two
in turn (A B A B …) so that a drift of the machine's speed hits both; the ratio is taken pair
by pair and its median printed. Target: ratio ≤ 1.3.

Run: python benchmarks/bench_speed.py [RUNS]
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
MODEL = "CSF-45-120-GH"


def _wall(cmd: list[str]) -> float:
    start = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def main(runs: int = 5) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        design = [sys.executable, "-m", "hdcad.cli", "design", MODEL, "--duty",
                  str(ROOT / "examples" / "duty_seed_example.yaml"), "--out", f"{tmp}/d"]
        floor = [sys.executable, str(ROOT / "benchmarks" / "floor_design.py"), f"{tmp}/f"]
        _wall(design), _wall(floor)  # warm-up: disk caches, compiled bytecode
        pairs = [(_wall(design), _wall(floor)) for _ in range(runs)]
    a, b = zip(*pairs)
    ratios = [x / y for x, y in pairs]
    print(f"{'command':34s} {'min [s]':>8s} {'median [s]':>10s} {'max [s]':>8s}")
    for name, times in ((f"hdcad design {MODEL}", a), ("floor (floor_design.py)", b)):
        print(f"{name:34s} {min(times):8.2f} {statistics.median(times):10.2f} {max(times):8.2f}")
    print(f"{'ratio design / floor':34s} {min(ratios):8.3f} {statistics.median(ratios):10.3f} "
          f"{max(ratios):8.3f}   (target ≤ 1.3)")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 5)
