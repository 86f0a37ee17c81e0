#!/usr/bin/python3
"""The demo's closed loop on the camera's stream: ask the informativeness server for the next best
view, move the simulated camera there, wait until the orientation estimator (subscribed straight
to the camera's cloud) has fused a new view, measure the orientation error against the ground
truth, repeat; then write errors.csv and a plot and exit.

The loop never touches a cloud: the estimator picks the frames worth featurising from the stream
itself (frame selection, doc/method.md section 12), and `views_fused` in its ~estimate says when
the move gave it a new view.

Topics and services (relative names, remapped in launch/demo.launch):
  next_best_view (GetNextBestView)  the informativeness server's ~next_best_view
  move_to (MoveCamera)              the simulated camera's ~move_to
  estimate (in, BinghamMixture)     the estimator's ~estimate
  /diagnostics (in)                 the estimator's status: why a view was not fused, frame counts
Private parameters: see PARAMETERS below (also listed in doc/nodes.md, "planner_loop.py").
"""
import csv
import math
import os
import sys
import threading

import numpy as np
import rospy
import tf2_ros
from diagnostic_msgs.msg import DiagnosticArray
from view_direction_classification.msg import BinghamMixture
from view_direction_classification.srv import (GetNextBestView, GetNextBestViewRequest,
                                               MoveCamera, MoveCameraRequest)

# name: (default, meaning)
PARAMETERS = {
    "views": (8, "camera positions per run, the camera's initial one included"),
    "utility": ("informativeness", "next-best-view utility: informativeness or information_gain"),
    "sample_count": (100, "candidate camera poses sampled around the object per step"),
    "sample_distance": (0.6, "their distance from the object [m] (the training distance)"),
    "min_view_separation_deg": (20.0, "a candidate this close to a visited view is not taken"),
    "min_elevation_deg": (15.0, "a candidate lower than this above the object's horizontal "
                                "plane is not taken (the table hides the object from below)"),
    "fixed_frame": ("world", "frame of the camera poses and of the estimate"),
    "ground_truth_frame": ("object_ground_truth", "tf frame of the true object pose"),
    "object_frame": ("object", "tf frame of the estimated object pose (the estimator's)"),
    "camera_frame": ("camera_optical_frame", "the camera's tf frame"),
    "timeout": (120.0, "seconds to wait for the services and the first estimate"),
    "fuse_timeout": (10.0, "seconds after a move to wait for the estimator to fuse the new view"),
    "start_delay": (0.0, "seconds to wait before the first view is recorded and the camera "
                         "moves (demo.launch gui:=true: for rviz to come up)"),
    "linger": (0.0, "seconds to stay at the last view after writing the results, before the "
                    "node exits and ends the launch (gui:=true: to look at rviz)"),
    "output_dir": ("demo_output", "where errors.csv and errors.png go (created if missing)"),
}

# The estimator's diagnostic status (orientation_estimator_ros.cpp, diagnose()).
DIAGNOSTIC_KEYS = {
    "clouds received": "received",
    "clouds fused (new views)": "fused",
    "clouds not novel (a view already fused)": "not_novel",
    "clouds dropped (a newer one arrived first)": "dropped",
    "clouds skipped (bad input or no tf)": "skipped",
    "last skip reason": "last_skip_reason",
}


def rotation_error_deg(q_a, q_b):
    """Angle of the rotation between two unit quaternions (x, y, z, w), q ~ -q, in degrees
    (the same metric as the core's rotationErrorDeg)."""
    dot = abs(sum(a * b for a, b in zip(q_a, q_b)))
    return math.degrees(2.0 * math.acos(min(1.0, dot)))


def quaternion_tuple(q):
    return (q.x, q.y, q.z, q.w)


