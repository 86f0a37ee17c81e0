#!/usr/bin/python3
"""The demo's closed loop: ask the informativeness server for the next best view, move the
simulated camera there, let the estimator fuse exactly one cloud from that view, measure the
orientation error against the ground truth, repeat; then write errors.csv and a plot and exit.

Topics and services (relative names, remapped in launch/demo.launch):
  next_best_view (GetNextBestView)  the informativeness server's ~next_best_view
  move_to (MoveCamera)              the simulated camera's ~move_to
  camera_cloud (in, PointCloud2)    the simulated camera's ~cloud
  ~view_cloud (out, PointCloud2)    the estimator's input: one cloud per planned view
  estimate (in, BinghamMixture)     the estimator's ~estimate
Private parameters: see PARAMETERS below (also listed in doc/nodes.md, "planner_loop.py").
"""
import csv
import math
import os
import sys
import threading

import numpy as np
import rospy
import sensor_msgs.msg
import tf2_ros
from view_direction_classification.msg import BinghamMixture
from view_direction_classification.srv import (GetNextBestView, GetNextBestViewRequest,
                                               MoveCamera, MoveCameraRequest)

# name: (default, meaning)
PARAMETERS = {
    "views": (8, "views per run, the camera's initial view included"),
    "utility": ("informativeness", "next-best-view utility: informativeness or information_gain"),
    "sample_count": (50, "candidate camera poses sampled around the object per step"),
    "sample_distance": (0.6, "their distance from the object [m] (the training distance)"),
    "min_view_separation_deg": (20.0, "a candidate this close to a visited view is not taken"),
    "fixed_frame": ("world", "frame of the camera poses and of the estimate"),
    "ground_truth_frame": ("object_ground_truth", "tf frame of the true object pose"),
    "object_frame": ("object", "tf frame of the estimated object pose (the estimator's)"),
    "camera_frame": ("camera_optical_frame", "the camera's tf frame"),
    "timeout": (120.0, "seconds to wait for services, a cloud from the new view, an estimate"),
    "output_dir": ("demo_output", "where errors.csv and errors.png go (created if missing)"),
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
        self.timeout = rospy.Duration(float(self.p["timeout"]))
        self.tf_buffer = tf2_ros.Buffer(cache_time=rospy.Duration(120))
        self.tf_listener = tf2_ros.TransformListener(self.tf_buffer)
        self.condition = threading.Condition()
        self.latest_cloud = None
        self.latest_estimate = None
        self.view_cloud_publisher = rospy.Publisher("~view_cloud", sensor_msgs.msg.PointCloud2,
                                                    queue_size=1)
        rospy.Subscriber("camera_cloud", sensor_msgs.msg.PointCloud2, self.on_cloud,
                         queue_size=1)
        rospy.Subscriber("estimate", BinghamMixture, self.on_estimate, queue_size=5)

    def on_cloud(self, cloud):
        with self.condition:
            self.latest_cloud = cloud
            self.condition.notify_all()

    def on_estimate(self, estimate):
        with self.condition:
            self.latest_estimate = estimate
            self.condition.notify_all()

    def wait_for(self, predicate, what):
        """The first non-None value of predicate() (called under the lock), or an error."""
        deadline = rospy.Time.now() + self.timeout
        with self.condition:
            while not rospy.is_shutdown():
                value = predicate()
                if value is not None:
                    return value
                if rospy.Time.now() > deadline:
                    break
                self.condition.wait(0.1)
        raise RuntimeError("No %s within %.0f s." % (what, self.timeout.to_sec()))

    def camera_position_at(self, stamp):
        t = self.tf_buffer.lookup_transform(self.p["fixed_frame"], self.p["camera_frame"], stamp,
                                            rospy.Duration(1.0))
        v = t.transform.translation
        return np.array([v.x, v.y, v.z])

    def take_view(self, expected_position, after):
        """Forward to the estimator the first camera cloud stamped after `after` that was rendered
        from `expected_position` (the camera's timer may have rendered one more cloud from the old
        pose while the move was served), and return its stamp."""
        def fresh_cloud():
            c = self.latest_cloud
            return c if c is not None and c.header.stamp > after else None

        while True:
            cloud = self.wait_for(fresh_cloud, "camera cloud after the move")
            after = cloud.header.stamp
            try:
                position = self.camera_position_at(cloud.header.stamp)
            except tf2_ros.TransformException as error:
                rospy.logwarn("planner: no camera tf for a cloud (%s); waiting for the next", error)
                continue
            if expected_position is None or np.linalg.norm(position - expected_position) < 1e-3:
                self.view_cloud_publisher.publish(cloud)
                return cloud.header.stamp, position

    def next_best_pose(self, visited_directions, object_position):
        request = GetNextBestViewRequest(sample_count=int(self.p["sample_count"]),
                                         sample_distance=float(self.p["sample_distance"]),
                                         utility=self.p["utility"])
        response = self.next_best_view(request)
        if not response.success:
            raise RuntimeError("The server refused the next-best-view request: %s"
                               % response.message)
        # The ranking is best first; a view already taken would only repeat a measurement, so take
        # the best candidate away from every visited one (as `vdc evaluate` takes unused ones).
        min_cos = math.cos(math.radians(float(self.p["min_view_separation_deg"])))
        for pose, utility in zip(response.ranked.poses, response.utilities):
            p = pose.position
            direction = np.array([p.x, p.y, p.z]) - object_position
            direction /= np.linalg.norm(direction)
            if all(direction.dot(v) < min_cos for v in visited_directions):
                return pose, utility
        raise RuntimeError("Every sampled candidate is within %.0f deg of a visited view; raise "
                           "~sample_count or lower ~min_view_separation_deg."
                           % self.p["min_view_separation_deg"])

    def truth(self):
        t = self.tf_buffer.lookup_transform(self.p["fixed_frame"], self.p["ground_truth_frame"],
                                            rospy.Time(0), self.timeout)
        return quaternion_tuple(t.transform.rotation)

    def run(self):
        wait = self.timeout.to_sec()
        rospy.wait_for_service("next_best_view", wait)
        rospy.wait_for_service("move_to", wait)
        self.next_best_view = rospy.ServiceProxy("next_best_view", GetNextBestView)
        self.move_to = rospy.ServiceProxy("move_to", MoveCamera)
        true_orientation = self.truth()
        # A cloud published before the estimator is connected would be lost.
        self.wait_for(lambda: True if self.view_cloud_publisher.get_num_connections() > 0
                      else None, "estimator subscribed to view_cloud")
        rospy.loginfo("planner: %d views, utility %s, results into %s", self.p["views"],
                      self.p["utility"], os.path.abspath(self.p["output_dir"]))

        rows = []
        visited = []
        start = rospy.Time.now()
        for view in range(1, int(self.p["views"]) + 1):
            utility = float("nan")
            expected = None
            if view > 1:  # view 1 is wherever the camera starts, as in `vdc evaluate`
                object_position = self.estimated_position()
                pose, utility = self.next_best_pose(visited, object_position)
                response = self.move_to(MoveCameraRequest(mode=MoveCameraRequest.MODE_POSE,
                                                          pose=pose))
                if not response.success:
                    raise RuntimeError("The camera refused the move: %s" % response.message)
                expected = np.array([pose.position.x, pose.position.y, pose.position.z])
            moved_at = rospy.Time.now()
            stamp, camera_position = self.take_view(expected, moved_at)
            visited.append(self.unit(camera_position - self.estimated_position()))
            try:
                estimate = self.wait_for(
                    lambda: self.latest_estimate if self.latest_estimate is not None
                    and self.latest_estimate.header.stamp >= stamp else None,
                    "estimate of view %d" % view)
            except RuntimeError:
                # The estimator skips views it cannot use (too few features); the belief stands.
                rospy.logwarn("planner: view %d was not fused (see the estimator's warnings)",
                              view)
                estimate = self.latest_estimate
                if estimate is None:
                    raise
            error = rotation_error_deg(quaternion_tuple(estimate.map_orientation),
                                       true_orientation)
            direction = visited[-1]
            rospy.loginfo("view %d: error %.1f deg, entropy %.2f nats, %d components, utility "
                          "%.3f, camera direction (%.2f, %.2f, %.2f)", view, error,
                          estimate.entropy, len(estimate.components), utility, *direction)
            rows.append({"view": view, "error_deg": error, "entropy_nats": estimate.entropy,
                         "components": len(estimate.components), "utility": utility,
                         "direction_x": direction[0], "direction_y": direction[1],
                         "direction_z": direction[2],
                         "seconds": (rospy.Time.now() - start).to_sec()})
        self.write(rows)

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
        error_axis.plot(views, [r["error_deg"] for r in rows], "o-", color="tab:red")
        error_axis.set_xlabel("view")
        error_axis.set_ylabel("MAP orientation error [deg]", color="tab:red")
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
