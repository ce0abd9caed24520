"""Regenerate ``belyakov_record.csv``: a synthetic free-oscillation record of Belyakov's stand (2005, p. 78-80).

The body (m = 15000 kg, rx = 2 m, rz = 0.87 m, Ixx = 3000, Iyy = 43000, Izz = 44000, Ixz = 400 kg*m^2) rests on
four springs (k = 7.4e5 N/m, transverse 3.1e5 N/m) at Lx = 4 m, Lz = 1.74 m; 2000 N pressing spring 2 down is
released at t = 0.  The nonlinear stand model is integrated and the four vertical displacements sampled every
22.12 ms (ten times the dissertation's step), 0.1 % white noise added with a fixed seed.

Run ``python examples/data/make_belyakov_record.py``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from symosc.identification import simulate_stand
from symosc.models import body_on_springs

STAND = dict(m=15000, rx=2, rz=0.87, Ixx=3000, Iyy=43000, Izz=44000, Ixz=400, Lx=4, Lz=1.74)
STAND.update({f"k{i}": 7.4e5 for i in range(1, 5)})
STAND.update({f"c{i}": 3.1e5 for i in range(1, 5)})
FORCE = [0.0, -2000.0, 0.0, 0.0]


def main() -> Path:
    model = body_on_springs(product_of_inertia="dissertation")
    rec = simulate_stand(model, STAND, force=FORCE, dt=0.02212, n_samples=1254, noise=0.001, seed=2005)
    out = Path(__file__).resolve().parent / "belyakov_record.csv"
    table = np.vstack([rec.t, rec.signals]).T
    header = "t," + ",".join(f"y{i + 1}" for i in range(rec.signals.shape[0]))
    np.savetxt(out, table, delimiter=",", header=header, comments="", fmt="%.10g")
    return out


if __name__ == "__main__":
    print(main())
