"""The moored buoy's offset curve (the restoring force as the buoy is held 0 to 40 m off its
equilibrium along x, the lines settled at each offset) and each line's tension, with matplotlib.

    pip install ./python matplotlib
    python examples/python/offset_curve.py            # writes offset_curve.png

Past about 20 m the lines ahead lift off the seabed up to their anchors and the curve stiffens;
mooring2 and mooring3 lie symmetric about x: their curves coincide.
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import tether

scene = Path(__file__).resolve().parents[2] / "scenes" / "moored_buoy.ron"
sim = tether.load(scene)

rest = sim.equilibrium()
print(f"equilibrium of {rest.bodies[0]} at {rest.position[0].round(3)} m")
print("surge stiffness K_xx =", f"{rest.stiffness[0, 0, 0]:.4g} N/m")

curve = sim.offsets("buoy", "x", 40.0, steps=40)
offset = curve["offset x [m]"]

fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 7))
top.plot(offset, curve["restoring [N]"] / 1e3)
top.set_ylabel("restoring force [kN]")
top.set_title(f"{scene.stem}: offset curve of the buoy in x")
for name in sim.couplings:
    column = f"{name} T2 [N]"
    if column in curve:
        bottom.plot(offset, curve[column] / 1e3, label=f"{name} (fairlead)")
bottom.set_xlabel("offset x [m]")
bottom.set_ylabel("line tension [kN]")
bottom.legend()
fig.tight_layout()
fig.savefig("offset_curve.png", dpi=120)
print("wrote offset_curve.png")
