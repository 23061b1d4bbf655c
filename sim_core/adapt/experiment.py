"""The seed's Fig. 5/8 experiment (Hodgins & Pollard 1997, [B] 124-126, 208): the time before
falling of the man's controller on bodies from the man to the woman, unscaled, geometrically
scaled and mass-scaled (SEEDS-WAVE2.md §5.4, §8.5 S5).

The bodies are ``between(man, woman, x)``. The controller is everything the man's run is set
with, carried to the new body as each column says:

- the spec's joint servos (kp, kv, torque limits) and its time scale (the physics step and the
  control period, x L^1/2 in both scaled columns, the man's 1 ms and rates unscaled):
  adapt/servos.controller_servos;
- every number of the run's request (the animator's parameters and the tuned settings at their
  man's values, e.g. the desired speed, the timing of a knee bend): adapt/settings.scale_settings;
- for running, the man's table (SpeedTable of running_man.json, speeds and every column),
  passed as the run's ``table`` parameter (adapt/settings.scale_columns), so nothing is patched.

"unscaled" runs the man's request as it is on the new body with the man's servos. A scaled value
that leaves its setting's range (the ranges are the man's search ranges) is held at the range's
end, and the report lists every such value: the run then is not purely Fig. 6's.

L is the leg-length ratio.

    python -m sim_core character scaling-report [--cap 100] [--out docs/bodies.md]
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from pathlib import Path

from .servos import CONTROLLERS, controller_servos
from .settings import GEOMETRIC, MASS, CharacterPair, scale_columns, scale_settings
from ..character.make import between
from ..character.spec import CharacterSpec, load_character
from ..errors import ParameterError
from ..files import write_atomically

FRACTIONS = (0.0, 0.25, 0.5, 0.7, 1.0)        # the seed's intermediates, and its two ends
CAP = 100.0                                    # s: the seed's bar (§8.5 S5); a run that has not fallen by then counts as the cap
BEGIN, END = "<!-- scaling:begin -->", "<!-- scaling:end -->"
# the man's request per skill (the "controller" the columns carry): balance with a knee bend
# (tests/addon's), running at its default speed
REQUESTS = {
    "balance": {"pelvis_height": 0.52, "move_start": 0.3, "move_time": 1.2, "hold_time": 0.5},
    "running": {"swing_yields": 1.0},
}
MODE_OF = {"geometric": GEOMETRIC, "mass": MASS}


@dataclass
class Trial:
    skill: str
    fraction: float
    controller: str
    time_before_falling: float          # s; == cap when the run did not fall
    fell: bool
    clamped: list[str] = field(default_factory=list)     # settings held at their range's end
    wall_seconds: float = 0.0


def _clamp(values: dict, schema) -> tuple[dict, list[str]]:
    """``values`` held inside their settings' ranges; the names of those that were not."""
    out, clamped = {}, []
    for name, value in values.items():
        knob = schema.by_name[name]
        low, high = getattr(knob, "minimum", None), getattr(knob, "maximum", None)
        special = getattr(knob, "special", None)
        if low is None or isinstance(value, bool) or value == special or not isinstance(value, float):
            out[name] = value
        elif value < low or value > high:
            out[name] = min(max(value, low), high)
            clamped.append(name)
        else:
            out[name] = value
    return out, clamped


def controller_for(skill: str, man: CharacterSpec, body: dict, controller: str) -> tuple[CharacterSpec, dict, list[str]]:
    """The body with ``controller``'s servos and the run's parameters; the clamped settings."""
    from ..skills import behaviour_class
    cls = behaviour_class(skill)
    body_spec = CharacterSpec(body, body["name"])
    pair = CharacterPair(man, body_spec)
    character = CharacterSpec(controller_servos(body, man, pair.length, controller), body["name"])
    request = dict(REQUESTS[skill])
    if controller == "unscaled":            # the man's own settings as they are (for running: his table, given
        if skill == "running":              # as the run's table - a body with none of its own is refused)
            from ..skills.running.behaviour import SpeedTable
            return character, {**request, "table": SpeedTable.load(man.name).to_table()}, []
        return character, request, []
    mode = MODE_OF[controller]
    schema = cls.schema
    own = {}                                # the man's own constants of the laws (his running table's)
    if skill == "running":
        from ..skills.running.behaviour import SpeedTable
        own = {n: v for n, v in SpeedTable.load(man.name).constants.items() if n in schema.by_name}
    base = {**schema.defaults(), **own, **request}
    numbers = {n: v for n, v in base.items() if isinstance(v, (int, float)) and not isinstance(v, bool)
               and getattr(schema.by_name[n], "kind", "number") == "number"}
    params, clamped = _clamp(scale_settings(numbers, schema, pair, mode), schema)
    if skill == "running":
        from ..skills.running.behaviour import RUNNING_TABLE, SpeedTable
        table = SpeedTable.load(man.name)
        speeds, columns = scale_columns(table.speeds, table.values, RUNNING_TABLE.settings, pair, mode)
        rows = [_clamp({n: columns[n][k] for n in columns}, RUNNING_TABLE.settings) for k in range(len(speeds))]
        clamped += sorted({c for _, names in rows for c in names})
        params["table"] = {"speeds": speeds, "parameters": {n: [row[n] for row, _ in rows] for n in columns}}
    return character, params, sorted(set(clamped))


