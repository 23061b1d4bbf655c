"""The tuned-table store (sim_core/tuned) and a calibration's bookkeeping (sim_core/control/tuned.py):
every stored table loads and round-trips byte for byte, a bad table is refused in one line naming
the bad value, a save is whole or nothing, and no tuned number hides in a control module."""
import argparse
import ast
import json
import re
import shutil
from pathlib import Path

import pytest

from sim_core import tuned
from sim_core.skills import available_behaviours, behaviour_class
from sim_core.control.tuned import merge_search, names_option
from sim_core.tuned import TableError, store

KEY = {"direction": "backward", "strength": "human"}
OTHER = {"direction": "forward", "strength": "human", "settings": {"a": 1}}
SIM_CORE = Path(__file__).resolve().parents[1] / "sim_core"


def driving_modules() -> list[Path]:
    """The modules that drive a run: the basis controllers and each skill's behaviour code (not
    its calibration, report or experiments, whose numbers are search settings and protocols)."""
    skills = [p for p in sorted((SIM_CORE / "skills").glob("*/*.py"))
              if p.stem not in ("report", "experiments", "__init__") and not p.stem.startswith("calibrate")]
    return sorted((SIM_CORE / "control").glob("*.py")) + skills


def stored_tables() -> list[tuple[str, str]]:
    available_behaviours()                       # every skill's module imported: their row types declared
    # (skill, character) from each file's header: a name split at its last "_" would cut
    # running_imaginary_runner into the skill "running_imaginary"
    tables = [json.loads(p.read_text()) for p in sorted(store.DIRECTORY.glob("*.json"))]
    return [(t["skill"], t["character"]) for t in tables]


@pytest.fixture
def tables(tmp_path, monkeypatch):
    """The store pointed at a copy of the package's tables."""
    shutil.copytree(store.DIRECTORY, tmp_path, dirs_exist_ok=True)
    monkeypatch.setattr(store, "DIRECTORY", tmp_path)
    return tmp_path


# ------------------------------------------------------------------ the store
def test_every_stored_table_loads_and_round_trips_byte_for_byte(tmp_path, monkeypatch):
    """Loading checks every row against its skill's settings schema; saving what was loaded writes
    the very bytes (JSON floats round-trip exactly: every stored row reproduces)."""
    names = stored_tables()
    assert {"leap", "landing", "dives", "somersaults", "handspring", "jump_targets", "running"} <= {s for s, _ in names}
    originals = {(s, c): tuned.table_path(s, c).read_bytes() for s, c in names}
    monkeypatch.setattr(store, "DIRECTORY", tmp_path)
    for (skill, character), text in originals.items():
        header = json.loads(text)
        (tmp_path / f"{skill}_{character}.json").write_bytes(text)
        body = tuned.load(skill, character)
        tuned.save(skill, character, body, strengths=header["strengths"])
        assert (tmp_path / f"{skill}_{character}.json").read_bytes() == text, f"{skill}_{character}"
    assert not list(tmp_path.glob("*.tmp"))


def _write(directory: Path, name: str, data: dict) -> None:
    (directory / name).write_text(json.dumps(data))


def refusal(directory: Path, skill: str, character: str, change) -> str:
    """The one-line refusal of loading the stored table after ``change(data)`` edited it on disk."""
    path = directory / f"{skill}_{character}.json"
    data = json.loads(path.read_text())
    change(data)
    path.write_text(json.dumps(data))
    with pytest.raises(TableError) as refused:
        tuned.load(skill, character)
    assert "\n" not in str(refused.value)
    return str(refused.value)


def test_a_table_of_another_schema_version_is_refused_in_one_line(tables):
    assert refusal(tables, "handspring", "man", lambda d: d.update(schema_version=0)) == \
        "handspring_man.json: schema_version=0, this sim_core reads version 1"


def test_a_row_with_an_unknown_setting_is_refused_naming_it(tables):
    message = refusal(tables, "somersaults", "woman", lambda d: d["somersaults"][0]["settings"].update(tuck_speed=1.0))
    assert message.startswith("somersaults_woman.json somersaults forward human: unknown setting 'tuck_speed'")


def test_a_row_with_an_out_of_range_setting_is_refused_with_the_range(tables):
    assert refusal(tables, "dives", "man", lambda d: d["dives"][1]["settings"].update(crouch_height=1.5)) == (
        "dives_man.json dive 1: parameter crouch_height=1.5 m is out of range; "
        "allowed range for crouch_height is [0.4, 0.95] m")


