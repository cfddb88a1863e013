#!/usr/bin/env python3
"""Mean wave drift coefficients (docs/PHYSICS.md §10) from Capytaine 3.0.0's far-field
(Maruo–Newman, Kochin-function) formula, written as WAMIT `.8` files, for the three bodies whose
`.1`/`.3` files the other scripts here write: the validation cylinder (cylinder.py), the moored
buoy (moored_buoy.py) and the OC3-Hywind spar (oc3_spar.py); their hulls, lids and reference
points are imported from those scripts, so the drift belongs to the same panel model.

    nice -n 19 ~/.cache/tether/capytaine-venv/bin/python validation/potential-flow/drift.py cylinder
    nice -n 19 ~/.cache/tether/capytaine-venv/bin/python validation/potential-flow/drift.py buoy
    nice -n 19 ~/.cache/tether/capytaine-venv/bin/python validation/potential-flow/drift.py oc3

(the environment as in cylinder.py; no argument runs all three, 2.5 min). On 2 shared cores:
cylinder (34 frequencies) about 1.5 min, buoy (28) 20 s, OC3 (19) 1 min.

Writes
- `cylinder`: `validation/potential-flow/cylinder/cylinder.8` and `cylinder_drift.csv`
  (`omega,kR,surge_drift_N_per_m2`: the dimensional surge drift D₁ in N per m² of wave
  amplitude, for the Rust tests); ω = 0.3 to 3.6 rad/s by 0.1 (kR = ω²R/g up to 3.96: the
  short-wave limit D₁ → (2/3) ρ g R of a vertical surface-piercing cylinder needs kR ≳ 3);
- `buoy`: `scenes/meshes/buoy.8`, ω = 0.3 to 3.0 rad/s by 0.1;
- `oc3`: `scenes/meshes/oc3_spar.8`, ω = 0.25, then 0.3 to 2.0 rad/s by 0.1 (19 frequencies).

The `.8` files are Capytaine's own WAMIT writer's (`cpt.export_dataset(..., format="wamit",
exports=("8",))`): tab-separated rows `PER β₁ β₂ I |F̄| phase Re(F̄) Im(F̄)`, PER in seconds,
headings in degrees (heading 0° only: β₁ = β₂ = 0, waves travelling toward +x), rows in
increasing period (short waves first, like the `.1`/`.3` files beside them), one row per period
for each of I = 1, 2, 6 (surge, sway, yaw: the far field gives no heave, roll or pitch drift),
F̄ = D / (ρ g L^k) with L = 1 m, k = 1 for forces and 2 for the yaw moment, D per unit wave
amplitude squared (so a regular wave of amplitude a pushes with a² ρ g F̄). Positive surge drift
pushes the body along +x, the way the waves travel. No ω = 0 or ω = ∞ rows.

The Kochin functions are computed on 72 + 2 × 6 directions 5° apart, θ = −30° to 390° (the
far-field formula integrates over [0, 2π] and differentiates in θ at the heading, which must lie
strictly inside the range; 0 and 2π are grid points, so the integral is over the whole circle).
The script prints the drift again from every other direction (10°): the difference is the
quadrature's error.

The motion in the far-field formula is the freely floating body's RAO (`capytaine.post_pro.rao`:
mass matrix about the reference point, Capytaine's hydrostatic stiffness with the weight term,
radiation and excitation from the same solve, no external damping). For the moored buoy and the
spar the mooring is not in that RAO, and the script prints the surge drift again with an
approximate mooring stiffness (`buoy_mooring`, `oc3_mooring`: the lines' horizontal and vertical
stiffness at the fairleads plus their pretension's geometric stiffness) to show where that matters:
- the spar: acceptable. Its lines (41.2 kN/m in surge) put its moored surge period at 125 s; they
  change the surge motion by k/(ω²(m + A₁₁)) = 6 % at 0.2 rad/s and less above, its pitch
  stiffness about the reference point by 1 %, and the drift by < 1 % from 0.6 to 2 rad/s (5 % at
  0.4 rad/s, where it is 1e-5 ρ g R). The grid starts at 0.25 rad/s: the freely floating spar's heave
  resonance is at 0.200 rad/s (heave 359 m/m there, radiation damping B₃₃ ≈ 35 N·s/m), where the
  drift of an undamped resonance (0.095 ρ g R at exactly 0.2 rad/s, ~1e-4 at 0.195 and 0.205) is an
  artefact that the scene's heave damping (1.3e5 N·s/m) and lines remove;
- the buoy: not everywhere. It is light (8 t, 15.5 t displaced: its chains pull 74 kN down), and
  its chains' 5.05 kN/m against m + A₁₁ = 15.8 t put its moored surge resonance at 0.57 rad/s
  (11 s), inside the wave band: at the scene's 8 s wave the moored surge RAO is about 2.7 against
  1.4 free, and below 1.8 rad/s the moored drift is 2 to 20 times the free one (1,000 times near
  the surge resonance); both are below 0.013 ρ g R there (1.5 against 0.07 N/m² at 0.8 rad/s;
  13 kN/m² in short waves). The chains' pull at the hull's bottom (down and 3 × 21 kN outward) also more than doubles its pitch
  stiffness (65 kN·m/rad hydrostatic about G), moving its pitch resonance from 1.85 rad/s to above
  3 rad/s: at 1.9 rad/s the free drift is twice the moored one; from 2.0 to 3.0 rad/s, where the
  drift is 0.03–0.9 ρ g R, they agree within 15 %.
The `.8` files hold the freely floating values.

What the cylinder's drift shows (heading 0): ~0 in long waves (1e-9 ρ g R at kR = 0.03: a free
body that follows the water scatters nothing), sharp peaks at its lightly damped heave (ω ≈ 1.1,
0.45 ρ g R) and pitch (ω = 1.3, 2.98 ρ g R) resonances, which the 0.1 rad/s grid samples but does
not resolve, then a rise to 0.65 ρ g R at kR ≥ 1.9 and 0.648 at kR = 3.1–4.0, 3 % below the
(2/3) ρ g R limit, which is reached slowly (the exact drift on a fixed deep cylinder, from the
scattered field's Bessel series, is 0.633 ρ g R at kR = 3.13 and 0.639 at 3.97; Capytaine's with
the body held fixed, 0.637 and 0.640 on this mesh, 0.636 and 0.640 on one with 2.4 times the
panels). Its sway and yaw drift (≤ 1.5e-4 ρ g R, 5e-4 ρ g R²) are not quite 0 because
Capytaine's lid is not mirror-symmetric (a staircase of squares, centroid 18 mm off the axis);
the spar, without a lid, has 1e-15.

Mass properties: the cylinder's from cylinder.py; the buoy's the scene's node (8,000 kg,
I = 12,000 / 12,000 / 16,000 kg·m² about G, scenes/moored_buoy.ron); the spar's the scene's
four nodes (platform, tower, nacelle, rotor: 8,066,048 kg, G 78.0 m below the still water level,
scenes/oc3_hywind.ron), about its reference point 89.9155 m down. Deep water, ρ = 1025 kg/m³,
g = 9.80665 m/s².
"""

