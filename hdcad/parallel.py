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
import threading
from concurrent.futures import Executor, Future, ProcessPoolExecutor
from contextlib import contextmanager
from typing import Iterator


class InlineExecutor(Executor):
    """Runs each job at once in the calling process; its futures are done when returned."""

    def submit(self, fn, /, *args, **kwargs) -> Future:
        future: Future = Future()
        try:
            future.set_result(fn(*args, **kwargs))
        except BaseException as error:  # the caller sees it on .result(), as with a pool
            future.set_exception(error)
        return future


@contextmanager
def interrupts_ignored() -> Iterator[None]:
    """SIGINT ignored in this block (main thread only); processes started here inherit it.

    Ctrl-C reaches the whole process group: the parent handles it (exit 130, staging folder
    removed); a worker that raised KeyboardInterrupt too would print a traceback. A worker
    started while SIGINT is ignored keeps ignoring it from its first instruction.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


@contextmanager
def interrupts_deferred() -> Iterator[None]:
    """Ctrl-C inside this block takes effect when it ends (main thread only).

    For imports of large C++ extensions (OCP under cadquery): an interrupt raised inside a
    module's initialisation can crash the interpreter instead of unwinding it.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    caught = []
    previous = signal.signal(signal.SIGINT, lambda signum, frame: caught.append(signum))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
    if caught:
        if callable(previous):
            previous(signal.SIGINT, None)  # the CLI's handler: remembers, then raises
        raise KeyboardInterrupt


class QuietProcessPool(ProcessPoolExecutor):
    """A process pool whose workers (started on demand by submit) ignore Ctrl-C."""

    def submit(self, fn, /, *args, **kwargs) -> Future:
        with interrupts_ignored():
            return super().submit(fn, *args, **kwargs)


@contextmanager
def running(executor: Executor) -> Iterator[Executor]:
    """Use ``executor`` in a with-block; on an error or Ctrl-C, jobs not started are
    cancelled and the running one is waited for, so nothing writes after the block."""
    try:
        yield executor
    except BaseException:
        executor.shutdown(wait=True, cancel_futures=True)
        raise
    executor.shutdown(wait=True)


def _die_with_parent() -> None:
    """Worker start-up: on Linux the kernel kills the worker when its parent dies, so a
    SIGKILLed run leaves no worker writing into its staging folder."""
    if not os.path.exists("/proc/self"):
        return
    try:
        import ctypes
        libc = ctypes.CDLL(None, use_errno=True)
        PR_SET_PDEATHSIG = 1
        libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (OSError, AttributeError):  # no prctl: the worker ends at its next read instead
        pass


def cores() -> int:
    """Cores this process may use."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def process_pool(workers: int) -> ProcessPoolExecutor:
    """A pool of fresh interpreters (spawn: no state inherited) that ignore Ctrl-C."""
    return QuietProcessPool(max_workers=workers, initializer=_die_with_parent,
                            mp_context=multiprocessing.get_context("spawn"))


def side_executor(parallel: bool = True) -> Executor:
    """One side process for a design's report chain, or inline when it cannot help."""
    if parallel and cores() > 1 and not multiprocessing.current_process().daemon:
        return process_pool(1)
    return InlineExecutor()
