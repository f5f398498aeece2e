#!/usr/bin/python3
"""Plots of a ``tangle run`` results directory.

Command line (Debian's Python, which has numpy and matplotlib)::

    /usr/bin/python3 python/tangle_plot.py RESULTS_DIR [--out DIR]

writes PNG files to ``DIR`` (default ``RESULTS_DIR/plots``):

===============================  ==============================================================
input (under RESULTS_DIR)        plot
===============================  ==============================================================
``statics/<line>.csv``           ``statics_<line>.png``: profile (with the seabed when
                                 ``summary.json`` gives ``water_depth_m``), effective tension
                                 and bending moment along the line
``dynamics/<line>/range.csv``    ``range_<line>.png``: min / max envelope and mean of tension,
                                 bending moment and curvature along the line
``dynamics/end_forces.csv``      ``end_tensions.png``: tension at each line end vs time
``contact/events.csv``           ``clash_events.png``: impact energy and peak force per clash
``contact/clearance.csv``        ``clearance.png``: minimum clearance vs time per line pair
``clearance/envelope.csv``       ``clearance_envelope.png``: static and minimum dynamic clearance
                                 along each line of each assessed pair, with the required
                                 clearance of ``clearance/summary.json`` (DNV-RP-F203)
===============================  ==============================================================

Parts whose input file does not exist are skipped silently. A file that exists but cannot be
read or plotted is reported on stderr; the other plots are still made and the exit status is 1.

Importable: every plot has a ``*_figure`` function that returns a matplotlib ``Figure`` (built
without pyplot, so importing this module changes no global matplotlib state) and a ``plot_*``
function that reads the CSV and writes the PNG. ``plot_results`` does the whole directory::

    import sys; sys.path.insert(0, "python")
    import tangle_plot
    written = tangle_plot.plot_results("out/my_run")

Units: the CSV files are SI (N, N m, m, s); plots show forces in kN and moments in kN m.
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import re
import sys
from pathlib import Path
from typing import Any, Iterable

import matplotlib
import numpy as np
from matplotlib.figure import Figure

__all__ = [
    "read_csv",
    "read_summary",
    "water_depth",
    "horizontal_distance",
    "statics_figure",
    "range_figure",
    "end_tensions_figure",
    "clash_events_figure",
    "clearance_figure",
    "clearance_envelope_figure",
    "plot_statics",
    "plot_range",
    "plot_end_tensions",
    "plot_clash_events",
    "plot_clearance",
    "plot_clearance_envelope",
    "plot_results",
    "main",
]

KN = 1.0e-3  # N -> kN
DPI = 120

# A cable line's tables have no bending moment columns (it has none): its figures leave that panel out.
STATICS_COLUMNS = (
    "arc_length_m",
    "x_m",
    "y_m",
    "z_m",
    "effective_tension_N",
    "curvature_1_per_m",
)
RANGE_COLUMNS = (
    "arc_length_m",
    "tension_min_N",
    "tension_max_N",
    "tension_mean_N",
    "curvature_min_1_per_m",
    "curvature_max_1_per_m",
    "curvature_mean_1_per_m",
)
EVENTS_COLUMNS = ("start_time_s", "line_1", "line_2", "peak_force_N", "impact_energy_J")
CLEARANCE_COLUMNS = ("time_s", "pair", "min_clearance_m")
ENVELOPE_COLUMNS = ("line", "other_line", "arc_length_m", "static_clearance_m", "min_clearance_m")

Table = dict  # column name -> numpy array (float, or object for text columns)


# --------------------------------------------------------------------------------------------
# Reading


def read_csv(path: str | Path, text: Iterable[str] = ()) -> Table:
    """Reads a CSV file with a header row into ``{column: numpy array}``.

    Columns whose every value parses as a number become float arrays (empty cells become NaN);
    the others, and the columns named in ``text`` (e.g. line names, which may look like numbers),
    stay arrays of stripped strings. Blank lines are ignored. Raises ``ValueError``
    naming the file and row on an empty file, a repeated column name or a row of the wrong length.
    """
    path = Path(path)
    with path.open(newline="", encoding="utf-8") as f:
        rows = [(n, r) for n, r in enumerate(csv.reader(f), start=1) if any(c.strip() for c in r)]
    if not rows:
        raise ValueError(f"{path}: empty file (no header row)")
    header = [h.strip() for h in rows[0][1]]
    if len(set(header)) != len(header):
        raise ValueError(f"{path}: repeated column name in header {header}")
    columns: list[list[str]] = [[] for _ in header]
    for n, row in rows[1:]:
        if len(row) != len(header):
            raise ValueError(f"{path}:{n}: expected {len(header)} fields, found {len(row)}")
        for c, value in enumerate(row):
            columns[c].append(value.strip())
    text = set(text)
    table: Table = {}
    for name, values in zip(header, columns):
        if name in text:
            table[name] = np.array(values, dtype=object)
            continue
        try:
            table[name] = np.array([float(v) if v else math.nan for v in values], dtype=float)
        except ValueError:
            table[name] = np.array(values, dtype=object)
    return table


def _require(table: Table, columns: Iterable[str], path: Any) -> None:
    missing = [c for c in columns if c not in table]
    if missing:
        raise ValueError(f"{path}: missing column(s) {', '.join(missing)}")


def _numeric(table: Table, name: str, path: Any) -> np.ndarray:
    values = table[name]
    if values.dtype == object:
        raise ValueError(f"{path}: column {name} is not numeric")
    return values


def read_summary(results_dir: str | Path) -> dict:
    """Returns the parsed ``summary.json`` of a results directory, or ``{}`` when it is absent."""
    path = Path(results_dir) / "summary.json"
    if not path.is_file():
        return {}
    with path.open(encoding="utf-8") as f:
        return json.load(f)


def water_depth(summary: Any) -> float | None:
    """The first ``water_depth_m`` found in a summary (searched at any depth), or None.

    Only a finite positive number counts.
    """
    if isinstance(summary, dict):
        value = summary.get("water_depth_m")
        if isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value) and value > 0:
            return float(value)
        children = summary.values()
    elif isinstance(summary, list):
        children = summary
    else:
        return None
    for child in children:
        found = water_depth(child)
        if found is not None:
            return found
    return None


def horizontal_distance(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Horizontal distance [m] of each node from the first one, measured along the line's plane.

    The plane is the vertical plane through the best-fit horizontal direction of the nodes
    (principal axis of their x, y), oriented so the distance grows from the first node to the
    last. For a planar catenary this is the usual profile abscissa. All zeros for a line whose
    nodes share one x, y (a vertical line).
    """
    xy = np.column_stack([np.asarray(x, dtype=float), np.asarray(y, dtype=float)])
    if len(xy) < 2:
        return np.zeros(len(xy))
    centred = xy - xy.mean(axis=0)
    if not np.any(np.abs(centred) > 0):
        return np.zeros(len(xy))
    direction = np.linalg.svd(centred, full_matrices=False)[2][0]
    s = (xy - xy[0]) @ direction
    if s[-1] < 0 or (s[-1] == 0 and np.sum(s) < 0):
        s = -s
    return s


