"""Calibrate the vertical leap (the role of Wooten's Table 4.1) and the standing broad jump (the
role of Table 4.2).

Vertical leap: for each crouch height and thrust damping (less damping extends the legs faster
and leaps higher), and for each strength (human torque limits; unlimited, as the thesis ran):
  1. find the lift-off hip angle and crouch COM offset that leave the ground with no somersault
     (angular momentum about the COM ~ 0) and no drift (horizontal COM speed ~ 0), by Newton's
     method on thrust-only runs;
  2. run the whole leap with them and measure the COM rise, the thrust's peak ground force and
     whether it lands balanced;
  3. a fast (low-damping) thrust that does not land: a few landing foot deltas, then a small grid
     of lift-off hip angles and offsets, then - when none of that lands - a finer grid around
     flexed lift-off hips (WIDE_FALLBACK_*); of the balanced landings the one that travels least.
Writes the mapping commanded rise -> crouch height, thrust damping, COM offset, neutral lift-off
hip angle to sim_core/tuned/tables/leap_<character>.json ("vertical": human torque limits,
"vertical_unlimited": unlimited strength), which the leap behaviour interpolates.

Broad jump: the distance is not smooth in the leap's settings (the thrust starts on a tipping
condition), so each distance of BROAD_DISTANCES is planned by simulation as a jump to a point on
the ground straight ahead (sim_core/skills/jump_to_target/behaviour.py's planner: crouch, lean, thrust, arm
swing, lift-off hip angle and the landing's settings) with the air time of the report's targets
(GROUND_AIR_TIME: the request python -m sim_core calibrate jump_to_target makes for a forward target, whose stored plan
is reused when its best trial ended balanced; new plans are stored there too); the whole leap is
then run with the plan's settings and kept as a row (measured COM travel - within a few cm of the
landing point - and the leap's low-level parameters) if it ends balanced.
The behaviour runs the row within 10 % of the commanded distance (control.leap.broad_row). Rerun after any change to the model
or the controllers:

    python -m sim_core calibrate leap [--character man woman] [--processes 1] [--only vertical broad]
    python -m sim_core calibrate leap --fill [--only vertical broad]   # more rows where no row is near

A broad-jump distance no row is within 10 % of gets a row from --fill --only broad: blends of the
two rows around it (control.leap.blend_rows, the broad jump's own interpolation) run whole, the one
that lands balanced and covers most of the gap kept (fill_broad).
"""
from __future__ import annotations

import argparse
import itertools
import sys
from multiprocessing import Pool
from pathlib import Path

ROOT = Path.cwd()                   # docs are written under the folder it runs in (the checkout)

import numpy as np

from ...control.leap import AIRBORNE_HEIGHT, UNCOVERED_STEP, blend_rows, broad_gaps, broad_tolerance, uncovered_gaps
from ..jump_to_target.behaviour import GROUND_AIR_TIME, leap_params, stored_plan
from ...planning.jump import plan_jump, store_plan
from ... import tuned
from ...simulate import RunRequest, run

CROUCH_FRACTIONS = (0.9, 0.875, 0.85, 0.825, 0.8, 0.775, 0.75, 0.725, 0.7, 0.68, 0.66, 0.64, 0.62, 0.59)   # of the standing hip height
CROUCH_FRACTIONS_FAST = (0.75, 0.7, 0.68, 0.66, 0.64, 0.62, 0.59, 0.56, 0.53, 0.5)
CROUCH_FRACTIONS_HIGH = (0.61, 0.6, 0.595, 0.58, 0.57)    # more of the deep fast crouches with unlimited strength,
                                                        # whose leaps (0.8 - 1.1 m) land only here and there
