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

from .simcore import sim


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


def planned_request(request, cancelled=None):
    """(the request a bake runs, its plan or None): a landing's with the foot placement, a dive's with
    the take-off for its platform, that its plan chose above the loop by a few trial runs
    (sim_core.planning.planned_request, as ``simulate`` does); any other request as it is."""
    return sim("planning").planned_request(request, cancelled=cancelled)


def plan_note(plan) -> str:
    """What a bake's report adds about a landing's or a dive's plan ("" for none)."""
    return "" if plan is None else "; " + sim("planning").describe(plan)


class SimulationJob(Job):
    def __init__(self, request):
        super().__init__("sim-athletics-run")
        self.request = request
        self.plan = None

    @property
    def trajectory(self):
        return self.result

    def work(self):
        request, self.plan = planned_request(self.request, cancelled=self._cancel.is_set)
        return sim("simulate").run(request, progress=self._set_progress, cancelled=self._cancel.is_set)

    def _set_progress(self, fraction: float) -> None:
        self.progress = float(fraction)


def cancelled_error() -> type[BaseException]:
    """The Cancelled exception of the sim_core in use (sim_core.errors once it is there)."""
    errors = sim("errors")
    return getattr(errors, "Cancelled", None) or sim("simulate").Cancelled


class Planner:
    """The jump planner of the sim_core in use (``planning/jump.py``: plans take ``budget`` and
    ``cancelled``; kept in the user's plan store): ``stored``, ``plan``, ``store``."""

    def __init__(self):
        self.module = sim("planning.jump")

    def stored(self, character: str, params: dict, strength):
        return self.module.planned(character, params, strength)

    def plan(self, character: str, params: dict, strength, budget: int, progress, cancelled, executor=None) -> dict:
        m = self.module
        return m.plan_jump(character, target_of(params), params["air_time"], params["windup_time"],
                           m.strength_name(strength), budget, progress=progress, cancelled=cancelled, executor=executor)

    def store(self, character: str, params: dict, strength, plan: dict) -> None:
        m = self.module
        m.store_user_plan(character, m.request_of(target_of(params), params["air_time"], params["windup_time"],
                                                  m.strength_name(strength)), plan)


def target_of(params: dict) -> tuple:
    """The planner's target of jump_to_target parameters: (x, y, z, obstacle height)."""
    return tuple(params[k] for k in ("target_x", "target_y", "target_z", "obstacle_height"))


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
