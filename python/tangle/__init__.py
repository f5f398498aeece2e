"""tangle: nonlinear static and dynamic analysis of offshore lines with line-to-line contact.

Scripting interface (docs/python.md)::

    import tangle
    model = tangle.Model.load("examples/mooring-dynamics/model.yaml")
    model.set("environment.current", {"speed": 1.0, "azimuth": 90})   # checked at once by the reader
    model.set("dynamics.duration", 60)
    statics = model.run_statics()                # StaticResults
    print(statics.lines["mooring1"]["end_b_tension_N"])
    run = model.run_dynamics(progress=lambda t, T: print(f"{t:.0f}/{T:.0f} s"))
    tension = run.lines["mooring1"]["effective_tension_N"]   # numpy array [time, node], N

Units are SI (m, kg, N, s) everywhere in results; the model itself is in the units of the model file
(angles in degrees). Every key of a result says its unit (``_m``, ``_N``, ``_Nm``, ``_1_per_m``, ``_s``,
``_deg``). Runs release the GIL, so several models can run side by side in threads.
"""

from __future__ import annotations

import copy
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Optional, Union

import numpy as np

from ._tangle import ConvergenceError, ModelError, __version__  # noqa: F401
from . import _tangle
from . import statistics  # noqa: F401  (design statistics: rainflow, S-N damage, extremes)
from .statistics import rainflow  # noqa: F401
from .coupling import Coupling  # noqa: F401  (co-simulation: a model stepped by a host)

__all__ = ["Model", "StaticResults", "DynamicResults", "ModelError", "ConvergenceError", "Interrupted",
           "DynamicsFailed", "__version__", "rainflow", "statistics", "Coupling"]


class Interrupted(KeyboardInterrupt):
    """Ctrl-C (or an exception raised by the progress callback) stopped a dynamic run.

    ``results`` holds the DynamicResults up to the step where the run stopped; ``__cause__`` is the
    exception that stopped it.
    """

    def __init__(self, message: str, results: "DynamicResults"):
        super().__init__(message)
        self.results = results


def _at_arc_length(arc: np.ndarray, values: np.ndarray, arc_length_m: float, line: str) -> np.ndarray:
    """``values`` [..., node] at an unstretched arc length [m], linear between the two nodes around it
    (the last axis is the node axis; a node's value is exact at the node)."""
    arc = np.asarray(arc, dtype=float)
    if not (arc[0] - 1e-9 <= arc_length_m <= arc[-1] + 1e-9):
        raise ValueError(f"arc length {arc_length_m} m is outside line {line!r} (0 to {arc[-1]:g} m)")
    i = int(np.clip(np.searchsorted(arc, arc_length_m, side="right") - 1, 0, len(arc) - 2))
    w = (arc_length_m - arc[i]) / (arc[i + 1] - arc[i])
    values = np.asarray(values)
    return (1.0 - w) * values[..., i] + w * values[..., i + 1]


class DynamicsFailed(ConvergenceError):
    """A dynamic run stopped before its end (the solver's diagnosis is the message: a step that does not
    converge even at the minimum time step, lines passing through each other, ...).

    ``results`` holds the DynamicResults up to the last accepted step, as the command line keeps every
    result already computed.
    """

    def __init__(self, message: str, results: "DynamicResults"):
        super().__init__(message)
        self.results = results


