"""Design statistics of responses (docs/python.md, docs/theory.md "Extreme statistics and fatigue").

The computations are the compiled core's (the same code the command line will use): rainflow counting
(ASTM E1049-85), Miner's damage against two-slope S-N curves (DNV-RP-C203) or chain T-N curves
(API RP 2SK), peaks with Rayleigh and Weibull fits and the most probable maximum of a storm, and the
Gumbel fit of maxima over seeds. Units are those of the input (stress in Pa for S-N curves).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterable, Sequence

import numpy as np

from . import _tangle


def rainflow(values: Iterable[float]) -> np.ndarray:
    """Rainflow cycles of a series (ASTM E1049-85 5.4.4, half cycles kept): an array of rows
    (range, mean, count), count 1 for a closed cycle and 0.5 for a half cycle."""
    return _tangle.rainflow(np.asarray(list(values) if not isinstance(values, np.ndarray) else values, dtype=float))


@dataclass(frozen=True)
class SnCurve:
    """A two-slope S-N curve, log10 N = log10 a - m log10(S (t / t_ref)^k) with S in MPa as the standards
    publish it (the second segment beyond ``knee_cycles``); stress ranges are given in Pa."""

    m1: float
    log_a1: float
    m2: float
    log_a2: float
    knee_cycles: float = 1e7
    k: float = 0.0
    reference_thickness: float = 0.025
    thickness: float = 0.025

    @staticmethod
    def dnv_d(thickness: float = 0.025) -> "SnCurve":
        """DNV-RP-C203 (2021) Table 2-1, curve D in air (m 3 / 5, log a 12.164 / 15.606, k 0.20, t_ref 25 mm)."""
        return SnCurve(3.0, 12.164, 5.0, 15.606, 1e7, 0.20, 0.025, thickness)

    @staticmethod
    def preset(name: str, thickness: float = 0.025) -> "SnCurve":
        """A DNV-RP-C203 (2021) curve by the name a model's fatigue.sn_curves preset takes: "dnv-<class>-air"
        (Table 2-1) or "dnv-<class>-seawater-cp" (Table 2-2), e.g. "dnv-f1-seawater-cp"."""
        m1, log_a1, m2, log_a2, knee, k, t_ref = _tangle.sn_preset(name)
        return SnCurve(m1, log_a1, m2, log_a2, knee, k, t_ref, thickness)

    def cycles_to_failure(self, stress_range_pa: float) -> float:
        return _tangle.sn_cycles_to_failure(stress_range_pa, self.m1, self.log_a1, self.m2, self.log_a2,
                                            self.knee_cycles, self.k, self.reference_thickness, self.thickness)


def miner_damage(cycles: np.ndarray, curve: SnCurve) -> float:
    """Miner's sum of rainflow cycles (rows range [Pa], mean, count) against an S-N curve."""
    return _tangle.sn_damage(np.asarray(cycles, dtype=float).reshape(-1, 3), curve.m1, curve.log_a1, curve.m2,
                             curve.log_a2, curve.knee_cycles, curve.k, curve.reference_thickness, curve.thickness)


def chain_damage(cycles: np.ndarray, breaking_strength_n: float, m: float = 3.0, a_d: float = 316.0) -> float:
    """Miner's sum of rainflow cycles of tension [N] against a chain T-N curve N R^m = a_D (R = range /
    breaking strength; API RP 2SK (2005) 7.5: a_D = 1000 studlink, 316 studless, m = 3)."""
    return _tangle.tn_damage(np.asarray(cycles, dtype=float).reshape(-1, 3), breaking_strength_n, m, a_d)


@dataclass(frozen=True)
class ExtremeEstimate:
    """Peaks of a record, the fits of their excess over the mean, and the most probable maximum of a storm."""

    mean: float
    standard_deviation: float
    upcrossing_period_s: float
    peaks: np.ndarray
    storm_duration_s: float
    rayleigh_sigma: float
    rayleigh_mpm: float
    weibull_scale: float
    weibull_shape: float
    weibull_mpm: float


def extreme_estimate(times: Sequence[float], values: Sequence[float], storm_duration_s: float = 3 * 3600.0) -> ExtremeEstimate:
    """Peaks (the largest value between mean up-crossings), Rayleigh and Weibull fits, and the most probable
    maximum of the N = storm / Tz peaks of a storm (default 3 h): mean + alpha (ln N)^(1/beta)."""
    p = _tangle.peaks(np.asarray(times, dtype=float), np.asarray(values, dtype=float))
    if not p["peaks"] or p["upcrossing_period_s"] <= 0.0:
        raise ValueError("the record has fewer than two up-crossings of its mean: no peaks to fit")
    n = storm_duration_s / p["upcrossing_period_s"]
    ra, _, rayleigh_mpm = _tangle.fit_peaks(p["peaks"], p["mean"], "rayleigh", n)
    wa, wb, weibull_mpm = _tangle.fit_peaks(p["peaks"], p["mean"], "weibull", n)
    return ExtremeEstimate(p["mean"], p["standard_deviation"], p["upcrossing_period_s"], np.asarray(p["peaks"]),
                           storm_duration_s, ra / math.sqrt(2.0), rayleigh_mpm, wa, wb, weibull_mpm)


@dataclass(frozen=True)
class GumbelFit:
    """Gumbel fit of maxima over seeds by the method of moments (scale s sqrt(6) / pi, mode mean - 0.5772
    scale); the mode is the most probable maximum."""

    mean: float
    standard_deviation: float
    scale: float
    mode: float

    def quantile(self, probability: float = 0.9) -> float:
        """The value not exceeded with this probability: mode - scale ln(-ln q)."""
        return self.mode - self.scale * math.log(-math.log(probability))


def gumbel_fit(maxima: Sequence[float]) -> GumbelFit:
    return GumbelFit(*_tangle.fit_gumbel([float(x) for x in maxima]))


def _read_columns(path) -> dict:
    """The columns of a results CSV file as numpy arrays (numbers; NaN for an empty field) or lists (text)."""
    import csv

    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    columns = {}
    for key in rows[0].keys() if rows else []:
        values = [r[key] for r in rows]
        try:
            columns[key] = np.array([float(v) if v != "" else math.nan for v in values])
        except ValueError:
            columns[key] = values
    return columns


def read_fatigue(folder) -> dict:
    """The fatigue results of a run (``tangle run`` or ``Model.run`` of a model with a ``fatigue`` block):
    per line (keyed by its file stem, the line name for plain names) the columns of fatigue/<line>.csv as
    numpy arrays: arc_length_m, damage_run, damage_per_year, life_years, cycles, largest_stress_range_MPa,
    largest_tension_range_kN (NaN where not applicable), worst_point_deg; and line_type, curve (lists)."""
    from pathlib import Path

    return {p.stem: _read_columns(p) for p in sorted((Path(folder) / "fatigue").glob("*.csv")) if p.name != "summary.csv"}


def read_line_statistics(folder) -> dict:
    """The extreme statistics along the lines of a dynamic run (dynamics/<line>/statistics.csv, docs/theory.md
    13.3): per line file stem, the columns as numpy arrays: arc_length_m and, for tension_ (N) and moment_
    (N m), mean, standard_deviation, upcrossing_period_s, peaks, max, rayleigh_sigma, rayleigh_mpm,
    weibull_scale, weibull_shape, weibull_mpm (NaN where the fit is not credible: docs/theory.md 13.3), and note
    (why, where it is not)."""
    from pathlib import Path

    return {p.parent.name: _read_columns(p) for p in sorted((Path(folder) / "dynamics").glob("*/statistics.csv"))}
