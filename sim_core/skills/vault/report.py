"""The vault's report: Table 1 and the run-up speed scan (the measures are assess.py's, read off a
trajectory's contact forces).

``python -m sim_core report vault [--character woman] [--out FILE.npz]`` simulates the vault and
prints Table 1 of Hodgins et al. 1995: our value, Takei's mean and range (24 elite women, 1987 Pan
American Games) and the 1995 simulation, for the four phase times, the eight COM velocities and
the two mean vertical forces F = integral F_z dt / T, with each force row's impulse-momentum check
m (dv_z / T + g) beside it."""
from __future__ import annotations

import argparse

import numpy as np

from .assess import (TABLE_1, TAKEI_MASS, servos_on_horse, table_1)


def format_table_1(trajectory) -> str:
    """Table 1 as text: per row our value, Takei's mean [min, max], the 1995 simulation, whether
    ours is inside the human range; and per contact the impulse-momentum check."""
    measured = table_1(trajectory)
    rows = measured["rows"]
    meta = trajectory.meta
    apparatus = ("the 1987 women's horse", "the FIG table")[int(round(meta["params"]["apparatus"]))]
    lines = [f"Table 1 (Hodgins et al. 1995): the {meta['character']} vaulting {apparatus}",
             f"{'variable':28s} {'ours':>9s} {'Takei mean':>10s} {'[min, max]':>16s} {'1995 sim':>9s}  in range"]
    mass = measured["mass"]
    m0, lo, hi, sim = TAKEI_MASS
    lines.append(f"{'mass (kg)':28s} {mass:9.2f} {m0:10.2f} {f'[{lo:g}, {hi:g}]':>16s} {sim:9.2f}  {lo <= mass <= hi}")
    if not lo <= mass <= hi:
        lines.append(f"  (Takei's 24 gymnasts are a reference here: the {meta['character']} is {mass:.1f} kg, outside their "
                     f"{lo:g}-{hi:g} kg)")
    for name, unit, mean, lo, hi, sim in TABLE_1:
        ours = rows[name]
        value = "   (none)" if ours is None else f"{ours:9.3f}"
        inside = "-" if ours is None else str(lo <= ours <= hi)
        lines.append(f"{f'{name} ({unit})':28s} {value} {mean:10.3f} {f'[{lo:g}, {hi:g}]':>16s} {sim:9.3f}  {inside}")
    lines.append("impulse-momentum (mean vertical force against m (dv_z / T + g)):")
    for name, check in measured["impulse_momentum"].items():
        lines.append(f"  {name}: integral F_z dt / T = {check['mean_force']:.0f} N, m (dv_z / T + g) = "
                     f"{check['momentum_force']:.0f} N, difference {100 * check['relative_difference']:.1f} %")
    return "\n".join(lines)


def run_at(speed: float, character: str = "woman", apparatus: str = "horse_1987", duration: float | None = None,
           overrides: list[str] = ()):
    """The whole vault (or its first ``duration`` s) with the character's row at one run-up speed - also
    outside the offered range (vault_any.json's handled_speed), since this is how that range is
    measured: the row's settings as set (``low_level``), with ``overrides`` (``name=value``, the CLI's
    --set) over them."""
    from ...simulate import RunRequest, run
    from ...errors import ParameterError
    from .behaviour import calibrated
    row = calibrated(character, "human")
    if row is None:
        raise ParameterError(f"the {character} has no vault settings with human torque limits to scan")
    params = {**row["settings"], "low_level": 1.0, "runup_speed": float(speed), "apparatus": apparatus}
    if overrides:
        from .behaviour import Vault
        params = Vault.schema.parse_assignments(list(overrides), params)
    return run(RunRequest("vault", character, params=params, duration=duration))


def speed_scan(speeds, character: str = "woman", apparatus: str = "horse_1987", overrides: list[str] = ()) -> list[dict]:
    """Runs the whole vault at each run-up speed (``run_at``) and returns per speed its outcome, the
    fall time, the rotation and the bodies on the horse."""
    rows = []
    for speed in speeds:
        trajectory = run_at(speed, character, apparatus, overrides=overrides)
        m = trajectory.meta["metrics"]
        rows.append({"speed": float(speed), "outcome": trajectory.meta["outcome"], "fall_time": m.get("fall_time"),
                     "rotation": m["rotation"], "horse_fault": m.get("horse_fault")})
    return rows


