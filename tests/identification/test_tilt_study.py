"""Belyakov (2005), Fig. 19: principal axis tilted up from Cx by a rotation about z; error of Izz and Ixx.

The identification (matrix pencil + refine + Algorithm 1) assumes the product of inertia Ixy is zero.  A tilt b
creates ``Ixy = (Iyy0 - Ixx0) sin b cos b``; eliminating the pitch coordinate it couples to lowers the apparent Ixx
by about ``Ixy**2 / Iyy`` (second order in b), while Izz (not coupled) is unaffected.  The dissertation claims errors
<= 2 % for tilts <= 3 deg; that holds for Izz, while the Ixx error follows the second-order law (about -3.2 % at 3 deg
on this stand, whose geometry the thesis does not give).
"""

from __future__ import annotations

import numpy as np
import pytest

from symosc.identification import inertia_from_release, matrix_pencil, refine, simulate_stand
from symosc.models import body_on_springs

STAND = dict(m=15000, rx=2, rz=0.87, Ixx=3000, Iyy=43000, Izz=44000, Ixz=400, Lx=4, Lz=1.74)
STAND.update({f"k{i}": 7.4e5 for i in range(1, 5)})
STAND.update({f"c{i}": 3.1e5 for i in range(1, 5)})
FORCE = [0.0, -2000.0, 0.0, 0.0]


def _identify(deg):
    b = np.radians(deg)
    R = np.array([[np.cos(b), -np.sin(b), 0], [np.sin(b), np.cos(b), 0], [0, 0, 1]])
    J = R @ np.diag([3000.0, 43000.0, 44000.0]) @ R.T
    vals = {**STAND, "Ixx": J[0, 0], "Iyy": J[1, 1], "Izz": J[2, 2], "Ixy": -J[0, 1], "Ixz": 0.0, "Iyz": 0.0}
    rec = simulate_stand(body_on_springs(), vals, force=FORCE, dt=4 * 0.002212, n_samples=600)
    est = refine(matrix_pencil(rec.clean, rec.dt, 3, constant=False, hankel_size=100), rec.clean)
    res = inertia_from_release(est.undamped_frequencies, est.mode_shapes, FORCE, (4, 1.74))
    return res, J


def test_tilt_errors_follow_second_order_law():
    errs = {}
    for deg in (0.0, 1.0, 2.0):
        res, J = _identify(deg)
        ezz, exx = res.Izz / J[2, 2] - 1, res.Ixx / J[0, 0] - 1
        predicted = -(J[0, 1] ** 2) / (J[0, 0] * J[1, 1])  # apparent Ixx lowered by Ixy^2 / Iyy
        if deg == 0.0:
            assert abs(exx) < 1e-6 and abs(ezz) < 1e-6
        else:
            assert exx == pytest.approx(predicted, rel=0.06)
            assert abs(ezz) < 0.02  # the dissertation's <= 2 % claim holds for Izz
        errs[deg] = exx
    assert errs[2.0] / errs[1.0] == pytest.approx(4.0, rel=0.03)  # quadratic in the tilt
