"""The ``hdcad`` command line.

Exit codes: 0 every evaluated check passes (checks that cannot be evaluated are listed, not
failed), 1 a check fails, 2 bad input or bad arguments (one line naming the file and field
and the allowed range), 3 an internal error (one line; the traceback with --debug), 130
interrupted (Ctrl-C). Commands that need no geometry never import cadquery.
"""

from __future__ import annotations

from . import _entry

if __name__ == "__main__":  # ``python -m hdcad.cli``: remember Ctrl-C while the rest loads
    _entry.arm()

import argparse
import os
import signal
import sys
from typing import Sequence

from . import __version__
from .errors import InputError
from .report.format import check_label, fmt, margin_text, relation_text, status_text

EXIT_OK, EXIT_FAIL, EXIT_INPUT, EXIT_INTERNAL, EXIT_INTERRUPTED = 0, 1, 2, 3, 130
MESSAGE_LIMIT = 300  # characters of an error line; longer values are shortened


def _table(headers: Sequence[str], rows: Sequence[Sequence[str]]) -> str:
    widths = [max(len(str(x)) for x in col) for col in zip(headers, *rows)]
    line = lambda cells: "  ".join(str(c).ljust(w) for c, w in zip(cells, widths)).rstrip()
    return "\n".join([line(headers), line(["-" * w for w in widths])] + [line(r) for r in rows])


def cmd_catalog(args) -> int:
    from .catalog import load_catalog
    from .checks.fd import momentary_allowance
    from .models import list_models, resolve
    catalog = load_catalog(args.catalog_overlay)
    if args.model:
        from .catalog_view import model_lines
        print("\n".join(model_lines(resolve(args.model, catalog), catalog)))
        return EXIT_OK
    rows = []
    for code in list_models(catalog, args.series):
        m = resolve(code, catalog)
        if m.is_fd:  # FD ratings depend on speed: show the 1450 r/min row (table 310-1)
            rated = dict(m.fd_torque_by_speed).get(1450.0)
            rows.append([code, fmt(_f(rated)) + " @1450", "—", "—",
                         fmt(_f(momentary_allowance(m.fd_torque_by_speed))),
                         fmt(_f(m.get("max_input_speed_oil_rpm"))) + " (oil)"])
        else:
            rows.append([code, fmt(_f(m.get("rated_torque_Nm"))),
                         fmt(_f(m.get("avg_torque_max_Nm"))), fmt(_f(m.get("peak_torque_Nm"))),
                         fmt(_f(m.get("momentary_torque_Nm"))),
                         fmt(_f(m.get("max_input_speed_rpm")))])
    print(f"hdcad catalog (revision {catalog.revision}); torques in N·m, speeds in r/min")
    print(_table(["model", "rated", "avg max", "peak", "momentary", "max input speed"], rows))
    return EXIT_OK


def _f(datum):
    return None if datum is None else float(datum)


def print_evaluation(ev) -> None:
    print(f"{ev.model.code}: {ev.model.description}")
    d = ev.derived
    print(f"duty {ev.duty.name}: Tav {fmt(d['avg_torque_Nm'])} N·m, no_av "
          f"{fmt(d['avg_output_speed_rpm'])} r/min, ni_av {fmt(d['avg_input_speed_rpm'])} r/min, "
          f"ni_max {fmt(d['max_input_speed_rpm'])} r/min")
    rows = [[check_label(c.id, c.details), status_text(c.status), fmt(c.value),
             relation_text(c.sense, c.status),
             fmt(c.limit), c.unit, margin_text(c.margin)]
            for c in ev.checks]
    print(_table(["check", "status", "value", "", "limit", "unit", "margin"], rows))
    for c in ev.checks:
        if c.note:
            print(f"  {check_label(c.id, c.details)}: {c.note}")
    print(f"verdict: {ev.verdict} (catalog revision {ev.catalog_revision})")


