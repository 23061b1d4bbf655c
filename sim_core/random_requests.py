"""Random requests (issue 29, "What it must show, measured"): draw jump targets, leap heights and
broad-jump distances at random inside the ranges the skills offer, run each the way a new user's
request runs (an unplanned jump target is planned first, above the loop, through
sim_core.planning, into a temporary plan store), and print for each one line with what the
simulation did and whether it passed TARGETS.md's check, then the pass rate and the time to a
result per skill and character. Writes docs/random_requests.md:

    python -m sim_core report random --seed 1 [--jumps 30 --leaps 20 --broad 20 --boxes 20
                                      --characters man,woman --budget 24 --workers 2]

It is its own module, not a skill room's report.py, because it spans the jump_to_target and leap
skills. The same seed draws the same requests; different seeds draw different ones. Nothing is
written to the shipped tables or to the user's plan store (the plans go to a temporary store
unless --store names one). Times are wall seconds of one request in one worker (plan + simulate),
with ``--workers`` of them running at once on this machine.
"""
from __future__ import annotations

import argparse
import math
import statistics
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .control.leap import commandable_heights, load_mapping, rise_tolerance
from .errors import ParameterError
from .planning.jump import MODEL_TRIALS
from .skills.jump_to_target.region import HEIGHT_REACH
from .tuning import executor_for

# the ranges issue 29 names for a jump to a target on the ground
JUMP_FORWARD = {"man": (0.5, 1.9), "woman": (0.5, 1.6)}     # m forward of the start
JUMP_LATERAL = 0.6                                          # m: lateral offset within +-this
JUMP_AIR_TIME = (0.4, 0.7)                                  # s
BOX_HEIGHT = (0.25, 0.75)                                   # m: onto a box this high, or down from one (issue 29)
BOX_STREAM = 29                                             # the box draws' own random stream (seed, this): the other
                                                            # draws of a seed stay as they were without them
COMMANDED_STREAM = 30                                       # the commanded region's draws' own stream (seed, this)
TURNED_STREAM = 31                                          # the turned commanded region's draws' own stream (seed, this)
SIDEWAYS_STREAM = 32                                        # the sideways commanded region's draws' own stream (seed, this)
LONG_STREAM = 33                                            # the long air times' commanded region's draws' own stream
TURNED_LONG_STREAM = 34                                     # the turned long air times' region's draws' own stream
MID_LONG_STREAM = 35                                        # the mid long row's regions' draws' own stream
BROAD_TOLERANCE = 0.1                                       # TARGETS.md: broad jump travel within 10 %
DRAW_DECIMALS = 3                                           # requests are drawn to the millimetre / millisecond
DEFAULT_BUDGET = 24                                         # trials of a plan: two of the planner's batches
JUMP_SKILLS = ("jump", "box", "commanded", "turned", "sideways", "long", "turned_long", "mid_long")    # draws run as a jump to a target (_jump)
SKILLS = JUMP_SKILLS + ("leap", "broad")
REGION_DRAWS = 1_000_000                                    # box draws tried for one target in the region offered
SHARE_DRAWS = 20_000                                        # box draws that measure the region's share of the box


@dataclass(frozen=True)
class Draw:
    """One random request: ``skill`` "jump" (target_x, target_y, air_time), "box" (target_x,
    target_z, air_time: onto a box target_z high, or down from one -target_z high, straight ahead),
    "commanded" (a jump's, in the commanded region outside the measured one), "turned" (a jump's, in the
    turned commanded region outside the measured one: turn first, then forward), "sideways" (a jump's,
    straight to the side in the sideways commanded region: a quarter turn first), "long" (a jump's, in the long
    air times' commanded region outside the measured one: the vertical thrust), "turned_long" (a jump's, in the
    turned long air times' commanded regions outside the measured one: the hop first, then the long row, or nearer the near
    long row), "mid_long" (a jump's, in the turned mid long row's region outside the measured one: the hop first, then
    the mid long row), "leap" (height) or
    "broad" (distance), with its numbers in ``values``."""
    skill: str
    character: str
    values: tuple

    def describe(self) -> str:
        if self.skill in JUMP_SKILLS and self.skill != "box":
            x, y, t = self.values
            return f"jump to ({x:.3f}, {y:+.3f}) m in {t:.3f} s"
        if self.skill == "box":
            x, z, t = self.values
            return f"jump {'onto' if z > 0 else 'down'} {abs(z):.3f} m box, {x:.3f} m in {t:.3f} s"
        if self.skill == "leap":
            return f"leap {self.values[0]:.3f} m"
        return f"broad jump {self.values[0]:.3f} m"


