"""Command line: python -m sim_core {list, describe, simulate, plan, replay, bench, calibrate, report, character, adapt}.

Errors a user can cause print one line ('error: ...') and exit with status 2; nothing is written.
``simulate`` prints a JSON summary (outcome and metrics) as its last line.
"""
from __future__ import annotations

import argparse
import importlib
import json
import math
import sys

from .errors import ParameterError, SimAthleticsError
from .request import add_request_arguments

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
    """The RunRequest of ``simulate``'s flags: the behaviour's --set values by its schema, the
    rest by the request schema (sim_core.request), as the panel and batch bakes do."""
    from .request import behaviour_params, build_request as request_from_values, request_values

    params = behaviour_params(args.behaviour, args.character, args.set or [])
    values, pushes = request_values(args)
    return request_from_values(args.behaviour, args.character, params, values, pushes)


def cmd_list(args) -> int:
    from .character.spec import available_characters
    from .skills import available_behaviours, behaviour_class
    print("behaviours:")
    for name in available_behaviours():
        print(f"  {name:12s} {behaviour_class(name).summary}")
    print("characters:")
    for name in available_characters():
        print(f"  {name}")
    return 0


def schema_markdown(cls) -> str:
    """The parameter table of a behaviour as Markdown (the README's tables are made by this)."""
    return cls.schema.markdown()


def cmd_describe(args) -> int:
    from .skills import behaviour_class
    cls = behaviour_class(args.behaviour)
    if args.markdown:
        print(schema_markdown(cls))
        return 0
    from .request import REQUEST_SCHEMA
    settings = getattr(cls, "settings_schema", None)
    print(json.dumps({"behaviour": cls.name, "summary": cls.summary, "default_duration": cls.default_duration,
                      "parameters": cls.schema.to_json_dict(),
                      "settings": settings.to_json_dict() if settings is not None else [],
                      "request": REQUEST_SCHEMA.to_json_dict()}, indent=1))
    return 0


def _plan_progress(done: int, total: int, best: dict) -> None:
    print(f"planning: {done}/{total} trials, nearest so far lands at ({best['landing'][0]:.2f}, "
          f"{best['landing'][1]:.2f}) m after {best['air_time']:.2f} s ({best['outcome']})", file=sys.stderr, flush=True)


def _trial_progress(done: int, total: int, last: dict) -> None:
    print(f"plan: {done}/{total} trials, the last {last['outcome']}", file=sys.stderr, flush=True)


def _use_store(args) -> None:
    """--store DIR: the user's plan store for this command (read and written), as
    $SIM_ATHLETICS_PLANS would set it."""
    if getattr(args, "store", None):
        import os
        from .skills.jump_to_target.behaviour import PLAN_STORE_VARIABLE
        os.environ[PLAN_STORE_VARIABLE] = args.store


def cmd_simulate(args) -> int:
    from .simulate import run
    if args.out and not args.out.endswith(".npz"):
        raise ParameterError(f"--out {args.out!r} must end in .npz")
    if args.scene:
        return simulate_scene(args)
    if not args.behaviour:
        raise ParameterError("simulate needs a behaviour (see list) or --scene FILE")
    request = build_request(args)
    _use_store(args)
    # planning runs here, above the loop, not in the behaviour; for planning.PLANNED_BEHAVIOURS only (imported
    # only then: the search service's imports take about a second)
    if request.behaviour == "jump_to_target":
        from .planning import plan_before_run
        from .tuning import executor_for
        with executor_for(args.workers) as executor:
            plan_before_run(request, int(request.params.get("plan_trials", 120)), progress=_plan_progress,
                            executor=executor)
    plan = None
    if request.behaviour in ("land", "dive"):    # planning.PLANNED_REQUESTS: a landing's foot placement, a dive's
        from .planning import describe, planned_request   # take-off for its platform, planned by simulating it
        from .tuning import executor_for
        with executor_for(args.workers) as executor:
            request, plan = planned_request(request, progress=_trial_progress, executor=executor)
        if plan is not None:
            print(describe(plan), file=sys.stderr, flush=True)
    trajectory = run(request, progress=_progress_printer(args.progress or sys.stderr.isatty()))
    if args.out:
        trajectory.save(args.out)
    summary = {"outcome": trajectory.meta["outcome"], "metrics": trajectory.meta["metrics"],
               "behaviour": trajectory.meta["behaviour"], "character": trajectory.meta["character"],
               "out": args.out}
    if plan is not None:
        summary["plan"] = plan
    print(json.dumps(summary))
    return 0