def cmd_check(args) -> int:
    from .catalog import load_catalog
    from .checks.run import run_checks
    from .duty import load_duty
    from .models import resolve
    from .output import json_text, write_text_atomic
    from .design_options import load_options
    catalog = load_catalog(args.catalog_overlay)
    model = resolve(args.model, catalog)
    duty = load_duty(args.duty)
    options = load_options(args.design)
    ev = run_checks(model, duty, catalog, options.input_thrust_capacity_N, options.check_rules)
    print_evaluation(ev)
    if args.json:
        write_text_atomic(args.json, json_text(ev.as_dict()))
    return EXIT_OK if ev.all_passed else EXIT_FAIL


def cmd_select(args) -> int:
    from .catalog import load_catalog
    from .duty import load_duty
    from .output import json_text, write_text_atomic
    from .selection import select
    catalog = load_catalog(args.catalog_overlay)
    duty = load_duty(args.duty)
    candidates = select(duty, catalog, args.series)
    passing = [c for c in candidates if c.passes]
    rows = []
    for c in candidates:
        f, ev = c.first_failure, c.evaluation
        remark = (f"{f.id}: {fmt(f.value)} {relation_text(f.sense, f.status)} {fmt(f.limit)} "
                  f"{f.unit}".rstrip() if f else
                  f"missing core rating: {', '.join(c.missing_core)}" if c.missing_core else
                  f"{len(ev.not_evaluated)} not evaluated")
        rows.append([c.model, c.status.upper() if c.passes else c.status, remark])
    print(_table(["model", "result", "first failing check / remarks"], rows))
    print(f"{len(passing)} of {len(candidates)} models pass"
          + (f"; smallest: {passing[0].model}" if passing else ""))
    if args.json:
        write_text_atomic(args.json, json_text({
            "duty": duty.as_dict(),
            "passing": [{"model": c.model, "verdict": c.evaluation.verdict,
                         "not_evaluated": [x.id for x in c.evaluation.not_evaluated]}
                        for c in passing],
            "rejected": [{"model": c.model, "check": c.first_failure.as_dict()}
                         for c in candidates if c.status == "fail"],
            "incomplete": [{"model": c.model, "missing": c.missing_core}
                           for c in candidates if c.status == "incomplete"],
        }))
    if args.design_top:
        return _design_top(args, duty, catalog, [c.model for c in passing[:args.design_top]])
    return EXIT_OK if passing else EXIT_FAIL


def _design_top(args, duty, catalog, codes: list[str]) -> int:
    """Packets of the best candidates in parallel, and DIR/index.html comparing them."""
    from pathlib import Path
    from .batch import batch_executor, run_batch, write_index
    from .design_options import load_options
    if not codes:
        print("no passing model: no design packets", file=sys.stderr)
        return EXIT_FAIL
    options = load_options(args.design)
    out = Path(args.out)

    def progress(done: int, total: int, summary: dict) -> None:
        state = summary["verdict"] if summary["built"] else f"not built: {summary['error']}"
        print(f"[{done}/{total}] {summary['model']} ({summary['seconds']:.1f} s): {state}",
              file=sys.stderr, flush=True)

    print(f"building {len(codes)} design packets: {', '.join(codes)}", file=sys.stderr)
    from .parallel import running
    with running(batch_executor(args.jobs, args.scheduler)) as executor:
        summaries = run_batch(codes, duty, options, catalog, out, executor, progress,
                              args.force)
    index = write_index(summaries, duty.name, out)
    print(f"wrote {index} ({sum(s['built'] for s in summaries)} of {len(codes)} packets)")
    return EXIT_OK if any(s["built"] and s["all_passed"] for s in summaries) else EXIT_FAIL


