"""Work running beside Blender's UI: a worker thread, a progress fraction, a cancel flag.

A modal operator polls a job from a timer, so the UI stays responsive and Esc can cancel; what
touches bpy (the bake) or writes a file (storing a jump plan) happens on the main thread once
the job is done and was not cancelled - a cancelled job has written nothing. No bpy here.

* :class:`SimulationJob` - one run (``simulate.run``), cancelled within 50 control ticks.
* :class:`PlanningJob` - a jump plan (many trial runs): ``planning.jump.plan_jump`` with its
  ``cancelled`` hook, or the older ``control.target_jump.plan_jump``, cancelled after the trial
  in flight.
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


def planning_api():
    """(plan_jump, store_plan, stored_plan, takes_cancel) of the jump planner: the planning
    room's (``planning/jump.py``, which takes ``budget`` and ``cancelled``) where it exists,
    else the older one in ``control/target_jump.py``."""
    import importlib
    try:
        module = importlib.import_module(f"{SIM_CORE}.planning.jump")
        new = True
    except ModuleNotFoundError as exc:
        if not (exc.name or "").startswith(f"{SIM_CORE}.planning"):
            raise
        module, new = None, False
    old = sim("control.target_jump")

    def pick(name):
        return getattr(module, name, None) or getattr(old, name)
    return (module.plan_jump if new else old.plan_jump), pick("store_plan"), pick("stored_plan"), new


JUMP_REQUEST_KEYS = ("target_x", "target_y", "target_z", "obstacle_height", "air_time", "windup_time")


def jump_request(params: dict, strength) -> dict:
    """The key a jump plan is stored under: the jump_to_target parameters that define the jump,
    and the strength (as JumpToTarget.request)."""
    request = {k: float(params[k]) for k in JUMP_REQUEST_KEYS}
    request["strength"] = strength
    return request


class PlanningJob(Job):
    """Plan a jump for ``character`` (a name) to the request's target; ``store()`` (main thread,
    after a successful finish) writes the plan to the character's plan table."""

    def __init__(self, character: str, params: dict, strength="human", budget: int | None = None, executor=None):
        super().__init__("sim-athletics-plan")
        self.character, self.params, self.strength = character, dict(params), strength
        self.budget = int(params["plan_trials"] if budget is None else budget)
        self.executor = executor
        self.request = jump_request(params, strength)

    @property
    def target(self) -> tuple:
        p = self.params
        return (p["target_x"], p["target_y"], p["target_z"], p["obstacle_height"])

    def work(self):
        plan_jump, _, _, new = planning_api()
        Cancelled = cancelled_error()
        p = self.params
        if new:
            return plan_jump(self.character, self.target, p["air_time"], p["windup_time"], self.strength,
                             self.budget, progress=self._progress, cancelled=self._cancel.is_set,
                             executor=self.executor)

        def progress(done, total, best):          # the older planner has no cancel hook: stop it
            self._progress(done, total, best)     # between trials
            if self._cancel.is_set():
                raise Cancelled("jump planning cancelled; nothing was written")
        plan = plan_jump(self.character, self.target, p["air_time"], p["windup_time"], self.strength,
                         trials=self.budget, progress=progress)
        if self._cancel.is_set():
            raise Cancelled("jump planning cancelled; nothing was written")
        return plan

    def _progress(self, done: int, total: int, best) -> None:
        self.progress = done / max(total, 1)
        self.status = f"trial {done}/{total}"
        if isinstance(best, dict) and best.get("landing") is not None:
            x, y = best["landing"][:2]
            self.status += f", best landing ({x:.2f}, {y:.2f}) m"

    def store(self, script: str = "blender_addon: Plan Jump") -> None:
        """Write the finished plan (main thread only; never after a cancel)."""
        if self.cancelled or self.result is None:
            raise RuntimeError("a cancelled or unfinished plan is never stored")
        _, store_plan, _, _ = planning_api()
        store_plan(self.character, self.request, self.result, script)


def stored_jump_plan(character: str, params: dict, strength):
    """The plan stored for this jump, or None (then Simulate & Bake would have to plan it)."""
    _, _, stored_plan, _ = planning_api()
    return stored_plan(character, jump_request(params, strength))