def cmd_plan(args) -> int:
    from .request import behaviour_params
    from .planning import PLANNED_BEHAVIOURS, plan_and_store
    from .tuning import executor_for
    if args.behaviour not in PLANNED_BEHAVIOURS:
        raise ParameterError(f"behaviour {args.behaviour!r} needs no plan; planned behaviours: "
                             f"{', '.join(PLANNED_BEHAVIOURS)}")
    if args.budget < 1:
        raise ParameterError(f"--budget {args.budget}: must be at least 1 trial (a simulated jump, ~0.5 s)")
    params = behaviour_params(args.behaviour, args.character, args.set or [])
    strength = args.strength if args.strength in ("human", "unlimited") else _finite(args.strength, "--strength")
    _use_store(args)
    with executor_for(args.workers) as executor:
        plan = plan_and_store(args.character, params, strength, args.budget, progress=_plan_progress,
                              executor=executor)
    from .skills.jump_to_target.behaviour import plan_store_dir
    m = plan["measured"]
    print(json.dumps({"found": plan["found"], "trials": plan["trials"], "landing": m["landing"],
                      "air_time": m["air_time"], "outcome": m["outcome"], "store": str(plan_store_dir())}))
    return 0


SINGLE_ACTOR_OPTIONS = ("set", "duration", "push", "start_height", "start_velocity", "backpack", "slope", "strength",
                        "character")


def simulate_scene(args) -> int:
    """``simulate --scene FILE``: every actor of the scene file in one run; the summary lists each
    actor's outcome. The scene file says everything: the one-character options are refused."""
    from .scene import load_scene
    from .simulate import run_scene
    defaults = parser().parse_args(["simulate", "x"])
    for option in SINGLE_ACTOR_OPTIONS:
        if getattr(args, option) != getattr(defaults, option):
            raise ParameterError(f"--{option.replace('_', '-')} does not apply to --scene: set it in the scene file")
    if args.behaviour:
        raise ParameterError(f"give a behaviour ({args.behaviour!r}) or --scene, not both")
    trajectory = run_scene(load_scene(args.scene), progress=_progress_printer(args.progress or sys.stderr.isatty()))
    if args.out:
        trajectory.save(args.out)
    actors = [{"name": a["name"], "character": a["character"], "behaviour": a["behaviour"],
               "outcome": a["outcome"]} for a in trajectory.meta["actors"]]
    print(json.dumps({"scene": args.scene, "duration": trajectory.meta["duration"], "actors": actors,
                      "out": args.out}))
    return 0


def cmd_replay(args) -> int:
    from .simulate import largest_difference, replay
    from .trajectory import Trajectory
    try:
        original = Trajectory.load(args.file)
    except Exception as exc:  # noqa: BLE001 - any unreadable file is the same user error
        raise SimAthleticsError(f"cannot read trajectory {args.file!r}: {exc}") from None
    difference = largest_difference(original, replay(original))
    print(json.dumps({"file": args.file, "largest_difference": difference, "bit_identical": difference == 0.0}))
    return 0 if difference == 0.0 else 1


def cmd_bench(args) -> int:
    from .bench import bench
    from .request import behaviour_params
    params = behaviour_params(args.behaviour, args.character, args.set or [])
    result = bench(behaviour=args.behaviour, character=args.character, params=params,
                   duration=_finite(args.duration, "--duration"), repeats=args.repeats)
    print(f"controller in the loop: {result['controller_in_loop_sim_s_per_wall_s']:.2f} sim s / wall s")
    print(f"raw mj_step:            {result['raw_mj_step_sim_s_per_wall_s']:.2f} sim s / wall s")
    print(f"ratio:                  {result['ratio']:.3f}  (goal >= 0.75)")
    print(json.dumps(result))
    if args.scene_actors:
        from .bench import scene_bench
        scene = scene_bench(count=args.scene_actors, duration=_finite(args.scene_duration, "--scene-duration"),
                            repeats=args.repeats)
        print(f"scene of {args.scene_actors} runners: {scene['scene_loop_sim_s_per_wall_s']:.2f} sim s / wall s, raw "
              f"mj_step of the same model {scene['raw_mj_step_sim_s_per_wall_s']:.2f}, ratio {scene['ratio']:.3f}")
        print(json.dumps(scene))
    if args.search_runs:
        from .bench import search_bench
        search = search_bench(runs=args.search_runs, repeats=args.repeats)
        rates = ", ".join(f"{n} worker{'s' if n > 1 else ''} {r:.1f}" for n, r in search["evaluations_per_minute"].items())
        print(f"running search ({search['evaluation']} an evaluation), evaluations per minute: {rates}; "
              f"speed-up {search['speedup']:.2f} (goal >= 1.8)")
        print(json.dumps(search))
    return 0