def cmd_design(args) -> int:
    from .catalog import load_catalog
    from .design import run_design
    from .design_options import load_options
    from .duty import load_duty
    from .models import resolve
    catalog = load_catalog(args.catalog_overlay)
    model = resolve(args.model, catalog)
    duty = load_duty(args.duty)
    options = load_options(args.design)
    result = run_design(model, duty, options, catalog, args.out, parallel=True,
                        progress=_stage_printer(args), force=args.force)
    print_evaluation(result.evaluation)
    print(f"wrote {result.folder}/: {', '.join(result.files)}")
    return EXIT_OK if result.evaluation.all_passed else EXIT_FAIL


def _stage_printer(args):
    """A line per finished stage on stderr: on a terminal, or when --progress asks for it."""
    if args.quiet or not (args.progress or sys.stderr.isatty()):
        return None

    def stage(name: str, seconds: float) -> None:
        print(f"  {name} done ({seconds:.1f} s)", file=sys.stderr, flush=True)
    return stage


def cmd_reconcile(args) -> int:
    from .catalog import load_catalog
    from .models import resolve_gear
    from .output import json_text, staged_dir, write_text_atomic
    from .reconcile import read_data, reconcile
    catalog = load_catalog(args.catalog_overlay)
    model, model_note = resolve_gear(args.model, catalog)
    if args.kind == "vibration" and args.load_inertia is None:
        raise InputError("--load-inertia", "vibration needs the load inertia [kg·m²]")
    if args.out is not None:
        from pathlib import Path
        from .output import check_target
        check_target(Path(args.out), args.force)
    data = read_data(args.kind, args.data)
    result = reconcile(args.kind, data, model, catalog, args.load_inertia)
    if model_note:
        result.notes.insert(0, model_note)
    print_reconciliation(result)
    if args.json:
        write_text_atomic(args.json, json_text(result.as_dict()))
    if args.out:
        from .reconcile.report import write_report
        with staged_dir(args.out, args.force) as folder:
            files = write_report(result, folder)
        print(f"wrote {args.out}/: {', '.join(files)}")
    return EXIT_OK


def print_reconciliation(result) -> None:
    u = result.unit
    print(f"{result.model} {result.kind}: {len(result.series['measured'])} rows, noise RMS "
          f"{fmt(result.noise_rms)} {u} (estimated from the data)")
    for d in result.disagreements:
        print(f"  disagrees: {d['where']}: RMS {fmt(d['rms'])} {u}")
    for step in result.steps:
        params = ", ".join(f"{k} = {fmt(v['value'])} {v['unit']}".rstrip()
                           for k, v in step.params.items())
        print(f"  added {step.effect} (ΔBIC {step.criterion_gain:.1f}, RMSE "
              f"{fmt(step.rmse)} {u}): {params}")
    gain = 1 - result.rmse_after / result.rmse_before if result.rmse_before else 0.0
    print(f"missing effects: {', '.join(result.missing_effects) or 'none'}; RMSE "
          f"{fmt(result.rmse_before)} → {fmt(result.rmse_after)} {u} ({gain:.0%} less)")
    for m in result.measurement_effects:  # the rig, not the gear
        detail = m.get("reading") or ", ".join(
            f"{k} = {fmt(v['value'])} {v['unit']}".rstrip() for k, v in m["params"].items())
        print(f"  test rig: {m['effect']}: {detail}")
    for n in result.nuisances:
        print(f"  catalog scatter: {n['text']}")
    for r in result.equivalent_readings:
        print(f"  cannot tell apart: {r['text']}")
    if result.outliers:
        print(f"  {result.outliers} gross outlier(s) left out")
    for text in result.unexplained:
        print(f"  unexplained: {text}")