def leap_height_range(character: str) -> tuple[float, float]:
    """The heights the character's vertical leap (human torque limits) accepts: commandable_heights
    of its calibrated rises."""
    return commandable_heights(load_mapping(character)["vertical"]["com_rise"])


def broad_range(character: str) -> tuple[float, float]:
    """The calibrated broad-jump distances' range (the COM travel the calibrated rows measured)."""
    travels = load_mapping(character).get("broad", {}).get("com_travel", [])
    if not len(travels):
        raise ParameterError(f"the broad jump of {character} is not calibrated: run python -m sim_core calibrate "
                             f"leap --only broad")
    return float(min(travels)), float(max(travels))


def drawn_inside(rng, low: float, high: float) -> float:
    """A value uniform in [low, high], to DRAW_DECIMALS, rounded inward at the ends (a height drawn just above
    the lowest offered and rounded down was refused)."""
    step = 10.0 ** -DRAW_DECIMALS
    inner = (math.ceil(low / step - 1e-9) * step, math.floor(high / step + 1e-9) * step)
    return round(min(max(float(rng.uniform(low, high)), inner[0]), inner[1]), DRAW_DECIMALS)


def draw_requests(seed: int, characters, jumps: int, leaps: int, broads: int, boxes: int = 0,
                  commanded: int = 0, turned: int = 0, sideways: int = 0, long: int = 0, turned_long: int = 0,
                  mid_long: int = 0) -> list[Draw]:
    """The random requests of ``seed`` (NumPy's default generator), per character: ``jumps`` jump
    targets, ``leaps`` leap heights and ``broads`` broad-jump distances, uniform in their ranges;
    then ``boxes`` box targets per character (draw_box_jump, from their own stream); then ``commanded``
    targets per character that has a commanded region (draw_commanded, from their own stream); then
    ``turned`` targets per character that has a turned commanded region (draw_turned, their own stream); then
    ``sideways`` targets per character that has a sideways commanded region (draw_sideways, their own stream); then
    ``long`` targets per character that has a long air times' commanded region (draw_long, their own stream); then
    ``turned_long`` targets per character that has a turned long air times' region (draw_turned_long, their own stream); then
    ``mid_long`` targets per character that has a turned mid long row (draw_mid_long, their own stream)."""
    rng = np.random.default_rng(seed)
    drawn = []
    for character in characters:
        if character not in JUMP_FORWARD:
            raise ParameterError(f"character {character!r}: the random requests' ranges are known for "
                                 f"{', '.join(JUMP_FORWARD)}")
        forward, heights, distances = JUMP_FORWARD[character], leap_height_range(character), broad_range(character)
        for _ in range(jumps):
            drawn.append(Draw("jump", character, draw_jump(rng, character)))
        for _ in range(leaps):
            drawn.append(Draw("leap", character, (drawn_inside(rng, *heights),)))
        for _ in range(broads):
            drawn.append(Draw("broad", character, (drawn_inside(rng, *distances),)))
    boxes_rng = np.random.default_rng((seed, BOX_STREAM))
    for character in characters:
        drawn += [Draw("box", character, draw_box_jump(boxes_rng, character)) for _ in range(boxes)]
    from .skills.jump_to_target.commanded import SIDEWAYS_WAYS, table
    # the commanded take-off's regions, each from its own stream, for the characters whose table has the region
    for skill, count, stream, regions, draw in (("commanded", commanded, COMMANDED_STREAM, ("region",), draw_commanded),
                                               ("turned", turned, TURNED_STREAM, ("turned_region",), draw_turned),
                                               ("sideways", sideways, SIDEWAYS_STREAM,
                                                tuple(f"{way}_region" for way in SIDEWAYS_WAYS), draw_sideways),
                                               ("long", long, LONG_STREAM, ("long_region",), draw_long),
                                               ("turned_long", turned_long, TURNED_LONG_STREAM,
                                                tuple(f"{way}_region" for way in TURNED_LONG_WAYS), draw_turned_long),
                                               ("mid_long", mid_long, MID_LONG_STREAM,
                                                ("turned_mid_long_region",), draw_mid_long)):
        stream_rng = np.random.default_rng((seed, stream))
        for character in characters:
            if count and any((table(character) or {}).get(key) is not None for key in regions):
                drawn += [Draw(skill, character, draw(stream_rng, character)) for _ in range(count)]
    return drawn


