"""The vault's board phase, measured off a run (issue 31: why the COM leaves the board low).

    python tools/vault_board.py [--set block_hip=-0.5 ...] [--duration 0.9]

Runs the woman's vault for ``--duration`` seconds (her table's row; ``--set`` replaces settings of
it, run with low_level 1) and prints, per 5 ms frame of the board contact, the deck's deflection,
the board's vertical force, the right leg's and shoulder's angles, the COM's velocity, the spin
L_y, the energies (the body's kinetic, translational and rotational, its potential, the deck's
spring) and the leg strut: the angle of the COM from the right toe (- the feet ahead). Then the
energy at the touchdown, at the deepest deflection and at the liftoff, and Table 1's first rows.
"""
from __future__ import annotations

import argparse
import math

import mujoco
import numpy as np

from sim_core.simulate import RunRequest, run
from sim_core.skills.vault.behaviour import DEFLECTION_JOINT, calibrated
from sim_core.skills.vault.report import format_table_1


def settings(overrides: list[str]) -> dict:
    if not overrides:
        return {}
    row = dict(calibrated("woman", "human")["settings"])
    for item in overrides:
        name, value = item.split("=")
        row[name] = float(value)
    return dict(row, low_level=1)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--set", action="append", default=[], help="name=value on top of the woman's row")
    parser.add_argument("--duration", type=float, default=0.9)
    args = parser.parse_args()
    trajectory = run(RunRequest("vault", "woman", params=settings(args.set), duration=args.duration))
    a, meta = trajectory.arrays, trajectory.meta
    model = mujoco.MjModel.from_xml_string(meta["model_xml"])
    data = mujoco.MjData(model)
    mass = float(meta["total_mass"])
    deck = model.joint(DEFLECTION_JOINT)
    deck_q, deck_v, k = int(deck.qposadr[0]), int(deck.dofadr[0]), float(model.jnt_stiffness[deck.id])
    qadr = {name: int(model.joint(name).qposadr[0]) for name in ("knee_r_y", "hip_r_y", "ankle_r_y", "shoulder_r_z")}
    toe = model.body("TOER").id
    events = dict((name, when) for when, name in meta["phase_events"])
    time = a["time"]
    board = a["contact_force"][:, :, meta["world_geoms"].index("springboard"), 2].sum(1)
    first = int(np.searchsorted(time, events["board"] - 1e-9)) - 1
    last = int(np.searchsorted(time, events.get("first_flight", events["board"] + 0.2) + 0.015))
    print(" t (s)  deck (m) F_z (N)  knee   hip  ankle shoulder  v_x   v_z   L_y  | KE   trans  rot  PE-PE0 spring total (J) | strut (deg)")
    budget, struts = {}, {}
    for i in range(first, last + 1):
        data.qpos[:], data.qvel[:] = a["qpos"][i], a["qvel"][i]
        mujoco.mj_forward(model, data)
        body_v = data.qvel.copy()
        body_v[deck_v] = 0.0
        product = np.zeros(model.nv)
        mujoco.mj_mulM(model, data, product, body_v)
        kinetic = 0.5 * float(body_v @ product)
        translational = 0.5 * mass * float(a["com_vel"][i] @ a["com_vel"][i])
        potential = mass * 9.81 * float(a["com"][i, 2] - a["com"][first, 2])
        spring = 0.5 * k * float(data.qpos[deck_q]) ** 2
        reach = a["com"][i] - data.xpos[toe]
        strut = math.degrees(math.atan2(float(reach[0]), float(reach[2])))
        q = {name: float(a["qpos"][i, adr]) for name, adr in qadr.items()}
        total = kinetic + potential + spring
        budget.setdefault("touchdown", total)
        if board[i] > 0:
            struts.setdefault("touchdown", strut)
            struts["liftoff"] = strut
        if a["qpos"][i, deck_q] <= a["qpos"][first:last + 1, deck_q].min():
            budget["deepest"], budget["spring at the deepest"] = total, spring
        if board[i] > 0:
            budget["liftoff"] = total
        print(f"{time[i]:6.3f} {a['qpos'][i, deck_q]:+8.4f} {board[i]:7.0f} {q['knee_r_y']:+5.2f} {q['hip_r_y']:+5.2f} "
              f"{q['ankle_r_y']:+5.2f} {q['shoulder_r_z']:+6.2f}  {a['com_vel'][i, 0]:5.2f} {a['com_vel'][i, 2]:+5.2f} "
              f"{a['angmom'][i, 1]:5.1f} | {kinetic:5.0f} {translational:5.0f} {kinetic - translational:4.0f} "
              f"{potential:+6.0f} {spring:6.0f} {total:6.0f}   | {strut:+6.1f}")
    print("energy (J): " + ", ".join(f"{name} {value:.0f}" for name, value in budget.items()))
    print("strut (deg): " + ", ".join(f"{name} {value:+.1f}" for name, value in struts.items()))
    print(f"events: {meta['phase_events'][:8]}")
    print(format_table_1(trajectory))


if __name__ == "__main__":
    main()
