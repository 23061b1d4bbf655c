"""The man and the woman as data and as MuJoCo models, checked against Wooten's tables."""
import json
import math

import mujoco
import numpy as np
import pytest

from sim_core.character.model import compile_model, set_standing_pose
from sim_core.character.sdfast import parse_sdfast
from sim_core.character.spec import RIGS_DIR, CharacterSpec, load_character
from sim_core.errors import RigFileError, UnknownNameError

# Wooten 1998, Tables 3.3 and 3.4: joint world positions (m) in the reference configuration;
# one entry per joint, the left side is +Y (the right side is checked mirrored).
TABLE_3_3_MAN = {
    "NECKC2": (0.013, 0.000, 1.555), "SPINET4": (-0.012, 0.000, 1.400), "SPINET7": (-0.002, 0.000, 1.304),
    "SPINEL1": (-0.001, 0.000, 1.180), "SPINEL3": (0.001, 0.000, 1.079), "HIP": (-0.019, 0.082, 0.937),
    "KNEE": (-0.020, 0.096, 0.524), "ANKLE": (-0.054, 0.088, 0.084), "MT": (0.049, 0.110, 0.022),
    "CLAV": (0.003, 0.035, 1.483), "SHLD": (-0.001, 0.182, 1.483), "ELB": (0.016, 0.456, 1.475),
    "WRST": (0.119, 0.758, 1.474),
}
TABLE_3_4_WOMAN = {
    "NECKC2": (-0.062, 0.000, 1.394), "SPINET4": (-0.035, 0.000, 1.201), "SPINET7": (-0.031, 0.000, 1.111),
    # L3: the scan prints 0.016; Appendix A.2 gives -0.016 (the OCR drops minus signs, see seeds/README)
    "SPINEL1": (-0.022, 0.000, 1.027), "SPINEL3": (-0.016, 0.000, 0.962), "HIP": (-0.038, 0.077, 0.836),
    "KNEE": (-0.027, 0.078, 0.401), "ANKLE": (-0.039, 0.088, 0.082), "MT": (0.043, 0.094, 0.015),
    "CLAV": (-0.035, 0.023, 1.300), "SHLD": (-0.066, 0.171, 1.287), "ELB": (-0.036, 0.450, 1.244),
    "WRST": (0.038, 0.666, 1.220),
}
TABLES = {"man": TABLE_3_3_MAN, "woman": TABLE_3_4_WOMAN}
# Table 3.1 caption: 97.84 kg. Table 3.2 caption says 55.24 kg, but its own segment masses (and
# Appendix A.2) add up to 53.30 kg: the caption disagrees with the thesis's data; we keep the data.
TOTAL_MASS = {"man": 97.84, "woman": 53.30}


def joint_world_positions(character):
    model, _ = compile_model(character)
    data = mujoco.MjData(model)
    mujoco.mj_resetData(model, data)
    data.qpos[:3] = character.bodies[0]["com"]
    data.qpos[3:7] = [1, 0, 0, 0]
    mujoco.mj_kinematics(model, data)
    positions = {}
    for b in character.bodies[1:]:
        positions[b["joint"]["sdfast_name"]] = data.xpos[model.body(b["name"]).id].copy()
    return model, data, positions


@pytest.mark.parametrize("name", ["man", "woman"])
def test_mass_and_segments(name):
    spec = load_character(name)
    assert len(spec.bodies) == 22                     # 20 segments + 2 toes (SD/FAST files)
    assert len(spec.dofs) == 47                       # 47 internal rotational DOF
    assert spec.total_mass == pytest.approx(TOTAL_MASS[name], abs=0.1)
    model, _ = compile_model(spec)
    assert model.body_subtreemass[1] == pytest.approx(TOTAL_MASS[name], abs=0.1)
    assert model.nq == 7 + 47 and model.nv == 6 + 47


@pytest.mark.parametrize("name", ["man", "woman"])
def test_joint_positions_match_tables(name):
    spec = load_character(name)
    _, _, positions = joint_world_positions(spec)
    checked = 0
    for sd_name, pos in positions.items():
        key = sd_name
        if sd_name[-1] in "RL" and sd_name not in TABLES[name]:
            key = sd_name[:-1]
        expected = np.array(TABLES[name][key])
        if sd_name.endswith("R") and key != sd_name:
            expected[1] = -expected[1]
        assert np.abs(pos - expected).max() < 0.003, (sd_name, pos, expected)
        checked += 1
    assert checked == 21


@pytest.mark.parametrize("name", ["man", "woman"])
def test_centres_of_mass_as_in_appendix_a(name):
    spec = load_character(name)
    model, data, _ = joint_world_positions(spec)
    for b in parse_sdfast(RIGS_DIR / "sdfast" / f"{name}.sd"):
        # the model runs from its MJCF text, whose numbers keep 6 significant digits: the rounding
        # adds up along the chain to ~1 micron
        assert np.abs(data.xipos[model.body(b.name).id] - b.original_com).max() < 5e-6


@pytest.mark.parametrize("name", ["man", "woman"])
def test_joint_types_and_axes(name):
    spec = load_character(name)
    counts = {"gimbal": 3, "ujoint": 2, "pin": 1, "ball": 3}
    for b in spec.bodies[1:]:
        joint = b["joint"]
        assert len(joint["dofs"]) == counts[joint["type"]]
    hip = spec.body("ULEGR")["joint"]
    assert [d["name"] for d in hip["dofs"]] == ["hip_r_y", "hip_r_x", "hip_r_z"]   # SD/FAST pin order