import sys
import time
from pathlib import Path

import numpy as np
import xarray as xr
import capytaine as cpt
from capytaine.post_pro import rao, far_field_mean_drift_force

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import cylinder  # noqa: E402
import moored_buoy  # noqa: E402
import oc3_spar  # noqa: E402

RHO, G = 1025.0, 9.80665
MESHES = HERE.parent.parent / "scenes" / "meshes"
N_THETA, EXTRA = 72, 6  # Kochin directions per turn, and beyond each end
THETA = 2 * np.pi * np.arange(-EXTRA, N_THETA + EXTRA + 1) / N_THETA


def mass_matrix(nodes, ref):
    """The 6 × 6 rigid-body mass matrix about `ref` of point masses with their own inertia:
    nodes = [(mass, (x, y, z) of its G, (Ixx, Iyy, Izz) about its G)]. Returns (M, mass, G)."""
    mass = sum(m for m, _, _ in nodes)
    cog = sum(m * np.asarray(p, float) for m, p, _ in nodes) / mass
    M = np.zeros((6, 6))
    M[:3, :3] = mass * np.eye(3)
    for m, p, inertia in nodes:
        r = np.asarray(p, float) - ref
        rx = np.array([[0, -r[2], r[1]], [r[2], 0, -r[0]], [-r[1], r[0], 0]])
        M[:3, 3:] += -m * rx  # velocity of the point: v + ω × r
        M[3:, :3] += m * rx
        M[3:, 3:] += np.diag(inertia) + m * (r @ r * np.eye(3) - np.outer(r, r))
    return M, mass, cog


def mooring_stiffness(k_h, k_v, k_yaw, fairleads, tensions, ref):
    """An approximate 6 × 6 mooring stiffness about `ref` (for the printed comparison only): the
    lines' total horizontal (k_h, surge and sway) and vertical (k_v) stiffness acting at the
    fairleads' mean point, a yaw stiffness, and the geometric stiffness of the pretension T_i
    carried round by the rotating fairleads p_i: K_rot += Σ (p_i · T_i) I − p_i T_iᵀ."""
    p = np.asarray(fairleads, float) - ref
    c = p.mean(axis=0)
    cx = np.array([[0, -c[2], c[1]], [c[2], 0, -c[0]], [-c[1], c[0], 0]])
    kt = np.diag([k_h, k_h, k_v])
    K = np.zeros((6, 6))
    K[:3, :3] = kt
    K[:3, 3:] = -kt @ cx
    K[3:, :3] = cx @ kt
    K[3:, 3:] = -cx @ kt @ cx
    for pi, ti in zip(p, np.asarray(tensions, float)):
        K[3:, 3:] += (pi @ ti) * np.eye(3) - np.outer(pi, ti)
    K[5, 5] += k_yaw
    return K


