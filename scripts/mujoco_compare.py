"""Steps per CPU second of the whole `tether record` process against a loop of MuJoCo's `mj_step`
on the same chain (scenes/bench/chain100*.ron beside chain100*.xml), ROUNDS rounds interleaved
(each Tether binary, then MuJoCo), medians; then where each chain is at the end, to show that the
two models are the same chain. Run by scripts/mujoco-compare.sh, which builds Tether and installs
the `mujoco` package:
    SCENES="chain100 chain100_air" DURATION=60 python scripts/mujoco_compare.py STEPS_EXAMPLE ROUNDS TETHER...

Tether's side is the whole process (start, scene load, the framing, the physics, the recorder
at 60 frames a second, the file written), its user + system CPU as the kernel counts it for the
child; MuJoCo's side is its loop of `mj_step` alone, in C (`mj_step(model, data, nstep)`, the
model compiled beforehand). Tether's physics alone is timed too, as the `steps` example's whole
process (the scene loaded and stepped, no recorder; this checkout's physics): the per-step ratio.
"""

import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import mujoco
import numpy as np

NUMBER = r"(-?[\d.]+(?:e[+-]?\d+)?)"


def ron_chain(text):
    """The chain a bench RON file describes: step, duration, gravity, bodies, springs, anchors."""
    bodies = re.findall(
        rf'name: "(ball\d+)",\s*master: Node\(position: \({NUMBER}, {NUMBER}, {NUMBER}\), mass: {NUMBER}, '
        rf"inertia: Inertia\(xx: {NUMBER}, yy: {NUMBER}, zz: {NUMBER}\)\),\s*shape: Sphere\(radius: {NUMBER}",
        text,
    )
    end = r'(World\(\([^)]*\)\)|Body\(body: "ball\d+"\))'
    springs = re.findall(
        rf'SpringDamper\(name: "spring\d+", end1: {end}, end2: {end}, '
        rf"law: Linear\(stiffness: {NUMBER}, rest_length: {NUMBER}\), damping: {NUMBER}\)",
        text,
    )
    return {
        "dt": float(re.search(rf"\bdt: {NUMBER}", text).group(1)),
        "duration": float(re.search(rf"\bduration: {NUMBER}", text).group(1)),
        "gravity": [float(g) for g in re.search(rf"gravity: \({NUMBER}, {NUMBER}, {NUMBER}\)", text).groups()],
        "bodies": [(name, [float(v) for v in values]) for name, *values in bodies],
        "springs": springs,
        "contacts": len(re.findall(r"\bContact\(", text)),
        "friction": float(re.search(rf"friction: {NUMBER}", text).group(1)) if "friction:" in text else None,
    }


def check_same_chain(chain, model):
    """Fails unless the compiled MJCF holds the RON file's bodies, springs and settings."""
    assert model.opt.timestep == chain["dt"], (model.opt.timestep, chain["dt"])
    assert np.allclose(model.opt.gravity, chain["gravity"])
    assert model.nbody - 1 == len(chain["bodies"]) == 100, model.nbody
    for name, (x, y, z, mass, ixx, iyy, izz, radius) in chain["bodies"]:
        body = model.body(name)
        assert np.allclose(body.pos, [x, y, z], rtol=0, atol=1e-12), name
        assert body.mass[0] == mass and np.allclose(body.inertia, [ixx, iyy, izz]), name
        assert model.geom_size[body.geomadr[0]][0] == radius, name
    assert model.ntendon == len(chain["springs"]) == 101, model.ntendon
    for index, (end1, end2, stiffness, rest, damping) in enumerate(chain["springs"]):
        assert model.tendon_stiffness[index] == float(stiffness), index
        assert model.tendon_damping[index] == float(damping), index
        assert np.all(model.tendon_lengthspring[index] == float(rest)), index
        sites = [model.wrap_objid[model.tendon_adr[index] + k] for k in range(2)]
        for site, end in zip(sites, (end1, end2)):
            ball = re.search(r'"(ball\d+)"', end)
            if ball:
                assert model.site_bodyid[site] == model.body(ball.group(1)).id, (index, end)
            else:
                point = [float(v) for v in re.search(r"\(\(([^)]*)\)\)", end).group(1).split(",")]
                assert model.site_bodyid[site] == 0 and np.allclose(model.site_pos[site], point), (index, end)
    assert model.ngeom - 100 == (1 if chain["contacts"] else 0), model.ngeom
    if chain["contacts"]:
        assert chain["contacts"] == 100 and model.geom_friction[0][0] == chain["friction"], model.geom_friction[0]
    else:
        assert model.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_CONTACT, "no contact in either"


