"""The simulation loop: physics at the model's step (1 ms for the man; x a made body's Fig. 6 time
scale, as its control period: CharacterSpec.time_scale) (finer for the ticks a behaviour asks it for:
``ControlContext.step_division``), the behaviour at the control rate, frames
recorded into a Trajectory together with the log that replays it bit for bit.

Per control tick, in this order (replay follows the same order):
  1. apply the edit log of this tick (pushes, gains, gravity, a morph of the body) - in a live run,
     written by the push schedule and the behaviour as they act;
  2. fresh kinematics (positions, COM, COM velocity) of the current state;
  3. record a frame;
  4. the behaviour sets servo targets -> control vector (live run) / read it from the log (replay);
  5. ``steps_per_tick`` x ``step_division`` physics steps of the model's step / ``step_division``.

``run`` drives one character (a RunRequest); ``run_scene`` drives every actor of a scene
(sim_core.scene) in one model with the same loop: in step 4 each actor's behaviour writes its own
slice of the control vector, on its own ticks.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Callable

import mujoco
import numpy as np

from .character.model import compile_model, place_standing, set_standing_pose
from .character.morph import morph_models
from .character.spec import CharacterSpec, load_character
from .control.actor import ActorView
from .control.behaviour import Behaviour, ControlContext
from .skills import behaviour_class
from .control.servo import ServoBank
from .edit_log import EDITABLE_FIELDS, EditLog, EditPlayer
from .errors import Cancelled, ParameterError, SimAthleticsError
from .perturbation import Push, PushSchedule
from .scene import Scene, compile_scene, control_tick
from .trajectory import PER_ACTOR_FIELDS, Trajectory
from .world import World, world_geom_mask

STATE_SPEC = mujoco.mjtState.mjSTATE_INTEGRATION
THREE = np.arange(3)        # a contact's force components (normal, two tangents) in its efc rows
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

    def apply(self, model: mujoco.MjModel, data: mujoco.MjData) -> None:
        """Raise and launch every free body (the character, and a prop it rides with, e.g. a
        bicycle) alike, so that they start together."""
        for joint in np.flatnonzero(model.jnt_type == mujoco.mjtJoint.mjJNT_FREE):
            data.qpos[model.jnt_qposadr[joint] + 2] += self.height
            start = model.jnt_dofadr[joint]
            data.qvel[start:start + 3] = self.velocity


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
        duration = cls.duration_for(params, character.name, self.strength) if self.duration is None else self.duration
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
    """Preallocated frame buffers; ``record`` copies the current state in. Per-actor quantities
    (COM, its velocity, angular momentum, ground reaction and push force) have an actor axis,
    dropped for a single character (``per_actor=False``: the arrays of a one-character run)."""

    def __init__(self, model: mujoco.MjModel, n_frames: int, site_ids: np.ndarray,
                 actors: list[ActorView] | None = None, per_actor: bool = False):
        self.model = model
        actors = actors or [ActorView.of(model)]
        self.per_actor = per_actor
        world_geom = world_geom_mask(model)             # the ground, boxes, props (what the body stands on)
        # every body but the world and a moving prop's (which come after the characters), in model order
        self.bodies = np.arange(1, model.nbody - len(set(model.geom_bodyid[world_geom]) - {0}))
        self.body_rows = slice(1, 1 + len(self.bodies))
        self.roots = np.array([a.root for a in actors])
        self.actor_bodies = [a.bodies for a in actors]
        # a single character's push is summed over every row of xfrc_applied (the world's is 0)
        self.push_rows = [a.bodies for a in actors] if per_actor else [slice(None)]
        self.site_ids = site_ids
        contiguous = len(site_ids) and np.all(np.diff(site_ids) == 1)
        self.sites = slice(int(site_ids[0]), int(site_ids[-1]) + 1) if contiguous else site_ids
        self.world_geom = world_geom
        self.geom_body = model.geom_bodyid - 1
        self.world_geom_ids = named_world_geoms(model)
        self.world_column = np.full(model.ngeom, -1)       # geom id -> its column of contact_force
        self.world_column[self.world_geom_ids] = np.arange(len(self.world_geom_ids))
        nb, na = len(self.bodies), len(actors)
        self.buf = {
            "time": np.zeros(n_frames), "qpos": np.zeros((n_frames, model.nq)),
            "qvel": np.zeros((n_frames, model.nv)), "body_pos": np.zeros((n_frames, nb, 3)),
            "body_quat": np.zeros((n_frames, nb, 4)), "com": np.zeros((n_frames, na, 3)),
            "com_vel": np.zeros((n_frames, na, 3)), "angmom": np.zeros((n_frames, na, 3)),
            "grf": np.zeros((n_frames, na, 3)),
            "ground_contact": np.zeros((n_frames, nb), dtype=bool),
            "support_points": np.zeros((n_frames, len(site_ids), 3)), "push_force": np.zeros((n_frames, na, 3)),
        }
        self.contacts = []          # per frame with contacts: (frame, geoms, frames, efc addresses, dims, forces)
        self.n = 0

    def record(self, data: mujoco.MjData) -> None:
        k, b = self.n, self.buf
        b["time"][k] = data.time
        b["qpos"][k] = data.qpos
        b["qvel"][k] = data.qvel
        b["body_pos"][k] = data.xpos[self.body_rows]
        b["body_quat"][k] = data.xquat[self.body_rows]
        b["com"][k] = data.subtree_com[self.roots]
        b["com_vel"][k] = data.subtree_linvel[self.roots]
        b["angmom"][k] = data.subtree_angmom[self.roots]
        for a, (bodies, rows) in enumerate(zip(self.actor_bodies, self.push_rows)):
            push = data.xfrc_applied[rows, :3].sum(axis=0)
            b["push_force"][k, a] = push
            if k:                           # no physics step has produced a contact force at frame 0
                b["grf"][k, a] = data.cfrc_ext[bodies, 3:].sum(axis=0) - push
        if data.ncon:
            geoms = data.contact.geom
            first, second = geoms[:, 0], geoms[:, 1]
            world = self.world_geom
            touched = np.where(world[first], second, np.where(world[second], first, -1))
            touched = touched[touched >= 0]
            touched = touched[~world[touched]]       # a prop touching the ground is not a body's contact
            b["ground_contact"][k, self.geom_body[touched]] = True
            if k and data.nefc:             # the contacts' forces, assembled in contact_forces()
                contact = data.contact
                address = contact.efc_address
                self.contacts.append((k, contact.geom.copy(), contact.frame.copy(), address.copy(), contact.dim.copy(),
                                      data.efc_force.take(address[:, None] + THREE, mode="clip")))
        b["support_points"][k] = data.site_xpos[self.sites]
        self.n += 1

    def contact_forces(self) -> np.ndarray:
        """contact_force (frames x bodies x named world geoms x 3): the world-frame force of each
        named world geom on each body, summed over its contacts in the last physics step. A
        contact's force in its own frame (normal, two tangents) is the constraint force of its
        rows (with elliptic cones the rows are exactly those components); it pushes geom2 along
        the frame's normal (geom1 -> geom2) and geom1 the other way. The frames' contacts are
        copied in ``record`` and turned into forces here, all frames at once."""
        out = np.zeros((self.n, len(self.bodies), len(self.world_geom_ids), 3))
        if not self.contacts:
            return out
        frame = np.concatenate([np.full(len(c[1]), c[0]) for c in self.contacts])
        geoms, axes, address, dim, rows = (np.concatenate([c[i] for c in self.contacts]) for i in range(1, 6))
        column1, column2 = self.world_column[geoms[:, 0]], self.world_column[geoms[:, 1]]
        use = ((column1 >= 0) ^ (column2 >= 0)) & (address >= 0)
        local = rows[use] * (THREE < dim[use, None])            # components a contact does not have: 0
        force = np.einsum("ni,nij->nj", local, axes[use].reshape(-1, 3, 3))
        on_second = column1[use] >= 0                          # the world geom is geom1: the body is geom2
        body = np.where(on_second, self.geom_body[geoms[use, 1]], self.geom_body[geoms[use, 0]])
        column = np.where(on_second, column1[use], column2[use])
        np.add.at(out, (frame[use], body, column), np.where(on_second[:, None], force, -force))
        return out

    def arrays(self) -> dict[str, np.ndarray]:
        out = {name: array[: self.n] for name, array in self.buf.items()}
        out["contact_force"] = self.contact_forces()
        if not self.per_actor:
            for name in PER_ACTOR_FIELDS:
                out[name] = out[name][:, 0]
        return out


def named_world_geoms(model: mujoco.MjModel) -> np.ndarray:
    """Ids of the world's named geoms (the ground, boxes, a platform, water, apparatus), in model order:
    the columns of a trajectory's contact_force."""
    world = world_geom_mask(model)
    return np.array([g for g in range(model.ngeom) if world[g] and model.geom(g).name], dtype=int)