def test_a_running_column_out_of_range_is_refused_naming_its_speed(tables):
    message = refusal(tables, "running", "man", lambda d: d["parameters"]["thrust_time"].__setitem__(2, 0.9))
    assert message.startswith("running_man.json row 3.5 m/s: parameter thrust_time=0.9 1 is out of range")


def test_a_table_for_another_character_or_with_an_unknown_strength_is_refused(tables):
    assert refusal(tables, "landing", "man", lambda d: d.update(character="woman")) == \
        "landing_man.json: character='woman', expected 'man'"
    assert "strengths=['superhuman']" in refusal(tables, "landing", "woman", lambda d: d.update(strengths=["superhuman"]))


def test_a_refused_save_leaves_the_stored_table_as_it_was(tables):
    before = (tables / "handspring_man.json").read_bytes()
    body = tuned.load("handspring", "man")
    body["handsprings"][0]["settings"]["arm_time"] = 5.0
    with pytest.raises(TableError, match="arm_time=5"):
        tuned.save("handspring", "man", body, strengths=["human", "unlimited"])
    assert (tables / "handspring_man.json").read_bytes() == before and not list(tables.glob("*.tmp"))


def test_no_table_is_none_and_a_skill_without_a_row_type_is_refused(tables):
    assert tuned.load("somersaults", "child") is None
    _write(tables, "bicycling_man.json", {"schema_version": 1, "skill": "bicycling", "character": "man", "strengths": []})
    with pytest.raises(TableError, match="no row type is declared for tables of skill 'bicycling'"):
        tuned.load("bicycling", "man")


def test_every_skill_with_a_table_declares_its_settings_schema_and_lookup():
    """A row type names its settings schema and the function(s) that pick a row, each saying how."""
    for skill, _ in stored_tables():
        kind = store.table_type(skill)
        assert kind.settings.parameters and kind.lookup and all(f.__doc__ for f in kind.lookup), skill
    assert "nearest" in store.table_type("leap").describe_lookup()


# ------------------------------------------------------------------ settings schemas
def test_every_behaviour_has_a_settings_schema_apart_from_its_animator_schema():
    """The panel shows ``schema`` and folds ``settings_schema`` away: no name is in both, and a
    request may still set a tuned setting by its name (--set)."""
    for name in available_behaviours():
        cls = behaviour_class(name)
        animator = {p.name for p in cls.schema.parameters}
        settings = {p.name for p in cls.settings_schema.parameters}
        assert not animator & settings, name
        assert settings <= set(cls.schema.validate({})), name
    handspring = behaviour_class("handspring")
    assert handspring.schema.validate({"low_level": 1, "crouch_height": 0.7})["crouch_height"] == 0.7


def test_the_handspring_defaults_are_the_mans_calibrated_unlimited_row():
    from sim_core.skills.handspring.behaviour import OLD_ROW, calibrated
    row = {**OLD_ROW, **calibrated("man", "unlimited")["settings"]}
    assert behaviour_class("handspring").settings_schema.defaults() == {k: float(v) for k, v in row.items()}


def test_the_running_constants_are_the_running_any_tables():
    constants = tuned.load("running", "any")["constants"]
    defaults = behaviour_class("running").settings_schema.defaults()
    assert len(constants) > 50 and all(defaults[n] == v for n, v in constants.items())


def test_a_running_candidate_table_is_checked_like_a_stored_one():
    from sim_core.skills.running.behaviour import SpeedTable
    schema = behaviour_class("running").schema
    table = SpeedTable.load("man").with_row(3.5, {"toe_push": 0.9}).to_table()
    with pytest.raises(TableError, match="the table parameter row 3.5 m/s: parameter toe_push=0.9"):
        schema.validate({"table": table})


