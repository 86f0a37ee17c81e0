"""Quaternion helpers of the estimator rostests (estimator_stream, scene_estimator)."""

import math


def rotation_error_deg(q_a, q_b):
    """Angle of the rotation between two unit quaternions (x, y, z, w), q ~ -q, in degrees (the
    core's rotationErrorDeg)."""
    dot = abs(sum(a * b for a, b in zip(q_a, q_b)))
    return math.degrees(2.0 * math.acos(min(1.0, dot)))
