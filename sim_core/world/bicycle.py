"""The bicycle: an articulated prop (Hodgins et al. 1995, Fig. 4: four joint DOF on a free frame).

Bodies and joints (names as the trajectory and the rider's attachments use them):

    bicycle_frame        free joint "bicycle_free" (rear frame: tubes, saddle, rear axle)
      bicycle_fork       hinge "bicycle_steer" along the steering axis (fork, stem, handlebar, grips)
        bicycle_front_wheel  hinge "bicycle_front_spin" (rolls on the ground by contact)
      bicycle_rear_wheel hinge "bicycle_rear_spin"
      bicycle_crank      hinge "bicycle_crank_spin" (two arms 180 deg apart, pedals)

The frame's origin is the rear axle; in the frame's own axes X points forward, Y left, Z up (the
thesis frame of SEEDS-WAVE2 §0), so every spin is positive about +Y when riding forward and the
steering angle is positive to the left.

* Drive: a fixed gear (no freewheel, [A] 120). The crank drives the rear wheel through a
  spring-damper, the fixed tendon "bicycle_chain" of length ``L = g*theta_crank - theta_rear``
  with stiffness ``CHAIN_STIFFNESS`` and damping ``CHAIN_DAMPING``: it puts
  ``tau = -k L - b dL/dt`` times the moment arms (g on the crank, -1 on the wheel), i.e.
  ``tau_rear = k(g theta_c - theta_r) + b(...)`` and ``-g`` times that on the crank, the seed's
  reading. ``g`` is wheel turns per crank turn.
* Freewheel (``Bicycle.freewheel``, the coast and stop courses): the chain is the same tendon, but
  it carries no spring; the actuator "bicycle_freewheel" on it is a one-way viscous clutch,
  ``F = -FREEWHEEL_DAMPING dL/dt`` held to the driving sign (MuJoCo's force range ``[-max, 0]``): the
  crank drives the wheel forward, and when the wheel overruns the crank it is slack. It has no
  control (gain 0) and no position term, so it re-engages at any crank angle, as a ratchet with
  many pawls does; under drive it slips by torque / FREEWHEEL_DAMPING (4 % of the cadence at 4 m/s).
* Rim brakes: dry friction on each wheel hinge (front wheel against the fork, rear wheel against
  the frame), MuJoCo's joint ``frictionloss``, at most ``BRAKE_MAX_TORQUE``: the rider sets it
  (sim_core.skills.bicycle, the stop) through the run's edit log, so a replay brakes at the same
  ticks. Dry friction holds the bicycle at rest, as a squeezed brake does (a damper let it creep
  backwards 2-5 cm/s under the rider leaning on his foot, and fall).
* Rolling resistance proportional to speed ([A] 120): hinge damping on both wheels,
  ``tau = -b omega`` with ``b = (c/2) r^2`` so that the ground force of the two wheels is ``c v``.
* Wheels: cylinders ``TYRE_WIDTH`` wide touching the ground by contact only (no joint to the
  ground); the frame's other geoms also collide with the ground, so a fall is seen as a frame,
  fork or pedal contact.

Dimensions and masses (a 26-inch city / hybrid bicycle of 13.7 kg; docs/bicycle.md lists the
sources): Hodgins & Pollard 1997 Fig. 3's "wheel radius" 0.667 m for the man's bike is read as a
*diameter* (26 in = 0.660 m nominal; 0.667 m is a 26 x 1.75 in tyre's outer diameter within 3 %),
so r = 0.3335 m. Head angle 71 deg and fork offset 45 mm give a trail of 67 mm (trail =
(r cos(head) - offset) / sin(head)), inside the 55-80 mm of common road and city bikes. Wheelbase
1.05 m, chainstay 0.43 m, bottom bracket 0.28 m high, crank arms 170 mm, seat tube 73 deg.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import mujoco
import numpy as np

# --- geometry (m, rad) -----------------------------------------------------------------------
WHEEL_RADIUS = 0.3335           # 26 in wheel: Fig. 3's 0.667 m read as the diameter
TYRE_WIDTH = 0.045              # 26 x 1.75 in tyre (seen)
CONTACT_DISC_WIDTH = 0.004      # the tyre as felt: a thin disc, the Whipple model's knife-edge wheel. A
                                # flat 45 mm cylinder moves its contact to the rim edge (22 mm sideways)
                                # as soon as it leans, which a round tyre does not; it made the bicycle
                                # capsize at every speed from 3 to 7 m/s (docs/bicycle.md)
WHEELBASE = 1.05
HEAD_ANGLE = math.radians(71.0) # head tube from the horizontal (city / hybrid: 69-72 deg)
FORK_OFFSET = 0.045             # rake: front axle ahead of the steering axis, perpendicular to it
CHAINSTAY = 0.43                # rear axle to bottom bracket, horizontal
BOTTOM_BRACKET_HEIGHT = 0.28    # above the ground
CRANK_LENGTH = 0.170            # crank arm l of eqs. 9-10
PEDAL_HALF_SPACING = 0.09       # pedal centre from the bicycle's mid-plane (Q-factor / 2 + pedal)
SEAT_TUBE_ANGLE = math.radians(73.0)
SADDLE_FROM_BOTTOM_BRACKET = 0.68   # along the seat tube to the saddle's top, set for the man (hip joint
                                    # 0.94 m high): the pedal at the bottom is 0.91 m from the hip, knee ~30 deg
HEAD_TUBE_TOP = 0.86            # height of the steering axis point where the stem clamps
STEM_RISE = 0.12                # handlebar above the head tube top
GRIP_BACK = 0.10                # grips behind the steering axis (swept city bar)
GRIP_HALF_WIDTH = 0.28          # grip centre from the mid-plane (560 mm bar)
STEER_RANGE = math.radians(60)  # fork stop either side

# --- masses (kg) and inertias ------------------------------------------------------------------
FRAME_MASS = 7.5                # frame, saddle and post, rack, mudguards, chain (city bike)
FORK_MASS = 1.8                 # fork, stem, handlebar, grips
FRONT_WHEEL_MASS = 1.5          # rim, spokes, hub, tyre and tube
REAR_WHEEL_MASS = 2.0           # plus sprocket
CRANK_MASS = 0.9                # arms, chainring, pedals
WHEEL_RIM_SHARE = 0.75          # axial inertia = share * m r^2 (mass mostly at the rim; Meijaard 2007)

# --- drive and resistance ----------------------------------------------------------------------
DEFAULT_GEAR = 2.6              # wheel turns per crank turn (e.g. 42/16)
CHAIN_STIFFNESS = 2000.0        # N m / rad of rear-wheel angle: stretch < 0.1 rad in a ride (docs/bicycle.md)
CHAIN_DAMPING = 20.0           # N m s / rad
ROLLING_RESISTANCE = 1.5        # N s / m: ground force c v of both wheels (= Crr m g of a 110 kg
                                # rider + bike at 4 m/s for Crr = 0.0055, Wilson 2004)
FREEWHEEL_DAMPING = 50.0        # N m s / rad of rear-wheel slip. Stiffer is not better: MuJoCo's implicitfast
                                # step of a clamped stiff damper gains energy while engaged (the riderless
                                # bicycle pushed by its spinning crank: T = 11.5 / 12.1 / 13.3 / 26.5 s at
                                # 50 / 100 / 200 / 5000, the fixed gear's 11.1 s); under a 25 N m drive it
                                # slips 0.5 rad/s (4 % of the cadence at 4 m/s)
FREEWHEEL_MAX_FORCE = 1000.0    # N m: the clutch's largest torque on the wheel (never reached)
BRAKE_MAX_TORQUE = 60.0         # N m per wheel: both at once decelerate rider and bicycle (114 kg) by 3.2 m/s^2,
                                # a hard stop on a city bike (rim brakes: 2-4 m/s^2, Wilson 2004 ch. 7)
BRAKE_SOLREF = (0.005, 1.0)     # s, damping ratio of the brakes' dry friction (MuJoCo's joint solreffriction)
BRAKE_SOLIMP = (0.99, 0.999, 0.001, 0.5, 2.0)   # its impedance (solimpfriction). MuJoCo's dry friction is a soft
                                # constraint: under a steady load it creeps at a speed ~ (1 - d) / d * timeconst;
                                # at the defaults (0.9, 0.02 s) the braked bicycle crept forward 20-50 mm/s under the
                                # rider leaning on his foot and fell within 9-16 s of coming to rest (docs/bicycle.md)
CRANK_ARMATURE = 0.02           # kg m^2: drivetrain inertia (chainring, chain) about the crank axle
TYRE_FRICTION = 0.9             # rubber on asphalt
FRAME_COLOUR = [0.15, 0.35, 0.6, 1.0]
TYRE_COLOUR = [0.1, 0.1, 0.1, 1.0]

NAMES = dict(frame="bicycle_frame", fork="bicycle_fork", front="bicycle_front_wheel",
             rear="bicycle_rear_wheel", crank="bicycle_crank", free="bicycle_free",
             steer="bicycle_steer", front_spin="bicycle_front_spin", rear_spin="bicycle_rear_spin",
             crank_spin="bicycle_crank_spin", chain="bicycle_chain", freewheel="bicycle_freewheel")
WHEEL_BODIES = (NAMES["front"], NAMES["rear"])


def wheel_radius(size: float = 1.0) -> float:
    """The wheels' radius (m) of a bicycle of ``size`` (Bicycle.size: every length x size)."""
    return WHEEL_RADIUS * size


