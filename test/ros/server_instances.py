#!/usr/bin/python3
"""rostest: the informativeness server with a model library (~models) answers a next-best-view
request for a named instance and for the most uncertain one from the latest ObjectInstances
message, names the instance in its answer, and refuses an unknown instance or one whose model it
has not loaded with success=false while it keeps serving."""
import math
import unittest

import rospy
import rostest
from view_direction_classification.msg import ObjectInstance, ObjectInstances
from view_direction_classification.srv import (GetHeatmap, GetHeatmapRequest, GetNextBestView,
                                               GetNextBestViewRequest)

from server_bad_requests import girdle_free_belief

SERVER = "informativeness_server"
# The instances' positions in the world frame.
POSITIONS = {"mug_1": (0.5, 0.0, 0.2), "mug_2": (-0.3, 0.4, 0.1), "bowl_1": (0.0, -0.4, 0.1)}


def instance(id_, name, model, cone90_deg):
    entry = ObjectInstance(id=id_, name=name, model=model, cone90_deg=cone90_deg)
    entry.pose.pose.position.x, entry.pose.pose.position.y, entry.pose.pose.position.z = \
        POSITIONS[name]
    entry.pose.pose.orientation.w = 1.0
    entry.belief = girdle_free_belief()
    entry.belief.object_id = name
    return entry


class ServerInstances(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("server_instances")
        rospy.wait_for_service(SERVER + "/next_best_view", timeout=60)
        cls.next_best_view = rospy.ServiceProxy(SERVER + "/next_best_view", GetNextBestView)
        cls.heatmap = rospy.ServiceProxy(SERVER + "/get_heatmap", GetHeatmap)
        # The server subscribes to `instances`, remapped as the launch files do.
        cls.publisher = rospy.Publisher("orientation_estimator/instances", ObjectInstances,
                                        queue_size=1, latch=True)
        message = ObjectInstances()
        message.header.frame_id = "world"
        # mug_2 is the most uncertain mug; the bowl's model is not in the server's library.
        message.instances = [instance(1, "mug_1", "mug", 12.0), instance(2, "mug_2", "mug", 48.0),
                             instance(3, "bowl_1", "bowl", 10.0)]
        cls.publisher.publish(message)
        cls.wait_for_instances()

    @classmethod
    def wait_for_instances(cls):
        deadline = rospy.Time.now() + rospy.Duration(20)
        while rospy.Time.now() < deadline:
            if "No instances received" not in cls.plan("mug_1").message:
                return
            rospy.sleep(0.1)

    @classmethod
    def plan(cls, name):
        request = GetNextBestViewRequest(sample_count=30, sample_distance=0.6, instance=name)
        return cls.next_best_view(request)

    def assert_planned_around(self, response, name):
        self.assertTrue(response.success, response.message)
        self.assertIn("Instance " + name + " (model mug", response.message)
        self.assertEqual(len(response.ranked.poses), 30)
        p = response.best.pose.position
        self.assertAlmostEqual(math.dist((p.x, p.y, p.z), POSITIONS[name]), 0.6, places=6)

    def test_a_named_instance_is_planned_around_its_pose_with_its_belief(self):
        response = self.plan("mug_1")
        self.assert_planned_around(response, "mug_1")
        self.assertIn("Belief of mug_1 from the latest instances", response.message)

    def test_most_uncertain_is_the_instance_with_the_widest_cone(self):
        response = self.plan("most_uncertain")
        self.assert_planned_around(response, "mug_2")
        self.assertIn("the most uncertain", response.message)

    def test_an_unknown_instance_or_model_is_refused_and_the_server_keeps_serving(self):
        response = self.plan("cup_7")
        self.assertFalse(response.success)
        self.assertIn("Unknown instance 'cup_7'", response.message)
        self.assertEqual(len(response.ranked.poses), 0)
        response = self.plan("bowl_1")
        self.assertFalse(response.success)
        self.assertIn("not loaded", response.message)
        self.assert_planned_around(self.plan("mug_2"), "mug_2")

    def test_an_empty_instance_plans_for_the_one_object_as_before(self):
        response = self.plan("")
        self.assertTrue(response.success, response.message)
        self.assertNotIn("Instance", response.message)
        # No tf for `object` here: the one object is taken at the origin.
        p = response.best.pose.position
        self.assertAlmostEqual(math.dist((p.x, p.y, p.z), (0.0, 0.0, 0.0)), 0.6, places=6)

    def test_a_heatmap_for_an_instance_is_drawn_in_its_frame(self):
        response = self.heatmap(GetHeatmapRequest(mode=GetHeatmapRequest.MODE_GLOBAL,
                                                  instance="mug_2"))
        self.assertTrue(response.success, response.message)
        self.assertEqual(response.cloud.header.frame_id, "mug_2")
        self.assertFalse(self.heatmap(GetHeatmapRequest(instance="cup_7")).success)


if __name__ == "__main__":
    rostest.rosrun("view_direction_classification", "server_instances", ServerInstances)