def draw_sideways(rng, character: str) -> tuple:
    """A jump target to the side (issue 29's left and right jumps), left or right equally likely, its distance,
    bearing and air time uniform over the character's sideways commanded regions (the table's ``sideways_region``: the
    quarter turn, then the short row; ``sideways_<row>_region``: then a long row), drawn again until
    commanded.commanded_way flies it one of SIDEWAYS_WAYS; as (target_x, target_y, air_time)."""
    from .skills.jump_to_target.commanded import SIDEWAYS_WAYS, commanded_way, table
    regions = [table(character)[f"{way}_region"] for way in SIDEWAYS_WAYS if f"{way}_region" in table(character)]
    bounds = {k: (min(r[k][0] for r in regions), max(r[k][1] for r in regions)) for k in ("distance", "bearing", "air_time")}
    for _ in range(REGION_DRAWS):
        distance, bearing, air_time = (float(rng.uniform(*bounds[k])) for k in ("distance", "bearing", "air_time"))
        side = float(rng.choice((-1.0, 1.0)))
        values = tuple(round(v, DRAW_DECIMALS) for v in (distance * math.cos(bearing), side * distance * math.sin(bearing),
                                                          air_time))
        if commanded_way(character, values[:2], values[2]) in SIDEWAYS_WAYS:
            return values
    raise ParameterError(f"no target of the {character}'s sideways commanded regions in {REGION_DRAWS} draws")


def draw_turned(rng, character: str, ways: tuple = ("turned",)) -> tuple:
    """A jump target uniform in issue 29's box that the character's turned commanded region holds
    (commanded.commanded_way one of ``ways``: "turned", or "turned_long" / "turned_near_long" for its turned long air
    times' regions) and its measured jumps do not offer (region.offered) - one that the turn and the commanded take-off
    serve - drawn again until it is; as (target_x, target_y, air_time)."""
    from .skills.jump_to_target.commanded import commanded_way
    from .skills.jump_to_target.region import offered
    for _ in range(REGION_DRAWS):
        values = box_draw(rng, character)
        if commanded_way(character, values[:2], values[2]) in ways and not offered(character, values[:2], values[2]):
            return values
    raise ParameterError(f"no target of issue 29's box in {REGION_DRAWS} draws lies in the {character}'s "
                         f"{' or '.join(ways)} commanded region outside the region its measured jumps offer")


TURNED_LONG_WAYS = ("turned_long", "turned_long_short", "turned_near_long", "turned_far_long", "turned_deep_long",
                    "turned_far_short", "turned_near_short", "turned_near_deep_long", "turned_mid_deep_long")   # --turned-long's rows


def draw_turned_long(rng, character: str) -> tuple:
    """draw_turned in the table's turned long air times' regions (``turned_long_region``: the hop, then the long row,
    and ``turned_long_short_region``: the same at shorter air times; ``turned_near_long_region``: the hop, then the near
    long row; ``turned_far_long_region``: the hop, then the far long row (its own smaller lean push);
    ``turned_deep_long_region``: the hop, then the long row at its deepest crouches; ``turned_far_short_region``
    / ``turned_near_short_region``: the hop, then the long / near long row at its shallowest crouches;
    ``turned_near_deep_long_region`` / ``turned_mid_deep_long_region``: the hop, then the near / mid deep row), uniform
    in issue 29's box where one of them holds it."""
    return draw_turned(rng, character, TURNED_LONG_WAYS)


def draw_mid_long(rng, character: str) -> tuple:
    """draw_turned in the table's ``turned_mid_long_region`` (the hop, then the mid long row), uniform in issue 29's box
    where it holds it."""
    return draw_turned(rng, character, ("turned_mid_long",))


