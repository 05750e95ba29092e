"""The ``hdcad`` console command's first lines: Ctrl-C is remembered from here on, so an
interrupt while the command line's modules load still ends with one line and exit 130
instead of a traceback (the interpreter's own start-up is the only window left)."""

from __future__ import annotations

import signal

caught: list[int] = []


def remember(signum, frame) -> None:
    caught.append(signum)


def run() -> int:
    if signal.getsignal(signal.SIGINT) is signal.default_int_handler:
        signal.signal(signal.SIGINT, remember)
    from .cli import main
    return main()
