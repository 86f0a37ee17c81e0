"""Helpers of the start-up rostests (estimator_startup, server_startup, camera_startup): run a
node binary in the test's ROS graph, as roslaunch would, and look at how it ends."""

import itertools
import os
import signal
import subprocess
import time

import roslib.packages
import rosgraph
import rosparam

PACKAGE = "view_direction_classification"
_RUNS = itertools.count()


def _binary(node_type):
    # Found as roslaunch finds nodes: rosrun skips executables below <package>/build/, which is
    # where `make test` builds.
    executables = roslib.packages.find_node(PACKAGE, node_type)
    if not executables:
        raise RuntimeError("the %s binary is not built" % node_type)
    return executables[0]


def config_file(name):
    """Path of config/<name> in the package."""
    return os.path.join(roslib.packages.get_pkg_dir(PACKAGE), "config", name)


def fresh_name(node_type):
    """A node name not used before in this test (private parameters stay on the server)."""
    return "%s_under_test_%d" % (node_type, next(_RUNS))


def run_node(node_type, *parameters, name=None, preset=None):
    """Runs the node binary under a fresh name with private parameters `_name:=value` (roscpp
    reads such a value as a number, a boolean or else a string) and those of the dictionary
    `preset` (put on the parameter server first, e.g. lists); returns (exit code, stdout +
    stderr)."""
    name = name or fresh_name(node_type)
    if preset:
        rosparam.upload_params("/" + name, preset)
    result = subprocess.run(
        [_binary(node_type), "__name:=" + name, *parameters],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60, check=False)
    return result.returncode, result.stdout.decode(errors="replace")


def fatal_lines(output):
    return [line for line in output.splitlines() if "FATAL" in line]


# roscpp's own line when one of its calls to the master fails and it tries again: seen about one
# run in six on a loaded machine, in registerSubscriber, i.e. while the node still registers its
# subscriber after advertising the service this test waits for (the SIGINT that ends the node may
# then interrupt the call, or the polled master answers late). It is transport, not the node's
# start-up: the test still requires the service to be advertised and the exit status 0.
_MASTER_RETRY = "Failed to contact master at"


def error_lines(output):
    """The FATAL and ERROR lines of a node's output, other than roscpp's master retries."""
    return [line for line in output.splitlines()
            if ("FATAL" in line or "ERROR" in line) and _MASTER_RETRY not in line]


def load_config(name, yaml_file):
    """Puts a config/*.yaml file into the private namespace of node `name`."""
    for parameters, namespace in rosparam.load_file(config_file(yaml_file),
                                                    default_namespace="/" + name):
        rosparam.upload_params(namespace, parameters)


def _service_is_up(service):
    try:
        rosgraph.Master("/startup_test").lookupService(service)
        return True
    except Exception:  # rosgraph.MasterError until the node has advertised it
        return False


def start_and_stop(node_type, service, *parameters, name=None, timeout=60.0):
    """Starts the node, waits until it advertises `service` (relative to its name), then stops
    it with SIGINT as roslaunch does. Returns (advertised, exit code, output)."""
    name = name or fresh_name(node_type)
    process = subprocess.Popen(
        [_binary(node_type), "__name:=" + name, *parameters],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    deadline = time.monotonic() + timeout
    advertised = False
    while process.poll() is None and time.monotonic() < deadline:
        if _service_is_up("/%s/%s" % (name, service)):
            advertised = True
            break
        time.sleep(0.1)
    if process.poll() is None:
        process.send_signal(signal.SIGINT)
    try:
        output, _ = process.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        process.kill()
        output, _ = process.communicate()
    return advertised, process.returncode, output.decode(errors="replace")


def assert_refused(test, node_type, expected_words, *parameters, preset=None):
    """The node exits with status 1 and exactly one FATAL line, which contains every one of
    `expected_words` (e.g. the parameter's name and the rule)."""
    code, output = run_node(node_type, *parameters, preset=preset)
    test.assertEqual(code, 1, output)
    fatal = fatal_lines(output)
    test.assertEqual(len(fatal), 1, output)
    for words in expected_words:
        test.assertIn(words, fatal[0])


def assert_starts(test, node_type, yaml_file, service, *parameters):
    """With the package's config/<yaml_file> loaded, the node advertises `service`, writes no
    FATAL or ERROR line, reads every parameter of the file (no warning about unknown ones) and
    exits with status 0 on SIGINT."""
    name = fresh_name(node_type)
    load_config(name, yaml_file)
    advertised, code, output = start_and_stop(node_type, service, *parameters, name=name)
    test.assertTrue(advertised, output)
    test.assertEqual(code, 0, output)
    test.assertEqual(error_lines(output), [], output)
    test.assertNotIn("does not read", output)
