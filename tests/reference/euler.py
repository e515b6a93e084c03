# Regenerate: `python3 tests/reference/euler.py` from the repository root (Python 3.11, `pip install scipy numpy`); writes euler.csv next to this script.
"""SciPy reference quaternions for Strider's Euler conventions (`strider_core::euler`).

Strider's Euler triple is (x, y, z) in degrees about the fixed rig axes:
  XYZ: X first, then Y, then Z (extrinsic)  = SciPy from_euler('xyz', [x, y, z])
  ZYX: Z first, then Y, then X (extrinsic)  = SciPy from_euler('zyx', [z, y, x])
Lower-case sequences are extrinsic in SciPy, and the angles are given in the order of
the sequence string, hence [z, y, x] for 'zyx'.

Output (checked in; run by hand, not in CI):
  euler.csv  order,ex,ey,ez,qx,qy,qz,qw   quaternion scalar-last (SciPy's as_quat order)
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation as R

HERE = Path(__file__).resolve().parent

ANGLES: list[tuple[float, float, float]] = [
    (0.0, 0.0, 0.0),
    (90.0, 0.0, 0.0),
    (0.0, 90.0, 0.0),
    (0.0, 0.0, 90.0),
    (-90.0, 0.0, 0.0),
    (0.0, -90.0, 0.0),
    (0.0, 0.0, -90.0),
    (90.0, 0.0, 90.0),
    (10.0, 20.0, 30.0),
    (-10.0, -20.0, -30.0),
    (-170.0, 45.0, 120.0),
    (0.0, -80.0, -5.0),
    (33.0, -47.0, 161.0),
    (-123.0, 12.5, -77.0),
    (5.0, 5.0, 5.0),
    (0.5, -0.25, 0.125),
    # 180 degrees
    (180.0, 0.0, 0.0),
    (0.0, 180.0, 0.0),
    (0.0, 0.0, 180.0),
    (180.0, 180.0, 180.0),
    (-180.0, 30.0, 60.0),
    (45.0, 180.0, -45.0),
    (179.0, -1.0, -179.0),
    # near and at gimbal lock (middle angle +-89, +-90)
    (30.0, 89.0, -40.0),
    (30.0, 90.0, -40.0),
    (-45.0, -89.0, 10.0),
    (-45.0, -90.0, 10.0),
    (60.0, 90.0, 0.0),
    (90.0, 90.0, 90.0),
    (-90.0, -90.0, -90.0),
    (120.0, 89.9, 60.0),
    (-150.0, -89.9, 170.0),
    (15.0, 90.0, 15.0),
    (0.0, -90.0, 45.0),
    # outside the principal ranges (the rotation, not the triple, is compared)
    (270.0, 0.0, 0.0),
    (0.0, 135.0, 0.0),
    (-200.0, 100.0, 370.0),
    (360.0, -360.0, 720.0),
    (-60.0, 60.0, -60.0),
    (75.0, -30.0, 200.0),
]


def scipy_rotation(order: str, ex: float, ey: float, ez: float) -> R:
    if order == "XYZ":
        return R.from_euler("xyz", [ex, ey, ez], degrees=True)
    if order == "ZYX":
        return R.from_euler("zyx", [ez, ey, ex], degrees=True)
    raise ValueError(order)


def self_check(order: str, ex: float, ey: float, ez: float, rot: R) -> None:
    """The same rotation composed by hand from single-axis rotations (left = applied last)."""
    rx = R.from_rotvec(np.radians(ex) * np.array([1.0, 0.0, 0.0]))
    ry = R.from_rotvec(np.radians(ey) * np.array([0.0, 1.0, 0.0]))
    rz = R.from_rotvec(np.radians(ez) * np.array([0.0, 0.0, 1.0]))
    # SciPy's `a * b` applies b first, then a.
    manual = rz * ry * rx if order == "XYZ" else rx * ry * rz
    assert np.allclose(manual.as_matrix(), rot.as_matrix(), atol=1e-12), (order, ex, ey, ez)


def main() -> None:
    assert len(ANGLES) == len(set(ANGLES))
    with open(HERE / "euler.csv", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["order", "ex", "ey", "ez", "qx", "qy", "qz", "qw"])
        for order in ("XYZ", "ZYX"):
            for ex, ey, ez in ANGLES:
                rot = scipy_rotation(order, ex, ey, ez)
                self_check(order, ex, ey, ez, rot)
                qx, qy, qz, qw = rot.as_quat()  # scalar-last
                w.writerow(
                    [order, repr(ex), repr(ey), repr(ez)]
                    + [repr(float(v)) for v in (qx, qy, qz, qw)]
                )


if __name__ == "__main__":
    main()
