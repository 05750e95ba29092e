"""Vector plots (SVG) for the calculation sheet: duty cycle, torque-twist, life, bolt pattern.

Each function writes one SVG sized for an A4 portrait text column and returns its path, or
returns None (and writes nothing) when the data to plot is missing; the caller then prints
"not plotted: <reason>". Titles belong in the sheet's caption, not in the figure.

Only :class:`matplotlib.figure.Figure` objects are used (no pyplot, no global backend or rc
state), so the functions are thread-safe; a Figure not registered with pyplot is freed with
its last reference, there is nothing to close. Text is written as glyph paths (matplotlib's
default ``svg.fonttype = "path"``) so WeasyPrint draws it without the font being installed.

References
----------
Seed 000 p.014 (graph 014-1, load-torque pattern), p.020 (three-segment torque-twist curve),
p.012 (formula 012-1, wave-generator life); ISO 128-2 (line types: dash-dot for pitch
circles and centre lines).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Iterable

from ..checks.life import life_hours
from ..checks.load_pattern import average_output_speed, average_torque
from ..checks.record import NOT_EVALUATED, CheckResult
from ..checks.stiffness import MissingStiffness, StiffnessCurve
from ..duty import Duty
from ..errors import InputError

# Layout: design choices for the calculation sheet, not catalog data.
COLUMN_WIDTH_MM = 170.0  # A4 (210 mm) less 20 mm margins each side
HEIGHT_MM = {"duty": 95.0, "twist": 85.0, "life": 80.0, "bolts": 95.0}
LABEL_PT = 9.0   # axis labels
SMALL_PT = 8.0   # ticks, legends, annotations: the smallest size allowed on the sheet
# Okabe-Ito colours (distinct for colour-blind readers); every series also has its own line
# style so the plots stay readable in black-and-white print.
INK, BLUE, VERMILION, GREEN, GREY = "#000000", "#0072B2", "#D55E00", "#009E73", "#777777"
LIGHT_PASS, LIGHT_FAIL, LIGHT_MATERIAL = "#DDEFE6", "#F6DDD0", "#E6E6E6"
TWIST_RANGE_FACTOR = 1.1  # torque-twist curve drawn to 1.1 × the largest torque of interest
CURVE_SAMPLES = 401
# torque-twist leader texts: first baseline [pt above the axes' bottom], line pitch [× font size]
LEADER_TEXT_TOP_PT, LEADER_LINE_STEP = 64.0, 1.5
ARCMIN_PER_RAD = 180.0 / math.pi * 60.0


# -- shared helpers --------------------------------------------------------------------------
def _figure(kind: str):
    from matplotlib.figure import Figure  # lazy: `hdcad check` never needs matplotlib
    return Figure(figsize=(COLUMN_WIDTH_MM / 25.4, HEIGHT_MM[kind] / 25.4), layout="constrained")


def _svg_path(path: Path | str) -> Path:
    path = Path(path)
    if path.suffix.lower() != ".svg":
        raise InputError("plot path", f"must end in .svg (got {path.name!r})")
    return path


def _style(ax, xlabel: str = "", ylabel: str = "") -> None:
    """Axis labels and tick sizes set per axes (not through global rcParams)."""
    if xlabel:
        ax.set_xlabel(xlabel, fontsize=LABEL_PT)
    if ylabel:
        ax.set_ylabel(ylabel, fontsize=LABEL_PT)
    ax.tick_params(labelsize=SMALL_PT)
    for axis in (ax.xaxis, ax.yaxis):
        axis.get_offset_text().set_fontsize(SMALL_PT)
    ax.spines[["top", "right"]].set_visible(False)


def _legend(ax, **kwargs) -> None:
    # outside the data area, right of it: a legend never hides a curve
    ax.legend(fontsize=SMALL_PT, loc="center left", bbox_to_anchor=(1.02, 0.5),
              frameon=False, **kwargs)


def _save(fig, path: Path, title: str = "") -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    # no date: the same data gives the same file; the title goes in the metadata only
    metadata = {"Date": None, **({"Title": title} if title else {})}
    import matplotlib
    # a fixed salt for the ids of clip paths and hatches: the same plot gives the same bytes
    with matplotlib.rc_context({"svg.hashsalt": "hdcad"}):
        fig.savefig(path, format="svg", metadata=metadata)
    return path


# -- duty cycle ------------------------------------------------------------------------------
def duty_cycle_plot(duty: Duty, path: Path) -> Path:
    """Output torque T [N·m] and output speed n [r/min] over one cycle, time t [s].

    Step plots on two stacked axes sharing time; the phase names above; the average torque
    Tav and average output speed no,av as dashed lines; the shock torque Ts as a dotted line
    (it occurs at an unknown time of some cycles, so it is a level, not a step).

    References
    ----------
    Seed 000 p.014 (graph 014-1, formula for Tav); p.015 (no,av).
    """
    path = _svg_path(path)
    edges = [0.0]
    for seg in duty.cycle:
        edges.append(edges[-1] + seg.time_s)
    torques = [s.torque_Nm for s in duty.cycle]
    speeds = [s.speed_rpm for s in duty.cycle]
    tav, no_av = average_torque(duty.cycle), average_output_speed(duty.cycle)

    fig = _figure("duty")
    ax_t, ax_n = fig.subplots(2, 1, sharex=True)
    ax_t.stairs(torques, edges, baseline=None, color=BLUE, lw=1.6, label="T (cycle)")
    ax_t.axhline(tav, color=INK, ls="--", lw=1.0, label=f"Tav = {tav:,.1f} N·m")
    levels = torques + [tav, 0.0]
    if duty.shock is not None:
        s = duty.shock
        count = f", {s.count:,} times" if s.count is not None else ""
        ax_t.axhline(s.torque_Nm, color=VERMILION, ls=":", lw=1.4,
                     label=f"shock Ts = {s.torque_Nm:,.0f} N·m\n(ts = {s.time_s:g} s{count})")
        levels.append(s.torque_Nm)
    ax_t.axhline(0.0, color=GREY, lw=0.5)
    ax_t.set_ylim(*_padded(levels))
    _style(ax_t, ylabel="output torque T [N·m]")
    _legend(ax_t)

    ax_n.stairs(speeds, edges, baseline=None, color=GREEN, lw=1.6, label="n (cycle)")
    ax_n.axhline(no_av, color=INK, ls="--", lw=1.0, label=f"no,av = {no_av:,.1f} r/min")
    ax_n.set_ylim(*_padded(speeds + [0.0, no_av]))
    ax_n.set_xlim(edges[0], edges[-1])
    _style(ax_n, xlabel="time t [s]", ylabel="output speed n [r/min]")
    _legend(ax_n)

    _phase_names(ax_t, edges, [s.phase for s in duty.cycle])
    return _save(fig, path)


def _padded(values: Iterable[float], frac: float = 0.12) -> tuple[float, float]:
    low, high = min(values), max(values)
    span = (high - low) or 1.0
    return low - (frac * span if low < 0 else 0.0), high + frac * span


def _phase_names(ax, edges: list[float], phases: list[str]) -> None:
    """Phase names as ticks on a top axis, at the middle of each segment."""
    top = ax.secondary_xaxis("top")
    top.set_xticks([(a + b) / 2 for a, b in zip(edges, edges[1:])], phases)
    top.tick_params(labelsize=SMALL_PT, length=0)
    top.spines["top"].set_visible(False)
    # a segment narrower than its name: tilt the names so neighbours do not overlap
    if min(b - a for a, b in zip(edges, edges[1:])) < 0.08 * (edges[-1] - edges[0]):
        for label in top.get_xticklabels():
            label.set_rotation(30)
            label.set_horizontalalignment("left")


# -- torque-twist ----------------------------------------------------------------------------
def torque_twist_plot(curve: StiffnessCurve | None, points: dict[str, float], path: Path,
                      limit_Nm: float | None = None) -> Path | None:
    """Catalog torque-twist curve, twist θ [arcmin] (right axis [mrad]) against torque T [N·m].

    Both signs from −Tmax to +Tmax, Tmax = 1.1 × max(|points|, limit_Nm) (T2 or T1 when
    neither is given); T1 and T2 marked on the curve; each operating point (label → torque
    [N·m]) marked with its twist [arcmin]; ±limit_Nm as dash-dot lines. None when the curve
    is missing or lacks a stiffness value needed in that range.

    References
    ----------
    Seed 000 p.020 (K1, K2, K3, T1, T2, θ1, θ2); ratings per model: seed 003 tables
    052-1/060-1, seed 001 table 314-1 (FD spring constant).
    """
    path = _svg_path(path)
    if curve is None:
        return None
    breaks = [t for t in (curve.T1, curve.T2) if t is not None and math.isfinite(t)]
    scale = [abs(t) for t in points.values()] + ([abs(limit_Nm)] if limit_Nm else [])
    t_max = TWIST_RANGE_FACTOR * max(scale or breaks[-1:] or [0.0])
    if t_max <= 0:
        return None
    torques = sorted({t_max * (2 * i / (CURVE_SAMPLES - 1) - 1) for i in range(CURVE_SAMPLES)}
                     | {sign * t for t in breaks if t < t_max for sign in (-1, 1)})
    try:
        twist = [curve.twist(t) * ARCMIN_PER_RAD for t in torques]
        marked = {name: (t, curve.twist(t) * ARCMIN_PER_RAD) for name, t in points.items()}
        knees = [(f"T{i}", t, curve.twist(t) * ARCMIN_PER_RAD)
                 for i, t in enumerate(breaks, 1) if t < t_max]
    except MissingStiffness:
        return None

    fig = _figure("twist")
    ax = fig.subplots()
    ax.plot(torques, twist, color=BLUE, lw=1.6, label="catalog curve")
    ax.axhline(0.0, color=GREY, lw=0.5)
    ax.axvline(0.0, color=GREY, lw=0.5)
    if knees:
        # the segment limits sit close to the origin where on-curve texts would collide with
        # each other and with the curve: they are named once in the legend instead
        ax.plot([s * t for _, t, _ in knees for s in (-1, 1)],
                [s * th for _, _, th in knees for s in (-1, 1)], ls="none", marker="D", ms=4,
                mfc="white", mec=INK,
                label="segment limits " + ", ".join(f"{n} = {t:g}" for n, t, _ in knees) + " N·m")
    if limit_Nm:
        for sign in (-1, 1):
            ax.axvline(sign * abs(limit_Nm), color=VERMILION, ls="-.", lw=1.0,
                       label=f"limit ±{abs(limit_Nm):,.0f} N·m" if sign > 0 else None)
    # largest torque gets the top text: the leader lines then neither cross each other nor
    # run through a text (each passes left of the texts above its own)
    order = sorted(marked.items(), key=lambda item: -item[1][0])
    for i, (name, (t, th)) in enumerate(order):
        ax.plot(t, th, ls="none", marker="o", ms=5, color=INK)
        # texts stacked in the empty lower-right quadrant (T > 0, θ < 0) with leader lines:
        # operating points are often close together and their labels would overlap
        ax.annotate(f"{name}: {t:,.0f} N·m → {th:.2f} arcmin", (t, th),
                    xytext=(0.64, LEADER_TEXT_TOP_PT - LEADER_LINE_STEP * SMALL_PT * i),
                    textcoords=("axes fraction", "axes points"),
                    fontsize=SMALL_PT, va="center",
                    arrowprops={"arrowstyle": "-", "color": GREY, "lw": 0.6,
                                "relpos": (0.0, 0.5), "shrinkA": 2, "shrinkB": 3})
    ax.set_xlim(-t_max, t_max)
    _style(ax, xlabel="output torque T [N·m]", ylabel="twist θ [arcmin]")
    right = ax.secondary_yaxis("right", functions=(_arcmin_to_mrad, _mrad_to_arcmin))
    right.set_ylabel("twist θ [mrad]", fontsize=LABEL_PT)
    right.tick_params(labelsize=SMALL_PT)
    ax.legend(fontsize=SMALL_PT, loc="upper left", frameon=False)
    return _save(fig, path)


def _arcmin_to_mrad(x):
    return x / ARCMIN_PER_RAD * 1e3


def _mrad_to_arcmin(x):
    return x / 1e3 * ARCMIN_PER_RAD


# -- wave-generator life ---------------------------------------------------------------------
def _input(record: CheckResult, *names: str) -> float | None:
    for name in names:
        if name in record.inputs and record.inputs[name].value is not None:
            return float(record.inputs[name].value)
    return None


def life_plot(life_check: CheckResult, required_h: float, path: Path) -> Path | None:
    """Wave-generator life L10 [h] (log) against average output torque Tav [N·m].

    Lh = Ln·(Tr/Tav)³·(Nr/ni_av) at the record's ni_av [r/min], Ln, Tr, Nr; the operating
    point, the required life [h] and the pass (Lh ≥ required) and fail regions. None when
    the record is not evaluated or has no load (life not limited by torque).

    References
    ----------
    Seed 000 p.012 (table 012-1, formula 012-1).
    """
    path = _svg_path(path)
    if life_check.status == NOT_EVALUATED:
        return None
    tav, ni = _input(life_check, "Tav"), _input(life_check, "ni_av")
    tr, nr = _input(life_check, "Tr"), _input(life_check, "Nr")
    ln = _input(life_check, "Ln (L10)", "Ln")
    if None in (tav, ni, tr, nr, ln) or tav <= 0 or ni <= 0 or required_h <= 0:
        return None

    def life(t: float) -> float:
        return life_hours(ln, tr, t, nr, ni)

    lh = life(tav)
    t_req = tav * (lh / required_h) ** (1 / 3)  # Lh ∝ Tav⁻³ (formula 012-1)
    lo, hi = 0.25 * min(tav, t_req), 1.6 * max(tav, t_req)
    torques = [lo + (hi - lo) * i / (CURVE_SAMPLES - 1) for i in range(CURVE_SAMPLES)]

    from matplotlib.ticker import FuncFormatter, NullFormatter
    fig = _figure("life")
    ax = fig.subplots()
    ax.axvspan(lo, t_req, color=LIGHT_PASS, lw=0, label="pass: L10 ≥ required")
    ax.axvspan(t_req, hi, facecolor=LIGHT_FAIL, edgecolor="#C9A08A", hatch="///", lw=0,
               label="fail: L10 < required")
    ax.plot(torques, [life(t) for t in torques], color=BLUE, lw=1.6,
            label=f"L10 at ni,av = {ni:,.0f} r/min")
    ax.axhline(required_h, color=INK, ls="--", lw=1.0, label=f"required {required_h:,.0f} h")
    ax.plot(tav, lh, ls="none", marker="o", ms=5, color=INK)
    ax.annotate(f"Tav = {tav:,.1f} N·m\nL10 = {lh:,.0f} h", (tav, lh), xytext=(8, 8),
                textcoords="offset points", fontsize=SMALL_PT)
    ax.set_yscale("log")
    # "10,000 h" rather than 10⁴: no superscripts below the 8 pt minimum, read without math
    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:,.0f}"))
    ax.yaxis.set_minor_formatter(NullFormatter())
    ax.set_xlim(lo, hi)
    _style(ax, xlabel="average output torque Tav [N·m]", ylabel="wave-generator life L10 [h]")
    _legend(ax)
    return _save(fig, path)


# -- bolt pattern ----------------------------------------------------------------------------
BOLT_KEYS = ("diameter_mm", "count", "hole_diameter_mm")


def hole_centres(diameter_mm: float, count: int, start_deg: float = 0.0
                 ) -> list[tuple[float, float]]:
    """Centres (x, y) [mm] of ``count`` holes evenly spaced on a circle of ``diameter_mm``."""
    angles = (math.radians(start_deg + 360.0 * i / count) for i in range(count))
    return [(diameter_mm / 2 * math.cos(a), diameter_mm / 2 * math.sin(a)) for a in angles]


def bolt_pattern_plot(circles: list[dict], path: Path, title: str = "",
                      outer_diameter_mm: float | None = None,
                      bore_mm: float | None = None) -> Path | None:
    """Front view (equal aspect, x and y [mm]) of a part's bolt circles.

    ``circles`` are dicts with the fields of ``hdcad.geometry.part.BoltCircle`` and an
    optional ``start_angle_deg`` (angle of the first hole [deg], default 0). Each hole is a
    circle of its hole diameter; the bolt circle is dash-dotted (ISO 128-2), the material
    annulus shaded, outer diameter and bore solid. ``title`` goes into the SVG metadata (the
    sheet's caption carries the visible title). None when no circle or a circle lacks
    diameter, count or hole diameter.
    """
    path = _svg_path(path)
    if not circles or any(c.get(k) in (None, 0) for c in circles for k in BOLT_KEYS):
        return None
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle, Wedge

    fig = _figure("bolts")
    ax = fig.subplots()
    styles = [(BLUE, "-"), (VERMILION, "--"), (GREEN, ":"), (INK, "-.")]
    handles = []
    for ci, c in enumerate(circles):
        color, ls = styles[ci % len(styles)]
        inner, outer = c.get("annulus_inner_mm"), c.get("annulus_outer_mm")
        if inner and outer and outer > inner:
            ax.add_patch(Wedge((0, 0), outer / 2, 0, 360, width=(outer - inner) / 2,
                               facecolor=LIGHT_MATERIAL, edgecolor="none", alpha=0.6,
                               zorder=0.5))  # under every line of every circle
        ax.add_patch(Circle((0, 0), c["diameter_mm"] / 2, fill=False, color=color, ls="-.",
                            lw=0.7))
        for i, (x, y) in enumerate(hole_centres(c["diameter_mm"], int(c["count"]),
                                                c.get("start_angle_deg", 0.0))):
            ax.add_patch(Circle((x, y), c["hole_diameter_mm"] / 2, fill=False, color=color,
                                ls=ls, lw=1.2, gid=f"hole_{ci}_{i}"))
        handles.append(Line2D([], [], color=color, ls=ls, marker="o", mfc="none",
                              label=_circle_label(c)))
    for d, text in ((outer_diameter_mm, "outer"), (bore_mm, "bore")):
        if d:
            ax.add_patch(Circle((0, 0), d / 2, fill=False, color=INK, lw=1.4))
            handles.append(Line2D([], [], color=INK, lw=1.4, label=f"{text} Ø{d:g}"))
    if any(c.get("annulus_inner_mm") and c.get("annulus_outer_mm") for c in circles):
        handles.append(_material_handle())
    radius = max([c["diameter_mm"] / 2 + c["hole_diameter_mm"] for c in circles]
                 + [d / 2 for d in (outer_diameter_mm, bore_mm, *_annuli(circles)) if d])
    r = 1.08 * radius
    ax.plot([-r, r], [0, 0], color=GREY, ls="-.", lw=0.5)  # centre lines (ISO 128-2)
    ax.plot([0, 0], [-r, r], color=GREY, ls="-.", lw=0.5)
    ax.set_xlim(-r, r)
    ax.set_ylim(-r, r)
    ax.set_aspect("equal")
    _style(ax, xlabel="x [mm]", ylabel="y [mm]")
    ax.legend(handles=handles, fontsize=SMALL_PT, loc="center left", bbox_to_anchor=(1.02, 0.5),
              frameon=False)
    return _save(fig, path, title)


def _annuli(circles: list[dict]) -> list[float]:
    return [c["annulus_outer_mm"] for c in circles if c.get("annulus_outer_mm")]


def _material_handle():
    from matplotlib.patches import Patch
    return Patch(facecolor=LIGHT_MATERIAL, edgecolor="none", label="material annulus")


def _circle_label(c: dict) -> str:
    """"n × M5 on Ø70", then name, kind, hole Ø, depth and first-hole angle."""
    hole = "drill" if c.get("kind") == "tapped" else "hole"
    depth = f", {c['depth_mm']:g} deep" if c.get("depth_mm") else ""
    name = f"{c['name']}: " if c.get("name") else ""
    # BoltCircle has no angle field: say so rather than draw an assumed clocking as fact
    angle = (f"1st hole at {c['start_angle_deg']:g}°" if c.get("start_angle_deg") is not None
             else "1st hole at 0° (angle not given)")
    return (f"{name}{int(c['count'])} × {c.get('thread') or 'hole'} on Ø{c['diameter_mm']:g}\n"
            f"  ({c.get('kind') or 'hole'}, {hole} Ø{c['hole_diameter_mm']:g}{depth})\n"
            f"  {angle}")
