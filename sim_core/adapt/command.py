"""``python -m sim_core adapt --character F.json [--skills all]``: adapt every skill to a body and
report what works (issue 28 part 7; Hodgins & Pollard 1997 §5).

For each skill with an adapter (``sim_core.adapt.skills``: balance, land, leap, running):
- the character's own table, if it has one, is checked as it is and never replaced (a calibrated
  character is searched again by ``calibrate SKILL``, not here);
- otherwise the nearest calibrated character's table is scaled by Fig. 6, written through the store
  and checked by measured runs of random requests;
- where the check fails and budget is left, the skill's search runs and the result is checked again;
- the landing is adapted first (the leap lands), with the leap's constants scaled to the body as the
  leap's adapter will write them (``LandingAdapter.runs_with``: a provisional leap table holding
  only them, removed afterwards), not with leap_any's;
- a skill that still fails is **refused**: its provisional table is removed (or the one that was
  there restored byte for byte: ``tuned.provisional``), so the body is never offered a skill that
  fell; an adapter may keep the part that works instead (``keep_what_works``: a running table keeps
  the rows that ran and drops the others).

Every other skill is run once with its default request: refused before simulating (and why), or
the outcome measured. The report is a Markdown table, skill x character: works / refused, the
measured figures, simulated runs (checks and searches) and wall time.

Resumable: each finished skill is recorded in ``<out>/state.json`` (written whole after each skill);
a rerun skips the recorded ones (``--redo`` runs them all again, ``--redo SKILL ...`` those). Stopped with Ctrl-C, the skill under
way (or killed with SIGTERM) leaves the tables as they were. ``--minutes`` is the budget of the searches: a search starts only
while budget is left and gets its share of what is left.
"""
from __future__ import annotations

import json
import signal
import time
import zlib
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from .skills import ADAPTERS, Check, nearest_source
from .. import tuned
from ..character.spec import CharacterSpec, load_character
from ..errors import ParameterError
from ..files import write_atomically


@dataclass
class Result:
    skill: str
    status: str              # works / works in part of the range / refused / fails its check (own table kept)
    route: str               # own table / scaled from X / scaled from X and searched / default request
    figures: str
    runs: int = 0            # simulated runs: the checks' and the searches'
    wall_seconds: float = 0.0


def adapt_skill(skill: str, character: str, rng, workers: int, deadline: float, say) -> Result:
    """One skill carried to the body, inside its adapter's context (the landing: with the leap's
    constants scaled to the body, which the leap's adapter writes only after it)."""
    spec = load_character(character)
    with ADAPTERS[skill].runs_with(spec):
        return _adapt_skill(skill, character, spec, rng, workers, deadline, say)


def _adapt_skill(skill: str, character: str, spec: CharacterSpec, rng, workers: int, deadline: float, say) -> Result:
    adapter = ADAPTERS[skill]
    started = time.monotonic()
    result = lambda state, route, check, runs: Result(skill, state, route, check.figures, runs,
                                                       time.monotonic() - started)
    if adapter.table is None:
        check = adapter.check(character, rng)
        return result(status(check), "no table (the controller reads the body)", check, check.runs)
    if tuned.exists(adapter.table, spec.name):      # a calibrated character's table is checked, never replaced here
        check = adapter.check(character, rng)
        say(f"{skill}: own table: {check.figures}")
        if not check.works:
            check.figures += f"; `calibrate {skill}` searches it again"
        return result(status(check) if check.works else "fails its check (own table kept)", "own table", check,
                      check.runs)
    source_name = nearest_source(spec, tuned.characters_of(adapter.table))
    if source_name is None:
        return Result(skill, "refused", "no calibrated character to scale from", "-")
    with tuned.provisional(adapter.table, spec.name) as provisional:
        body, runs = adapter.scale(load_character(source_name), spec, tuned.load(adapter.table, source_name))
        tuned.save(adapter.table, spec.name, body, strengths=["human"])
        route = f"scaled from the {source_name}"
        check = adapter.check(character, rng)
        runs += check.runs
        say(f"{skill}: {route}: {check.figures}")
        if not (check.works and check.covers):
            minutes = (deadline - time.monotonic()) / 60.0
            if minutes <= 0:
                check.figures += " (no budget left for a search)"
            else:
                say(f"{skill}: searching ({minutes:.0f} min of budget left)")
                with tuned.provisional(adapter.table, spec.name) as searched_table:
                    body, evaluations = adapter.search(character, workers, minutes, check)
                    tuned.save(adapter.table, spec.name, body, strengths=["human"])
                    searched = adapter.check(character, rng)
                    runs += evaluations + searched.runs
                    say(f"{skill}: {route} and searched: {searched.figures}")
                    # kept unless the scaled table works and the search's works less: a search that
                    # fails where the scaled table failed too is the body's own calibration, narrowed next
                    if not check.works or (searched.works, searched.covers) >= (check.works, check.covers):
                        searched_table.keep()
                        check, route = searched, route + " and searched"
                    else:                      # the search's table checked worse: the scaled one is put back
                        route += f" (searched; its table checked worse and was not kept: {searched.figures})"
        if not check.works:                    # e.g. a running table without the rows that did not run
            narrowed = adapter.keep_what_works(character, check, rng)
            if narrowed is not None:
                runs += narrowed.runs
                check = narrowed
        if check.works:
            provisional.keep()
        return result(status(check), route, check, runs)


