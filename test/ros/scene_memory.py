#!/usr/bin/python3
"""rostest: the scene node's ~memory_file. Saved at shutdown where there was none, loaded again by
the next start; ~save_memory says why when the file cannot be written; a file that cannot be
loaded is one ERROR line naming it, the node keeps running, and the file is never saved over."""

import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest

import rospy
import rostest
import tf2_ros
from std_srvs.srv import Trigger

from node_startup import PACKAGE, _binary, error_lines, fresh_name, load_config

NODE = "orientation_estimator"
# The scene_memory fuzz target's seed: one remembered mug, mug_1 (id 1, identity 0.9), its
# refined position (0.41, -0.1, 0.7) in the fixed frame `world`.
ONE_MUG = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "fuzz", "corpus",
                       "scene_memory", "one_mug.h5")


class RunningNode:
    """The scene node with a library of the test's mug and `memory_file`, until stop()."""

    def __init__(self, memory_file):
        self.name = fresh_name(NODE)
        load_config(self.name, "estimator.yaml")
        rospy.set_param("/%s/models" % self.name, {"mug": rospy.get_param("/memory_test_model")})
        self.process = subprocess.Popen(
            [_binary(NODE), "__name:=" + self.name, "_memory_file:=" + memory_file],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        rospy.wait_for_service("/%s/save_memory" % self.name, timeout=60.0)

    def save(self):
        return rospy.ServiceProxy("/%s/save_memory" % self.name, Trigger)()

    def stop(self):
        """SIGINT as roslaunch sends it; returns (exit code, output)."""
        self.process.send_signal(signal.SIGINT)
        output, _ = self.process.communicate(timeout=60)
        return self.process.returncode, output.decode(errors="replace")


class SceneMemory(unittest.TestCase):
    def test_a_memory_saved_at_shutdown_is_loaded_by_the_next_start(self):
        with tempfile.TemporaryDirectory() as directory:
            memory = os.path.join(directory, "objects.h5")
            code, output = RunningNode(memory).stop()
            self.assertEqual(code, 0, output)
            self.assertTrue(os.path.isfile(memory), output)
            self.assertEqual(os.listdir(directory), ["objects.h5"], "no temporary file is left")
            node = RunningNode(memory)
            response = node.save()
            code, output = node.stop()
            self.assertTrue(response.success, response.message)
            self.assertIn("0 instances from the object memory", output)
            self.assertEqual(error_lines(output), [], output)

    def test_a_remembered_instance_has_its_tf_frame_before_any_cloud(self):
        with tempfile.TemporaryDirectory() as directory:
            memory = os.path.join(directory, "objects.h5")
            shutil.copy(ONE_MUG, memory)
            buffer = tf2_ros.Buffer()
            listener = tf2_ros.TransformListener(buffer)  # noqa: F841 (fills the buffer)
            node = RunningNode(memory)
            try:
                transform = buffer.lookup_transform("world", "mug_1", rospy.Time(0),
                                                    rospy.Duration(20.0))
            finally:
                code, output = node.stop()
            self.assertEqual(code, 0, output)
            self.assertIn("1 instances from the object memory", output)
            translation = transform.transform.translation
            self.assertAlmostEqual(translation.x, 0.41, places=6)
            self.assertAlmostEqual(translation.y, -0.1, places=6)
            self.assertAlmostEqual(translation.z, 0.7, places=6)

    def test_saving_into_a_missing_directory_fails_with_the_reason(self):
        with tempfile.TemporaryDirectory() as directory:
            memory = os.path.join(directory, "missing", "objects.h5")
            node = RunningNode(memory)
            response = node.save()
            node.stop()
            self.assertFalse(response.success)
            self.assertIn(memory, response.message)
            self.assertIn("cannot create the file", response.message)

    def test_a_file_that_cannot_be_loaded_is_reported_and_never_saved_over(self):
        with tempfile.TemporaryDirectory() as directory:
            memory = os.path.join(directory, "objects.h5")
            content = b"not an object memory\n" * 10
            with open(memory, "wb") as damaged:
                damaged.write(content)
            node = RunningNode(memory)
            response = node.save()
            time.sleep(0.5)
            self.assertIsNone(node.process.poll(), "the node keeps running")
            code, output = node.stop()
            self.assertEqual(code, 0, output)
            self.assertFalse(response.success)
            self.assertIn("could not be loaded", response.message)
            errors = error_lines(output)
            self.assertTrue(any(memory in line and "not an HDF5 file" in line for line in errors),
                            output)
            with open(memory, "rb") as kept:
                self.assertEqual(kept.read(), content)


if __name__ == "__main__":
    rospy.init_node("scene_memory_test", anonymous=True)
    rostest.rosrun(PACKAGE, "scene_memory", SceneMemory)
