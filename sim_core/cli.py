"""Command line: python -m sim_core {list, describe, simulate, replay, bench, balance-report, character}.

Errors a user can cause print one line ('error: ...') and exit with status 2; nothing is written.
``simulate`` prints a JSON summary (outcome and metrics) as its last line.
"""
from __future__ import annotations

import argparse
import json
import math
import sys

from sim_core.errors import ParameterError, SimAthleticsError

EXIT_USAGE = 2


def _progress_printer(enabled: bool):
    if not enabled:
        return None
    def show(fraction: float) -> None:
        bar = "#" * int(30 * fraction)
        print(f"\r[{bar:<30}] {100 * fraction:5.1f} %", end="" if fraction < 1 else "\n", file=sys.stderr, flush=True)
    return show


def _finite(text: str, name: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise ParameterError(f"{name}={text!r} is not a number") from None
    if not math.isfinite(value):
        raise ParameterError(f"{name}={text} is not finite")
    return value


def build_request(args):
    from sim_core.character.model import World
    from sim_core.perturbation import Push
    from sim_core.simulate import RunRequest
    from sim_core.control.behaviour import behaviour_class

    params = behaviour_class(args.behaviour).schema.parse_assignments(args.set or [])
    slope = math.radians(_finite(args.slope, "--slope"))
    if not 0.0 <= abs(slope) <= math.radians(60):
        raise ParameterError(f"--slope={args.slope} degrees is out of range; allowed range is [-60, 60]")
    backpack = _finite(args.backpack, "--backpack")
    if not 0.0 <= backpack <= 40.0:
        raise ParameterError(f"--backpack={backpack:g} kg is out of range; allowed range is [0, 40] kg")
    world = World(slope=abs(slope), slope_axis=args.slope_axis if slope >= 0 else args.slope_axis.replace("+", "#").replace("-", "+").replace("#", "-"),
                  extra_mass={"CHEST1": backpack} if backpack else {})
    strength = args.strength
    if strength not in ("human", "unlimited"):
        strength = _finite(strength, "--strength")
    duration = None if args.duration is None else _finite(args.duration, "--duration")
    from sim_core.simulate import StartState
    velocity = tuple(_finite(v, "--start-velocity") for v in args.start_velocity.split(","))
    if len(velocity) != 3:
        raise ParameterError(f"--start-velocity {args.start_velocity!r} must be three numbers VX,VY,VZ in m/s")
    start = StartState(height=_finite(args.start_height, "--start-height"), velocity=velocity)
    return RunRequest(args.behaviour, args.character, params=params, duration=duration,
                      pushes=[Push.parse(p) for p in args.push or []], world=world, strength=strength,
                      start=start)


def cmd_list(args) -> int:
    from sim_core.character.spec import available_characters
    from sim_core.control.behaviour import available_behaviours, behaviour_class
    print("behaviours:")
    for name in available_behaviours():
        print(f"  {name:12s} {behaviour_class(name).summary}")
    print("characters:")
    for name in available_characters():
        print(f"  {name}")
    return 0


def schema_markdown(cls) -> str:
    """The parameter table of a behaviour as Markdown (the README's tables are made by this)."""
    rows = [f"| `{p.name}` | {p.unit} | {p.default:g} | {p.minimum:g} … {p.maximum:g} | {p.help} |"
            for p in cls.schema.parameters]
    return "\n".join(["| parameter | unit | default | range | meaning |", "| --- | --- | --- | --- | --- |", *rows])


def cmd_describe(args) -> int:
    from sim_core.control.behaviour import behaviour_class
    cls = behaviour_class(args.behaviour)
    if args.markdown:
        print(schema_markdown(cls))
        return 0
    print(json.dumps({"behaviour": cls.name, "summary": cls.summary, "default_duration": cls.default_duration,
                      "parameters": cls.schema.to_json_dict()}, indent=1))
    return 0


def cmd_simulate(args) -> int:
    from sim_core.simulate import run
    request = build_request(args)
    if args.out and not args.out.endswith(".npz"):
        raise ParameterError(f"--out {args.out!r} must end in .npz")
    trajectory = run(request, progress=_progress_printer(args.progress or sys.stderr.isatty()))
    if args.out:
        trajectory.save(args.out)
    summary = {"outcome": trajectory.meta["outcome"], "metrics": trajectory.meta["metrics"],
               "behaviour": trajectory.meta["behaviour"], "character": trajectory.meta["character"],
               "out": args.out}
    print(json.dumps(summary))
    return 0


def cmd_replay(args) -> int:
    from sim_core.simulate import largest_difference, replay
    from sim_core.trajectory import Trajectory
    try:
        original = Trajectory.load(args.file)
    except Exception as exc:  # noqa: BLE001 - any unreadable file is the same user error
        raise SimAthleticsError(f"cannot read trajectory {args.file!r}: {exc}") from None
    difference = largest_difference(original, replay(original))
    print(json.dumps({"file": args.file, "largest_difference": difference, "bit_identical": difference == 0.0}))
    return 0 if difference == 0.0 else 1


def cmd_bench(args) -> int:
    from sim_core.bench import bench
    from sim_core.control.behaviour import behaviour_class
    params = behaviour_class(args.behaviour).schema.parse_assignments(args.set or [])
    result = bench(behaviour=args.behaviour, character=args.character, params=params,
                   duration=_finite(args.duration, "--duration"), repeats=args.repeats)
    print(f"controller in the loop: {result['controller_in_loop_sim_s_per_wall_s']:.2f} sim s / wall s")
    print(f"raw mj_step:            {result['raw_mj_step_sim_s_per_wall_s']:.2f} sim s / wall s")
    print(f"ratio:                  {result['ratio']:.3f}  (goal >= 0.75)")
    print(json.dumps(result))
    return 0


def cmd_balance_report(args) -> int:
    from sim_core.experiments import balance_report
    balance_report(characters=args.character or ["man", "woman"], quick=args.quick)
    return 0


def cmd_character(args) -> int:
    """``character make``: a new body (Fig. 3 preset, between two characters, or to a height and
    mass), validated and compiled before it is written; ``character report``: Fig. 3 comparison."""
    from sim_core.character.spec import load_character
    if args.character_command == "report":
        from sim_core.character.fig3_report import write_report
        print(write_report(args.out))
        return 0
    from sim_core.character import make
    modes = [args.preset is not None, args.to is not None, args.height is not None or args.mass is not None]
    if sum(modes) != 1:
        raise ParameterError("character make needs exactly one of --preset NAME, --to CHARACTER --fraction F, "
                             "or --height H --mass M")
    base = load_character(args.from_)
    if args.preset is not None:
        from sim_core.character.fig3 import build_fig3_character
        data = build_fig3_character(args.preset, base)
    elif args.to is not None:
        if args.fraction is None:
            raise ParameterError("--to needs --fraction F (how far from --from, in [0, 1])")
        fraction = _finite(args.fraction, "--fraction")
        make.check_fraction(fraction)
        data = make.between(base, load_character(args.to), fraction)
    else:
        if args.height is None or args.mass is None:
            raise ParameterError("character make by targets needs both --height H (m) and --mass M (kg)")
        data = make.scaled_to(base, _finite(args.height, "--height"), _finite(args.mass, "--mass"))
    if args.name:
        data["name"] = args.name
    if args.out is None and args.preset is None:
        raise ParameterError("--out F.json is required (only --preset writes rigs/<name>.json by default)")
    path = make.write_character(data, args.out)
    print(json.dumps({"character": data["name"], "out": str(path), "total_mass": data["total_mass"],
                      "height": data["height"]}))
    return 0


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m sim_core", description="Sim Athletics simulation core")
    sub = p.add_subparsers(dest="command", required=True)
    sub.add_parser("list", help="list behaviours and characters").set_defaults(func=cmd_list)
    d = sub.add_parser("describe", help="print a behaviour's parameter schema as JSON")
    d.add_argument("behaviour")
    d.add_argument("--markdown", action="store_true", help="print the parameter table as Markdown")
    d.set_defaults(func=cmd_describe)
    s = sub.add_parser("simulate", help="run a behaviour and save its trajectory")
    s.add_argument("behaviour")
    s.add_argument("--character", default="man", help="character name (see list) or path to a spec .json")
    s.add_argument("--set", action="append", metavar="NAME=VALUE", help="behaviour parameter (repeatable)")
    s.add_argument("--duration", help="seconds to simulate (default: the behaviour's)")
    s.add_argument("--push", action="append", metavar="FORCE@DIR[:START[:DURATION]]",
                   help="sternum push, e.g. 120@back:1.0:0.25 (N, direction name or degrees, s, s)")
    s.add_argument("--slope", default="0", help="ground slope in degrees (default 0)")
    s.add_argument("--slope-axis", default="x+", choices=["x+", "x-", "y+", "y-"],
                   help="direction in which the ground rises")
    s.add_argument("--backpack", default="0", help="extra mass in kg on the upper torso (CHEST1)")
    s.add_argument("--strength", default="human", help="'human' torque limits, 'unlimited', or a factor")
    s.add_argument("--start-height", default="0", help="start the standing pose this many metres up (drop tests)")
    s.add_argument("--start-velocity", default="0,0,0", help="start moving at VX,VY,VZ m/s (landing tests)")
    s.add_argument("--out", help="trajectory file to write (.npz); written only if the run completes")
    s.add_argument("--progress", action="store_true", help="show a progress bar on stderr")
    s.set_defaults(func=cmd_simulate)
    r = sub.add_parser("replay", help="re-run a trajectory's log and report the largest difference")
    r.add_argument("file")
    r.set_defaults(func=cmd_replay)
    b = sub.add_parser("bench", help="controller-in-the-loop speed against raw mj_step")
    b.add_argument("--behaviour", default="balance")
    b.add_argument("--character", default="man")
    b.add_argument("--set", action="append", metavar="NAME=VALUE")
    b.add_argument("--duration", default="10")
    b.add_argument("--repeats", type=int, default=5)
    b.set_defaults(func=cmd_bench)
    br = sub.add_parser("balance-report", help="push scan, slopes and backpacks for the balance behaviour")
    br.add_argument("--character", action="append", help="man and/or woman (default both)")
    br.add_argument("--quick", action="store_true", help="coarser search (for a fast look)")
    br.set_defaults(func=cmd_balance_report)
    ch = sub.add_parser("character", help="make new characters (Hodgins & Pollard 1997) and report them")
    ch_sub = ch.add_subparsers(dest="character_command", required=True)
    mk = ch_sub.add_parser("make", help="write a new character spec (any command's --character takes it)")
    mk.add_argument("--from", dest="from_", default="man", help="character to start from (name or .json)")
    mk.add_argument("--preset", help="a Fig. 3 character: child, imaginary_runner or imaginary_cyclist")
    mk.add_argument("--to", help="character to interpolate towards (name or .json), with --fraction")
    mk.add_argument("--fraction", help="0..1: how far from --from to --to")
    mk.add_argument("--height", help="target height in m (top of the head), with --mass")
    mk.add_argument("--mass", help="target total mass in kg, with --height")
    mk.add_argument("--name", help="name of the new character (default: made from the inputs)")
    mk.add_argument("--out", help="spec file to write (.json); a --preset defaults to rigs/<name>.json")
    mk.set_defaults(func=cmd_character)
    rp = ch_sub.add_parser("report", help="compare the built characters with Fig. 3 (Markdown)")
    rp.add_argument("--out", help="Markdown file whose Fig. 3 table block to rewrite (e.g. docs/bodies.md)")
    rp.set_defaults(func=cmd_character)
    return p


def main(argv=None) -> int:
    args = parser().parse_args(argv)
    try:
        return args.func(args)
    except SimAthleticsError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:
        print("error: interrupted; nothing was written", file=sys.stderr)
        return 130
