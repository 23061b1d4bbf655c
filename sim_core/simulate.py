"""The simulation loop: physics at a 1 ms step (finer for the ticks a behaviour asks it for:
``ControlContext.step_division``), the behaviour at the control rate, frames
recorded into a Trajectory together with the log that replays it bit for bit.

Per control tick, in this order (replay follows the same order):
  1. apply the edit log of this tick (pushes, gains, gravity) - in a live run, written by the
     push schedule and the behaviour as they act;
  2. fresh kinematics (positions, COM, COM velocity) of the current state;
  3. record a frame;
  4. the behaviour sets servo targets -> control vector (live run) / read it from the log (replay);
  5. ``steps_per_tick`` x ``step_division`` physics steps of the model's step / ``step_division``.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Callable

import mujoco
import numpy as np

from sim_core.character.model import World, compile_model, set_standing_pose
from sim_core.character.spec import CharacterSpec, load_character
from sim_core.control.behaviour import Behaviour, ControlContext, behaviour_class
from sim_core.control.servo import ServoBank
from sim_core.edit_log import EDITABLE_FIELDS, EditLog, EditPlayer
from sim_core.errors import Cancelled, ParameterError, SimAthleticsError
from sim_core.perturbation import Push, PushSchedule
from sim_core.trajectory import Trajectory

STATE_SPEC = mujoco.mjtState.mjSTATE_INTEGRATION
# MuJoCo's answer to a diverging state is to reset it (a teleport): any of these ends the run
DIVERGENCE_WARNINGS = (mujoco.mjtWarning.mjWARN_BADQACC, mujoco.mjtWarning.mjWARN_BADQPOS,
                       mujoco.mjtWarning.mjWARN_BADQVEL)


class UnstableSimulation(SimAthleticsError):
    """MuJoCo reported diverging accelerations: the run is not physics any more."""


@dataclass(frozen=True)
class StartState:
    """A named test input for the initial state (logged in the trajectory's meta and in its
    initial_state): the standing pose raised ``height`` metres above the ground, with every body
    moving at ``velocity`` (m/s, world frame). Used for drop and landing tests; a run never
    changes the state after t = 0."""
    height: float = 0.0
    velocity: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def check(self) -> None:
        if not (math.isfinite(self.height) and 0.0 <= self.height <= 20.0):
            raise ParameterError(f"start height={self.height} m is out of range; allowed range is [0, 20] m")
        if len(self.velocity) != 3 or not all(math.isfinite(v) and abs(v) <= 20.0 for v in self.velocity):
            raise ParameterError(f"start velocity={self.velocity} m/s: need 3 finite numbers in [-20, 20] m/s")

    def apply(self, data: mujoco.MjData) -> None:
        data.qpos[2] += self.height
        data.qvel[:3] = self.velocity


@dataclass
class RunRequest:
    behaviour: str
    character: str | CharacterSpec = "man"
    params: dict = field(default_factory=dict)
    duration: float | None = None
    pushes: list[Push] = field(default_factory=list)
    world: World = field(default_factory=World)
    strength: str | float = "human"
    start: StartState = field(default_factory=StartState)

    def validated(self) -> tuple[CharacterSpec, type[Behaviour], dict, float]:
        character = self.character if isinstance(self.character, CharacterSpec) else load_character(self.character)
        cls = behaviour_class(self.behaviour)
        params = cls.schema.validate(self.params)
        duration = cls.default_duration if self.duration is None else self.duration
        if not (isinstance(duration, (int, float)) and math.isfinite(duration) and 0.01 <= duration <= 3600):
            raise ParameterError(f"duration={duration!r} s is out of range; allowed range is [0.01, 3600] s")
        if not (self.strength in ("human", "unlimited") or
                (isinstance(self.strength, (int, float)) and 0.1 <= self.strength <= 10)):
            raise ParameterError(f"strength={self.strength!r} must be 'human', 'unlimited' or a factor in [0.1, 10]")
        for push in self.pushes:
            push.check()
        self.start.check()
        return character, cls, params, float(duration)


class Recorder:
    """Preallocated frame buffers; ``record`` copies the current state in."""

    def __init__(self, model: mujoco.MjModel, n_frames: int, site_ids: np.ndarray):
        self.model = model
        self.bodies = np.arange(1, model.nbody)        # every body but the world, in model order
        self.root = 1
        self.site_ids = site_ids
        contiguous = len(site_ids) and np.all(np.diff(site_ids) == 1)
        self.sites = slice(int(site_ids[0]), int(site_ids[-1]) + 1) if contiguous else site_ids
        self.world_geom = model.geom_bodyid == 0           # the ground, boxes (what the body stands on)
        self.geom_body = model.geom_bodyid - 1
        nb = len(self.bodies)
        self.buf = {
            "time": np.zeros(n_frames), "qpos": np.zeros((n_frames, model.nq)),
            "qvel": np.zeros((n_frames, model.nv)), "body_pos": np.zeros((n_frames, nb, 3)),
            "body_quat": np.zeros((n_frames, nb, 4)), "com": np.zeros((n_frames, 3)),
            "com_vel": np.zeros((n_frames, 3)), "angmom": np.zeros((n_frames, 3)), "grf": np.zeros((n_frames, 3)),
            "ground_contact": np.zeros((n_frames, nb), dtype=bool),
            "support_points": np.zeros((n_frames, len(site_ids), 3)), "push_force": np.zeros((n_frames, 3)),
        }
        self.n = 0

    def record(self, data: mujoco.MjData) -> None:
        k, b = self.n, self.buf
        b["time"][k] = data.time
        b["qpos"][k] = data.qpos
        b["qvel"][k] = data.qvel
        b["body_pos"][k] = data.xpos[1:]
        b["body_quat"][k] = data.xquat[1:]
        b["com"][k] = data.subtree_com[self.root]
        b["com_vel"][k] = data.subtree_linvel[self.root]
        b["angmom"][k] = data.subtree_angmom[self.root]
        push = data.xfrc_applied[:, :3].sum(axis=0)
        b["push_force"][k] = push
        if k:                               # no physics step has produced a contact force at frame 0
            b["grf"][k] = data.cfrc_ext[1:, 3:].sum(axis=0) - push
        if data.ncon:
            geoms = data.contact.geom
            first, second = geoms[:, 0], geoms[:, 1]
            world = self.world_geom
            touched = np.where(world[first], second, np.where(world[second], first, -1))
            touched = touched[touched >= 0]
            b["ground_contact"][k, self.geom_body[touched]] = True
        b["support_points"][k] = data.site_xpos[self.sites]
        self.n += 1

    def arrays(self) -> dict[str, np.ndarray]:
        return {name: array[: self.n] for name, array in self.buf.items()}


def refresh_kinematics(model: mujoco.MjModel, data: mujoco.MjData) -> None:
    """Contact forces of the last physics step (cfrc_ext), then positions, COM, body velocities,
    COM velocity and angular momentum of the current state."""
    mujoco.mj_rnePostConstraint(model, data)
    mujoco.mj_kinematics(model, data)
    mujoco.mj_comPos(model, data)
    mujoco.mj_comVel(model, data)
    mujoco.mj_subtreeVel(model, data)


def run(request: RunRequest, progress: Callable[[float], None] | None = None,
        cancelled: Callable[[], bool] | None = None) -> Trajectory:
    """Validate, simulate and return the trajectory (nothing is written to disk here)."""
    character, cls, params, duration = request.validated()
    world = cls.scene(params, request.world, character)
    model, xml = compile_model(character, world, request.strength)
    data = mujoco.MjData(model)
    set_standing_pose(model, data, character)
    request.start.apply(data)
    data.ctrl[:] = data.qpos[[model.jnt_qposadr[model.actuator_trnid[i, 0]] for i in range(model.nu)]]
    mujoco.mj_forward(model, data)

    log = EditLog()
    servos = ServoBank(model, data, character, log)
    behaviour = cls(params, ControlContext(model, data, character, servos, control_dt=1.0 / cls.control_rate))
    behaviour.check_feasible()

    steps_per_tick = int(round(1.0 / (cls.control_rate * model.opt.timestep)))
    tick_time = steps_per_tick * model.opt.timestep
    n_ticks = int(math.ceil(duration / tick_time - 1e-9))
    initial_state = np.zeros(mujoco.mj_stateSize(model, STATE_SPEC))
    mujoco.mj_getState(model, data, initial_state, STATE_SPEC)
    mujoco.mj_setState(model, data, initial_state, STATE_SPEC)   # replay starts from exactly this
    support_sites = behaviour_support_sites(model)
    recorder = Recorder(model, n_ticks + 1, support_sites)
    control = np.zeros((n_ticks, model.nu))
    divisions = np.ones(n_ticks, dtype=np.int64)
    pushes = PushSchedule(request.pushes, model, data, log)
    base_timestep = model.opt.timestep

    loop_start = time.perf_counter()
    for tick in range(n_ticks):
        log.tick = tick
        t = data.time
        pushes.apply(t, 0.5 * tick_time)
        if world.tilting(t):
            log.set_flat(model.opt.gravity, "opt.gravity", world.gravity(t))
        refresh_kinematics(model, data)
        if tick == 0:
            behaviour.start(t)
        recorder.record(data)
        behaviour.update(t)
        servos.write(t)
        control[tick] = data.ctrl
        divisions[tick] = division = behaviour.ctx.step_division
        model.opt.timestep = base_timestep / division
        mujoco.mj_step(model, data, nstep=steps_per_tick * division)
        if any(data.warning[w].number for w in DIVERGENCE_WARNINGS):
            raise UnstableSimulation(
                f"the simulation became numerically unstable at t={t:.3f} s (accelerations blew "
                f"up); nothing was written - lower the gains or the strength, or shorten the step")
        if behaviour.run_complete:
            control, divisions = control[:tick + 1], divisions[:tick + 1]
            break
        if progress and tick % 200 == 0:
            progress(tick / n_ticks)
        if cancelled and tick % 50 == 0 and cancelled():
            raise Cancelled("run cancelled; nothing was written")
    log.tick = len(control)
    model.opt.timestep = base_timestep
    refresh_kinematics(model, data)
    recorder.record(data)
    loop_seconds = time.perf_counter() - loop_start

    arrays = recorder.arrays()
    arrays.update(log.arrays())
    arrays["initial_state"] = initial_state
    arrays["control"] = control
    arrays["step_division"] = divisions
    arrays["body_names"] = np.array([model.body(i).name for i in recorder.bodies])
    meta = {
        "model_xml": xml, "character": character.name, "behaviour": cls.name, "params": params,
        "duration": duration if len(control) == n_ticks else float(len(control) * tick_time),
        "ended_early": len(control) < n_ticks, "pushes": [p.to_dict() for p in request.pushes],
        "world": {"slope": world.slope, "slope_axis": world.slope_axis,
                  "extra_mass": world.extra_mass, "platform": world.platform,
                  "platform_edge": world.platform_edge, "boxes": [list(b) for b in world.boxes],
                  "floor": world.floor},
        "start_state": {"height": request.start.height, "velocity": list(request.start.velocity)},
        "strength": request.strength, "total_mass": float(model.body_subtreemass[1]), "timestep": model.opt.timestep, "steps_per_tick": steps_per_tick,
        "control_rate": cls.control_rate, "phase_events": behaviour.phase_events,
        "edit_fields": list(EDITABLE_FIELDS), "state_spec": int(STATE_SPEC),
        "dof_names": [model.actuator(i).name for i in range(model.nu)],
        "wall_seconds_in_loop": loop_seconds,
        "support_site_side": [model.body(model.site_bodyid[i]).name[-1] for i in support_sites],
    }
    trajectory = Trajectory(arrays, meta)
    outcome, metrics = cls.assess(trajectory)
    trajectory.meta["outcome"] = outcome
    trajectory.meta["metrics"] = metrics
    if progress:
        progress(1.0)
    return trajectory


def behaviour_support_sites(model: mujoco.MjModel) -> np.ndarray:
    feet = {model.body(n).id for n in ("FOOTR", "FOOTL", "TOER", "TOEL")}
    return np.array([i for i in range(model.nsite) if model.site_bodyid[i] in feet])


def replay(trajectory: Trajectory) -> Trajectory:
    """Re-run the logged controls and edits on the logged model and initial state."""
    meta = trajectory.meta
    model = mujoco.MjModel.from_xml_string(meta["model_xml"])
    data = mujoco.MjData(model)
    mujoco.mj_setState(model, data, trajectory.arrays["initial_state"], meta["state_spec"])
    player = EditPlayer(model, data, trajectory.arrays)
    control = trajectory.arrays["control"]
    steps = meta["steps_per_tick"]
    base_timestep = model.opt.timestep
    divisions = trajectory.arrays.get("step_division", np.ones(len(control), dtype=np.int64))
    recorder = Recorder(model, len(control) + 1, behaviour_support_sites(model))
    for tick in range(len(control)):
        player.apply(tick)
        refresh_kinematics(model, data)
        recorder.record(data)
        data.ctrl[:] = control[tick]
        model.opt.timestep = base_timestep / int(divisions[tick])
        mujoco.mj_step(model, data, nstep=steps * int(divisions[tick]))
    model.opt.timestep = base_timestep
    player.apply(len(control))
    refresh_kinematics(model, data)
    recorder.record(data)
    return Trajectory(recorder.arrays(), dict(meta))


def largest_difference(a: Trajectory, b: Trajectory) -> float:
    worst = 0.0
    for name in ("time", "qpos", "qvel", "body_pos", "body_quat", "com", "com_vel", "angmom", "grf", "support_points"):
        x, y = a.arrays[name], b.arrays[name]
        if x.shape != y.shape:
            return math.inf
        worst = max(worst, float(np.max(np.abs(x - y))) if x.size else 0.0)
    return worst
