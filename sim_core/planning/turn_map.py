"""The turn's hop measured as a map (issue 29's lateral targets): the heading each ``turn_angle`` reaches.

A target to the side is flown by turning first (one hop, control/turn.py) and then forward
(planning/commanded.py plan_turned). The hop's heading is not smooth in its angle - asked 0.50 / 0.51 /
0.52 rad it turned the woman 35.7 / 53.1 / 47.8 deg (the feet pivot on the ground after the touchdown as
the spinning body is stopped; docs/jump_to_target.md) - but it is the same every run: the hop starts from
the same standing state and does not depend on the jump after it. So the hop is measured on a fine grid,
once, and the plan inverts the measured map (the skill's table ``turn_headings``, turn_for_heading)
instead of stepping through it. ``tools/turn_headings.py`` writes the table; a test replays a stored
row."""
from __future__ import annotations

import math

import numpy as np

from ..control.turn import jump_start, turn_duration
from ..simulate import RunRequest, run
from ..skills.jump_to_target.behaviour import leap_params, scene_for
from ..skills.jump_to_target.commanded import commanded_settings, table

MAP_TARGET, MAP_AIR_TIME, MAP_WINDUP = (1.0, 0.0, 0.0, 0.0), 0.45, 1.25   # definition: any jump (the hop is the same)


def hop_heading(character: str, angle: float) -> tuple[float, float, bool]:
    """(heading rad, the COM's lowest height m, whether the leap's crouch began) of the hop turned by
    ``angle``: the pelvis's heading when the leap's own crouch begins (the commanded take-off flies along
    it), the run stopped soon after."""
    settings = {**commanded_settings(table(character), MAP_AIR_TIME, MAP_TARGET[0]), "turn_angle": angle}
    params = {**leap_params(settings, MAP_TARGET, MAP_WINDUP, MAP_AIR_TIME), "turn_angle": angle}
    duration = turn_duration(0.0, angle) + 0.4                # definition: a margin past the longest hop
    trajectory = run(RunRequest("leap", character, params=params, duration=duration,
                                world=scene_for(character, MAP_TARGET)))
    a = trajectory.arrays
    begun = jump_start(trajectory)
    k = min(int(np.searchsorted(a["time"], begun)), len(a["time"]) - 1) if begun else len(a["time"]) - 1
    w, x, y, z = a["body_quat"][k, trajectory.body_index("PELVIS")]
    heading = math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    return heading, float(a["com"][:k + 1, 2].min()), bool(begun)
