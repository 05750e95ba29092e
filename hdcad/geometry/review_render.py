"""A section of the review assembly as PNG: every part and neighbour body cut by the plane
through the axis at a chosen angle (upper half) and the opposite angle (lower half)."""

from __future__ import annotations

from pathlib import Path

from .drawing.measure import xz_section

COLORS = {"spacer": "#aaaaaa", "part": "#b8c0cc", "bearing": "#5b8bd9", "seal": "#d9534f", "oring": "#d9534f",
          "ring": "#444444", "screw": "#555555", "plug": "#8a6d3b", "gear": "#7fb77e",
          "shaft": "#e8d8a8", "motor": "#c9a0dc", "other": "#999999"}
LEGEND = {"part": "generated part", "bearing": "bearing", "seal": "seal / O-ring",
          "ring": "retaining ring", "screw": "screw", "plug": "plug",
          "gear": "gear or gear head (catalog or overlay outline)",
          "shaft": "user's shaft", "motor": "motor envelope", "spacer": "spacer",
          "other": "machine frame (envelope)"}


def render_section(bodies, angle_deg: float, path: Path, title: str) -> Path:
    """PNG of the assembly cut at ``angle_deg`` (above the axis) and ``angle_deg`` + 180°
    (below), z horizontal; parts hatched, neighbours filled by kind."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Polygon
    from .review import reach
    r_max = reach(bodies) + 2
    fig, ax = plt.subplots(figsize=(9, 5.4), dpi=150)
    used = set()
    for body in bodies:
        kind = body.kind if body.kind in COLORS else "other"
        for sign, angle in ((1, angle_deg), (-1, angle_deg + 180)):
            turned = body.solid.rotate((0, 0, 0), (0, 0, 1), -angle)
            for outer, *holes in xz_section(turned, 0.0, r_max):
                pts = [(z, sign * x) for z, x in outer]
                ax.add_patch(Polygon(pts, closed=True, facecolor=COLORS[kind],
                                     edgecolor="black", linewidth=0.4,
                                     hatch="////" if kind == "part" else None))
                for hole in holes:
                    ax.add_patch(Polygon([(z, sign * x) for z, x in hole], closed=True,
                                         facecolor="white", edgecolor="black", linewidth=0.4))
                used.add("seal" if kind == "oring" else kind)
    ax.axhline(0, color="black", linewidth=0.5, dashes=(8, 2, 1, 2))
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_xlabel("z [mm] (axis)")
    ax.set_ylabel("r [mm]")
    ax.set_title(title, fontsize=9)
    handles = [Polygon([(0, 0)], facecolor=COLORS[k], edgecolor="black",
                       hatch="////" if k == "part" else None, label=LEGEND[k])
               for k in LEGEND if k in used]
    ax.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    fig.savefig(path, bbox_inches="tight")
    plt.close(fig)
    return path
