#!/usr/bin/env python3
"""A floating vertical cylinder's potential-flow coefficients from Capytaine 3.0.0, written as the
WAMIT files Tether reads (docs/PHYSICS.md §9), and Capytaine's own RAO as a small CSV.

The Rust tests read what this writes (no Python needed to test); rerun it to check or to remake
them (about 6 minutes on 2 cores):

    python3 -m venv ~/.cache/tether/capytaine-venv
    ~/.cache/tether/capytaine-venv/bin/pip install capytaine==3.0.0
    nice ~/.cache/tether/capytaine-venv/bin/python validation/potential-flow/cylinder.py

Writes, beside this script, in `cylinder/`:
- `cylinder.1`, `cylinder.3`, `cylinder.hst`: WAMIT's added mass and damping (ω = 0 as PER = −1,
  ω = ∞ as PER = 0, then 100 periods, ω = 0.05 to 5 rad/s), excitation (heading 0°) and hydrostatic stiffness, L = 1;
- `cylinder_rao.csv`: ω [rad/s], then for surge, heave and pitch the RAO's amplitude (m/m,
  rad/m) and phase [deg] in WAMIT's convention (q = Re{a ξ e^{+iωt}}: Capytaine's phase negated);
- `cylinder_body.csv`: the mass matrix M and hydrostatic stiffness C (6 × 6, SI, about the
  reference point) the RAO was solved with, so a test can repeat the solve.

Body: radius 3 m, draft 6 m, freely floating (mass = ρπR²T), centre of gravity 4 m below the
still water level on the axis; the reference point (WAMIT's origin, the rotation centre of every
coefficient) is the centre of gravity. Deep water, ρ = 1025 kg/m³, g = 9.80665 m/s².
"""

from pathlib import Path

import numpy as np
import xarray as xr
import capytaine as cpt
from capytaine.post_pro import rao

R, T, Z_G, RHO, G = 3.0, 6.0, -4.0, 1025.0, 9.80665
OUT = Path(__file__).resolve().parent / "cylinder"
DOFS = ["Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw"]


def body():
    """The immersed cylinder with a lid (the lid removes irregular frequencies), its rigid-body
    dofs about G, its inertia and its hydrostatic stiffness (weight term included: z_G − z_B)."""
    mesh = cpt.mesh_vertical_cylinder(length=T + 2, radius=R, center=(0, 0, (2 - T) / 2), resolution=(10, 56, 30))
    mass = RHO * np.pi * R**2 * T
    b = cpt.FloatingBody(mesh=mesh, lid_mesh=mesh.generate_lid(),
                         dofs=cpt.rigid_body_dofs(rotation_center=(0, 0, Z_G)),
                         center_of_mass=(0, 0, Z_G), mass=mass).immersed_part()
    # Inertia about G: a uniform cylinder's about its own centre (radii of gyration chosen, the
    # ballast being what puts G below the centre of buoyancy).
    ixx = mass * (3 * R**2 + T**2) / 12
    b.inertia_matrix = b.add_dofs_labels_to_matrix(np.diag([mass, mass, mass, ixx, ixx, mass * R**2 / 2]))
    b.hydrostatic_stiffness = b.compute_hydrostatic_stiffness(rho=RHO, g=G)
    return b


def main():
    OUT.mkdir(exist_ok=True)
    b = body()
    w = np.arange(0.05, 5.0001, 0.05)
    test = xr.Dataset(coords={"omega": np.concatenate([[0.0], w, [np.inf]]), "wave_direction": [0.0],
                              "radiating_dof": list(b.dofs), "water_depth": [np.inf], "rho": [RHO], "g": [G]})
    ds = cpt.BEMSolver().fill_dataset(test, b)
    cpt.export_dataset(str(OUT / "cylinder"), ds, format="wamit", exports=("1", "3", "hst"))
    r = rao(ds.sel(omega=w)).sel(wave_direction=0.0)
    with open(OUT / "cylinder_rao.csv", "w") as f:
        f.write("# Capytaine 3.0.0 RAO of validation/potential-flow/cylinder.py (capytaine.post_pro.rao), heading 0;\n")
        f.write("# amplitude per unit wave amplitude (m/m, rad/m), phase in WAMIT's convention (Capytaine's negated) [deg]\n")
        f.write("omega,surge_amp,surge_phase,heave_amp,heave_phase,pitch_amp,pitch_phase\n")
        for i, om in enumerate(w):
            row = [f"{om:.4f}"]
            for dof in ("Surge", "Heave", "Pitch"):
                z = complex(r.sel(radiating_dof=dof).values[i])
                row += [f"{abs(z):.8e}", f"{-np.degrees(np.angle(z)):.6f}"]
            f.write(",".join(row) + "\n")
    # The matrices rao() solved with: the dataset's, as fill_dataset stored them.
    m = np.asarray(ds.inertia_matrix.sel(influenced_dof=DOFS, radiating_dof=DOFS))
    c = np.asarray(ds.hydrostatic_stiffness.sel(influenced_dof=DOFS, radiating_dof=DOFS))
    print("body C55", float(b.hydrostatic_stiffness.sel(influenced_dof="Pitch", radiating_dof="Pitch")),
          "dataset C55", c[4, 4], "body M55", float(b.inertia_matrix.sel(influenced_dof="Pitch", radiating_dof="Pitch")), "dataset M55", m[4, 4])
    with open(OUT / "cylinder_body.csv", "w") as f:
        f.write("# validation/potential-flow/cylinder.py: matrix,row,col,value (SI, about the reference point G)\n")
        for name, mat in (("M", m), ("C", c)):
            for i in range(6):
                for j in range(6):
                    if mat[i, j] != 0.0:
                        f.write(f"{name},{i + 1},{j + 1},{mat[i, j]:.10e}\n")


if __name__ == "__main__":
    main()
