"""Measure the leap's commanded take-off (sim_core/control/commanded_thrust.py) with no search: each
jump runs one stored plan's crouch, thrust and landing settings (``--base``: the plan for that
forward target in 0.45 s; ``--set`` overrides) with ``commanded_takeoff`` on and the request's
target and air time as the commanded flight, once. Prints every jump and the summary figures of
docs/jump_to_target.md ("A commanded take-off"):

    tools/commanded_jumps.py --character man --base 1.3 --set com_offset=0.03 --sweep 0.5,1.9,0.05
    tools/commanded_jumps.py --character man --base 1.3 --set com_offset=0.03 --random 30 --seed 29
    tools/commanded_jumps.py ... --random 10 --seed 30 --fixed-air-time 0.45 --aim 5   # aim moved by a secant
    tools/commanded_jumps.py ... --landings 0.8,1.0,1.3,1.6,1.9      # landing variants per target
    tools/commanded_jumps.py --character woman --table --long --random 20 --seed 7 --air-times 0.52,0.7 --aim 9 --plan-landing 9

``--random`` plans each target with the skill's planner (sim_core/planning/commanded.py), these
settings and crouch pairs standing in for the character's jump_commanded table and ``--aim`` /
``--plan-landing`` for its bounds. ``--const name=value`` overrides a leap constant (``commanded_*``:
leap_any.json's, or the character's own in its leap table) for the run."""
from __future__ import annotations

import argparse
import math
import sys
import time
from types import SimpleNamespace

import numpy as np

from sim_core.analysis import feet_above_surface
from sim_core.ballistics import flat_air_time
from sim_core.control import leap
from sim_core.planning.commanded import plan_commanded
from sim_core.planning.jump import JumpTrial, lands_on, within_tolerance
from sim_core.simulate import RunRequest, run
from sim_core.skills.jump_to_target.behaviour import GROUND_AIR_TIME, landing_measures, leap_params, read_plans, scene_for
from sim_core.skills.jump_to_target.commanded import CONSTANTS, long_body, table as commanded_table

WINDUP = 1.25                       # s: the requests' wind-up time (the report's)
FORWARD = {"man": 1.9, "woman": 1.6}    # m: issue 29's forward range ends here (from 0.5 m)
AIR_TIMES = (0.4, 0.7)              # s: issue 29's air times
LANDING_VARIANTS = ([{"foot_delta": d, "landing_foot_lead_time": lead} for d in (-0.15, -0.05, 0.05, 0.15)
                     for lead in (0.15, 0.3)]
                    + [{"foot_delta": d, "landing_swing_arms": 1.0, "landing_arm_flexion": 2.5, "landing_right_time": 0.4}
                       for d in (-0.1, 0.0, 0.1)])     # the landings tried on each flight (jump_model's kinds)


def base_settings(character: str, forward: float, overrides: list[str]) -> dict:
    plan = next(p for p in read_plans(character)
                if abs(p["request"]["target_x"] - forward) < 1e-6 and p["request"]["target_y"] == 0
                and p["request"]["target_z"] == 0 and p["request"].get("obstacle_height", 0) == 0
                and p["request"]["air_time"] == GROUND_AIR_TIME)
    return dict(plan["settings"], commanded_takeoff=1.0, **assignments(overrides))


def assignments(items: list[str]) -> dict:
    """``name=value`` strings (--set, --const) as a dict of floats."""
    return {name: float(value) for name, value in (item.split("=") for item in items)}


def crouch_pairs(crouches: str | None, settings: dict) -> dict:
    """The planner's ``crouch_by_air_time`` columns from ``crouch:air time`` pairs (m:s, comma-separated;
    --crouch-by-air-time); none given: the settings' own crouch at every air time."""
    if not crouches:
        return {"air_time": [GROUND_AIR_TIME], "crouch_height": [settings["crouch_height"]]}
    pairs = sorted((float(b), float(a)) for a, b in (item.split(":") for item in crouches.split(",")))
    return {"air_time": [p[0] for p in pairs], "crouch_height": [p[1] for p in pairs]}