# table -> (strength, [(thrust damping, crouch fractions)])
VERTICAL_TABLES = {
    "vertical": ("human", [(1.0, CROUCH_FRACTIONS), (0.3, CROUCH_FRACTIONS_FAST)]),
    "vertical_unlimited": ("unlimited", [(1.0, CROUCH_FRACTIONS), (0.3, CROUCH_FRACTIONS_FAST + CROUCH_FRACTIONS_HIGH),
                                         (0.15, (0.56, 0.53, 0.5))]),
}
THRUST_ONLY = 1.7            # s: crouch (0.2 + 0.8 + 0.15 s) and the thrust, up to just after lift-off
LEAP_DURATION = 4.5
NEWTON_STEPS = 5
ARM_SWING = 1.0              # rad: a forward swing that adds height without spinning the body
FALLBACK_HIPS = (-0.3, 0.0, 0.3, 0.6, 0.9)      # rad: lift-off hip angles tried when Newton leaves a fast thrust spinning
FALLBACK_OFFSETS = (-0.05, 0.0)      # m: crouch COM offsets tried with them
FALLBACK_FOOT_DELTAS = (0.04, 0.08, -0.04)   # m: landing foot servo deltas tried first
WIDE_FALLBACK_HIPS = (-0.6, -0.5, -0.4, -0.3, -0.2)     # rad: a finer ring of flexed lift-off hips, tried when
WIDE_FALLBACK_OFFSETS = (-0.05, -0.025, 0.0, 0.025, 0.05)   # nothing of the first ring landed (the woman's
WIDE_FALLBACK_FOOT_DELTAS = (0.0, 0.04)                 # deep unlimited crouches: few land, all in here)


def liftoff_state(character, crouch_height, hip, offset, damping=1.0, strength="human"):
    params = dict(low_level=1, crouch_height=crouch_height, crouch_pitch=0.0, com_offset=offset,
                  liftoff_hip=hip, arm_swing=ARM_SWING, thrust_damping=damping)
    traj = run(RunRequest("leap", character, params=params, duration=THRUST_ONLY, strength=strength))
    flying = traj.arrays["support_points"][:, :, 2].min(axis=1) > AIRBORNE_HEIGHT
    if not flying.any():
        return None
    k = int(np.argmax(flying))
    mass = traj.meta["total_mass"]
    # angular momentum as a pitch rate of a ~ 15 kg m^2 body, to weigh it like the speed in m/s
    return np.array([traj.arrays["angmom"][k, 1] / 15.0, traj.arrays["com_vel"][k, 0]]), mass


def neutral_settings(character, crouch_height, damping=1.0, strength="human"):
    """Newton steps on (lift-off hip angle, COM offset) towards no spin and no drift at lift-off;
    returns the best point seen and its residual."""
    # a fast thrust (low damping) needs the hips extended well past neutral at lift-off
    x = np.array([0.0, 0.0]) if damping >= 1.0 else np.array([0.6, 0.03])
    best = (np.inf, x.copy(), None)
    for _ in range(NEWTON_STEPS + 1):
        base = liftoff_state(character, crouch_height, *x, damping, strength)
        if base is None:
            break
        f = base[0]
        if np.linalg.norm(f) < best[0]:
            best = (float(np.linalg.norm(f)), x.copy(), f)
        if np.abs(f).max() < 0.03:
            break
        jac = np.zeros((2, 2))
        for i, eps in enumerate((0.05, 0.01)):
            probe = x.copy()
            probe[i] += eps
            shifted = liftoff_state(character, crouch_height, *probe, damping, strength)
            if shifted is None:
                return best[1], best[2]
            jac[:, i] = (shifted[0] - f) / eps
        step = np.linalg.lstsq(jac, -f, rcond=None)[0]
        x = np.clip(x + np.clip(step, [-0.3, -0.02], [0.3, 0.02]), [-0.6, -0.05], [0.95, 0.06])
    return best[1], best[2]