def status(check: Check) -> str:
    return ("works" if check.covers else "works in part of the range") if check.works else "refused"


def try_default(skill: str, character: str) -> Result:
    """A skill without an adapter, run once with its default request."""
    from ..simulate import RunRequest, run
    started = time.monotonic()
    try:
        trajectory = run(RunRequest(skill, character))
    except ParameterError as refusal:
        return Result(skill, "refused", "not adapted (no adapter scales its table)", str(refusal).split("\n")[0], 0,
                      time.monotonic() - started)
    outcome = trajectory.meta["outcome"]
    return Result(skill, "works" if outcome == "success" else "refused", "default request as it is",
                  f"outcome {outcome} in {trajectory.arrays['time'][-1]:.1f} s", 1, time.monotonic() - started)


def skills_of(names: list[str]) -> list[str]:
    from ..skills import available_behaviours
    every = available_behaviours()
    if names == ["all"]:          # the adapted skills first, in ADAPTERS' order (the leap lands: the landing first)
        return [*ADAPTERS, *(n for n in every if n not in ADAPTERS)]
    unknown = [n for n in names if n not in every]
    if unknown:
        raise ParameterError(f"--skills {' '.join(unknown)}: unknown skill; available: all, {', '.join(every)}")
    return names


def markdown(character: CharacterSpec, results: list[Result]) -> str:
    lines = [f"**{character.name}** ({character.total_mass:.1f} kg)", "",
             "| skill | result | route | measured | runs | wall s |", "| --- | --- | --- | --- | --- | --- |"]
    for r in results:
        lines.append(f"| {r.skill} | {r.status} | {r.route} | {r.figures.replace('|', '/')} | {r.runs} | "
                     f"{r.wall_seconds:.0f} |")
    return "\n".join(lines) + "\n"


def adapt(character: str, skills: list[str], out: Path, minutes: float, workers: int, seed: int,
          redo: list[str] | None, say=print) -> list[Result]:
    """``redo``: None resumes (skills state.json records are skipped), [] runs every skill again, a list
    runs those again."""
    if not (np.isfinite(minutes) and 0 <= minutes <= 24 * 60):
        raise ParameterError(f"--minutes={minutes:g} is out of range; allowed range is [0, 1440]")
    if not 1 <= workers <= 64:
        raise ParameterError(f"--workers={workers} is out of range; allowed range is [1, 64]")
    spec = load_character(character)           # a bad spec is refused here, before anything runs
    names = skills_of(skills)
    state_path = out / "state.json"
    state = json.loads(state_path.read_text()) if state_path.exists() and redo != [] else {}
    if state and state.get("character") != spec.name:
        raise ParameterError(f"{state_path} records an adaptation of {state.get('character')!r}, not {spec.name!r}: "
                             f"give another --out, or --redo")
    done = {r["skill"]: Result(**r) for r in state.get("results", []) if r["skill"] not in (redo or [])}
    deadline = time.monotonic() + 60.0 * minutes
    results = []
    for skill in names:
        if skill in done:
            say(f"{skill}: done before ({done[skill].status}); --redo {skill} runs it again")
            results.append(done[skill])
            continue
        say(f"{skill}: adapting to the {spec.name}")
        rng = np.random.default_rng([seed, zlib.crc32(skill.encode())])   # a skill's draw whatever ran before it
        try:
            result = (adapt_skill(skill, character, rng, workers, deadline, say) if skill in ADAPTERS
                      else try_default(skill, character))
        except ParameterError as error:        # e.g. a scaled row its table refuses: that skill only is refused
            result = Result(skill, "refused", "error", str(error).split("\n")[0])
        say(f"{skill}: {result.status} ({result.route}; {result.figures})")
        results.append(result)
        if result.route == "error":          # not recorded: a rerun tries it again
            continue
        done[skill] = result
        write_atomically(state_path, json.dumps({"character": spec.name, "seed": seed,
                                                 "results": [asdict(r) for r in done.values()]}, indent=1) + "\n")
    report = markdown(spec, results)
    write_atomically(out / "report.md", report)
    return results


def _stop_on_terminate(signum, frame):
    raise KeyboardInterrupt          # a kill (SIGTERM) unwinds like Ctrl-C: the table under way is put back


def main(args) -> int:
    signal.signal(signal.SIGTERM, _stop_on_terminate)
    out = Path(args.out) if args.out else Path("out") / "adapt" / load_character(args.character).name
    results = adapt(args.character, args.skills, out, args.minutes, args.workers, args.seed, args.redo,
                    say=lambda line: print(line, flush=True))
    print(markdown(load_character(args.character), results))
    print(f"wrote {out / 'report.md'}")
    return 0