def trail(radius: float = WHEEL_RADIUS, head_angle: float = HEAD_ANGLE, offset: float = FORK_OFFSET) -> float:
    """Ground distance from the front contact back to where the steering axis meets the ground."""
    return (radius * math.cos(head_angle) - offset) / math.sin(head_angle)


# --- the rider's attachments (Hodgins et al. 1995 [A] 118-120) ---------------------------------
SEAT_PIVOT_HALF_WIDTH = 0.06    # the pelvis-seat pivot: two ball joints this far either side of the
                                # mid-plane make a hinge about the lateral axis (passive, SEEDS-WAVE2 §1.2)
SEAT_SOLREF = (0.004, 1.0)      # s, damping ratio: stiff (the pivot drifts < 1 mm)
LIMB_SOLREF = (0.02, 1.0)       # hands to grips, feet to pedals: two-sided soft springs ([A] 120)
ISCHIUM_BELOW_HIP = 0.065       # the seat bones are this far below the hip joints' centre
ISCHIUM_BEHIND_HIP = 0.03


@dataclass(frozen=True)
class Bicycle:
    """What a run asks of the bicycle prop: the gear ratio (wheel turns per crank turn), where
    the bicycle stands (rear contact at (x, y), facing ``heading`` rad from +X) and the prefix of
    the rider attached to it (None: riderless); ``freewheel``: the chain drives through a freewheel
    instead of the fixed gear; ``fit``: the saddle's height above the bottom bracket and the grips'
    place from the saddle as a share of the man's (a smaller rider's frame size: his leg length ratio);
    ``foot_time``: the feet's attachments' time constant (s; None: LIMB_SOLREF's, the man's); ``size``: the
    bicycle's every length (wheels, crank, frame, bar) and every mass as a share of the 26-inch one's, its
    angles kept (a child's bicycle; 1: the 26-inch one, exactly)."""
    gear: float = DEFAULT_GEAR
    x: float = 0.0
    y: float = 0.0
    heading: float = 0.0
    rider: str | None = None
    freewheel: bool = False
    fit: float = 1.0
    foot_time: float | None = None
    size: float = 1.0

    def to_dict(self) -> dict:
        return {"gear": self.gear, "x": self.x, "y": self.y, "heading": self.heading, "rider": self.rider,
                "freewheel": self.freewheel, **({"fit": self.fit} if self.fit != 1.0 else {}),
                **({"foot_time": self.foot_time} if self.foot_time is not None else {}),
                **({"size": self.size} if self.size != 1.0 else {})}