# --------------------------------------------------------------------------------------------
# Figures


def _finish(ax, xlabel: str, ylabel: str) -> None:
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)


def _no_data(fig: Figure, message: str) -> Figure:
    ax = fig.subplots()
    ax.text(0.5, 0.5, message, ha="center", va="center", transform=ax.transAxes)
    ax.set_axis_off()
    return fig


def statics_figure(table: Table, name: str = "", depth: float | None = None) -> Figure:
    """Static configuration of one line from a ``statics/<line>.csv`` table: profile (with the
    seabed at ``z = -depth`` when ``depth`` [m] is given), effective tension and (a line with
    bending stiffness) bending moment vs arc length."""
    _require(table, STATICS_COLUMNS, name or "statics table")
    s = _numeric(table, "arc_length_m", name)
    z = _numeric(table, "z_m", name)
    h = horizontal_distance(_numeric(table, "x_m", name), _numeric(table, "y_m", name))

    bending = "bending_moment_Nm" in table
    fig = Figure(figsize=(8.0, 10.0 if bending else 7.0), layout="constrained")
    fig.suptitle(f"Statics: {name}" if name else "Statics")
    axes = fig.subplots(3 if bending else 2, 1)
    ax_profile, ax_tension = axes[0], axes[1]

    ax_profile.plot(h, z, color="C0", marker=".", markersize=3, label=name or "line")
    if len(h):
        ax_profile.axhline(0.0, color="tab:blue", linestyle=":", linewidth=1.0, label="still water level")
    if depth is not None:
        ax_profile.axhline(-depth, color="saddlebrown", linewidth=1.5, label=f"seabed (depth {depth:g} m)")
    _finish(ax_profile, "horizontal distance from end A, in the line's plane [m]", "z [m]")
    ax_profile.set_title("Profile")
    ax_profile.legend(loc="best", fontsize="small")

    ax_tension.plot(s, _numeric(table, "effective_tension_N", name) * KN, color="C1", label="effective tension")
    if "wall_tension_N" in table:  # a pipe (its line type has a bore): the wall tension beside it
        ax_tension.plot(s, _numeric(table, "wall_tension_N", name) * KN, color="C4", linestyle="--",
                        label="wall tension")
        ax_tension.legend(loc="best", fontsize="small")
        _finish(ax_tension, "arc length from end A [m]", "tension [kN]")
        ax_tension.set_title("Effective and wall tension")
    else:
        _finish(ax_tension, "arc length from end A [m]", "effective tension [kN]")
        ax_tension.set_title("Effective tension")

    if bending:
        axes[2].plot(s, _numeric(table, "bending_moment_Nm", name) * KN, color="C2")
        _finish(axes[2], "arc length from end A [m]", "bending moment [kN m]")
        axes[2].set_title("Bending moment")
    return fig


