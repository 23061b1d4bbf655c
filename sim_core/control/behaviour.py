"""Mid-level control: behaviours are named state machines with a parameter schema, found by a
registry (sim_core.skills, like Rigify's rig types). A behaviour reads the measured state and sets servo targets
and gains; it never applies forces or sets positions."""
from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import mujoco
import numpy as np

from ..character.morph import Morph
from ..character.spec import CharacterSpec
from .actor import ActorView
from .servo import ServoBank
from ..schema import Schema

REGISTRY: dict[str, type["Behaviour"]] = {}


def register(cls: type["Behaviour"]) -> type["Behaviour"]:
    REGISTRY[cls.name] = cls
    return cls



@dataclass
class ControlContext:
    model: mujoco.MjModel
    data: mujoco.MjData
    character: CharacterSpec
    servos: ServoBank
    control_dt: float = 0.01          # s between update() calls of this run
    step_division: int = 1            # the physics step of the coming control tick is the model's
                                      # divided by this (a behaviour sets it where fast motion needs
                                      # a finer step, e.g. a twisting flight); logged for replay
    actor: ActorView | None = None    # where this behaviour's character is in the model (its name
                                      # prefix, root body, index ranges); None: the model's only one
    morph: Morph | None = None        # a Morph when the body turns into another
                                      # during the run (the loop applies morph_fraction each tick)

    def __post_init__(self):
        if self.actor is None:
            self.actor = ActorView.of(self.model)


class Behaviour:
    name: ClassVar[str]
    summary: ClassVar[str]
    schema: ClassVar[Schema]                  # what an animator sets
    settings_schema: ClassVar[Schema] = Schema()   # what a search sets (a tuned table's rows; docs/tables.md)
    default_duration: ClassVar[float] = 5.0
    control_rate: ClassVar[float] = 200.0     # Hz at which update() runs for the man (the servos run every
                                              # step); a run's own rate is rate_for(its character)
    # True for a skill that measures or aims in the world's own axes (a somersault's rotation in
    # the X-Z plane, a jump's target from the origin): in a scene it must start at the origin
    # facing +X (sim_core.scene refuses it elsewhere)
    world_frame: ClassVar[bool] = False

    def __init__(self, params: dict[str, float], ctx: ControlContext):
        self.params = params
        self.ctx = ctx
        self.control_rate = self.rate_for(ctx.character)      # this run's rate (Hz), shadowing the class's
        self.phase_events: list[tuple[float, str]] = []

    @classmethod
    def rate_for(cls, character: CharacterSpec) -> float:
        """The control rate (Hz) on ``character``: the man's ``control_rate`` over the body's Fig. 6
        time scale, so the control period scales with the physics step (x L^1/2)."""
        return cls.control_rate / character.time_scale

    def start(self, t: float) -> None:
        """Called once before the first physics step."""

    def update(self, t: float) -> None:
        """Called at the control rate; sets servo targets, offsets and gains."""
        raise NotImplementedError

    def event(self, t: float, name: str) -> None:
        self.phase_events.append((float(t), name))

    @classmethod
    def duration_for(cls, params: dict, character: str, strength) -> float:
        """How long a run of these parameters lasts when its request names no duration."""
        return cls.default_duration

    @classmethod
    def morph_target(cls, params: dict) -> str | None:
        """The character the body turns into during the run (None: it stays itself)."""
        return None

    def morph_fraction(self, t: float) -> float:
        """How far the body is on its way to ``morph_target`` at time t (0-1)."""
        return 0.0

    @classmethod
    def scene(cls, params: dict[str, float], world, character=None):
        """The world this behaviour runs in, given the requested one and the character (e.g. a
        dive adds its platform, a jump a box under its target). Default: the requested world."""
        return world

    @classmethod
    def start_state(cls, params: dict[str, float], model: mujoco.MjModel, data: mujoco.MjData,
                    character: CharacterSpec, prefix: str = "") -> dict | None:
        """Pose the start where the skill begins, after the standing pose and any StartState (a
        rider mounted on a rolling bicycle): a named initial condition, recorded in the run's
        initial state and described by the returned dict in meta["start_state"]["skill"].
        ``prefix``: the character's names' prefix (a scene's "<actor>/"; it must move that
        character only). Default: nothing (None)."""
        return None

    @property
    def run_complete(self) -> bool:
        """True when the skill has ended before the requested duration (e.g. a dive at water
        entry); the run stops there."""
        return False

    def check_feasible(self) -> None:
        """Raise ParameterError before simulating if the request cannot be done."""

    @classmethod
    def character_defaults(cls, character: str) -> dict:
        """The animator parameters whose schema default ``character`` is not offered, moved into
        what it is offered (the child's leap height, a runner's speed): what a run takes for the
        knobs the user did not set (CLI, batch; the add-on's panel on adding the character).
        Default: none ({})."""
        return {}

    @classmethod
    def assess(cls, trajectory) -> tuple[str, dict]:
        """Outcome and metrics read off a finished run. The default judges a standing skill
        (TARGETS.md "stable"); behaviours that end in motion override it."""
        from ..analysis import standing_outcome, standard_metrics
        metrics = standard_metrics(trajectory)
        return standing_outcome(metrics), metrics


def angle_offsets(values: dict[str, float], servos: ServoBank) -> tuple[np.ndarray, np.ndarray]:
    names = list(values)
    return servos.indices(names), np.array([values[n] for n in names])
