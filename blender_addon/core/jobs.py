"""Work running beside Blender's UI: a worker thread, a progress fraction, a cancel flag.

A modal operator polls a job from a timer, so the UI stays responsive and Esc can cancel; what
touches bpy (the bake) or writes a file (storing a jump plan) happens on the main thread once
the job is done and was not cancelled - a cancelled job has written nothing. No bpy here.

* :class:`SimulationJob` - one run (``simulate.run``), cancelled within 50 control ticks.
* :class:`PlanningJob` - a jump plan (many trial runs of the planner, :class:`Planner`), whose
  trial in flight is cancelled within 50 control ticks.
"""
from __future__ import annotations

import threading
import time

from .simcore import SIM_CORE, sim


class Job:
    """A worker thread running ``work(progress, cancelled)``; ``result`` or ``error`` when done."""

    def __init__(self, name: str):
        self.progress = 0.0
        self.status = ""
        self.result = None
        self.error: BaseException | None = None
        self.finished_at: float | None = None
        self._cancel = threading.Event()
        self._thread = threading.Thread(target=self._run, name=name, daemon=True)

    def work(self):
        raise NotImplementedError

    def start(self) -> "Job":
        self._thread.start()
        return self

    def cancel(self) -> None:
        self._cancel.set()

    @property
    def cancelled(self) -> bool:
        return self._cancel.is_set()

    def done(self) -> bool:
        return not self._thread.is_alive()

    def wait(self, timeout: float | None = None) -> bool:
        self._thread.join(timeout)
        return self.done()

    def _run(self) -> None:
        try:
            self.result = self.work()
        except BaseException as exc:          # handed to the main thread, which reports it
            self.error = exc
        finally:
            self.finished_at = time.monotonic()


class SimulationJob(Job):
    def __init__(self, request):
        super().__init__("sim-athletics-run")
        self.request = request

    @property
    def trajectory(self):
        return self.result

    def work(self):
        return sim("simulate").run(self.request, progress=self._set_progress, cancelled=self._cancel.is_set)

    def _set_progress(self, fraction: float) -> None:
        self.progress = float(fraction)


def cancelled_error() -> type[BaseException]:
    """The Cancelled exception of the sim_core in use (sim_core.errors once it is there)."""
    errors = sim("errors")
    return getattr(errors, "Cancelled", None) or sim("simulate").Cancelled


class Planner:
    """The jump planner of the sim_core in use: the planning room's (``planning/jump.py``: plans
    take ``budget`` and ``cancelled``; kept in the user's plan store) where it exists, else the
    older one in ``control/target_jump.py`` (plans kept in the shipped table). One interface for
    both: ``stored``, ``plan``, ``store``."""

    def __init__(self):
        import importlib
        try:
            self.module = importlib.import_module(f"{SIM_CORE}.planning.jump")
        except ModuleNotFoundError as exc:
            if not (exc.name or "").startswith(f"{SIM_CORE}.planning"):
                raise
            self.module = None
        self.old = None if self.module is not None else sim("control.target_jump")

    def stored(self, character: str, params: dict, strength):
        if self.module is not None:
            return self.module.planned(character, params, strength)
        return self.old.stored_plan(character, jump_request(params, strength))

    def plan(self, character: str, params: dict, strength, budget: int, progress, cancelled, executor=None) -> dict:
        target = tuple(params[k] for k in ("target_x", "target_y", "target_z", "obstacle_height"))
        if self.module is not None:
            return self.module.plan_jump(character, target, params["air_time"], params["windup_time"],
                                         self.module.strength_name(strength), budget, progress=progress,
                                         cancelled=cancelled, executor=executor)
        return self.old.plan_jump(character, target, params["air_time"], params["windup_time"], strength,
                                  trials=budget, progress=progress, cancelled=cancelled)

    def store(self, character: str, params: dict, strength, plan: dict) -> None:
        if self.module is not None:
            m = self.module
            target = tuple(params[k] for k in ("target_x", "target_y", "target_z", "obstacle_height"))
            m.store_user_plan(character, m.request_of(target, params["air_time"], params["windup_time"],
                                                      m.strength_name(strength)), plan)
        else:
            self.old.store_plan(character, jump_request(params, strength), plan, "blender_addon: Plan Jump")


JUMP_REQUEST_KEYS = ("target_x", "target_y", "target_z", "obstacle_height", "air_time", "windup_time")


def jump_request(params: dict, strength) -> dict:
    """The key the older planner stores a plan under (as its JumpToTarget.request)."""
    request = {k: float(params[k]) for k in JUMP_REQUEST_KEYS}
    request["strength"] = strength
    return request


class PlanningJob(Job):
    """Plan a jump of ``character`` (a name) for the jump_to_target ``params`` (validated) in at
    most ``budget`` trials (default: its plan_trials); ``store()`` (main thread, after a finish
    that was not cancelled) keeps the plan where Simulate & Bake finds it."""

    def __init__(self, character: str, params: dict, strength="human", budget: int | None = None, executor=None):
        super().__init__("sim-athletics-plan")
        self.character, self.params, self.strength = character, dict(params), strength
        self.budget = int(params["plan_trials"] if budget is None else budget)
        self.executor = executor
        self.planner = Planner()

    def work(self):
        return self.planner.plan(self.character, self.params, self.strength, self.budget, self._progress,
                                 self._cancel.is_set, self.executor)

    def _progress(self, done: int, total: int, best) -> None:
        self.progress = done / max(total, 1)
        self.status = f"trial {done}/{total}"
        landing = best.get("landing") if isinstance(best, dict) else None
        if landing is not None:
            self.status += f", best landing ({landing[0]:.2f}, {landing[1]:.2f}) m"

    def store(self) -> None:
        """Keep the finished plan (main thread only; never after a cancel)."""
        if self.cancelled or self.result is None:
            raise RuntimeError("a cancelled or unfinished plan is never stored")
        self.planner.store(self.character, self.params, self.strength, self.result)


def stored_jump_plan(character: str, params: dict, strength):
    """The plan stored for this jump, or None (then it needs planning first)."""
    return Planner().stored(character, params, strength)
