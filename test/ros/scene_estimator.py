#!/usr/bin/python3
"""rostest: the orientation_estimator with a model library (scene_estimator.test). A simulated
table holds three mugs (the library's one model) and two unknown objects (a box of a mug's size
and a tall cylinder); the camera is moved through four views. At the end:
- ~instances holds three instances of `mug`, and each mug of the scene has a tf frame
  (fixed frame -> <name>) within 2 cm of it, oriented within BOUND_DEG;
- no instance stands on the box or the cylinder;
- ~query_instances answers the three mugs for model `mug` (and one by id), and an empty list
  with a message for an unknown model, a negative id and an unknown id;
- ~memory_markers draws a sphere and a label per remembered instance;
- ~reset_instance forgets one instance by id and refuses an unknown id.
"""
import math
import threading
import unittest

import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import Vector3
from quaternions import rotation_error_deg
from view_direction_classification.msg import ObjectInstances
from view_direction_classification.srv import (MoveCamera, MoveCameraRequest, QueryInstances,
                                               QueryInstancesRequest, ResetInstance,
                                               ResetInstanceRequest)
from visualization_msgs.msg import Marker, MarkerArray

# Object-frame directions after the camera's initial [1, 0, 0.5], all above the table.
MOVES = [(0.0, 1.0, 0.6), (-1.0, 0.0, 0.7), (0.0, -1.0, 0.5)]
DWELL_S = 4.0
DISTANCE = 0.7
POSITION_BOUND_M = 0.02
BOUND_DEG = 20.0  # the quick 12-direction model; the core's scene test reaches < 5


def quaternion_from_yaw(yaw):
    return (0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0))