SERIES = ["FD", "CSF-GH", "CSG-GH", "CSF", "CSG"]


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="hdcad", description="Design guides for strain wave gears: selection checks, "
        "housings, STEP, calc sheets. Exit codes: 0 all evaluated checks pass, 1 a check "
        "fails, 2 bad input, 3 internal error, 130 interrupted.")
    parser.add_argument("--version", action="version", version=f"hdcad {__version__}")
    parser.add_argument("--debug", action="store_true",
                        help="print the traceback of an internal error (exit 3)")
    sub = parser.add_subparsers(dest="command", required=True)

    def command(name: str, func, help_: str) -> argparse.ArgumentParser:
        p = sub.add_parser(name, help=help_, description=help_,
                           formatter_class=argparse.ArgumentDefaultsHelpFormatter)
        p.add_argument("--catalog-overlay", metavar="FILE",
                       help="YAML file adding catalog rows or tables the seeds lack "
                            "(see examples/overlay_example.yaml)")
        p.add_argument("--debug", action="store_true", default=argparse.SUPPRESS,
                       help="print the traceback of an internal error (exit 3)")
        p.set_defaults(func=func)
        return p

    def force(p) -> None:
        p.add_argument("--force", action="store_true",
                       help="replace an output folder that holds files hdcad did not write "
                            "(refused otherwise, exit 2)")

    def duty(p) -> None:
        p.add_argument("--duty", required=True, metavar="FILE",
                       help="duty YAML file: load-torque cycle [N·m, s, r/min], max speeds "
                            "[r/min], required life [h], lubrication (examples/*.yaml)")

    p = command("catalog", cmd_catalog, "List catalog models with their key ratings, or "
                                        "show every value of one model.")
    p.add_argument("model", nargs="?", help="model code: show its full data, with sources "
                                            "and (gear heads) the motor-flange codes")
    p.add_argument("--series", choices=SERIES, help="only models of this series")
    p = command("check", cmd_check, "Run every selection check for one model and duty.")
    p.add_argument("model", help="model code, e.g. FD-25-80-2, CSF-45-120-GH, CSF-40-120-2A-GR")
    duty(p)
    p.add_argument("--design", metavar="FILE", help="design options YAML: its rules: block "
                                                    "changes hdcad's own rules (resonance "
                                                    "band, static safety, …)")
    p.add_argument("--json", metavar="FILE", help="also write the results as JSON")
    p = command("select", cmd_select, "Every catalog model that passes the duty, smallest first.")
    duty(p)
    p.add_argument("--series", choices=SERIES, help="only models of this series")
    p.add_argument("--json", metavar="FILE", help="also write the results as JSON")
    p.add_argument("--design-top", type=_positive_int, metavar="N",
                   help="build the design packets of the N smallest passing models into "
                        "--out DIR, in parallel, with DIR/index.html comparing them")
    p.add_argument("--out", metavar="DIR", help="output folder of --design-top: DIR/MODEL/")
    p.add_argument("--design", metavar="FILE", help="design options YAML for --design-top "
                                                    "(defaults: hdcad/design_options.py)")
    p.add_argument("--jobs", type=_positive_int, metavar="J",
                   help="parallel packet builds (default: one per core)")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="run the packet builds on a Dask cluster, e.g. tcp://host:8786 "
                        "(needs the [cluster] extra)")
    force(p)
    p = command("design", cmd_design, "Checks, housing/flange parts, STEP/STL/SVG, drawings, "
                                      "calc sheet (PDF) and results.json for one model.")
    p.add_argument("model", help="model code, e.g. FD-25-80-2, FD-25-80-0, CSF-45-120-GH")
    duty(p)
    p.add_argument("--design", metavar="FILE", help="design options YAML (defaults: "
                                                    "hdcad/design_options.py, README)")
    p.add_argument("--out", required=True, metavar="DIR", help="output folder; writes DIR/MODEL/")
    p.add_argument("--progress", action="store_true",
                   help="a line per finished stage on stderr (default on a terminal)")
    p.add_argument("--quiet", action="store_true", help="no stage lines")
    force(p)
    p = command("reconcile", cmd_reconcile, "Where measured data and the catalog model "
                                            "disagree, which effect is missing, and the gap "
                                            "with it added.")
    p.add_argument("kind", choices=["torsion", "transmission", "efficiency", "vibration"],
                   help="test kind; columns: torsion torque_Nm,twist_rad (time_s optional); transmission "
                        "input_angle_rad,output_angle_rad; efficiency input_speed_rpm,"
                        "load_torque_Nm,temperature_C,efficiency_pct; vibration time_s,"
                        "input_speed_rpm,output_vibration_rad")
    p.add_argument("data", metavar="DATA.csv", help="measured data, CSV with a header row, SI "
                                                    "units as in the column names")
    p.add_argument("--model", required=True, help="model code, e.g. CSF-32-100-GH; an FD gear "
                   "may be given without its type (FD-25-80 reads as the unit FD-25-80-0)")
    p.add_argument("--load-inertia", type=_finite_positive, metavar="KGM2",
                   help="load inertia on the output [kg·m²] (vibration only)")
    p.add_argument("--json", metavar="FILE", help="also write the result as JSON")
    p.add_argument("--out", metavar="DIR", help="write plots and report.html/.pdf into DIR")
    force(p)
    return parser


