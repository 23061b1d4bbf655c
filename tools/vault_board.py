"""The vault's board phase, measured off a run (issue 31: why the COM leaves the board low).

    python tools/vault_board.py [--set block_hip=-0.5 ...] [--duration 0.9]
                                [--board-friction 1.5] [--board-tilt 0.08] [--horse-gap 1.113]

Runs the woman's vault for ``--duration`` seconds (her table's row; ``--set`` replaces settings of
it, run with low_level 1) and prints, per 5 ms frame of the board contact, the deck's deflection,
the board's vertical force, the right leg's and shoulder's angles, the COM's velocity, the spin
L_y, the energies (the body's kinetic, translational and rotational, its potential, the deck's
spring) and the leg strut: the angle of the COM from the right toe (- the feet ahead). Then the
energy at the touchdown, at the deepest deflection and at the liftoff; the work done on her and
the deck over the contact by each source (the servos of the legs, arms and the rest, the passive
forces - the deck's spring-damper -, the contacts), integrated over every physics step (MuJoCo's
mj_step is wrapped to step one at a time, which is the same simulation); how far the right toe slid
along the board; and Table 1; the horse state's COM velocity and height at its start and end, and the work over it
by the same sources (the clavicles' servos, ``girdle``, apart: the shoulder-girdle push).

--board-friction and --board-tilt are what-ifs of the apparatus, not the shipped board: the deck's
friction coefficient (the shipped 1.0, FOOT_FRICTION), and the deck tilted by this angle (rad) about
its centre, the front edge up (the shipped deck is flat).
"""
from __future__ import annotations

import argparse
import math

import mujoco
import numpy as np

import sim_core.world.apparatus as apparatus
from sim_core.simulate import RunRequest, run
from sim_core.skills.vault.behaviour import CONSTANTS, DEFLECTION_JOINT, calibrated
from sim_core.skills.vault.report import format_table_1


def settings(overrides: list[str]) -> dict:
    if not overrides:
        return {}
    row = dict(calibrated("woman", "human")["settings"])
    for item in overrides:
        name, value = item.split("=")
        row[name] = float(value)
    return dict(row, low_level=1)


class WorkBySource:
    """mujoco.mj_step wrapped: per physics step, the power of the actuators (by joint group), of the
    passive forces and of the constraints (contacts; joint limits), times the step, summed."""

    GROUPS = {"legs": ("hip", "knee", "ankle"), "arms": ("shoulder", "elbow", "wrist"), "girdle": ("clav",)}

    def __init__(self):
        self.step, self.rows, self.masks = mujoco.mj_step, [], None

    def __enter__(self):
        mujoco.mj_step = self.wrapped
        return self

    def __exit__(self, *exc):
        mujoco.mj_step = self.step

    def wrapped(self, model, data, nstep=1):
        if self.masks is None:
            names = [model.joint(model.dof_jntid[i]).name for i in range(model.nv)]
            self.masks = {g: np.array([any(k in n for k in keys) for n in names]) for g, keys in self.GROUPS.items()}
            self.total = dict.fromkeys((*self.GROUPS, "other servos", "passive", "contacts", "limits"), 0.0)
        for _ in range(nstep):
            v = data.qvel
            power = {g: float(data.qfrc_actuator[m] @ v[m]) for g, m in self.masks.items()}
            power["other servos"] = float(data.qfrc_actuator @ v) - sum(power.values())
            power["passive"] = float(data.qfrc_passive @ v)
            power["contacts"], power["limits"] = self.constraint_power(model, data)
            self.step(model, data)
            for k, p in power.items():
                self.total[k] += p * model.opt.timestep
            self.rows.append((float(data.time), dict(self.total)))

    @staticmethod
    def constraint_power(model, data) -> tuple[float, float]:
        n = data.nefc
        if not n:
            return 0.0, 0.0
        jac = np.zeros((n, model.nv))
        if mujoco.mj_isSparse(model):
            mujoco.mju_sparse2dense(jac, data.efc_J, data.efc_J_rownnz, data.efc_J_rowadr, data.efc_J_colind)
        else:
            jac = data.efc_J[:n * model.nv].reshape(n, model.nv)
        power = data.efc_force[:n] * (jac @ data.qvel)
        limit = data.efc_type[:n] == mujoco.mjtConstraint.mjCNSTR_LIMIT_JOINT
        return float(power[~limit].sum()), float(power[limit].sum())

    def between(self, t0: float, t1: float) -> dict:
        def at(t):
            return min(self.rows, key=lambda r: abs(r[0] - t))[1]
        start, end = at(t0), at(t1)
        return {k: end[k] - start[k] for k in end}


