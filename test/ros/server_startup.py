#!/usr/bin/python3
"""rostest: the informativeness_server refuses a bad start-up (missing model, a parameter of the
wrong type or out of range, a bad model library) with one FATAL line naming the parameter and
exit code 1, and starts with its config/informativeness_server.yaml (with a model, or with a
library alone)."""

import unittest

import rosparam
import rospy
import rostest

from node_startup import (PACKAGE, assert_refused, assert_starts, error_lines, fatal_lines,
                          fresh_name, load_config, run_node, start_and_stop)

NODE = "informativeness_server"


class ServerStartup(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.model_path = rospy.get_param("/startup_test_model")
        cls.model = "_model:=" + cls.model_path

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

    def test_a_library_that_is_not_a_map_of_paths_is_refused_naming_the_parameter(self):
        assert_refused(self, NODE, ["~models", "a non-empty map"], "_models:=mug.h5")
        assert_refused(self, NODE, ["~models", "'cup'"], preset={"models": {"cup": 5}})

    def test_a_library_entry_that_cannot_be_loaded_stops_the_node_naming_it(self):
        code, output = run_node(NODE, preset={"models": {"cup": "/nonexistent/cup_model.h5"}})
        self.assertEqual(code, 1, output)
        fatal = fatal_lines(output)
        self.assertEqual(len(fatal), 1, output)
        self.assertIn("'cup'", fatal[0])
        self.assertIn("/nonexistent/cup_model.h5", fatal[0])

    def test_starts_with_a_library_and_no_model(self):
        name = fresh_name(NODE)
        load_config(name, "informativeness_server.yaml")
        rosparam.upload_params("/" + name, {"models": {"mug": self.model_path}})
        advertised, code, output = start_and_stop(NODE, "next_best_view", name=name)
        self.assertTrue(advertised, output)
        self.assertEqual(code, 0, output)
        self.assertEqual(error_lines(output), [], output)
        self.assertNotIn("does not read", output)  # ~models is one of its parameters

    def test_starts_with_its_config_file(self):
        assert_starts(self, NODE, "informativeness_server.yaml", "next_best_view", self.model)


if __name__ == "__main__":
    rostest.rosrun(PACKAGE, "server_startup", ServerStartup)