def landing_trace(trajectory) -> dict:
    """Where a run goes, read off the trajectory: the board touchdown (time, the feet's x), the board and
    horse liftoff (COM velocity, angular momentum L_y about the COM), the hand touchdown (time, the hands'
    x and z), the head's first push on the horse, the mat touchdown (the COM's distance ahead of the middle
    of the feet, its velocity, L_y) and the controller's landing events (absorb, rise, balance)."""
    from .assess import vault_phases
    a, meta = trajectory.arrays, trajectory.meta
    t, names = a["time"], list(a["body_names"])
    phases = vault_phases(trajectory)
    trace = {"outcome": meta["outcome"], "fall_time": meta["metrics"].get("fall_time")}
    if "board" in phases:
        b0, b1 = phases["board"]
        trace["board"] = (float(t[b0]), float(a["body_pos"][b0, names.index("FOOTR"), 0]),
                          *a["com_vel"][b1, [0, 2]], float(a["angmom"][b1, 1]))
    if "horse" in phases:
        h0, h1 = phases["horse"]
        hands = a["body_pos"][h0, [names.index("HANDR"), names.index("HANDL")]]
        head = np.flatnonzero(a["contact_force"][:, names.index("HEAD"), meta["world_geoms"].index("vault_table"), 2] > 0)
        trace["horse"] = (float(t[h0]), float(hands[:, 0].mean()), float(hands[:, 2].mean()),
                          float(t[head[0]]) if len(head) else None, *a["com_vel"][h1, [0, 2]], float(a["angmom"][h1, 1]))
    if "mat" in phases:
        k = phases["mat"][0] - 1
        trace["mat"] = (float(t[k + 1]), float(a["com"][k, 0] - a["support_points"][k, :, 0].mean()),
                        *a["com_vel"][k, [0, 2]], float(a["angmom"][k, 1]))
    trace["events"] = {}
    for when, name in meta["phase_events"]:
        if name in ("absorb", "rise", "balance") and name not in trace["events"]:
            trace["events"][name] = float(when)
    return trace


def parting(first, second, thresholds=(1e-3, 1e-2, 5e-2)) -> list[float | None]:
    """The times at which two runs' COMs are first further apart than each threshold (m)."""
    a, b = first.arrays, second.arrays
    n = min(len(a["time"]), len(b["time"]))
    apart = np.abs(a["com"][:n] - b["com"][:n]).max(axis=1)
    return [float(a["time"][int(np.argmax(apart > d))]) if (apart > d).any() else None for d in thresholds]


def landing_main(args) -> int:
    """--landing: per run-up speed where the run goes (``landing_trace``), and where each speed's run
    parts from the first one's."""
    speeds = [float(x) for x in args.landing.split(",")]
    runs = [run_at(speed, args.character, args.apparatus, overrides=args.set) for speed in speeds]
    for speed, trajectory in zip(speeds, runs):
        r = landing_trace(trajectory)
        fell = "" if r["fall_time"] is None else f" at {r['fall_time']:.2f} s"
        print(f"runup_speed {speed:.4f} m/s: {r['outcome']}{fell}")
        if "board" in r:
            print("  board: touchdown at {:.3f} s, the right foot at x = {:.3f} m; liftoff v = ({:.3f}, {:.3f}) m/s, "
                  "L_y {:.2f} kg m2/s".format(*r["board"]))
        if "horse" in r:
            h = r["horse"]
            head = "none" if h[3] is None else f"{h[3]:.3f} s"
            print(f"  horse: hands at {h[0]:.3f} s, x = {h[1]:.3f} m, z = {h[2]:.3f} m; the head from {head}; liftoff v = "
                  f"({h[4]:.3f}, {h[5]:.3f}) m/s, L_y {h[6]:.2f} kg m2/s")
        if "mat" in r:
            print("  mat: touchdown at {:.3f} s, the COM {:+.3f} m ahead of the feet's middle, v = ({:.3f}, {:.3f}) m/s, "
                  "L_y {:.2f} kg m2/s".format(*r["mat"]))
        print("  landing: " + ", ".join(f"{name} at {when:.3f} s" for name, when in r["events"].items()))
    for speed, trajectory in zip(speeds[1:], runs[1:]):
        apart = ", ".join("never" if when is None else f"{when:.3f} s" for when in parting(runs[0], trajectory))
        print(f"{speed:.4f} against {speeds[0]:.4f} m/s: the COMs 1 mm, 1 cm, 5 cm apart at {apart}")
    return 0


