#!/usr/bin/python3
"""rostest: the simulated_depth_camera refuses a bad start-up (an unreadable mesh, a parameter of
the wrong type or out of range) with one FATAL line naming it and exit code 1, and starts with
its config/simulated_depth_camera.yaml."""

import unittest

import rostest

from node_startup import PACKAGE, assert_refused, assert_starts

NODE = "simulated_depth_camera"


class CameraStartup(unittest.TestCase):
    def refused(self, expected_words, *parameters, preset=None):
        assert_refused(self, NODE, expected_words, *parameters, preset=preset)

    def test_unreadable_mesh_is_refused_naming_the_file(self):
        self.refused(["/nonexistent/mug.ply"], "_mesh:=/nonexistent/mug.ply")

    def test_a_value_of_the_wrong_type_is_refused_not_replaced_by_the_default(self):
        self.refused(["~rate", "must be a number", "got a string ('fast')"], "_rate:=fast")
        self.refused(["~noise", "must be true or false", "got an integer (1)"], "_noise:=1")
        self.refused(["~seed", "must be an integer", "(1.5)"], "_seed:=1.5")
        self.refused(["~object_pose", "list of numbers", "got a string ('origin')"],
                     "_object_pose:=origin")
        self.refused(["~view_direction", "element 1 is a string ('x')"],
                     preset={"view_direction": [1.0, "x", 0.5]})

    def test_out_of_range_values_are_refused_naming_the_parameter_and_the_range(self):
        self.refused(["~rate", "> 0", "got 0"], "_rate:=0.0")
        self.refused(["~distance", "> 0"], "_distance:=-0.6")
        self.refused(["~visibility_radius", ">= 0"], "_visibility_radius:=-0.01")
        self.refused(["~seed", ">= 0"], "_seed:=-1")
        self.refused(["~object_pose", "6 finite numbers", "got [0, 0, 0]"],
                     preset={"object_pose": [0.0, 0.0, 0.0]})
        self.refused(["~view_direction", "not all zero"],
                     preset={"view_direction": [0.0, 0.0, 0.0]})
        self.refused(["~visibility_anchors", "groups of 3", "got [0.1, 0.2]"],
                     preset={"visibility_anchors": [0.1, 0.2]})
        self.refused(["~camera_frame", "different from ~fixed_frame"], "_camera_frame:=world")

    def test_a_scene_that_cannot_be_built_is_refused(self):
        self.refused(["~table_size", "both positive, or [0, 0]", "got [1, 0]"],
                     preset={"table_size": [1.0, 0.0]})
        self.refused(["~distractor_poses", "one x, y, z, roll, pitch, yaw pose per distractor",
                      "(2 in ~distractors)"],
                     preset={"distractors": "box 0.1 0.1 0.1; cylinder 0.03 0.2",
                             "distractor_poses": [0.0, 0.2, 0.0, 0.0, 0.0, 0.0]})
        self.refused(["distractor 'cone 0.1'"], preset={"distractors": "cone 0.1",
                                                       "distractor_poses": [0.0] * 6})

    def test_starts_with_its_config_file(self):
        assert_starts(self, NODE, "simulated_depth_camera.yaml", "move_to", "_mesh:=mug")


if __name__ == "__main__":
    rostest.rosrun(PACKAGE, "camera_startup", CameraStartup)
