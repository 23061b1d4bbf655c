"""How ``python -m sim_core adapt`` carries each skill to a new body (Hodgins & Pollard 1997 §5):

1. **scale** the skill's table from the nearest character that has one (``nearest_source``) by
   Fig. 6, each value by its units (``sim_core.adapt.scaling``): lengths by L, speeds by L^1/2, gains
   by the mass or inertia they move (``scale_settings``, ``scale_columns``);
2. **check** it by measured runs of random requests inside the skill's range (a seeded draw, so the
   same seed checks the same requests and another seed others);
3. where the check fails, **search**: the skill's own calibration (the landing's foot-delta sweep,
   the vertical leap's crouch sweep, CMA-ES over the five running parameters of each failing row),
   then check again.

One adapter per skill with a per-character table that scales: landing, leap (vertical, human
strength), running and the vault (its one row and the constants the body meets the vault by); balance
has no table and is checked only. Every other skill is run once
with its default request by the command (``sim_core.adapt.command``) and reported as it is.

An adapter's ``scale`` returns a table body; the command writes it through the store, so a check's
runs read it like any calibrated table. Nothing here writes a file.
"""
from __future__ import annotations

import contextlib
import math
import time
from dataclasses import dataclass

import numpy as np

from .scaling import ScaleFactors, Units, scale
from .settings import GEOMETRIC, MASS, CharacterPair, scale_constants, scale_settings
from ..character.dimensions import leg_length_ratio
from ..character.spec import CharacterSpec, load_character
from ..errors import ParameterError

VELOCITY, LENGTH = Units.parse("m/s"), Units.parse("m")
CHECKS = 6                   # definition: random requests a check draws (balance: 3 knee bends, running: every row)
KNEE_BEND = (0.75, 0.95)     # definition: a balance check's pelvis heights, shares of the standing hip height
BALANCE_SECONDS = 5.0        # definition: a knee bend's run (move 1.2 s, hold 0.5 s, back up, stand)
LANDING_DROPS = (0.2, 0.6)   # definition: drops (m above standing, x L) the landing's check draws: calibrate land's DROPS
LANDING_SPEEDS = (-1.0, 1.5)  # definition: horizontal speeds (m/s, x L^1/2) drawn: drops and vertical leaps; the broad
                             # jump's faster landings (to 3 m/s) are not adapted (the man's own table lands 4 of 6 there)
LANDING_SECONDS = 3.0        # definition: a landing's run, as calibrate land's trials
LEAP_HEIGHTS = (0.2, 0.5)    # definition: the leap range for adapted bodies (m of COM rise, x L: a length,
                             # Fig. 6; the man's 0.5 m is 0.29 m for the child, 0.47 m for the 70 % man -> woman body)
LEAP_SECONDS = 4.5           # definition: a leap's run, as calibrate leap's trials
RUN_SECONDS = 100.0          # criterion: TARGETS.md's 100 s of running without a fall
SPEED_TOLERANCE = 0.05       # criterion: mean speed of the last 10 s within 5 % (TARGETS.md "Running")
RUN_SEARCH_SECONDS = 15.0    # definition: the seed's 15 s evaluation runs (§5, S6)
VAULT_BODY_CONSTANTS = ("start_com_height", "touchdown_on_board", "horse_gap", "horse_height", "board_stiffness",
                        "handled_speed")
                             # definition: the vault's constants a body meets the vault by (its start, the apparatus,
                             # the board's springs and the run-up), scaled with its row; the rest (mat, bow, gesture,
                             # search) are shared


@dataclass
class Check:
    works: bool              # every drawn request did what was asked
    figures: str             # what was measured, one line
    runs: int
    covers: bool = True      # the table serves the whole range checked (else works only where it serves)
    failed: tuple = ()       # the requests that failed, where an adapter can act on them (running: speeds)


