"""The moored buoy released off its rest position: each mooring line's tension over 60 s of
simulated time, sampled at 20 Hz, with matplotlib; then the same run with stiffer lines, set by
the sweep's parameter path. mooring2 and mooring3 lie symmetric about the buoy's path (x): their
curves coincide.

    pip install ./python matplotlib
    python examples/python/tension_series.py          # writes tension_series.png
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import tether

scene = Path(__file__).resolve().parents[2] / "scenes" / "moored_buoy.ron"
fig, axes = plt.subplots(2, 1, sharex=True, figsize=(8, 7))
for ax, factor in zip(axes, (1.0, 3.0)):
    sim = tether.load(scene)
    for line in ("mooring1", "mooring2", "mooring3"):
        path = f"couplings.{line}.stiffness"
        sim[path] = sim[path] * factor
    run = sim.run(60.0, rate=20.0)  # GIL released; Ctrl-C stops it
    for name in ("mooring1", "mooring2", "mooring3"):
        ax.plot(run.time, run.coupling(name)["tension"] / 1e3, label=name)
    ax.set_ylabel("tension [kN]")
    ax.set_title(f"line stiffness × {factor:g}")
    ax.legend(loc="upper right")
    drift = run.energy["balance"][-1] - run.energy["balance"][0]
    print(f"× {factor:g}: largest tension {run.tension.max() / 1e3:.1f} kN; energy balance moved {drift:.3g} J")
axes[-1].set_xlabel("time [s]")
fig.tight_layout()
fig.savefig("tension_series.png", dpi=120)
print("wrote tension_series.png")
