"""Headless: add a character, simulate a behaviour, bake it, save a .blend.

    blender -b -P <add-on folder>/batch.py -- --character man --behaviour balance \\
        --set pelvis_height=0.52 --set move_time=1.2 --duration 3 --fps 25 --out out/balance.blend

(In a repository checkout the add-on folder is ``blender_addon``; with Blender as a Python
module, ``python blender_addon/batch.py --character man ...`` does the same.)

A scene of several actors (sim_core.scene; docs/scenes.md) bakes each actor onto its own
armature, named after the actor, in one .blend:

    blender -b -P <add-on folder>/batch.py -- --scene examples/two_runners.json --out out/runners.blend

Everything is validated before the scene is touched. Exit status: 0 baked (the outcome is
printed, whatever it is), 2 bad input (one line on stderr naming the value and what is
allowed), 3 the run's outcome was not success and ``--require-success`` was given, 1 anything
else. The .blend is written only after a complete bake (Blender saves through a temporary file).
"""
from __future__ import annotations

import argparse
import importlib
import sys
from pathlib import Path

PROG = "sim_athletics"


class BatchError(Exception):
    """Bad input (exit status 2)."""


class _Parser(argparse.ArgumentParser):
    def error(self, message):                 # one line, not usage + message
        raise BatchError(message)


def _package():
    """The add-on package this file belongs to, however it was started (Blender's -P runs it
    as __main__, outside its package)."""
    if __package__:
        return importlib.import_module(__package__)
    here = Path(__file__).resolve().parent
    if str(here.parent) not in sys.path:
        sys.path.append(str(here.parent))      # after Blender's own packages: only finds the add-on
    return importlib.import_module(here.name)


def parse_args(argv: list[str], request_arguments=None) -> argparse.Namespace:
    """``request_arguments``: sim_core.request.add_request_arguments (the run request's flags,
    as ``python -m sim_core simulate`` has them: --duration, --strength, --slope, --push...)."""
    p = _Parser(prog=PROG, description="Simulate a behaviour and bake it into a .blend")
    p.add_argument("--character", default="man", help="character name (rigs/<name>.json); default man")
    p.add_argument("--behaviour", help="behaviour name, e.g. balance (or --scene)")
    p.add_argument("--scene", help="scene file (.json/.toml): every actor baked onto its own armature")
    p.add_argument("--set", dest="assignments", action="append", default=[], metavar="NAME=VALUE",
                   help="behaviour parameter (repeatable), SI units: metres, radians, seconds")
    if request_arguments is not None:
        request_arguments(p, strength_choices=True)
    p.add_argument("--fps", type=int, default=None, help="scene frame rate (default: the file's)")
    p.add_argument("--start-frame", type=int, default=1, help="frame of the first key (default 1)")
    p.add_argument("--out", required=True, help="the .blend file to write")
    p.add_argument("--trajectory", default=None, help="also save the trajectory (.npz)")
    p.add_argument("--keep-scene", action="store_true", help="add to the loaded file instead of an empty one")
    p.add_argument("--require-success", action="store_true", help="exit 3 unless the outcome is success")
    args = p.parse_args(argv)
    if not args.out.endswith(".blend"):
        raise BatchError(f"--out {args.out!r} must end in .blend")
    if bool(args.behaviour) == bool(args.scene):
        raise BatchError("give --behaviour (one character) or --scene FILE (its actors), one of the two")
    if args.scene and (args.assignments or args.duration is not None or args.strength != "human"
                       or args.character != "man"):
        raise BatchError("--character, --set, --duration and --strength do not apply to --scene: set them in the scene file")
    if args.fps is not None and not 1 <= args.fps <= 1000:
        raise BatchError(f"--fps {args.fps} is out of range; allowed range is [1, 1000]")
    return args


def script_argv(argv: list[str] | None = None) -> list[str]:
    """Arguments after '--' (Blender's own come before it)."""
    argv = sys.argv if argv is None else argv
    return argv[argv.index("--") + 1:] if "--" in argv else argv[1:]


def _prepared_file(args: argparse.Namespace, pkg):
    """An empty file (or the loaded one with --keep-scene), the add-on registered, the frame rate
    set; returns bpy.context."""
    import bpy
    if not args.keep_scene:
        bpy.ops.wm.read_homefile(use_empty=True)
    if "sim_athletics" not in bpy.types.Scene.bl_rna.properties:
        pkg.register()
    if args.fps is not None:
        bpy.context.scene.render.fps, bpy.context.scene.render.fps_base = args.fps, 1.0
    return bpy.context