def hold_pose(model: mujoco.MjModel, data: mujoco.MjData) -> None:
    """Every servo's target at its joint's current angle (the start holds the pose it is put in)."""
    data.ctrl[:] = data.qpos[[model.jnt_qposadr[model.actuator_trnid[i, 0]] for i in range(model.nu)]]


def refresh_kinematics(model: mujoco.MjModel, data: mujoco.MjData) -> None:
    """Contact forces of the last physics step (cfrc_ext), then positions, COM, body velocities,
    COM velocity and angular momentum of the current state."""
    mujoco.mj_rnePostConstraint(model, data)
    mujoco.mj_kinematics(model, data)
    mujoco.mj_comPos(model, data)
    mujoco.mj_comVel(model, data)
    mujoco.mj_subtreeVel(model, data)


@dataclass
class ActorRun:
    """One actor in the loop: its behaviour (with its own context and servo bank), how many
    ticks apart it updates, and whether it has finished (then it holds its last controls)."""
    name: str
    view: ActorView
    behaviour: Behaviour
    every: int = 1
    done: bool = False
    last_tick: int | None = None      # the tick after whose physics its skill had ended


def run(request: RunRequest, progress: Callable[[float], None] | None = None,
        cancelled: Callable[[], bool] | None = None) -> Trajectory:
    """Validate, simulate and return the trajectory (nothing is written to disk here)."""
    character, cls, params, duration = request.validated()
    world = cls.scene(params, request.world, character)
    morph_to = cls.morph_target(params)
    morph = None
    if morph_to is None:
        model, xml = compile_model(character, world, request.strength)
    else:
        model, xml, morph = morph_models(character, load_character(morph_to), world, request.strength)
    data = mujoco.MjData(model)
    set_standing_pose(model, data, character)
    request.start.apply(model, data)
    skill_start = cls.start_state(params, model, data, character)
    hold_pose(model, data)
    mujoco.mj_forward(model, data)

    log = EditLog()
    view = ActorView.of(model)
    servos = ServoBank(model, data, character, log, view)
    rate = cls.rate_for(character)
    behaviour = cls(params, ControlContext(model, data, character, servos, control_dt=1.0 / rate,
                                           actor=view, morph=morph))
    behaviour.check_feasible()
    actors = [ActorRun("", view, behaviour)]
    support_sites = behaviour_support_sites(model)
    loop = _Loop(model, data, world, log, actors, rate, duration, per_actor=False,
                 support_sites=support_sites, pushes=request.pushes)
    arrays, loop_seconds = loop.run(progress, cancelled, stop_when_done=True)
    control = arrays["control"]
    meta = {
        "model_xml": xml, "character": character.name, "behaviour": cls.name, "params": params,
        "duration": duration if len(control) == loop.n_ticks else float(len(control) * loop.tick_time),
        "ended_early": len(control) < loop.n_ticks, "pushes": [p.to_dict() for p in request.pushes],
        "world": world.to_dict(),
        "start_state": {"height": request.start.height, "velocity": list(request.start.velocity),
                        **({"skill": skill_start} if skill_start is not None else {})},
        "strength": request.strength, "total_mass": float(model.body_subtreemass[1]), "timestep": model.opt.timestep,
        "steps_per_tick": loop.steps_per_tick,
        "control_rate": rate, "phase_events": behaviour.phase_events,
        "edit_fields": list(EDITABLE_FIELDS), "state_spec": int(STATE_SPEC),
        "dof_names": [model.actuator(i).name for i in range(model.nu)],
        "wall_seconds_in_loop": loop_seconds,
        "support_site_side": [model.body(model.site_bodyid[i]).name[-1] for i in support_sites],
        "world_geoms": [model.geom(g).name for g in named_world_geoms(model)],
        "mujoco_version": mujoco.__version__,
        **({"morph_to": morph_to} if morph is not None else {}),
    }
    trajectory = Trajectory(arrays, meta)
    outcome, metrics = cls.assess(trajectory)
    trajectory.meta["outcome"] = outcome
    trajectory.meta["metrics"] = metrics
    if progress:
        progress(1.0)
    return trajectory