@dataclass(frozen=True)
class Layout:
    """Derived points in the frame's axes (origin at the rear axle, X forward, Z up), for a frame
    sized by ``fit`` (Bicycle.fit; 1: the man's) on a bicycle of ``size`` (Bicycle.size)."""
    fit: float = 1.0
    size: float = 1.0
    steer_axis: np.ndarray = field(init=False)   # unit, pointing up (and back)
    front_axle: np.ndarray = field(init=False)
    head_top: np.ndarray = field(init=False)     # the fork body's origin, on the steering axis
    bottom_bracket: np.ndarray = field(init=False)
    saddle: np.ndarray = field(init=False)
    grips: tuple = field(init=False)              # (right, left) at zero steer
    pedals: tuple = field(init=False)             # (right, left) offsets from the crank axle at crank angle 0

    def __post_init__(self):
        k = self.size
        r = wheel_radius(k)
        tilt = math.pi / 2 - HEAD_ANGLE
        axis = np.array([-math.sin(tilt), 0.0, math.cos(tilt)])
        front_axle = np.array([WHEELBASE * k, 0.0, 0.0])
        ground_point = np.array([WHEELBASE * k + trail(r, HEAD_ANGLE, FORK_OFFSET * k), 0.0, -r])   # axis meets the ground
        head_top = ground_point + axis * (HEAD_TUBE_TOP * k / axis[2])
        bb = np.array([CHAINSTAY * k, 0.0, BOTTOM_BRACKET_HEIGHT * k - r])
        seat_tube = np.array([-math.cos(SEAT_TUBE_ANGLE), 0, math.sin(SEAT_TUBE_ANGLE)])
        saddle = bb + self.fit * SADDLE_FROM_BOTTOM_BRACKET * k * seat_tube
        mans_saddle = bb + SADDLE_FROM_BOTTOM_BRACKET * k * seat_tube
        mans_bar = head_top + np.array([-GRIP_BACK * k, 0.0, STEM_RISE * k])
        bar = mans_bar + (saddle - mans_saddle) + (self.fit - 1.0) * (mans_bar - mans_saddle)   # fit 1: the man's, exactly
        set_ = object.__setattr__
        set_(self, "steer_axis", axis)
        set_(self, "front_axle", front_axle)
        set_(self, "head_top", head_top)
        set_(self, "bottom_bracket", bb)
        set_(self, "saddle", saddle)
        set_(self, "grips", (bar + [0, -GRIP_HALF_WIDTH * k, 0], bar + [0, GRIP_HALF_WIDTH * k, 0]))
        # crank angle 0: the right arm up (Hodgins' theta_crank = 0, right foot higher), left arm down
        set_(self, "pedals", (np.array([0.0, -PEDAL_HALF_SPACING * k, CRANK_LENGTH * k]),
                              np.array([0.0, PEDAL_HALF_SPACING * k, -CRANK_LENGTH * k])))



