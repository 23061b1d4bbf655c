"""Build generated assets: the character specs and rigged skins in rigs/, and the add-on zips.

    python build.py rigs      # rigs/man.json, rigs/woman.json from rigs/sdfast/*.sd, then
                              # rigs/man.glb, rigs/woman.glb (armature + weighted skin)
    python build.py rigs --no-skin   # only the JSON specs
    python build.py rigs --character child   # rigs/child.glb for a made character (name or .json
                              # path; the .glb goes next to the spec), repeatable
    python build.py addon     # dist/sim_athletics-<version>.zip (legacy add-on, Blender 3.4-4.1)
                              # dist/sim_athletics-<version>-extension.zip (extension, 4.2+)
    python build.py           # both

The skins need scikit-image, trimesh and pygltflib (pip install -e ".[rigs]"). The add-on zips
bundle sim_core, the rigs and the wheels of sim_core's dependencies for Linux x86-64 (fetched
once with ``pip download`` into build/wheels*/ and then reused), so they install offline.
"""
from __future__ import annotations

import argparse
import ast
import json
import os
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent          # on sys.path already: `python build.py` runs from here

THESIS_CHARACTERS = {
    "man": "Wooten 1998, Appendix A.1 (SD/FAST file), Tables 3.1 and 3.3",
    "woman": "Wooten 1998, Appendix A.2 (SD/FAST file), Tables 3.2 and 3.4",
}


def write_atomically(path: Path, text: str) -> None:
    tmp = path.with_suffix(path.suffix + ".tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def build_rigs(skin: bool = True) -> None:
    from sim_core.character.spec import CharacterSpec, build_spec_from_sdfast
    for name, source in THESIS_CHARACTERS.items():
        data = build_spec_from_sdfast(name, ROOT / "rigs" / "sdfast" / f"{name}.sd", source)
        CharacterSpec(data, name)              # validate before writing
        write_atomically(ROOT / "rigs" / f"{name}.json", json.dumps(data, indent=1) + "\n")
        print(f"wrote rigs/{name}.json ({len(data['bodies'])} bodies, {data['total_mass']:.2f} kg)")
        if skin:
            build_skin(CharacterSpec(data, name))


def build_skin(spec, out: Path | None = None) -> None:
    """rigs/<name>.glb (or ``out``): armature + one watertight skin, written only if it passes the
    check (tools.rigbuild.check_rig: each segment's skin mass within 15 %, issue 3)."""
    try:
        from tools.rigbuild import write_checked_rig
    except ImportError as exc:
        raise SystemExit(f"build.py rigs: {exc.name} is missing; pip install -e '.[rigs]' "
                         "(or use --no-skin)") from None
    out = out or ROOT / "rigs" / f"{spec.name}.glb"
    report, failure = write_checked_rig(spec, out)
    worst, error = report.worst_mass_error()
    print(report.table())
    print(f"largest segment mass error: {worst} {100 * error:+.1f} %")
    if failure:
        raise SystemExit(f"{out.name}: skin check failed ({failure}); nothing written")
    print(f"wrote {out} ({report.vertices} vertices, {report.faces} triangles, "
          f"watertight={report.watertight}, mesh volume {1000 * report.mesh_volume:.2f} L vs level set "
          f"{1000 * report.field_volume:.2f} L, {100 * report.rigid_vertices:.0f} % of vertices on one bone)")


def build_character_skins(names: list[str]) -> None:
    """The skins of made characters (``character make`` output): each .glb next to its spec."""
    from sim_core.character.spec import RIGS_DIR, load_character
    for name in names:
        spec = load_character(name)
        path = Path(name) if name.endswith(".json") else RIGS_DIR / f"{name}.json"
        build_skin(spec, path.with_suffix(".glb"))


# ----------------------------------------------------------------------------- add-on zips

ADDON_ID = "sim_athletics"
ADDON_SOURCE = ROOT / "blender_addon"
ADDON_EXCLUDE = {"__pycache__"}         # build-time code lives in tools/, outside the add-on
# Wheels of sim_core's dependencies (and theirs), Linux x86-64, CPython 3.11 (Blender 3.4-5.0).
# scipy 1.15 is the newest that accepts the numpy 1.23 of the legacy bundle; Blender 4.2+ ships
# its own numpy, so the extension bundles everything but numpy.
BUNDLED = ["mujoco==4.0.0", "scipy==1.15.3", "cma==4.5.0"]   # cma: the search service (planning a jump or a landing)
LEGACY_NUMPY = "numpy==1.23.5"     # Blender 3.4's glTF importer still uses numpy.bool (< 1.24)
PLATFORM_TAGS = {"linux-x64": ["manylinux_2_28_x86_64", "manylinux_2_27_x86_64",
                               "manylinux_2_17_x86_64", "manylinux2014_x86_64",
                               "manylinux_2_5_x86_64", "manylinux1_x86_64"]}


def addon_version() -> str:
    tree = ast.parse((ADDON_SOURCE / "__init__.py").read_text())
    for node in tree.body:
        if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "bl_info":
            return ".".join(str(v) for v in ast.literal_eval(node.value)["version"])
    raise SystemExit("blender_addon/__init__.py has no bl_info version")


def fetch_wheels(requirements: list[str], dest: Path, platform: str = "linux-x64") -> list[Path]:
    """``pip download`` the wheels once (cached in ``dest``); returns the wheel files."""
    dest.mkdir(parents=True, exist_ok=True)
    stamp = dest / "requirements.txt"
    wanted = "\n".join(requirements) + "\n"
    if not (stamp.exists() and stamp.read_text() == wanted and list(dest.glob("*.whl"))):
        for old in dest.glob("*.whl"):
            old.unlink()
        cmd = [sys.executable, "-m", "pip", "download", "--quiet", "--only-binary=:all:",
               "--python-version", "3.11", "--implementation", "cp", "--abi", "cp311",
               "-d", str(dest), *requirements]
        for tag in PLATFORM_TAGS[platform]:
            cmd += ["--platform", tag]
        subprocess.run(cmd, check=True)
        stamp.write_text(wanted)
    return sorted(dest.glob("*.whl"))


def stage_addon(stage: Path) -> None:
    """<stage>/: the add-on's modules, with sim_core as its own subpackage (<stage>/sim_core,
    imported relatively: nothing goes on sys.path) carrying the rigs (specs + skins) and their
    tuned tables in sim_core/rigs/, where sim_core.resources finds them."""
    if stage.exists():
        shutil.rmtree(stage)
    ignore = shutil.ignore_patterns("__pycache__", "*.pyc", "*.tmp")
    shutil.copytree(ADDON_SOURCE, stage, ignore=lambda d, names: [n for n in names if n in ADDON_EXCLUDE]
                    + list(ignore(d, names)))
    shutil.copytree(ROOT / "sim_core", stage / "sim_core", ignore=ignore)
    rigs = stage / "sim_core" / "rigs"
    if rigs.exists():
        shutil.rmtree(rigs)
    rigs.mkdir(parents=True)
    for name in THESIS_CHARACTERS:
        for suffix in (".json", ".glb"):
            src = ROOT / "rigs" / f"{name}{suffix}"
            if not src.exists():
                raise SystemExit(f"{src.relative_to(ROOT)} is missing; run 'python build.py rigs' first")
            shutil.copy2(src, rigs / src.name)
    for skin in sorted((ROOT / "rigs").glob("*.glb")):      # made characters with a built skin
        if skin.stem not in THESIS_CHARACTERS and skin.with_suffix(".json").exists():
            for src in (skin.with_suffix(".json"), skin):
                shutil.copy2(src, rigs / src.name)
    if (ROOT / "rigs" / "tuned").is_dir():
        shutil.copytree(ROOT / "rigs" / "tuned", rigs / "tuned", ignore=ignore)


def zip_tree(root: Path, out: Path, prefix: str = "") -> None:
    """Write ``out`` atomically from the files under ``root`` (with ``prefix`` in the archive)."""
    tmp = out.with_suffix(".zip.tmp")
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED, compresslevel=6) as zf:
        for path in sorted(root.rglob("*")):
            if path.is_file():
                zf.write(path, prefix + path.relative_to(root).as_posix())
    os.replace(tmp, out)