def time_before_falling(skill: str, character: CharacterSpec, params: dict, cap: float) -> tuple[float, bool]:
    """Seconds until the run falls (standard_metrics' fall_time), or ``cap`` if it does not (a run
    lasts whole control ticks, so a scaled body's may end a fraction of a tick past the cap)."""
    from ..simulate import RunRequest, run
    trajectory = run(RunRequest(skill, character, params=params, duration=cap))
    fall = trajectory.meta["metrics"].get("fall_time")
    return (float(fall), True) if fall is not None else (min(float(trajectory.arrays["time"][-1]), cap), False)


def experiment(skill: str, fractions=FRACTIONS, controllers=CONTROLLERS, cap: float = CAP,
               progress=None) -> list[Trial]:
    """One run per (fraction, controller): man -> woman."""
    if skill not in REQUESTS:
        raise ParameterError(f"skill {skill!r} has no scaling experiment; available: {', '.join(REQUESTS)}")
    if not (math.isfinite(cap) and 0.5 <= cap <= 600):
        raise ParameterError(f"--cap={cap:g} s is out of range; allowed range is [0.5, 600] s")
    man, woman = load_character("man"), load_character("woman")
    trials = []
    for fraction in fractions:
        body = between(man, woman, fraction)
        for controller in controllers:
            start = time.perf_counter()
            character, params, clamped = controller_for(skill, man, body, controller)
            seconds, fell = time_before_falling(skill, character, params, cap)
            trials.append(Trial(skill, fraction, controller, seconds, fell, clamped, time.perf_counter() - start))
            if progress:
                progress(trials[-1])
    return trials


def ordering_holds(trials: list[Trial]) -> dict[float, bool]:
    """Per fraction: mass >= geometric >= unscaled (the seed's ordering), as measured."""
    by = {(t.fraction, t.controller): t.time_before_falling for t in trials}
    return {f: by[(f, "mass")] >= by[(f, "geometric")] >= by[(f, "unscaled")]
            for f in sorted({t.fraction for t in trials}) if all((f, c) in by for c in CONTROLLERS)}


def markdown(results: dict[str, list[Trial]], cap: float, plot_name: str | None) -> str:
    lines = [BEGIN, ""]
    for skill, trials in results.items():
        holds = ordering_holds(trials)
        fractions = sorted({t.fraction for t in trials})
        by = {(t.fraction, t.controller): t for t in trials}
        lines += [f"**{skill}** (time before falling, s; {cap:g} s = did not fall within the cap)", "",
                  "| man -> woman | " + " | ".join(CONTROLLERS) + " | mass >= geometric >= unscaled | held at a range's end |",
                  "| --- | " + " | ".join("---" for _ in CONTROLLERS) + " | --- | --- |"]
        for f in fractions:
            cells = [(f"{by[(f, c)].time_before_falling:.2f}" + ("" if by[(f, c)].fell else " (no fall)"))
                     if (f, c) in by else "-" for c in CONTROLLERS]
            clamped = sorted({n for c in CONTROLLERS if (f, c) in by for n in by[(f, c)].clamped})
            lines.append(f"| {100 * f:g} % | " + " | ".join(cells) + f" | {'yes' if holds.get(f) else 'no'} | "
                         f"{', '.join(clamped) or '-'} |")
        lines.append("")
    if plot_name:
        lines += [f"![time before falling against the fraction of the way to the woman]({plot_name})", ""]
    lines.append(END)
    return "\n".join(lines)


def plot(results: dict[str, list[Trial]], cap: float, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(results), figsize=(5 * len(results), 3.6), squeeze=False)
    for ax, (skill, trials) in zip(axes[0], results.items()):
        for controller, style in zip(CONTROLLERS, ("o-", "s--", "^-")):
            points = sorted((100 * t.fraction, t.time_before_falling) for t in trials if t.controller == controller)
            ax.plot(*zip(*points), style, label=controller)
        ax.axhline(cap, color="grey", lw=0.8, ls=":")
        ax.set(title=f"{skill}: man -> woman", xlabel="% of the way to the woman", ylabel="time before falling (s)",
               ylim=(0, cap * 1.08))
        ax.legend(loc="lower left")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def write_report(out: str | Path, skills=("balance", "running"), cap: float = CAP, fractions=FRACTIONS,
                 progress=None) -> str:
    """Run the experiment for ``skills`` and replace the block between BEGIN and END in ``out``
    (a Markdown file) with its table; the plot goes next to it as bodies_scaling.png."""
    out = Path(out)
    results = {skill: experiment(skill, fractions, cap=cap, progress=progress) for skill in skills}
    plot_path = out.with_name("bodies_scaling.png")
    plot(results, cap, plot_path)
    block = markdown(results, cap, plot_path.name)
    text = out.read_text() if out.exists() else ""
    if BEGIN in text and END in text:
        text = text[:text.index(BEGIN)] + block + text[text.index(END) + len(END):]
    else:
        text = text.rstrip("\n") + "\n\n" + block + "\n"
    write_atomically(out, text)
    return block
