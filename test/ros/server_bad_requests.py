#!/usr/bin/python3
"""rostest: the informativeness server refuses every bad request with a message and keeps
serving; its latched (and periodically re-sent) topics carry the model's surface set and
training directions."""
import math
import struct
import time
import unittest

import geometry_msgs.msg
import rospy
import rostest
import sensor_msgs.msg
import tf2_ros
import visualization_msgs.msg
from view_direction_classification.msg import BinghamComponent, BinghamMixture
from view_direction_classification.srv import (GetHeatmap, GetHeatmapRequest, GetNextBestView,
                                               GetNextBestViewRequest)

SERVER = "informativeness_server"


def quaternion(x, y, z, w):
    return geometry_msgs.msg.Quaternion(x=x, y=y, z=z, w=w)


def girdle_free_belief(weight=1.0):
    """One component with concentrations (-10, -10, 0) around the identity: its normaliser has
    the closed form 2 pi^2 (1 - e^-k) / k."""
    component = BinghamComponent()
    component.weight = weight
    component.concentrations = [-10.0, -10.0, 0.0]
    component.axes = [quaternion(1, 0, 0, 0), quaternion(0, 1, 0, 0), quaternion(0, 0, 1, 0)]
    component.mode = quaternion(0, 0, 0, 1)
    component.normaliser = 2 * math.pi ** 2 * (1 - math.exp(-10.0)) / 10.0
    belief = BinghamMixture()
    belief.header.frame_id = "world"
    belief.components = [component]
    belief.map_orientation = quaternion(0, 0, 0, 1)
    return belief


def xyz_cloud(points, frame="world"):
    cloud = sensor_msgs.msg.PointCloud2()
    cloud.header.frame_id = frame
    cloud.height, cloud.width = 1, len(points)
    cloud.fields = [sensor_msgs.msg.PointField(name=n, offset=4 * i, datatype=7, count=1)
                    for i, n in enumerate("xyz")]
    cloud.point_step, cloud.row_step = 12, 12 * len(points)
    cloud.data = b"".join(struct.pack("<fff", *p) for p in points)
    return cloud


