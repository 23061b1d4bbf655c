"""The turn's hop measured as a map (issue 29's lateral targets): the heading each ``turn_angle`` reaches
(and the quarter turn's, ``turn_first``, with the line of the sideways jump after it: quarter_line).

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

import mujoco
import numpy as np

from ..control.measure import yaw_of
from ..control.turn import jump_start, turn_duration
from ..simulate import RunRequest, run
from ..skills.jump_to_target.behaviour import leap_params, scene_for
from ..skills.jump_to_target.commanded import commanded_settings, table, turned_settings, way_body

MAP_TARGET, MAP_AIR_TIME, MAP_WINDUP = (1.0, 0.0, 0.0, 0.0), 0.45, 1.25   # definition: any jump (the hop is the same)
MAP_FALL_HEIGHT = 0.5                   # m: definition: hops whose COM went lower fell (tools/turn_headings.py's default)
SIDE_TARGET, SIDE_AIR_TIME = 1.15, 0.44  # definition: the quarter map's jump, in the middle of the sideways region
# definition: a sideways row's own quarter map's jump (quarter_line's ``way``), in the middle of its region
SIDE_JUMPS = {"sideways": (SIDE_TARGET, SIDE_AIR_TIME), "sideways_long_short": (1.3, 0.5),
              "sideways_far_short": (1.48, 0.45)}
LINE_DISTANCES, LINE_AIR_TIME = (0.85, 1.15), 0.44   # definition: the hop line map's two jumps, near and far in the turned region


def hop_heading(character: str, angle: float) -> tuple[float, float, bool]:
    """(heading rad, the COM's lowest height m, whether the leap's crouch began) of the hop turned by
    ``angle``: the pelvis's heading when the leap's own crouch begins (the commanded take-off flies along
    it), the run stopped soon after."""
    return hop_stance(character, angle)[:3]


def quarter_line(character: str, scale: float, way: str = "sideways") -> dict:
    """The quarter turn of ``turn_first`` ``scale`` (its two hops) and the commanded jump after it, measured:
    the hops' heading, the middle of the feet when the leap's crouch begins (``feet_x``, ``feet_y``) and where
    a commanded jump straight to that side (SIDE_TARGET m, SIDE_AIR_TIME s; ``way`` a sideways row's: that row's
    jump, SIDE_JUMPS) landed, its line's direction from the feet (``line`` rad) and whether it ended balanced
    (``stood``); None where the hops fell."""
    heading, lowest, begun, feet = hop_stance(character, scale, "turn_first")
    if not begun or lowest < MAP_FALL_HEIGHT:
        return None
    distance, air_time = SIDE_JUMPS[way]
    landing, stood = jump_after(character, "turn_first", scale, (0.0, -math.copysign(distance, scale)), air_time,
                                way)   # + turns right
    return {"turn_first": scale, "heading": heading, "feet_x": feet[0], "feet_y": feet[1],
            "line": math.atan2(landing[1] - feet[1], landing[0] - feet[0]), "stood": stood}


def hop_line(character: str, angle: float) -> dict:
    """The hop of ``turn_angle`` ``angle`` and the commanded jumps after it, measured as quarter_line's row: the
    hop's heading and the middle of the feet at the leap's crouch, and two commanded jumps along that heading
    (LINE_DISTANCES m from the start's feet in LINE_AIR_TIME s): ``line`` the direction from the feet to the
    middle of their landings (rad), ``stood`` the share of the two that ended balanced; None where the hop fell.
    The heading does not say where the jump after the hop lands (each hop leaves its own stance, and the jump
    from it drifts its own way, docs/jump_to_target.md); the line does, whatever the distance aimed."""
    heading, lowest, begun, feet = hop_stance(character, angle)
    if not begun or lowest < MAP_FALL_HEIGHT:
        return None
    jumps = [jump_after(character, "turn_angle", angle, (d * math.cos(heading), d * math.sin(heading)), LINE_AIR_TIME)
             for d in LINE_DISTANCES]
    middle = np.mean([landing for landing, _ in jumps], axis=0)
    return {"turn_angle": angle, "heading": heading, "feet_x": feet[0], "feet_y": feet[1],
            "line": math.atan2(middle[1] - feet[1], middle[0] - feet[0]),
            "stood": float(np.mean([stood for _, stood in jumps]))}


def jump_after(character: str, setting: str, turn: float, point, air_time: float, way: str | None = None) -> tuple:
    """A commanded jump aimed at ``point`` (x, y m from the start's feet) in ``air_time`` s after the turn
    ``setting`` (``turn_angle``: one hop, ``turn_first``: the quarter turn) ``turn`` (``way``: the row a sideways way
    flies, way_body; none: the table's own): (where the feet's middle landed (x, y m), 1.0 if it ended balanced having
    flown (more than half the air time) else 0.0)."""
    from .jump import JumpTrial      # the trial's measure; jump.py plans with this module's map
    target = (float(point[0]), float(point[1]), 0.0, 0.0)
    way = way or ("sideways" if setting == "turn_first" else "turned")
    _, measured = JumpTrial(character, target, air_time, MAP_WINDUP, "human")(
        turned_settings(way_body(table(character), way), air_time, math.hypot(*target[:2]),
                        math.atan2(target[1], target[0]), turn, way))
    return measured["landing"], float(measured["outcome"] in ("success", "stepped") and measured["air_time"] > 0.5 * air_time)


def hop_stance(character: str, angle: float, setting: str = "turn_angle") -> tuple[float, float, bool, tuple]:
    """hop_heading's figures and the middle of the feet (x, y m) when the leap's own crouch begins; ``setting``
    "turn_first": the quarter turn's two hops scaled by ``angle`` instead of one hop (the leap's ``turn_first``)."""
    settings = {**commanded_settings(table(character), MAP_AIR_TIME, MAP_TARGET[0]), setting: angle}
    params = {**leap_params(settings, MAP_TARGET, MAP_WINDUP, MAP_AIR_TIME), setting: angle}
    duration = (turn_duration(angle, 0.0) if setting == "turn_first" else turn_duration(0.0, angle)) + 0.4   # definition: a margin past the longest hop
    trajectory = run(RunRequest("leap", character, params=params, duration=duration,
                                world=scene_for(character, MAP_TARGET)))
    a = trajectory.arrays
    begun = jump_start(trajectory)
    k = min(int(np.searchsorted(a["time"], begun)), len(a["time"]) - 1) if begun else len(a["time"]) - 1
    pelvis = np.empty(9)
    mujoco.mju_quat2Mat(pelvis, a["body_quat"][k, trajectory.body_index("PELVIS")])
    heading = yaw_of(pelvis)
    feet = a["body_pos"][k, [trajectory.body_index("FOOTR"), trajectory.body_index("FOOTL")], :2].mean(axis=0)
    return heading, float(a["com"][:k + 1, 2].min()), bool(begun), (float(feet[0]), float(feet[1]))