def jump(character: str, settings: dict, x: float, air_time: float) -> tuple[dict, np.ndarray, float]:
    """One commanded jump: the landing measures, the COM velocity and spin at lift-off."""
    target = (x, 0.0, 0.0, 0.0)
    trajectory = run(RunRequest("leap", character, params=leap_params(settings, target, WINDUP, air_time),
                                duration=5.0, world=scene_for(character, target)))
    flying = feet_above_surface(trajectory).min(axis=1) > leap.AIRBORNE_HEIGHT
    k = int(np.argmax(flying))
    return landing_measures(trajectory), trajectory.arrays["com_vel"][k], float(trajectory.arrays["angmom"][k][1])


def describe(x: float, air_time: float, measured: dict, velocity, spin: float | None, y: float = 0.0) -> str:
    error = math.hypot(measured["landing"][0] - x, measured["landing"][1] - y)
    at = f"({x:.3f}, {y:+.3f}) m" if y else f"{x:.2f} m"
    return (f"  {at} in {air_time:.3f} s: landed {measured['landing'][0]:.3f} m ({error * 100:4.1f} cm off), air "
            f"{measured['air_time']:.3f} s ({measured['air_time'] - air_time:+.3f}), {measured['outcome']}"
            + (f" (a recovery step at {measured['recovery_step_time']:.2f} s)" if "recovery_step_time" in measured else "")
            + ("" if velocity is None else f"; lift-off COM velocity ({velocity[0]:.2f}, {velocity[2]:.2f}) m/s, spin "
                                           f"{spin:+.1f} kg m2/s"))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--character", default="man")
    parser.add_argument("--base", type=float, default=1.3)
    parser.add_argument("--set", action="append", default=[])
    parser.add_argument("--table", action="store_true",
                        help="start from the character's commanded table (its settings and crouch pairs) instead of --base's plan")
    parser.add_argument("--long", action="store_true",
                        help="with --table: its long air times' row (long_settings over its settings, long_crouch_by_air_time)")
    parser.add_argument("--const", action="append", default=[])
    parser.add_argument("--sweep", help="first,last,step m of forward targets")
    parser.add_argument("--air-time", type=float, default=GROUND_AIR_TIME)
    parser.add_argument("--fixed-air-time", type=float, help="random targets: all in this air time (else drawn)")
    parser.add_argument("--random", type=int, default=0, help="this many seeded random forward targets and air times")
    parser.add_argument("--seed", type=int, default=29)
    parser.add_argument("--forward", help="random targets: low,high m forward (default 0.5 to issue 29's end)")
    parser.add_argument("--air-times", help="random targets: low,high s (default issue 29's 0.4,0.7)")
    parser.add_argument("--heights", help="random targets: low,high m - each onto a box that high or down from one "
                                          "(either equally likely; default: flat ground)")
    parser.add_argument("--flat-air-times", help="random box targets: low,high s - drawn again until the flat-ground air time "
                                                 "of their lift-off speed (sim_core.ballistics.flat_air_time) lies in it")
    parser.add_argument("--flat-forward", help="random box targets: low,high m - drawn again until the flat-ground landing "
                                               "of their lift-off velocity (x flat_air_time / air time) lies in it")
    parser.add_argument("--down", action="store_true", help="random box targets: down from the boxes only")
    parser.add_argument("--onto", action="store_true", help="random box targets: onto the boxes only")
    parser.add_argument("--lateral", type=float, default=0.0, help="random targets: target_y within +-this m")
    parser.add_argument("--aim", type=int, default=1,
                        help="random targets: at most this many trials, the commanded target moved by a secant on the "
                             "landing point after each (1 = the commanded take-off alone)")
    parser.add_argument("--crouch-by-air-time",
                        help="crouch:air time pairs (m:s, comma-separated) measured with this take-off: each jump's crouch "
                             "is interpolated at its air time (with --aim, at an air time moved by a secant too)")
    parser.add_argument("--plan-landing", type=int, default=0,
                        help="random targets: a hit that falls is planned as planning/land.py plans a drop - foot_delta "
                             "one step (land's plan step) more and less, two, ..., this many placements in all (the "
                             "planner's landing_trials), the aimed command kept; the first that ends balanced and hits")
    parser.add_argument("--landings", help="targets (m, comma-separated) whose flights try LANDING_VARIANTS")
    args = parser.parse_args(argv)
    overrides = assignments(args.const)
    for name, value in overrides.items():
        setattr(leap.CONSTANTS, name, value)
    if overrides:           # a character's own constants (its leap table's section) overridden too
        import sim_core.skills.leap.behaviour as leap_skill
        own = leap_skill.leap_constants
        leap_skill.leap_constants = lambda character: SimpleNamespace(**{**vars(own(character)), **overrides})
    stored = commanded_table(args.character) if args.table else None
    if args.table and stored is None:
        parser.error(f"the {args.character} has no commanded table (jump_commanded_{args.character}.json)")
    if args.long:
        if stored is None or "long_settings" not in stored:
            parser.error(f"--long: the {args.character}'s commanded table has no long air times' row (long_settings)")
        stored = long_body(stored)
    settings = (dict(stored["settings"], commanded_takeoff=1.0, **assignments(args.set))
                if stored else base_settings(args.character, args.base, args.set))
    started = time.time()
    if args.sweep:
        first, last, step = (float(v) for v in args.sweep.split(","))
        xs = [round(first + step * k, 4) for k in range(int(round((last - first) / step)) + 1)]
        rows = [(x, *jump(args.character, settings, x, args.air_time)) for x in xs]
        for x, measured, velocity, spin in rows:
            print(describe(x, args.air_time, measured, velocity, spin))
        landed = np.array([m["landing"][0] for _, m, _, _ in rows])
        errors = np.abs(landed - np.array(xs))
        late = np.array([m["air_time"] - args.air_time for _, m, _, _ in rows])
        steps = np.diff(landed) if len(xs) > 1 else np.zeros(1)
        speeds = np.diff([v[0] for _, _, v, _ in rows]) if len(xs) > 1 else np.zeros(1)
        print(f"sweep {args.character} {first:g}-{last:g} m every {step * 100:g} cm in {args.air_time:g} s ({len(xs)} jumps): "
              f"landing error median {np.median(errors) * 100:.1f} cm (max {errors.max() * 100:.1f}), within 5 cm "
              f"{int((errors <= 0.05).sum())}; air time error median {np.median(np.abs(late)):.3f} s ({late.min():+.3f} .. "
              f"{late.max():+.3f}); landing moved per step {np.median(steps) * 100:.1f} cm median ({steps.min() * 100:+.1f} .. "
              f"{steps.max() * 100:+.1f}), {int((steps < 0).sum())} steps back; lift-off speed forward per step "
              f"{speeds.min():+.2f} .. {speeds.max():+.2f} m/s; landed {landed.min():.2f}-{landed.max():.2f} m; balanced "
              f"{sum(m['outcome'] == 'success' for _, m, _, _ in rows)}")
    if args.random:
        rng = np.random.default_rng(args.seed)
        forward = tuple(float(v) for v in args.forward.split(",")) if args.forward else (0.5, FORWARD[args.character])
        air_times = tuple(float(v) for v in args.air_times.split(",")) if args.air_times else AIR_TIMES
        heights = tuple(float(v) for v in args.heights.split(",")) if args.heights else None
        flat = tuple(float(v) for v in args.flat_air_times.split(",")) if args.flat_air_times else None
        flat_forward = tuple(float(v) for v in args.flat_forward.split(",")) if args.flat_forward else None
        draws = []
        while len(draws) < args.random:
            draw = (float(rng.uniform(*forward)),
                    float(rng.uniform(*air_times)) if args.fixed_air_time is None else args.fixed_air_time,
                    float(rng.uniform(-args.lateral, args.lateral)) if args.lateral else 0.0,
                    float((-1.0 if args.down else 1.0 if args.onto else rng.choice((-1.0, 1.0))) * rng.uniform(*heights)) if heights else 0.0)
            flat_time = flat_air_time(draw[3], draw[1])
            if ((flat is None or flat[0] <= flat_time <= flat[1])
                    and (flat_forward is None or flat_forward[0] <= draw[0] * flat_time / draw[1] <= flat_forward[1])):
                draws.append(draw)
        # the skill's planner (planning/commanded.py) with these settings and crouch pairs as its table, and
        # --aim / --plan-landing as its bounds
        pairs = (stored["crouch_by_air_time"] if stored and not args.crouch_by_air_time
                 else crouch_pairs(args.crouch_by_air_time, settings))
        body = {"settings": settings, "crouch_by_air_time": pairs,
                # a low lift-off down from a box (low_down_body, push_down_body): the same pairs, --set's settings
                "low_down_crouch_by_air_time": pairs, "push_down_crouch_by_air_time": pairs, "push_down_settings": {},
                **({"down_settings": stored["down_settings"]} if stored and "down_settings" in stored else {})}
        constants = SimpleNamespace(**{**vars(CONSTANTS), "aim_trials": args.aim,
                                       "landing_trials": max(args.plan_landing, 1)})
        errors, late, hits, balanced, hits_balanced, planned, trials, stepped = [], [], 0, 0, 0, 0, [], 0
        for x, air_time, y, z in draws:
            target = (x, y, z, 0.0)
            judge = lambda m, target=target, air_time=air_time: (lands_on(m, target, air_time),      # noqa: E731
                                                                 within_tolerance(m, target, air_time))
            plan = plan_commanded(args.character, target, air_time, JumpTrial(args.character, target, air_time, WINDUP, "human"),
                                  constants.aim_trials + constants.landing_trials - 1, judge, body=body, constants=constants)
            measured = plan["measured"]
            trials.append(plan["trials"])
            planned += plan["settings"]["foot_delta"] != settings["foot_delta"]
            print(describe(x, air_time, measured, None, None, y) + (f" ({'onto' if z > 0 else 'down from'} a {abs(z):.3f} m box)" if z else "")
                  + f"; {plan['trials']} trials, aimed at {plan['settings']['flight_target_x']:.2f} m, foot_delta "
                    f"{plan['settings']['foot_delta']:+.4f} m")
            errors.append(math.hypot(measured["landing"][0] - x, measured["landing"][1] - y))
            late.append(measured["air_time"] - air_time)
            hits += lands_on(measured, target, air_time)
            balanced += measured["outcome"] == "success"
            hits_balanced += plan["found"]
            stepped += plan["found"] and "recovery_step_time" in measured
        times = f"{air_times[0]:g}-{air_times[1]:g}" if args.fixed_air_time is None else f"{args.fixed_air_time:g}"
        print(f"random {args.character} seed {args.seed} ({args.random} forward targets {forward[0]:g}-{forward[1]:g} m"
              f"{f' within +-{args.lateral:g} m' if args.lateral else ''}"
              f"{f', onto or down from boxes {heights[0]:g}-{heights[1]:g} m' if heights else ''}, "
              f"air time {times} s): landing error median {np.median(errors) * 100:.1f} cm (max "
              f"{max(errors) * 100:.1f}); air time error median {np.median(np.abs(late)):.3f} s ({min(late):+.3f} .. "
              f"{max(late):+.3f}); within 5 cm and 0.05 s: {hits}, {hits_balanced} of them balanced ({stepped} after a "
              f"recovery step); balanced {balanced}; "
              f"landings planned {planned}; trials median {np.median(trials):.0f}, most {max(trials)}")
    if args.landings:
        for x in (float(v) for v in args.landings.split(",")):
            outcomes = [jump(args.character, {**settings, **variant}, x, args.air_time)[0] for variant in LANDING_VARIANTS]
            landed = ", ".join(f"{m['landing'][0]:.2f}" for m in outcomes)
            print(f"  {x:.2f} m: {sum(m['outcome'] == 'success' for m in outcomes)} of {len(outcomes)} landings balanced "
                  f"(landed {landed} m)")
    print(f"({time.time() - started:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
