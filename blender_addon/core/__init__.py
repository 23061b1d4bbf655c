"""The add-on's bpy-free core (glTF-Blender-IO's ``io/`` beside ``blender/``): axes, rig frames,
bake math, jobs, value conversions and the look-up of sim_core and the vendored wheels. Nothing
here imports bpy, so it is tested without Blender (tests/addon/test_core.py, test_bake_math.py)."""