class Adapter:
    """What every adapter has: ``skill``, its ``table`` (None: no table), ``check``; with a table
    also ``scale`` and ``search(character, workers, minutes, check)``."""
    skill: str
    table: str | None

    def keep_what_works(self, character: str, check: Check, rng) -> Check | None:
        """After a failed check: the table narrowed to what worked, checked again (None: all or nothing)."""
        return None

    def runs_with(self, target: CharacterSpec):
        """A context the skill's scaling, checks and searches run in (nothing by default)."""
        return contextlib.nullcontext()


def nearest_source(target: CharacterSpec, candidates: list[str]) -> str | None:
    """Of ``candidates`` (characters with a table of the skill), the one nearest ``target`` in size:
    the smallest |ln L| + |ln (m'/m)| / 3 (leg length, and total mass as a length)."""
    best = None
    for name in candidates:
        if name == target.name:
            continue
        try:
            source = load_character(name)
        except Exception:                      # a table of a character whose spec is not shipped
            continue
        distance = (abs(math.log(leg_length_ratio(source, target)))
                    + abs(math.log(target.total_mass / source.total_mass)) / 3.0)   # definition: mass as a length
        if best is None or distance < best[0]:
            best = (distance, name)
    return None if best is None else best[1]


def _run(behaviour: str, character: str, **request):
    """A check's run, as the user's runs go: planned first where the skill plans (a landing's foot
    placement, planning.planned_request), then simulated."""
    from ..planning import planned_request
    from ..simulate import RunRequest, run
    return run(planned_request(RunRequest(behaviour, character, **request))[0])


class BalanceAdapter(Adapter):
    """Balance has no table: its controller reads the body (leg geometry, feet, servos)."""
    skill, table = "balance", None

    def check(self, character: str, rng) -> Check:
        from ..control.balance import standing_hip_height
        stand = standing_hip_height(load_character(character))
        heights = rng.uniform(*KNEE_BEND, size=3) * stand      # definition: 3 knee bends
        failed = []
        for h in heights:
            t = _run("balance", character, params={"pelvis_height": float(h), "move_start": 0.3, "move_time": 1.2,
                                                   "hold_time": 0.5}, duration=BALANCE_SECONDS)
            if t.meta["outcome"] != "success" or t.meta["metrics"].get("fell"):
                failed.append(f"{h:.3f} m ({t.meta['outcome']})")
        figures = (f"knee bends to pelvis {min(heights):.2f}-{max(heights):.2f} m, {BALANCE_SECONDS:g} s: "
                   + (f"{len(heights)}/{len(heights)} balanced" if not failed else "not balanced at " + ", ".join(failed)))
        return Check(not failed, figures, len(heights))


