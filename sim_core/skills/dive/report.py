"""Tumbling and diving report: moments of inertia of the positions beside Wooten's Fig. 5.2, the
four 10 m platform dives of §8.2.1, the standing somersaults of §8.4-8.5 and the back handspring of
§8.3 measured off the simulation, and a plot of the somersault and twist rates in flight (like Figs. 5.3 and 5.7).
Writes docs/tumbling.md's results block and docs/tumbling_rates.png.

    python -m sim_core report dive
"""
from __future__ import annotations

import re
import sys
from pathlib import Path

import mujoco
import numpy as np

ROOT = Path.cwd()                   # docs are written under the folder it runs in (the checkout)

from ...character.model import compile_model
from ...character.spec import load_character
from .behaviour import CALIBRATED_DIVES, dive_name
from ..somersault.behaviour import DIRECTIONS
from ...control.tumble import CONSTANTS as TUMBLE, inertia_about_com, position_inertia
from ...errors import ParameterError
from ...simulate import RunRequest, run

DOC = ROOT / "docs" / "tumbling.md"
PLOT = ROOT / "docs" / "tumbling_rates.png"
DIVES = [(character, CALIBRATED_DIVES[character][k]) for pair in ((0, 1), (2, 3))   # the seed's four, then
         for character in ("man", "woman") for k in pair]                             # beyond it: facing the water


def inertia_series(trajectory) -> np.ndarray:
    """Whole-body moment of inertia about the somersault axis at every frame."""
    model = mujoco.MjModel.from_xml_string(trajectory.meta["model_xml"])
    data = mujoco.MjData(model)
    out = []
    for q in trajectory.arrays["qpos"]:
        data.qpos[:] = q
        mujoco.mj_kinematics(model, data)
        mujoco.mj_comPos(model, data)
        out.append(inertia_about_com(model, data)[1, 1])
    return np.array(out)


def inertia_table() -> list[str]:
    lines = ["| character | position | this model, kg m² | Wooten Fig. 5.2 | difference |", "| --- | --- | --- | --- | --- |"]
    for character, seeds in TUMBLE.seed_inertia.items():
        spec = load_character(character)
        model, _ = compile_model(spec)
        for position, seed in seeds.items():
            value = position_inertia(model, spec, position)
            lines.append(f"| {character} | {position} | {value:.2f} | {seed:.2f} | {100 * (value / seed - 1):+.1f} % |")
    return lines


