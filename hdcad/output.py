"""Writing results without leaving half-written files behind."""

from __future__ import annotations

import json
import math
import os
import shutil
import tempfile
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Iterator


def finite(obj: Any) -> Any:
    """Copy of ``obj`` with non-finite floats replaced by None (JSON has no inf/nan)."""
    if isinstance(obj, float):
        return obj if math.isfinite(obj) else None
    if isinstance(obj, dict):
        return {k: finite(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [finite(v) for v in obj]
    return obj


def json_text(data: Any) -> str:
    return json.dumps(finite(data), indent=2, ensure_ascii=False, allow_nan=False)


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _publish_modes(root: Path) -> None:
    """Modes a plain write would give (0666/0777 less the umask): mkstemp/mkdtemp make
    0600/0700 files and folders, which would hide a packet from the rest of a team."""
    mask = _umask()
    os.chmod(root, 0o777 & ~mask) if root.is_dir() else os.chmod(root, 0o666 & ~mask)
    for folder, dirs, files in os.walk(root):
        for name in dirs:
            os.chmod(os.path.join(folder, name), 0o777 & ~mask)
        for name in files:
            os.chmod(os.path.join(folder, name), 0o666 & ~mask)


def write_text_atomic(path: str | Path, text: str) -> None:
    """Write ``text`` to ``path`` whole or not at all.

    A regular file (or a new one) is written beside it and renamed into place; a symlink is
    followed and its target replaced that way; a device, FIFO or terminal (``/dev/stdout``,
    a pipe) is written through, since it cannot be replaced. A folder or an unwritable place
    is an InputError.
    """
    from .errors import InputError
    raw = Path(path)
    if str(path) == "":
        raise InputError("--json", "needs a file name")
    if raw.is_dir():
        raise InputError("--json", f"{raw} is a folder; give a file name")
    try:
        if raw.exists() and not raw.is_file():
            # a FIFO or a device (/dev/stdout → /proc/self/fd/1 → a pipe): write through
            with open(raw, "w", encoding="utf-8") as fh:
                fh.write(text)
            return
        target = Path(os.path.realpath(raw)) if raw.is_symlink() else raw
        target.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", dir=target.parent)
    except OSError as exc:
        raise InputError("--json", f"cannot write {raw}: {exc.strerror or exc}") from None
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(text)
        _publish_modes(Path(tmp))
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


MANIFEST = ".hdcad-manifest.json"  # the files hdcad wrote into a folder it owns
STAGING = ".{name}.staging-{pid}-"


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def _remove_stale_staging(target: Path) -> None:
    """Staging folders of runs that were killed (SIGKILL leaves no chance to clean up)."""
    prefix = f".{target.name}.staging-"
    for folder in target.parent.glob(prefix + "*"):
        pid = folder.name[len(prefix):].split("-", 1)[0]
        if pid.isdigit() and not _alive(int(pid)):
            shutil.rmtree(folder, ignore_errors=True)


def check_target(target: Path, force: bool = False) -> None:
    """Refuse, before any work, a target hdcad must not replace: a symlink, a file, or a
    folder holding files hdcad did not write (unless ``force``)."""
    from .errors import InputError
    if str(target) in ("", "."):
        raise InputError("--out", "needs a folder name")
    if target.is_symlink():
        raise InputError("--out", f"{target} is a symbolic link; give the real folder")
    if target.exists() and not target.is_dir():
        raise InputError("--out", f"{target} is a file, not a folder")
    if target.is_dir() and not force:
        foreign = sorted(_foreign_files(target))
        if foreign:
            raise InputError("--out", f"{target} holds files hdcad did not write "
                                      f"({', '.join(foreign[:3])}{' …' if len(foreign) > 3 else ''})"
                                      "; move them or pass --force to replace the folder")


def _foreign_files(target: Path) -> set[str]:
    present = {p.relative_to(target).as_posix() for p in target.rglob("*") if p.is_file()}
    try:
        written = set(json.loads((target / MANIFEST).read_text(encoding="utf-8")))
    except (OSError, ValueError, TypeError):
        written = set()
    return present - written - {MANIFEST}


@contextmanager
def staged_dir(target: str | Path, force: bool = False) -> Iterator[Path]:
    """Yield a temporary folder that replaces ``target`` only when the block completes.

    One run at a time per target (a lock beside it); staging folders of killed runs are
    removed; the finished folder gets a manifest of its files and the umask's modes.
    """
    from .errors import InputError
    target = Path(target)
    check_target(target, force)
    target.parent.mkdir(parents=True, exist_ok=True)
    with _locked(target.parent / f".{target.name}.lock") as locked:
        if not locked:
            raise InputError("--out", f"another hdcad run is writing {target}")
        _remove_stale_staging(target)
        staging = Path(tempfile.mkdtemp(
            prefix=STAGING.format(name=target.name, pid=os.getpid()), dir=target.parent))
        try:
            yield staging
            files = sorted(p.relative_to(staging).as_posix()
                           for p in staging.rglob("*") if p.is_file())
            (staging / MANIFEST).write_text(json.dumps(files, indent=1), encoding="utf-8")
            _publish_modes(staging)
            if target.exists():
                shutil.rmtree(target)
            os.replace(staging, target)
        except BaseException:
            shutil.rmtree(staging, ignore_errors=True)
            raise


@contextmanager
def _locked(path: Path) -> Iterator[bool]:
    """An exclusive advisory lock on ``path`` (True), or False when another run holds it."""
    import fcntl
    with open(path, "a+") as fh:
        try:
            fcntl.flock(fh, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            yield False
            return
        try:
            yield True
        finally:
            # removed while still held: a run that opens it after this finds no lock file
            # and makes its own; nothing is left beside the output
            path.unlink(missing_ok=True)
            fcntl.flock(fh, fcntl.LOCK_UN)
