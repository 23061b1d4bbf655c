"""Measure the running behaviour and write the results into docs/running.md (between the
<!-- results --> markers) and the figures docs/running_*.png.

    python -m sim_core report running            # everything (several minutes on 2 cores)
    python -m sim_core report running --quick    # shorter runs, no 100 s runs
    python -m sim_core report running --fig12    # only Fig. 12: man, woman and child beside the human rows

Every number comes from a simulation started from the standing pose (the issue asks for a start
from a stand), read off the trajectory by sim_core.gait and the behaviour's own assess().
"""
from __future__ import annotations

import argparse
import math
import re
import sys
import time
from multiprocessing import Pool
from pathlib import Path

import numpy as np

ROOT = Path.cwd()                   # docs are written under the folder it runs in (the checkout)

from ...gait import HUMAN_FIG12, SIMULATED_1997, STEADY_RUN

DOC = ROOT / "docs" / "running.md"


def speeds() -> list[float]:
    """The speeds of the man's running table he is offered: its rows, the ends of his offered ranges."""
    from .behaviour import offered_speeds
    return offered_speeds("man")
HIP_ROTATION_NEAR_RANGE = 0.75     # rad: the stance hip's rotation counted as at its range (+-0.785 rad)


def hip_yaw_probe():
    """Instrument (read only) the running behaviour of this worker process: after each control
    tick, note whether the stance hip's yaw servo is at its torque limit, and per stance how far
    the stance foot turned about the vertical on the ground (touchdown to lift-off) and the
    largest rotation of the stance hip. Returns the lists the samples go to: (time, saturated)
    per tick and (lift-off time, foot pivot rad, largest |hip rotation| rad) per stance."""
    from . import behaviour as running
    update = running.Running.update
    if getattr(update, "probe", None) is not None:
        return update.probe
    samples, stances, current = [], [], {}
    stance = {running.LOADING, running.HEEL, running.HEEL_TOE, running.TOE, running.UNLOADING}

    def probed(self, t):
        update(self, t)
        d, model = self.ctx.data, self.ctx.model
        key = (self.active, self.t_touchdown)
        if current and (current["key"] != key or self.state not in stance):
            stances.append((t, abs(running.wrap_angle(current["last"] - current["first"])), current["hz"]))
            current.clear()
        if self.state in stance:
            i = self.j[self.active]["hz"]
            force, limit = d.actuator_force[i], model.actuator_forcerange[i, 1]
            samples.append((t, abs(force) >= 0.99 * limit))
            foot = model.body("FOOTR" if self.active == 0 else "FOOTL").id
            yaw = math.atan2(d.xmat[foot, 3], d.xmat[foot, 0])
            hz = abs(float(self.ctx.servos.angles()[i]))
            if not current:
                current.update(key=key, first=yaw, hz=0.0)
            current["last"] = yaw
            current["hz"] = max(current["hz"], hz)
    probed.probe = (samples, stances)
    running.Running.update = probed
    return probed.probe