def lines(n, radius, z, t_h, t_v, first=0.0):
    """n fairleads at 360°/n round the axis and their lines' pull (outward t_h, down t_v)."""
    a = first + 2 * np.pi * np.arange(n) / n
    return ([(radius * np.cos(x), radius * np.sin(x), z) for x in a],
            [(t_h * np.cos(x), t_h * np.sin(x), -t_v) for x in a])


def cylinder_body():
    return cylinder.body()


def buoy_body():
    """moored_buoy.py's hull with the scene's mass and inertia about G."""
    b = moored_buoy.body()
    M, mass, cog = mass_matrix([(8000.0, (0, 0, moored_buoy.Z_REF), (12000.0, 12000.0, 16000.0))],
                               np.array([0, 0, moored_buoy.Z_REF]))
    b.mass, b.center_of_mass = mass, cog
    b.inertia_matrix = b.add_dofs_labels_to_matrix(M)
    b.hydrostatic_stiffness = b.compute_hydrostatic_stiffness(rho=RHO, g=G)
    return b


def buoy_mooring(b):
    """scenes/moored_buoy.ron's chains, roughly: fairleads 2 m out on the hull's bottom (1 m
    below G), 5.05 kN/m in surge (`tether equilibrium`), heave 128 kN/m less the waterplane's,
    the hull's excess buoyancy as their vertical pull, 32.5 kN fairlead tension."""
    t_v = (b.disp_mass(rho=RHO) - b.mass) * G / 3
    t_h = np.sqrt(32.5e3**2 - t_v**2)
    ref = np.array([0, 0, moored_buoy.Z_REF])
    p, t = lines(3, 2.0, moored_buoy.Z_REF - 1.0, t_h, t_v)
    k_v = max(128e3 - RHO * G * np.pi * moored_buoy.RADIUS**2, 0.0)
    return mooring_stiffness(5.05e3, k_v, 0.0, p, t, ref)


OC3_NODES = [  # scenes/oc3_hywind.ron: mass, G (world, at rest), inertia about G
    (7466330.0, (0.0, 0.0, -89.9155), (4229230000.0, 4229230000.0, 164230000.0)),
    (249718.0, (0.0, 0.0, 43.4), (119349100.0, 119349100.0, 0.0)),
    (240000.0, (1.9, 0.0, 89.35), (0.0, 0.0, 1741490.0)),
    (110000.0, (-5.0191, 0.0, 90.0), (38759236.0, 19379618.0, 19379618.0)),
]


def oc3_body():
    """oc3_spar.py's hull and lid with the whole turbine's mass about the master node. The lid
    comes out empty (Capytaine warns and ignores it): `generate_lid` grids the waterplane at the
    hull's mean panel size, 1.28 m here (the 3 m panels down the spar), too coarse for a 3.25 m
    waterline circle; so oc3_spar.py's `.1`/`.3` have no lid either, and this drift is of the
    same panel model. Without a lid the first irregular frequency of this hull is about
    √(g j₀₁/R) = 2.7 rad/s, above the 2 rad/s here."""
    mesh = oc3_spar.hull().immersed_part()
    ref = np.array([0, 0, oc3_spar.Z_REF])
    M, mass, cog = mass_matrix(OC3_NODES, ref)
    b = cpt.FloatingBody(mesh=mesh, lid_mesh=mesh.generate_lid(),
                         dofs=cpt.rigid_body_dofs(rotation_center=tuple(ref)),
                         center_of_mass=tuple(cog), mass=mass)
    b.inertia_matrix = b.add_dofs_labels_to_matrix(M)
    b.hydrostatic_stiffness = b.compute_hydrostatic_stiffness(rho=RHO, g=G)
    return b


def oc3_mooring(b):
    """scenes/oc3_hywind.ron's lines (`tether equilibrium`): fairleads 5.2 m out, 70 m down,
    41,181 N/m in surge, 11,942 N/m in heave, 11.567e6 + 98.34e6 N·m/rad in yaw (the delta
    connection's springs), 736.94 kN horizontal and 1,607.2 kN / 3 vertical pull each."""
    ref = np.array([0, 0, oc3_spar.Z_REF])
    p, t = lines(3, 5.2, -70.0, 736.94e3, 1607.2e3 / 3)
    return mooring_stiffness(41181.0, 11942.0, 11.567e6 + 98.34e6, p, t, ref)