def cpu_rate(command, steps):
    """Steps per CPU second (user + system, as the kernel counts it for the child) of a process
    taking `steps` steps, and what it printed."""
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    stdout, stderr = process.communicate()
    if process.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{stderr}")
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    spent = usage.ru_utime + usage.ru_stime - cpu_rate.spent
    cpu_rate.spent = usage.ru_utime + usage.ru_stime
    return steps / spent, stdout


cpu_rate.spent = 0.0


def mujoco_round(model, steps):
    """Steps per CPU second of `steps` calls of `mj_step` from the model's initial state, and the data."""
    data = mujoco.MjData(model)
    start = time.process_time()
    mujoco.mj_step(model, data, nstep=steps)
    return steps / (time.process_time() - start), data


def mujoco_figure(model, data):
    """Where MuJoCo's chain is: the line the steps example prints for Tether's."""
    heights = data.xpos[1:, 2]
    velocities = data.qvel.reshape(-1, 6)
    kinetic = 0.5 * (model.body_mass[1:] @ (velocities[:, :3] ** 2).sum(axis=1)) + 0.5 * (
        model.body_inertia[1:] * velocities[:, 3:] ** 2
    ).sum()
    return f"t = {data.time:.3f} s: mean height {heights.mean():.4f} m, lowest {heights.min():.4f} m, kinetic energy {kinetic:.2f} J"


def main():
    steps_example, rounds, *binaries = sys.argv[1:]
    with tempfile.TemporaryDirectory() as out:
        for stem in os.environ.get("SCENES", "chain100 chain100_air").split():
            ron, xml = f"scenes/bench/{stem}.ron", f"scenes/bench/{stem}.xml"
            chain = ron_chain(open(ron, encoding="utf-8").read())
            model = mujoco.MjModel.from_xml_path(xml)
            check_same_chain(chain, model)
            duration = float(os.environ.get("DURATION", chain["duration"]))
            steps = round(duration / chain["dt"])
            process = {binary: [] for binary in binaries}
            physics, engine = [], []
            stepping = [steps_example, ron, "0", str(steps)]
            for _ in range(int(rounds)):
                for binary in binaries:
                    record = [binary, "record", ron, "--duration", str(duration), "-o", os.path.join(out, "run.rrd")]
                    whole, _ = cpu_rate(record, steps)
                    process[binary].append(whole)
                rate, figure = cpu_rate(stepping, steps)
                physics.append(rate)
                rate, data = mujoco_round(model, steps)
                engine.append(rate)
            mujoco_rate, physics_rate = statistics.median(engine), statistics.median(physics)
            print(f"{stem}: {steps} steps, medians of {rounds} rounds")
            print(f"  mujoco {mujoco.__version__} mj_step loop: {mujoco_rate:.0f} steps per CPU second")
            for binary in binaries:
                tether_rate = statistics.median(process[binary])
                print(f"  {binary} record, whole process: {tether_rate:.0f} steps per CPU second, {tether_rate / mujoco_rate:.2f}x")
            print(
                f"  {steps_example} (load and step, no recorder), whole process: {physics_rate:.0f} steps per CPU"
                f" second, {physics_rate / mujoco_rate:.2f}x"
            )
            print(f"  tether {figure.strip()}")
            print(f"  mujoco {mujoco_figure(model, data)}")


if __name__ == "__main__":
    main()