def trial(args):
    character, crouch_height, damping, strength = args
    (hip, offset), residual = neutral_settings(character, crouch_height, damping, strength)
    params = dict(low_level=1, crouch_height=crouch_height, crouch_pitch=0.0, com_offset=float(offset),
                  liftoff_hip=float(hip), arm_swing=ARM_SWING, thrust_damping=damping)
    traj = run(RunRequest("leap", character, params=params, duration=LEAP_DURATION, strength=strength))
    foot_delta = 0.0
    if traj.meta["outcome"] != "success" and damping < 1.0:
        # first a small correction of where the feet land (the landing's foot servo delta)
        for d in FALLBACK_FOOT_DELTAS:
            t = run(RunRequest("leap", character, params=dict(params, foot_delta=d), duration=LEAP_DURATION,
                               strength=strength))
            if t.meta["outcome"] == "success":
                traj, foot_delta = t, d
                break
    if traj.meta["outcome"] != "success" and damping < 1.0:
        # a fast thrust whose spin and drift Newton could not both cancel: of a few lift-off hip
        # angles and offsets around the usual ones (none landing: a finer grid of flexed ones, with
        # two foot deltas), keep the leap that lands balanced and travels least
        def landings(hips, offsets, deltas):
            found = []
            for h, o, d in itertools.product(hips, offsets, deltas):
                p = dict(params, liftoff_hip=h, com_offset=o, foot_delta=d)
                t = run(RunRequest("leap", character, params=p, duration=LEAP_DURATION, strength=strength))
                if t.meta["outcome"] == "success":
                    found.append((abs(t.meta["metrics"]["com_travel"]), h, o, d, t))
            return found

        landed = (landings(FALLBACK_HIPS, FALLBACK_OFFSETS, (0.0,))
                  or landings(WIDE_FALLBACK_HIPS, WIDE_FALLBACK_OFFSETS, WIDE_FALLBACK_FOOT_DELTAS))
        if landed:
            _, hip, offset, foot_delta, traj = min(landed, key=lambda x: x[0])
            residual = None
    m = traj.meta["metrics"]
    result = {"crouch_height": crouch_height, "thrust_damping": damping, "liftoff_hip": float(hip), "foot_delta": foot_delta,
              "com_offset": float(offset), "residual": None if residual is None else [float(r) for r in residual],
              "com_rise": m["com_rise"], "com_travel": m["com_travel"], "peak_thrust_grf_body_weights": m.get("peak_thrust_grf_body_weights"),
              "outcome": traj.meta["outcome"]}
    print(f"  {character} ({strength}): crouch {crouch_height:.3f} m, damping {damping:.2f}, hip {hip:+.2f} rad, "
          f"offset {offset:+.3f} m (residual {result['residual']}) -> COM rise {m['com_rise']:.3f} m, "
          f"{traj.meta['outcome']}", flush=True)
    return result


BROAD_DISTANCES = {"man": (0.3, 0.4, 0.5, 0.75, 1.0, 1.3, 1.6, 1.9, 2.1),      # m: TARGETS.md's ranges
                   "woman": (0.3, 0.5, 0.7, 0.75, 1.0, 1.3, 1.6)}
BROAD_WINDUP = 1.25          # s: first move to lift-off
BROAD_TRIALS = 200           # simulated jumps the planner may run per distance
BROAD_AIM_TOLERANCE = 0.05   # share of the distance the COM travel may miss by before the feet are re-aimed


def broad_leap(character: str, aim: float) -> tuple[dict, dict, object]:
    """The planned jump to ``aim`` m straight ahead (GROUND_AIR_TIME; python -m sim_core calibrate jump_to_target makes the
    same request for its forward targets, and its best trial serves if it ended balanced, whether or
    not it met the air time - a broad jump asks only for the distance), run as a leap."""
    target = (aim, 0.0, 0.0)
    request = {"target_x": aim, "target_y": 0.0, "target_z": 0.0, "air_time": GROUND_AIR_TIME,
               "windup_time": BROAD_WINDUP, "strength": "human"}
    plan = stored_plan(character, request)
    if not (plan and plan["measured"]["outcome"] == "success"):
        plan = plan_jump(character, target, GROUND_AIR_TIME, BROAD_WINDUP, budget=BROAD_TRIALS)
        store_plan(character, request, plan, "python -m sim_core calibrate leap")
    params = leap_params(plan["settings"], target, BROAD_WINDUP)
    traj = run(RunRequest("leap", character, params=params, duration=BROAD_WINDUP + GROUND_AIR_TIME + 2.5))
    m = traj.meta["metrics"]
    print(f"  {character} broad, aiming the feet at {aim:.3f} m: plan {'found' if plan['found'] else 'not found'} "
          f"in {plan['trials']} trials, lands at {plan['measured']['landing'][0]:.3f} m; leap -> COM travel "
          f"{m['com_travel']:.3f} m, {traj.meta['outcome']}", flush=True)
    return plan, params, traj


def broad_row(args) -> dict:
    """Plan one broad jump and run it as a leap: the row for the COM travel it measured. The COM ends
    a few cm past the feet's landing point (the stand-up); when that takes it more than
    BROAD_AIM_TOLERANCE of the distance away, the feet are aimed short by that much and it is
    planned again (the nearer of the two is kept)."""
    character, distance = args
    plan, params, traj = broad_leap(character, distance)
    m = traj.meta["metrics"]
    overshoot = m["com_travel"] - plan["measured"]["landing"][0]
    if traj.meta["outcome"] == "success" and abs(m["com_travel"] - distance) > BROAD_AIM_TOLERANCE * distance:
        again = broad_leap(character, round(distance - overshoot, 3))
        if again[2].meta["outcome"] == "success" and \
                abs(again[2].meta["metrics"]["com_travel"] - distance) < abs(m["com_travel"] - distance):
            plan, params, traj = again
            m = traj.meta["metrics"]
    kept = traj.meta["outcome"] == "success"      # a row for the distance it travelled
    return {"distance": distance, "air_time": GROUND_AIR_TIME, "com_travel": m["com_travel"],
            "outcome": traj.meta["outcome"], "kept": kept, "settings": plan["settings"], "params": params,
            "peak_thrust_grf_body_weights": m.get("peak_thrust_grf_body_weights")}


