#!/usr/bin/env python3
"""The navigation buoy of scenes/moored_buoy.ron: its potential-flow coefficients from Capytaine
3.0.0, written as the WAMIT files the scene reads (docs/PHYSICS.md §9).

    nice ~/.cache/tether/capytaine-venv/bin/python validation/potential-flow/moored_buoy.py

(the environment as in cylinder.py; about 3 minutes on 2 cores). Writes `scenes/meshes/buoy.1`
and `.3` (heading 0°).

The hull: the scene's `Cylinder(radius: 2.0, length: 3.0)`, floating at its moored equilibrium
(`tether equilibrium scenes/moored_buoy.ron` without the current: G 0.2034 m below the still
water level, the hull's bottom 1.2034 m below it), clipped at the still water level, with a lid
against irregular frequencies. Panels of about 0.25 m: at 6 rad/s, the highest frequency, a wave
is 1.7 m long.

Reference point (WAMIT's origin, the rotation centre of every coefficient): the scene's master
node, the buoy's G (the origin of the body's reference frame). Deep water: the buoy's draft is
1.2 m in 50 m of water (kh > 1 above 0.45 rad/s, a 14 s wave; the sea it meets is 8 s), and
Capytaine gives the ω = 0 limit only in infinite depth. Mass and stiffness are not written: the
scene's own (its node, its mesh's buoyancy, its chains).
"""

from pathlib import Path

import numpy as np
import xarray as xr
import capytaine as cpt

RHO, G = 1025.0, 9.80665
RADIUS, LENGTH = 2.0, 3.0  # the scene's hull [m]
DRAFT = 1.2034  # its bottom below the still water level at the equilibrium [m]
Z_REF = -0.2034  # G, the master node [m]
OUT = Path(__file__).resolve().parent.parent.parent / "scenes" / "meshes"


def body():
    """The immersed hull with a lid, its rigid-body dofs about G."""
    mesh = cpt.mesh_vertical_cylinder(length=LENGTH, radius=RADIUS, center=(0, 0, LENGTH / 2 - DRAFT),
                                      resolution=(8, 52, 12)).immersed_part()
    return cpt.FloatingBody(mesh=mesh, lid_mesh=mesh.generate_lid(),
                            dofs=cpt.rigid_body_dofs(rotation_center=(0, 0, Z_REF)),
                            center_of_mass=(0, 0, Z_REF))


def main():
    b = body()
    print(f"{b.mesh.nb_faces} panels")
    w = np.arange(0.05, 6.0001, 0.05)
    test = xr.Dataset(coords={"omega": np.concatenate([[0.0], w, [np.inf]]), "wave_direction": [0.0],
                              "radiating_dof": list(b.dofs), "water_depth": [np.inf], "rho": [RHO], "g": [G]})
    ds = cpt.BEMSolver().fill_dataset(test, b)
    cpt.export_dataset(str(OUT / "buoy"), ds, format="wamit", exports=("1", "3"))


if __name__ == "__main__":
    main()
