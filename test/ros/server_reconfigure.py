#!/usr/bin/python3
"""rostest: the informativeness_server's dynamic_reconfigure server starts from the node's
parameters, a change of the default utility answers the next request that leaves its utility
empty, and a value the parameter rule refuses keeps the previous settings."""

import unittest

import rospy
import rostest
from dynamic_reconfigure.client import Client
from view_direction_classification.srv import GetNextBestView, GetNextBestViewRequest

NODE = "informativeness_server"


class ServerReconfigure(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("server_reconfigure_test")
        cls.client = Client(NODE, timeout=60)
        # Taken before any test changes a value (get_configuration answers from the last
        # ~parameter_updates message, which may lag behind later updates).
        cls.start_up = cls.client.get_configuration(timeout=10)
        rospy.wait_for_service(NODE + "/next_best_view", timeout=60)
        cls.next_best_view = rospy.ServiceProxy(NODE + "/next_best_view", GetNextBestView)

    def rank_with_default_utility(self):
        request = GetNextBestViewRequest(sample_count=20, sample_distance=0.6)
        response = self.next_best_view(request)
        self.assertTrue(response.success, response.message)
        return response

    def test_start_up_parameters_are_shown_not_the_cfg_defaults(self):
        self.assertEqual(self.start_up["default_utility"], "information_gain")
        self.assertAlmostEqual(self.start_up["occluder_radius"], 0.007)
        self.assertEqual(self.start_up["belief_samples_per_component"], 8)

    def test_a_changed_default_utility_answers_the_next_request(self):
        config = self.client.update_configuration({"default_utility": "informativeness"})
        self.assertEqual(config["default_utility"], "informativeness")
        self.assertIn("by informativeness", self.rank_with_default_utility().message)
        config = self.client.update_configuration({"default_utility": "information_gain"})
        self.assertEqual(config["default_utility"], "information_gain")
        self.assertIn("by information_gain", self.rank_with_default_utility().message)

    def test_a_value_the_rule_refuses_keeps_the_previous_settings(self):
        before = self.client.update_configuration(
            {"default_utility": "information_gain", "occluder_radius": 0.007})
        # In the .cfg's range [0, 0.1], but ~occluder_radius must be > 0.
        config = self.client.update_configuration(
            {"occluder_radius": 0.0, "default_utility": "informativeness"})
        self.assertAlmostEqual(config["occluder_radius"], before["occluder_radius"])
        # The whole request is refused, not only its bad value.
        self.assertEqual(config["default_utility"], "information_gain")
        self.assertIn("by information_gain", self.rank_with_default_utility().message)
        self.assertAlmostEqual(rospy.get_param("/%s/occluder_radius" % NODE), 0.007)


if __name__ == "__main__":
    rostest.rosrun("view_direction_classification", "server_reconfigure", ServerReconfigure)