# ------------------------------------------------------------------ no tuned number in code
# Every module-level numeric constant left in the driving modules, with why it may stay there. A new
# one fails this test: a number a search or a hand tuning produced goes into a table (docs/tables.md),
# a hand-set control value into its controller's "constants" (sim_core/tuned/constants.py).
# "definition": a code, a special value, a unit vector or a structural choice; "criterion": a threshold
# of judging or of the request (TARGETS.md), not of driving; "search": a search space or starting prior
# (the planner's). No "design" value is left in code: the balance's, crouch's, leap's, take-off's and
# tumbling's are in their *_any tables' constants, the dive's, handspring's, somersault's and running's
# in their skills' *_any tables.
ALLOWED = {
    "control.balance": {"CROUCH_TABLE_ROWS": "definition"},
    "skills.dive.behaviour": {"ROTATION_TOLERANCE": "criterion", "CALIBRATED_DIVES": "definition"},
    "skills.handspring.behaviour": {"SKID_LIMIT": "criterion", "OLD_ROW": "definition"},
    "skills.land.behaviour": {"DROP_TOLERANCE": "criterion", "SPEED_TOLERANCE": "criterion"},
    "control.leap": {n: "criterion" for n in ("AIRBORNE_HEIGHT", "TOUCHDOWN_HEIGHT", "LANDING_SLIDE_LIMIT",
                                              "LANDING_SKID_LIMIT", "UNCOVERED_STEP")} | {"UP": "definition"},
    "skills.running.behaviour": {n: "definition" for n in ("FLIGHT", "LOADING", "HEEL", "HEEL_TOE", "TOE", "UNLOADING", "START", "TUNED")}
               | {"SCHEDULED": "search"} | {"MORPH_SPEEDS": "criterion"},
    "control.path": {**{n: "criterion" for n in ("MIN_SEGMENT", "MIN_LENGTH", "MAX_POINTS", "MIN_TURN_RADIUS")},
                     "CURVATURE_CHORD": "definition", "RADIUS_SAMPLE": "definition"}
               | {n: "definition" for n in ("TURN_RUN_OUT", "FIGURE_EIGHT_LAPS", "CIRCLE_LAPS")},
    "skills.somersault.behaviour": {"TUCK": "definition", "ROTATION_TOLERANCE": "criterion"},
    "skills.jump_to_target.behaviour": {n: "search" for n in ("TAKEOFF_COM", "TOUCHDOWN_COM", "WINDUP_OVERHEAD", "KNOB_DEFAULTS",
                                                   "MIN_CROUCH_TIME", "MIN_BROAD_DISTANCE")}
                   | {n: "criterion" for n in ("GROUND_AIR_TIME",
                                               "SIDEWAYS_AIR_TIME", "BOX_DISTANCE", "BOX_AIR_TIME", "BOX_LENGTH",
                                               "BOX_WIDTH", "START_BOX_LENGTH", "START_BOX_EDGE", "OBSTACLE_LENGTH",
                                               "OBSTACLE_ROOM")},
    "skills.jump_to_target.region": {n: "criterion" for n in ("LANDING_TOLERANCE", "AIR_TIME_TOLERANCE", "REACH",
                                                                          "HEIGHT_REACH")},
    # the bicycle's inverse-kinematics solver settings (numerics, not control) and its judging threshold
    "skills.bicycle.mount": {n: "definition" for n in ("IK_DAMPING", "IK_POSTURE_WEIGHT", "IK_ITERATIONS",
                                                       "IK_ITERATIONS_PER_TICK", "IK_TOLERANCE")},
    "skills.bicycle.assess": {n: "criterion" for n in ("HEADING_TOLERANCE_DEG", "SEGMENT_TAIL", "HILL_SETTLE",
                                                       "STOP_FALL_ROLL_DEG", "STOPPED_SPEED", "COAST_SETTLE")},
    # the foot going down: its inverse-kinematics solver's numerics, and the knee's index in the leg's servos
    "skills.bicycle.behaviour": {n: "definition" for n in ("MIN_LOOKAHEAD_SPEED", "FOOT_IK_ITERATIONS", "FOOT_IK_DAMPING",
                                                           "HIP_Y", "KNEE")},
    "skills.bicycle.steering": {"MIN_SCHEDULED_SPEED": "definition"},
    # the vault's judging (TARGETS.md, issue 31) and Takei's Table 1, the reference it is judged against
    "skills.vault.assess": {n: "criterion" for n in ("STILL_SPEED", "ROTATION_TOLERANCE", "PEAK_LANDING_LIMIT", "CONTACT_GAP",
                                                     "KNEELING_HEIGHT", "FALLEN_PELVIS", "BALANCED_TIME", "NO_STEP",
                                                     "TABLE_1", "TAKEI_MASS", "TAKEI_HEIGHT")},
    "skills.bicycle.course": {"SLALOM_POINT_SPACING": "definition", "RUN_OUT": "definition"},
}


