"""Time `hdcad design` for one model per family; print a table.

Run: python benchmarks/bench_design.py   (needs the cad extra: cadquery, weasyprint)
The first run in a process also pays the imports (cadquery, matplotlib, WeasyPrint); the
median over the repeats is the steady-state time.
"""

from __future__ import annotations

import statistics
import tempfile
import time
from pathlib import Path

from hdcad.catalog import load_catalog
from hdcad.design import run_design
from hdcad.design_options import DesignOptions
from hdcad.duty import load_duty
from hdcad.models import resolve
from hdcad.resources import examples_dir

MODELS = ("FD-25-80-2", "FD-25-80-0", "CSF-45-120-GH", "CSG-65-100-GH", "CSF-40-120-2A-GR")
# the 2A-GR housing needs outline tables the seeds lack: the invented test overlay supplies them
TEST_OVERLAY = (Path(__file__).resolve().parent.parent / "tests" / "data" /
                "overlay_2a_gr_TEST_DATA_NOT_CATALOG.yaml")


def main(repeat: int = 3) -> None:
    catalog = load_catalog(TEST_OVERLAY)
    duty = load_duty(examples_dir() / "duty_seed_example.yaml")
    stages = ("checks", "build", "geometric checks", "export", "drawings", "calc sheet")
    print(f"{'model':16s} {'parts':>5s} {'total [s]':>9s} " +
          " ".join(f"{s:>16s}" for s in stages) + f" {'files [kB]':>10s}")
    for code in MODELS:
        samples, laps, size, parts = [], [], 0, 0
        for _ in range(repeat):
            with tempfile.TemporaryDirectory() as tmp:
                start = time.perf_counter()
                result = run_design(resolve(code, catalog), duty, DesignOptions(), catalog,
                                    Path(tmp))
                samples.append(time.perf_counter() - start)
                laps.append(result.timings_s)
                size = sum(p.stat().st_size for p in result.folder.rglob("*")) // 1024
                parts = len(result.masses_kg)
        stage_medians = [statistics.median(l[s] for l in laps) for s in stages]
        print(f"{code:16s} {parts:5d} {statistics.median(samples):9.2f} " +
              " ".join(f"{t:16.2f}" for t in stage_medians) + f" {size:10d}")


if __name__ == "__main__":
    main()