def scan_main(args) -> int:
    """--scan: a grid of run-up speeds plus random draws; prints each and the contiguous range
    around the default run-up speed (the seed's) where every speed scanned succeeds."""
    from .behaviour import Vault
    default = Vault.schema.by_name["runup_speed"].default
    low, high, step = args.scan
    grid = list(np.round(np.arange(low, high + step / 2, step), 4))
    draws = list(np.round(np.random.default_rng(args.seed).uniform(low, high, args.draws), 4))
    rows = sorted(speed_scan(sorted(set(grid + draws)), args.character, args.apparatus, args.set), key=lambda r: r["speed"])
    for r in rows:
        fell = "" if r["fall_time"] is None else f", fell at {r['fall_time']:.2f} s"
        print(f"runup_speed {r['speed']:.4f} m/s: {r['outcome']}{fell}; rotation {r['rotation']:.2f} rad; "
              f"on the horse besides the hands and forearms: {', '.join(r['horse_fault'] or []) or 'nothing'}")
    ok = [r["outcome"] == "success" for r in rows]
    seed_speed = min(range(len(rows)), key=lambda k: abs(rows[k]["speed"] - default))
    if not ok[seed_speed]:
        print(f"the scanned speed nearest {default:g} m/s does not succeed")
        return 0
    lo = hi = seed_speed
    while lo > 0 and ok[lo - 1]:
        lo -= 1
    while hi < len(rows) - 1 and ok[hi + 1]:
        hi += 1
    print(f"every scanned speed succeeds in [{rows[lo]['speed']:g}, {rows[hi]['speed']:g}] m/s "
          f"({hi - lo + 1} of {len(rows)} speeds; the neighbours outside it fall or fail)")
    return 0


def plan_main(args) -> int:
    """--plan: at each run-up speed the bounded landing search of planning.vault (from her row's foot_delta,
    every trial a whole vault at that speed, ``run_at``), with its progress, and per speed what it found and
    how long it took."""
    import time
    from ...planning.vault import plan_foot_delta
    from .behaviour import VAULT_SETTINGS, calibrated
    knob = VAULT_SETTINGS.by_name["foot_delta"]
    start = calibrated(args.character, "human")["settings"]["foot_delta"] if args.start is None else args.start
    found = 0
    speeds = [float(x) for x in args.plan.split(",")]
    for speed in speeds:
        began = time.time()

        def simulate(foot_delta, speed=speed):
            return run_at(speed, args.character, args.apparatus, overrides=[*args.set, f"foot_delta={foot_delta}"])

        def progress(done, bound, best):
            print(f"  {speed:.4f} m/s: {done}/{bound} trials, the best so far foot_delta {best['foot_delta']:.5f} m "
                  f"{best['outcome']}", flush=True)
        plan = plan_foot_delta(simulate, start, knob.minimum, knob.maximum, progress=progress if args.progress else None)
        seconds = time.time() - began
        found += plan["found"]
        sides = ", ".join(f"{t['foot_delta']:.5f} {t['outcome'] if t['side'] == 0 else ('fwd', 'back')[t['side'] < 0]}"
                          for t in plan["tried"])
        if plan["found"]:
            what = f"stands with foot_delta {plan['foot_delta']:.5f} m"
        elif plan["bracket"]:
            what = (f"NO standing foot_delta: the fall turns from forward to back between {plan['bracket'][0]:.5f} and "
                    f"{plan['bracket'][1]:.5f} m")
        else:
            what = "NO standing foot_delta and no turn of the fall's side within the bound"
        print(f"runup_speed {speed:.4f} m/s: {what} ({plan['trials']} trials, {seconds:.1f} s): {sides}", flush=True)
    print(f"{found} of {len(speeds)} speeds have a standing foot_delta")
    return 0