class PlannerLoop:
    def __init__(self):
        self.p = {name: rospy.get_param("~" + name, default)
                  for name, (default, _) in PARAMETERS.items()}
        if int(self.p["views"]) < 1:
            raise ValueError("Parameter ~views must be at least 1, got %s." % self.p["views"])
        if self.p["utility"] not in ("informativeness", "information_gain"):
            raise ValueError("Parameter ~utility must be informativeness or information_gain, "
                             "got '%s'." % self.p["utility"])
        for name in ("timeout", "fuse_timeout"):
            if not float(self.p[name]) > 0.0:
                raise ValueError("Parameter ~%s must be > 0 [s], got %s." % (name, self.p[name]))
        for name in ("start_delay", "linger"):
            if not float(self.p[name]) >= 0.0:
                raise ValueError("Parameter ~%s must be >= 0 [s], got %s." % (name, self.p[name]))
        self.timeout = rospy.Duration(float(self.p["timeout"]))
        self.fuse_timeout = rospy.Duration(float(self.p["fuse_timeout"]))
        self.tf_buffer = tf2_ros.Buffer(cache_time=rospy.Duration(120))
        self.tf_listener = tf2_ros.TransformListener(self.tf_buffer)
        self.condition = threading.Condition()
        self.latest_estimate = None
        self.estimator_status = {}
        rospy.Subscriber("estimate", BinghamMixture, self.on_estimate, queue_size=5)
        rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diagnostics, queue_size=5)

    def on_estimate(self, estimate):
        with self.condition:
            self.latest_estimate = estimate
            self.condition.notify_all()

    def on_diagnostics(self, array):
        for status in array.status:
            values = {DIAGNOSTIC_KEYS[v.key]: v.value for v in status.values
                      if v.key in DIAGNOSTIC_KEYS}
            if "received" in values:  # the estimator's status (other nodes may publish too)
                with self.condition:
                    self.estimator_status = values

    def wait_for(self, predicate, timeout):
        """The first non-None value of predicate() (called under the lock) within timeout, or
        None."""
        deadline = rospy.Time.now() + timeout
        with self.condition:
            while not rospy.is_shutdown():
                value = predicate()
                if value is not None:
                    return value
                if rospy.Time.now() > deadline:
                    return None
                self.condition.wait(0.1)
        return None

    def wait_for_new_view(self, views_before, moved_at):
        """The first estimate that fused a view after the move (views_fused above views_before,
        stamped after moved_at), or None after ~fuse_timeout."""
        def fused():
            e = self.latest_estimate
            if e is not None and e.views_fused > views_before and e.header.stamp >= moved_at:
                return e
            return None
        return self.wait_for(fused, self.fuse_timeout)

    def not_fused_message(self, view, views_before):
        reason = self.estimator_status.get("last_skip_reason", "none")
        if reason == "none":
            why = ("it saw only views it had fused already (within its ~min_view_separation of a "
                   "fused view: raise ~min_view_separation_deg), or no frame arrived")
        else:
            why = "its last skip reason: " + reason
        return ("view %d: the estimator fused no new view within %.0f s of the move "
                "(views_fused stays %d); %s. Frames so far: %s."
                % (view, self.fuse_timeout.to_sec(), views_before, why, self.frame_counts()))

    def frame_counts(self):
        s = self.estimator_status
        if not s:
            return "no diagnostics from the estimator yet"
        return ("%s received, %s fused, %s not novel, %s dropped, %s skipped"
                % tuple(s.get(k, "?") for k in ("received", "fused", "not_novel", "dropped",
                                                 "skipped")))

    def next_best_pose(self, visited_directions, object_position):
        request = GetNextBestViewRequest(sample_count=int(self.p["sample_count"]),
                                         sample_distance=float(self.p["sample_distance"]),
                                         utility=self.p["utility"])
        response = self.next_best_view(request)
        if not response.success:
            raise RuntimeError("The server refused the next-best-view request: %s"
                               % response.message)
        # The ranking is best first. A view already taken would only repeat a measurement (the
        # estimator would not even fuse it), and a camera under the table sees no object: take
        # the best candidate above the table and away from every visited view.
        min_cos = math.cos(math.radians(float(self.p["min_view_separation_deg"])))
        min_sin_elevation = math.sin(math.radians(float(self.p["min_elevation_deg"])))
        for pose, utility in zip(response.ranked.poses, response.utilities):
            p = pose.position
            direction = self.unit(np.array([p.x, p.y, p.z]) - object_position)
            if direction[2] < min_sin_elevation:
                continue
            if all(direction.dot(v) < min_cos for v in visited_directions):
                return pose, utility
        raise RuntimeError("Every sampled candidate is within %.0f deg of a visited view or "
                           "lower than %.0f deg; raise ~sample_count or lower "
                           "~min_view_separation_deg."
                           % (self.p["min_view_separation_deg"], self.p["min_elevation_deg"]))

    def truth(self):
        t = self.tf_buffer.lookup_transform(self.p["fixed_frame"], self.p["ground_truth_frame"],
                                            rospy.Time(0), self.timeout)
        return quaternion_tuple(t.transform.rotation)

    def camera_position(self, pose):
        return np.array([pose.position.x, pose.position.y, pose.position.z])

    def run(self):
        wait = self.timeout.to_sec()
        rospy.wait_for_service("next_best_view", wait)
        rospy.wait_for_service("move_to", wait)
        self.next_best_view = rospy.ServiceProxy("next_best_view", GetNextBestView)
        self.move_to = rospy.ServiceProxy("move_to", MoveCamera)
        true_orientation = self.truth()
        rospy.loginfo("planner: %d views, utility %s, results into %s", self.p["views"],
                      self.p["utility"], os.path.abspath(self.p["output_dir"]))

        rospy.sleep(float(self.p["start_delay"]))
        # View 1 is wherever the camera starts, as in `vdc evaluate`: the estimator fuses it
        # from the stream as soon as it is up.
        start = rospy.Time.now()
        estimate = self.wait_for(lambda: self.latest_estimate, self.timeout)
        if estimate is None:
            raise RuntimeError("No estimate within %.0f s of the start: the estimator fused no "
                               "frame of the camera's stream (last skip reason: %s; frames: %s)."
                               % (wait, self.estimator_status.get("last_skip_reason", "none"),
                                  self.frame_counts()))
        rows = []
        visited = []
        camera = self.camera_position_now()
        for view in range(1, int(self.p["views"]) + 1):
            utility = float("nan")
            if view > 1:
                object_position = self.estimated_position()
                pose, utility = self.next_best_pose(visited, object_position)
                views_before = self.latest_estimate.views_fused
                moved_at = rospy.Time.now()
                response = self.move_to(MoveCameraRequest(mode=MoveCameraRequest.MODE_POSE,
                                                          pose=pose))
                if not response.success:
                    raise RuntimeError("The camera refused the move: %s" % response.message)
                camera = self.camera_position(pose)
                fused = self.wait_for_new_view(views_before, moved_at)
                if fused is None:
                    rospy.logwarn("planner: %s", self.not_fused_message(view, views_before))
                estimate = self.latest_estimate
            visited.append(self.unit(camera - self.estimated_position()))
            rows.append(self.record(view, estimate, true_orientation, utility, visited[-1],
                                    (rospy.Time.now() - start).to_sec()))
        rospy.sleep(1.5)  # the estimator's diagnostics come once a second
        rospy.loginfo("planner: the estimator's frames: %s", self.frame_counts())
        self.write(rows)
        if self.p["linger"] > 0.0:
            rospy.loginfo("planner: staying at the last view for %.0f s", self.p["linger"])
            rospy.sleep(float(self.p["linger"]))

    def record(self, view, estimate, true_orientation, utility, direction, seconds):
        error = rotation_error_deg(quaternion_tuple(estimate.map_orientation), true_orientation)
        rospy.loginfo("view %d: error %.1f deg, %d views fused, cone90 %.1f deg%s, entropy %.2f "
                      "nats, %d components, utility %.3f, camera direction (%.2f, %.2f, %.2f)",
                      view, error, estimate.views_fused, estimate.cone90_deg,
                      " (converged)" if estimate.converged else "", estimate.entropy,
                      len(estimate.components), utility, *direction)
        return {"view": view, "error_deg": error, "views_fused": estimate.views_fused,
                "cone90_deg": estimate.cone90_deg, "converged": int(estimate.converged),
                "entropy_nats": estimate.entropy, "components": len(estimate.components),
                "utility": utility, "direction_x": direction[0], "direction_y": direction[1],
                "direction_z": direction[2], "seconds": seconds}

    def camera_position_now(self):
        """Where the camera starts (its tf), for the first view's direction."""
        t = self.tf_buffer.lookup_transform(self.p["fixed_frame"], self.p["camera_frame"],
                                            rospy.Time(0),
                                            self.timeout)
        v = t.transform.translation
        return np.array([v.x, v.y, v.z])

    def estimated_position(self):
        """The object's position as the estimator publishes it (the server samples candidates
        around it); before the first estimate the fixed frame's origin, as the server assumes."""
        try:
            t = self.tf_buffer.lookup_transform(self.p["fixed_frame"], self.p["object_frame"],
                                                rospy.Time(0))
            v = t.transform.translation
            return np.array([v.x, v.y, v.z])
        except tf2_ros.TransformException:
            return np.zeros(3)

    @staticmethod
    def unit(v):
        return v / np.linalg.norm(v)

    def write(self, rows):
        out = os.path.abspath(self.p["output_dir"])
        os.makedirs(out, exist_ok=True)
        csv_path = os.path.join(out, "errors.csv")
        with open(csv_path, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            writer.writeheader()
            writer.writerows(rows)

        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        views = [r["view"] for r in rows]
        figure, error_axis = plt.subplots(figsize=(6, 4), dpi=100)
        error_axis.plot(views, [r["error_deg"] for r in rows], "o-", color="tab:red",
                        label="MAP error")
        # The belief's own claim: the truth should lie inside its 90 % cone.
        error_axis.plot(views, [r["cone90_deg"] for r in rows], "^:", color="tab:orange",
                        label="cone90 (belief)")
        error_axis.legend(loc="upper right")
        error_axis.set_xlabel("view")
        error_axis.set_ylabel("MAP error, 90 % cone [deg]", color="tab:red")
        error_axis.set_ylim(bottom=0)
        error_axis.set_xticks(views)
        entropy_axis = error_axis.twinx()
        entropy_axis.plot(views, [r["entropy_nats"] for r in rows], "s--", color="tab:blue")
        entropy_axis.set_ylabel("belief entropy [nats]", color="tab:blue")
        error_axis.set_title("Closed-loop demo, utility %s" % self.p["utility"])
        figure.tight_layout()
        plot_path = os.path.join(out, "errors.png")
        figure.savefig(plot_path)
        rospy.loginfo("planner: wrote %s and %s", csv_path, plot_path)


def main():
    rospy.init_node("planner_loop")
    try:
        PlannerLoop().run()
    except (RuntimeError, ValueError, rospy.ROSException) as error:
        rospy.logfatal("planner: %s", error)
        sys.exit(1)


if __name__ == "__main__":
    main()
