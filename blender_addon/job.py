"""A simulation running beside Blender's UI: a worker thread, a progress fraction, a cancel flag.

The modal operator polls it from a timer, so the UI stays responsive and ESC can cancel; the
bake itself (which touches bpy) runs on the main thread once the job is done. No bpy here.
"""
from __future__ import annotations

import threading


class SimulationJob:
    def __init__(self, request):
        self.request = request
        self.progress = 0.0
        self.trajectory = None
        self.error: BaseException | None = None
        self._cancel = threading.Event()
        self._thread = threading.Thread(target=self._work, name="sim-athletics", daemon=True)

    def start(self) -> "SimulationJob":
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

    def _work(self) -> None:
        from sim_core.simulate import run
        try:
            self.trajectory = run(self.request, progress=self._set_progress, cancelled=self._cancel.is_set)
        except BaseException as exc:          # handed to the main thread, which reports it
            self.error = exc

    def _set_progress(self, fraction: float) -> None:
        self.progress = float(fraction)
