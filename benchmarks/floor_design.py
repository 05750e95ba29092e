"""The floor of a design packet: the same kind of work as `hdcad design`, done the shortest way.

Imports cadquery, matplotlib and WeasyPrint; builds one flanged part (a disc with a spigot, a
bore and a bolt circle), writes it as STEP and STL; draws three SVG plots; writes a ten-page
PDF of tables with the plots. bench_speed.py times this script against `hdcad design` as
fresh processes, so both pay their imports.

Run: python benchmarks/floor_design.py OUT_DIR
"""

from __future__ import annotations

import sys
from pathlib import Path


def flanged_part(out: Path) -> None:
    import cadquery as cq
    part = (cq.Workplane("XY").circle(52.5).extrude(17.4)
            .faces(">Z").workplane().circle(35).extrude(8)
            .faces(">Z").workplane().hole(26)
            .faces("<Z").workplane().polarArray(45, 45, 360, 4).hole(4.2, 14.4))
    cq.exporters.export(part, str(out / "part.step"))
    cq.exporters.export(part, str(out / "part.stl"))


def plots(out: Path) -> list[Path]:
    import numpy as np
    from matplotlib.figure import Figure
    paths = []
    x = np.linspace(-2000, 2000, 401)
    for i, y in enumerate((np.sign(x) * np.abs(x) ** 0.9, np.cumsum(np.ones_like(x)),
                           1e5 * (x + 2100) ** -1.5)):
        fig = Figure(figsize=(6.7, 3.4), layout="constrained")
        ax = fig.subplots()
        ax.plot(x, y, label=f"curve {i}")
        for k in range(4):
            ax.annotate(f"point {k}: {x[100 * k]:.0f}", (x[100 * k], y[100 * k]))
        ax.set_xlabel("x [unit]")
        ax.set_ylabel("y [unit]")
        ax.legend()
        paths.append(out / f"plot{i}.svg")
        fig.savefig(paths[-1], format="svg")
    return paths


def pdf(out: Path, figures: list[Path]) -> None:
    from weasyprint import HTML
    rows = "".join(f"<tr><td>quantity {i}</td><td>{i * 3.14159:.4g}</td><td>N·m</td>"
                   f"<td>seed table 050-1 p.050</td></tr>" for i in range(30))
    pages = []
    for page in range(10):  # ten pages: 30 rows of tables each
        image = f'<img src="{figures[page % 3].name}" style="width:170mm">' if page < 3 else ""
        pages.append(f"<section style='page-break-after:always'><h2>Chapter {page}</h2>"
                     f"{image}<table>{rows}</table></section>")
    html = ("<html><head><style>@page{size:A4;margin:15mm} td{font-size:8pt;border:0.3pt "
            "solid #888}</style></head><body>" + "".join(pages) + "</body></html>")
    HTML(string=html, base_url=str(out)).write_pdf(out / "sheet.pdf")


def main(out: str) -> None:
    folder = Path(out)
    folder.mkdir(parents=True, exist_ok=True)
    flanged_part(folder)
    pdf(folder, plots(folder))


if __name__ == "__main__":
    main(sys.argv[1])