def simulate(job):
    """(name, params, duration) -> summary dict (run in a worker process)."""
    from ...simulate import RunRequest, run
    name, params, duration = job
    started = time.perf_counter()
    samples, stances = hip_yaw_probe()
    samples.clear()
    stances.clear()
    traj = run(RunRequest("running", "man", params=params, duration=duration))
    m = traj.meta["metrics"]
    end = m["fall_time"] if m["fell"] else duration
    window = [s for t, s in samples if end - 5.0 <= t <= end]
    hip_yaw_saturated = 100.0 * sum(window) / len(window) if window else None
    last = [(pivot, hz) for t, pivot, hz in stances if end - 5.0 <= t <= end]
    foot_pivot = math.degrees(float(np.mean([p for p, _ in last]))) if last else None
    # the hip's rotation range is +-0.785 rad (45 deg): a stance leg that reaches it was turned by the foot's pivot
    at_range = 100.0 * float(np.mean([hz >= HIP_ROTATION_NEAR_RANGE for _, hz in last])) if last else None
    out = {"name": name, "params": params, "duration": duration, "outcome": traj.meta["outcome"],
           "fall_time": m["fall_time"], "gait": m["gait"], "time_to_90pct_speed": m["time_to_90pct_speed"],
           "path_deviation_mean": m.get("path_deviation_mean"), "path_deviation_max": m.get("path_deviation_max"),
           "stride_attitude_variation": m.get("stride_attitude_variation"), "hip_yaw_saturated": hip_yaw_saturated,
           "foot_pivot_deg": foot_pivot, "hip_rotation_at_range": at_range,
           "wall_s": time.perf_counter() - started}
    a = traj.arrays
    if name == f"speed {speeds()[-1]}":
        dof = traj.meta["dof_names"]
        import mujoco
        model = mujoco.MjModel.from_xml_string(traj.meta["model_xml"])
        sel = a["time"] >= a["time"][-1] - 3.0
        out["hip"] = (-a["qpos"][sel, model.joint("hip_r_y").qposadr[0]]).tolist()    # flexion positive
        out["knee"] = a["qpos"][sel, model.joint("knee_r_y").qposadr[0]].tolist()
    if name.startswith(("turn", "eight", "circle")):
        out["xy"] = a["com"][::4, :2].tolist()
    if name.startswith("start"):
        out["t"] = a["time"][::4].tolist()
        out["speed"] = np.linalg.norm(a["com_vel"][::4, :2], axis=1).tolist()
    return out


def jobs(quick: bool) -> list:
    d = 14.0 if quick else STEADY_RUN
    out = [] if quick else [(f"long {v}", {"speed": v}, 100.0) for v in (3.0, speeds()[-1])]   # longest first
    out += [(f"speed {v}", {"speed": v}, d) for v in speeds()]
    out.append(("start 3.5", {"speed": 3.5}, 8.0))
    if not quick:                      # a whole eight and a third of radius-20 m loops
        out.append(("eight r20", {"speed": 3.5, "course": 2, "turn_radius": 20.0, "turn_after": 25.0}, 100.0))
    out.append(("circle 40", {"speed": 3.5, "course": 3, "turn_radius": 40.0, "turn_after": 15.0}, 24.0))
    for r in (20.0, 30.0):             # 90-degree turns inside the offered region (v^2 / r <= 0.625 m/s^2)
        out.append((f"turn 90 r{r:g}", {"speed": 3.5, "course": 1, "turn_angle": math.pi / 2, "turn_radius": r,
                                        "turn_after": 25.0}, 32.0))
    # the tightest courses offered at 3.0 m/s (radius 14.4 m: 0.625 m/s^2)
    out.append(("turn 90 v3", {"speed": 3.0, "course": 1, "turn_angle": math.pi / 2, "turn_radius": 14.4,
                               "turn_after": 25.0}, 24.0))
    out.append(("eight v3", {"speed": 3.0, "course": 2, "turn_radius": 14.4, "turn_after": 25.0}, 50.0))
    return out


def fmt(x, digits=2):
    return "–" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{x:.{digits}f}"


