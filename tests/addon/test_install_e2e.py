"""End to end: `python build.py addon`, install the zips offline into a real Blender, run the
documented batch command, open the saved .blend and check the bake.

* legacy zip -> Debian's `blender` 3.4 binary (skipped only where that binary is missing);
* extension zip -> Blender 5.0 as a Python module (the extension installer validates the
  manifest and installs the bundled wheels).
Each Blender runs with temporary user folders, and without PYTHONPATH, so only what the zip
brought is used. sim_core is the add-on's own subpackage: no top-level ``sim_core`` is importable,
and the legacy add-on's vendored wheels come after Blender's own packages on sys.path.
"""
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BLENDER = shutil.which("blender") or "/usr/bin/blender"
KNEE_BEND = ["--set", "pelvis_height=0.52", "--set", "move_start=0.3", "--set", "move_time=1.2",
             "--set", "hold_time=0.5"]
DURATION, FPS = 4.0, 25
CHECK = """
import bpy, json, sys
arm = next(o for o in bpy.data.objects if o.type == 'ARMATURE')
action = arm.animation_data.action
curves = list(action.fcurves) if hasattr(action, 'fcurves') else [
    fc for layer in action.layers for strip in layer.strips for bag in strip.channelbags for fc in bag.fcurves]
keys = sorted({round(p.co[0], 3) for fc in curves for p in fc.keyframe_points})
print('CHECK ' + json.dumps({
    'character': arm.get('sim_athletics_character'), 'action': action.name,
    'curves': len(curves), 'keys_per_curve': sorted({len(fc.keyframe_points) for fc in curves}),
    'frames': keys, 'frame_start': bpy.context.scene.frame_start, 'frame_end': bpy.context.scene.frame_end,
    'info': json.loads(action['sim_athletics']),
    'skin_modifier': [m.type for o in bpy.data.objects if o.type == 'MESH' for m in o.modifiers]}))
"""


def clean_env(**extra) -> dict:
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    env.update(extra)
    return env


@pytest.fixture(scope="module")
def zips():
    subprocess.run([sys.executable, "build.py", "addon"], cwd=ROOT, check=True)
    import build                     # the repository root is on sys.path (pytest's pythonpath option)
    version = build.addon_version()
    return ROOT / "dist" / f"sim_athletics-{version}.zip", ROOT / "dist" / f"sim_athletics-{version}-extension.zip"


def parse_check(stdout: str) -> dict:
    line = next(l for l in stdout.splitlines() if l.startswith("CHECK "))
    return json.loads(line[len("CHECK "):])


def assert_baked(result: dict) -> None:
    frames = int(round(DURATION * FPS)) + 1
    assert result["character"] == "man"
    assert result["curves"] == 3 + 4 * 22
    assert result["keys_per_curve"] == [frames]
    assert result["frames"] == [float(f) for f in range(1, frames + 1)]           # a key on every frame
    assert (result["frame_start"], result["frame_end"]) == (1, frames)
    assert result["info"]["outcome"] == "success"
    assert result["info"]["params"]["pelvis_height"] == 0.52
    assert result["skin_modifier"] == ["ARMATURE"]


LAYOUT = """
import importlib.util, json, sys, addon_utils
addon_utils.enable('sim_athletics', default_set=True)
import sim_athletics.sim_core.simulate as simulate
vendor = [i for i, p in enumerate(sys.path) if p.endswith('sim_athletics/vendor')]
own = [i for i, p in enumerate(sys.path) if p.startswith(sys.prefix) or 'blender/scripts' in p]
print('CHECK ' + json.dumps({'sim_core': simulate.__file__,
                             'top_level_sim_core': importlib.util.find_spec('sim_core') is not None,
                             'vendor_after_blender': bool(vendor) and vendor[0] > max(own)}))
"""


