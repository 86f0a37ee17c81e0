#!/usr/bin/python3
"""rostest: the orientation_estimator refuses a bad start-up with one FATAL line and exit code 1
(no crash, no restart loop), for a missing model and for an invalid parameter."""

import itertools
import os
import subprocess
import tempfile
import unittest

import roslib.packages
import rostest

PACKAGE = "view_direction_classification"


RUNS = itertools.count()


def run_estimator(*parameters):
    """Runs the node binary in the test's ROS graph under a fresh name (private parameters set
    with _name:=value stay on the parameter server); returns (exit code, stdout + stderr)."""
    name = "__name:=estimator_under_test_%d" % next(RUNS)
    # Found as roslaunch finds nodes: rosrun skips executables below <package>/build/, which is
    # where `make test` builds.
    executables = roslib.packages.find_node(PACKAGE, "orientation_estimator")
    if not executables:
        raise RuntimeError("the orientation_estimator binary is not built")
    result = subprocess.run(
        [executables[0], name, *parameters],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60, check=False)
    return result.returncode, result.stdout.decode(errors="replace")


class EstimatorStartup(unittest.TestCase):
    def test_missing_model_exits_with_status_1_and_a_fatal_line_naming_the_file(self):
        code, output = run_estimator("_model:=/nonexistent/mug_model.h5")
        self.assertEqual(code, 1, output)
        fatal = [line for line in output.splitlines() if "FATAL" in line]
        self.assertEqual(len(fatal), 1, output)
        self.assertIn("/nonexistent/mug_model.h5", fatal[0])

    def test_corrupt_model_exits_with_status_1(self):
        with tempfile.NamedTemporaryFile(suffix=".h5") as corrupt:
            corrupt.write(b"this is not an HDF5 file\n" * 10)
            corrupt.flush()
            code, output = run_estimator("_model:=" + corrupt.name)
        self.assertEqual(code, 1, output)
        self.assertIn(os.path.basename(corrupt.name), output)

    def test_invalid_parameter_exits_with_status_1_naming_the_parameter(self):
        code, output = run_estimator("_model:=/nonexistent.h5", "_tf_timeout:=-1.0")
        self.assertEqual(code, 1, output)
        self.assertIn("~tf_timeout", output)

    def test_negative_tf_rate_is_refused_naming_the_parameter(self):
        code, output = run_estimator("_model:=/nonexistent.h5", "_tf_rate:=-1.0")
        self.assertEqual(code, 1, output)
        self.assertIn("~tf_rate", output)

    def test_unknown_segmentation_mode_is_refused(self):
        code, output = run_estimator("_model:=/nonexistent.h5", "_segmentation:=magic")
        self.assertEqual(code, 1, output)
        self.assertIn("~segmentation", output)


if __name__ == "__main__":
    rostest.rosrun(PACKAGE, "estimator_startup", EstimatorStartup)
