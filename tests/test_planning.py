"""Planning above the loop: the import graph (no cycle; control/ never imports simulate or
planning), the plan command and the user's plan store, cancel, and 1 or 2 workers planning alike."""
from __future__ import annotations

import ast
import json
import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

from sim_core.errors import Cancelled, ParameterError
from sim_core.skills.jump_to_target.behaviour import GROUND_AIR_TIME, stored_plan, user_plans_path

ROOT = Path(__file__).resolve().parents[1]
UNPLANNED = {"target_x": 1.17, "air_time": GROUND_AIR_TIME}     # no shipped plan has this request
SLOW_TO_PLAN = {"target_x": 1.3, "target_z": -0.4, "obstacle_height": 0.3, "air_time": 0.6}   # down over a box, no
                                    # plan is for (an obstacle: no measured jumps, the search runs on)
WINDUP_TIME = 1.25


def import_graph() -> dict[str, set[str]]:
    """sim_core module -> the sim_core modules it imports (at the top or inside a function)."""
    modules = {}
    for path in (ROOT / "sim_core").rglob("*.py"):
        name = ".".join(path.relative_to(ROOT).with_suffix("").parts).removesuffix(".__init__")
        modules[name] = path
    graph = {}
    for name, path in modules.items():
        imported = set()
        package = name.split(".") if path.name == "__init__.py" else name.split(".")[:-1]
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.level:        # sim_core imports itself relatively
                base = package[: len(package) - node.level + 1]
                module = ".".join(base + ([node.module] if node.module else []))
                imported.add(module)
                imported.update(f"{module}.{a.name}" for a in node.names)
            elif isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("sim_core"):
                imported.add(node.module)
                imported.update(f"{node.module}.{a.name}" for a in node.names)
            elif isinstance(node, ast.Import):
                imported.update(a.name for a in node.names if a.name.startswith("sim_core"))
        graph[name] = {m for m in imported if m in modules and m != name}
    return graph


def test_the_import_graph_has_no_cycle_and_control_is_below_simulate_and_planning():
    graph = import_graph()
    upward = {(m, d) for m, deps in graph.items() if m.startswith("sim_core.control") for d in deps
              if d == "sim_core.simulate" or d.startswith("sim_core.planning")}
    assert not upward, f"control imports the loop or planning: {sorted(upward)}"
    assert "sim_core.simulate" in graph["sim_core.planning.jump"]          # planning sits above the loop
    state, cycle = {}, []

    def visit(module, path):
        state[module] = "open"
        for dep in sorted(graph[module]):
            if state.get(dep) == "open":
                cycle.append(path[path.index(dep):] + [dep] if dep in path else [module, dep])
            elif dep not in state:
                visit(dep, path + [dep])
        state[module] = "done"

    for module in sorted(graph):
        if module not in state:
            visit(module, [module])
    assert not cycle, f"import cycles: {cycle}"


def _cli(*args, store: Path) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(ROOT), "SIM_ATHLETICS_PLANS": str(store)}
    return subprocess.run([sys.executable, "-m", "sim_core", *args], cwd=ROOT, env=env, capture_output=True,
                          text=True, timeout=600)


def test_plan_stores_a_plan_that_a_later_simulate_finds_without_a_trial(tmp_path):
    """A plan of at most 4 trials for 1.31 m (nobody planned it; on flat ground it starts from the
    measured jump nearest it, which lands within 5 cm), stored in --store; a later simulate finds
    it, runs no trial, and its run is the plan's trial again (the same landing)."""
    store = tmp_path / "plans"
    sets = ["--set", "target_x=1.31"]
    planned = _cli("plan", "jump_to_target", "--character", "man", *sets, "--budget", "4", "--workers", "2",
                   "--store", str(store), store=tmp_path / "unused")
    assert planned.returncode == 0, planned.stderr
    summary = json.loads(planned.stdout.strip().splitlines()[-1])
    assert summary["found"] and 1 <= summary["trials"] <= 4 and summary["store"] == str(store)
    assert f"planning: {summary['trials']}/4 trials" in planned.stderr
    plans = json.loads((store / "jump_targets_man.json").read_text())["plans"]
    assert len(plans) == 1 and plans[0]["request"]["target_x"] == pytest.approx(1.31)
    assert not list(store.glob("*.tmp"))                                   # written through a temporary file
    out = tmp_path / "jump.npz"
    again = _cli("simulate", "jump_to_target", *sets, "--out", str(out), store=store)
    assert again.returncode == 0, again.stderr
    assert "planning:" not in again.stderr                                 # no trial: the stored plan
    metrics = json.loads(again.stdout.strip().splitlines()[-1])["metrics"]
    assert [metrics["landing_x"], metrics["landing_y"]] == pytest.approx(summary["landing"], abs=1e-9)


def test_simulate_plans_an_unplanned_jump_first_above_the_loop(tmp_path):
    store = tmp_path / "plans"
    ran = _cli("simulate", "jump_to_target", "--set", "target_x=1.17", "--set", "plan_trials=2", "--workers", "1",
               "--duration", "0.1", store=store)
    assert "planning: 1/2 trials" in ran.stderr          # the search ran (it stops early once a trial lands)
    assert (store / "jump_targets_man.json").exists()