def results_markdown(res: dict) -> str:
    lines = ["Measured by `python -m sim_core report running` (man, human strength, every run from the standing pose).", ""]
    lines += ["| commanded m/s | outcome | mean speed, last 10 s | error | steps/s | step length m | stance/step % | stance hip yaw at its limit, % of stance (last 5 s) | stance foot's turn on the ground, deg, mean per stance (last 5 s) | stances whose hip rotation reaches its ±45° range, % (last 5 s) |",
              "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for v in speeds():
        r = res[f"speed {v}"]
        g = r["gait"]
        err = (g["mean_speed"] - v) / v * 100
        outcome = r["outcome"] if r["outcome"] == "success" else f"fell at {r['fall_time']:.1f} s"
        lines.append(f"| {v} | {outcome} | {fmt(g['mean_speed'])} | {err:+.1f} % | {fmt(g['step_frequency'])} | "
                     f"{fmt(g['step_length'])} | {fmt(g['stance_fraction'], 1)} | {fmt(r['hip_yaw_saturated'], 0)} | "
                     f"{fmt(r['foot_pivot_deg'], 0)} | {fmt(r['hip_rotation_at_range'], 0)} |")
    lines += ["", "(Fig. 12's 4.83 m/s is above the man's offered range: his gait beside Fig. 12 at his fastest "
              "offered speed is in *Fig. 12 for each runner*, `report running --fig12`.)", "",
              "| check | outcome | measured |", "| --- | --- | --- |"]
    s = res["start 3.5"]
    lines.append(f"| start from a stand into 3.5 m/s | {s['outcome']} | 90 % of 3.5 m/s reached at "
                 f"{fmt(s['time_to_90pct_speed'])} s (goal: within 5 s) |")
    for key, label in (("eight r20", "figure eight, loops of radius 20 m, at 3.5 m/s (100 s: both loops, both crossings)"),
                       ("circle 40", "circle of radius 40 m at 3.5 m/s"),
                       ("turn 90 r20", "90° left turn, radius 20 m, at 3.5 m/s (32 s)"),
                       ("turn 90 r30", "90° left turn, radius 30 m, at 3.5 m/s (32 s)"),
                       ("turn 90 v3", "90° left turn, radius 14.4 m, at 3.0 m/s"),
                       ("eight v3", "figure eight, loops of radius 14.4 m, at 3.0 m/s (50 s)")):
        r = res.get(key)
        if r is None:                  # not run by --quick
            continue
        lines.append(f"| {label} | {r['outcome'] if r['outcome'] == 'success' else 'fell at %.1f s' % r['fall_time']} | lateral deviation "
                     f"mean {fmt(r['path_deviation_mean'])} m, max {fmt(r['path_deviation_max'])} m (goal: mean < 0.3 m); "
                     f"stance hip yaw at its 100 N m limit in {fmt(r['hip_yaw_saturated'], 0)} % of stance, the stance foot turning "
                     f"{fmt(r['foot_pivot_deg'], 0)}° on the ground per stance, in the last 5 s |")
    for v in (3.0, speeds()[-1]):
        r = res.get(f"long {v}")
        if r:
            lines.append(f"| 100 s at {v} m/s | {r['outcome'] if r['outcome'] == 'success' else 'fell at %.1f s' % r['fall_time']} | "
                         f"mean speed over the last 10 s {fmt(r['gait']['mean_speed'])} m/s |")
    return "\n".join(lines)


def figures(res: dict) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    r = res[f"speed {speeds()[-1]}"]             # the fastest offered speed
    fig, ax = plt.subplots(figsize=(4.5, 4.5))
    ax.plot(np.degrees(r["hip"]), np.degrees(r["knee"]), lw=1.0)
    ax.set_xlabel("hip flexion (deg)")
    ax.set_ylabel("knee flexion (deg)")
    ax.set_title(f"Right hip vs knee, last 3 s at {r['params']['speed']} m/s\n(cf. Hodgins et al. 1995, Fig. 6)", fontsize=9)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(ROOT / "docs" / "running_phase.png", dpi=110)
    plt.close(fig)

    from .behaviour import path_for
    from .. import behaviour_class
    schema = behaviour_class("running").schema
    keys = [k for k in ("turn 90 r20", "eight r20", "eight v3", "circle 40") if k in res]
    fig, axes = plt.subplots(1, len(keys), figsize=(4.4 * len(keys), 4.2))
    for ax, key in zip(axes, keys):
        path = path_for(schema.validate(res[key]["params"]))
        xy = np.array(res[key]["xy"])
        ax.plot(path[:, 0], path[:, 1], "k--", lw=0.8, label="path")
        ax.plot(xy[:, 0], xy[:, 1], lw=1.0, label="COM")
        r = res[key]
        ax.set_title(f"{key}: {r['outcome']}" + ("" if r["outcome"] == "success" else f" at {r['fall_time']:.1f} s"), fontsize=9)
        ax.set_aspect("equal")
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(ROOT / "docs" / "running_paths.png", dpi=110)
    plt.close(fig)


FIG12_SECONDS = 30.0       # definition: a Fig. 12 run from a stand; its gait is the last 10 s (sim_core.gait)


def fig12_markdown(duration: float = FIG12_SECONDS) -> str:
    """Each character of Fig. 12 that runs (man, woman, child): a run at the speed of its table nearest
    the figure's, its gait beside the human row and the 1997 simulation's."""
    from ... import tuned
    from ...simulate import RunRequest, run
    from .behaviour import SpeedTable
    lines = ["| character | Fig. 12 speed (human / 1997 sim) m/s | run at m/s | mean speed | steps/s (human, error) | "
             "step length m (human, error) | stance/step % (human, error) | outcome |",
             "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for character, human in HUMAN_FIG12.items():
        if not tuned.exists("running", character):
            continue
        speed = min(SpeedTable.load(character).speeds, key=lambda v: abs(v - human["speed"]))
        trajectory = run(RunRequest("running", character, params={"speed": speed}, duration=duration))
        g = trajectory.meta["metrics"]["gait"]

        def cell(key, digits):
            value = g[key]
            return "-" if value is None else f"{value:.{digits}f} ({human[key]}, {(value - human[key]) / human[key] * 100:+.0f} %)"
        lines.append(f"| {character} | {human['speed']} / {SIMULATED_1997[character]['speed']} | {speed:g} | "
                     f"{fmt(g['mean_speed'])} | {cell('step_frequency', 2)} | {cell('step_length', 2)} | "
                     f"{cell('stance_fraction', 1)} | {trajectory.meta['outcome']} |")
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--fig12", action="store_true",
                    help="only the Fig. 12 table: man, woman and child at their tables' speeds nearest the figure's "
                         "(rewrites the <!-- fig12 --> block of docs/running.md)")
    ap.add_argument("--workers", type=int, default=1, help="simulation processes (the project's machine: 1 while others work)")
    args = ap.parse_args(argv)
    started = time.perf_counter()
    if args.fig12:
        block = fig12_markdown()
        text = DOC.read_text()
        if "<!-- fig12 -->" not in text:
            raise SystemExit(f"{DOC}: no <!-- fig12 --> ... <!-- /fig12 --> block to rewrite")
        DOC.write_text(re.sub(r"<!-- fig12 -->\n.*?<!-- /fig12 -->", lambda _: f"<!-- fig12 -->\n{block}\n<!-- /fig12 -->",
                              text, flags=re.S))
        print(block)
        print(f"total {time.perf_counter() - started:.0f} s")
        return 0
    with Pool(args.workers) as pool:
        res = {r["name"]: r for r in pool.map(simulate, jobs(args.quick), chunksize=1)}
    for r in res.values():
        g = r["gait"]
        print(f"{r['name']:12s} {r['outcome']:8s} fall={fmt(r['fall_time'])} v={fmt(g['mean_speed'])} "
              f"f={fmt(g['step_frequency'])} L={fmt(g['step_length'])} stance%={fmt(g['stance_fraction'], 1)} "
              f"dev={fmt(r['path_deviation_mean'])} t90={fmt(r['time_to_90pct_speed'])} wall={r['wall_s']:.0f}s")
    figures(res)
    block = results_markdown(res)
    text = DOC.read_text()
    new = re.sub(r"<!-- results -->\n.*?<!-- /results -->", lambda _: f"<!-- results -->\n{block}\n<!-- /results -->",
                 text, flags=re.S)
    DOC.write_text(new)
    print(block)
    print(f"total {time.perf_counter() - started:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