def main(argv=None) -> int:
    from ...simulate import RunRequest, run
    parser = argparse.ArgumentParser(prog="python -m sim_core report vault", description=__doc__.split("\n\n")[0])
    parser.add_argument("--character", default="woman")
    parser.add_argument("--apparatus", default="horse_1987", choices=("horse_1987", "table"))
    parser.add_argument("--speed", type=float, default=None,
                        help="the run-up speed (default: the middle of the character's handled_speed)")
    parser.add_argument("--out", default=None, help="also write the trajectory (.npz)")
    parser.add_argument("--scan", nargs=3, type=float, metavar=("LOW", "HIGH", "STEP"),
                        help="instead: run the vault at run-up speeds LOW..HIGH every STEP m/s (and --draws random ones) "
                             "and print which succeed (how handled_speed is measured)")
    parser.add_argument("--draws", type=int, default=0, help="with --scan: this many random speeds in [LOW, HIGH]")
    parser.add_argument("--seed", type=int, default=0, help="with --scan: the random draws' seed")
    parser.add_argument("--landing", default=None, metavar="SPEEDS",
                        help="instead: run the vault at these run-up speeds (comma-separated) and print where each run goes "
                             "(board, horse, mat touchdown, the landing's events) and where it parts from the first")
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                        help="with --scan, --landing or --plan: a setting over the character's row (repeatable), e.g. --set catch=1")
    parser.add_argument("--plan", default=None, metavar="SPEEDS",
                        help="instead: at each run-up speed (comma-separated) search the landing's foot_delta (planning.vault: "
                             "step out the way the fall goes, then bisect; at most vault_any.json's plan_trials vaults) and "
                             "print whether a standing one exists")
    parser.add_argument("--start", type=float, default=None, help="with --plan: the search's first foot_delta (default: her row's)")
    parser.add_argument("--progress", action="store_true", help="with --plan: print each trial")
    args = parser.parse_args(argv)
    if args.plan:
        return plan_main(args)
    if args.scan:
        return scan_main(args)
    if args.landing:
        return landing_main(args)
    from ...character.spec import load_character
    from .behaviour import vault_constants
    speed = args.speed if args.speed is not None else float(np.mean(vault_constants(load_character(args.character).name).handled_speed))
    trajectory = run(RunRequest("vault", args.character, params={"apparatus": args.apparatus, "runup_speed": speed}))
    if args.out:
        trajectory.save(args.out)
    print(format_table_1(trajectory))
    metrics = trajectory.meta["metrics"]
    print(f"outcome: {trajectory.meta['outcome']}; rotation {metrics['rotation']:.2f} rad "
          f"({metrics['somersaults']:.2f} somersaults); feet first: {metrics.get('feet_first')}; "
          f"peak landing force {metrics.get('peak_landing_body_weights', float('nan')):.1f} body weights; "
          f"fell at {metrics.get('fall_time')} s; feet through the mat onto the floor: {metrics.get('through_the_mat')} "
          f"(floor force up to {metrics.get('floor_under_mat_peak', 0.0):.0f} N); balanced at the end for "
          f"{metrics.get('balanced_time_at_end', 0.0):.2f} s; the palms at the horse touchdown "
          f"{', '.join(f'{x:.0f}' for x in metrics.get('palm_angle_at_horse_deg', []))} deg from palm-down; the elbows "
          f"bent at most {', '.join(f'{x:.0f}' for x in metrics.get('elbow_bend_on_horse_deg', []))} deg on the horse")
    if "horse_bodies" in metrics:
        shares = ", ".join(f"{name} {100 * share:.0f} %" for name, share in metrics["horse_bodies"].items())
        fault = metrics["horse_fault"]
        print(f"on the horse (share of its vertical impulse): {shares}; "
              + (f"FAULT: {', '.join(fault)} on the horse (only the hands and forearms may touch it)" if fault
                 else "only the hands and forearms touch it"))
    if "horse_bodies" in metrics:
        v5 = servos_on_horse(trajectory)
        print(f"shoulder and wrist servos while she touches the horse (TARGETS.md V5): acting in {v5['active_frames']} of "
              f"the {v5['frames']} frames ({v5['active_time']:.3f} of {v5['touching_time']:.3f} s"
              + (f", from {v5['first_active']:.3f} s: {', '.join(v5['acting'])}" if v5["acting"] else "")
              + f"; {v5['onsets_active']} more where a touch begins)")
    if "bow_start" in metrics:
        print(f"the bow from {metrics['bow_start']:.2f} s: the trunk pitched {metrics['bow_trunk_pitch_start']:.3f} -> "
              f"{metrics['bow_trunk_pitch']:.3f} rad (at {metrics['bow_deepest_time']:.2f} s) -> "
              f"{metrics['bow_trunk_pitch_end']:.3f} rad at the end ({trajectory.arrays['time'][-1]:.2f} s); the feet moved "
              f"at most {100 * metrics['bow_feet_moved']:.2f} cm")
    return 0