def numeric_constants(path: Path) -> list[str]:
    """Module-level names bound to numbers: a literal, arithmetic of literals, or tuples, lists,
    dicts and sets of them (a call - Schema(...), np.array(...) of literals aside - is code)."""
    def literal(node) -> bool:
        if isinstance(node, ast.Constant):
            return type(node.value) in (int, float, str) or node.value is None
        if isinstance(node, (ast.UnaryOp, ast.BinOp)):
            return all(literal(n) for n in ast.iter_child_nodes(node) if not isinstance(n, (ast.operator, ast.unaryop)))
        if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
            return all(literal(e) for e in node.elts)
        if isinstance(node, ast.Dict):
            return all(literal(e) for e in node.keys + node.values if e is not None)
        if isinstance(node, ast.Call) and ast.unparse(node.func) in ("np.array", "range", "dict"):
            return all(literal(a) for a in node.args) and all(literal(k.value) for k in node.keywords)
        if isinstance(node, ast.Name):
            return True                 # a name of another constant (checked where it is bound)
        return False

    found = []
    for node in ast.parse(path.read_text()).body:
        if isinstance(node, (ast.Assign, ast.AnnAssign)) and node.value is not None and literal(node.value):
            has_number = any(isinstance(n, ast.Constant) and type(n.value) in (int, float) for n in ast.walk(node.value))
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            if has_number:
                found += [n.id for t in targets for n in ast.walk(t) if isinstance(n, ast.Name)]
    return found


def test_no_tuned_number_is_a_constant_in_a_control_module():
    """A module-level numeric constant of a driving module (sim_core/control, the skills' behaviour
    code) must be on the allow-list with its reason; the list names nothing that is gone (it
    shrinks as the design values move to tables)."""
    unlisted, gone = [], []
    for path in driving_modules():
        module = ".".join(path.relative_to(SIM_CORE).with_suffix("").parts)
        names = numeric_constants(path)
        allowed = ALLOWED.get(module, {})
        unlisted += [f"{module}.{n}" for n in names if n not in allowed]
        gone += [f"{module}.{n}" for n in allowed if n not in names]
    assert not unlisted, f"numbers in code: {', '.join(unlisted)} - put them in the skill's table (docs/tables.md)"
    assert not gone, f"allow-listed but no longer constants: {', '.join(gone)}"
    assert not [f"{m}.{n}" for m, names in ALLOWED.items() for n, why in names.items() if why not in REASONS]


REASONS = ("definition", "criterion", "search")     # what may stay a number in code; "design" may not


# ------------------------------------------------------------------ a calibration's bookkeeping
def test_a_found_row_replaces_the_old_one_and_its_not_found_record():
    rows, missing = merge_search([OTHER, {**KEY, "settings": {"a": 0}}], [{**KEY, "best": "fell"}], KEY, True,
                                 {"settings": {"a": 2}, "score": 0.1}, "unused")
    assert rows == [OTHER, {**KEY, "settings": {"a": 2}, "score": 0.1}] and missing == []


def test_without_a_find_the_old_row_stays_else_the_best_run_is_recorded():
    old = {**KEY, "settings": {"a": 0}}
    assert merge_search([old, OTHER], [], KEY, False, {"settings": {"a": 3}}, "fell") == ([OTHER, old], [])
    rows, missing = merge_search([OTHER], [], KEY, False, {"settings": {"a": 3}}, "fell, rotation 5.5 rad")
    assert rows == [OTHER] and missing == [{**KEY, "settings": {"a": 3}, "best": "fell, rotation 5.5 rad"}]
    rows, missing = merge_search([OTHER], [], KEY, False, {"settings": {"a": 3}, "score": 7.0}, "fell")
    assert missing == [{**KEY, "settings": {"a": 3}, "best": "fell", "score": 7.0}]


def test_a_worse_search_does_not_overwrite_the_recorded_best_miss():
    earlier = {**KEY, "settings": {"a": 1}, "best": "fell, rotation 6.35 rad", "score": 20.0}
    _, missing = merge_search([], [earlier], KEY, False, {"settings": {"a": 9}, "score": 63.0}, "fell, rotation -1.3 rad")
    assert missing == [earlier]
    _, missing = merge_search([], [earlier], KEY, False, {"settings": {"a": 2}, "score": 10.0}, "fell, rotation 6.2 rad")
    assert missing == [{**KEY, "settings": {"a": 2}, "best": "fell, rotation 6.2 rad", "score": 10.0}]


