"""Co-simulation: a tangle model stepped by a host program in Python (docs/moordyn.md, "C API and Python
coupling").

The host owns the motion of some points (fairleads on its floating body): at each of its steps it gives
their positions and velocities at the step start and reads the forces the lines exert on them at the step
end, as with MoorDyn's ``MoorDyn_Step``; tangle runs its own time steps inside::

    import numpy as np
    import tangle

    c = tangle.Coupling("mooring.txt")                 # a MoorDyn deck: its Coupled points
    x = c.model_positions                              # (n, 3) [m]
    c.init(x)                                          # statics with the points at x
    for k in range(1000):
        xd = np.zeros_like(x)
        xd[0, 0] = 0.2 * np.cos(0.5 * k * 0.1)         # the host's velocities [m/s]
        f = c.step(x, xd, 0.1)                         # (n, 3) [N] at t + 0.1 s
        x = x + 0.1 * xd

Units are SI (m, m/s, N, s). The solver runs without the GIL.
"""

from __future__ import annotations

import os
from typing import Optional, Sequence, Union

import numpy as np

from . import _tangle

__all__ = ["Coupling"]


class Coupling:
    """A tangle model whose coupled points a host moves (analysis::CoupledRun).

    ``path``: a MoorDyn v2 deck (read and converted as the MoorDyn-compatible C API reads it) or a tangle
    model file (YAML). ``points``: the line ends each coupled point holds, one list per point, each end
    named ``"line_name:a"`` or ``"line_name:b"`` (tangle line names); required for a YAML model, and by
    default for a deck its Coupled points in deck order. Every end must be a held end (``anchored``,
    ``pinned`` or ``fixed``) without a motion of its own. A point ``["vessel:name"]`` is the reference point
    of a pinned free vessel (``pinned: true``): the host moves it, the vessel's rotations are solved, and its
    force is what the vessel exerts on its pin (the reaction, with its inertia).

    Raises ``tangle.ModelError`` (a ValueError) for a file that cannot be read, bad end names or ends that
    cannot be coupled; ``tangle.ConvergenceError`` (a RuntimeError) when the statics or a step cannot be
    solved (the state is then the last converged one); ValueError for arrays of the wrong size;
    RuntimeError for calls out of order.
    """

    def __init__(self, path: Union[str, "os.PathLike[str]"], points: Optional[Sequence[Sequence[str]]] = None):
        if points is not None:
            if isinstance(points, str) or any(isinstance(p, str) for p in points):
                raise ValueError("points is a list of lists of line ends, e.g. [['mooring1:b']], "
                                 f"not {points!r}")
            points = [list(p) for p in points]
        self._core = _tangle.CoupledRun(os.fspath(path), points)
        self.path = os.fspath(path)

    @property
    def n_points(self) -> int:
        """Number of coupled points."""
        return self._core.point_count

    @property
    def points(self) -> list[list[str]]:
        """The line ends of each point (``"line_name:a"`` / ``"line_name:b"``)."""
        return self._core.point_ends

    @property
    def model_positions(self) -> np.ndarray:
        """Positions of the points in the model [m], shape (n, 3): before ``init`` the model's own (the
        deck's), then where the host put them."""
        return np.asarray(self._core.model_positions()).reshape(self.n_points, 3)

    def _array(self, values, name: str) -> np.ndarray:
        a = np.asarray(values, dtype=float)
        if a.size != 3 * self.n_points:
            raise ValueError(f"{name} must have shape ({self.n_points}, 3), got {a.shape}")
        return np.ascontiguousarray(a.reshape(-1))

    def init(self, x, xd=None) -> None:
        """Puts the points at ``x`` [m], shape (n, 3), and solves the static equilibrium there; ``xd`` [m/s]
        is their velocity until the first step (None: zero). Time is then 0."""
        self._core.initialize(self._array(x, "x"), None if xd is None else self._array(xd, "xd"))

    def step(self, x, xd, dt: float) -> np.ndarray:
        """Advances by ``dt`` [s] with the points moving as ``x + xd (t - t0)`` from the step start (x [m],
        xd [m/s], shape (n, 3)); returns the forces the lines exert on the points at the end of the step
        [N], shape (n, 3)."""
        f = self._core.step(self._array(x, "x"), self._array(xd, "xd"), float(dt))
        return np.asarray(f).reshape(self.n_points, 3)

    @property
    def time(self) -> float:
        """Simulated time [s] (0 after ``init``)."""
        return self._core.time

    @property
    def forces(self) -> np.ndarray:
        """Forces the lines exert on the points at the current state [N], shape (n, 3) (zero before
        ``init``): the lines' pull with the weight and inertia of their end nodes (their acceleration the
        change of ``xd`` over the host's step divided by it); at a pinned vessel's point, what the vessel
        exerts on its pin."""
        return np.asarray(self._core.forces()).reshape(self.n_points, 3)

    def line_tensions(self) -> dict[str, np.ndarray]:
        """Effective tension at every node of every line at the current state [N], by tangle line name
        (node 0 at end A; at the end nodes the end tensions)."""
        return {name: np.asarray(t) for name, t in self._core.line_tensions().items()}

    def __repr__(self) -> str:
        return f"Coupling({self.path!r}, points={self.points!r}, time={self.time:g} s)"
