"""Each skill calibration (python -m sim_core calibrate SKILL) searches through the search service with a tiny budget (a few
simulations), writes its table where --tables says, and leaves the shipped tables alone."""
from __future__ import annotations

import hashlib
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SHIPPED = ROOT / "sim_core" / "tuned" / "tables"


def _shipped_digest() -> str:
    h = hashlib.sha256()
    for path in sorted(SHIPPED.glob("*.json")):
        h.update(path.name.encode() + path.read_bytes())
    return h.hexdigest()


@pytest.mark.parametrize("skill, args, table, progress", [
    ("dive", ["--character", "man", "--only", "0", "--fresh", "--budget", "5", "--population", "4",
                         "--no-refine"], "dives_man.json", "man inward 5/5 dives"),
    ("dive", ["--character", "man", "--only", "0", "--fresh", "--budget", "4", "--method", "anneal",
                         "--no-refine"], "dives_man.json", "man inward 4/4 dives"),
    ("handspring", ["--character", "man", "--budget", "4", "--population", "3", "--no-refine"],
     "handspring_man.json", "man (unlimited) 4/4 handsprings"),
    ("somersault", ["--character", "man", "--direction", "backward", "--strength", "unlimited",
                               "--budget", "4", "--population", "3", "--no-refine"],
     "somersaults_man.json", "man backward (unlimited) 4/4 somersaults"),
    ("running", ["--speeds", "3.5", "--duration", "6", "--max-evaluations", "3", "--method", "cma",
                      "--leans", "0.35"], None, "3.5 m/s: 3 evaluations"),
    ("jump_to_target", ["--characters", "man", "--distances", "1.31", "--boxes", "--sideways", "--no-down",
                    "--trials", "3", "--plan-only"], "jump_targets_man.json", "man 1.3 m forward: 1/3 trials"),   # planned from the measured jumps in one trial
])
def test_a_tiny_budget_run_searches_and_writes_only_where_told(tmp_path, skill, args, table, progress):
    before = _shipped_digest()
    ran = subprocess.run([sys.executable, "-m", "sim_core", "calibrate", skill, *args, "--workers", "2",
                          "--tables", str(tmp_path)], cwd=ROOT, capture_output=True, text=True, timeout=600,
                         env={**os.environ, "PYTHONPATH": str(ROOT)})
    assert ran.returncode == 0, ran.stderr[-2000:]
    assert progress in ran.stdout
    assert _shipped_digest() == before
    if table:
        written = json.loads((tmp_path / table).read_text())
        assert written["character"] == "man"
    else:           # tune_running writes only a better row: either way, only into --tables
        assert {p.name for p in tmp_path.iterdir()} <= {"running_man.json"}