CROSS_SKILL_REPORTS = {"random": "random_requests"}     # ``report NAME``: reports that span several skills


def cmd_skill_part(args) -> int:
    """``calibrate SKILL ...`` / ``report SKILL ...``: the skill room's calibrate.py or report.py,
    with the rest of the command line as its own options (``--help`` lists them); ``report random``
    is sim_core/random_requests.py, which spans several skills and so lives in no skill's room."""
    from .skills import skill_module
    if args.part == "report" and args.skill in CROSS_SKILL_REPORTS:
        module = importlib.import_module(f".{CROSS_SKILL_REPORTS[args.skill]}", __package__)
    else:
        module = skill_module(args.skill, args.part)
    sys.argv = [f"python -m sim_core {args.part} {args.skill}", *args.options]     # its usage line names it so
    if args.part != "calibrate":
        return module.main(args.options) or 0
    from .skills.jump_to_target.behaviour import shipped_plans_only
    with shipped_plans_only():      # a calibration writes the shipped tables and docs: the user's plans set aside
        return module.main(args.options) or 0


def cmd_character(args) -> int:
    """``character make``: a new body (Fig. 3 preset, between two characters, or to a height and
    mass), validated and compiled before it is written; ``character report``: Fig. 3 comparison."""
    from .character.spec import load_character
    if args.character_command == "report":
        from .character.fig3_report import write_report
        print(write_report(args.out))
        return 0
    if args.character_command == "scaling-report":
        from .adapt.experiment import write_report as write_scaling_report
        print(write_scaling_report(args.out, skills=args.skill or ("balance", "running"), cap=_finite(args.cap, "--cap"),
                                   progress=lambda t: print(f"{t.skill} {100 * t.fraction:g} % {t.controller}: "
                                                            f"{t.time_before_falling:.2f} s", file=sys.stderr)))
        return 0
    from .character import make
    modes = [args.preset is not None, args.to is not None, args.height is not None or args.mass is not None]
    if sum(modes) != 1:
        raise ParameterError("character make needs exactly one of --preset NAME, --to CHARACTER --fraction F, "
                             "or --height H --mass M")
    base = load_character(args.from_)
    if args.preset is not None:
        from .character.fig3 import build_fig3_character
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
    skin = None if args.no_skin else _write_skin(load_character(str(path)), path.with_suffix(".glb"))
    print(json.dumps({"character": data["name"], "out": str(path), "total_mass": data["total_mass"],
                      "height": data["height"], "skin": skin}))
    return 0


def cmd_adapt(args) -> int:
    """``adapt``: every skill carried to a body (sim_core/adapt/command.py)."""
    from .adapt.command import main as adapt_main
    args.minutes, args.workers = _finite(args.minutes, "--minutes"), int(_finite(args.workers, "--workers"))
    return adapt_main(args)