@pytest.mark.slow
def test_legacy_zip_in_blender_3_4_batch_bakes_and_saves(zips, tmp_path):
    if not Path(BLENDER).exists():
        pytest.skip("Debian's blender binary is not installed (apt-get install blender)")
    legacy, _ = zips
    env = clean_env(BLENDER_USER_SCRIPTS=str(tmp_path / "scripts"), BLENDER_USER_CONFIG=str(tmp_path / "config"))
    install = subprocess.run(
        [BLENDER, "-b", "--factory-startup", "--python-exit-code", "1", "--python-expr",
         f"import bpy; bpy.ops.preferences.addon_install(filepath={str(legacy)!r})"],
        env=env, capture_output=True, text=True, timeout=300)
    assert install.returncode == 0, install.stderr[-2000:]
    batch = tmp_path / "scripts" / "addons" / "sim_athletics" / "batch.py"
    assert batch.exists()

    out = tmp_path / "out" / "balance.blend"
    run = subprocess.run(
        [BLENDER, "-b", "--factory-startup", "-P", str(batch), "--", "--character", "man", "--behaviour", "balance",
         *KNEE_BEND, "--duration", str(DURATION), "--fps", str(FPS), "--out", str(out), "--require-success"],
        env=env, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    assert "outcome success" in run.stdout

    check = subprocess.run([BLENDER, "-b", "--factory-startup", str(out), "--python-exit-code", "1",
                            "--python-expr", CHECK], env=env, capture_output=True, text=True, timeout=300)
    assert check.returncode == 0, check.stderr[-2000:]
    assert_baked(parse_check(check.stdout))

    layout = subprocess.run(
        [BLENDER, "-b", "--factory-startup", "--python-exit-code", "1", "--python-expr", LAYOUT],
        env=env, capture_output=True, text=True, timeout=300)
    assert layout.returncode == 0, layout.stdout[-2000:] + layout.stderr[-2000:]
    found = parse_check(layout.stdout)
    assert found["sim_core"].startswith(str(tmp_path / "scripts" / "addons" / "sim_athletics" / "sim_core"))
    assert not found["top_level_sim_core"]
    assert found["vendor_after_blender"]

    bad = subprocess.run(
        [BLENDER, "-b", "--factory-startup", "-P", str(batch), "--", "--behaviour", "balance",
         "--set", "pelvis_height=5", "--out", str(tmp_path / "bad.blend")],
        env=env, capture_output=True, text=True, timeout=300)
    assert bad.returncode == 2
    errors = [l for l in bad.stderr.splitlines() if l.startswith("sim_athletics: error:")]
    assert errors == ["sim_athletics: error: parameter pelvis_height=5 m is out of range; allowed range "
                      "for pelvis_height is [0.2, 1.2] m (or 0: 0 = standing height)"]
    assert not (tmp_path / "bad.blend").exists()


@pytest.mark.slow
def test_extension_zip_installs_offline_in_blender_5_and_bakes(zips, tmp_path):
    pytest.importorskip("bpy")
    _, extension = zips
    out = tmp_path / "balance.blend"
    script = f"""
import bpy, sys
bpy.ops.extensions.package_install_files(filepath={str(extension)!r}, repo='user_default', enable_on_install=True)
from bl_ext.user_default.sim_athletics import batch
from bl_ext.user_default.sim_athletics import sim_core
assert sim_core.__file__.startswith({str(tmp_path)!r}), sim_core.__file__
from bl_ext.user_default.sim_athletics.core.simcore import SIM_CORE
assert SIM_CORE == 'bl_ext.user_default.sim_athletics.sim_core', SIM_CORE
code = batch.run(['--character', 'man', '--behaviour', 'balance', *{KNEE_BEND!r}, '--duration', '{DURATION}',
                  '--fps', '{FPS}', '--out', {str(out)!r}])
assert 'sim_core' not in sys.modules, 'the add-on imported a top-level sim_core'
bpy.ops.wm.open_mainfile(filepath={str(out)!r})
exec({CHECK!r})
sys.exit(code)
"""
    run = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, capture_output=True, text=True,
                         env=clean_env(BLENDER_USER_RESOURCES=str(tmp_path / "resources")), timeout=600)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    site = tmp_path / "resources" / "extensions" / ".local" / "lib" / "python3.11" / "site-packages"
    assert (site / "mujoco").is_dir() and (site / "scipy").is_dir()     # the bundled wheels
    assert_baked(parse_check(run.stdout))