def run(argv: list[str]) -> int:
    import bpy
    pkg = _package()
    api = importlib.import_module(pkg.__name__ + ".api")
    rig = importlib.import_module(pkg.__name__ + ".rig")
    sim = importlib.import_module(pkg.__name__ + ".core.simcore").sim
    SimAthleticsError = sim("errors").SimAthleticsError
    try:
        args = parse_args(argv, sim("request").add_request_arguments)
        if args.scene:
            return run_scene(args, pkg)
        params = api.parse_params(args.behaviour, args.assignments, args.character)
        request, pushes = sim("request").request_values(args)
        api.make_request(args.character, args.behaviour, params, request=request, pushes=pushes)   # validate all first
    except (BatchError, SimAthleticsError) as exc:
        print(f"{PROG}: error: {exc}", file=sys.stderr)
        return 2

    context = _prepared_file(args, pkg)
    scene = context.scene
    try:
        arm = api.add_character(context, args.character)
        action, trajectory = api.simulate_and_bake(
            context, armature=arm.name, behaviour=args.behaviour, params=params, request=request, pushes=pushes,
            start_frame=args.start_frame, fit_scene_range=True, progress=api.console_progress)
    except (SimAthleticsError, rig.RigError) as exc:
        print(f"{PROG}: error: {exc}", file=sys.stderr)
        return 2
    out = Path(args.out).resolve()
    out.parent.mkdir(parents=True, exist_ok=True)
    if args.trajectory:
        trajectory.save(args.trajectory)
    bpy.ops.wm.save_as_mainfile(filepath=str(out))
    outcome = trajectory.meta.get("outcome")
    frames = action.frame_range
    print(f"{PROG}: baked {action.name!r} onto {arm.name}: frames {frames[0]:g}-{frames[1]:g} at "
          f"{scene.render.fps / scene.render.fps_base:g} fps, outcome {outcome}; wrote {out}")
    if args.require_success and outcome != "success":
        return 3
    return 0


def run_scene(args: argparse.Namespace, pkg) -> int:
    """Bake every actor of the scene file onto its own armature (named after the actor; the
    armature at the world origin, so its baked root motion puts the actor where the scene placed
    it), the world's props once, and save one .blend."""
    import bpy
    sim = importlib.import_module(pkg.__name__ + ".core.simcore").sim
    SimAthleticsError = sim("errors").SimAthleticsError
    load_scene, simulate_scene = sim("scene").load_scene, sim("simulate").run_scene
    api = importlib.import_module(pkg.__name__ + ".api")
    rig = importlib.import_module(pkg.__name__ + ".rig")
    bake = importlib.import_module(pkg.__name__ + ".bake")
    scenery = importlib.import_module(pkg.__name__ + ".scenery")
    try:
        trajectory = simulate_scene(load_scene(args.scene), progress=api.console_progress)
    except SimAthleticsError as exc:
        print(f"{PROG}: error: {exc}", file=sys.stderr)
        return 2
    context = _prepared_file(args, pkg)
    scene = context.scene
    fps, end = bake.scene_fps(scene), args.start_frame
    outcomes, armatures = {}, {}
    try:
        for actor in trajectory.meta["actors"]:
            arm = api.add_character(context, actor["character"], location=(0.0, 0.0, 0.0))
            arm.name = arm.data.name = actor["name"]
            for child in arm.children:
                child.name = f"{actor['name']}_skin"
            action = bake.bake_trajectory(arm, trajectory.actor(actor["name"]), fps=fps, start_frame=args.start_frame)
            end = max(end, int(round(action.frame_range[1])))
            outcomes[arm.name] = actor["outcome"]
            armatures[actor["prefix"]] = arm
        scenery.add_scenery(context, arm, trajectory)
        bicycle = trajectory.meta["world"].get("bicycle")
        if bicycle:                 # the bicycle's bodies as objects, parented to its rider's armature
            bake.bake_moving_props(context, armatures[bicycle["rider"]], trajectory, fps=fps, start_frame=args.start_frame)
    except (SimAthleticsError, rig.RigError) as exc:
        print(f"{PROG}: error: {exc}", file=sys.stderr)
        return 2
    scene.frame_start, scene.frame_end = args.start_frame, end
    out = Path(args.out).resolve()
    out.parent.mkdir(parents=True, exist_ok=True)
    if args.trajectory:
        trajectory.save(args.trajectory)
    bpy.ops.wm.save_as_mainfile(filepath=str(out))
    print(f"{PROG}: baked {len(outcomes)} actors (frames {args.start_frame}-{end} at {fps:g} fps), outcomes "
          f"{', '.join(f'{k} {v}' for k, v in outcomes.items())}; wrote {out}")
    if args.require_success and any(v != "success" for v in outcomes.values()):
        return 3
    return 0


def main(argv: list[str] | None = None) -> None:
    sys.exit(run(script_argv(argv)))


if __name__ == "__main__":
    main()