def _inertia(body, mass: float, diag, pos=(0.0, 0.0, 0.0)) -> None:
    body.explicitinertial = True
    body.mass = mass
    body.ipos = list(pos)
    body.inertia = list(diag)


def _tube(body, name: str, a, b, radius: float = 0.016, colour=FRAME_COLOUR, contact: int = 1):
    g = body.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_CAPSULE, size=[radius, 0, 0],
                      fromto=[*map(float, a), *map(float, b)], rgba=colour)
    g.contype = g.conaffinity = contact
    return g


def _wheel(parent, name: str, joint: str, pos, mass: float, contact: int, r: float = WHEEL_RADIUS):
    wheel = parent.add_body(name=name, pos=list(map(float, pos)))
    axial = WHEEL_RIM_SHARE * mass * r * r
    diametral = axial / 2                  # a flat wheel: A + C = B exactly, and the model's XML keeps 6 digits
    if 2 * float(f"{diametral:g}") < float(f"{axial:g}"):      # (%g), which can round A + C below B: the
        diametral *= 1 + 2e-5                                  # compiler refuses it; raised by < 2 of the 6th digit
    _inertia(wheel, mass, [diametral, axial, diametral])
    hinge = wheel.add_joint(name=joint, type=mujoco.mjtJoint.mjJNT_HINGE, axis=[0, 1, 0])
    hinge.damping = [ROLLING_RESISTANCE / 2 * r * r, 0.0, 0.0]     # linear viscous term only
    hinge.solref_friction = list(BRAKE_SOLREF)                        # the rim brake's dry friction holds
    hinge.solimp_friction = list(BRAKE_SOLIMP)
    seen = wheel.add_geom(name=name + "_tyre_seen", type=mujoco.mjtGeom.mjGEOM_CYLINDER, size=[r - 0.005, 0, 0],
                          fromto=[0, -TYRE_WIDTH / 2, 0, 0, TYRE_WIDTH / 2, 0], rgba=TYRE_COLOUR)
    seen.contype = seen.conaffinity = 0
    tyre = wheel.add_geom(name=name + "_tyre", type=mujoco.mjtGeom.mjGEOM_CYLINDER, size=[r, 0, 0],
                          fromto=[0, -CONTACT_DISC_WIDTH / 2, 0, 0, CONTACT_DISC_WIDTH / 2, 0], rgba=TYRE_COLOUR)
    tyre.friction = [TYRE_FRICTION, 0.005, 0.0001]
    tyre.contype = tyre.conaffinity = contact
    tyre.group = 3
    return wheel