class LandingAdapter(Adapter):
    """The landing's foot-servo delta table (python -m sim_core calibrate land): drops by L, speeds
    by L^1/2, deltas by L."""
    skill, table = "land", "landing"

    def scale(self, source: CharacterSpec, target: CharacterSpec, body: dict) -> tuple[dict, int]:
        f = ScaleFactors(leg_length_ratio(source, target))
        v = lambda x: round(scale(x, VELOCITY, f), 3)
        m = lambda x: round(scale(x, LENGTH, f), 3)
        from ..control.leap import LANDING_SETTINGS
        knob = LANDING_SETTINGS.by_name["foot_delta"]
        rows = []
        for r in body["foot_delta"]:           # a delta scaled out of the setting's range: that speed is left out
            kept = [(v(s), m(d)) for s, d in zip(r["speed"], r["delta"]) if knob.minimum <= m(d) <= knob.maximum]
            rows.append({"drop": m(r["drop"]), "touchdown_speed": v(r["touchdown_speed"]),
                         "speed": [s for s, _ in kept], "delta": [d for _, d in kept]})
        out = {"script": f"python -m sim_core adapt (scaled from the {source.name}'s landing table by Fig. 6)",
               "foot_delta": rows, "offered_speeds": [round(v, 3) for v in self.wanted_speeds(target)]}
        fast = body.get("fast_touchdown")
        if fast:
            out["fast_touchdown"] = {"speed": v(fast["speed"]), "ramp": v(fast["ramp"]), "delta": m(fast["delta"])}
        return out, 0

    @contextlib.contextmanager
    def runs_with(self, target: CharacterSpec):
        """A body with no leap table yet lands with the leap's constants scaled to it, as it will
        once the leap is adapted (the landing reads them: control.leap.leap_constants; the landing is
        adapted first because the leap lands): a provisional leap table holding only the constants
        LeapAdapter.scaled_constants gives from the nearest leap source, removed afterwards, also on
        an exception or Ctrl-C. A body with a leap table lands with what it holds."""
        from .. import tuned
        source = nearest_source(target, tuned.characters_of("leap"))
        if tuned.exists("leap", target.name) or source is None:
            yield
            return
        with tuned.provisional("leap", target.name):
            source_spec = load_character(source)
            constants = LeapAdapter().scaled_constants(source_spec, target, tuned.load("leap", source))
            tuned.save("leap", target.name, {"character": target.name, "constants": constants, "vertical": {},
                                             "script": f"python -m sim_core adapt (the {source}'s thrust and landing "
                                                       f"constants scaled by Fig. 6, while the landing is adapted)"},
                       strengths=["human"])
            yield

    @staticmethod
    def wanted_speeds(spec: CharacterSpec) -> tuple[float, float]:
        """The horizontal speeds (m/s) the body is adapted for and its check draws: LANDING_SPEEDS x L^1/2."""
        L = leg_length_ratio(load_character("man"), spec)
        return (LANDING_SPEEDS[0] * L ** 0.5, LANDING_SPEEDS[1] * L ** 0.5)

    def check(self, character: str, rng) -> Check:
        from ..control.leap import landing_drops, landing_speeds
        from ..simulate import StartState
        from .. import tuned
        spec = load_character(character)
        table = tuned.load("landing", spec.name)
        L = leg_length_ratio(load_character("man"), spec)
        wanted = self.wanted_speeds(spec)
        try:
            served = landing_speeds(table)
        except ParameterError as exc:          # no landing of the table balanced
            return Check(False, str(exc), 0)
        low, high = max(wanted[0], served[0]), min(wanted[1], served[1])
        drops = rng.uniform(LANDING_DROPS[0] * L, LANDING_DROPS[1] * L, size=CHECKS)
        speeds = rng.uniform(low, high, size=CHECKS) if high > low else np.full(CHECKS, low)
        # inside what the table offers at each speed (landing_drops: a table scaled from another body's
        # rows can start a little above the drops drawn; the land skill refuses drops outside it)
        drops = np.array([min(max(h, lo), hi) for h, v in zip(drops, speeds) for lo, hi in [landing_drops(table, v)]])
        missed, failed = [], []
        for drop, speed in zip(drops, speeds):
            t = _run("land", character, start=StartState(height=float(drop), velocity=(float(speed), 0.0, 0.0)),
                     duration=LANDING_SECONDS)
            if t.meta["outcome"] != "success":
                missed.append(f"{drop:.2f} m at {speed:+.2f} m/s ({t.meta['outcome']})")
                failed.append(float(speed))
        figures = (f"drops {drops.min():.2f}-{drops.max():.2f} m at {speeds.min():+.2f}..{speeds.max():+.2f} m/s "
                   f"(the table's common speeds within {low:+.2f}..{high:+.2f} of {wanted[0]:+.2f}..{wanted[1]:+.2f}): "
                   f"{CHECKS - len(missed)}/{CHECKS} balanced" + (f"; missed {', '.join(missed)}" if missed else ""))
        return Check(not missed, figures, CHECKS, covers=(low, high) == wanted, failed=tuple(failed))

    def keep_what_works(self, character: str, check: Check, rng) -> Check | None:
        """The table's rows cut to the horizontal speeds between the slowest failing draw on each
        side of standing still (a landing fails at its fast edges), checked again with new draws."""
        from .. import tuned
        name = load_character(character).name
        body = tuned.load("landing", name)
        above = min((v for v in check.failed if v >= 0.0), default=math.inf)
        below = max((v for v in check.failed if v < 0.0), default=-math.inf)
        rows = []
        for row in body["foot_delta"]:
            kept = [(v, d) for v, d in zip(row["speed"], row["delta"]) if below < v < above]
            rows.append(dict(row, speed=[v for v, _ in kept], delta=[d for _, d in kept]))
        if not all(row["speed"] for row in rows):
            return None
        tuned.save("landing", name, dict(body, foot_delta=rows), strengths=["human"])
        kept = self.check(character, rng)
        kept.figures += f" (rows cut to the speeds inside ({below:+.2f}, {above:+.2f}) m/s: {check.figures})"
        return kept

    def search(self, character: str, workers: int, minutes: float, check: Check) -> tuple[dict, int]:
        """calibrate land's sweep (every drop, speed and delta), then its fast-touchdown scan."""
        from ..skills.land.calibrate import calibrate, fast_touchdown
        from ..skills.land.calibrate_grid import grid
        table = calibrate(character, workers)
        fast = fast_touchdown(character, table)
        if fast is not None:
            table["fast_touchdown"] = fast
        table["script"] = "python -m sim_core adapt (calibrate land's sweep, its grid scaled to the body by Fig. 6)"
        table["offered_speeds"] = [round(v, 3) for v in self.wanted_speeds(load_character(character))]
        return table, grid(character).trials


