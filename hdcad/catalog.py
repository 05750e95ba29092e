"""The catalog: tables transcribed from the seeds, plus optional user overlays.

Each CSV in ``catalog/`` is one table; its name is the file stem without the trailing
seed-table ids (``fd_rated_torque_310-1.csv`` → ``fd_rated_torque``). ``SOURCES*.yaml`` says
where every file comes from. A catalog overlay (YAML) appends rows to these tables or
supplies tables the seeds lack; overlay rows are validated with the same column rules and
win over shipped rows with the same key.
"""

from __future__ import annotations

import csv
import hashlib
import math
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any, Iterable

import yaml

from .errors import InputError
from .resources import catalog_dir

# Columns that hold text even when the text looks like a number.
TEXT_COLUMNS = {
    "series", "thread", "M_thread", "K_thread", "Q_bearing", "flange_code", "flange_type",
    "table", "note", "source", "lubricant", "kind", "basis", "grease", "rating", "condition",
    "path", "lubrication", "event", "input_codes", "model", "bearing_type", "family",
    "pilot_kind", "pilot_fit", "bolt_thread", "oring_d1_d2_mm", "sealant",
}
# Columns that are whole numbers.
INTEGER_COLUMNS = {"size", "ratio", "ratio_min", "ratio_max", "R", "L_count", "J_count",
                   "bolt_count",
                   "z_num1", "z_num2", "z_den1", "z_den2"}
# Units whose values may be negative (temperatures); every other measured value is >= 0.
SIGNED_UNITS = ("_C",)

# Tables the seeds do not contain; an overlay may supply them. Columns and key columns.
OVERLAY_ONLY_TABLES: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "main_bearing": (
        ("model", "bearing_type", "dp_m", "R_m", "C_N", "Co_N", "Mc_Nm", "source"),
        ("model",),
    ),
    "component_ratings": (
        ("series", "size", "ratio", "rated_torque_Nm", "avg_torque_max_Nm", "peak_torque_Nm",
         "momentary_torque_Nm", "avg_input_speed_max_rpm", "max_input_speed_rpm",
         "efficiency_rated_pct", "T1_Nm", "T2_Nm", "K1_Nm_per_rad", "K2_Nm_per_rad",
         "K3_Nm_per_rad", "theta1_rad", "theta2_rad", "source"),
        ("series", "size", "ratio"),
    ),
    # CSF/CSG-2A-GR outline (catalog "outline dimensions"); see catalog/README.md
    "component_outline": (
        ("series", "size", "cs_outer_diameter_mm", "cs_width_mm", "cs_bolt_circle_mm",
         "cs_bolt_count", "cs_bolt_thread", "fs_outer_diameter_mm", "fs_length_mm",
         "fs_boss_diameter_mm", "fs_bolt_circle_mm", "fs_bolt_count", "fs_bolt_thread",
         "wg_hub_width_mm", "wg_hub_bore_mm", "wg_protrusion_mm", "cring_hook_radius_mm",
         "cring_protrusion_mm", "source"),
        ("series", "size"),
    ),
    # the gear-head housing face a GH motor flange bolts onto: in the lost figures 053-1 …
    # 064-1 and Harmonic Drive's delivery drawings, not in the seeds (HOUSING_RULES §5 (1))
    "gh_input_interface": (
        ("series", "size", "pilot_diameter_mm", "pilot_kind", "pilot_fit", "pilot_depth_mm",
         "bolt_circle_mm", "bolt_count", "bolt_thread", "clearance_hole_mm",
         "bolt_start_angle_deg", "outline_mm", "face_to_coupling_mm",
         "coupling_outer_diameter_mm", "oring_d1_d2_mm", "sealant", "thread_depth_mm",
         "source"),
        ("series", "size", "pilot_diameter_mm", "pilot_kind", "pilot_depth_mm",
         "bolt_circle_mm", "bolt_count", "bolt_thread"),
    ),
    # the gear head's mounting face on the machine (output side): lost outline figures 050/058
    "gh_mounting_interface": (
        ("series", "size", "pilot_diameter_mm", "pilot_kind", "pilot_fit", "pilot_depth_mm",
         "bolt_circle_mm", "bolt_count", "bolt_thread", "clearance_hole_mm",
         "bolt_start_angle_deg", "outline_mm", "bore_mm", "oring_d1_d2_mm", "sealant",
         "thread_depth_mm", "source"),
        ("series", "size", "pilot_diameter_mm", "pilot_kind", "pilot_depth_mm",
         "bolt_circle_mm", "bolt_count", "bolt_thread"),
    ),
    # CSF/CSG-2A-GR "recommended housing dimensions" (inner wall); see catalog/README.md
    "component_housing": (
        ("series", "size", "fs_wall_diameter_mm", "diaphragm_side_diameter_mm",
         "diaphragm_side_depth_mm", "cring_clearance_min_mm", "output_flange_radius_mm",
         "fs_radial_deflection_mm", "oil_level_from_axis_mm", "grease_g", "source"),
        ("series", "size"),
    ),
}
# Overlay values that divide or scale a check (ratings, stiffness, bearing data, sizes) must be
# > 0: a zero would end in a division by zero or a meaningless margin.
POSITIVE_UNITS = ("Nm", "Nm_per_rad", "rpm", "N", "mm", "kgm2", "rad", "m", "pct", "h", "kg")
BEARING_TYPES = ("cross_roller", "four_point_contact", "four_point")  # exponent 10/3, 3, 3