@dataclass
class StaticResults:
    """Static equilibrium.

    lines: per line name, a dict of numpy arrays along the line (node by node from end A):
    ``arc_length_m``, ``position_m`` [node, xyz], ``effective_tension_N``, ``bending_moment_Nm``,
    ``curvature_1_per_m``, ``torque_Nm``; and ``end_a_tension_N``, ``end_b_tension_N`` (effective tension
    at the end points), ``end_a_force_N``/``end_b_force_N`` (force the line exerts on what holds its
    ends, xyz), ``end_a_support_reaction_N``/``end_b_support_reaction_N``, ``touchdown_arc_length_m``
    (NaN when none), ``nodes_on_seabed``.
    equilibrium_audit: one dict per line and free vessel (``kind``, ``name``, ``forces_N`` by source,
    ``residual_N``, ``reference_force_N``, ``relative_residual``, ``tolerance``), as summary.json's
    (theory manual 7.8); a body out of balance is also in ``warnings``.
    """

    converged: bool
    iterations: int
    load_fraction: float
    max_out_of_balance_N: float
    message: str
    warnings: list[str]
    lines: dict[str, dict[str, Any]]
    equilibrium_audit: list[dict[str, Any]] = field(default_factory=list)

    def end_angles(self, line: str, end: str) -> dict[str, float]:
        """Angles of the force the line exerts on what holds end ``"a"`` or ``"b"`` [deg], as summary.json:
        ``angle_from_horizontal_deg`` (positive when the line pulls its support upward),
        ``angle_from_vertical_deg`` (90 minus its magnitude) and ``azimuth_deg`` (of the horizontal part,
        anticlockwise from +x; NaN for a vertical force)."""
        if end not in ("a", "b"):
            raise ValueError(f"end must be 'a' or 'b', not {end!r}")
        f = np.asarray(self.lines[line][f"end_{end}_force_N"], dtype=float)
        horizontal = float(np.hypot(f[0], f[1]))
        elevation = float(np.degrees(np.arctan2(f[2], horizontal)))
        azimuth = float(np.degrees(np.arctan2(f[1], f[0])) % 360.0) if horizontal > 0.0 else float("nan")
        return {"angle_from_horizontal_deg": elevation, "angle_from_vertical_deg": 90.0 - abs(elevation),
                "azimuth_deg": azimuth}

    def at(self, line: str, quantity: str, arc_length_m: float) -> Any:
        """A per-node result (``effective_tension_N``, ``bending_moment_Nm``, ``curvature_1_per_m``,
        ``torque_Nm``, ``position_m``) at an unstretched arc length from end A [m], interpolated linearly
        between the nodes around it (as OrcFxAPI's results with an arc length)."""
        d = self.lines[line]
        if quantity not in d:
            raise KeyError(f"no result {quantity!r} for line {line!r}")
        values = np.asarray(d[quantity])
        if quantity == "position_m":
            return _at_arc_length(d["arc_length_m"], values.T, arc_length_m, line)
        return float(_at_arc_length(d["arc_length_m"], values, arc_length_m, line))


@dataclass
class DynamicResults:
    """A dynamic run.

    time_s: output times [s]. lines: per line name, a dict: ``arc_length_m`` [node];
    ``position_m`` [time, node, xyz]; ``effective_tension_N``, ``bending_moment_Nm``,
    ``curvature_1_per_m``, ``torque_Nm`` [time, node]; ``end_tension_N`` [time, end A/B];
    ``end_force_N`` [time, end A/B, xyz]; ``range``: range graphs over every accepted step (not only the
    output times) as ``<quantity>_min/_max/_mean_<unit>`` [node], means time-weighted, and
    ``seabed_clearance_min_m`` [node] (the smallest clearance to the seabed over the run, 0 on it).
    newton_iterations_on_parts, matrix_refreshes, block_refreshes, matrix_step_length_changes, fallback_steps,
    unload_rejections, converged_blocks_left_out: solver counters,
    as the dynamics summary.json (theory manual 8.2).
    vessels: per vessel name, ``motion`` [time, (x_m, y_m, z_m, rx_deg, ry_deg, rz_deg)] (reference point and
    rotation vector from the initial attitude). contact_events: one dict per contact event (the clash
    report's rows). clearance: one dict per line and other line: ``arc_length_m``, ``static_clearance_m``,
    ``min_clearance_m`` (over every accepted step), ``time_of_min_s`` [node]. line_failures: one dict per line
    that parted (``lines[].failure``): ``line``, ``time_s`` (None: before the statics), ``trigger``, ``value``,
    ``threshold``, ``parted_from_m``, ``parted_to_m``, ``message`` (as dynamics/summary.json).
    seabed_impacts: one dict per contact of a line with the seabed during the dynamics (the rows of
    dynamics/seabed_impacts.csv): ``line``, ``kind`` (``impact`` or ``contact``), ``start_time_s``,
    ``end_time_s``, ``arc_length_m``, ``position_m`` (x, y, z), ``impact_velocity_m_s``, ``impact_energy_J``
    and ``eq5_mass_kg`` (None when not measured), ``impact_phase_end_s``, ``impact_phase_work_J``,
    ``peak_force_N``, ``impulse_Ns``, ``open_at_end``.
    hull_impacts: one dict per contact event with a vessel's hull (the rows of dynamics/hull_impacts.csv;
    empty without hulls): ``body_a`` (line or vessel), ``body_b`` (vessel), ``kind`` (``line_impact``,
    ``hull_impact``, ``line_contact``, ``hull_contact``), ``start_time_s``, ``end_time_s``, ``position_m``,
    ``impact_velocity_m_s``, ``rebound_velocity_m_s``, ``peak_force_N``, ``impulse_Ns``, ``max_penetration_m``,
    ``bodies_effective_mass_kg``, ``eq5_mass_kg``, ``impact_energy_J`` (None where not measured), ``open_at_end``.
    """

    completed: bool
    interrupted: bool
    message: str
    end_time_s: float
    steps: int
    step_cutbacks: int
    newton_iterations: int
    wall_time_s: float
    time_s: np.ndarray
    lines: dict[str, dict[str, Any]]
    vessels: dict[str, dict[str, Any]] = field(default_factory=dict)
    contact_events: list[dict[str, Any]] = field(default_factory=list)
    clearance: list[dict[str, Any]] = field(default_factory=list)
    newton_iterations_on_parts: int = 0
    matrix_refreshes: int = 0
    block_refreshes: int = 0
    matrix_step_length_changes: int = 0
    fallback_steps: int = 0
    unload_rejections: int = 0
    converged_blocks_left_out: int = 0
    line_failures: list[dict[str, Any]] = field(default_factory=list)
    seabed_impacts: list[dict[str, Any]] = field(default_factory=list)
    hull_impacts: list[dict[str, Any]] = field(default_factory=list)

    def time_history(self, line: str, quantity: str, arc_length_m: float) -> np.ndarray:
        """Time history [time] of a per-node result (``effective_tension_N``, ``bending_moment_Nm``,
        ``curvature_1_per_m``, ``torque_Nm``; ``position_m`` gives [time, xyz]) at an unstretched arc length
        from end A [m], interpolated linearly between the nodes around it (as OrcFxAPI's TimeHistory with an
        arc length)."""
        d = self.lines[line]
        if quantity not in d or quantity in ("arc_length_m", "range", "end_tension_N", "end_force_N"):
            raise KeyError(f"no per-node time history {quantity!r} for line {line!r}")
        values = np.asarray(d[quantity])
        if quantity == "position_m":
            return _at_arc_length(d["arc_length_m"], np.moveaxis(values, 1, -1), arc_length_m, line)
        return _at_arc_length(d["arc_length_m"], values, arc_length_m, line)

    def range_graph(self, line: str, quantity: str = "effective_tension") -> dict[str, np.ndarray]:
        """Min, max and mean of a quantity along a line: {'arc_length_m', 'min', 'max', 'mean'}."""
        r = self.lines[line]["range"]
        keys = [k for k in r if k.startswith(quantity + "_min_")]
        if not keys:
            raise KeyError(f"no range graph of {quantity!r}; one of: effective_tension, wall_tension (a line with a "
                           "bore), bending_moment, curvature")
        unit = keys[0][len(quantity) + 5:]
        return {"arc_length_m": self.lines[line]["arc_length_m"], "min": r[f"{quantity}_min_{unit}"],
                "max": r[f"{quantity}_max_{unit}"], "mean": r[f"{quantity}_mean_{unit}"]}


