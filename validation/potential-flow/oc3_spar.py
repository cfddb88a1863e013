#!/usr/bin/env python3
"""The OC3-Hywind spar's potential-flow coefficients from Capytaine 3.0.0 on the hull of
scenes/meshes/oc3_spar.obj, written as the WAMIT files scenes/oc3_hywind.ron reads (docs/PHYSICS.md §9).

    nice ~/.cache/tether/capytaine-venv/bin/python validation/potential-flow/oc3_spar.py

(the environment as in cylinder.py; about 30 minutes on 2 busy cores). Writes
`scenes/meshes/oc3_spar.1` and `.3` (heading 0°), beside the mesh.

The mesh: the OBJ's 48-sided rings (its radii, each polygon with its circle's area) at its own
heights, with rings added between them (`row_height`: 0.4 m at the surface, where the shortest
waves move the water, to 3 m from 10 m down; the hull is straight between its rings, so the
surface is the same: the OBJ's 12 m strips are too slender for the panel method), clipped at the
still water level, with a lid against irregular frequencies. Frequencies 0.02 to 4 rad/s: the
spar's surge damping is still 60 % of its peak at 2 rad/s, and a kernel cut there rings.

Reference point (WAMIT's origin, the rotation centre of every coefficient): the scene's master
node, the platform's centre of gravity 89.9155 m below the still water level (the origin of the
body's reference frame in scenes/oc3_hywind.ron). Deep water: Capytaine gives the ω = 0 limit
only in infinite depth, and the site's 320 m changes the surge and pitch added mass at the pitch
period by 0.02 % (Capytaine at ω = 0.2, 0.215 and 0.23 rad/s, both depths, run by hand on `hull()`).
Mass and stiffness are not written: the scene's own (its nodes, its mesh's buoyancy, its lines).
"""

from pathlib import Path

import numpy as np
import xarray as xr
import capytaine as cpt

RHO, G = 1025.0, 9.80665
Z_REF = -89.9155  # the master node [m]
HERE = Path(__file__).resolve().parent
OBJ = HERE.parent.parent / "scenes" / "meshes" / "oc3_spar.obj"
OUT = HERE.parent.parent / "scenes" / "meshes"
MAX_ROW = 3.0  # m


def row_height(z):
    """The panels' height at depth -z [m]: 0.4 m at the surface, where the shortest waves
    (4 rad/s: 3.9 m long) still move the water, growing by a quarter of the depth to MAX_ROW."""
    return min(MAX_ROW, 0.4 + 0.25 * max(-z, 0.0))


def rings():
    """The OBJ's rings: {z: polygon radius}, from its vertices (x, y, z)."""
    radius = {}
    for line in OBJ.read_text().splitlines():
        if line.startswith("v "):
            x, y, z = map(float, line.split()[1:4])
            radius[z] = max(radius.get(z, 0.0), np.hypot(x, y))
    return dict(sorted(radius.items(), reverse=True))


def hull(sides=48):
    """Quads down the side between the OBJ's rings (refined as `row_height` says) and a bottom disc."""
    profile = list(rings().items())
    levels = []
    for (z0, r0), (z1, r1) in zip(profile, profile[1:]):
        z = z0
        while z > z1 + 1e-9:
            levels.append((z, r0 + (r1 - r0) * (z - z0) / (z1 - z0)))
            step = row_height(z)
            z = z1 if z - step < z1 + 0.25 * step else z - step
    levels.append(profile[-1])
    phi = 2 * np.pi * np.arange(sides) / sides
    vertices = [(r * np.cos(p), r * np.sin(p), z) for z, r in levels for p in phi]
    faces = []
    for row in range(len(levels) - 1):
        for k in range(sides):
            a, b = row * sides + k, row * sides + (k + 1) % sides
            faces.append([a, a + sides, b + sides, b])  # outward normals
    # Bottom: rings of quads toward the centre.
    z_bottom, r_bottom = levels[-1]
    start = (len(levels) - 1) * sides
    n_rings = 4
    previous = list(range(start, start + sides))
    for ring in range(1, n_rings):
        r = r_bottom * (1 - ring / n_rings)
        first = len(vertices)
        vertices += [(r * np.cos(p), r * np.sin(p), z_bottom) for p in phi]
        current = list(range(first, first + sides))
        for k in range(sides):
            faces.append([previous[k], current[k], current[(k + 1) % sides], previous[(k + 1) % sides]])
        previous = current
    centre = len(vertices)
    vertices.append((0.0, 0.0, z_bottom))
    for k in range(sides):
        faces.append([previous[k], centre, centre, previous[(k + 1) % sides]])
    return cpt.Mesh(vertices=np.array(vertices), faces=np.array(faces), name="oc3_spar")


def main():
    OUT.mkdir(exist_ok=True)
    mesh = hull().immersed_part()
    body = cpt.FloatingBody(mesh=mesh, lid_mesh=mesh.generate_lid(),
                            dofs=cpt.rigid_body_dofs(rotation_center=(0, 0, Z_REF)),
                            center_of_mass=(0, 0, Z_REF))
    print(f"{mesh.nb_faces} panels")
    # 0.02 rad/s apart up to 1 rad/s (the spar's resonances), 0.05 apart to 4 rad/s, where its
    # surge damping has fallen off (at 2 rad/s it is still 60 % of its peak: a kernel cut there rings).
    w = np.concatenate([np.arange(0.02, 1.0001, 0.02), np.arange(1.05, 4.0001, 0.05)])
    test = xr.Dataset(coords={"omega": np.concatenate([[0.0], w, [np.inf]]), "wave_direction": [0.0],
                              "radiating_dof": list(body.dofs), "water_depth": [np.inf], "rho": [RHO], "g": [G]})
    ds = cpt.BEMSolver().fill_dataset(test, body)
    cpt.export_dataset(str(OUT / "oc3_spar"), ds, format="wamit", exports=("1", "3"))


if __name__ == "__main__":
    main()