# Key columns of the shipped tables: an overlay row with the same key replaces the row.
TABLE_KEYS: dict[str, tuple[str, ...]] = {
    "fd_ratios": ("size", "ratio"),
    "fd_rated_torque": ("size", "ratio", "speed_rpm"),
    "gh_ratings": ("series", "size", "ratio"),
    "gh_stiffness": ("series", "size", "ratio_min"),
    "gh_motor_flange": ("series", "size", "flange_code"),
    "component_examples": ("series", "size", "ratio"),
    "ke_curve": ("series", "alpha"),
}


def table_name(file_stem: str) -> str:
    """Table name from a file stem: drop trailing tokens that are seed table ids."""
    parts = file_stem.split("_")
    while len(parts) > 1 and parts[-1][:1].isdigit():
        parts.pop()
    return "_".join(parts)


@dataclass(frozen=True)
class Datum:
    """One catalog value with its unit and where it comes from."""

    value: Any
    unit: str
    source: str

    def __float__(self) -> float:
        return float(self.value)


@dataclass
class Table:
    name: str
    columns: tuple[str, ...]
    rows: list[dict[str, Any]]
    source: str  # file-level source text
    file: str = ""
    meta: dict = field(default_factory=dict)

    def row_source(self, row: dict) -> str:
        return row.get("source") or self.source


UNITS = ("Nm_per_rad", "kgfm_per_arcmin", "cNm", "kgfcm", "Nm", "kgfm", "rpm", "mm", "kgm2",
         "kg", "rad", "arcmin", "arcsec", "h", "N", "m", "deg", "pct", "C", "months")


def _unit_of(column: str) -> str:
    """Unit part of a column name (``torque_Nm`` → ``Nm``); '' for keys and text."""
    if column in TEXT_COLUMNS or column in INTEGER_COLUMNS:
        return ""
    for unit in UNITS:
        if column.endswith("_" + unit):
            return unit
    return ""


def _parse_cell(column: str, text: Any, where: str) -> Any:
    if text is None or (isinstance(text, str) and text.strip() == ""):
        return None
    if column in TEXT_COLUMNS:
        return str(text).strip()
    try:
        value = float(text)
    except (TypeError, ValueError):
        if _unit_of(column) or column in INTEGER_COLUMNS:
            raise InputError(where, f"column {column!r} must be a number (got {text!r})")
        return str(text).strip()
    if not math.isfinite(value):
        raise InputError(where, f"column {column!r} must be finite (got {text!r})")
    if value < 0 and not column.endswith(SIGNED_UNITS):
        raise InputError(where, f"column {column!r} must be >= 0 (got {text!r})")
    if column in INTEGER_COLUMNS:
        if value != int(value):
            raise InputError(where, f"column {column!r} must be a whole number (got {text!r})")
        return int(value)
    return value


def _source_text(meta: dict, file_name: str) -> str:
    seed = meta.get("seed", "")
    tables = "/".join(meta.get("tables", []))
    pages = "/".join(meta.get("pages", []))
    text = f"seed {seed} table {tables}" if tables else f"seed {seed}"
    return text + (f" (p.{pages})" if pages else "") if seed else file_name


def _read_csv(path: Path, meta: dict) -> Table:
    with path.open(newline="", encoding="utf-8") as fh:
        reader = csv.DictReader(fh)
        columns = tuple(reader.fieldnames or ())
        rows = []
        for line_no, raw in enumerate(reader, start=2):
            where = f"{path.name}:{line_no}"
            rows.append({c: _parse_cell(c, raw.get(c), where) for c in columns})
    return Table(table_name(path.stem), columns, rows, _source_text(meta, path.name),
                 path.name, meta)


def _read_sources(folder: Path) -> dict[str, dict]:
    sources: dict[str, dict] = {}
    for path in sorted(folder.glob("SOURCES*.yaml")):
        sources.update(yaml.safe_load(path.read_text(encoding="utf-8")) or {})
    return sources