class Model:
    """A tangle model: the content of a model file as nested dicts and lists (``data``).

    Edit ``data`` directly or with ``set(path, value)``; paths are the reader's key paths, e.g.
    ``environment.current.speed``, ``lines[mooring1].end_b.position``, ``line_types[chain76].axial_stiffness``
    (list items by name or 0-based index). ``set`` checks the whole model at once with the model reader and
    raises ModelError (a ValueError) with the reader's message, leaving the model unchanged; direct edits
    of ``data`` are checked by ``check()`` and by every run.
    """

    def __init__(self, data: dict, source: str = "<python model>"):
        if not isinstance(data, dict):
            raise TypeError(f"a model is a dict of blocks (environment, line_types, lines, ...), got {type(data).__name__}")
        self.data = copy.deepcopy(data)
        self.source = source
        self._text: Optional[str] = None  # the file's own text while data is unchanged (line numbers in messages)
        self._loaded: Optional[dict] = None

    @classmethod
    def load(cls, path: str | Path) -> "Model":
        """Reads a model file (YAML), or a MoorDyn v2 input file, which is converted as `tangle convert` does
        (docs/moordyn.md). Raises ModelError naming the file when it cannot be read or parsed."""
        path = str(path)
        if Path(path).is_file() and _tangle.is_moordyn_deck(path):
            text, _notes = _tangle.convert_moordyn(path)
            return cls.from_yaml(text, path)
        try:
            text = Path(path).read_text(encoding="utf-8")
        except OSError as e:
            raise ModelError(f"{path}: cannot read the model file: {e.strerror}") from None
        model = cls(_tangle.load_yaml(text, path), path)
        model._text, model._loaded = text, copy.deepcopy(model.data)
        return model

    @classmethod
    def from_yaml(cls, text: str, source: str = "<yaml text>") -> "Model":
        model = cls(_tangle.load_yaml(text, source), source)
        model._text, model._loaded = text, copy.deepcopy(model.data)
        return model

    def text(self) -> str:
        """The model as YAML text (the original file's text while unchanged)."""
        if self._text is not None and self.data == self._loaded:
            return self._text
        return _tangle.dump_yaml(self.data)

    def save(self, path: str | Path) -> None:
        Path(path).write_text(self.text(), encoding="utf-8")

    def get(self, path: str) -> Any:
        """The value at a key path (a copy)."""
        return _tangle.get_path(self.data, path, self.source)

    def set(self, path: str, value: Any) -> None:
        """Sets the value at a key path and checks the model; on ModelError the model is unchanged."""
        updated = _tangle.set_path(self.data, path, value, self.source)
        _tangle.check(_tangle.dump_yaml(updated), self.source + " (after set)")
        self.data = updated

    def check(self) -> None:
        """Checks the model with the model reader (raises ModelError)."""
        _tangle.check(self.text(), self.source)

    def copy(self) -> "Model":
        m = Model(self.data, self.source)
        m._text, m._loaded = self._text, copy.deepcopy(self._loaded)
        return m

    # -- runs -------------------------------------------------------------------------------------
    def simulation(self) -> "Simulation":
        """A Simulation of the model as it is now (later changes to the model do not affect it)."""
        return Simulation(self)

    def run_statics(self) -> StaticResults:
        """Static equilibrium (raises ConvergenceError with the solver's diagnosis when none is found)."""
        return self.simulation().run_statics()

    def run(self, folder: Union[str, "os.PathLike[str]"], *, overwrite: bool = False, statics_only: bool = False,
            report: bool = True, plots: bool = False, quiet: bool = True) -> Path:
        """Runs the model into a results folder exactly as ``tangle run -o folder`` does: summary.json,
        statics/, dynamics/, contact and clearance reports, results.h5 and report.html (plots with
        ``plots=True``), the model as run in model.yaml and the run log. Returns the folder. Raises
        ConvergenceError when the statics do not converge or the dynamics stop early (the folder keeps what
        was computed, and its tangle-run.json says where it stopped), KeyboardInterrupt on Ctrl-C, ModelError
        on bad input or a folder that holds other files (``overwrite=True`` replaces an earlier run's)."""
        text = self.text()
        edited = self._text is None or text != self._text
        source = self.source + (" (as edited in Python: see Model.text())" if edited else "")
        code, status = _tangle.run_to_folder(text, source, os.fspath(folder), overwrite, statics_only, report,
                                             plots, quiet)
        if code == 130:
            raise KeyboardInterrupt(f"run into {os.fspath(folder)} stopped: {status}")
        if code != 0:
            raise ConvergenceError(f"run into {os.fspath(folder)} {status} (see its run.log)")
        return Path(folder)

    def run_dynamics(self, progress: Optional[Callable[[float, float], Any]] = None) -> DynamicResults:
        """Statics, then the dynamic run of the model's dynamics block. ``progress(time_s, duration_s)`` is
        called at every output time. Ctrl-C stops the run at the next step and raises Interrupted, whose
        ``results`` hold everything up to then; a run the solver cannot finish raises DynamicsFailed
        (a ConvergenceError) with the diagnosis and the results up to the last accepted step."""
        sim = self.simulation()
        sim.run_statics()
        return sim.run_dynamics(progress)