class LeapAdapter(Adapter):
    """The vertical leap's table (human strength): crouch heights, COM offsets and the measured rises
    by L; angles and shares as they are. The broad jump is not carried (it is planned per distance)."""
    skill, table = "leap", "leap"

    def scaled_rows(self, source: CharacterSpec, target: CharacterSpec, body: dict) -> list[dict]:
        """The source's vertical rows, each setting by its units; a row scaled out of a setting's range
        is left out."""
        from ..control.leap import LEAP_SETTINGS
        pair = CharacterPair(source, target)
        columns = body["vertical"]
        settings = {n: c for n, c in columns.items() if n in LEAP_SETTINGS.by_name}
        rows = [scale_settings({n: c[k] for n, c in settings.items()}, LEAP_SETTINGS, pair, GEOMETRIC)
                for k in range(len(columns["com_rise"]))]
        return [row for row in rows if all(LEAP_SETTINGS.by_name[n].minimum <= v <= LEAP_SETTINGS.by_name[n].maximum
                                           for n, v in row.items())]

    def scaled_constants(self, source: CharacterSpec, target: CharacterSpec, body: dict) -> dict:
        """The thrust's and the landing's constants the source uses (its own, else leap_any's),
        scaled geometrically by Fig. 6: the thrust's extension times by L^1/2, so that the legs
        extend at the speeds of a body of their length (with the man's times the child's leaps rose
        0.06-0.12 m, with scaled times 0.10-0.20 m)."""
        from ..control.leap import LEAP_CONSTANTS, leap_constants
        own = vars(leap_constants(source.name))
        return scale_constants({n: own[n] for n in LEAP_CONSTANTS.by_name}, LEAP_CONSTANTS, CharacterPair(source, target),
                               GEOMETRIC)

    def scale(self, source: CharacterSpec, target: CharacterSpec, body: dict) -> tuple[dict, int]:
        """The scaled rows, each leapt once on the new body: the rows that land balanced, with their
        rises as measured (a rise scaled by L missed by 8-15 % on the 70 % man -> woman body)."""
        from .. import tuned
        rows = self.scaled_rows(source, target, body)
        constants = self.scaled_constants(source, target, body)
        # the rows leap with the scaled constants: the body's table holds them (inside adapt's provisional table)
        tuned.save("leap", target.name, {"character": target.name, "script": "python -m sim_core adapt (scaling)",
                                         "constants": constants, "vertical": {}}, strengths=["human"])
        measured = []
        for row in rows:
            t = _run("leap", target.path, params={"low_level": 1, **row}, duration=LEAP_SECONDS)
            if t.meta["outcome"] == "success":
                measured.append((row, t.meta["metrics"]))
        measured.sort(key=lambda m: m[1]["com_rise"])
        vertical = {n: [row[n] for row, _ in measured] for n in (rows[0] if rows else {})}
        for name in ("com_rise", "com_travel", "peak_thrust_grf_body_weights"):
            vertical[name] = [metrics[name] for _, metrics in measured]
        return {"character": target.name,
                "script": f"python -m sim_core adapt (the {source.name}'s vertical leaps and the thrust's and landing's "
                          f"constants scaled by Fig. 6, each row run once: {len(measured)} of {len(rows)} landed "
                          f"balanced, their rises as measured)",
                "constants": constants,
                "vertical": vertical}, len(rows)

    def check(self, character: str, rng) -> Check:
        from .. import tuned
        from ..control.leap import commandable_heights, rise_tolerance
        spec = load_character(character)
        rises = tuned.load("leap", spec.name)["vertical"]["com_rise"]
        if not rises:
            return Check(False, "no leap of the table landed balanced", 0)
        L = leg_length_ratio(load_character("man"), spec)
        wanted = (round(LEAP_HEIGHTS[0] * L, 3), round(LEAP_HEIGHTS[1] * L, 3))
        low, high = commandable_heights(rises)
        top, bottom = min(high, wanted[1]), max(low, wanted[0])
        if top <= bottom:
            return Check(False, f"the table's leaps rise {min(rises):.2f}-{max(rises):.2f} m, outside "
                                f"{wanted[0]:g}-{wanted[1]:g} m ({LEAP_HEIGHTS[0]:g}-{LEAP_HEIGHTS[1]:g} m x L {L:.2f})", 0)
        heights = rng.uniform(bottom, top, size=CHECKS)
        missed, errors = [], []
        for h in heights:
            t = _run("leap", character, params={"height": float(h)}, duration=LEAP_SECONDS)
            rise = t.meta["metrics"].get("com_rise", float("nan"))
            errors.append(abs(rise - h))
            if t.meta["outcome"] != "success" or not abs(rise - h) <= rise_tolerance(h):
                missed.append(f"{h:.2f} m rose {rise:.2f} ({t.meta['outcome']})")
        covered = "" if (bottom, top) == wanted else f" (the table serves {low:.2f}-{high:.2f} m of {wanted[0]:g}-{wanted[1]:g})"
        figures = (f"heights {heights.min():.2f}-{heights.max():.2f} m{covered}: {CHECKS - len(missed)}/{CHECKS} within "
                   f"tolerance and balanced, largest error {max(errors) * 100:.1f} cm"
                   + (f"; missed {', '.join(missed)}" if missed else ""))
        return Check(not missed, figures, CHECKS, covers=(bottom, top) == wanted)

    def search(self, character: str, workers: int, minutes: float, check: Check) -> tuple[dict, int]:
        """calibrate leap's crouch sweep of the vertical table (human strength)."""
        from .. import tuned
        from ..skills.leap.calibrate import calibrate
        current = tuned.load("leap", load_character(character).name) or {}
        mapping = calibrate(character, workers, ["vertical"], current)     # its other tables (broad, unlimited) kept
        mapping["script"] = "python -m sim_core adapt (calibrate leap --only vertical)"
        return mapping, len(mapping["trials_by_table"]["vertical"])


