"""Reading user files safely: regular files only, a size cap, UTF-8, and YAML without traps.

Every input file (duty, design options, catalog overlay, reconcile CSV) is read through
``read_text``: devices, FIFOs and folders are refused before they are opened (``/dev/zero``
would never end), files over ``MAX_BYTES`` are refused, and text must be UTF-8. ``load_yaml``
parses with a loader that refuses duplicate keys (the later would silently win), anchors and
aliases beyond a small budget (alias bombs) and nesting beyond ``MAX_DEPTH`` (recursion), and
integers too large for a float. Each refusal is an InputError naming the file and where.
"""

from __future__ import annotations

import math
import re
import stat
from pathlib import Path
from typing import Any

import yaml

from .errors import InputError

MAX_BYTES = 10 * 1024 * 1024  # 10 MB: far above any duty, options or overlay file
MAX_DEPTH = 20                # nesting of mappings and lists
MAX_ALIASES = 20              # uses of anchors (&a / *a) in one document
MAX_INT_DIGITS = 300          # a float holds ~1.8e308


def read_text(path: str | Path, field: str, max_bytes: int = MAX_BYTES) -> str:
    """The UTF-8 text of a regular file; InputError naming ``field`` otherwise."""
    path = Path(path)
    try:
        info = path.stat()
    except OSError as exc:
        raise InputError(field, f"cannot read {path}: {exc.strerror or type(exc).__name__}"
                         ) from None
    if not stat.S_ISREG(info.st_mode):
        kind = "a folder" if stat.S_ISDIR(info.st_mode) else "not a regular file"
        raise InputError(field, f"{path} is {kind}; give a file")
    if info.st_size > max_bytes:
        raise InputError(field, f"{path.name} is {info.st_size / 1e6:.1f} MB; at most "
                                f"{max_bytes / 1e6:g} MB")
    try:
        with path.open("rb") as fh:
            data = fh.read(max_bytes + 1)
    except OSError as exc:
        raise InputError(field, f"cannot read {path}: {exc.strerror or type(exc).__name__}"
                         ) from None
    if len(data) > max_bytes:
        raise InputError(field, f"{path.name} is larger than {max_bytes / 1e6:g} MB")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputError(field, f"{path.name} is not UTF-8 text (byte {exc.start})") from None


class _SafeLoader(yaml.SafeLoader):
    """SafeLoader that counts aliases and depth and refuses duplicate keys and huge ints."""

    def __init__(self, stream):
        super().__init__(stream)
        self.aliases = 0

    def compose_node(self, parent, index):
        if self.check_event(yaml.AliasEvent):
            self.aliases += 1
            if self.aliases > MAX_ALIASES:
                raise _Refused(f"more than {MAX_ALIASES} aliases (*name)",
                               self.peek_event().start_mark)
        depth = getattr(self, "_depth", 0) + 1
        if depth > MAX_DEPTH:
            raise _Refused(f"nesting deeper than {MAX_DEPTH} levels",
                           self.peek_event().start_mark)
        self._depth = depth
        try:
            return super().compose_node(parent, index)
        finally:
            self._depth = depth - 1

    def construct_mapping(self, node, deep=False):
        seen: dict[Any, Any] = {}
        for key_node, _ in node.value:
            key = self.construct_object(key_node, deep=True)
            if not isinstance(key, (str, int, float, bool)) and key is not None:
                raise _Refused("a mapping key must be a plain value", key_node.start_mark)
            if key in seen:
                raise _Refused(f"duplicate key {str(key)[:40]!r}", key_node.start_mark)
            seen[key] = True
        return super().construct_mapping(node, deep=deep)

    def construct_yaml_int(self, node):
        digits = sum(ch.isdigit() for ch in str(node.value))
        if digits > MAX_INT_DIGITS:
            raise _Refused(f"an integer of {digits} digits (too large for a number)",
                           node.start_mark)
        return super().construct_yaml_int(node)


# YAML 1.2 floats: "1e7" and "2.5E-3" are numbers (YAML 1.1 read them as strings)
_SafeLoader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^[-+]?(?:[0-9][0-9_]*)?(?:\.[0-9_]*)?[eE][-+]?[0-9]+$"), list("-+0123456789."))
_SafeLoader.add_constructor("tag:yaml.org,2002:int", _SafeLoader.construct_yaml_int)
_SafeLoader.add_constructor("tag:yaml.org,2002:map", _SafeLoader.construct_yaml_map)


class _Refused(yaml.YAMLError):
    def __init__(self, problem: str, mark):
        super().__init__(problem)
        self.problem, self.problem_mark = problem, mark


def load_yaml(path: str | Path, field: str) -> Any:
    """Parse a YAML file safely (see the module docstring); InputError naming the line."""
    path = Path(path)
    text = read_text(path, field)
    try:
        loader = _SafeLoader(text)
        try:
            return loader.get_single_data()
        finally:
            loader.dispose()
    except _Refused as exc:
        raise InputError(field, f"{path.name} line {exc.problem_mark.line + 1}: "
                                f"{exc.problem}") from None
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f" at line {mark.line + 1}" if mark is not None else ""
        raise InputError(field, f"{path.name} is not valid YAML{where}") from None
    except RecursionError:
        raise InputError(field, f"{path.name}: nesting too deep") from None


def finite_number(value: Any) -> bool:
    """A real number (not bool) that is finite: what every numeric input must be."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return False
    try:
        return math.isfinite(float(value))
    except OverflowError:
        return False