def what_if_board(friction: float | None, tilt: float | None) -> None:
    """The deck's friction and tilt set for this process's runs (apparatus._felt wrapped)."""
    felt = apparatus._felt

    def board_felt(geom):
        felt(geom)
        if geom.name == "springboard":
            if friction is not None:
                geom.friction = [friction, 0.005, 0.0001]
                geom.priority = 2                    # the deck's friction, not the larger of the two
            if tilt:
                geom.quat = [math.cos(-tilt / 2), 0.0, math.sin(-tilt / 2), 0.0]
    apparatus._felt = board_felt


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--set", action="append", default=[], help="name=value on top of the woman's row")
    parser.add_argument("--duration", type=float, default=0.9)
    parser.add_argument("--board-friction", type=float, default=None)
    parser.add_argument("--board-tilt", type=float, default=None)
    parser.add_argument("--horse-gap", type=float, default=None,
                        help="the board this far from the horse (m; vault_any.json's horse_gap, a probe)")
    args = parser.parse_args()
    if args.horse_gap is not None:
        CONSTANTS.horse_gap = args.horse_gap
    if args.board_friction is not None or args.board_tilt:
        what_if_board(args.board_friction, args.board_tilt)
    with WorkBySource() as work:
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
    on = np.flatnonzero((board > 0) & (time < events.get("first_flight", time[-1]) + 0.015))   # this contact's frames
    t0, t1 = float(time[on[0]] - 0.005), float(time[on[-1]] + 0.005)
    print(f"work over the board contact {t0:.3f}-{t1:.3f} s (J): "
          + ", ".join(f"{k} {v:+.0f}" for k, v in work.between(t0, t1).items()))
    toe_x = np.array([a["body_pos"][i, list(a["body_names"]).index("TOER"), 0] for i in range(len(time))])
    stuck = on[0] + int(np.argmax(np.abs(np.diff(toe_x[on[0]:on[-1] + 1])) < 0.002 * 1))
    print(f"the right toe slid {toe_x[stuck] - toe_x[on[0]]:.3f} m along the board before it stuck at "
          f"{time[stuck]:.3f} s; the toe's largest backward/forward motion after: "
          f"{np.ptp(toe_x[stuck:on[-1] + 1]):.3f} m")
    print("strut (deg): " + ", ".join(f"{name} {value:+.1f}" for name, value in struts.items()))
    lift = on[-1] + 1
    v = a["com_vel"][lift]
    print(f"liftoff ({time[lift]:.3f} s): v_x {v[0]:.2f}, v_z {v[2]:.2f} m/s, L_y {a['angmom'][lift, 1]:.1f} kg m^2/s, "
          f"translational KE {0.5 * mass * float(v @ v):.0f} J; Takei's corner (3.97, 2.98) m/s needs "
          f"{0.5 * mass * (3.97 ** 2 + 2.98 ** 2):.0f} J, his means (4.61, 3.34) {0.5 * mass * (4.61 ** 2 + 3.34 ** 2):.0f} J")
    shares = meta["metrics"].get("horse_bodies") or {}
    print("on the horse (share of its vertical impulse): "
          + (", ".join(f"{b} {100 * x:.0f} %" for b, x in shares.items()) or "nothing"))
    bodies = list(a["body_names"])
    horse = next((when for when, name in meta["phase_events"] if name == "horse"), None)
    if horse is not None:
        k = int(np.searchsorted(time, horse - 1e-9))
        shoulder, wrist = a["body_pos"][k, bodies.index("UARMR")], a["body_pos"][k, bodies.index("HANDR")]
        arm = wrist - shoulder
        trunk = a["body_pos"][k, bodies.index("CHEST1")] - a["body_pos"][k, bodies.index("PELVIS")]
        print(f"the hand touchdown ({horse:.3f} s): the right shoulder at x {shoulder[0]:.3f}, z {shoulder[2]:.3f} m, the "
              f"wrist at x {wrist[0]:.3f}, z {wrist[2]:.3f} m, the arm {math.degrees(math.atan2(arm[0], -arm[2])):.0f} deg "
              f"from the downward vertical (+ forward), the trunk pitched {math.degrees(math.atan2(trunk[0], trunk[2])) % 360:.0f} deg")
        off = next((when for when, name in meta["phase_events"] if name == "second_flight"), None)
        if off is not None:
            j = int(np.searchsorted(time, off - 1e-9))
            print(f"L_y at the hand touchdown {a['angmom'][k, 1]:.1f}, at the horse liftoff ({off:.3f} s) "
                  f"{a['angmom'][j, 1]:.1f} kg m^2/s")
            print(f"the horse state {horse:.3f}-{off:.3f} s: COM (v_x, v_z) ({a['com_vel'][k, 0]:.2f}, "
                  f"{a['com_vel'][k, 2]:+.2f}) -> ({a['com_vel'][j, 0]:.2f}, {a['com_vel'][j, 2]:+.2f}) m/s, height "
                  f"{a['com'][k, 2]:.3f} -> {a['com'][j, 2]:.3f} m; work over it (J): "
                  + ", ".join(f"{name} {value:+.0f}" for name, value in work.between(horse, off).items()))
    metrics = meta["metrics"]
    print(f"outcome {meta['outcome']} (the run's {args.duration:g} s), rotation {metrics['rotation']:.2f} rad, "
          f"fell at {metrics.get('fall_time')}")
    print(f"events: {meta['phase_events'][:8]}")
    print(format_table_1(trajectory))


if __name__ == "__main__":
    main()