def range_figure(table: Table, name: str = "") -> Figure:
    """Range graphs of one line from a ``dynamics/<line>/range.csv`` table: min / max envelope
    (shaded) and mean of tension, bending moment (a line with bending stiffness) and curvature vs arc
    length, and the smallest seabed clearance over the run where the table has it."""
    _require(table, RANGE_COLUMNS, name or "range table")
    s = _numeric(table, "arc_length_m", name)
    quantities = [("tension", "N", KN, "effective tension [kN]", "C1")]
    if "wall_tension_min_N" in table:  # a pipe (its line type has a bore)
        quantities.append(("wall_tension", "N", KN, "wall tension [kN]", "C4"))
    if "bending_moment_min_Nm" in table:
        quantities.append(("bending_moment", "Nm", KN, "bending moment [kN m]", "C2"))
    quantities.append(("curvature", "1_per_m", 1.0, "curvature [1/m]", "C3"))
    if "seabed_clearance_min_m" in table:  # the smallest clearance to the seabed over the run
        quantities.append(("seabed_clearance", "m", 1.0, "min. seabed clearance [m]", "C5"))
    fig = Figure(figsize=(8.0, 3.3 * len(quantities) + 0.4), layout="constrained")
    fig.suptitle(f"Dynamic range: {name}" if name else "Dynamic range")
    axes = fig.subplots(len(quantities), 1, sharex=True)
    for ax, (quantity, unit, scale, label, color) in zip(axes, quantities):
        if quantity == "seabed_clearance":
            ax.plot(s, _numeric(table, "seabed_clearance_min_m", name), color=color, linewidth=1.8,
                    label="minimum over the run (0: on the seabed)")
            _finish(ax, "arc length from end A [m]" if ax is axes[-1] else "", label)
            ax.legend(loc="best", fontsize="small")
            continue
        lo = _numeric(table, f"{quantity}_min_{unit}", name) * scale
        hi = _numeric(table, f"{quantity}_max_{unit}", name) * scale
        mean = _numeric(table, f"{quantity}_mean_{unit}", name) * scale
        ax.fill_between(s, lo, hi, color=color, alpha=0.25, linewidth=0, label="min to max")
        ax.plot(s, lo, color=color, linewidth=0.8, alpha=0.8)
        ax.plot(s, hi, color=color, linewidth=0.8, alpha=0.8)
        ax.plot(s, mean, color=color, linewidth=1.8, label="mean")
        _finish(ax, "arc length from end A [m]" if ax is axes[-1] else "", label)
        ax.legend(loc="best", fontsize="small")
    return fig


_END_COLUMN = re.compile(r"^(?P<line>.*)_end_(?P<end>[ab])_tension_N$")


def _end_label(column: str) -> str:
    m = _END_COLUMN.match(column)
    if m:
        return f"{m['line']} end {m['end'].upper()}"
    return column