def add_bicycle(spec: mujoco.MjSpec, bicycle: Bicycle, contact_group: int) -> None:
    """The bicycle's five bodies, four hinges, chain tendon and sites (grips, pedals, saddle) into
    ``spec``, standing upright on the ground (z = 0) as ``bicycle`` places it."""
    k = bicycle.size                          # lengths x k, masses x k, inertias x k^3
    lay, r, n = Layout(bicycle.fit, k), wheel_radius(k), NAMES
    c, s = math.cos(bicycle.heading), math.sin(bicycle.heading)
    frame = spec.worldbody.add_body(name=n["frame"], pos=[bicycle.x, bicycle.y, r],
                                    quat=[math.cos(bicycle.heading / 2), 0, 0, math.sin(bicycle.heading / 2)])
    frame.add_freejoint(name=n["free"])
    _inertia(frame, FRAME_MASS * k, [0.35 * k ** 3, 0.85 * k ** 3, 0.55 * k ** 3], pos=[0.45 * k, 0.0, 0.25 * k])
    bb, seat, head = lay.bottom_bracket, lay.saddle, lay.head_top
    head_low = head - lay.steer_axis * 0.15 * k
    for name, a, b in (("chainstay_r", [0, -0.06, 0], bb), ("chainstay_l", [0, 0.06, 0], bb),
                       ("seatstay_r", [0, -0.05, 0], seat - [0, 0.05, 0.12]),
                       ("seatstay_l", [0, 0.05, 0], seat - [0, -0.05, 0.12]),
                       ("seat_tube", bb, seat), ("top_tube", seat - [0, 0, 0.12], head - lay.steer_axis * 0.03),
                       ("down_tube", bb, head_low), ("head_tube", head_low, head)):
        _tube(frame, f"bicycle_{name}", a, b, contact=contact_group)
    saddle = frame.add_geom(name="bicycle_saddle", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.13, 0.07, 0.025],
                            pos=list(seat + [0.0, 0, 0.025]), rgba=[0.1, 0.1, 0.1, 1])
    saddle.contype = saddle.conaffinity = 0     # the rider sits on it through the seat pivot
    frame.add_site(name="bicycle_saddle", pos=list(seat + [0.0, 0, 0.05]))

    fork = frame.add_body(name=n["fork"], pos=list(head))
    _inertia(fork, FORK_MASS * k, [0.08 * k ** 3, 0.07 * k ** 3, 0.03 * k ** 3],
             pos=list((lay.steer_axis * -0.15 + [-0.02, 0, 0.05]) * k))
    steer = fork.add_joint(name=n["steer"], type=mujoco.mjtJoint.mjJNT_HINGE, axis=list(lay.steer_axis),
                           range=[-STEER_RANGE, STEER_RANGE], limited=mujoco.mjtLimited.mjLIMITED_TRUE)
    steer.armature = 0.01
    axle = lay.front_axle - head
    crown = -lay.steer_axis * (head[2] - 0.30 * k) / lay.steer_axis[2]
    for side in (-1, 1):
        _tube(fork, f"bicycle_fork_blade_{'rl'[side > 0]}", crown + [0, side * 0.05, 0], axle + [0, side * 0.05, 0],
              radius=0.012, contact=contact_group)
    bar = lay.grips[0] - head
    _tube(fork, "bicycle_stem", [0, 0, 0], [bar[0], 0, bar[2]], radius=0.014, contact=contact_group)
    _tube(fork, "bicycle_handlebar", bar, lay.grips[1] - head, radius=0.012, colour=[0.3, 0.3, 0.3, 1],
          contact=contact_group)
    for side, grip in zip("rl", lay.grips):
        fork.add_site(name=f"bicycle_grip_{side}", pos=list(grip - head))
    _wheel(fork, n["front"], n["front_spin"], axle, FRONT_WHEEL_MASS * k, contact_group, r)
    _wheel(frame, n["rear"], n["rear_spin"], [0, 0, 0], REAR_WHEEL_MASS * k, contact_group, r)

    crank = frame.add_body(name=n["crank"], pos=list(bb))
    _inertia(crank, CRANK_MASS * k, [0.01 * k ** 3, 0.01 * k ** 3, 0.01 * k ** 3])
    spin = crank.add_joint(name=n["crank_spin"], type=mujoco.mjtJoint.mjJNT_HINGE, axis=[0, 1, 0])
    spin.armature = CRANK_ARMATURE
    for side, pedal in zip("rl", lay.pedals):
        _tube(crank, f"bicycle_crank_arm_{side}", [0, pedal[1], 0], pedal, radius=0.01, colour=[0.5, 0.5, 0.5, 1],
              contact=contact_group)
        g = crank.add_geom(name=f"bicycle_pedal_{side}", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.05, 0.04, 0.01],
                           pos=list(pedal + [0, np.sign(pedal[1]) * 0.04, 0]), rgba=[0.2, 0.2, 0.2, 1])
        g.contype = g.conaffinity = contact_group
        crank.add_site(name=f"bicycle_pedal_{side}", pos=list(pedal + [0, np.sign(pedal[1]) * 0.04, 0]))

    fixed = not bicycle.freewheel
    chain = spec.add_tendon(name=n["chain"], stiffness=[CHAIN_STIFFNESS * fixed, 0.0, 0.0],
                            damping=[CHAIN_DAMPING * fixed, 0.0, 0.0])
    chain.springlength = [0.0, 0.0]
    chain.wrap_joint(n["crank_spin"], bicycle.gear)
    chain.wrap_joint(n["rear_spin"], -1.0)
    if bicycle.freewheel:       # a one-way viscous clutch on the chain: F = -b dL/dt, only while F <= 0 (driving)
        _bicycle_actuator(spec, n["freewheel"], mujoco.mjtTrn.mjTRN_TENDON, n["chain"], gain=(0.0, 0.0, 0.0),
                          bias=(0.0, 0.0, -FREEWHEEL_DAMPING), force=(-FREEWHEEL_MAX_FORCE, 0.0))
    spec.add_exclude(bodyname1=n["frame"], bodyname2=n["front"])
    spec.add_exclude(bodyname1=n["fork"], bodyname2=n["crank"])
    spec.add_exclude(bodyname1=n["front"], bodyname2=n["crank"])
    spec.add_exclude(bodyname1=n["rear"], bodyname2=n["crank"])