class Simulation:
    """One analysis of one model (statics, then dynamics from the static equilibrium)."""

    def __init__(self, model: Model):
        text = model.text()
        edited = model._text is None or text != model._text
        # Messages name the file; after edits their line numbers are those of model.text().
        self._core = _tangle.Simulation(text, model.source + (" (as edited in Python: see Model.text())" if edited else ""))
        self.lines = [d["name"] for d in self._core.lines()]
        self.statics: Optional[StaticResults] = None

    def run_statics(self) -> StaticResults:
        s = self._core.statics()
        if not s["converged"]:
            raise ConvergenceError(s["message"])
        self.statics = StaticResults(lines={p["name"]: p for p in self._core.profiles()}, **s)
        return self.statics

    def run_dynamics(self, progress: Optional[Callable[[float, float], Any]] = None) -> DynamicResults:
        if self.statics is None:
            self.run_statics()
        d = self._core.dynamics(progress)
        error = d.pop("error")
        d.pop("range_steps")
        d["lines"] = {x["name"]: x for x in d["lines"]}
        d["vessels"] = {x["name"]: x for x in d["vessels"]}
        results = DynamicResults(**d)
        if error is not None:
            raise Interrupted(results.message, results) from error
        if not results.completed:
            raise DynamicsFailed(results.message, results)
        return results