def end_tensions_figure(table: Table) -> Figure:
    """Tension [kN] at every line end vs time from a ``dynamics/end_forces.csv`` table: the
    ``<line>_end_<a|b>_tension_N`` columns only (the signed force components beside them are not tensions),
    one colour per line, end A solid and end B dashed."""
    _require(table, ("time_s",), "end forces table")
    t = _numeric(table, "time_s", "end forces table")
    columns = [c for c in table if _END_COLUMN.match(c) and table[c].dtype != object]
    fig = Figure(figsize=(10.0, 5.5), layout="constrained")
    if not columns:
        return _no_data(fig, "no end tension columns")
    ax = fig.subplots()
    lines = list(dict.fromkeys(_END_COLUMN.match(c)["line"] for c in columns))
    palette = matplotlib.colormaps["tab10" if len(lines) <= 10 else "tab20"]
    for column in columns:
        m = _END_COLUMN.match(column)
        colour = palette(lines.index(m["line"]) % palette.N)
        ax.plot(t, table[column] * KN, linewidth=1.0, color=colour, linestyle="-" if m["end"] == "a" else "--",
                label=_end_label(column))
    _finish(ax, "time [s]", "tension [kN]")
    ax.set_title("Line end tensions")
    ax.legend(loc="best", fontsize="small", ncol=max(1, (len(columns) + 7) // 8))
    return fig


def _pairs(first: np.ndarray, second: np.ndarray | None = None) -> tuple[list[str], list[str]]:
    """(distinct pair labels in order of first appearance, the label of every row)."""
    labels = [f"{a} / {b}" for a, b in zip(first, second)] if second is not None else [str(a) for a in first]
    return list(dict.fromkeys(labels)), labels


def clash_events_figure(table: Table) -> Figure:
    """Impact energy [J] and peak contact force [kN] of every clash event vs its start time, one
    colour per line pair, from a ``contact/events.csv`` table."""
    _require(table, EVENTS_COLUMNS, "clash events table")
    t = _numeric(table, "start_time_s", "events")
    energy = _numeric(table, "impact_energy_J", "events")
    force = _numeric(table, "peak_force_N", "events") * KN
    fig = Figure(figsize=(10.0, 7.0), layout="constrained")
    if len(t) == 0:
        return _no_data(fig, "no clash events")
    fig.suptitle(f"Clash events ({len(t)})")
    ax_energy, ax_force = fig.subplots(2, 1, sharex=True)
    unique, labels = _pairs(table["line_1"], table["line_2"])
    labels = np.array(labels, dtype=object)
    for k, pair in enumerate(unique):
        sel = labels == pair
        color = f"C{k % 10}"
        for ax, values in ((ax_energy, energy), (ax_force, force)):
            ax.vlines(t[sel], 0.0, values[sel], color=color, linewidth=0.8, alpha=0.6)
            ax.plot(t[sel], values[sel], linestyle="none", marker="o", markersize=4, color=color, label=pair)
    _finish(ax_energy, "", "impact energy [J]")
    _finish(ax_force, "event start time [s]", "peak contact force [kN]")
    ax_energy.set_ylim(bottom=0.0)
    ax_force.set_ylim(bottom=0.0)
    ax_energy.legend(loc="best", fontsize="small", title="line pair")
    return fig


def clearance_figure(table: Table) -> Figure:
    """Minimum clearance [m] vs time for every line pair from a ``contact/clearance.csv`` table;
    the legend gives each pair's smallest clearance and when it occurs. Negative means overlap."""
    _require(table, CLEARANCE_COLUMNS, "clearance table")
    t = _numeric(table, "time_s", "clearance")
    d = _numeric(table, "min_clearance_m", "clearance")
    fig = Figure(figsize=(10.0, 5.5), layout="constrained")
    if len(t) == 0:
        return _no_data(fig, "no clearance data")
    ax = fig.subplots()
    unique, labels = _pairs(table["pair"])
    labels = np.array(labels, dtype=object)
    title = "Line-to-line clearance"
    if len(unique) > MAX_PAIR_CURVES:
        # A model of many lines: the pairs that come nearest (a legend of thousands is no plot).
        nearest = {p: np.nanmin(np.where(labels == p, d, np.inf)) for p in unique}
        unique = sorted(unique, key=lambda p: nearest[p])[:MAX_PAIR_CURVES]
        title += f" (the {MAX_PAIR_CURVES} nearest of {len(nearest)} pairs)"
    for k, pair in enumerate(unique):
        sel = labels == pair
        tp, dp = t[sel], d[sel]
        order = np.argsort(tp, kind="stable")
        tp, dp = tp[order], dp[order]
        color = f"C{k % 10}"
        if np.all(np.isnan(dp)):
            ax.plot(tp, dp, color=color, label=f"{pair} (no data)")
            continue
        i = int(np.nanargmin(dp))
        ax.plot(tp, dp, color=color, linewidth=1.0, label=f"{pair} (min {dp[i]:.3g} m at t = {tp[i]:.4g} s)")
        ax.plot(tp[i], dp[i], marker="v", color=color, markersize=6)
    ax.axhline(0.0, color="black", linewidth=0.8, linestyle="--")
    _finish(ax, "time [s]", "minimum clearance [m]")
    ax.set_title(title)
    ax.legend(loc="best", fontsize="small")
    return fig


MAX_PAIR_CURVES = 10       # clearance.png: the pairs that come nearest, beyond this many pairs
MAX_ENVELOPE_PANELS = 12   # clearance_envelope.png: the sides with the smallest clearance, beyond this many
MAX_LINE_FIGURES = 100     # statics_<line>.png and range_<line>.png: the first lines, beyond this many
MAX_PATH_EVENTS = 3        # drift_path.png: the paths of the lines' points hit in the first events


def clearance_envelope_figure(table: Table, required: float | None = None) -> Figure:
    """Clearance [m] along each line of each assessed pair from a ``clearance/envelope.csv`` table: the
    static clearance (dashed) and the minimum over the dynamics (solid), one panel per line, with the
    required clearance (DNV-RP-F203 no-collision criterion) as a red line when given."""
    _require(table, ENVELOPE_COLUMNS, "clearance envelope table")
    arc = _numeric(table, "arc_length_m", "clearance envelope")
    static = _numeric(table, "static_clearance_m", "clearance envelope")
    dynamic = _numeric(table, "min_clearance_m", "clearance envelope")
    fig = Figure(figsize=(10.0, 6.0), layout="constrained")
    if len(arc) == 0:
        return _no_data(fig, "no clearance envelope data")
    sides = np.array([f"{a} to {b}" for a, b in zip(table["line"], table["other_line"])], dtype=object)
    unique = list(dict.fromkeys(sides))
    if len(unique) > MAX_ENVELOPE_PANELS:
        # A model of many lines: the sides with the smallest clearance (static or dynamic), one panel each.
        smallest = {side: np.nanmin(np.fmin(static[sides == side], dynamic[sides == side])) for side in unique}
        unique = sorted(unique, key=lambda side: smallest[side])[:MAX_ENVELOPE_PANELS]
        fig.suptitle(f"Clearance envelope: the {MAX_ENVELOPE_PANELS} sides with the smallest clearance of "
                     f"{len(smallest)} (clearance/summary.json has every pair)")
        fig.set_size_inches(10.0, 2.2 * MAX_ENVELOPE_PANELS)
    axes = np.atleast_1d(fig.subplots(len(unique), 1, sharex=False, squeeze=False)[:, 0])
    for ax, side in zip(axes, unique):
        sel = sides == side
        order = np.argsort(arc[sel], kind="stable")
        a, st, dy = arc[sel][order], static[sel][order], dynamic[sel][order]
        ax.plot(a, st, color="C0", linestyle="--", linewidth=1.0, label=f"static (min {np.nanmin(st):.3g} m)")
        if not np.all(np.isnan(dy)):
            ax.plot(a, dy, color="C1", linewidth=1.2, label=f"dynamic minimum (min {np.nanmin(dy):.3g} m)")
        if required is not None and required > 0.0:
            ax.axhline(required, color="red", linewidth=1.0, label=f"required {required:.3g} m")
        _finish(ax, "arc length from end A [m]", "clearance [m]")
        ax.set_title(f"Clearance from '{side.split(' to ')[0]}' to '{side.split(' to ')[1]}'")
        ax.legend(loc="best", fontsize="small")
    return fig


# --------------------------------------------------------------------------------------------
# Files


# CSV time-history names -> (dataset in results.h5 under /dynamics/lines/<line>/, component or None).
_H5_QUANTITIES = {
    "x_m": ("position", 0), "y_m": ("position", 1), "z_m": ("position", 2),
    "effective_tension_N": ("effective_tension", None), "bending_moment_Nm": ("bending_moment", None),
    "curvature_1_per_m": ("curvature", None), "torque_Nm": ("torque", None),
    "wall_tension_N": ("wall_tension", None),
    "bending_moment_x_Nm": ("bending_moment_vector", 0), "bending_moment_y_Nm": ("bending_moment_vector", 1),
    "bending_moment_z_Nm": ("bending_moment_vector", 2),
}


def _line_history(results: Path, line: str, quantity: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Time history of one quantity along a line: (times [s], arc lengths [m], values[time, node]), from
    ``dynamics/<line>/<quantity>.csv`` or, when the run wrote HDF5 only (output.format), ``results.h5``."""
    path = results / "dynamics" / line / f"{quantity}.csv"
    if not path.exists() and (results / "results.h5").exists():
        import h5py  # Debian's python3-h5py; only needed for HDF5-only runs

        name, component = _H5_QUANTITIES[quantity]
        with h5py.File(results / "results.h5", "r") as f:
            g = f["dynamics/lines"][line]
            values = g[name][...] if component is None else g[name][:, :, component]
            return f["dynamics/time"][...], g["arc_length"][...], np.asarray(values, dtype=float)
    raw = np.genfromtxt(path, delimiter=",", names=None, skip_header=1)
    raw = np.atleast_2d(raw)
    with open(path, encoding="utf-8") as f:
        header = f.readline().strip().split(",")
    arcs = np.array([float(h[2:-1]) for h in header[1:]])  # "s=12.500m"
    return raw[:, 0], arcs, raw[:, 1:]


def _interp_along(arcs: np.ndarray, values: np.ndarray, arc: float) -> float:
    return float(np.interp(arc, arcs, values))


def drift_path_figure(results: Path) -> Figure:
    """XY path of every free vessel and of the contact points (from the clash report), in plan; the kind of
    figure of the seed paper's Fig. 11 (which shows the riser's contact path after the collision)."""
    vessels = read_csv(results / "dynamics" / "vessels.csv")
    fig = Figure(figsize=(8, 7))
    ax = fig.add_subplot(1, 1, 1)
    # Vessel names from their x columns; "<name>_wf_x_m" is a vessel's wave-frequency motion, not a vessel.
    names = [c[: -len("_x_m")] for c in vessels if c.endswith("_x_m") and not c.endswith("_wf_x_m")]
    for name in names:
        x = _numeric(vessels, f"{name}_x_m", "vessels.csv")
        y = _numeric(vessels, f"{name}_y_m", "vessels.csv")
        if np.ptp(x) + np.ptp(y) < 1e-6:
            ax.plot(x[:1], y[:1], "s", color="0.3", label=f"{name} (fixed)")
            continue
        ax.plot(x, y, "-", lw=2, label=f"{name} path")
        ax.plot(x[0], y[0], "o", color="k")
        ax.annotate("t = 0", (x[0], y[0]), textcoords="offset points", xytext=(5, 5))
    paths = results / "contact" / "event_paths.csv"
    events = results / "contact" / "events.csv"
    xs: list = []
    ys: list = []
    if paths.is_file() and events.is_file():
        ev = read_csv(events, text=("line_1", "line_2"))
        pt = read_csv(paths)
        line1 = {int(i): str(n) for i, n in zip(ev["event"], ev["line_1"])}
        cache: dict = {}
        for event, t, arc in zip(_numeric(pt, "event", paths), _numeric(pt, "time_s", paths), _numeric(pt, "arc_1_m", paths)):
            line = line1.get(int(event))
            if line is None:
                continue
            if line not in cache:
                cache[line] = (_line_history(results, line, "x_m"), _line_history(results, line, "y_m"))
            (times, arcs, xv), (_, _, yv) = cache[line]
            k = int(np.argmin(np.abs(times - t)))
            xs.append(_interp_along(arcs, xv[k], arc))
            ys.append(_interp_along(arcs, yv[k], arc))
        if xs:
            ax.plot(xs, ys, ".", color="tab:red", ms=4, label="contact point")
        # The paper's Fig. 11 plots the riser's point where it is hit, before and after: the path of the
        # material point of each line where each of the first events started, over the whole run (its turn
        # at the collision is the riser's, not the vessel's).
        starts = read_csv(events, text=("line_1", "line_2"))
        for k in range(min(MAX_PATH_EVENTS, len(starts.get("event", [])))):
            for line_key, arc_key in (("line_1", "arc_1_start_m"), ("line_2", "arc_2_start_m")):
                if arc_key not in starts:
                    continue
                line, arc = str(starts[line_key][k]), float(starts[arc_key][k])
                try:
                    if line not in cache:
                        cache[line] = (_line_history(results, line, "x_m"), _line_history(results, line, "y_m"))
                except OSError:
                    continue
                (_, arcs, xv), (_, _, yv) = cache[line]
                px = [_interp_along(arcs, row, arc) for row in xv]
                py = [_interp_along(arcs, row, arc) for row in yv]
                ax.plot(px, py, "--", lw=1, label=f"{line} at {arc:.0f} m (event {k})")
                xs.extend(px)
                ys.extend(py)
    # The lines at the end of the run, in plan.
    for line_dir in sorted(p for p in (results / "dynamics").iterdir() if p.is_dir()):
        try:
            _, _, xv = _line_history(results, line_dir.name, "x_m")
            _, _, yv = _line_history(results, line_dir.name, "y_m")
        except OSError:
            continue
        ax.plot(xv[-1], yv[-1], "-", color="0.6", lw=0.8)
    # Zoom on the moving vessels (the lines run off the figure).
    moving = [(_numeric(vessels, f"{n}_x_m", "v"), _numeric(vessels, f"{n}_y_m", "v")) for n in names]
    moving = [(x, y) for x, y in moving if np.ptp(x) + np.ptp(y) >= 1e-6]
    if moving:
        allx = np.concatenate([x for x, _ in moving] + ([np.array(xs)] if paths.is_file() and xs else []))
        ally = np.concatenate([y for _, y in moving] + ([np.array(ys)] if paths.is_file() and ys else []))
        half = 0.5 * max(np.ptp(allx), np.ptp(ally), 20.0) * 1.4
        cx, cy = 0.5 * (allx.min() + allx.max()), 0.5 * (ally.min() + ally.max())
        ax.set_xlim(cx - half, cx + half)
        ax.set_ylim(cy - half, cy + half)
    ax.set_aspect("equal", adjustable="box")
    ax.set_title("Paths of the moving vessels and of the contact points (plan view)")
    ax.legend(loc="best", fontsize="small")
    _finish(ax, "x [m]", "y [m]")
    return fig


def peak_bending_figure(results: Path, line: str) -> Figure:
    """Paper Fig. 12: bending moment along a line at the instant of its peak bending moment."""
    times, arcs, moments = _line_history(results, line, "bending_moment_Nm")
    k, node = np.unravel_index(int(np.argmax(moments)), moments.shape)
    fig = Figure(figsize=(8, 5))
    ax = fig.add_subplot(1, 1, 1)
    ax.plot(arcs, moments[k] / 1000.0, "-", lw=2, label=f"t = {times[k]:.2f} s")
    ax.plot(arcs[node], moments[k, node] / 1000.0, "v", color="tab:red",
            label=f"peak {moments[k, node] / 1000.0:.1f} kN m at {arcs[node]:.1f} m")
    ax.set_title(f"Bending moment along '{line}' at the instant of peak moment (cf. paper Fig. 12)")
    ax.legend(loc="best")
    _finish(ax, "arc length from end A [m]", "bending moment [kN m]")
    return fig


def _save(fig: Figure, out_png: str | Path) -> Path:
    out_png = Path(out_png)
    out_png.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out_png, dpi=DPI, format="png")
    return out_png


def plot_statics(csv_path: str | Path, out_png: str | Path, depth: float | None = None, name: str | None = None) -> Path:
    """Reads ``statics/<line>.csv`` and writes the statics figure to ``out_png``; returns its path."""
    csv_path = Path(csv_path)
    return _save(statics_figure(read_csv(csv_path), name or csv_path.stem, depth), out_png)


def plot_range(csv_path: str | Path, out_png: str | Path, name: str | None = None) -> Path:
    """Reads ``dynamics/<line>/range.csv`` and writes the range graphs to ``out_png``."""
    csv_path = Path(csv_path)
    return _save(range_figure(read_csv(csv_path), name or csv_path.parent.name), out_png)


def plot_end_tensions(csv_path: str | Path, out_png: str | Path) -> Path:
    """Reads ``dynamics/end_forces.csv`` and writes the end tension time histories to ``out_png``."""
    return _save(end_tensions_figure(read_csv(csv_path)), out_png)


def plot_clash_events(csv_path: str | Path, out_png: str | Path) -> Path:
    """Reads ``contact/events.csv`` and writes the clash event plot to ``out_png``."""
    return _save(clash_events_figure(read_csv(csv_path, text=("line_1", "line_2"))), out_png)


def plot_clearance(csv_path: str | Path, out_png: str | Path) -> Path:
    """Reads ``contact/clearance.csv`` and writes the clearance plot to ``out_png``."""
    return _save(clearance_figure(read_csv(csv_path, text=("pair",))), out_png)


def plot_clearance_envelope(csv_path: str | Path, out_png: str | Path) -> Path:
    """Reads ``clearance/envelope.csv`` (and the required clearance from ``summary.json`` beside it)
    and writes the clearance envelope plot to ``out_png``."""
    csv_path = Path(csv_path)
    required = None
    summary = csv_path.parent / "summary.json"
    if summary.is_file():
        required = float(json.loads(summary.read_text(encoding="utf-8")).get("required_clearance_m", 0.0))
    table = read_csv(csv_path, text=("line", "other_line"))
    return _save(clearance_envelope_figure(table, required), out_png)


def plot_results(results_dir: str | Path, out_dir: str | Path | None = None, errors: list | None = None) -> list[Path]:
    """Makes every plot whose input exists in ``results_dir``; returns the PNG paths written.

    ``out_dir`` defaults to ``results_dir/plots``. A file that exists but fails to plot does not
    stop the others: its ``(path, exception)`` is appended to ``errors`` when a list is given,
    and re-raised (after the other plots) when not.
    """
    results = Path(results_dir)
    out = Path(out_dir) if out_dir is not None else results / "plots"
    written: list[Path] = []
    failures: list[tuple[Path, Exception]] = []

    def attempt(source: Path, make) -> None:
        try:
            written.append(make())
        except Exception as exc:  # noqa: BLE001 - reported to the caller, other plots go on
            failures.append((source, exc))

    summary: dict = {}
    summary_path = results / "summary.json"
    try:
        summary = read_summary(results)
    except (OSError, ValueError) as exc:
        failures.append((summary_path, exc))
    depth = water_depth(summary)

    statics_dir = results / "statics"
    if statics_dir.is_dir():
        # The line tables are the files the summary names; statics/contact_*.csv are contact results.
        stems = {line.get("file_stem") for line in summary.get("lines", []) if isinstance(line, dict)}
        tables = [p for p in sorted(statics_dir.glob("*.csv"))
                  if not (stems - {None} and p.stem not in stems)
                  and not (not stems - {None} and p.stem in ("contact_points", "contact_zones", "contact_pairs"))]
        # A model of many lines: a figure per line for the first MAX_LINE_FIGURES (in name order), and a note;
        # thousands of figures took longer than the run (2000 lines: more than 10 minutes).
        if len(tables) > MAX_LINE_FIGURES:
            print(f"tangle_plot: {len(tables)} lines: statics and range figures of the first {MAX_LINE_FIGURES} "
                  f"only (plot_statics / plot_range make any other)", file=sys.stderr)
        for csv_path in tables[:MAX_LINE_FIGURES]:
            attempt(csv_path, lambda p=csv_path: plot_statics(p, out / f"statics_{p.stem}.png", depth))

    dynamics_dir = results / "dynamics"
    if dynamics_dir.is_dir():
        for line_dir in sorted(p for p in dynamics_dir.iterdir() if p.is_dir())[:MAX_LINE_FIGURES]:
            csv_path = line_dir / "range.csv"
            if csv_path.is_file():
                attempt(csv_path, lambda p=csv_path: plot_range(p, out / f"range_{p.parent.name}.png"))
        end_forces = dynamics_dir / "end_forces.csv"
        if end_forces.is_file():
            attempt(end_forces, lambda: plot_end_tensions(end_forces, out / "end_tensions.png"))

    events = results / "contact" / "events.csv"
    if events.is_file():
        attempt(events, lambda: plot_clash_events(events, out / "clash_events.png"))
    clearance = results / "contact" / "clearance.csv"
    if clearance.is_file():
        attempt(clearance, lambda: plot_clearance(clearance, out / "clearance.png"))

    envelope = results / "clearance" / "envelope.csv"
    if envelope.is_file():
        attempt(envelope, lambda: plot_clearance_envelope(envelope, out / "clearance_envelope.png"))

    if (dynamics_dir / "vessels.csv").is_file():
        attempt(dynamics_dir / "vessels.csv", lambda: _save(drift_path_figure(results), out / "drift_path.png"))
    if events.is_file():
        # Peak bending moment of the line hit second in each pair (line_2) that has bending stiffness.
        try:
            second = sorted(set(str(v) for v in read_csv(events, text=("line_1", "line_2"))["line_2"]))
        except (OSError, ValueError, KeyError):
            second = []
        for line in second:
            bm = dynamics_dir / line / "bending_moment_Nm.csv"
            if bm.is_file():
                attempt(bm, lambda l=line: _save(peak_bending_figure(results, l), out / f"peak_bending_{l}.png"))

    if errors is not None:
        errors.extend(failures)
    elif failures:
        source, exc = failures[0]
        raise RuntimeError(f"{source}: {exc}") from exc
    return written


def main(argv: list[str] | None = None) -> int:
    """Command-line entry point; returns the exit status (0 ok, 1 some plot failed, 2 bad usage)."""
    import matplotlib

    matplotlib.use("Agg")
    parser = argparse.ArgumentParser(
        prog="tangle_plot.py",
        description="Write PNG plots of a `tangle run` results directory "
        "(statics, dynamic ranges, end tensions, clash events, clearance).",
    )
    parser.add_argument("results_dir", type=Path, help="output directory of `tangle run`")
    parser.add_argument("--out", type=Path, default=None, help="where to write the PNGs (default RESULTS_DIR/plots)")
    args = parser.parse_args(argv)

    if not args.results_dir.is_dir():
        print(f"tangle_plot: {args.results_dir}: not a directory", file=sys.stderr)
        return 2
    errors: list = []
    written = plot_results(args.results_dir, args.out, errors)
    for path in written:
        print(path)
    for source, exc in errors:
        print(f"tangle_plot: skipped {source}: {exc}", file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
