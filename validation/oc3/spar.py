#!/usr/bin/env python3
"""The OC3-Hywind spar of scenes/oc3_hywind.ron: writes its hull mesh and prints the numbers the
scene declares that are derived rather than published (standard library only; rerun it to check).

Published geometry (Jonkman 2010, "Definition of the Floating System for Phase IV of OC3",
NREL/TP-500-47535, Table 3-1): draft 120 m, platform top (tower base) 10 m above SWL, diameter
6.5 m above the taper, 9.4 m below it, taper from 4 m to 12 m below SWL.

    python3 validation/oc3/spar.py            # prints the derived numbers
    python3 validation/oc3/spar.py --write    # also writes scenes/meshes/oc3_spar.obj
"""

import math
import sys
from pathlib import Path

RHO = 1025.0  # kg/m³
G = 9.80665  # m/s²
# (z, diameter) down the spar, SWL coordinates [m]; the diameter changes linearly between.
PROFILE = [(10.0, 6.5), (-4.0, 6.5), (-12.0, 9.4), (-120.0, 9.4)]
SIDES = 48
Z_G = None  # set in main: the full system's centre of mass [m]


def diameter(z):
    """Diameter [m] at height z [m] (SWL coordinates)."""
    for (z0, d0), (z1, d1) in zip(PROFILE, PROFILE[1:]):
        if z1 <= z <= z0:
            return d0 + (d1 - d0) * (z0 - z) / (z0 - z1)
    raise ValueError(z)


def integrate(f, a, b, n=20000):
    """∫_a^b f(z) dz by the midpoint rule (n panels; smooth integrands, error ~1e-9 relative)."""
    h = (b - a) / n
    return h * sum(f(a + (i + 0.5) * h) for i in range(n))


def mass_properties():
    """The full system as one rigid body: platform, tower, nacelle and rotor (the nodes of the
    scene), its mass [kg], G [m] and inertia about G [kg·m²] (xx = yy: roll, pitch; zz: yaw)."""
    # (mass kg, (x, z) m, own inertia (ixx, iyy, izz) kg·m²)
    nodes = [
        # Jonkman 2010 Table 3-1: platform with ballast.
        (7_466_330.0, (0.0, -89.9155), (4_229_230_000.0, 4_229_230_000.0, 164_230_000.0)),
        # Jonkman 2010 Table 2-1 (tower mass and CM); own inertia: tower_inertia().
        (249_718.0, (0.0, 43.4), tower_inertia()),
        # Jonkman, Butterfield, Musial & Scott 2009 (NREL/TP-500-38060), Table 1-1 and §4:
        # nacelle 240 t, CM 1.9 m downwind of the yaw axis, 1.75 m above the yaw bearing at
        # 87.6 m; inertia about the yaw axis 2,607,890 kg·m² (less its own m·1.9² here).
        (240_000.0, (1.9, 89.35), (0.0, 0.0, 2_607_890.0 - 240_000.0 * 1.9**2)),
        # Rotor (hub and blades) 110 t at the hub, 5.0191 m upwind, 90 m up; inertia about the
        # shaft 38,759,236 kg·m², half of it about a diameter (a disc).
        (110_000.0, (-5.0191, 90.0), (38_759_236.0, 19_379_618.0, 19_379_618.0)),
    ]
    mass = sum(m for m, _, _ in nodes)
    xg = sum(m * x for m, (x, _), _ in nodes) / mass
    zg = sum(m * z for m, (_, z), _ in nodes) / mass
    ixx = sum(i[0] + m * (z - zg) ** 2 for m, (x, z), i in nodes)
    iyy = sum(i[1] + m * ((x - xg) ** 2 + (z - zg) ** 2) for m, (x, z), i in nodes)
    izz = sum(i[2] + m * (x - xg) ** 2 for m, (x, z), i in nodes)
    return mass, xg, zg, ixx, iyy, izz


def tower_inertia():
    """The OC3 tower's own inertia [kg·m²] about its CM (Jonkman 2010 §2: 10 m to 87.6 m above
    SWL, diameter 6.5 → 3.87 m, wall 27 → 19 mm, both linear): a thin tube, its mass scaled to
    the published 249,718 kg; its CM lands at 43.5 m against the published 43.4 m."""
    z0, z1 = 10.0, 87.6
    per_m = lambda z: math.pi * (6.5 - 2.63 * (z - z0) / (z1 - z0)) * (0.027 - 0.008 * (z - z0) / (z1 - z0))
    raw = integrate(per_m, z0, z1)
    zc = integrate(lambda z: per_m(z) * z, z0, z1) / raw
    scale = 249_718.0 / raw
    bending = scale * integrate(lambda z: per_m(z) * (z - zc) ** 2, z0, z1)
    return (bending, bending, 0.0)