def manifest(version: str, wheels: list[str]) -> str:
    listed = ",\n".join(f'  "./wheels/{w}"' for w in wheels)
    return f"""schema_version = "1.0.0"
id = "{ADDON_ID}"
version = "{version}"
name = "Sim Athletics"
tagline = "Physics-simulated athletes baked into actions on a skinned rig"
maintainer = "Sim Athletics"
type = "add-on"
blender_version_min = "4.2.0"
license = ["SPDX:GPL-3.0-or-later"]
platforms = ["linux-x64"]
wheels = [
{listed}
]

[permissions]
files = "Read the bundled character rigs"
"""


def build_addon() -> list[Path]:
    version = addon_version()
    dist = ROOT / "dist"
    dist.mkdir(exist_ok=True)
    wheels = fetch_wheels(BUNDLED, ROOT / "build" / "wheels")
    legacy_wheels = fetch_wheels(BUNDLED + [LEGACY_NUMPY], ROOT / "build" / "wheels-legacy")

    # legacy add-on (Blender 3.4-4.1): sim_athletics/ with the wheels unpacked into vendor/, which
    # the add-on appends to sys.path (after Blender's own packages: core/vendor.py)
    stage = ROOT / "build" / "legacy" / ADDON_ID
    stage_addon(stage)
    for wheel in legacy_wheels:
        with zipfile.ZipFile(wheel) as zf:
            zf.extractall(stage / "vendor")
    legacy = dist / f"{ADDON_ID}-{version}.zip"
    zip_tree(stage, legacy, prefix=f"{ADDON_ID}/")

    # extension (Blender 4.2+): manifest at the archive root, wheels installed by Blender
    stage = ROOT / "build" / "extension"
    stage_addon(stage)
    (stage / "wheels").mkdir()
    names = []
    for wheel in wheels:
        if wheel.name.startswith("numpy-"):
            continue
        shutil.copy2(wheel, stage / "wheels" / wheel.name)
        names.append(wheel.name)
    (stage / "blender_manifest.toml").write_text(manifest(version, names))
    extension = dist / f"{ADDON_ID}-{version}-extension.zip"
    zip_tree(stage, extension)
    for out in (legacy, extension):
        print(f"wrote {out.relative_to(ROOT)} ({out.stat().st_size / 1e6:.1f} MB)")
    return [legacy, extension]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("target", nargs="?", default="all", choices=["rigs", "addon", "all"])
    parser.add_argument("--no-skin", action="store_true", help="rigs: write only the JSON specs")
    parser.add_argument("--character", action="append", metavar="NAME_OR_JSON",
                        help="rigs: only the skin of this made character (repeatable), next to its spec")
    args = parser.parse_args(argv)
    if args.character:
        if args.target != "rigs" or args.no_skin:
            parser.error("--character builds a skin: use it with 'rigs' and without --no-skin")
        build_character_skins(args.character)
    elif args.target in ("rigs", "all"):
        build_rigs(skin=not args.no_skin)
    if args.target in ("addon", "all"):
        build_addon()
    return 0


if __name__ == "__main__":
    sys.exit(main())
