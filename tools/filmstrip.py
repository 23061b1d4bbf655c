"""Filmstrip of a baked skill, like the thesis's figures: simulate, bake onto the rigged skin,
render frames at fixed intervals headless (Cycles on the CPU) and lay them side by side.

    tools/filmstrip.py leap --set height=0.35 --frames 8 --out docs/leap_filmstrip.png

Needs the bpy module (pip install -e ".[test]")."""
from __future__ import annotations

import argparse
import math
import sys
import tempfile
from pathlib import Path

ROOT = Path.cwd()                   # docs are written under the folder it runs in (the checkout)
APPARATUS_COLOURS = {"springboard": (0.85, 0.55, 0.25), "vault_table": (0.35, 0.18, 0.10),
                     "landing_mat": (0.15, 0.30, 0.75)}     # so they stand out from the grey floor


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("behaviour")
    parser.add_argument("--character", default="man")
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE")
    parser.add_argument("--duration", type=float, default=None)
    parser.add_argument("--strength", choices=("human", "unlimited"), default="human", help="joint torque limits")
    parser.add_argument("--frames", type=int, default=8, help="pictures in the strip")
    parser.add_argument("--start", type=float, default=0.0, help="first picture at this time (s)")
    parser.add_argument("--end", type=float, default=None, help="last picture at this time (s)")
    parser.add_argument("--times", default=None, metavar="T,T,...",
                        help="the pictures at these times (s) instead of --frames evenly from --start to --end")
    parser.add_argument("--size", type=int, default=260, help="height of one picture in pixels")
    parser.add_argument("--follow", nargs="?", const="com", choices=("com", "path"), default=None,
                        help="the camera follows the COM (dives: the body falls 10 m); --follow path: only "
                             "along the path, at a fixed height (a vault: the apparatus stays put); default: fixed")
    parser.add_argument("--view", choices=("side", "front"), default="side",
                        help="side: looking across the path (default); front: from ahead of the character, "
                             "looking back at it (a sideways jump)")
    parser.add_argument("--camera-height", type=float, default=1.0, help="the camera's height (m) unless it follows the COM")
    parser.add_argument("--lens", type=float, default=50.0, help="the camera's focal length (mm); shorter sees more")
    parser.add_argument("--out", required=True)
    args = parser.parse_args(argv)
    try:
        chosen = None if args.times is None else [float(t) for t in args.times.split(",")]
    except ValueError:
        parser.error(f"--times {args.times!r} is not a list of times in seconds, e.g. 0,0.25,1.5")

    import bpy
    import numpy as np
    from PIL import Image

    from blender_addon import api

    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps = 30
    params = dict(item.split("=", 1) for item in args.set)
    rig = api.add_character(bpy.context, args.character)
    action, trajectory = api.simulate_and_bake(bpy.context, behaviour=args.behaviour, params=params,
                                               duration=args.duration, strength=args.strength)
    last = trajectory.arrays["time"][-1]
    end = last if args.end is None else min(args.end, last)
    if chosen is not None:
        times = chosen
        bad = [t for t in times if not 0.0 <= t <= last]
        if bad:
            parser.error(f"--times {bad[0]:g} s is outside the run; allowed range is [0, {last:g}] s")
        args.frames, args.start, end = len(times), times[0], times[-1]
    else:
        times = [args.start + (end - args.start) * k / max(args.frames - 1, 1) for k in range(args.frames)]

    _colour_apparatus(bpy)
    # ground, light, a side camera looking at the character's path (the sim's X is Blender's -Y)
    world = trajectory.meta.get("world", {})
    if not world.get("platform"):     # a dive brings its platform and water
        bpy.ops.mesh.primitive_plane_add(size=40, location=(0.0, 0.0, float(world.get("floor", 0.0) or 0.0)))
    sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", type="SUN"))
    sun.data.energy = 3.0
    sun.rotation_euler = (math.radians(50), 0, math.radians(30))
    scene.collection.objects.link(sun)
    travel = trajectory.arrays["com"][-1, :2] - trajectory.arrays["com"][0, :2]
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    if args.view == "front":       # ahead of the character (sim +X = Blender -Y), looking back along +Y
        camera.location = (float(travel[1]) / 2, -4.2, args.camera_height)
        camera.rotation_euler = (math.radians(90), 0, 0)
    else:
        camera.location = (4.2, -float(travel[0]) / 2, args.camera_height)
        camera.rotation_euler = (math.radians(90), 0, math.radians(90))
    camera.data.lens = args.lens
    scene.collection.objects.link(camera)
    scene.camera = camera
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 16
    scene.render.resolution_x = int(args.size * 0.6)
    scene.render.resolution_y = args.size
    scene.world = bpy.data.worlds.new("world")
    scene.world.use_nodes = True
    scene.world.node_tree.nodes["Background"].inputs[0].default_value = (0.75, 0.78, 0.85, 1.0)

    pictures = []
    with tempfile.TemporaryDirectory() as tmp:
        com = trajectory.arrays["com"]
        sim_time = trajectory.arrays["time"]
        for k, t in enumerate(times):
            scene.frame_set(scene.frame_start + int(round(t * scene.render.fps)))
            if args.follow:          # sim (x, y, z) -> Blender (y, -x, z)
                c = com[min(int(np.searchsorted(sim_time, t)), len(com) - 1)]
                height = float(c[2]) if args.follow == "com" else camera.location[2]
                camera.location = ((float(c[1]), -4.2, height) if args.view == "front"
                                   else (4.2, -float(c[0]), height))
            scene.render.filepath = str(Path(tmp) / f"f{k:02d}.png")
            bpy.ops.render.render(write_still=True)
            pictures.append(Image.open(scene.render.filepath).convert("RGB"))
        width = sum(p.width for p in pictures)
        strip = Image.new("RGB", (width, pictures[0].height), "white")
        x = 0
        for picture in pictures:
            strip.paste(picture, (x, 0))
            x += picture.width
        Path(args.out).parent.mkdir(parents=True, exist_ok=True)
        strip.save(args.out)
    print(f"wrote {args.out}: {args.frames} frames from {args.start:.2f} to {end:.2f} s, outcome "
          f"{trajectory.meta['outcome']}")
    del rig, action
    return 0


def _colour_apparatus(bpy) -> None:
    """The vaulting apparatus's scenery objects (if any) in their own colours."""
    from blender_addon.scenery import APPARATUS_NAMES
    for geom, colour in APPARATUS_COLOURS.items():
        obj = bpy.data.objects.get(APPARATUS_NAMES[geom])
        if obj is None:
            continue
        material = bpy.data.materials.new(f"filmstrip {geom}")
        material.use_nodes = True
        material.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (*colour, 1.0)
        obj.data.materials.append(material)


if __name__ == "__main__":
    sys.exit(main())