def test_a_calibration_searches_only_the_settings_named_and_refuses_an_unknown_one(capsys):
    """--names of the calibration scripts: the named settings, or a clear refusal naming the
    allowed ones (argparse exits with status 2)."""
    parser = argparse.ArgumentParser()
    names_option(parser, {"open_time": (0.03, 0.4), "foot_delta": (-0.3, 0.3)}, ("open_time",))
    assert parser.parse_args(["--names", "open_time,foot_delta"]).names == ["open_time", "foot_delta"]
    assert parser.parse_args([]).names is None
    with pytest.raises(SystemExit) as refused:
        parser.parse_args(["--names", "open_time,tuck"])
    assert refused.value.code == 2
    assert "tuck: not searched settings; choose from open_time, foot_delta" in capsys.readouterr().err


def test_a_search_varies_the_named_settings_of_its_space_and_keeps_the_others_as_started():
    from sim_core.control.tuned import searched_and_fixed
    settings = ("crouch_height", "open_time", "foot_delta", "flight_step_division")
    space = {"crouch_height": (0.4, 0.9), "open_time": (0.03, 0.4), "foot_delta": (-0.3, 0.3)}
    start = {"crouch_height": 0.7, "open_time": 0.1, "foot_delta": 0.0, "flight_step_division": 8}
    assert searched_and_fixed(settings, space, None, start) == (
        ["crouch_height", "open_time", "foot_delta"], {"flight_step_division": 8})
    assert searched_and_fixed(settings, space, ["foot_delta", "open_time"], start) == (
        ["open_time", "foot_delta"], {"crouch_height": 0.7, "flight_step_division": 8})


# ------------------------------------------------------------------ a controller's constants
def test_a_controllers_constants_are_checked_against_its_schema_in_one_line(tables):
    """A constants section is data like a settings row: a value out of its sanity range (also inside
    a pose map) or a missing constant is refused naming the file, the place and the range."""
    from sim_core.control.balance import BALANCE_CONSTANTS
    from sim_core.control.tumble import TUMBLE_CONSTANTS
    from sim_core.tuned.constants import read_constants

    def edit(table, change):
        path = tables / f"{table}_any.json"
        data = json.loads(path.read_text())
        change(data["constants"])
        path.write_text(json.dumps(data))

    assert read_constants("balance", BALANCE_CONSTANTS).lean_max == 0.8
    edit("balance", lambda c: c.update(lean_max=9.0))
    with pytest.raises(TableError) as refused:
        read_constants("balance", BALANCE_CONSTANTS)
    assert str(refused.value) == ("balance_any.json constants lean_max: parameter lean_max=9 rad is out of range; "
                                  "allowed range for lean_max is [0, 2] rad")
    edit("balance", lambda c: c.pop("lean_max"))
    with pytest.raises(TableError, match="balance_any.json constants: missing lean_max"):
        read_constants("balance", BALANCE_CONSTANTS)
    edit("tumble", lambda c: c["positions"]["tuck"].update({"knee_*_y": 4.0}))
    with pytest.raises(TableError, match=r"tumble_any.json constants positions\[tuck\]\[knee_\*_y\]: parameter positions=4"):
        read_constants("tumble", TUMBLE_CONSTANTS)


def test_every_controller_constant_has_a_unit_a_range_and_help():
    from sim_core.tuned.constants import as_constants
    for skill, character in stored_tables():
        body = tuned.load(skill, character)
        if "constants" in body and skill != "running":
            kind = store.table_type(skill)
            assert set(vars(as_constants(body))) <= set(kind.settings.by_name), skill
            assert all(kind.settings.by_name[n].unit and kind.settings.by_name[n].help for n in body["constants"]), skill