def _bicycle_actuator(spec: mujoco.MjSpec, name: str, trntype, target: str, gain, bias, force) -> None:
    """A bicycle-internal element as a MuJoCo actuator (force = gain(velocity) * control + bias(length,
    velocity), clamped to ``force``): its transmission is a bicycle joint or the chain, so it acts
    between two bicycle bodies only; its control column is logged with the servos' (the freewheel
    has no control: gain 0)."""
    a = spec.add_actuator(name=name, trntype=trntype, target=target)
    a.gaintype = mujoco.mjtGain.mjGAIN_AFFINE
    a.biastype = mujoco.mjtBias.mjBIAS_AFFINE
    a.gainprm[:3] = gain
    a.biasprm[:3] = bias
    a.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
    a.ctrlrange = [0.0, 1.0]
    a.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
    a.forcerange = list(force)


@dataclass(frozen=True)
class BicycleView:
    """Addresses of the bicycle's joints in a compiled model."""
    model: mujoco.MjModel
    frame: int
    free_qpos: int
    free_dof: int
    steer_qpos: int
    steer_dof: int
    front_dof: int
    rear_qpos: int
    rear_dof: int
    crank_qpos: int
    crank_dof: int
    chain: int
    crank_body: int
    wheel_radius: float      # m, this bicycle's (Bicycle.size x WHEEL_RADIUS)
    crank_length: float      # m, this bicycle's crank arm (Bicycle.size x CRANK_LENGTH)

    @classmethod
    def of(cls, model: mujoco.MjModel) -> "BicycleView":
        n = NAMES
        j = lambda name: model.joint(name)
        return cls(model, model.body(n["frame"]).id, int(j(n["free"]).qposadr[0]), int(j(n["free"]).dofadr[0]),
                   int(j(n["steer"]).qposadr[0]), int(j(n["steer"]).dofadr[0]), int(j(n["front_spin"]).dofadr[0]),
                   int(j(n["rear_spin"]).qposadr[0]), int(j(n["rear_spin"]).dofadr[0]),
                   int(j(n["crank_spin"]).qposadr[0]), int(j(n["crank_spin"]).dofadr[0]), model.tendon(n["chain"]).id,
                   model.body(n["crank"]).id, float(model.geom(n["rear"] + "_tyre").size[0]),
                   float(model.site("bicycle_pedal_r").pos[2]))

    @property
    def gear(self) -> float:
        return float(self.model.wrap_prm[self.model.tendon_adr[self.chain]])

    @property
    def rolling_resistance(self) -> float:
        """N s/m: the ground force per m/s of both wheels' hinge damping (b = (c/2) r^2 each: c)."""
        damping = self.model.dof_damping[self.front_dof] + self.model.dof_damping[self.rear_dof]
        return float(damping) / self.wheel_radius ** 2

    def road_sine(self, data: mujoco.MjData) -> float:
        """The sine of the road's grade under the bicycle (uphill ahead positive): the rise of the
        line from the rear to the front wheel's axle, which lies at the wheels' radius above the road
        at both ends (level on flat ground whatever the frame's pitch on its tyres)."""
        rear = data.xpos[self.model.dof_bodyid[self.rear_dof]]
        front = data.xpos[self.model.dof_bodyid[self.front_dof]]
        axle_line = front - rear
        return float(axle_line[2] / np.linalg.norm(axle_line))

    def set_crank(self, data: mujoco.MjData, angle: float) -> None:
        """Turn the crank to ``angle`` (0: right pedal up) and the rear wheel with it, so that the
        chain spring stays unstretched."""
        data.qpos[self.crank_qpos] = angle
        data.qpos[self.rear_qpos] = self.gear * angle

    def rolling_start(self, data: mujoco.MjData, speed: float) -> None:
        """The named start state of a run "rolling at ``speed``": the frame (and whatever the
        caller moves with it) translating along its heading, both wheels turning at v/r, the crank
        at v/(r g) so the chain is unstretched. Logged in the initial state like StartState."""
        quat = data.qpos[self.free_qpos + 3:self.free_qpos + 7]
        heading = 2.0 * math.atan2(quat[3], quat[0])
        data.qvel[self.free_dof:self.free_dof + 3] = [speed * math.cos(heading), speed * math.sin(heading), 0.0]
        data.qvel[self.front_dof] = data.qvel[self.rear_dof] = speed / self.wheel_radius
        data.qvel[self.crank_dof] = speed / (self.wheel_radius * self.gear)

    def state(self, data: mujoco.MjData) -> dict:
        """Forward speed, roll (positive: right side down, about the heading axis), yaw (heading),
        their rates, steering angle and crank angle, read off the frame's pose and velocity."""
        quat = data.qpos[self.free_qpos + 3:self.free_qpos + 7]
        return frame_state(quat, data.qvel[self.free_dof:self.free_dof + 6], data.qpos[self.steer_qpos],
                           data.qpos[self.crank_qpos])