class Catalog:
    """All catalog tables, shipped and overlaid, with a revision hash."""

    def __init__(self, tables: dict[str, Table], sources: dict[str, dict], revision: str,
                 overlays: tuple[str, ...] = ()):
        self.tables = tables
        self.sources = sources
        self.revision = revision
        self.overlays = overlays

    def has(self, name: str) -> bool:
        return name in self.tables and bool(self.tables[name].rows)

    def table(self, name: str) -> Table:
        try:
            return self.tables[name]
        except KeyError:
            raise KeyError(f"catalog has no table {name!r}") from None

    def rows(self, name: str, **match: Any) -> list[dict]:
        if name not in self.tables:
            return []
        return [r for r in self.tables[name].rows
                if all(r.get(k) == v for k, v in match.items())]

    def find(self, name: str, **match: Any) -> dict | None:
        """Last row matching ``match`` (overlay rows come last, so they win)."""
        found = self.rows(name, **match)
        return found[-1] if found else None

    def datum(self, name: str, row: dict | None, column: str) -> Datum | None:
        if row is None or row.get(column) is None:
            return None
        return Datum(row[column], _unit_of(column), self.tables[name].row_source(row))

    def interpretations(self) -> list[tuple[str, str]]:
        """(file, text) for every interpretation and correction in the sources."""
        out = []
        for file, meta in sorted(self.sources.items()):
            for text in meta.get("interpretations", []) or []:
                out.append((file, str(text)))
            for corr in meta.get("corrections", []) or []:
                if isinstance(corr, dict):
                    out.append((file, "correction: {where}: seed prints {seed_value}, stored "
                                      "{stored} ({why})".format(**{k: corr.get(k, "")
                                                                   for k in ("where",
                                                                             "seed_value",
                                                                             "stored",
                                                                             "why")})))
                else:
                    out.append((file, f"correction: {corr}"))
        return out


def _revision(paths: Iterable[Path]) -> str:
    digest = hashlib.sha256()
    for path in sorted(paths, key=lambda p: p.name):
        digest.update(path.name.encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:12]


@lru_cache(maxsize=1)
def _shipped() -> tuple[dict[str, Table], dict[str, dict], tuple[Path, ...]]:
    folder = catalog_dir()
    sources = _read_sources(folder)
    tables = {}
    files = tuple(sorted(folder.glob("*.csv")))
    for path in files:
        table = _read_csv(path, sources.get(path.name, {}))
        tables[table.name] = table
    return tables, sources, files + tuple(sorted(folder.glob("SOURCES*.yaml")))


def load_catalog(overlay: str | Path | None = None) -> Catalog:
    """The shipped catalog, with ``overlay`` (a YAML file) applied when given."""
    shipped, sources, files = _shipped()
    tables = {name: Table(t.name, t.columns, list(t.rows), t.source, t.file, t.meta)
              for name, t in shipped.items()}
    revision_files = list(files)
    overlays: tuple[str, ...] = ()
    if overlay is not None:
        path = Path(overlay)
        apply_overlay(tables, path)
        revision_files.append(path)
        overlays = (str(path),)
    return Catalog(tables, sources, _revision(revision_files), overlays)


def apply_overlay(tables: dict[str, Table], path: Path) -> None:
    """Validate ``path`` and merge its rows into ``tables`` (in place)."""
    from .safe_io import load_yaml
    field_ = "--catalog-overlay"
    doc = load_yaml(path, field_)
    if not isinstance(doc, dict) or not isinstance(doc.get("tables"), dict):
        raise InputError(field_, f"{path.name} must be a mapping with 'source' and 'tables'")
    source = doc.get("source")
    if not isinstance(source, str) or not source.strip():
        raise InputError(f"{path.name}: source", "required: where these values come from")
    allowed = sorted(set(tables) | set(OVERLAY_ONLY_TABLES))
    for name, rows in doc["tables"].items():
        where = f"{path.name}: tables.{name}"
        if name not in tables and name not in OVERLAY_ONLY_TABLES:
            raise InputError(where, f"unknown table; allowed: {', '.join(allowed)}")
        if not isinstance(rows, list) or not all(isinstance(r, dict) for r in rows):
            raise InputError(where, "must be a list of rows (mappings)")
        _merge_rows(tables, name, rows, where, f"overlay {path.name}: {source.strip()}")


