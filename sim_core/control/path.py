"""Paths on the ground plane for a runner or a rider to follow: a polyline of points, steered
along by pure pursuit (the heading points at a point a look-ahead distance further along the
path).

Built-in shapes (a 90-degree turn, a figure eight, a circle) are polylines too, so a path from
a Blender curve object (its evaluated points) and a built-in one are followed by the same code.
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import ParameterError

MIN_SEGMENT = 0.05          # m: consecutive points closer than this are merged
MIN_LENGTH = 2.0            # m: a path shorter than this cannot be run along
MAX_POINTS = 10000
MIN_TURN_RADIUS = 1.5       # m: a corner tighter than this is rounded to it (a runner cannot turn on a spot)
CURVATURE_CHORD = 0.5       # m: the half-chord over which a path's curvature ahead is measured
RADIUS_SAMPLE = 0.1         # m: spacing of the points along a path where its tightest bend is looked for
# the request's path shapes (turn, figure_eight, circle): what each one means
TURN_RUN_OUT = 60.0         # m straight on after a turn: longer than any run goes
FIGURE_EIGHT_LAPS = 3
CIRCLE_LAPS = 5


def validate_path(points) -> np.ndarray:
    """Clean a path (merge repeated points) and refuse a degenerate one with a clear message."""
    array = np.asarray(points, dtype=float)
    if len(array) < 2:
        raise ParameterError(f"parameter path has {len(array)} point(s); a path needs at least 2 distinct points")
    kept = [array[0]]
    for p in array[1:]:
        if np.hypot(*(p - kept[-1])) >= MIN_SEGMENT:
            kept.append(p)
    kept = np.array(kept)
    length = float(np.sum(np.hypot(*np.diff(kept, axis=0).T))) if len(kept) > 1 else 0.0
    if len(kept) < 2 or length < MIN_LENGTH:
        raise ParameterError(f"parameter path is degenerate: its length is {length:.3f} m; "
                             f"a path must be at least {MIN_LENGTH:g} m long with points at least {MIN_SEGMENT:g} m apart")
    return kept


def turn_path(angle: float, straight: float, radius: float, after: float = TURN_RUN_OUT) -> np.ndarray:
    """Straight ahead (+X) for ``straight`` m, an arc of ``radius`` turning by ``angle`` (left
    positive), then straight on for ``after`` m."""
    pts = [[0.0, 0.0], [straight, 0.0]]
    sign = 1.0 if angle >= 0 else -1.0
    n = max(2, int(abs(angle) * radius / 0.2))          # definition: arc points 0.2 m apart
    cx, cy = straight, sign * radius
    for k in range(1, n + 1):
        a = abs(angle) * k / n
        pts.append([cx + radius * math.sin(a), cy - sign * radius * math.cos(a)])
    end = np.array(pts[-1])
    direction = np.array([math.cos(angle), math.sin(angle)])
    pts.append((end + after * direction).tolist())
    return np.array(pts)


def figure_eight_path(radius: float, start: float, laps: int = FIGURE_EIGHT_LAPS) -> np.ndarray:
    """A run-up of ``start`` m along +X, then ``laps`` figure eights of two circles of ``radius``
    touching at the crossing point, entered tangentially (left loop first)."""
    pts = [[0.0, 0.0]]
    n = max(24, int(2 * math.pi * radius / 0.25))       # definition: circle points 0.25 m apart, 24 at least
    cx = start
    for _ in range(laps):
        for k in range(n + 1):                         # left loop, counter-clockwise
            a = 2 * math.pi * k / n
            pts.append([cx + radius * math.sin(a), radius - radius * math.cos(a)])
        for k in range(1, n + 1):                      # right loop, clockwise
            a = 2 * math.pi * k / n
            pts.append([cx + radius * math.sin(a), -radius + radius * math.cos(a)])
    return validate_path(pts)


def circle_path(radius: float, start: float, laps: int = CIRCLE_LAPS) -> np.ndarray:
    pts = [[0.0, 0.0]]
    n = max(24, int(2 * math.pi * radius / 0.25))       # definition: circle points 0.25 m apart, 24 at least
    for k in range(laps * n + 1):
        a = 2 * math.pi * k / n
        pts.append([start + radius * math.sin(a), radius - radius * math.cos(a)])
    return validate_path(pts)


class PathFollower:
    """Pure pursuit along a polyline. Keeps the index of the segment it is on so that a path
    that crosses itself (a figure eight) is followed in order; each query looks only a few
    segments ahead, so a control tick costs a handful of float operations."""

    def __init__(self, points: np.ndarray, lookahead: float):
        self.points = [tuple(map(float, p)) for p in points]
        self.lookahead = lookahead
        self.segment = 0
        seg = np.diff(np.asarray(points), axis=0)
        self.lengths = [float(x) for x in np.hypot(seg[:, 0], seg[:, 1])]
        self.finished = False

    def _closest_on(self, k: int, x: float, y: float) -> tuple[float, float]:
        """(squared distance, parameter in [0, 1]) of the closest point on segment k."""
        (ax, ay), (bx, by) = self.points[k], self.points[k + 1]
        dx, dy = bx - ax, by - ay
        s = ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy)
        s = 0.0 if s < 0.0 else 1.0 if s > 1.0 else s
        px, py = ax + s * dx - x, ay + s * dy - y
        return px * px + py * py, s

    def advance(self, x: float, y: float) -> tuple[int, float, float]:
        """Move the current segment forward to the closest one among the next few;
        return (segment, parameter, distance to the path)."""
        last = len(self.points) - 2
        best_k, (best_d, best_s) = self.segment, self._closest_on(self.segment, x, y)
        k, travelled = self.segment, 0.0
        while k < last and travelled < 3.0 * self.lookahead:   # definition: the closest segment is within 3 lookaheads
            travelled += self.lengths[k]
            k += 1
            d, s = self._closest_on(k, x, y)
            if d < best_d:
                best_k, best_d, best_s = k, d, s
        self.segment = best_k
        if best_k == last and best_s >= 1.0:
            self.finished = True
        return best_k, best_s, math.sqrt(best_d)

    def signed_offset(self, x: float, y: float) -> float:
        """Distance from the path (left of the path positive), on the current segment."""
        k = self.segment
        (ax, ay), (bx, by) = self.points[k], self.points[k + 1]
        dx, dy = bx - ax, by - ay
        length = self.lengths[k]
        return ((x - ax) * dy * -1.0 + (y - ay) * dx) / length

    def target(self, x: float, y: float) -> tuple[float, float]:
        """The look-ahead point: ``lookahead`` metres along the path from the closest point."""
        return self.ahead(x, y, self.lookahead)

    def ahead(self, x: float, y: float, distance: float) -> tuple[float, float]:
        """The point ``distance`` metres along the path from the closest point (the path's end
        beyond its last point)."""
        k, s, _ = self.advance(x, y)
        return self._along(k, s, distance)

    def _along(self, k: int, s: float, distance: float) -> tuple[float, float]:
        """The point ``distance`` metres on from parameter ``s`` of segment ``k``."""
        remaining = distance + s * self.lengths[k]
        last = len(self.points) - 2
        while k < last and remaining > self.lengths[k]:
            remaining -= self.lengths[k]
            k += 1
        (ax, ay), (bx, by) = self.points[k], self.points[k + 1]
        f = remaining / self.lengths[k]
        return ax + f * (bx - ax), ay + f * (by - ay)

    def curvature_ahead(self, x: float, y: float, distance: float, chord: float = CURVATURE_CHORD) -> float:
        """The path's curvature (1/m, left turns positive) ``distance`` metres ahead: that of the
        circle through the points ``chord`` before, at and after it."""
        k, s, _ = self.advance(x, y)
        (ax, ay), (bx, by), (cx, cy) = (self._along(k, s, max(distance + d, 0.0)) for d in (-chord, 0.0, chord))
        cross = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
        sides = math.hypot(bx - ax, by - ay) * math.hypot(cx - bx, cy - by) * math.hypot(cx - ax, cy - ay)
        return 2.0 * cross / sides if sides > 0.0 else 0.0

    def heading(self, x: float, y: float) -> float:
        tx, ty = self.target(x, y)
        return math.atan2(ty - y, tx - x)


def tightest_radius(points: np.ndarray, chord: float) -> tuple[float, float]:
    """(radius m, distance along the path m) of the path's tightest bend at the scale ``chord``:
    the smallest circle through three points ``chord`` apart along it (a follower that aims a
    look-ahead ahead cuts a corner at about that scale; an arc of radius >= chord is measured
    exactly). A straight path gives (inf, 0)."""
    pts = np.asarray(points, dtype=float)
    lengths = np.hypot(*np.diff(pts, axis=0).T)
    along = np.concatenate([[0.0], np.cumsum(lengths)])
    if along[-1] <= 2.0 * chord:
        return math.inf, 0.0
    s = np.arange(chord, along[-1] - chord, RADIUS_SAMPLE)
    a, b, c = (np.column_stack([np.interp(s + d, along, pts[:, 0]), np.interp(s + d, along, pts[:, 1])])
               for d in (-chord, 0.0, chord))
    cross = np.abs((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))
    sides = np.linalg.norm(b - a, axis=1) * np.linalg.norm(c - b, axis=1) * np.linalg.norm(c - a, axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        radius = np.where(cross > 1e-12, sides / (2.0 * cross), math.inf)
    k = int(np.argmax(radius <= radius.min() * (1.0 + 1e-3)))      # definition: the first of bends as tight within 0.1 %
    return float(radius[k]), float(s[k])


def path_deviation(points: np.ndarray, xy: np.ndarray) -> np.ndarray:
    """Per sample: distance from the polyline (for reports; vectorised, not for the control loop)."""
    a = points[:-1][None, :, :]
    d = np.diff(points, axis=0)[None, :, :]
    p = xy[:, None, :]
    s = np.clip(np.sum((p - a) * d, axis=2) / np.sum(d * d, axis=2), 0.0, 1.0)
    closest = a + s[:, :, None] * d
    return np.min(np.linalg.norm(p - closest, axis=2), axis=1)
