"""`hdcad design`: checks, parts, STEP/STL/SVG export and results.json in one folder.

Everything is written to a staging folder that replaces ``OUT/<MODEL>`` only when complete:
bad input (exit 2) leaves nothing behind; a design whose checks fail is written in full.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from .catalog import Catalog
from .checks.record import CheckResult, Quantity, compared
from .checks.run import Evaluation, run_checks
from .design_options import DesignOptions
from .duty import Duty
from .models import GearModel


@dataclass
class DesignResult:
    evaluation: Evaluation
    options: DesignOptions
    folder: Path
    files: list[str]
    masses_kg: dict[str, float]


def interference_check(pairs: list[tuple[str, str, float]], masses: dict[str, float]
                       ) -> CheckResult:
    """No two parts overlap: largest pairwise intersection volume [mm³] must be 0."""
    worst = max((v for _, _, v in pairs), default=0.0)
    inputs = {f"{a} ∩ {b}": Quantity(v, "mm³") for a, b, v in pairs}
    inputs.update({f"mass {name}": Quantity(m, "kg") for name, m in masses.items()})
    # 1e-3 mm³ is far below any real overlap and above OCCT's boolean noise on touching faces
    return compared("interference", "Interference between parts", "geometry",
                    "max over part pairs of V(A ∩ B) ≤ 0", inputs, worst, 1e-3, "mm³", "<=",
                    "OCCT boolean common of the placed solids",
                    f"{len(pairs)} pair(s) checked; masses " +
                    ", ".join(f"{n} {m:.3f} kg" for n, m in masses.items()),
                    {"pairs": [{"a": a, "b": b, "volume_mm3": v} for a, b, v in pairs],
                     "masses_kg": masses})


def run_design(model: GearModel, duty: Duty, options: DesignOptions, catalog: Catalog,
               out_dir: Path) -> DesignResult:
    """Build, check and export ``model``; returns what was written."""
    from .geometry.build import build_parts, interference_mm3, part_mass_kg
    from .geometry.part import export_assembly, export_step, export_stl, export_svg
    from .checks.geometric import geometric_checks
    from .output import json_text, staged_dir

    evaluation = run_checks(model, duty, catalog, options.input_thrust_capacity_N)
    parts = build_parts(model, catalog, options)
    masses = {p.name: part_mass_kg(p, options.density_kg_m3) for p in parts}
    evaluation.checks += geometric_checks(model, parts, options, catalog)
    evaluation.checks.append(interference_check(interference_mm3(parts), masses))
    target = Path(out_dir) / model.code
    files: list[str] = []
    with staged_dir(target) as stage:
        for part in parts:
            for suffix, export in ((".step", export_step), (".stl", export_stl),
                                   (".svg", export_svg)):
                export(part, stage / f"{part.name}{suffix}")
                files.append(f"{part.name}{suffix}")
        export_assembly(parts, stage / "assembly.step")
        files.append("assembly.step")
        result = evaluation.as_dict()
        result.update({"design_options": options.as_dict(), "files": files + ["results.json"],
                       "parts": [{"name": p.name, "mass_kg": masses[p.name],
                                  "dimensions": p.dimensions, "notes": p.notes,
                                  "bolt_circles": [b.__dict__ for b in p.bolt_circles]}
                                 for p in parts]})
        (stage / "results.json").write_text(json_text(result), encoding="utf-8")
        files.append("results.json")
    return DesignResult(evaluation, options, target, files, masses)