def calibrate_broad(character: str, pool) -> dict:
    """Broad jump rows in order of COM travel (see the module's docstring)."""
    results = pool.map(broad_row, [(character, d) for d in BROAD_DISTANCES[character]])
    rows = sorted((r for r in results if r["kept"]), key=lambda r: r["com_travel"])
    return {"com_travel": [r["com_travel"] for r in rows], "params": [r["params"] for r in rows],
            "settings": [r["settings"] for r in rows], "distance": [r["distance"] for r in rows],
            "air_time": [r["air_time"] for r in rows],
            "peak_thrust_grf_body_weights": [r["peak_thrust_grf_body_weights"] for r in rows],
            "trials": [{k: r[k] for k in ("distance", "air_time", "com_travel", "outcome", "kept")} for r in results]}


BROAD_FILL_STEPS = 15        # blends tried between the two rows around a gap, evenly spaced (w = 1/16 .. 15/16)
BROAD_FILL_ROUNDS = 3        # rounds of gaps filled (a new row can leave a narrower gap beside it)
BROAD_COLUMNS = ("com_travel", "params", "settings", "distance", "air_time", "peak_thrust_grf_body_weights")


def blend_trial(args) -> dict:
    """The whole leap run with row ``a`` blended the share ``w`` of the way to row ``b``
    (control.leap.blend_rows, the broad jump's interpolation): a candidate row."""
    character, a, b, w = args
    from .behaviour import Leap
    params = blend_rows(a["params"], b["params"], w)
    traj = run(RunRequest("leap", character, params=params, duration=Leap.default_duration))
    m = traj.meta["metrics"]
    print(f"  {character} broad blend {a['com_travel']:.3f} -> {b['com_travel']:.3f} m at w = {w:.3f}: COM travel "
          f"{m['com_travel']:.3f} m, {traj.meta['outcome']}", flush=True)
    return {"distance": a["com_travel"] + w * (b["com_travel"] - a["com_travel"]), "air_time": GROUND_AIR_TIME,
            "com_travel": m["com_travel"], "outcome": traj.meta["outcome"], "kept": traj.meta["outcome"] == "success",
            "params": params, "settings": blend_rows(a["settings"], b["settings"], w),
            "peak_thrust_grf_body_weights": m.get("peak_thrust_grf_body_weights"),
            "blend": [a["com_travel"], b["com_travel"], w]}


def in_travel_order(broad: dict) -> dict:
    """The broad table with its row columns (BROAD_COLUMNS) in order of COM travel."""
    order = sorted(range(len(broad["com_travel"])), key=lambda i: broad["com_travel"][i])
    return {**broad, **{k: [broad[k][i] for i in order] for k in BROAD_COLUMNS}}


def row_travel(args) -> float:
    """The COM travel of a broad row's leap parameters, run as the leap runs (Leap.default_duration)."""
    character, params = args
    from .behaviour import Leap
    return run(RunRequest("leap", character, params=params, duration=Leap.default_duration)).meta["metrics"]["com_travel"]


def gap_cover(travel: float, gap: tuple[float, float]) -> float:
    """How much of the gap's commanded distances a row travelling ``travel`` m is within the
    tolerance of (broad_tolerance: from travel / 1.1 to travel / 0.9); each distance of the gap
    (UNCOVERED_STEP apart) stands for half a step either side, so a one-distance gap has a length."""
    low, high = travel / (1 + broad_tolerance(1.0)), travel / (1 - broad_tolerance(1.0))
    return min(high, gap[1] + 0.5 * UNCOVERED_STEP) - max(low, gap[0] - 0.5 * UNCOVERED_STEP)


