"""Benchmark: bake 10 s at 60 fps onto the man (601 frames x 22 bones) three ways, same run:

  bulk    the add-on's path: NumPy channels + keyframe_points.add + foreach_set per F-curve
  insert  a loop that sets each pose bone and calls keyframe_insert, frame by frame
  nla     Blender's own Bake Action (bpy.ops.nla.bake) from the same poses (the bulk action)

    python -m tools.bench_bake                    # from the repository root, Blender as a Python module
    PYTHONPATH=. blender -b -P tools/bench_bake.py     # a Blender binary that has mujoco & scipy

(Build-time tooling: not part of the shipped add-on.)

Prints each time and the ratios to the bulk path (goal: insert / bulk >= 20); the simulation
itself is not timed. Every method's keys are checked against the bulk keys.
"""
from __future__ import annotations

import time

DURATION, FPS = 10.0, 60


def main() -> None:
    import bpy
    import numpy as np
    import blender_addon as pkg
    from blender_addon import api, bake, compat
    from sim_core.simulate import RunRequest, run

    bpy.ops.wm.read_homefile(use_empty=True)
    if "sim_athletics" not in bpy.types.Scene.bl_rna.properties:
        pkg.register()
    context = bpy.context
    scene = context.scene
    scene.render.fps, scene.render.fps_base = FPS, 1.0
    arm = api.add_character(context, "man")
    trajectory = run(RunRequest("balance", "man", duration=DURATION,
                                params=dict(pelvis_height=0.6, move_start=1.0, move_time=2.0, hold_time=3.0)))

    def fresh():
        if arm.animation_data:
            arm.animation_data.action = None
            for track in list(arm.animation_data.nla_tracks):
                arm.animation_data.nla_tracks.remove(track)

    # 1. bulk: median of 5 (it is short enough for timer noise to matter)
    runs = []
    for attempt in range(5):
        fresh()
        if attempt:
            bpy.data.actions.remove(bulk)
        t0 = time.perf_counter()
        ch = bake.channels_for(arm, trajectory, FPS, 1)
        t1 = time.perf_counter()
        bulk = bake.write_action(arm, ch, "bench bulk", {"bench": "bulk"})
        runs.append((time.perf_counter() - t0, t1 - t0))
    t_bulk, t_math = sorted(runs)[len(runs) // 2]
    n_frames, n_bones = len(ch.frames), len(ch.names)

    # 2. keyframe_insert loop (same values)
    fresh()
    bones = [arm.pose.bones[n] for n in ch.names]
    root = bones[0]
    t0 = time.perf_counter()
    for k, frame in enumerate(ch.frames):
        root.location = ch.root_location[k]
        root.keyframe_insert("location", frame=frame)
        for b, pb in enumerate(bones):
            pb.rotation_quaternion = ch.rotations[k, b]
            pb.keyframe_insert("rotation_quaternion", frame=frame)
    t_insert = time.perf_counter() - t0
    inserted = arm.animation_data.action

    # 3. Blender's Bake Action, sampling the bulk action's poses
    fresh()
    arm.animation_data.action = bulk
    for o in context.view_layer.objects:
        o.select_set(o == arm)
    context.view_layer.objects.active = arm
    bpy.ops.object.mode_set(mode="POSE")
    for pb in arm.pose.bones:
        (pb.bone if hasattr(pb.bone, "select") else pb).select = True
    t0 = time.perf_counter()
    bpy.ops.nla.bake(frame_start=int(ch.frames[0]), frame_end=int(ch.frames[-1]), only_selected=False,
                     visual_keying=True, use_current_action=False, bake_types={"POSE"})
    t_nla = time.perf_counter() - t0
    bpy.ops.object.mode_set(mode="OBJECT")
    baked = arm.animation_data.action

    def keys(action):
        out = {}
        for fc in compat.action_fcurves(action):
            co = np.empty(2 * len(fc.keyframe_points), dtype=np.float32)
            fc.keyframe_points.foreach_get("co", co)
            out[(fc.data_path, fc.array_index)] = co[1::2]
        return out

    reference = keys(bulk)
    for label, action in (("insert", inserted), ("nla", baked)):
        other = keys(action)
        worst = max(float(np.max(np.abs(reference[k] - other[k]))) for k in reference if k in other)
        missing = [k for k in reference if k not in other]
        print(f"check {label}: {len(other)} curves, largest difference to bulk {worst:.2e}"
              + (f", {len(missing)} bulk curves not keyed" if missing else ""))

    print(f"Blender {bpy.app.version_string}: {DURATION:g} s at {FPS} fps onto the man = "
          f"{n_frames} frames x {n_bones} bones ({len(reference)} F-curves, {n_frames * len(reference)} keys)")
    print(f"bulk (foreach_set)     {1000 * t_bulk:9.1f} ms   median of 5 (of which NumPy channels {1000 * t_math:.1f} ms)")
    print(f"keyframe_insert loop   {1000 * t_insert:9.1f} ms   ratio {t_insert / t_bulk:6.1f}x bulk")
    print(f"bpy.ops.nla.bake       {1000 * t_nla:9.1f} ms   ratio {t_nla / t_bulk:6.1f}x bulk")


if __name__ == "__main__":
    main()