def test_every_knob_has_one_name_in_its_table_and_in_the_behaviour_that_runs_it():
    """A table row names each setting as the behaviour that runs it does (its animator schema or
    settings schema): the leap table and the jump plans in the leap's names (thrust_damping,
    liftoff_hip, landing_*), never a second name mapped in code. vertical_thrust is the planner's
    choice of the thrust (the leap's is its distance); constants are their controller's."""
    runs = {"leap": "leap", "jump_targets": "leap", "dives": "dive", "somersaults": "somersault",
            "handspring": "handspring", "running": "running", "landing": "land"}
    for table, skill in runs.items():
        cls = behaviour_class(skill)
        named = set(cls.schema.by_name) | set(cls.settings_schema.by_name)
        for character in ("man", "woman", "any"):
            body = tuned.load(table, character)
            if body is None:
                continue
            used = {n for where, row in store.table_type(table).rows(body) if not where.startswith("constants") for n in row}
            assert used - named <= {"vertical_thrust"}, (f"{table}_{character}", sorted(used - named))
    composites = [set(behaviour_class(s).settings_schema.by_name) | set(behaviour_class(s).schema.by_name)
                  for s in ("leap", "somersault", "handspring")]
    assert all({"landing_knee_flexion", "landing_foot_lead_time", "thrust_damping", "liftoff_hip"} <= n for n in composites)


# ------------------------------------------------------------------ no tuned number inline
# The rule for a number written inside a driving module's functions (default arguments included):
# it is structural or it says why it is there. Structural, never flagged: 0, 1, 2, -1 (identities,
# signs, doubling, pairs); 0.5 (a mean, a half); 100 (a percent); an epsilon up to 1e-6 (a guard
# against a division by zero); an index or a slice (the literal is inside a subscript: m[3], [:3]);
# an array's shape (the arguments of reshape, np.eye, np.zeros, np.ones) and round()'s digits.
# Anything else is a hand-set value and belongs in the module's table constants (docs/tables.md),
# unless its line says "# definition: ..." (a code, a unit, a solver's own precision, a structural
# count) or "# criterion: ..." (a TARGETS.md threshold of judging, not of driving).
STRUCTURAL = {0, 1, 2, -1, 0.5, 100}
SHAPE_CALLS = ("reshape", "eye", "zeros", "ones", "round")
EXPLAINED = re.compile(r"# (definition|criterion): \S")    # the mark and its reason


def inline_numbers(path: Path) -> list[str]:
    """``line: value`` of each numeric literal in the module's function bodies the rule above flags."""
    text = path.read_text()
    lines = text.splitlines()
    tree = ast.parse(text)
    exempt = set()                      # literals inside a subscript or a shape call
    for node in ast.walk(tree):
        if isinstance(node, ast.Subscript):
            exempt |= {id(n) for n in ast.walk(node.slice)}
        elif isinstance(node, ast.Call):
            func = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
            if func in SHAPE_CALLS:
                exempt |= {id(n) for a in node.args for n in ast.walk(a) if isinstance(n, ast.Constant)}
    found = set()
    for function in ast.walk(tree):
        if not isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
            continue
        for node in ast.walk(function):
            if not (isinstance(node, ast.Constant) and type(node.value) in (int, float)) or id(node) in exempt:
                continue
            value = node.value
            if value in STRUCTURAL or abs(value) <= 1e-6 or EXPLAINED.search(lines[node.lineno - 1]):
                continue
            found.add(f"{node.lineno}: {value!r}")
    return sorted(found, key=lambda s: int(s.split(":")[0]))


def test_no_tuned_number_is_written_inline_in_a_driving_module():
    """Every numeric literal inside a driving module's functions is structural or explained on its
    line; a hand-set gain, time, angle or share is its controller's table constant."""
    flagged = {}
    for path in driving_modules():
        module = ".".join(path.relative_to(SIM_CORE).with_suffix("").parts)
        if numbers := inline_numbers(path):
            flagged[module] = numbers
    assert not flagged, f"numbers inline: {flagged} - make them table constants (docs/tables.md) or explain them"


def test_the_inline_number_rule_flags_a_hand_set_value_and_passes_an_explained_one(tmp_path):
    source = tmp_path / "m.py"
    source.write_text("def f(m, t=0.25):\n    a = m[3] + 0.5 * m.reshape(3, 3)[0, 2]\n    b = 1e-9 + 100 * a\n"
                      "    return t * 0.8 + 7  # criterion: TARGETS.md\n")
    assert inline_numbers(source) == ["1: 0.25"]
    source.write_text("def f(x):\n    return x * 0.8  # definition:\n")
    assert inline_numbers(source) == ["2: 0.8"]           # a mark without its reason explains nothing