def _merge_rows(tables: dict[str, Table], name: str, rows: list[dict], where: str,
                source: str) -> None:
    if name in tables:
        columns = tables[name].columns
        keys = TABLE_KEYS.get(name, ())
    else:
        columns, keys = OVERLAY_ONLY_TABLES[name]
        tables[name] = Table(name, columns or (), [], source, "overlay", {})
    table = tables[name]
    schema = _row_schema(name, tuple(columns or ()), tuple(keys)) if columns else None
    for index, raw in enumerate(rows):
        row_where = f"{where}[{index}]"
        if schema is not None:
            from .schema import validated
            validated(schema, raw, row_where)
        missing = [k for k in keys if raw.get(k) is None]
        if missing:
            raise InputError(row_where, f"missing key column(s) {', '.join(missing)}")
        row = {c: _parse_cell(c, raw.get(c), row_where) for c in (columns or tuple(raw))}
        _check_overlay_row(name, row, row_where)
        _check_oring(row, tables, row_where)
        row["source"] = f"{source}" + (f" ({raw['source']})" if raw.get("source") else "")
        if keys:
            table.rows = [r for r in table.rows if any(r.get(k) != row.get(k) for k in keys)]
        table.rows.append(row)


def _check_overlay_row(table: str, row: dict, where: str) -> None:
    """An overlay row holds what the shipped tables hold: positive physical values and, for
    main bearings, a known bearing type."""
    for column, value in row.items():
        if (isinstance(value, (int, float)) and value <= 0
                and (_unit_of(column) in POSITIVE_UNITS or column in INTEGER_COLUMNS)):
            raise InputError(f"{where}.{column}", f"must be > 0 (got {value!r})")
    if table == "main_bearing":
        missing = [c for c in ("dp_m", "R_m", "C_N", "Co_N", "Mc_Nm") if row.get(c) is None]
        if missing:
            raise InputError(f"{where}.{missing[0]}", "required: the main-bearing check needs "
                                                      "dp_m, R_m, C_N, Co_N and Mc_Nm")
    if table == "main_bearing" and row.get("bearing_type") not in BEARING_TYPES:
        raise InputError(f"{where}.bearing_type", f"must be one of {', '.join(BEARING_TYPES)} "
                                                  f"(got {str(row.get('bearing_type'))[:40]!r})")


def _check_oring(row: dict, tables: dict[str, Table], where: str) -> None:
    """An O-ring given as "d1xd2" [mm] has a cross-section d2 of the ISO 3601 gland table."""
    text = row.get("oring_d1_d2_mm")
    if not text:
        return
    field_ = f"{where}.oring_d1_d2_mm"
    try:
        d1, d2 = (float(v) for v in str(text).lower().replace("×", "x").split("x"))
    except ValueError:
        raise InputError(field_, f"must be 'd1xd2' in mm, e.g. '104.37x2.62' (got {text!r})")
    allowed = sorted(r["d2_mm"] for r in tables["oring_gland_iso3601"].rows)
    if d1 <= 0 or d2 not in allowed:
        raise InputError(field_, "d1 > 0 and d2 one of the ISO 3601 cross-sections "
                                 f"{', '.join(f'{v:g}' for v in allowed)} (got {text!r})")


@lru_cache(maxsize=None)
def _row_schema(table: str, columns: tuple[str, ...], keys: tuple[str, ...]):
    """A pydantic model of one overlay row of ``table``, typed from its column names: text
    columns, whole numbers, positive physical values (``POSITIVE_UNITS``), signed
    temperatures and other non-negative numbers; key columns required, others optional."""
    from typing import Annotated, Optional

    from pydantic import ConfigDict, Field, create_model

    def field_type(column: str):
        if column in TEXT_COLUMNS:
            return Annotated[str, Field(strict=False, max_length=200,
                                        description="a text value")]
        if column in INTEGER_COLUMNS:
            return Annotated[int, Field(strict=True, ge=1, le=10**6,
                                        description="a whole number >= 1")]
        if column.endswith(SIGNED_UNITS):
            return Annotated[float, Field(strict=True, ge=-273.15, le=1e4, allow_inf_nan=False,
                                          description="a number in [-273.15, 1e4]")]
        low = {"gt": 0.0} if _unit_of(column) in POSITIVE_UNITS else {"ge": 0.0}
        number = Annotated[float, Field(strict=True, le=1e12, allow_inf_nan=False,
                                        description=f"a number {'> 0' if 'gt' in low else '>= 0'}"
                                                    " and <= 1e12", **low)]
        if _unit_of(column):
            return number
        # no unit in the name: a count or a designation (cs_bolt_thread: "M4")
        return number | Annotated[str, Field(max_length=200)]

    fields = {c: ((field_type(c), ...) if c in keys else (Optional[field_type(c)], None))
              for c in columns if c != "source"}
    fields["source"] = (Optional[str], None)
    return create_model(f"{table}_row", __config__=ConfigDict(extra="forbid"), **fields)
