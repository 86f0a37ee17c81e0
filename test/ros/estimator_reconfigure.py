#!/usr/bin/python3
"""rostest: the orientation_estimator's dynamic_reconfigure server starts from the node's
parameters, applies a valid change and refuses a value the parameter rule refuses."""

import unittest

import rospy
import rostest
from dynamic_reconfigure.client import Client

NODE = "orientation_estimator"


class EstimatorReconfigure(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("estimator_reconfigure_test")
        cls.client = Client(NODE, timeout=60)
        # Taken before any test changes a value. Client.get_configuration answers from the last
        # ~parameter_updates message it received, which can lag behind the server's state after
        # an update: the tests below compare with what the server answers to their requests.
        cls.start_up = cls.client.get_configuration(timeout=10)

    def test_start_up_parameters_are_shown_not_the_cfg_defaults(self):
        config = self.start_up
        self.assertAlmostEqual(config["kappa"], 18.4)
        self.assertEqual(config["max_components"], 20)
        # Parameters the launch left to config/estimator.yaml.
        self.assertAlmostEqual(config["min_weight"], 0.001)
        self.assertAlmostEqual(config["converged_cone90_deg"], 15.0)

    def test_a_valid_change_is_taken(self):
        config = self.client.update_configuration({"max_components": 5, "n_feat": 30})
        self.assertEqual(config["max_components"], 5)
        self.assertEqual(config["n_feat"], 30)
        self.assertEqual(rospy.get_param("/%s/max_components" % NODE), 5)
        self.client.update_configuration({"max_components": 20, "n_feat": 0})

    def test_the_camera_pose_uncertainty_is_tuned_live_and_clamped_at_zero(self):
        config = self.client.update_configuration({"camera_pose_uncertainty_deg": 2.0})
        self.assertAlmostEqual(config["camera_pose_uncertainty_deg"], 2.0)
        self.assertAlmostEqual(rospy.get_param("/%s/camera_pose_uncertainty_deg" % NODE), 2.0)
        # Below the .cfg's range: dynamic_reconfigure clamps it to 0 (exact poses).
        config = self.client.update_configuration({"camera_pose_uncertainty_deg": -1.0})
        self.assertAlmostEqual(config["camera_pose_uncertainty_deg"], 0.0)

    def test_refinement_is_switched_live_and_its_knobs_checked(self):
        config = self.client.update_configuration(
            {"refinement": "icp", "refinement_girdle_step_deg": 15.0, "psum_exponent": 2.0})
        self.assertEqual(config["refinement"], "icp")
        self.assertAlmostEqual(config["refinement_girdle_step_deg"], 15.0)
        self.assertAlmostEqual(config["psum_exponent"], 2.0)
        self.assertEqual(rospy.get_param("/%s/refinement" % NODE), "icp")
        # Inside the .cfg's range [0, 180], but the step must be positive: the whole request,
        # the mode with it, is refused.
        refused = self.client.update_configuration(
            {"refinement": "none", "refinement_girdle_step_deg": 0.0})
        self.assertEqual(refused["refinement"], "icp")
        self.assertAlmostEqual(refused["refinement_girdle_step_deg"], 15.0)
        # An unknown mode is refused too (the drop-down is a hint, dynparam sends any string).
        unknown = self.client.update_configuration({"refinement": "gicp"})
        self.assertEqual(unknown["refinement"], "icp")
        self.client.update_configuration(
            {"refinement": "none", "refinement_girdle_step_deg": 30.0, "psum_exponent": 1.0})

    def test_a_value_the_rule_refuses_keeps_the_previous_one(self):
        # A known state, as the server answers it (not the client's possibly stale copy).
        before = self.client.update_configuration({"min_weight": 0.001, "max_components": 20})
        self.assertEqual(before["max_components"], 20)
        # In the .cfg's range [0, 1], but ~min_weight must lie in [0, 1).
        config = self.client.update_configuration({"min_weight": 1.0, "max_components": 7})
        self.assertAlmostEqual(config["min_weight"], before["min_weight"])
        # The whole request is refused, not only its bad value.
        self.assertEqual(config["max_components"], before["max_components"])
        self.assertAlmostEqual(rospy.get_param("/%s/min_weight" % NODE), before["min_weight"])

    def test_a_value_outside_the_cfg_range_is_clamped(self):
        config = self.client.update_configuration({"max_components": 0})
        self.assertEqual(config["max_components"], 1)
        self.client.update_configuration({"max_components": 20})


if __name__ == "__main__":
    rostest.rosrun("view_direction_classification", "estimator_reconfigure", EstimatorReconfigure)