def fill_broad(character: str, broad: dict, pool) -> dict:
    """Rows added to a broad-jump table in its gaps (control.leap.broad_gaps: distances no row is
    within 10 % of), BROAD_FILL_ROUNDS times: BROAD_FILL_STEPS blends of the two rows around a gap
    are run whole, and the one that lands balanced and covers most of the gap becomes a row; where
    none does, the gap's middle is planned as a jump straight ahead like the first rows (broad_row).
    The rows already there keep their settings; their travel is measured again first as the leap
    runs them (row_travel), so that a row serves exactly the distances within 10 % of its travel."""
    broad = {k: list(v) for k, v in broad.items()}
    # the rows' travel as the leap runs them (Leap.default_duration): a planned row was measured in a
    # shorter run, and the COM creeps a few mm further while it stands up
    broad["com_travel"] = pool.map(row_travel, [(character, params) for params in broad["params"]])
    broad = in_travel_order(broad)
    for _ in range(BROAD_FILL_ROUNDS):
        gaps = broad_gaps(broad["com_travel"])
        print(f"  {character} broad: gaps {', '.join(f'{a:.3f}-{b:.3f}' for a, b in gaps) or 'none'} m", flush=True)
        if not gaps:
            break
        for gap in gaps:
            rows = [{k: broad[k][i] for k in ("com_travel", "params", "settings")} for i in range(len(broad["com_travel"]))]
            below = max((r for r in rows if r["com_travel"] < gap[0]), key=lambda r: r["com_travel"])
            above = min((r for r in rows if r["com_travel"] > gap[1]), key=lambda r: r["com_travel"])
            shares = np.linspace(0.0, 1.0, BROAD_FILL_STEPS + 2)[1:-1]
            results = pool.map(blend_trial, [(character, below, above, float(w)) for w in shares])
            covering = [r for r in results if r["kept"] and gap_cover(r["com_travel"], gap) > 0.0]
            if not covering:
                planned = broad_row((character, round(float(np.sqrt(gap[0] * gap[1])), 3)))
                results.append(planned)
                covering = [planned] if planned["kept"] and gap_cover(planned["com_travel"], gap) > 0.0 else []
            broad["trials"] += [{k: r[k] for k in ("distance", "air_time", "com_travel", "outcome", "kept")
                                 if k in r} | ({"blend": r["blend"]} if "blend" in r else {}) for r in results]
            if covering:
                best = max(covering, key=lambda r: gap_cover(r["com_travel"], gap))
                for k in BROAD_COLUMNS:
                    broad[k].append(best[k])
        broad = in_travel_order(broad)
    return in_travel_order(broad)


def vertical_table(results: list[dict]) -> dict:
    """The leaps that landed balanced, in order of COM rise, each more than 1 cm above the last (a
    monotonic mapping the behaviour can interpolate): the damped thrust's leaps first, then the
    faster thrust's above the highest of those, so that neighbouring rows have like settings."""
    rows, best = [], -1.0
    for damping in sorted({r["thrust_damping"] for r in results}, reverse=True):
        family = sorted((r for r in results if r["outcome"] == "success" and r["thrust_damping"] == damping),
                        key=lambda r: r["com_rise"])
        for r in family:
            if r["com_rise"] > best + 0.01:
                rows.append(r)
                best = r["com_rise"]
    table = {k: [r.get(k) for r in rows] for k in ("com_rise", "crouch_height", "thrust_damping", "com_offset",
                                                     "liftoff_hip", "peak_thrust_grf_body_weights", "com_travel",
                                                     "foot_delta")}
    table["foot_delta"] = [d or 0.0 for d in table["foot_delta"]]
    table["crouch_pitch"] = [0.0 for _ in rows]
    table["arm_swing"] = [ARM_SWING for _ in rows]
    return table


FILL_ROUNDS = 2               # rounds of crouches tried in the gaps (each between the last round's trials)


def gap_crouches(results: list[dict], gaps) -> list[tuple[float, float]]:
    """(crouch height, thrust damping) to try for each gap: in each damping's family of trials,
    ordered by crouch height, the two neighbouring crouches whose rises straddle the gap's middle,
    at a third and two thirds of the way between them (the rise is not monotonic in the crouch, so
    every straddling pair)."""
    jobs = []
    for first, last in gaps:
        middle = 0.5 * (first + last)
        for damping in sorted({r["thrust_damping"] for r in results}, reverse=True):
            family = sorted((r for r in results if r["thrust_damping"] == damping), key=lambda r: -r["crouch_height"])
            tried = {r["crouch_height"] for r in family}
            for a, b in zip(family, family[1:]):
                if min(a["com_rise"], b["com_rise"]) < middle < max(a["com_rise"], b["com_rise"]):
                    for share in (1 / 3, 2 / 3):
                        crouch = round(a["crouch_height"] + share * (b["crouch_height"] - a["crouch_height"]), 3)
                        if crouch not in tried and (crouch, damping) not in jobs:
                            jobs.append((crouch, damping))
    return jobs


