"""Executors: one side process for the independent stages of a design, pools for batches.

A design packet has two chains that need nothing from each other until the PDF: the CAD chain
(import cadquery, build, STEP/STL, drawings) and the report chain (import matplotlib and
WeasyPrint, plots). ``side_executor`` gives the report chain its own process, so on a machine
with two cores the two chains overlap. Everything goes through the
``concurrent.futures.Executor`` interface, so the same jobs run inline (one core, or inside a
batch worker that is itself parallel), in a local process pool, or on a Dask cluster.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
from concurrent.futures import Executor, Future, ProcessPoolExecutor


class InlineExecutor(Executor):
    """Runs each job at once in the calling process; its futures are done when returned."""

    def submit(self, fn, /, *args, **kwargs) -> Future:
        future: Future = Future()
        try:
            future.set_result(fn(*args, **kwargs))
        except BaseException as error:  # the caller sees it on .result(), as with a pool
            future.set_exception(error)
        return future


def _ignore_interrupt() -> None:
    # Ctrl-C reaches the whole process group: the parent handles it (exit 130, staging
    # folder removed); a worker that also raised KeyboardInterrupt would print a traceback
    signal.signal(signal.SIGINT, signal.SIG_IGN)


def cores() -> int:
    """Cores this process may use."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def process_pool(workers: int) -> ProcessPoolExecutor:
    """A pool of fresh interpreters (spawn: no state inherited) that ignore Ctrl-C."""
    return ProcessPoolExecutor(max_workers=workers, initializer=_ignore_interrupt,
                               mp_context=multiprocessing.get_context("spawn"))


def side_executor(parallel: bool = True) -> Executor:
    """One side process for a design's report chain, or inline when it cannot help."""
    if parallel and cores() > 1 and not multiprocessing.current_process().daemon:
        return process_pool(1)
    return InlineExecutor()
