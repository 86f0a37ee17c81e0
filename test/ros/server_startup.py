#!/usr/bin/python3
"""rostest: the informativeness_server refuses a bad start-up (missing model, a parameter of the
wrong type or out of range) with one FATAL line naming the parameter and exit code 1, and starts
with its config/informativeness_server.yaml."""

import unittest

import rospy
import rostest

from node_startup import PACKAGE, assert_refused, assert_starts

NODE = "informativeness_server"


class ServerStartup(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.model = "_model:=" + rospy.get_param("/startup_test_model")

    def refused(self, expected_words, *parameters):
        assert_refused(self, NODE, expected_words, self.model, *parameters)

    def test_unset_model_is_refused_naming_the_parameter(self):
        assert_refused(self, NODE, ["~model", "is required"])

    def test_missing_model_file_is_refused_naming_the_file(self):
        assert_refused(self, NODE, ["/nonexistent/mug_model.h5"],
                       "_model:=/nonexistent/mug_model.h5")

    def test_a_value_of_the_wrong_type_is_refused_not_replaced_by_the_default(self):
        self.refused(["~label_best", "must be an integer", "got a string ('three')"],
                     "_label_best:=three")
        self.refused(["~occluder_radius", "must be a number", "got a string ('wide')"],
                     "_occluder_radius:=wide")
        self.refused(["~belief_samples_per_component", "must be an integer", "(8.0)"],
                     "_belief_samples_per_component:=8.0")
        self.refused(["~fixed_frame", "must be a string"], "_fixed_frame:=3")

    def test_out_of_range_values_are_refused_naming_the_parameter_and_the_range(self):
        self.refused(["~occluder_radius", "> 0", "got -0.005"], "_occluder_radius:=-0.005")
        self.refused(["~view_marker_distance", "> 0"], "_view_marker_distance:=0.0")
        self.refused(["~belief_samples_per_component", "between 0 and 1000"],
                     "_belief_samples_per_component:=-1")
        self.refused(["~label_best", ">= 0"], "_label_best:=-2")
        self.refused(["~tf_timeout", ">= 0"], "_tf_timeout:=-1.0")
        self.refused(["~republish_period", ">= 0"], "_republish_period:=-1.0")
        self.refused(["~default_utility", "'informativeness', 'information_gain'"],
                     "_default_utility:=magic")
        self.refused(["~object_frame", "frame name"], "_object_frame:=my object")

    def test_starts_with_its_config_file(self):
        assert_starts(self, NODE, "informativeness_server.yaml", "next_best_view", self.model)


if __name__ == "__main__":
    rostest.rosrun(PACKAGE, "server_startup", ServerStartup)