def frame_state(quat, qvel6, steer: float, crank: float) -> dict:
    """Yaw-roll-pitch (Z-X-Y) of the frame from its quaternion and the rates from its free-joint
    velocity (linear in the world, angular in the body frame)."""
    rot = np.zeros(9)
    mujoco.mju_quat2Mat(rot, np.asarray(quat, dtype=float))
    rot = rot.reshape(3, 3)
    forward, left = rot[:, 0], rot[:, 1]
    yaw = math.atan2(forward[1], forward[0])
    heading_left = np.array([-math.sin(yaw), math.cos(yaw), 0.0])
    heading_forward = np.array([math.cos(yaw), math.sin(yaw), 0.0])
    roll = math.atan2(left[2], float(np.dot(left, heading_left)))       # right side down > 0
    omega = rot @ np.asarray(qvel6[3:6], dtype=float)                 # world-frame angular velocity
    return {"speed": float(np.dot(qvel6[:3], heading_forward)), "roll": roll, "yaw": yaw,
            "roll_rate": float(np.dot(omega, heading_forward)), "yaw_rate": float(omega[2]),
            "steer": float(steer), "crank": float(crank)}


ATTACHMENTS = (("seat_r", "PELVIS", "bicycle_seat_r", SEAT_SOLREF), ("seat_l", "PELVIS", "bicycle_seat_l", SEAT_SOLREF),
               ("hand_r", "HANDR", "bicycle_grip_r", LIMB_SOLREF), ("hand_l", "HANDL", "bicycle_grip_l", LIMB_SOLREF),
               ("foot_r", "FOOTR", "bicycle_pedal_r", LIMB_SOLREF), ("foot_l", "FOOTL", "bicycle_pedal_l", LIMB_SOLREF))