class RunningAdapter(Adapter):
    """The running table: the nearest runner's rows and the laws' constants mass-scaled by Fig. 6
    (calibrate running --scale-from), at its speeds x L^1/2 held inside the schema's range."""
    skill, table = "running", "running"

    def scale(self, source: CharacterSpec, target: CharacterSpec, body: dict) -> tuple[dict, int]:
        from ..skills.running.behaviour import Running
        from ..skills.running.calibrate import scaled_table
        knob = Running.schema.by_name["speed"]
        root = math.sqrt(leg_length_ratio(source, target))
        speeds = sorted({round(min(max(v * root, knob.minimum), knob.maximum), 2) for v in body["speeds"]})
        table = scaled_table(source.path, target.path, speeds, {})     # the source's own constants come along
        return {**table.to_table(),
                "note": f"the {source.name}'s rows and the constants of the running laws mass-scaled by Fig. 6 "
                        "(python -m sim_core adapt); rows that did not run were searched or dropped"}, 0

    def check(self, character: str, rng) -> Check:
        """A 100 s run at every speed of the table (the running's own measure: the gait's mean speed
        over the last 10 s)."""
        from .. import tuned
        speeds = tuned.load("running", load_character(character).name)["speeds"]
        failed, figures = [], []
        for v in speeds:
            m = _run("running", character, params={"speed": float(v)}, duration=RUN_SECONDS).meta["metrics"]
            mean = m["gait"]["mean_speed"]
            figures.append(f"{v:g} m/s: " + (f"fell at {m['fall_time']:.1f} s" if m["fell"] else f"{mean:.3f} m/s"))
            if m["fell"] or abs(mean - v) > SPEED_TOLERANCE * v:
                failed.append(v)
        return Check(not failed, f"{RUN_SECONDS:g} s runs: " + "; ".join(figures), len(speeds), failed=tuple(failed))

    def keep_what_works(self, character: str, check: Check, rng) -> Check | None:
        """The table with only the rows whose runs did not fall and held the speed."""
        from .. import tuned
        name = load_character(character).name
        body = tuned.load("running", name)
        keep = [k for k, v in enumerate(body["speeds"]) if v not in check.failed]
        if not keep:
            return None
        tuned.save("running", name, dict(body, speeds=[body["speeds"][k] for k in keep],
                                         parameters={n: [col[k] for k in keep] for n, col in body["parameters"].items()}),
                   strengths=["human"])
        kept = self.check(character, rng)
        dropped = ", ".join(f"{v:g}" for v in check.failed)
        kept.figures += f" (rows {dropped} m/s dropped: {check.figures})"
        return kept

    def search(self, character: str, workers: int, minutes: float, check: Check) -> tuple[dict, int]:
        """CMA-ES over the five parameters of each row the check saw fail (calibrate running, 15 s
        runs), within the budget; rows that still do not run are dropped by the command."""
        from .. import tuned
        from ..skills.running.calibrate import main as calibrate_running
        name = load_character(character).name
        evaluations = 0
        for k, v in enumerate(check.failed):
            share = minutes / (len(check.failed) - k)
            start = time.monotonic()
            calibrate_running(["--character", character, "--speeds", f"{v:g}", "--method", "cma", "--workers",
                               str(workers), "--duration", f"{RUN_SEARCH_SECONDS:g}", "--minutes", f"{share:.2f}"])
            minutes -= (time.monotonic() - start) / 60.0
            record = tuned.load("running", name).get("evaluation", {}).get("per_speed", {}).get(str(float(v)), {})
            evaluations += int(record.get("evaluations", 0))
        return tuned.load("running", name), evaluations


