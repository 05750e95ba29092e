"""The ``hdcad`` console command's first lines: Ctrl-C is remembered from here on, so an
interrupt while the command line's modules load still ends with one line and exit 130
instead of a traceback (the interpreter's own start-up is the only window left)."""

from __future__ import annotations

import os
import signal
import sys

caught: list[int] = []
reported: list[bool] = []  # the command line printed "hdcad: interrupted"


def remember(signum, frame) -> None:
    caught.append(signum)


def arm() -> None:
    """Remember Ctrl-C from here on, unless someone else already handles it."""
    if signal.getsignal(signal.SIGINT) is signal.default_int_handler:
        signal.signal(signal.SIGINT, remember)


def run() -> int:
    arm()
    try:
        try:
            from .cli import main
            code = main()
        finally:
            # the answer is given: a Ctrl-C still pending (the interpreter runs a signal's
            # handler at its next chance, even after main returned) must not turn the exit
            # code into a death by SIGINT; an ignored signal's pending handler is skipped
            signal.signal(signal.SIGINT, signal.SIG_IGN)
    except KeyboardInterrupt:  # raised between main's return and the line above
        if not reported:
            print("hdcad: interrupted", file=sys.stderr)
        code = 130
    return code


def leave(code: int) -> None:
    """End ``python -m hdcad`` (or ``-m hdcad.cli``) with ``code``.

    CPython's ``-m`` runner ends the process by SIGINT, whatever the exit code, once a
    KeyboardInterrupt has escaped any embedded ``PyRun_*`` call, even one that Python code
    caught later (a process-wide flag it never clears). An interrupted run has cleaned up and
    answered by now, so it leaves by ``os._exit`` once its output is flushed."""
    if code != 130:
        sys.exit(code)
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):
            pass
    os._exit(code)