def rider_points(character) -> dict[str, np.ndarray]:
    """Where each attachment holds the rider, in the character's own standing frame: the seat
    bones either side (below and behind the hip joints), the palm (the hand's centre of mass) and
    the ball of the foot on the sole."""
    hip_r, hip_l = (np.array(character.body(n)["joint"]["pos"]) for n in ("ULEGR", "ULEGL"))
    hips = (hip_r + hip_l) / 2
    ischium = hips + [-ISCHIUM_BEHIND_HIP, 0.0, -ISCHIUM_BELOW_HIP]
    points = {"seat_r": ischium + [0, -SEAT_PIVOT_HALF_WIDTH, 0], "seat_l": ischium + [0, SEAT_PIVOT_HALF_WIDTH, 0]}
    for side in "RL":
        points[f"hand_{side.lower()}"] = np.array(character.body(f"HAND{side}")["com"])
        balls = [c["pos"] for c in character.body(f"FOOT{side}")["contacts"] if c["site"].startswith("ball")]
        sole = np.mean(balls, axis=0)
        points[f"foot_{side.lower()}"] = sole - [0, 0, character.body(f"FOOT{side}")["contacts"][0]["radius"]]
    return points


def body_origin(character, name: str) -> np.ndarray:
    """A body's frame origin in the standing frame (as sim_core.character.model builds it: the
    root's at its COM, every other at its joint)."""
    b = character.body(name)
    return np.array(b["com"] if b["parent"] is None else b["joint"]["pos"])


def attach_rider(spec: mujoco.MjSpec, bicycle: Bicycle, character) -> None:
    """The rider's attachments, body to body (never to the world): the pelvis to the saddle by a
    passive pivot about the lateral axis, the hands to the grips and the feet to the pedals by
    two-sided soft connect constraints (MuJoCo equality constraints with a soft ``solref``: a
    spring-damper that pulls as well as pushes, as toe clips do). Sites on both sides mark the
    points; the constraint holds them together. Contacts between rider and bicycle are off (the
    saddle and the pedals carry the rider through these attachments)."""
    prefix = bicycle.rider
    frame = spec.body(NAMES["frame"])
    for side, dy in (("r", -SEAT_PIVOT_HALF_WIDTH), ("l", SEAT_PIVOT_HALF_WIDTH)):
        frame.add_site(name=f"bicycle_seat_{side}", pos=list(Layout(bicycle.fit, bicycle.size).saddle + [0, dy, 0]))
    points = rider_points(character)
    for name, body, bike_site, solref in ATTACHMENTS:
        rider_site = f"{prefix}rider_{name}"
        spec.body(prefix + body).add_site(name=rider_site, pos=list(points[name] - body_origin(character, body)))
        eq = spec.add_equality(name=f"{prefix}attach_{name}", type=mujoco.mjtEq.mjEQ_CONNECT,
                               objtype=mujoco.mjtObj.mjOBJ_SITE, name1=rider_site, name2=bike_site)
        eq.solref = [bicycle.foot_time, solref[1]] if bicycle.foot_time is not None and name.startswith("foot") else list(solref)
    for b in character.bodies:
        for part in ("frame", "fork", "front", "rear", "crank"):
            spec.add_exclude(bodyname1=prefix + b["name"], bodyname2=NAMES[part])