def test_a_run_never_plans_it_refuses_an_unplanned_jump_with_the_command_that_plans_it():
    from sim_core.simulate import RunRequest, run
    with pytest.raises(ParameterError, match="plan it first with 'python -m sim_core plan jump_to_target "
                                             "--character man --set target_x=1.17'"):
        run(RunRequest("jump_to_target", "man", params=UNPLANNED))


def test_a_plan_in_the_user_store_is_found_by_the_behaviour(monkeypatch):
    """plan_and_store -> the user's store; the behaviour's lookup finds it there (layered over
    the shipped table), and runs it."""
    from sim_core.planning import plan_and_store, planned
    plan = plan_and_store("man", UNPLANNED, budget=1)
    assert user_plans_path("man").exists()
    assert planned("man", UNPLANNED) == {"request": planned("man", UNPLANNED)["request"], **plan}
    request = {"target_x": 1.17, "target_y": 0.0, "target_z": 0.0, "obstacle_height": 0.0,
               "air_time": GROUND_AIR_TIME, "windup_time": WINDUP_TIME, "strength": "human"}
    assert stored_plan("man", request)["settings"] == plan["settings"]


def test_a_calibration_sets_the_user_store_aside(monkeypatch):
    """A user's plan is not seen while ``python -m sim_core calibrate SKILL`` runs (its tables and docs are
    the shipped ones on every machine), and is seen again after."""
    import types
    from sim_core import cli, skills
    from sim_core.skills.jump_to_target.behaviour import read_plans, stored_plans, user_plans_path
    shipped = read_plans("man")
    user = {**shipped[0], "request": {**shipped[0]["request"], "target_x": 1.234}}
    user_plans_path("man").parent.mkdir(parents=True, exist_ok=True)
    table = json.loads((ROOT / "sim_core/tuned/tables/jump_targets_man.json").read_text())
    user_plans_path("man").write_text(json.dumps({**table, "plans": [user]}))
    assert len(stored_plans("man")) == len(shipped) + 1
    seen = []
    calibration = types.SimpleNamespace(main=lambda options: seen.append(len(stored_plans("man"))))
    monkeypatch.setattr(skills, "skill_module", lambda skill, part: calibration)
    assert cli.main(["calibrate", "jump_to_target", "--report-only"]) == 0
    assert seen == [len(shipped)]
    assert len(stored_plans("man")) == len(shipped) + 1


def test_cancel_mid_plan_raises_within_a_second_and_writes_nothing():
    """A cancelled() that turns true 1.2 s into the plan (the second or third trial): Cancelled,
    within a second, and no plan file."""
    from sim_core.planning import plan_and_store
    started = time.monotonic()
    seen = []

    def cancelled() -> bool:
        seen.append(time.monotonic())
        return time.monotonic() - started > 1.2

    with pytest.raises(Cancelled):
        plan_and_store("man", SLOW_TO_PLAN, budget=50, cancelled=cancelled)
    late = time.monotonic() - (started + 1.2)
    print(f"cancel landed {late:.2f} s after cancelled() turned true")
    assert late < 1.0
    assert not user_plans_path("man").exists()


def test_cancel_with_a_process_pool_also_lands_within_a_second():
    from sim_core.planning import plan_and_store
    from sim_core.tuning import LocalPool
    started = time.monotonic()
    with pytest.raises(Cancelled), LocalPool(2) as pool:
        plan_and_store("man", SLOW_TO_PLAN, budget=50, executor=pool, cancelled=lambda: time.monotonic() - started > 1.2)
    assert time.monotonic() - started - 1.2 < 1.0
    assert not user_plans_path("man").exists()


def test_one_or_two_workers_plan_the_same_jump():
    from sim_core.planning import plan_jump
    from sim_core.tuning import LocalPool, SerialExecutor
    target = (1.17, 0.0, 0.0)
    serial = plan_jump("man", target, GROUND_AIR_TIME, WINDUP_TIME, budget=4, executor=SerialExecutor())
    with LocalPool(2) as pool:
        pooled = plan_jump("man", target, GROUND_AIR_TIME, WINDUP_TIME, budget=4, executor=pool)
    assert serial == pooled


def test_the_plan_command_refuses_bad_requests_in_one_line(tmp_path):
    for args, words in [(["plan", "balance"], "needs no plan"),
                        (["plan", "jump_to_target", "--budget", "0"], "--budget 0"),
                        (["plan", "jump_to_target", "--set", "target_x=-1"], "target_x=-1"),
                        (["plan", "jump_to_target", "--set", "target_x=2.5", "--set", "air_time=0.1"],
                         "needs a take-off at"),
                        (["plan", "jump_to_target", "--workers", "0"], "workers=0")]:
        refused = _cli(*args, store=tmp_path)
        assert refused.returncode == 2 and words in refused.stderr
        assert len(refused.stderr.strip().splitlines()) == 1
    assert not list(tmp_path.iterdir())