def run_scene(scene: Scene, progress: Callable[[float], None] | None = None,
              cancelled: Callable[[], bool] | None = None) -> Trajectory:
    """Simulate every actor of ``scene`` in one model for the scene's duration. The loop ticks
    at the fastest actor's control rate; an actor with a slower rate updates every n-th tick
    (sim_core.scene.control_tick); a tick's physics step is divided by the largest division any
    actor asks for. An actor whose skill has ended (run_complete) holds its last controls until
    the scene ends. Each actor is judged by its own behaviour's ``assess`` on its view
    (``Trajectory.actor``); meta["actors"] holds each one's outcome and metrics."""
    rate, every = control_tick(scene)
    model, xml = compile_scene(scene)
    data = mujoco.MjData(model)
    mujoco.mj_resetData(model, data)
    for a in scene.actors:
        place_standing(model, data, a.character, a.prefix, a.placement)
    skill_starts = {a.name: a.behaviour.start_state(a.params, model, data, a.character, prefix=a.prefix)
                    for a in scene.actors}       # after every actor stands (a rider mounts a rolling bicycle)
    hold_pose(model, data)
    mujoco.mj_forward(model, data)

    log = EditLog()
    runs, actor_meta = [], []
    for a in scene.actors:
        view = ActorView.of(model, a.prefix, a.placement)
        servos = ServoBank(model, data, a.character, log, view)
        ctx = ControlContext(model, data, a.character, servos, control_dt=1.0 / a.behaviour.rate_for(a.character),
                             actor=view)
        behaviour = a.behaviour(a.params, ctx)
        try:
            behaviour.check_feasible()
        except SimAthleticsError as exc:
            raise type(exc)(f"actor {a.name!r}: {exc}") from None
        runs.append(ActorRun(a.name, view, behaviour, every[a.name]))
    support = [behaviour_support_sites(model, a.prefix) for a in scene.actors]
    loop = _Loop(model, data, scene.world, log, runs, rate, scene.duration, per_actor=True,
                 support_sites=np.concatenate(support), pushes=[])
    arrays, loop_seconds = loop.run(progress, cancelled, stop_when_done=False)
    first_site = 0
    for a, r, sites in zip(scene.actors, runs, support):
        v = r.view
        actor_meta.append({
            "name": a.name, "prefix": a.prefix, "character": a.character.name, "behaviour": a.behaviour.name,
            "params": a.params, "strength": a.strength,
            "placement": {"x": a.placement.x, "y": a.placement.y, "heading": a.placement.heading},
            "bodies": [v.bodies.start - 1, v.bodies.stop - 1],         # columns of body_pos etc.
            "qpos": [v.qpos.start, v.qpos.stop], "qvel": [v.qvel.start, v.qvel.stop],
            "actuators": [v.actuators.start, v.actuators.stop],
            "support_sites": [first_site, first_site + len(sites)],
            "behaviour_rate": a.behaviour.rate_for(a.character), "update_every": r.every,
            "phase_events": r.behaviour.phase_events, "total_mass": float(model.body_subtreemass[v.root]),
            "support_site_side": [model.body(model.site_bodyid[i]).name[-1] for i in sites],
            "dof_names": [model.actuator(i).name[len(a.prefix):] for i in range(v.actuators.start, v.actuators.stop)],
            "completed": r.done,
            "start_state": {"height": 0.0, "velocity": [0.0, 0.0, 0.0],
                            **({"skill": skill_starts[a.name]} if skill_starts[a.name] is not None else {})},
            # its own run ends with the state after its last tick, as a one-character run's does
            "end_frame": len(arrays["time"]) if r.last_tick is None else r.last_tick + 2,
        })
        first_site += len(sites)
    meta = {
        "scene": True, "model_xml": xml, "duration": scene.duration, "ended_early": False,
        "world": scene.world.to_dict(), "timestep": model.opt.timestep, "steps_per_tick": loop.steps_per_tick,
        "control_rate": rate, "edit_fields": list(EDITABLE_FIELDS), "state_spec": int(STATE_SPEC),
        "pushes": [], "start_state": {"height": 0.0, "velocity": [0.0, 0.0, 0.0]},
        "wall_seconds_in_loop": loop_seconds, "actors": actor_meta,
        "world_geoms": [model.geom(g).name for g in named_world_geoms(model)],
        "mujoco_version": mujoco.__version__,
    }
    trajectory = Trajectory(arrays, meta)
    for a, m in zip(scene.actors, actor_meta):
        outcome, metrics = a.behaviour.assess(trajectory.actor(a.name))
        m["outcome"], m["metrics"] = outcome, metrics
    if progress:
        progress(1.0)
    return trajectory


