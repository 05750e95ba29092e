"""Design packets of several candidates at once, and an index page comparing them.

Each packet is one job, ``design_packet``, a plain function of picklable arguments that
returns a small summary dict: the jobs run through any ``concurrent.futures.Executor``: a
local process pool (one worker per core by default) or, given a scheduler address, a Dask
``distributed`` cluster. Inside a job the design runs its stages one after another: the batch
is already parallel across jobs, and Dask workers may not start processes of their own.
A job that fails (bad data for that model) is reported in the index; the others go on.
"""

from __future__ import annotations

import time
from concurrent.futures import Executor, as_completed
from pathlib import Path
from typing import Callable

from .catalog import Catalog
from .design_options import DesignOptions
from .duty import Duty
from .errors import InputError

# checks whose margins the index compares side by side (when evaluated)
INDEX_CHECKS = ("avg_torque", "peak_torque", "momentary_torque", "max_input_speed", "wg_life")


def design_packet(code: str, duty: Duty, options: DesignOptions, catalog: Catalog,
                  out_dir: str, force: bool = False) -> dict:
    """Build the packet ``out_dir/code/`` and return its summary (see ``packet_summary``)."""
    from .design import run_design
    from .models import resolve
    start = time.perf_counter()
    try:
        result = run_design(resolve(code, catalog), duty, options, catalog, Path(out_dir),
                            force=force)
    except InputError as error:
        return {"model": code, "built": False, "error": str(error),
                "seconds": time.perf_counter() - start}
    return dict(packet_summary(result), seconds=time.perf_counter() - start)


def packet_summary(result) -> dict:
    """Verdict, counts, governing check, compared margins, masses and life of one packet."""
    ev = result.evaluation
    checks = [c for c in ev.checks if c.margin is not None]
    governing = min(checks, key=lambda c: c.margin, default=None)
    life = next((c for c in ev.checks if c.id == "wg_life"), None)
    return {"model": ev.model.code, "built": True, "folder": result.folder.name,
            "description": ev.model.description, "verdict": ev.verdict,
            "all_passed": ev.all_passed,
            "counts": {s: sum(c.status == s for c in ev.checks)
                       for s in ("pass", "warn", "fail", "not_evaluated")},
            "governing": None if governing is None else
            {"id": governing.id, "name": governing.details.get("name", ""),
             "margin": governing.margin, "status": governing.status},
            "margins": {c.id: c.margin for c in ev.checks if c.id in INDEX_CHECKS},
            "life_h": None if life is None else life.value,
            "mass_kg": sum(result.masses_kg.values()), "parts": len(result.masses_kg)}


def run_batch(codes: list[str], duty: Duty, options: DesignOptions, catalog: Catalog,
              out_dir: Path, executor: Executor,
              progress: Callable[[int, int, dict], None] | None = None,
              force: bool = False) -> list[dict]:
    """One packet per model code through ``executor``; summaries in the order of ``codes``."""
    futures = {executor.submit(design_packet, code, duty, options, catalog, str(out_dir),
                               force): code for code in codes}
    done: dict[str, dict] = {}
    for future in as_completed(futures):
        summary = future.result()
        done[futures[future]] = summary
        if progress:
            progress(len(done), len(codes), summary)
    return [done[code] for code in codes]


def batch_executor(jobs: int | None = None, scheduler: str | None = None) -> Executor:
    """A Dask cluster's executor for a scheduler address, else a local process pool."""
    from .parallel import cores, process_pool
    if scheduler:
        try:
            from distributed import Client
        except ImportError as error:
            raise InputError("--scheduler", "needs the Dask extra: pip install "
                                            "'hdcad[cluster]'") from error
        try:
            return Client(scheduler, timeout="5s").get_executor()
        except (OSError, TimeoutError) as error:
            raise InputError("--scheduler", f"no Dask scheduler answers at {scheduler!r} "
                                            f"({type(error).__name__})") from error
    return process_pool(jobs or cores())


def write_index(summaries: list[dict], duty_name: str, folder: Path) -> Path:
    """``folder/index.html``: the candidates side by side, each linked to its packet."""
    from .output import write_text_atomic
    from .report.batch import index_context
    from .report.render import render_html
    path = folder / "index.html"
    write_text_atomic(path, render_html("batch_index.html.j2",
                                        index_context(summaries, duty_name)))
    return path