def draw_commanded(rng, character: str, keys: tuple = ("region",)) -> tuple:
    """A jump target uniform in the character's commanded region (skills/jump_to_target/commanded.py, the union of
    its table's boxes ``keys``: drawn in the box bounding them, again until one of them holds it) that its measured
    jumps do not offer (region.offered) - one the commanded take-off serves - drawn again until it is; as
    (target_x, target_y, air_time)."""
    from .skills.jump_to_target.commanded import table
    from .skills.jump_to_target.region import offered
    body, names = table(character), ("target_x", "target_y", "air_time")
    boxes = [body[key] for key in keys if body.get(key) is not None]
    bounds = {k: (min(b[k][0] for b in boxes), max(b[k][1] for b in boxes)) for k in names}
    for _ in range(REGION_DRAWS):
        values = tuple(round(float(rng.uniform(*bounds[k])), DRAW_DECIMALS) for k in names)
        if (any(all(b[k][0] <= v <= b[k][1] for k, v in zip(names, values)) for b in boxes)
                and not offered(character, values[:2], values[2])):
            return values
    raise ParameterError(f"no target of the {character}'s commanded region ({', '.join(keys)}) in {REGION_DRAWS} draws "
                         f"lies outside the region its measured jumps offer")


def draw_long(rng, character: str) -> tuple:
    """draw_commanded in the table's long air times' boxes: ``long_region`` (the vertical thrust's) and, where the
    table has them, ``near_long_region`` (the near row's), ``deep_long_region`` (the long row's deepest crouches) and
    ``far_short_region`` / ``near_short_region`` (the long / near long row's shallowest crouches) and
    ``near_deep_long_region`` / ``mid_deep_long_region`` (the near / mid deep rows), uniform in their union."""
    return draw_commanded(rng, character, ("long_region", "near_long_region", "deep_long_region", "far_short_region",
                                           "near_short_region", "near_deep_long_region", "mid_deep_long_region"))


def box_target_draw(rng, character: str) -> tuple:
    """A box target uniform in issue 29's span: forward JUMP_FORWARD, straight ahead, onto a box
    BOX_HEIGHT high or down from one (either way equally likely), air time JUMP_AIR_TIME; as
    (target_x, target_z, air_time)."""
    x, h, t = rng.uniform(*JUMP_FORWARD[character]), rng.uniform(*BOX_HEIGHT), rng.uniform(*JUMP_AIR_TIME)
    z = h if rng.uniform() < 0.5 else -h
    return tuple(round(float(v), DRAW_DECIMALS) for v in (x, z, t))