class _Loop:
    """The control loop shared by a one-character run and a scene (see the module doc for the
    order of a tick)."""

    def __init__(self, model, data, world: World, log: EditLog, actors: list[ActorRun], rate: float,
                 duration: float, per_actor: bool, support_sites: np.ndarray, pushes: list[Push]):
        self.model, self.data, self.world, self.log, self.actors = model, data, world, log, actors
        self.steps_per_tick = int(round(1.0 / (rate * model.opt.timestep)))
        self.tick_time = self.steps_per_tick * model.opt.timestep
        self.n_ticks = int(math.ceil(duration / self.tick_time - 1e-9))
        self.initial_state = np.zeros(mujoco.mj_stateSize(model, STATE_SPEC))
        mujoco.mj_getState(model, data, self.initial_state, STATE_SPEC)
        mujoco.mj_setState(model, data, self.initial_state, STATE_SPEC)   # replay starts from exactly this
        self.recorder = Recorder(model, self.n_ticks + 1, support_sites, [a.view for a in actors], per_actor)
        self.pushes = PushSchedule(pushes, model, data, log)

    def run(self, progress, cancelled, stop_when_done: bool) -> tuple[dict, float]:
        """``stop_when_done``: a one-character run ends when its skill does; a scene runs on."""
        model, data, world, log, recorder = self.model, self.data, self.world, self.log, self.recorder
        actors, steps_per_tick, n_ticks, tick_time = self.actors, self.steps_per_tick, self.n_ticks, self.tick_time
        single = actors[0] if len(actors) == 1 and stop_when_done else None
        control = np.zeros((n_ticks, model.nu))
        divisions = np.ones(n_ticks, dtype=np.int64)
        pushes = self.pushes
        base_timestep = model.opt.timestep

        loop_start = time.perf_counter()
        for tick in range(n_ticks):
            log.tick = tick
            t = data.time
            pushes.apply(t, 0.5 * tick_time)
            if world.tilting(t):
                log.set_flat(model.opt.gravity, "opt.gravity", world.gravity(t))
            for a in actors:
                morph = a.behaviour.ctx.morph
                if morph is not None and (f := a.behaviour.morph_fraction(t)) != morph.fraction:
                    log.set_morph(morph, f)          # the body changes before this tick's kinematics
            refresh_kinematics(model, data)
            if tick == 0:
                for a in actors:
                    a.behaviour.start(t)
            recorder.record(data)
            if single is not None:
                behaviour = single.behaviour
                behaviour.update(t)
                behaviour.ctx.servos.write(t)
                division = behaviour.ctx.step_division
            else:
                division = 1
                for a in actors:
                    if not a.done and tick % a.every == 0:
                        a.behaviour.update(t)
                        a.behaviour.ctx.servos.write(t)
                    division = max(division, a.behaviour.ctx.step_division)
            control[tick] = data.ctrl
            divisions[tick] = division
            model.opt.timestep = base_timestep / division
            mujoco.mj_step(model, data, nstep=steps_per_tick * division)
            if any(data.warning[w].number for w in DIVERGENCE_WARNINGS):
                raise UnstableSimulation(
                    f"the simulation became numerically unstable at t={t:.3f} s (accelerations blew "
                    f"up); nothing was written - lower the gains or the strength, or shorten the step")
            if single is not None:
                if single.behaviour.run_complete:
                    control, divisions = control[:tick + 1], divisions[:tick + 1]
                    break
            else:
                for a in actors:
                    if not a.done and a.behaviour.run_complete:
                        a.done, a.last_tick = True, tick
                        a.behaviour.event(data.time, "complete_holding")
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
        arrays["initial_state"] = self.initial_state
        arrays["control"] = control
        arrays["step_division"] = divisions
        arrays["body_names"] = np.array([model.body(i).name for i in recorder.bodies])
        return arrays, loop_seconds


def behaviour_support_sites(model: mujoco.MjModel, prefix: str = "") -> np.ndarray:
    """The foot contact sites of the character named by ``prefix``, in model order."""
    feet = {model.body(prefix + n).id for n in ("FOOTR", "FOOTL", "TOER", "TOEL")}
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
    if meta.get("scene"):
        prefixes = [a["prefix"] for a in meta["actors"]]
        recorder = Recorder(model, len(control) + 1,
                            np.concatenate([behaviour_support_sites(model, p) for p in prefixes]),
                            [ActorView.of(model, p) for p in prefixes], per_actor=True)
    else:
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
    for name in ("time", "qpos", "qvel", "body_pos", "body_quat", "com", "com_vel", "angmom", "grf", "support_points",
                 "contact_force"):
        if name == "contact_force" and not (name in a.arrays and name in b.arrays):
            continue                              # a trajectory from before contact forces were recorded
        x, y = a.arrays[name], b.arrays[name]
        if x.shape != y.shape:
            return math.inf
        worst = max(worst, float(np.max(np.abs(x - y))) if x.size else 0.0)
    return worst