class ServerBadRequests(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("server_bad_requests")
        # The object's pose, as the estimator would publish it.
        cls.broadcaster = tf2_ros.StaticTransformBroadcaster()
        t = geometry_msgs.msg.TransformStamped()
        t.header.stamp = rospy.Time.now()
        t.header.frame_id, t.child_frame_id = "world", "object"
        t.transform.translation.x, t.transform.translation.z = 0.5, 0.2
        t.transform.rotation.w = 1.0
        cls.broadcaster.sendTransform(t)
        rospy.wait_for_service(SERVER + "/get_heatmap", timeout=60)
        rospy.wait_for_service(SERVER + "/next_best_view", timeout=60)
        cls.heatmap = rospy.ServiceProxy(SERVER + "/get_heatmap", GetHeatmap)
        cls.next_best_view = rospy.ServiceProxy(SERVER + "/next_best_view", GetNextBestView)

    def sampling_request(self, utility="informativeness"):
        request = GetNextBestViewRequest()
        request.sample_count, request.sample_distance, request.utility = 42, 0.6, utility
        return request

    def assert_refused(self, response, words):
        self.assertFalse(response.success)
        self.assertIn(words, response.message)

    def test_heatmap_topic_is_latched_with_one_coloured_point_per_surface_point(self):
        cloud = rospy.wait_for_message(SERVER + "/heatmap", sensor_msgs.msg.PointCloud2, 30)
        scores = self.heatmap(GetHeatmapRequest(mode=GetHeatmapRequest.MODE_GLOBAL)).scores
        self.assertGreater(len(scores), 100)
        self.assertEqual(cloud.width * cloud.height, len(scores))
        self.assertEqual(cloud.header.frame_id, "object")
        self.assertIn("rgb", [f.name for f in cloud.fields])
        markers = rospy.wait_for_message(SERVER + "/view_scores",
                                         visualization_msgs.msg.MarkerArray, 30)
        spheres = [m for m in markers.markers if m.ns == "view_scores"]
        labels = [m for m in markers.markers if m.ns == "best_views"]
        self.assertEqual(len(spheres), 12)  # the quick model's 12 directions
        self.assertEqual(len(labels), 3)

    def test_heatmap_and_view_scores_are_re_sent_every_republish_period(self):
        # config/informativeness_server.yaml: republish_period 1.0 s. A subscriber gets the
        # latched copy at once, then fresh copies: rviz drops a stamp-0 message that arrived
        # before the object frame existed, so only a later copy can be drawn.
        for topic, message_type in ((SERVER + "/heatmap", sensor_msgs.msg.PointCloud2),
                                    (SERVER + "/view_scores", visualization_msgs.msg.MarkerArray)):
            arrivals = []
            subscriber = rospy.Subscriber(topic, message_type,
                                          lambda _, log=arrivals: log.append(time.monotonic()))
            deadline = time.monotonic() + 10.0
            while len(arrivals) < 3 and time.monotonic() < deadline:
                time.sleep(0.05)
            subscriber.unregister()
            self.assertGreaterEqual(len(arrivals), 3, topic + " was not re-sent")

    def test_heatmap_refuses_unknown_view_index_zero_or_nan_direction_and_bad_scaling(self):
        r = GetHeatmapRequest
        self.assert_refused(self.heatmap(r(mode=r.MODE_VIEW_INDEX, view_index=12)), "view index")
        self.assert_refused(self.heatmap(r(mode=r.MODE_VIEW_INDEX, view_index=-1)), "view index")
        zero = geometry_msgs.msg.Vector3(0, 0, 0)
        self.assert_refused(self.heatmap(r(mode=r.MODE_DIRECTION, direction=zero)), "direction")
        nan = geometry_msgs.msg.Vector3(float("nan"), 0, 1)
        self.assert_refused(self.heatmap(r(mode=r.MODE_DIRECTION, direction=nan)), "direction")
        self.assert_refused(self.heatmap(r(mode=r.MODE_GLOBAL, scaling="log")), "scaling")
        self.assert_refused(self.heatmap(r(mode=9)), "mode")

    def test_heatmap_of_a_view_and_of_a_direction_succeed_after_bad_requests(self):
        r = GetHeatmapRequest
        self.heatmap(r(mode=r.MODE_VIEW_INDEX, view_index=99))
        response = self.heatmap(r(mode=r.MODE_VIEW_INDEX, view_index=3, scaling="max"))
        self.assertTrue(response.success, response.message)
        self.assertEqual(response.view_index, 3)
        self.assertLessEqual(response.min, response.median)
        self.assertLessEqual(response.median, response.max)
        self.assertTrue(any(s >= 0 for s in response.scores))
        self.assertTrue(any(s < 0 for s in response.scores))  # one view never sees everything
        direction = geometry_msgs.msg.Vector3(0, 0, 5)
        response = self.heatmap(r(mode=r.MODE_DIRECTION, direction=direction))
        self.assertTrue(response.success, response.message)
        self.assertGreaterEqual(response.view_index, 0)

    def test_next_best_view_uses_the_latest_estimate_when_the_request_has_no_belief(self):
        publisher = rospy.Publisher("estimate", BinghamMixture, queue_size=1, latch=True)
        publisher.publish(girdle_free_belief())
        deadline = rospy.Time.now() + rospy.Duration(10)
        response = None
        while rospy.Time.now() < deadline:
            response = self.next_best_view(self.sampling_request("information_gain"))
            if "latest estimate" in response.message:
                break
            rospy.sleep(0.1)
        self.assertTrue(response.success, response.message)
        self.assertIn("latest estimate", response.message)

    def test_next_best_view_refuses_no_candidates_without_sampling(self):
        self.assert_refused(self.next_best_view(GetNextBestViewRequest()), "no candidate")

    def test_next_best_view_refuses_candidates_in_an_unknown_frame(self):
        request = GetNextBestViewRequest()
        request.candidates.header.frame_id = "no_such_frame"
        pose = geometry_msgs.msg.Pose()
        pose.position.x, pose.orientation.w = 1.0, 1.0
        request.candidates.poses = [pose]
        self.assert_refused(self.next_best_view(request), "no_such_frame")

    def test_next_best_view_refuses_a_belief_with_nan_weights(self):
        request = self.sampling_request()
        request.use_belief = True
        request.belief = girdle_free_belief(weight=float("nan"))
        self.assert_refused(self.next_best_view(request), "weight")

    def test_next_best_view_refuses_an_empty_occluder(self):
        request = self.sampling_request()
        request.use_occluder = True
        request.occluder = xyz_cloud([])
        self.assert_refused(self.next_best_view(request), "occluder")
        request.occluder = sensor_msgs.msg.PointCloud2()  # not even fields
        self.assertFalse(self.next_best_view(request).success)

    def test_next_best_view_refuses_an_unknown_utility(self):
        self.assert_refused(self.next_best_view(self.sampling_request("random")), "utility")

    def test_next_best_view_ranks_sampled_and_given_candidates_after_bad_requests(self):
        self.next_best_view(GetNextBestViewRequest())
        for utility in ("informativeness", "information_gain"):
            request = self.sampling_request(utility)
            request.use_belief = True
            request.belief = girdle_free_belief()
            response = self.next_best_view(request)
            self.assertTrue(response.success, response.message)
            self.assertEqual(len(response.ranked.poses), 42)
            self.assertEqual(response.ranked.header.frame_id, "world")
            self.assertEqual(list(response.utilities), sorted(response.utilities, reverse=True))
            self.assertEqual(response.best.pose, response.ranked.poses[0])
            self.assertEqual(response.best_index, response.candidate_indices[0])
            # Sampled around the object's tf position (0.5, 0, 0.2) at 0.6 m.
            p = response.best.pose.position
            self.assertAlmostEqual(math.dist((p.x, p.y, p.z), (0.5, 0.0, 0.2)), 0.6, places=6)

        # Candidates given in the object frame come back in the fixed frame.
        request = GetNextBestViewRequest()
        request.candidates.header.frame_id = "object"
        for x in (0.6, -0.6):
            pose = geometry_msgs.msg.Pose()
            pose.position.x, pose.orientation.w = x, 1.0
            request.candidates.poses.append(pose)
        request.use_occluder = True
        request.occluder = xyz_cloud([(0.8, 0.0, 0.2)], frame="world")
        response = self.next_best_view(request)
        self.assertTrue(response.success, response.message)
        self.assertEqual(sorted(response.candidate_indices), [0, 1])
        self.assertEqual(sorted(round(p.position.x, 6) for p in response.ranked.poses), [-0.1, 1.1])


if __name__ == "__main__":
    rostest.rosrun("view_direction_classification", "server_bad_requests", ServerBadRequests)