BODIES = {
    # name: (body, mooring stiffness or None, ω [rad/s], output stem, length for the table)
    "cylinder": (cylinder_body, None, np.round(np.arange(0.3, 3.6001, 0.1), 4),
                 cylinder.OUT / "cylinder", cylinder.R),
    "buoy": (buoy_body, buoy_mooring, np.round(np.arange(0.3, 3.0001, 0.1), 4),
             MESHES / "buoy", moored_buoy.RADIUS),
    # 0.25 rad/s, not 0.2: the freely floating spar's heave resonance (see the docstring).
    "oc3": (oc3_body, oc3_mooring, np.round(np.concatenate([[0.25], np.arange(0.3, 2.0001, 0.1)]), 4),
            MESHES / "oc3_spar", 3.25),
}


def drift(ds, X):
    """Capytaine's far-field drift, the unidirectional (k = l) heading 0, real [N/m², N·m/m²]."""
    d = far_field_mean_drift_force(X, ds).sel(wave_direction_k=0.0, wave_direction_l=0.0)
    return {dof: d[f"drift_force_{dof}"].values for dof in ("surge", "sway", "yaw")}


def run(name):
    make, mooring, w, stem, length = BODIES[name]
    t0 = time.time()
    b = make()
    lid = f"{b.lid_mesh.nb_faces} on the lid" if b.lid_mesh is not None else "no lid"
    print(f"{name}: {b.mesh.nb_faces} panels + {lid}, {len(w)} frequencies "
          f"{w[0]}–{w[-1]} rad/s, {len(THETA)} Kochin directions")
    test = xr.Dataset(coords={"omega": w, "wave_direction": [0.0], "radiating_dof": list(b.dofs),
                              "water_depth": [np.inf], "rho": [RHO], "g": [G], "theta": THETA})
    ds = cpt.BEMSolver().fill_dataset(test, b)
    t1 = time.time()
    X = rao(ds)
    res = far_field_mean_drift_force(X, ds)
    # The WAMIT writer reads rho, g and period as coordinates of the drift; the drift carries none.
    res = res.assign_coords(rho=RHO, g=G, period=("omega", 2 * np.pi / w))
    out = Path(f"{stem}.8")
    out.unlink(missing_ok=True)
    cpt.export_dataset(str(stem), res, format="wamit", exports=("8",))
    if not out.exists():  # the exporter only logs a warning when it fails
        raise SystemExit(f"Capytaine did not write {out}")
    print(f"solve {t1 - t0:.0f} s, drift and export {time.time() - t1:.1f} s → {out}")

    d = drift(ds, X)
    coarse = drift(ds.isel(theta=slice(None, None, 2)), X)  # every other direction: 10° apart
    moored = drift(ds, rao(ds, stiffness=b.add_dofs_labels_to_matrix(mooring(b)))) if mooring else None
    for dof in ("surge", "sway", "yaw"):
        im = np.abs(np.imag(d[dof])).max()
        assert im < 1e-6 * max(1.0, np.abs(d[dof]).max()), (dof, im)
    kR = w**2 / G * length
    norm = RHO * G * length
    print(f"heading 0; D/(ρ g L) with L = {length} m (yaw: D₆/(ρ g L²))")
    print("  omega     kL     D1/ρgL   10°-grid     D2/ρgL    D6/ρgL²" + ("  moored D1/ρgL" if moored else ""))
    for i, om in enumerate(w):
        row = (f"{om:7.3f} {kR[i]:6.3f} {d['surge'][i].real / norm:10.3e} {coarse['surge'][i].real / norm:10.3e}"
               f" {d['sway'][i].real / norm:10.1e} {d['yaw'][i].real / (norm * length):10.1e}")
        if moored:
            row += f" {moored['surge'][i].real / norm:15.3e}"
        print(row)
    if name == "cylinder":
        with open(stem.parent / "cylinder_drift.csv", "w") as f:
            f.write("# Capytaine 3.0.0 far-field mean surge drift of validation/potential-flow/cylinder.py's body"
                    " (validation/potential-flow/drift.py), freely floating, heading 0\n")
            f.write(f"# D1 per unit wave amplitude squared [N/m^2], positive along +x (the waves' way); kR = omega^2 R / g,"
                    f" R = {length} m, rho = {RHO}, g = {G}\n")
            f.write("omega,kR,surge_drift_N_per_m2\n")
            for i, om in enumerate(w):
                f.write(f"{om:.4f},{kR[i]:.6f},{d['surge'][i].real:.8e}\n")
    print(f"{name}: {time.time() - t0:.0f} s")


def main():
    names = sys.argv[1:] or list(BODIES)
    for name in names:
        if name not in BODIES:
            raise SystemExit(f"usage: drift.py [{'|'.join(BODIES)}] ...")
    for name in names:
        run(name)


if __name__ == "__main__":
    main()