class SceneEstimator(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("scene_estimator_test")
        cls.lock = threading.Lock()
        cls.instances = None
        cls.memory_markers = None
        cls.tf_buffer = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf_buffer)
        rospy.Subscriber("/orientation_estimator/instances", ObjectInstances, cls.on_instances)
        rospy.Subscriber("/orientation_estimator/memory_markers", MarkerArray,
                         cls.on_memory_markers)

    @classmethod
    def on_instances(cls, message):
        with cls.lock:
            cls.instances = message

    @classmethod
    def on_memory_markers(cls, message):
        with cls.lock:
            cls.memory_markers = message

    def latest(self):
        with self.lock:
            return self.instances

    def scene_truth(self):
        """The mugs' (x, y, z, yaw) and the unknown objects' positions, from the camera's
        parameters (distractor poses are x, y, z, roll, pitch, yaw)."""
        pose = rospy.get_param("/simulated_depth_camera/object_pose")
        poses = rospy.get_param("/simulated_depth_camera/distractor_poses")
        groups = [poses[i:i + 6] for i in range(0, len(poses), 6)]
        mugs = [pose] + groups[:2]
        unknown = groups[2:]
        return mugs, unknown

    def move_through_the_views(self):
        rospy.wait_for_service("/simulated_depth_camera/move_to", 30.0)
        move_to = rospy.ServiceProxy("/simulated_depth_camera/move_to", MoveCamera)
        deadline = rospy.Time.now() + rospy.Duration(60.0)
        while self.latest() is None and rospy.Time.now() < deadline:
            rospy.sleep(0.1)
        self.assertIsNotNone(self.latest(), "no ~instances from the estimator")
        rospy.sleep(DWELL_S)
        for direction in MOVES:
            response = move_to(MoveCameraRequest(mode=MoveCameraRequest.MODE_DIRECTION,
                                                 direction=Vector3(*direction),
                                                 distance=DISTANCE, roll=0.0))
            self.assertTrue(response.success, response.message)
            rospy.sleep(DWELL_S)

    def test_each_mug_gets_its_frame_and_the_unknown_objects_none(self):
        self.move_through_the_views()
        mugs, unknown = self.scene_truth()
        message = self.latest()
        names = ["%s at (%.3f, %.3f, %.3f), %d views, identity %.2f"
                 % (instance.name, instance.pose.pose.position.x, instance.pose.pose.position.y,
                    instance.pose.pose.position.z, instance.views_fused,
                    instance.identity_probability) for instance in message.instances]
        rospy.loginfo("scene: instances %s", names)
        self.assertEqual(len(message.instances), 3, names)
        self.assertTrue(all(instance.model == "mug" for instance in message.instances))
        frames = {}
        for instance in message.instances:
            transform = self.tf_buffer.lookup_transform("world", instance.name, rospy.Time(0),
                                                        rospy.Duration(5.0)).transform
            frames[instance.name] = transform
        for mug in mugs:
            nearest = min(frames.items(), key=lambda item: math.dist(
                (item[1].translation.x, item[1].translation.y, item[1].translation.z), mug[:3]))
            name, transform = nearest
            t = transform.translation
            distance = math.dist((t.x, t.y, t.z), mug[:3])
            q = transform.rotation
            error = rotation_error_deg((q.x, q.y, q.z, q.w), quaternion_from_yaw(mug[5]))
            rospy.loginfo("scene: %s is %.1f mm and %.1f deg from the mug at %s", name,
                          1000 * distance, error, mug[:3])
            self.assertLess(distance, POSITION_BOUND_M, name)
            self.assertLess(error, BOUND_DEG, name)
        for other in unknown:
            for name, transform in frames.items():
                t = transform.translation
                self.assertGreater(math.dist((t.x, t.y), other[:2]), 0.05,
                                   "%s stands on an unknown object at %s" % (name, other[:3]))

        self.check_the_memory(message)
        rospy.wait_for_service("/orientation_estimator/reset_instance", 10.0)
        reset_instance = rospy.ServiceProxy("/orientation_estimator/reset_instance", ResetInstance)
        refused = reset_instance(ResetInstanceRequest(id=9999))
        self.assertFalse(refused.success)
        forgotten = reset_instance(ResetInstanceRequest(id=message.instances[0].id))
        self.assertTrue(forgotten.success, forgotten.message)

    def check_the_memory(self, message):
        """~query_instances and ~memory_markers agree with the last ~instances (the camera is
        still: the memory has not changed since)."""
        rospy.wait_for_service("/orientation_estimator/query_instances", 10.0)
        query = rospy.ServiceProxy("/orientation_estimator/query_instances", QueryInstances)
        mugs = query(QueryInstancesRequest(model="mug", id=0, include_gone=True))
        rospy.loginfo("scene: query mug: %s", mugs.message)
        self.assertEqual(sorted(i.id for i in mugs.instances),
                         sorted(i.id for i in message.instances), mugs.message)
        self.assertEqual(mugs.header.frame_id, "world")
        one = query(QueryInstancesRequest(model="", id=message.instances[0].id))
        self.assertEqual([i.name for i in one.instances], [message.instances[0].name], one.message)
        for request in (QueryInstancesRequest(model="teapot"), QueryInstancesRequest(id=-1),
                        QueryInstancesRequest(id=9999)):
            answer = query(request)
            rospy.loginfo("scene: query model %r id %d: %s", request.model, request.id,
                          answer.message)
            self.assertEqual(len(answer.instances), 0, answer.message)
            self.assertTrue(answer.message)
        self.assertIn("teapot", query(QueryInstancesRequest(model="teapot")).message)

        deadline = rospy.Time.now() + rospy.Duration(5.0)
        while rospy.Time.now() < deadline:
            with self.lock:
                markers = self.memory_markers
            if markers is not None:
                break
            rospy.sleep(0.1)
        self.assertIsNotNone(markers, "no ~memory_markers within 5 s")
        spheres = [m for m in markers.markers if m.type == Marker.SPHERE]
        labels = [m for m in markers.markers if m.type == Marker.TEXT_VIEW_FACING]
        self.assertEqual(sorted(m.ns for m in spheres), sorted(i.name for i in message.instances))
        self.assertEqual(len(labels), len(spheres))
        self.assertTrue(all(0.0 < m.color.a <= 1.0 for m in spheres))


if __name__ == "__main__":
    rostest.rosrun("view_direction_classification", "scene_estimator", SceneEstimator)
