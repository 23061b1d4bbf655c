"""Tumbling and diving report: moments of inertia of the positions beside Wooten's Fig. 5.2, the
four 10 m platform dives of §8.2.1, the standing somersaults of §8.4-8.5 and the back handspring of
§8.3 measured off the simulation, and a plot of the somersault and twist rates in flight (like Figs. 5.3 and 5.7).
Writes docs/tumbling.md's results block and docs/tumbling_rates.png.

    python -m sim_core report dive
    python -m sim_core report dive --repertoire      # the FINA repertoire, both characters (REPERTOIRE_HELP)
"""
from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

import mujoco
import numpy as np

ROOT = Path.cwd()                   # docs are written under the folder it runs in (the checkout)

from ...character.model import compile_model
from ...character.spec import load_character
from .behaviour import (CALIBRATED_DIVES, CALIBRATION_PLATFORM, FORWARD_ROTATING, GROUPS, ROTATION_TOLERANCE, Dive, calibrated_row,
                        dive_name)
from .calibrate import NoLimits
from .fina import REPERTOIRE
from ... import tuned
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
               ("woman", "forward", "human"),                                     # §8.5: the woman's forward tuck
               ("woman", "backward", "human")]                                    # issue 29: both ways


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


# ------------------------------------------------------------------ the FINA repertoire
REPERTOIRE_HELP = """The FINA repertoire from 10 m, for the man and the woman, with human strength: which dives are
reached (rotations within a quarter turn of the dive's, a vertical entry, the platform not
touched) and, for each, the take-off angular momentum it needs against the one the calibration's
take-offs reached. Writes the table into docs/skills/dives.md between ``<!-- repertoire -->``
markers and prints it.

    python -m sim_core report dive --repertoire
    python -m sim_core report dive --repertoire --character woman --dive 107C --no-write

"Needed" is the physics estimate the feasibility check uses: 2 pi x somersaults over the
rotation per unit of angular momentum of a 10 m flight (its air time from the take-off's rise
and the drop to the hands reaching the water), spent in the position's moment of inertia but for
the take-off and opening, in the line's for those. "Reached" is the largest take-off angular
momentum the dive's own calibration search measured without touching the platform. A dive the
calibration did not reach is refused before simulating; the table then runs its best calibrated
take-off as set (low_level) to show what it makes.
"""
REPERTOIRE_DOC = ROOT / "docs" / "skills" / "dives.md"


def measure(character: str, number: str) -> dict:
    """One repertoire dive: run as an animator would (``--set dive=NUMBER``); refused, its best
    calibrated take-off run as set. The measured figures and the verdict."""
    params = Dive.schema.validate({"dive": number, "platform_height": CALIBRATION_PLATFORM})
    table = tuned.load("dives", character)
    row = calibrated_row(table, params) if table else None
    out = {"character": character, "number": number, "name": dive_name(params), "params": params,
           "needed": Dive.momentum_needed_by(character, params),
           "reached": row["largest_momentum_clear"] if row else None, "refused": None}
    try:
        trajectory = run(RunRequest("dive", character, params={"dive": number}, duration=4.5))  # enters within it
    except ParameterError as error:
        out["refused"] = str(error)
        if row is None:
            return out
        with NoLimits():            # as the calibration ran it: the table's limits are what it measured
            trajectory = run(RunRequest("dive", character, params=dict(dive=number, low_level=1, **row["settings"]),
                                        duration=4.5))
    out.update(outcome=trajectory.meta["outcome"], metrics=trajectory.meta["metrics"])
    return out