def dive_rows() -> tuple[list[str], dict]:
    lines = ["| character | dive | outcome | somersaults | twists | entry angle from vertical | take-off angular momentum kg m²/s | flight s | momentum drift in flight | tightest I in flight kg m² |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    runs = {}
    for character, params in DIVES:
        name = dive_name({**params, "platform_height": 10.0})
        try:
            traj = run(RunRequest("dive", character, params=params, duration=4.5))
        except ParameterError as error:
            lines.append(f"| {character} | {name} | refused: {error} | | | | | | | |")
            continue
        m = traj.meta["metrics"]
        runs[(character, name)] = traj
        tight = float(inertia_series(traj)[int(np.searchsorted(traj.arrays["time"], m["takeoff_time"])):].min())
        lines.append(f"| {character} | {name} | {traj.meta['outcome']} | {m['somersaults']:.2f} | {m['twists']:.2f} | "
                     f"{m['entry_angle_from_vertical_deg']:.0f}° | {m['takeoff_angular_momentum']:.1f} | "
                     f"{m['flight_time']:.2f} | {100 * m['angular_momentum_drift']:.2f} % | {tight:.2f} |")
        print(lines[-1], flush=True)
    return lines, runs


SOMERSAULTS = [("man", "backward", "human"), ("man", "backward", "unlimited"),    # Wooten §8.4: the man's back tuck
               ("man", "forward", "human"),
               ("woman", "forward", "human")]                                     # §8.5: the woman's forward tuck


def somersault_rows() -> list[str]:
    lines = ["| character | somersault | strength | outcome | rotation, standing to standing | in flight | "
             "flight s | COM rise m | COM travel m | take-off angular momentum kg m²/s | momentum drift in flight | "
             "peak thrust GRF (body weights) |", "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for character, direction, strength in SOMERSAULTS:
        params = {"direction": DIRECTIONS.index(direction)}
        try:
            traj = run(RunRequest("somersault", character, params=params, strength=strength))
        except ParameterError as error:
            lines.append(f"| {character} | {direction} tuck | {strength} | refused: {error} | | | | | | | | |")
            continue
        m = traj.meta["metrics"]
        lines.append(f"| {character} | {direction} tuck | {strength} | {traj.meta['outcome']} | {m['rotation']:.2f} rad "
                     f"({m['somersaults']:.3f} turns) | {m['flight_rotation']:.2f} rad | {m['first_flight_time']:.2f} | "
                     f"{m['com_rise']:.2f} | {m['com_travel']:+.2f} | {m['liftoff_angular_momentum']:.1f} | "
                     f"{100 * m['angular_momentum_drift']:.2f} % | {m['peak_thrust_grf_body_weights']:.1f} |")
        print(lines[-1], flush=True)
    return lines


HANDSPRINGS = [("man", "unlimited"), ("man", "human")]          # §8.3: the man's


def handspring_rows() -> list[str]:
    lines = ["| character | strength | outcome | rotation, standing to standing | turned when the hands land | "
             "first flight s | hands on the ground s | second flight s | take-off velocity m/s (back, up) | "
             "take-off angular momentum kg m²/s | momentum drift in the flights | COM rise m | COM travel m | "
             "peak vertical GRF, thrust / hands / landing (body weights) |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for character, strength in HANDSPRINGS:
        try:
            traj = run(RunRequest("handspring", character, strength=strength))
        except ParameterError as error:
            lines.append(f"| {character} | {strength} | refused: {error} | | | | | | | | | | | |")
            continue
        m = traj.meta["metrics"]
        vx, _, vz = m["liftoff_velocity"]
        lines.append(f"| {character} | {strength} | {traj.meta['outcome']} | {m['rotation']:.2f} rad "
                     f"({m['somersaults']:.3f} turns) | {m['rotation_at_hands']:.2f} rad | {m['first_flight_time']:.2f} | "
                     f"{m['hand_contact_time']:.3f} | {m['second_flight_time']:.2f} | {-vx:.2f}, {vz:.2f} | "
                     f"{m['liftoff_angular_momentum']:.1f} | "
                     f"{' / '.join(f'{100 * d:.2f} %' for d in m['flight_drifts'])} | {m['com_rise']:.2f} | "
                     f"{m['com_travel']:+.2f} | {m['peak_thrust_grf_body_weights']:.1f} / "
                     f"{m['peak_hands_grf_body_weights']:.1f} / {m['peak_landing_grf_body_weights']:.1f} |")
        print(lines[-1], flush=True)
    return lines


def plot(runs: dict) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    for ax, (key, traj) in zip(axes, list(runs.items())[:2]):
        a = traj.arrays
        t = a["time"]
        inertia = inertia_series(traj)
        somersault_rate = np.abs(a["angmom"][:, 1]) / inertia
        ax.plot(t, somersault_rate, label="somersault rate |H_y| / I_y (rad/s)")
        ax.plot(t, np.abs(a["qvel"][:, 5]), label="twist rate, about the long axis (rad/s)")
        ax.plot(t, inertia, label="I_y (kg m²)", alpha=0.6)
        marks = [(traj.meta["metrics"]["takeoff_time"], "take-off")]
        marks += [(time, event) for time, event in traj.meta["phase_events"]
                  if event in ("entry", "twist_throw", "twist_stop") and (time, event) not in marks]
        top = ax.get_ylim()[1]
        for k, (time, event) in enumerate(marks):
            ax.axvline(time, color="grey", lw=0.6)
            ax.text(time + 0.01, top * (0.98 - 0.12 * (k % 2)), event.replace("_", " "), rotation=90, fontsize=7, va="top")
        ax.set_title(f"{key[0]}: {key[1]}")
        ax.set_xlabel("time (s)")
        ax.set_xlim(traj.meta["metrics"]["takeoff_time"] - 0.3, t[-1])
        ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    fig.savefig(PLOT, dpi=110)


def main(argv=None) -> int:
    lines = ["Measured by `python -m sim_core report dive`.", "",
             "Moments of inertia about the somersault axis (positions as commanded, body upright):", ""]
    lines += inertia_table()
    dives, runs = dive_rows()
    lines += ["", "10 m platform dives (rotation counted from the standing start to the hands reaching the water); "
              "the first four are Wooten's (§8.2.1), the rest face the water (forward, reverse groups):", ""]
    lines += dives
    lines += ["", "Standing tuck somersaults (§8.4-8.5; calibrated by `python -m sim_core calibrate somersault`; a skill "
              "succeeds when it turns once, 2π ± 0.35 rad, and ends balanced on the feet):", ""]
    lines += somersault_rows()
    lines += ["", "Back handspring (§8.3; calibrated by `python -m sim_core calibrate handspring`; it succeeds when it turns once, "
              "2π ± 0.35 rad, with the hands on the ground between two flights, and ends balanced on the feet):", ""]
    lines += handspring_rows()
    plot(runs)
    text = DOC.read_text()
    block = "<!-- results -->\n" + "\n".join(lines) + "\n<!-- /results -->"
    DOC.write_text(re.sub(r"<!-- results -->.*<!-- /results -->", lambda _: block, text, flags=re.S))
    print(f"wrote {DOC} and {PLOT}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