def _positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if not 1 <= value <= 10_000:
        raise argparse.ArgumentTypeError(f"must be a whole number from 1 to 10000 (got {text!r})")
    return value


def _finite_positive(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not 0 < value <= 1e6:
        raise argparse.ArgumentTypeError(f"must be a number in (0, 1e6] (got {text[:40]!r})")
    return value


def shorten(text: str, limit: int = MESSAGE_LIMIT) -> str:
    """One line of at most ``limit`` characters: newlines joined, the middle elided."""
    line = " ".join(str(text).split())
    if len(line) <= limit:
        return line
    half = (limit - 5) // 2
    return f"{line[:half]} … {line[-half:]}"


_interrupted = False


def _on_interrupt(signum, frame) -> None:
    # remembered: an interrupt inside a C extension's import can surface as ImportError;
    # later interrupts are ignored so that the clean-up (staging folder, workers) finishes
    global _interrupted
    _interrupted = True
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    raise KeyboardInterrupt


def main(argv: Sequence[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    debug = "--debug" in argv
    if signal.getsignal(signal.SIGINT) in (signal.default_int_handler, _entry.remember):
        signal.signal(signal.SIGINT, _on_interrupt)
    try:
        if _entry.caught:  # Ctrl-C while the command line was loading
            raise KeyboardInterrupt
        args = _parser().parse_args(argv)
        if getattr(args, "design_top", None) and not args.out:
            raise InputError("--design-top", "needs --out DIR for the packets")
        return args.func(args)
    except InputError as exc:
        print(f"hdcad: error: {shorten(exc)}", file=sys.stderr)
        return EXIT_INPUT
    except KeyboardInterrupt:
        print("hdcad: interrupted", file=sys.stderr)
        _entry.reported.append(True)
        return EXIT_INTERRUPTED
    except BrokenPipeError:
        # the reader closed the pipe (`hdcad catalog | head`): what it wanted was printed
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return EXIT_OK
    except SystemExit as exc:  # argparse: exit 2 on bad arguments, 0 after --help
        return exc.code if isinstance(exc.code, int) else EXIT_INPUT
    except Exception as exc:  # noqa: BLE001 - the contract: never a bare traceback
        if _interrupted:
            print("hdcad: interrupted", file=sys.stderr)
            _entry.reported.append(True)
            return EXIT_INTERRUPTED
        if debug:
            import traceback
            traceback.print_exc()
        print(f"hdcad: internal error: {shorten(f'{type(exc).__name__}: {exc}', 200)}"
              + ("" if debug else " (run with --debug for the traceback)"), file=sys.stderr)
        return EXIT_INTERNAL


if __name__ == "__main__":
    # the console command's entry (a Ctrl-C still pending once main has answered must not
    # end in a death by SIGINT) for ``python -m hdcad.cli`` too
    _entry.leave(_entry.run())
