# Regenerate: `python3 tests/reference/bspline.py` from the repository root (Python 3.11, `pip install scipy numpy`); writes bspline.csv and bspline_points.csv next to this script.
"""SciPy reference data for Strider's spline kernel (`strider_nodes::kernels::spline`).

Builds `scipy.interpolate.BSpline` curves with the clamped uniform knot vector Strider
uses for `SplineMode::BSpline` and samples position and first derivative at evenly spaced
U values. This script is independent of the Rust code: it only shares the definition of
the curve.

Curve definition: N control points, degree k = min(3, N - 1), knots = k + 1 zeros,
uniform interior knots j / (N - k) for j = 1 .. N - k - 1, k + 1 ones. U is the knot
parameter itself (domain [0, 1]), so the tangent is dP/dU in cm per unit U.

Outputs (checked in; run by hand, not in CI):
  bspline_points.csv  case,i,x,y,z           control points (cm)
  bspline.csv         case,n,u,px,py,pz,tx,ty,tz
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
from scipy.interpolate import BSpline

HERE = Path(__file__).resolve().parent
SAMPLES = 21  # U = 0, 0.05, ..., 1 (hits the interior knots of every case).


def foot_swing() -> list[tuple[float, float, float]]:
    """The locomotion rig's CalculateFootSpline control points for one swing.

    Velocity v = (0, 300, 0) cm/s (forward +Y), foot from start (12, -25, 0) to
    end (12, 25, 0). remap(|v|, 0..500 -> 0..8) = 4.8 behind, 0..20 -> 12 ahead,
    lifts 0..10 -> 6 and 0..20 -> 12. P3 is the midpoint of P2 and P4 pushed 1.5 cm
    sideways (as the MovementAngleOffset rotation about the pelvis would).
    """
    start = np.array([12.0, -25.0, 0.0])
    end = np.array([12.0, 25.0, 0.0])
    fwd = np.array([0.0, 1.0, 0.0])
    p1 = start - fwd * 4.8
    p5 = end + fwd * 12.0
    p2 = p1 + np.array([0.0, 0.0, 6.0])
    p4 = p5 + np.array([0.0, 0.0, 12.0])
    p3 = (p2 + p4) / 2 + np.array([1.5, 0.0, 0.0])
    return [tuple(float(c) for c in p) for p in (start, p1, p2, p3, p4, p5, end)]


CASES: dict[str, list[tuple[float, float, float]]] = {
    # N = 2: the straight segment (degree 1).
    "line2": [(1.0, 2.0, 3.0), (5.0, -2.0, 11.0)],
    # N = 3: quadratic Bezier (degree 2, one span).
    "quad3": [(0.0, 0.0, 0.0), (4.0, 8.0, -2.0), (10.0, 2.0, 6.0)],
    # N = 4: cubic Bezier (degree 3, one span); a small step arc.
    "cubic4": [(0.0, 0.0, 0.0), (0.0, 10.0, 15.0), (5.0, 30.0, 15.0), (5.0, 40.0, 0.0)],
    # N = 5: cubic, two spans (interior knot at 1/2), fully 3D.
    "wave5": [
        (-10.0, 0.0, 2.0),
        (-4.0, 12.0, -6.0),
        (3.0, 5.0, 14.0),
        (8.0, -9.0, 4.0),
        (15.0, 2.0, -3.0),
    ],
    # N = 7: the foot swing arc (cubic, four spans, knots at 1/4, 1/2, 3/4).
    "swing7": foot_swing(),
    # N = 7: a generic 3D polygon with large coordinates (pelvis-height, world offsets).
    "coil7": [
        (120.0, -340.0, 95.0),
        (131.5, -322.0, 101.0),
        (118.0, -305.5, 112.25),
        (101.0, -310.0, 99.0),
        (97.5, -290.0, 87.5),
        (110.0, -275.0, 93.0),
        (126.0, -268.0, 104.5),
    ],
}


def clamped_uniform_knots(n: int, k: int) -> np.ndarray:
    spans = n - k
    interior = [j / spans for j in range(1, spans)]
    return np.array([0.0] * (k + 1) + interior + [1.0] * (k + 1))


def main() -> None:
    us = np.array([i / (SAMPLES - 1) for i in range(SAMPLES)])
    with open(HERE / "bspline_points.csv", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["case", "i", "x", "y", "z"])
        for case, pts in CASES.items():
            for i, (x, y, z) in enumerate(pts):
                w.writerow([case, i, repr(x), repr(y), repr(z)])

    with open(HERE / "bspline.csv", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["case", "n", "u", "px", "py", "pz", "tx", "ty", "tz"])
        for case, pts in CASES.items():
            c = np.array(pts, dtype=float)
            n = len(c)
            k = min(3, n - 1)
            t = clamped_uniform_knots(n, k)
            assert len(t) == n + k + 1
            spl = BSpline(t, c, k)
            dspl = spl.derivative(1)
            pos = spl(us)
            tan = dspl(us)
            # Sanity: clamped ends interpolate the first and last control points.
            assert np.allclose(pos[0], c[0]) and np.allclose(pos[-1], c[-1])
            for u, p, d in zip(us, pos, tan):
                w.writerow(
                    [case, n, repr(float(u))]
                    + [repr(float(v)) for v in p]
                    + [repr(float(v)) for v in d]
                )


if __name__ == "__main__":
    main()