def fill_gaps(character: str, key: str, strength: str, results: list[dict], pool) -> list[dict]:
    """More trials in the gaps of a vertical table (uncovered_gaps), FILL_ROUNDS times; returns all
    the trials, old and new."""
    results = list(results)
    for _ in range(FILL_ROUNDS):
        gaps = uncovered_gaps(vertical_table(results)["com_rise"])
        jobs = gap_crouches(results, gaps)
        print(f"  {character} {key}: gaps {', '.join(f'{a:.3f}-{b:.3f}' for a, b in gaps) or 'none'} m; "
              f"{len(jobs)} crouches to try", flush=True)
        if not jobs:
            break
        results += pool.map(trial, [(character, crouch, damping, strength) for crouch, damping in jobs])
    return results


def calibrate(character: str, processes: int, only: list[str], previous: dict, fill: bool = False) -> dict:
    from ...character.spec import load_character
    from ...control.balance import standing_hip_height
    spec = load_character(character)
    stand = standing_hip_height(spec)
    mapping = dict(previous)
    mapping.update({"character": spec.name, "script": "python -m sim_core calibrate leap"})
    trials = dict(mapping.get("trials_by_table", {}))
    with Pool(processes) as pool:
        for key, (strength, grid) in VERTICAL_TABLES.items():
            if key not in only:
                continue
            if fill:
                results = fill_gaps(character, key, strength, trials.get(key, []), pool)
            else:
                jobs = [(character, round(f * stand, 3), damping, strength) for damping, fractions in grid
                        for f in fractions]
                results = pool.map(trial, jobs)
            trials[key] = results
            mapping[key] = vertical_table(results)
        if "broad" in only:
            mapping["broad"] = fill_broad(character, mapping["broad"], pool) if fill else calibrate_broad(character, pool)
            mapping.pop("broad_calibrated", None)
    mapping["trials_by_table"] = trials
    mapping.pop("trials", None)
    return mapping


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--character", nargs="+", default=["man", "woman"])
    parser.add_argument("--processes", type=int, default=1)
    parser.add_argument("--only", nargs="+", default=[*VERTICAL_TABLES, "broad"],
                        help="tables to recalibrate (the others are kept): " + " ".join([*VERTICAL_TABLES, "broad"]))
    parser.add_argument("--fill", action="store_true",
                        help="keep the tables' rows and add rows in their gaps (commanded heights or distances no "
                             "row is within the tolerance of), instead of calibrating them afresh: crouches for the "
                             "vertical tables, blends of the neighbouring rows (else a plan) for the broad jump")
    args = parser.parse_args(argv)
    from ...character.spec import character_name
    for character in args.character:
        name = character_name(character)             # a spec file's tables are stored under its name
        previous = tuned.load("leap", name) or {}
        only = args.only
        mapping = calibrate(character, args.processes, only, previous, args.fill)
        # write only the recalibrated tables over the file as it is now (another run may have
        # recalibrated the others meanwhile)
        current = tuned.load("leap", name) or {}
        current.update({k: v for k, v in mapping.items() if k in only or k in ("character", "script")})
        current.setdefault("trials_by_table", {}).update(
            {k: v for k, v in mapping.get("trials_by_table", {}).items() if k in only})
        current.pop("broad_calibrated", None)
        mapping = current
        path = tuned.save("leap", name, mapping,
                          strengths=["human"] + (["unlimited"] if "vertical_unlimited" in mapping else []))
        for key in VERTICAL_TABLES:
            rises = mapping.get(key, {}).get("com_rise", [])
            print(f"wrote {path.relative_to(ROOT)} {key}: COM rise {min(rises, default=0):.2f} .. "
                  f"{max(rises, default=0):.2f} m from {len(rises)} balanced landings")
        b = mapping.get("broad", {"com_travel": []})
        print(f"  broad {min(b['com_travel'], default=0):.2f} .. {max(b['com_travel'], default=0):.2f} m "
              f"from {len(b['com_travel'])}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