def draw_box_jump(rng, character: str) -> tuple:
    """A box target (box_target_draw) drawn again until it lies in the region the character is
    offered (region.in_region: its measured jumps onto and down from boxes, and its commanded take-off's
    jumps down from them)."""
    from .skills.jump_to_target.region import in_region
    for _ in range(REGION_DRAWS // 10):
        x, z, t = box_target_draw(rng, character)
        if in_region(character, (x, 0.0, z), t):
            return x, z, t
    raise ParameterError(f"no box target of the {character} in {REGION_DRAWS // 10} draws lies in the region offered "
                         f"(python -m sim_core.planning.jump_model --boxes-only)")


def box_draw(rng, character: str) -> tuple:
    """A jump target uniform in issue 29's box (JUMP_FORWARD, JUMP_LATERAL, JUMP_AIR_TIME)."""
    values = (rng.uniform(*JUMP_FORWARD[character]), rng.uniform(-JUMP_LATERAL, JUMP_LATERAL), rng.uniform(*JUMP_AIR_TIME))
    return tuple(round(float(v), DRAW_DECIMALS) for v in values)


def draw_jump(rng, character: str) -> tuple:
    """A jump target uniform in the part of issue 29's box that the character is offered (region.in_region:
    its measured jumps' region and its commanded take-off's; outside them a request is refused before
    simulating), drawn again until it is; the whole box when the character's jumps are not measured."""
    from .skills.jump_to_target.region import in_region, model
    if model(character) is None:
        return box_draw(rng, character)
    for _ in range(REGION_DRAWS):
        values = box_draw(rng, character)
        if in_region(character, values[:2], values[2]):
            return values
    raise ParameterError(f"no jump target of the {character} in {REGION_DRAWS} draws from issue 29's box lies in "
                         f"the region offered (python -m sim_core.planning.jump_model)")


def region_share(character: str, seed: int, draws: int = SHARE_DRAWS) -> float:
    """The share of issue 29's box (uniform draws) that the character is offered (region.in_region)."""
    from .skills.jump_to_target.region import in_region
    rng = np.random.default_rng(seed)
    hits = 0
    for _ in range(draws):
        values = box_draw(rng, character)
        hits += in_region(character, values[:2], values[2])
    return hits / draws


def box_region_share(character: str, seed: int, draws: int = SHARE_DRAWS) -> tuple[float, float, float]:
    """The share of issue 29's box targets (box_target_draw, uniform) the character is offered: all,
    onto boxes, down from them (region.in_region)."""
    from .skills.jump_to_target.region import in_region
    rng = np.random.default_rng((seed, BOX_STREAM, 1))
    hits = {True: [0, 0], False: [0, 0]}
    for _ in range(draws):
        x, z, t = box_target_draw(rng, character)
        hits[z > 0][0] += in_region(character, (x, 0.0, z), t)
        hits[z > 0][1] += 1
    share = lambda a, b: a / b if b else 0.0       # noqa: E731
    return (share(hits[True][0] + hits[False][0], draws), share(*hits[True]), share(*hits[False]))


def evaluate(draw: Draw, budget: int, store: str) -> dict:
    """Run one request as a user's would and judge it by TARGETS.md; a module-level function so a
    process pool can run it. ``store``: the plan store a jump is planned into."""
    from .skills.jump_to_target.behaviour import plan_store_at
    began = time.perf_counter()
    result = {"draw": draw}
    with plan_store_at(store):              # the plans go to the report's store, not the user's
        try:
            result.update(_jump(draw, budget) if draw.skill in JUMP_SKILLS else _leap(draw))
        except ParameterError as exc:
            result.update(refused=str(exc), passed=False)
    result["seconds"] = time.perf_counter() - began
    return result


def _jump(draw: Draw, budget: int) -> dict:
    from .planning import plan_and_store, planned
    from .planning.jump import within_tolerance
    from .simulate import RunRequest, run
    from .skills.jump_to_target.behaviour import landing_measures
    if draw.skill == "box":
        x, z, air_time = draw.values
        y = 0.0
    else:
        (x, y, air_time), z = draw.values, 0.0
    params = {"target_x": x, "target_y": y, "target_z": z, "air_time": air_time}
    out = {"plan_seconds": 0.0, "planned_trials": 0}
    if planned(draw.character, params) is None:
        began = time.perf_counter()
        plan = plan_and_store(draw.character, params, budget=budget)
        out.update(plan_seconds=time.perf_counter() - began, planned_trials=plan["trials"], plan_found=plan["found"])
        if not plan["found"]:                 # the run would be refused; the nearest trial is what happened
            return {**out, "measured": plan["measured"], "passed": False,
                    "refused": f"no plan found in {plan['trials']} trials (nearest trial shown)"}
    measured = landing_measures(run(RunRequest("jump_to_target", draw.character, params=params)))
    return {**out, "measured": measured, "passed": bool(within_tolerance(measured, (x, y, z), air_time))}


def _leap(draw: Draw) -> dict:
    from .simulate import RunRequest, run
    commanded = draw.values[0]
    params = {"height": commanded} if draw.skill == "leap" else {"distance": commanded}
    trajectory = run(RunRequest("leap", draw.character, params=params, duration=5.0))
    metrics, outcome = trajectory.meta["metrics"], trajectory.meta["outcome"]
    achieved = metrics["com_rise"] if draw.skill == "leap" else metrics["com_travel"]
    tolerance = rise_tolerance(commanded) if draw.skill == "leap" else BROAD_TOLERANCE * commanded
    return {"achieved": float(achieved), "tolerance": float(tolerance), "outcome": outcome,
            "passed": bool(abs(achieved - commanded) <= tolerance and outcome == "success")}


def result_line(r: dict) -> str:
    """One request's line: the request, what happened (measured), PASS or MISS, and the time."""
    draw = r["draw"]
    head = f"{draw.character:5s} {draw.describe():38s}"
    plan = (f"; planned {r['planned_trials']} trials in {r['plan_seconds']:.1f} s" if r.get("planned_trials") else "")
    verdict = "PASS" if r["passed"] else "MISS"
    if "measured" in r:
        m = r["measured"]
        x, y = (draw.values[0], 0.0) if draw.skill == "box" else draw.values[:2]
        error = float(np.hypot(m["landing"][0] - x, m["landing"][1] - y))
        on = (f" on {m.get('landing_height', float('nan')):+.2f} m" if draw.skill == "box" else "")
        what = (f"landed at ({m['landing'][0]:.3f}, {m['landing'][1]:+.3f}) m{on}, {error * 100:.1f} cm off, air "
                f"{m['air_time']:.3f} s ({m['air_time'] - draw.values[2]:+.3f}), {m['outcome']}")
        if "refused" in r:
            what = f"refused: {r['refused']}: {what}"
    elif "refused" in r:
        what = f"refused: {r['refused']}"
    else:
        verb = "rose" if draw.skill == "leap" else "travelled"
        what = (f"{verb} {r['achieved']:.3f} m vs {draw.values[0]:.3f} (+-{r['tolerance']:.3f}), {r['outcome']}")
    return f"{head} {verdict}  {what}{plan}; {r['seconds']:.1f} s"


def summary_lines(results: list[dict]) -> list[str]:
    """Per skill and character: passed / drawn, and the time to a result (median, worst)."""
    lines = ["| skill | character | passed / drawn | time to a result, median (s) | worst (s) |",
             "| --- | --- | --- | --- | --- |"]
    for skill in SKILLS:
        for character in dict.fromkeys(r["draw"].character for r in results):
            mine = [r for r in results if r["draw"].skill == skill and r["draw"].character == character]
            if not mine:
                continue
            seconds = [r["seconds"] for r in mine]
            passed = sum(r["passed"] for r in mine)
            lines.append(f"| {skill} | {character} | {passed} / {len(mine)} ({100 * passed / len(mine):.0f} %) | "
                         f"{statistics.median(seconds):.1f} | {max(seconds):.1f} |")
    return lines


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seed", type=int, required=True, help="draws the requests (different seeds, different draws)")
    parser.add_argument("--jumps", type=int, default=30, help="jump targets per character")
    parser.add_argument("--leaps", type=int, default=20, help="leap heights per character")
    parser.add_argument("--broad", type=int, default=20, help="broad-jump distances per character")
    parser.add_argument("--boxes", type=int, default=0, help="box targets per character (onto or down from a box)")
    parser.add_argument("--commanded", type=int, default=0,
                        help="targets per character in its commanded region, outside its measured jumps' region")
    parser.add_argument("--turned", type=int, default=0,
                        help="targets per character in its turned commanded region, outside its measured jumps' region")
    parser.add_argument("--sideways", type=int, default=0,
                        help="targets straight to the side per character in its sideways commanded region")
    parser.add_argument("--long", type=int, default=0,
                        help="targets per character in its long air times' commanded region, outside its measured jumps' region")
    parser.add_argument("--turned-long", type=int, default=0,
                        help="targets per character in its turned long air times' region, outside its measured jumps' region")
    parser.add_argument("--mid-long", type=int, default=0,
                        help="targets per character in its turned mid long row's region, outside its measured jumps' region")
    parser.add_argument("--characters", default="man,woman")
    parser.add_argument("--budget", type=int, default=DEFAULT_BUDGET, help="trials of each unplanned jump's plan")
    parser.add_argument("--workers", type=int, default=2, help="requests run at once, one process each")
    parser.add_argument("--store", help="plan store for the jumps' plans (default: a temporary one, removed after)")
    parser.add_argument("--out", default="docs/random_requests.md")
    args = parser.parse_args(argv)
    for name in ("jumps", "leaps", "broad", "boxes", "commanded", "turned", "sideways", "long", "turned_long", "mid_long"):
        if getattr(args, name) < 0:
            parser.error(f"--{name}={getattr(args, name)}: must be 0 or more")
    if args.budget < 1:
        parser.error(f"--budget={args.budget}: must be at least 1 trial")
    characters = [c.strip() for c in args.characters.split(",") if c.strip()]
    draws = draw_requests(args.seed, characters, args.jumps, args.leaps, args.broad, args.boxes, args.commanded, args.turned,
                          args.sideways, args.long, args.turned_long, args.mid_long)
    command = (f"python -m sim_core report random --seed {args.seed} --jumps {args.jumps} --leaps {args.leaps} "
               f"--broad {args.broad}{f' --boxes {args.boxes}' if args.boxes else ''}"
               f"{f' --commanded {args.commanded}' if args.commanded else ''}"
               f"{f' --turned {args.turned}' if args.turned else ''}"
               f"{f' --sideways {args.sideways}' if args.sideways else ''}{f' --long {args.long}' if args.long else ''}"
               f"{f' --turned-long {args.turned_long}' if args.turned_long else ''}"
               f"{f' --mid-long {args.mid_long}' if args.mid_long else ''} --characters {','.join(characters)} --budget {args.budget} "
               f"--workers {args.workers}")
    print(command, flush=True)
    began = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="random_requests_plans_") as temporary:
        store = str(Path(args.store).expanduser().resolve()) if args.store else temporary
        with executor_for(args.workers) as executor:
            futures = [executor.submit(evaluate, draw, args.budget, store) for draw in draws]
            results = []
            for future in futures:
                results.append(future.result())
                print(result_line(results[-1]), flush=True)
    total = time.perf_counter() - began
    summary = summary_lines(results)
    print("\n".join(summary))
    shares = ", ".join(f"{100 * region_share(c, args.seed):.1f} % ({c})" for c in characters) if args.jumps else "not drawn"
    print(f"region offered: {shares} of issue 29's box")
    box_shares = {c: box_region_share(c, args.seed) for c in characters} if args.boxes else {}
    box_text = "; ".join(f"{c} {100 * a:.1f} % (onto {100 * u:.1f} %, down {100 * d:.1f} %)"
                         for c, (a, u, d) in box_shares.items())
    if box_shares:
        print(f"box region offered: {box_text} of issue 29's box targets")
    print(f"{len(results)} requests in {total:.0f} s")
    text = ["# Random requests (issue 29)", "",
            "Generated by", "", "```", command, "```", "",
            f"Seed {args.seed}. Every figure is measured off the simulation. Checks (TARGETS.md): a jump lands the "
            "middle of the feet within 5 cm of the target with the air time within 0.05 s and ends balanced "
            "(sim_core.planning.jump.within_tolerance); a leap rises within sim_core.control.leap.rise_tolerance "
            "(+-10 %, +-3 cm below 0.3 m) and lands balanced; a broad jump's COM travels within 10 % and it lands "
            "balanced. Jump targets are drawn uniformly in issue 29's box (forward 0.5-1.9 m (man) / 0.5-1.6 m "
            "(woman), lateral within +-0.6 m, air time 0.4-0.7 s) and drawn again until they lie in the region "
            "the character is offered (sim_core.skills.jump_to_target.region: where one of its measured balanced "
            "jumps, python -m sim_core.planning.jump_model, lands within the tolerances, or in the box its commanded "
            "take-off was measured in, skills/jump_to_target/commanded.py, the man's and the woman's; any other target is "
            f"refused before simulating, naming the limit). The region offered is {shares} of the box "
            f"({SHARE_DRAWS} uniform draws). "
            + (f"Box targets (--boxes) are drawn straight ahead, forward as above, onto a box 0.25-0.75 m high or down "
               f"from one (either equally likely), air time 0.4-0.7 s, and drawn again until they lie in the region "
               f"offered (where one of its measured jumps landed balanced at the measured heights on both sides, "
               f"{HEIGHT_REACH * 100:.0f} cm apart, within the tolerances interpolated; or where its commanded take-off's "
               f"box regions hold it - down_region, high_down_region, a straight row's <row>_onto_region / <row>_down_region (long_onto_region, "
               f"long_down_region, near_long_down_region, ...): the same lift-off on flat ground lands in its commanded region or that row's region; <row>_high_onto_region: "
               f"the same lift-off lands within that row's forward distances with a higher lift-off than the row flies "
               f"(within the take-off); low_down_regions: a lower lift-off by a shallower "
               f"crouch; push_down_regions: lower still, within a forward speed; a straight row's <row>_down_regions (far_short_down_regions): "
               f"that row down from the box within its boxes' heights, lift-offs and forward speeds; planned as a commanded target): {box_text} of those targets "
               f"({SHARE_DRAWS} uniform draws). " if box_shares else "")
            + ("Commanded targets (--commanded) are drawn uniformly in the commanded region of each character "
               "that has one (sim_core.skills.jump_to_target.commanded's table: the man's and the woman's) and drawn again until "
               "its measured jumps do not offer them, so that the commanded take-off alone serves them "
               "(sim_core.planning.commanded: at most 5 aimed jumps - the man's 9 - then at most 8 foot placements). "
               if args.commanded else "")
            + ("Turned targets (--turned) are drawn uniformly in issue 29's box and drawn again until they lie in "
               "the turned commanded region of each character that has one (the table's turned_region: the man's and the woman's) "
               "and outside the region its measured jumps offer: the jump turns first by one hop toward the target "
               "and flies the commanded take-off forward (sim_core.planning.commanded.plan_turned: the aimed distance "
               "and the turn, then the foot placements). " if args.turned else "")
            + ("Sideways targets (--sideways) are drawn straight to the side (target_x 0), left or right, the distance "
               "and air time uniform in the sideways commanded region of each character that has one (the table's "
               "sideways_region and each sideways_<row>_region it holds, a row steering by its own quarter map where the table has "
               "sideways_<row>_lines): "
               "the jump turns a quarter first by two hops (the leap's turn_first, the one whose measured jump's line "
               "passes nearest the target) and flies the commanded take-off or the row forward "
               "(sim_core.planning.commanded.plan_turned). " if args.sideways else "")
            + ("Long air time targets (--long) are drawn uniformly in the long air times' commanded region of each "
               "character that has one (the table's long_region: the man's and the woman's) and drawn again until its measured jumps do "
               "not offer them: the commanded take-off with the leap's vertical thrust and its own crouch pairs "
               "(skills/jump_to_target/commanded.py long_body), aimed as the commanded targets; where the table has a "
               "near_long_region too (the man's), uniformly in the union of both, the nearer ones flown by its near row "
               "(near_long_body: its own lean push and crouch pairs), and in its deep_long_region (the man's) the longest air "
               "times, by the long row at its deepest crouches (deep_long_body), in its near_deep_long_region (the man's) by the near "
               "row at its deepest crouches (near_deep_long_body), in its mid_deep_long_region (the man's) by the long row with its "
               "own push at its deepest crouches (mid_deep_long_body). " if args.long else "")
            + ("Turned long air time targets (--turned-long) are drawn uniformly in issue 29's box and drawn again until "
               "they lie in the turned long air times' region of each character that has one (the table's "
               "turned_long_region, turned_long_short_region (the same at shorter air times: the woman's) and turned_near_long_region "
               "where the table has it: the man's) and outside the region "
               "its measured jumps offer: the jump turns first by one hop toward the target (as the turned targets) and "
               "flies the long row forward (plan_turned with turned_long_body; in turned_near_long_region the near long "
               "row, near_long_body; in turned_deep_long_region, the man's, the long row at its deepest crouches, "
               "deep_long_body; in turned_near_deep_long_region, the man's, the near long row at its deepest crouches, "
               "near_deep_long_body; in turned_mid_deep_long_region, the man's, the mid deep row, mid_deep_long_body; "
               "in turned_far_long_region, the woman's, the long row with its own smaller lean push, far_long_body). "
               if args.turned_long else "")
            + ("Mid long air time targets (--mid-long) are drawn uniformly in issue 29's box and drawn again until they lie "
               "in the turned mid long row's region of each character that has one (the table's turned_mid_long_region: "
               "the man's) and outside the region its measured jumps offer: the hop first, then the long row with the mid "
               "row's own lean push and crouch pairs (plan_turned with mid_long_body). " if args.mid_long else "")
            + "A target without a stored plan is planned first (into a temporary "
            "plan store; on flat ground or a box from the measured jumps, at most "
            f"{min(args.budget, MODEL_TRIALS)} trials; in the commanded region only, the commanded take-off aimed "
            "and its landing planned, planning/commanded.py) and then simulated; a plan that found nothing within the "
            "tolerances is a miss, shown with its nearest trial. Leap heights within each character's "
            "commandable range (human torque limits); broad jumps within the calibrated distances. Times are "
            f"wall seconds of one request (plan + simulate) in one of {args.workers} worker processes running at "
            f"once; {len(results)} requests took {total:.0f} s.", "",
            *summary, "", "## Every request", "", "```", *(result_line(r) for r in results), "```", ""]
    Path(args.out).parent.mkdir(parents=True, exist_ok=True)
    Path(args.out).write_text("\n".join(text))
    print(f"wrote {args.out}")
    return 0
