"""Time `hdcad design` for one model per family; print a table.

Run: python benchmarks/bench_design.py   (needs the cad extra: cadquery)
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

MODELS = ("FD-25-80-2", "FD-25-80-0", "CSF-45-120-GH", "CSG-65-100-GH")


def main(repeat: int = 3) -> None:
    catalog = load_catalog()
    duty = load_duty(examples_dir() / "duty_seed_example.yaml")
    print(f"{'model':16s} {'parts':>5s} {'median [s]':>11s} {'files [kB]':>11s}")
    for code in MODELS:
        samples, size, parts = [], 0, 0
        for _ in range(repeat):
            with tempfile.TemporaryDirectory() as tmp:
                start = time.perf_counter()
                result = run_design(resolve(code, catalog), duty, DesignOptions(), catalog,
                                    Path(tmp))
                samples.append(time.perf_counter() - start)
                size = sum(p.stat().st_size for p in result.folder.iterdir()) // 1024
                parts = len(result.masses_kg)
        print(f"{code:16s} {parts:5d} {statistics.median(samples):11.2f} {size:11d}")


if __name__ == "__main__":
    main()