def _write_skin(spec, out) -> str:
    """The made character's rigged skin next to its spec, by the builder build.py uses
    (tools.rigbuild, a checkout's build-time code with the rig extras); where it or its
    extras are missing (the add-on), or the skin fails the builder's check, a note says so."""
    try:
        from tools.rigbuild import write_checked_rig
    except ImportError as exc:
        return f"not built: {exc.name} is missing (pip install -e '.[rigs]' in a checkout)"
    report, failure = write_checked_rig(spec, out)
    return f"not built: {failure}" if failure else str(out)


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m sim_core", description="Sim Athletics simulation core")
    sub = p.add_subparsers(dest="command", required=True)
    sub.add_parser("list", help="list behaviours and characters").set_defaults(func=cmd_list)
    d = sub.add_parser("describe", help="print a behaviour's parameter schema as JSON")
    d.add_argument("behaviour")
    d.add_argument("--markdown", action="store_true", help="print the parameter table as Markdown")
    d.set_defaults(func=cmd_describe)
    s = sub.add_parser("simulate", help="run a behaviour (or a scene of several actors) and save its trajectory")
    s.add_argument("behaviour", nargs="?", help="behaviour name (see list); omit with --scene")
    s.add_argument("--scene", metavar="FILE", help="scene file (.json or .toml; see docs/scenes.md): a world and its actors")
    s.add_argument("--character", default="man", help="character name (see list) or path to a spec .json")
    s.add_argument("--set", action="append", metavar="NAME=VALUE", help="behaviour parameter (repeatable)")
    add_request_arguments(s)
    s.add_argument("--out", help="trajectory file to write (.npz); written only if the run completes")
    s.add_argument("--progress", action="store_true", help="show a progress bar on stderr")
    s.add_argument("--workers", type=int, help="processes for planning an unplanned jump or a landing (default: one per CPU)")
    s.add_argument("--store", help="the user's plan store directory (default $SIM_ATHLETICS_PLANS, else "
                   "~/.cache/sim_athletics/plans)")
    s.set_defaults(func=cmd_simulate)
    pl = sub.add_parser("plan", help="plan a behaviour's request by simulation and store the plan")
    pl.add_argument("behaviour")
    pl.add_argument("--character", default="man", help="character name (see list) or path to a spec .json")
    pl.add_argument("--set", action="append", metavar="NAME=VALUE", help="behaviour parameter (repeatable)")
    pl.add_argument("--strength", default="human", help="'human' torque limits, 'unlimited', or a factor")
    pl.add_argument("--budget", type=int, default=120, help="simulated trials the search may run (default 120)")
    pl.add_argument("--workers", type=int, help="processes running the trials (default: one per CPU)")
    pl.add_argument("--store", help="the user's plan store directory (default $SIM_ATHLETICS_PLANS, else "
                    "~/.cache/sim_athletics/plans)")
    pl.set_defaults(func=cmd_plan)
    r = sub.add_parser("replay", help="re-run a trajectory's log and report the largest difference")
    r.add_argument("file")
    r.set_defaults(func=cmd_replay)
    b = sub.add_parser("bench", help="controller-in-the-loop speed against raw mj_step")
    b.add_argument("--behaviour", default="balance")
    b.add_argument("--character", default="man")
    b.add_argument("--set", action="append", metavar="NAME=VALUE")
    b.add_argument("--duration", default="10")
    b.add_argument("--repeats", type=int, default=5)
    b.add_argument("--scene-actors", type=int, default=4, help="runners in the scene benchmark (0 = none)")
    b.add_argument("--scene-duration", default="5", help="seconds simulated in the scene benchmark")
    b.add_argument("--search-runs", type=int, default=0,
                   help="runs of the running search timed through 1 and 2 local worker processes (0 = none)")
    b.set_defaults(func=cmd_bench)
    for part, text in (("calibrate", "run a skill's calibration: it searches by simulation and writes the skill's table"),
                       ("report", "run a skill's report (or 'report random': random requests across skills): it simulates and writes under docs/")):
        sp = sub.add_parser(part, help=text, add_help=False)
        sp.add_argument("skill", help="skill name (see list)")
        sp.add_argument("options", nargs=argparse.REMAINDER, help="the skill's own options (SKILL --help)")
        sp.set_defaults(func=cmd_skill_part, part=part)
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
    mk.add_argument("--no-skin", action="store_true", help="write only the spec, not its rigged skin (.glb)")
    mk.add_argument("--out", help="spec file to write (.json); a --preset defaults to rigs/<name>.json")
    mk.set_defaults(func=cmd_character)
    rp = ch_sub.add_parser("report", help="compare the built characters with Fig. 3 (Markdown)")
    rp.add_argument("--out", help="Markdown file whose Fig. 3 table block to rewrite (e.g. docs/bodies.md)")
    rp.set_defaults(func=cmd_character)
    sr = ch_sub.add_parser("scaling-report", help="the seed's Fig. 5/8 experiment: time before falling of the man's "
                           "controller, unscaled, geometric and mass-scaled, on bodies from the man to the woman")
    sr.add_argument("--out", default="docs/bodies.md", help="Markdown file whose scaling block is rewritten")
    sr.add_argument("--skill", action="append", choices=["balance", "running"], help="repeatable; default both")
    sr.add_argument("--cap", default="100", help="seconds: a run that has not fallen by then stops (default 100, the seed's bar)")
    sr.set_defaults(func=cmd_character)
    ad = sub.add_parser("adapt", help="adapt every skill to a body (scale from the nearest calibrated character, "
                        "check by random runs, search where that fails) and report what works")
    ad.add_argument("--character", required=True, help="the body: a name or a spec .json (character make)")
    ad.add_argument("--skills", nargs="+", default=["all"], help="skills to adapt (default all)")
    ad.add_argument("--minutes", default="60", help="budget of the searches in minutes (default 60)")
    ad.add_argument("--workers", default="2", help="processes a search runs its simulations in (default 2)")
    ad.add_argument("--seed", type=int, default=1, help="seed of the checks' random requests (default 1)")
    ad.add_argument("--out", help="folder of state.json and report.md (default out/adapt/<character>)")
    ad.add_argument("--redo", nargs="*", metavar="SKILL", help="adapt again the skills state.json records as done "
                    "(all of them, or the ones named)")
    ad.set_defaults(func=cmd_adapt)
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
