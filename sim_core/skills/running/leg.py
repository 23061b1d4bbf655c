"""Leg geometry of a runner: inverse kinematics from a desired ankle position (pelvis frame) to
hip and knee angles, and the foot's heel-to-ankle offset for a foot pitched toe-up.

Why a closed form: the flight controller solves it every control tick (200 Hz) and the hip
gimbal is simple (y fixed in the pelvis, then x, then z; the knee is a hinge about the thigh's
y), so plain floats are fast and exact enough; MuJoCo is used once, at construction, to read
the segment lengths off the character's own joints.
"""
from __future__ import annotations

import math

from ...character.spec import CharacterSpec


class RunnerLeg:
    """Sagittal lengths of one leg and the foot's contact points relative to the ankle."""

    def __init__(self, character: CharacterSpec, side: str):
        hip = character.joint_position("ULEG" + side)
        knee = character.joint_position("LLEG" + side)
        ankle = character.joint_position("FOOT" + side)
        thigh, shank = knee - hip, ankle - knee
        self.upper = math.hypot(thigh[0], thigh[2])
        self.lower = math.hypot(shank[0], shank[2])
        # geometric knee flexion already present at zero joint angle (shank leaning back)
        self.rest_flex = math.atan2(-shank[0], -shank[2]) - math.atan2(-thigh[0], -thigh[2])
        self.thigh_rest = math.atan2(thigh[0], -thigh[2])      # forward angle of the thigh at zero
        sites = {c["site"]: c for c in character.body("FOOT" + side)["contacts"] + character.body("TOE" + side)["contacts"]}
        heel = sites["heel_a"]["pos"]
        ball = sites["ball_a"]["pos"]
        radius = sites["heel_a"]["radius"]
        # heel and ball bottoms relative to the ankle joint, in the foot frame (x forward, z up)
        self.heel_x, self.heel_z = heel[0] - ankle[0], heel[2] - radius - ankle[2]
        self.ball_x = ball[0] - ankle[0]
        self.foot_length = self.ball_x - self.heel_x            # l_f of eqs. 1-2: heel to ball
        self.ankle_height = float(ankle[2])
        self.hip_height = float(hip[2])
        self.max_reach = self.upper + self.lower - 1e-3   # definition: 1 mm short of straight (acos stays finite)

    def knee_for(self, distance: float) -> float:
        """Knee joint angle that puts hip and ankle ``distance`` apart (law of cosines)."""
        u, l = self.upper, self.lower
        d = min(max(distance, abs(u - l) + 1e-3), self.max_reach)   # definition: 1 mm off folded
        c = (u * u + l * l - d * d) / (2.0 * u * l)
        flex = math.pi - math.acos(max(-1.0, min(1.0, c)))
        return flex - self.rest_flex

    def hip_knee_for(self, ax: float, ay: float, az: float) -> tuple[float, float, float]:
        """(hip_y, hip_x, knee) that put the ankle at (ax, ay, az) from the hip joint, in the
        pelvis frame. Hip gimbal: y (fixed in the pelvis), then x; the knee bends about the
        thigh's y axis, so the hip-ankle line lies in the thigh's x-z plane, behind the thigh
        by the triangle's angle at the hip."""
        u, l = self.upper, self.lower
        d = math.sqrt(ax * ax + ay * ay + az * az)
        d = min(max(d, abs(u - l) + 1e-3), self.max_reach)   # definition: 1 mm off folded
        knee = self.knee_for(d)
        cos_delta = max(-1.0, min(1.0, (u * u + d * d - l * l) / (2.0 * u * d)))
        delta = math.acos(cos_delta)
        nx, ny, nz = ax / d, ay / d, az / d
        sin_beta = max(-1.0, min(1.0, ny / max(cos_delta, 1e-6)))
        beta = math.asin(sin_beta)
        hip_y = math.atan2(-math.sin(delta), cos_delta * math.cos(beta)) - math.atan2(nx, -nz) + self.thigh_rest
        return hip_y, beta, knee

    def ankle_from_heel(self, toe_up: float) -> tuple[float, float]:
        """(forward, up) offset from the heel's bottom to the ankle joint with the foot pitched
        ``toe_up`` radians above flat."""
        c, s = math.cos(toe_up), math.sin(toe_up)
        hx, hz = -self.heel_x, -self.heel_z            # heel -> ankle in the foot frame
        return hx * c - hz * s, hx * s + hz * c