def board_for(stiffness: float, source: CharacterSpec, target: CharacterSpec, length: float) -> float:
    """The springboard's stiffness (N/m) for ``target`` by Fig. 6 on the board's half period with the
    gymnast on it, pi sqrt((m + deck) / k), a time: x L^1/2 (the deck's mass does not scale, so this is
    not the stiffness's own mass scaling; the board's springs are set for the gymnast's weight)."""
    from ..world.apparatus import BOARD_MASS
    return stiffness * (target.total_mass + BOARD_MASS) / (source.total_mass + BOARD_MASS) / length


class VaultAdapter(Adapter):
    """The vault's table (issue 31): the source's row scaled by Fig. 6 in mass mode (lengths by L,
    times and speeds by L^1/2, the gains by the mass or inertia they move: the row's gains are factors
    on the rig's own servos, so only ``settled_spin`` changes with the mode), and the constants the body
    meets the vault by (``VAULT_BODY_CONSTANTS``: the start's COM height, the board-to-horse gap, the
    horse's height, the board's springs and the run-up speed) scaled as lengths, times and speeds, so the
    apparatus stands for the body as it stood for the source (the man's horse 1.36 m: the men's horse is
    1.35 m; his board 62 kN/m, its half period with him on it 0.128 s, hers 0.120 s x L^1/2; docs/vault.md)."""
    skill, table = "vault", "vault"

    def scale(self, source: CharacterSpec, target: CharacterSpec, body: dict) -> tuple[dict, int]:
        from ..skills.vault.behaviour import VAULT_CONSTANTS, VAULT_SETTINGS, vault_constants
        pair = CharacterPair(source, target)
        shared = vars(vault_constants(source.name))
        constants = {**scale_constants({n: shared[n] for n in VAULT_BODY_CONSTANTS if n != "board_stiffness"},
                                       VAULT_CONSTANTS, pair, MASS),
                     "board_stiffness": board_for(shared["board_stiffness"], source, target, pair.length)}   # by its period
        held = lambda n, v: v if isinstance(v, bool) else min(max(v, VAULT_SETTINGS.by_name[n].minimum),
                                                               VAULT_SETTINGS.by_name[n].maximum)
        # each value held inside its setting's range (a flag such as horse_clav_after -1, "off", stays off;
        # capture_after's 3 s stays 3 s)
        rows = [{"strength": e["strength"], "settings": {n: held(n, v) for n, v in
                                                         scale_settings(e["settings"], VAULT_SETTINGS, pair, MASS).items()}}
                for e in body["vaults"] if e["strength"] == "human"]
        return {"script": f"python -m sim_core adapt (the {source.name}'s vault scaled by Fig. 6, mass mode)",
                "constants": {n: ([round(x, 4) for x in v] if isinstance(v, list) else round(v, 4))
                              for n, v in constants.items()},
                "vaults": [{**e, "settings": {n: round(v, 6) if isinstance(v, float) else v
                                              for n, v in e["settings"].items()}} for e in rows]}, 0

    def check(self, character: str, rng) -> Check:
        """The whole vault at each end of the table's handled_speed (one run where they are one speed):
        the vault's own assessment (one somersault, feet first, at most 11.6 body weights, standing,
        the gesture and the bow)."""
        from ..skills.vault.behaviour import vault_constants
        speeds = sorted(set(vault_constants(load_character(character).name).handled_speed))
        figures, failed = [], []
        for v in speeds:
            t = _run("vault", character, params={"runup_speed": float(v)})
            m = t.meta["metrics"]
            figures.append(f"{v:g} m/s: {t.meta['outcome']} ({m['rotation']:.2f} rad, "
                           f"{m.get('peak_landing_body_weights', float('nan')):.1f} body weights)")
            if t.meta["outcome"] != "success":
                failed.append(float(v))
        return Check(not failed, "; ".join(figures), len(speeds), failed=tuple(failed))

    def search(self, character: str, workers: int, minutes: float, check: Check) -> tuple[dict, int]:
        """The vault's landing search (planning.vault.plan_foot_delta) at each failing speed, from the
        row's foot_delta; the first standing placement is kept in the row."""
        from .. import tuned
        from ..planning.vault import plan_foot_delta
        from ..skills.vault.behaviour import VAULT_SETTINGS
        from ..skills.vault.report import run_at
        name = load_character(character).name
        body = tuned.load("vault", name)
        row = next(e for e in body["vaults"] if e["strength"] == "human")
        knob, trials = VAULT_SETTINGS.by_name["foot_delta"], 0
        for v in check.failed:
            plan = plan_foot_delta(lambda d, v=v: run_at(v, character, overrides=[f"foot_delta={d}"]),
                                   row["settings"]["foot_delta"], knob.minimum, knob.maximum)
            trials += plan["trials"]
            if plan["found"]:
                row["settings"]["foot_delta"] = plan["foot_delta"]
        return dict(body, script=body["script"] + " and its landing searched (planning.vault)"), trials


ADAPTERS = {a.skill: a for a in (BalanceAdapter(), LandingAdapter(), LeapAdapter(), RunningAdapter(), VaultAdapter())}
