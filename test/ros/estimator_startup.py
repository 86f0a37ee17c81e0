#!/usr/bin/python3
"""rostest: the orientation_estimator refuses a bad start-up with one FATAL line and exit code 1
(no crash, no restart loop), for a missing model and for an invalid parameter, and starts with
its config/estimator.yaml."""

import os
import tempfile
import unittest

import rospy
import rostest

from node_startup import PACKAGE, assert_refused, assert_starts, fatal_lines, run_node

NODE = "orientation_estimator"


class EstimatorStartup(unittest.TestCase):
    def test_missing_model_exits_with_status_1_and_a_fatal_line_naming_the_file(self):
        code, output = run_node(NODE, "_model:=/nonexistent/mug_model.h5")
        self.assertEqual(code, 1, output)
        fatal = fatal_lines(output)
        self.assertEqual(len(fatal), 1, output)
        self.assertIn("/nonexistent/mug_model.h5", fatal[0])

    def test_unset_model_is_refused_naming_the_parameter(self):
        assert_refused(self, NODE, ["~model", "is required"])

    def test_corrupt_model_exits_with_status_1(self):
        with tempfile.NamedTemporaryFile(suffix=".h5") as corrupt:
            corrupt.write(b"this is not an HDF5 file\n" * 10)
            corrupt.flush()
            code, output = run_node(NODE, "_model:=" + corrupt.name)
        self.assertEqual(code, 1, output)
        self.assertIn(os.path.basename(corrupt.name), output)

    def test_a_library_entry_that_cannot_be_loaded_stops_the_node_naming_it(self):
        code, output = run_node(NODE, preset={"models": {"cup": "/nonexistent/cup_model.h5"}})
        self.assertEqual(code, 1, output)
        fatal = fatal_lines(output)
        self.assertEqual(len(fatal), 1, output)
        self.assertIn("'cup'", fatal[0])
        self.assertIn("/nonexistent/cup_model.h5", fatal[0])

    def test_a_library_that_is_not_a_map_of_paths_is_refused_naming_the_parameter(self):
        assert_refused(self, NODE, ["~models", "a non-empty map"], "_models:=mug.h5")
        assert_refused(self, NODE, ["~models", "a non-empty map"], preset={"models": ["a", "b"]})
        assert_refused(self, NODE, ["~models", "'cup'"], preset={"models": {"cup": 5}})

    def test_a_bad_library_setting_is_refused_naming_the_parameter(self):
        assert_refused(self, NODE, ["~association_distance"], "_association_distance:=-1.0",
                       preset={"models": {"cup": "/nonexistent.h5"}})

    def test_label_models_that_are_not_a_map_of_class_ids_are_refused_naming_the_parameter(self):
        library = {"models": {"cup": "/nonexistent.h5"}}
        assert_refused(self, NODE, ["~label_models", "'chair'"],
                       preset=dict(library, label_models={"chair": "cup"}))
        assert_refused(self, NODE, ["~label_models", "'41'"],
                       preset=dict(library, label_models={"41": 5}))
        assert_refused(self, NODE, ["~label_models", "a map"],
                       preset=dict(library, label_models=["cup"]))

    def test_label_models_naming_no_model_of_the_library_stop_the_node_naming_it(self):
        model = rospy.get_param("/startup_test_model")
        assert_refused(self, NODE, ["label_models", "class 41", "'bowl'"], "_model:=" + model,
                       "_segmentation:=labels", preset={"label_models": {"41": "bowl"}})

    def test_invalid_parameter_exits_with_status_1_naming_the_parameter(self):
        code, output = run_node(NODE, "_model:=/nonexistent.h5", "_tf_timeout:=-1.0")
        self.assertEqual(code, 1, output)
        self.assertIn("~tf_timeout", output)

    def test_negative_tf_rate_is_refused_naming_the_parameter(self):
        code, output = run_node(NODE, "_model:=/nonexistent.h5", "_tf_rate:=-1.0")
        self.assertEqual(code, 1, output)
        self.assertIn("~tf_rate", output)

    def test_unknown_segmentation_mode_is_refused(self):
        code, output = run_node(NODE, "_model:=/nonexistent.h5", "_segmentation:=magic")
        self.assertEqual(code, 1, output)
        self.assertIn("~segmentation", output)

    def test_a_value_of_the_wrong_type_is_refused_not_replaced_by_the_default(self):
        assert_refused(self, NODE, ["~kappa", "must be a number", "got a string ('high')"],
                       "_model:=/nonexistent.h5", "_kappa:=high")
        assert_refused(self, NODE, ["~max_components", "must be an integer", "got a number (50.0)"],
                       "_model:=/nonexistent.h5", "_max_components:=50.0")
        assert_refused(self, NODE, ["~publish_tf", "true or false"],
                       "_model:=/nonexistent.h5", "_publish_tf:=1")

    def test_out_of_range_core_values_are_refused_naming_the_parameter(self):
        for parameter, value, shown in [("n_feat", -1, "-1"), ("max_components", 0, "0"),
                                        ("min_weight", 1.0, "1"),
                                        ("belief_weight_floor", -0.1, "-0.1"),
                                        ("sharpness_ratio", 0.5, "0.5"),
                                        ("roi_centre", [0.0, 1.0], "[0, 1]")]:
            assert_refused(self, NODE, ["~" + parameter, "got %s." % shown],
                           "_model:=/nonexistent.h5", preset={parameter: value})

    def test_bad_refinement_settings_are_refused_naming_the_parameter(self):
        assert_refused(self, NODE, ["~refinement", "one of 'none', 'icp'", "'gicp'"],
                       "_model:=/nonexistent.h5", "_refinement:=gicp")
        for parameter, value, shown in [("refinement_max_components", 0, "0"),
                                        ("refinement_girdle_step_deg", 0.0, "0"),
                                        ("refinement_girdle_step_deg", 181.0, "181"),
                                        ("refinement_max_refined", -1, "-1"),
                                        ("refinement_min_score", 1.5, "1.5"),
                                        ("refinement_restart_seeds", -1, "-1"),
                                        ("refinement_views", 0, "0"),
                                        ("refinement_search_below_score", -0.1, "-0.1"),
                                        ("refinement_rebuild_margin", 2.0, "2"),
                                        ("refinement_depth_noise_at_1m", -0.001, "-0.001")]:
            assert_refused(self, NODE, ["~" + parameter, "got %s." % shown],
                           "_model:=/nonexistent.h5", preset={parameter: value})
        assert_refused(self, NODE, ["~refinement_max_refined", "must be an integer"],
                       "_model:=/nonexistent.h5", "_refinement_max_refined:=2.5")

    def test_starts_with_its_config_file(self):
        assert_starts(self, NODE, "estimator.yaml", "reset",
                      "_model:=" + rospy.get_param("/startup_test_model"))


if __name__ == "__main__":
    rostest.rosrun(PACKAGE, "estimator_startup", EstimatorStartup)