def hydro(zg):
    """Morison strip theory over the wet spar (z from −120 m to 0), about G at height zg [m]:
    displaced volume, waterplane area and its second moment, centre of buoyancy, the pitch added
    inertia for C_a = 1 and the rotational drag coefficient for C_d = 0.6."""
    area = lambda z: math.pi * diameter(z) ** 2 / 4
    volume = integrate(area, -120.0, 0.0)
    zb = integrate(lambda z: area(z) * z, -120.0, 0.0) / volume
    added_pitch = integrate(lambda z: RHO * area(z) * (z - zg) ** 2, -120.0, 0.0)
    rot_drag = integrate(lambda z: 0.5 * RHO * 0.6 * diameter(z) * abs(z - zg) ** 3, -120.0, 0.0)
    total = volume + integrate(area, 0.0, 10.0)
    return volume, zb, added_pitch, rot_drag, total


def mesh():
    """The hull: rings at the profile's corners and every 12 m below the taper, SIDES sides each,
    radii scaled so each polygon has the circle's area (the displaced volume and waterplane area
    are then exact); closed, faces wound counter-clockwise seen from outside."""
    rings = [10.0, 0.0, -4.0, -12.0] + [-12.0 - 12.0 * k for k in range(1, 10)]
    scale = math.sqrt(2 * math.pi / (SIDES * math.sin(2 * math.pi / SIDES)))
    vertices, faces = [], []
    for z in rings:
        r = 0.5 * diameter(z) * scale
        for k in range(SIDES):
            a = 2 * math.pi * k / SIDES
            vertices.append((r * math.cos(a), r * math.sin(a), z))
    top, bottom = len(vertices), len(vertices) + 1
    vertices += [(0.0, 0.0, rings[0]), (0.0, 0.0, rings[-1])]
    for i in range(len(rings) - 1):
        for k in range(SIDES):
            a, b = i * SIDES + k, i * SIDES + (k + 1) % SIDES
            c, d = a + SIDES, b + SIDES
            faces += [(a, c, d), (a, d, b)]
    last = (len(rings) - 1) * SIDES
    for k in range(SIDES):
        faces.append((top, k, (k + 1) % SIDES))
        faces.append((bottom, last + (k + 1) % SIDES, last + k))
    return vertices, faces


def main():
    mass, xg, zg, ixx, iyy, izz = mass_properties()
    volume, zb, added_pitch, rot_drag, total = hydro(zg)
    wet = volume / total
    print(f"full system: mass {mass:,.0f} kg, G at x = {xg:.4f} m, z = {zg:.4f} m")
    print(f"  inertia about G: roll {ixx:.6e}, pitch {iyy:.6e}, yaw {izz:.6e} kg·m²")
    print(f"  tower own inertia {tower_inertia()[0]:.6e} kg·m²")
    print(f"displaced volume {volume:.3f} m³ (buoyancy {RHO * G * volume:,.0f} N), centre of buoyancy z = {zb:.4f} m")
    print(f"  buoyancy − weight = {RHO * G * volume - mass * G:,.0f} N (the lines' vertical pull at rest)")
    print(f"  hull volume {total:.3f} m³, wetted fraction {wet:.6f}")
    print(f"  waterplane area {math.pi * 6.5**2 / 4:.4f} m², heave stiffness ρgA {RHO * G * math.pi * 6.5**2 / 4:,.0f} N/m")
    print(f"pitch added inertia about G (C_a = 1): {added_pitch:.6e} kg·m² (declared /w: {added_pitch / wet:.6e})")
    print(f"rotational drag about G (C_d = 0.6): {rot_drag:.6e} N·m·s² (declared /w: {rot_drag / wet:.6e})")
    heave_added = 4.0 / 3.0 * RHO * 4.7**3
    print(f"heave added mass (4/3)ρa³ = {heave_added:,.0f} kg: C_a,z = {heave_added / (RHO * volume):.6f}")
    if "--write" in sys.argv:
        vertices, faces = mesh()
        out = Path(__file__).resolve().parents[2] / "scenes/meshes/oc3_spar.obj"
        with out.open("w") as f:
            f.write("# The OC3-Hywind spar (Jonkman 2010, NREL/TP-500-47535): 120 m draft, 10 m freeboard,\n")
            f.write(f"# 6.5 m above the taper (4 to 12 m below SWL), 9.4 m below; {SIDES} sides, radii scaled so each\n")
            f.write("# polygon has its circle's area. SWL coordinates (z = 0 at the still water level), metres;\n")
            f.write("# closed, counter-clockwise seen from outside. Written by validation/oc3/spar.py --write.\n")
            for v in vertices:
                f.write("v {:.6f} {:.6f} {:.6f}\n".format(*v))
            for a, b, c in faces:
                f.write(f"f {a + 1} {b + 1} {c + 1}\n")
        print(f"wrote {out} ({len(vertices)} vertices, {len(faces)} triangles)")


if __name__ == "__main__":
    main()