def test_no_actuator_on_the_root():
    model, _ = compile_model(load_character("man"))
    root = model.joint("root").id
    assert model.jnt_type[root] == mujoco.mjtJoint.mjJNT_FREE
    assert all(model.actuator_trnid[i, 0] != root for i in range(model.nu))
    assert all(model.jnt_type[model.actuator_trnid[i, 0]] == mujoco.mjtJoint.mjJNT_HINGE for i in range(model.nu))
    assert model.nu == 47


def test_standing_pose_feet_on_ground():
    spec = load_character("man")
    model, _ = compile_model(spec)
    data = mujoco.MjData(model)
    set_standing_pose(model, data, spec)
    mujoco.mj_forward(model, data)
    heights = [data.site_xpos[i, 2] for i in range(model.nsite) if model.site(i).name.startswith(("FOOT", "TOE"))]
    assert len(heights) == 12 and max(abs(h) for h in heights) < 1e-6
    hands = [data.xpos[model.body(n).id, 2] for n in ("HANDR", "HANDL")]
    assert max(hands) < 1.0                     # arms hang at the sides, not the T-pose


def test_strength_settings():
    spec = load_character("man")
    human, _ = compile_model(spec, strength="human")
    strong, _ = compile_model(spec, strength=2.0)
    unlimited, _ = compile_model(spec, strength="unlimited")
    knee = human.actuator("knee_r_y").id
    assert human.actuator_forcerange[knee, 1] == pytest.approx(300.0)
    assert strong.actuator_forcerange[knee, 1] == pytest.approx(600.0)
    assert not unlimited.actuator_forcelimited[knee]


def test_malformed_rig_files(tmp_path):
    good = json.loads((RIGS_DIR / "man.json").read_text())
    broken = tmp_path / "broken.json"
    broken.write_text("{not json")
    with pytest.raises(RigFileError, match="not valid JSON"):
        load_character(str(broken))
    bad_mass = json.loads(json.dumps(good))
    bad_mass["bodies"][3]["mass"] = -1.0
    with pytest.raises(RigFileError, match="mass -1.0 must be a finite number > 0"):
        CharacterSpec(bad_mass, "bad_mass.json")
    bad_parent = json.loads(json.dumps(good))
    bad_parent["bodies"][2]["parent"] = "NOSUCH"
    with pytest.raises(RigFileError, match="parent 'NOSUCH'"):
        CharacterSpec(bad_parent, "bad_parent.json")
    with pytest.raises(RigFileError, match="not a Sim Athletics character spec"):
        CharacterSpec({"bodies": []}, "empty.json")
    with pytest.raises(UnknownNameError, match="unknown character 'robot'"):
        load_character("robot")


def test_sdfast_parser_rejects_garbage(tmp_path):
    sd = tmp_path / "x.sd"
    sd.write_text("# original center of mass = 0, 0, 1\nbody = A\nmass = 2\ninertia = 1 1\n")
    with pytest.raises(RigFileError, match="expected 3 numbers"):
        parse_sdfast(sd)


def _same_spec(fresh, stored, where: str = "") -> list[str]:
    """Where two specs differ: every string, key and length exactly, every number to 1e-12 of its size
    (NumPy builds may round a square root or a power differently in the last bit: after a reinstall of
    the test dependencies, NumPy 1.26.4, the woman's right shank's capsule radius came out one ulp apart)."""
    if isinstance(fresh, dict) and isinstance(stored, dict):
        if set(fresh) != set(stored):
            return [f"{where}: keys {sorted(set(fresh) ^ set(stored))}"]
        return [d for k in fresh for d in _same_spec(fresh[k], stored[k], f"{where}/{k}")]
    if isinstance(fresh, list) and isinstance(stored, list):
        if len(fresh) != len(stored):
            return [f"{where}: {len(fresh)} items against {len(stored)}"]
        return [d for k, (a, b) in enumerate(zip(fresh, stored)) for d in _same_spec(a, b, f"{where}[{k}]")]
    if isinstance(fresh, (int, float)) and isinstance(stored, (int, float)) and not isinstance(fresh, bool):
        return [] if math.isclose(fresh, stored, rel_tol=1e-12, abs_tol=1e-15) else [f"{where}: {fresh!r} != {stored!r}"]
    return [] if fresh == stored else [f"{where}: {fresh!r} != {stored!r}"]


def test_rig_json_is_up_to_date():
    """rigs/*.json are generated by build.py; a hand edit or stale file shows here (numbers compared to
    1e-12 of their size: _same_spec)."""
    from sim_core.character.spec import build_spec_from_sdfast
    import build
    for name, source in build.THESIS_CHARACTERS.items():
        fresh = build_spec_from_sdfast(name, RIGS_DIR / "sdfast" / f"{name}.sd", source)
        stored = json.loads((RIGS_DIR / f"{name}.json").read_text())
        differences = _same_spec(json.loads(json.dumps(fresh)), stored)
        assert not differences, f"run: python build.py rigs ({name}): {differences[:5]}"
