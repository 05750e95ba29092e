"""Locate the data folders shipped with hdcad (catalog, templates, examples).

In a wheel they live inside the package (``hdcad/_catalog`` …); in a source checkout they
are the top-level folders beside ``hdcad/``.
"""

from pathlib import Path

_PACKAGE = Path(__file__).resolve().parent


def _folder(installed: str, source: str) -> Path:
    inside = _PACKAGE / installed
    return inside if inside.is_dir() else _PACKAGE.parent / source


def catalog_dir() -> Path:
    return _folder("_catalog", "catalog")


def templates_dir() -> Path:
    return _folder("_templates", "templates")


def examples_dir() -> Path:
    return _folder("_examples", "examples")