def table_lines(results: list[dict]) -> list[str]:
    lines = ["| character | dive | | reached | outcome | rotations within ¼ turn | somersaults (wanted) | twists (wanted) | "
             "entry from vertical | take-off H kg m²/s | needed H kg m²/s | reached H kg m²/s | flight s | why not |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in results:
        p, m = r["params"], r.get("metrics") or {}
        outcome = r.get("outcome", "not run") + (" (refused; its best calibrated take-off run as set)" if r["refused"] else "")
        cells = [r["character"], r["number"], r["name"], "yes" if reached(r) else "**no**", outcome]
        if "somersaults" in m:
            cells += ["yes" if rotations_right(p, m) else "no", f"{m['somersaults']:.2f} ({p['somersaults']:g})", f"{m['twists']:.2f} ({p['twists']:g})",
                      f"{m['entry_angle_from_vertical_deg']:.0f}°", f"{abs(m['takeoff_angular_momentum']):.1f}"]
        else:
            cells += ["—"] * 5
        cells += [f"{r['needed']:.1f}", "—" if r["reached"] is None else f"{r['reached']:.1f}",
                  f"{m['flight_time']:.2f}" if "flight_time" in m else "—", why_not(r)]
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def why_not(result: dict) -> str:
    """Why a dive is not reached: the angular momentum (the largest any take-off of its group
    reached without touching the platform is below the one it needs), or the control (that much
    was reached, but no searched take-off gave the rotations and a vertical entry together)."""
    if reached(result):
        return ""
    m, p = result.get("metrics") or {}, result["params"]
    group = GROUPS[int(round(p["group"]))]
    best = (tuned.load("dives", result["character"]) or tuned.load("dives", "any"))["limits"]["angular_momentum"][group]
    if best < result["needed"]:
        return f"momentum: the {group} take-offs reached {best:.1f} of {result['needed']:.1f}"
    if m and rotations_right(p, m):
        return f"entry: {m['entry_angle_from_vertical_deg']:.0f}° with the rotations right"
    if m and abs(m["somersaults"] - p["somersaults"]) <= ROTATION_TOLERANCE:
        return f"twist: {m['twists']:.2f} of {p['twists']:g} with the somersaults right"
    return (f"control: the {group} take-offs reached {best:.1f} kg m²/s, no searched one gave "
            f"{p['somersaults']:g} somersaults")


def rotations_right(params: dict, metrics: dict) -> bool:
    """The somersaults and twists within a quarter turn of the dive's, the right way round (the
    entry aside)."""
    forward = GROUPS[int(round(params["group"]))] in FORWARD_ROTATING
    return (abs(metrics["somersaults"] - params["somersaults"]) <= ROTATION_TOLERANCE
            and abs(metrics["twists"] - params["twists"]) <= ROTATION_TOLERANCE
            and metrics["somersault_direction"] == ("forward" if forward else "backward"))


def reached(result: dict) -> bool:
    """Run as an animator would (not refused) and a success."""
    return result["refused"] is None and result.get("outcome") == "success"


def summary(results: list[dict]) -> list[str]:
    out = []
    for character in dict.fromkeys(r["character"] for r in results):
        mine = [r for r in results if r["character"] == character]
        done = [r["number"] for r in mine if reached(r)]
        turned = [r["number"] for r in mine if r["number"] not in done and r.get("metrics")
                  and rotations_right(r["params"], r["metrics"])]
        short = [r["number"] for r in mine if r["number"] not in done + turned]
        out.append(f"- {character}: {len(done)} of {len(mine)} reached ({', '.join(done) or 'none'}); "
                   f"the rotations within a quarter turn but the entry not vertical: {', '.join(turned) or 'none'}; "
                   f"the rotations not reached: {', '.join(short) or 'none'}")
    return out


def repertoire_main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=REPERTOIRE_HELP, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repertoire", action="store_true", help="(the report dive option that runs this)")
    parser.add_argument("--character", choices=("man", "woman"), action="append")
    parser.add_argument("--dive", action="append", help="only this FINA number (repeatable)")
    parser.add_argument("--write", action=argparse.BooleanOptionalAction, default=True,
                        help="write the table into docs/skills/dives.md (only for the whole repertoire)")
    args = parser.parse_args(argv)
    numbers = [Dive.schema.by_name["dive"].option(Dive.schema.validate({"dive": n})["dive"]) for n in args.dive or []]
    results = []
    for character in args.character or ("man", "woman"):
        for number in numbers or REPERTOIRE:
            results.append(measure(character, number))
            print(table_lines([results[-1]])[-1], flush=True)
    lines = (["Measured by `python -m sim_core report dive --repertoire` (10 m, human strength; reached = "
              f"somersaults and twists within {ROTATION_TOLERANCE:g} turn of the dive's, entry within 20° of "
              "vertical, the platform not touched):", ""] + table_lines(results) + [""] + summary(results))
    print("\n".join(summary(results)))
    if args.write and not args.dive and not args.character:
        text = REPERTOIRE_DOC.read_text()
        block = "<!-- repertoire -->\n" + "\n".join(lines) + "\n<!-- /repertoire -->"
        REPERTOIRE_DOC.write_text(re.sub(r"<!-- repertoire -->.*<!-- /repertoire -->", lambda _: block, text, flags=re.S))
        print(f"wrote {REPERTOIRE_DOC}")
    return 0


def main(argv=None) -> int:
    if argv and "--repertoire" in argv:
        return repertoire_main(argv)
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
