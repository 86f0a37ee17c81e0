#!/usr/bin/python3
"""rostest: the simulated depth camera publishes organised clouds of the mug in its optical
frame near the configured distance, with its tf; ~move_to moves the camera (and its tf);
~place_part takes the mug away and puts it somewhere else (its cloud and ground-truth tf
follow)."""
import math
import unittest

import geometry_msgs.msg
import rospy
import rostest
import sensor_msgs.msg
import sensor_msgs.point_cloud2 as pc2
import tf2_ros
from view_direction_classification.srv import (MoveCamera, MoveCameraRequest, PlacePart,
                                               PlacePartRequest)

CAMERA = "simulated_depth_camera"
OBJECT = (0.4, -0.1, 0.3)  # object_pose in the .test file


def finite_points(cloud):
    points = pc2.read_points(cloud, field_names=("x", "y", "z"), skip_nans=False)
    return [p for p in points if all(math.isfinite(c) for c in p)]


class SimulatedCamera(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("simulated_camera_test")
        cls.tf_buffer = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf_buffer)
        rospy.wait_for_service(CAMERA + "/move_to", timeout=60)
        cls.move_to = rospy.ServiceProxy(CAMERA + "/move_to", MoveCamera)
        rospy.wait_for_service(CAMERA + "/place_part", timeout=60)
        cls.place_part = rospy.ServiceProxy(CAMERA + "/place_part", PlacePart)

    def camera_position(self, after):
        """The camera's position in world from the first tf stamped after `after`."""
        deadline = rospy.Time.now() + rospy.Duration(10)
        while rospy.Time.now() < deadline:
            try:
                t = self.tf_buffer.lookup_transform("world", "test_camera", rospy.Time(0))
                if t.header.stamp > after:
                    v = t.transform.translation
                    return (v.x, v.y, v.z)
            except tf2_ros.TransformException:
                pass
            rospy.sleep(0.05)
        self.fail("no camera tf after %s" % after.to_sec())

    def test_1_cloud_is_organised_in_the_camera_frame_near_the_configured_distance(self):
        cloud = rospy.wait_for_message(CAMERA + "/cloud", sensor_msgs.msg.PointCloud2, 30)
        self.assertEqual(cloud.header.frame_id, "test_camera")
        self.assertEqual((cloud.width, cloud.height), (640, 480))
        points = finite_points(cloud)
        self.assertGreater(len(points), 1000)
        # Mug radius 4 cm, height 9.5 cm: every point lies within 0.1 m of the 0.6 m distance.
        near = [p for p in points if abs(p[2] - 0.6) < 0.1]
        self.assertGreater(len(near), 0.95 * len(points))
        # The tf with the cloud's stamp puts the camera 0.6 m from the object.
        t = self.tf_buffer.lookup_transform("world", "test_camera", cloud.header.stamp,
                                            rospy.Duration(5))
        v = t.transform.translation
        self.assertAlmostEqual(math.dist((v.x, v.y, v.z), OBJECT), 0.6, places=6)

    def test_2_move_to_changes_the_camera_tf(self):
        request = MoveCameraRequest(mode=MoveCameraRequest.MODE_DIRECTION, distance=0.8)
        request.direction = geometry_msgs.msg.Vector3(0, 0, 1)
        response = self.move_to(request)
        self.assertTrue(response.success, response.message)
        position = self.camera_position(rospy.Time.now())
        # Straight above the object (its yaw does not move its z axis) at 0.8 m.
        for got, want in zip(position, (OBJECT[0], OBJECT[1], OBJECT[2] + 0.8)):
            self.assertAlmostEqual(got, want, places=6)

        pose = MoveCameraRequest(mode=MoveCameraRequest.MODE_POSE)
        pose.pose.position = geometry_msgs.msg.Point(1.0, 2.0, 3.0)
        pose.pose.orientation.w = 1.0
        self.assertTrue(self.move_to(pose).success)
        position = self.camera_position(rospy.Time.now())
        for got, want in zip(position, (1.0, 2.0, 3.0)):
            self.assertAlmostEqual(got, want, places=6)

    def test_3_move_to_refuses_invalid_requests_and_keeps_the_camera(self):
        bad = [MoveCameraRequest(mode=7),
               MoveCameraRequest(mode=MoveCameraRequest.MODE_DIRECTION, distance=0.6),
               MoveCameraRequest(mode=MoveCameraRequest.MODE_DIRECTION, distance=-1.0,
                                 direction=geometry_msgs.msg.Vector3(1, 0, 0)),
               MoveCameraRequest(mode=MoveCameraRequest.MODE_DIRECTION, distance=0.6,
                                 direction=geometry_msgs.msg.Vector3(float("nan"), 0, 0)),
               MoveCameraRequest(mode=MoveCameraRequest.MODE_POSE)]  # zero quaternion
        before = self.camera_position(rospy.Time.now())
        for request in bad:
            response = self.move_to(request)
            self.assertFalse(response.success)
            self.assertTrue(response.message)
        after = self.camera_position(rospy.Time.now())
        for got, want in zip(after, before):
            self.assertAlmostEqual(got, want, places=9)

    def cloud_after(self, after):
        """The first cloud stamped after `after` (a change shows from the next frame on)."""
        while True:
            cloud = rospy.wait_for_message(CAMERA + "/cloud", sensor_msgs.msg.PointCloud2, 30)
            if cloud.header.stamp > after:
                return cloud

    def test_4_place_part_takes_the_mug_away_and_puts_it_elsewhere(self):
        look = MoveCameraRequest(mode=MoveCameraRequest.MODE_DIRECTION, distance=0.6)
        look.direction = geometry_msgs.msg.Vector3(1, 0, 0.5)
        self.assertTrue(self.move_to(look).success)
        away = self.place_part(PlacePartRequest(part=0, present=False))
        self.assertTrue(away.success, away.message)
        # No table in this scene: with the mug gone the camera sees nothing at all.
        self.assertEqual(finite_points(self.cloud_after(rospy.Time.now())), [])

        back = PlacePartRequest(part=0, present=True)
        back.pose.position = geometry_msgs.msg.Point(0.4, 0.0, 0.3)  # 10 cm along y
        back.pose.orientation.w = 1.0
        self.assertTrue(self.place_part(back).success)
        # The camera still looks at the old place (the mug 10 cm to its side) ...
        self.assertGreater(len(finite_points(self.cloud_after(rospy.Time.now()))), 100)
        # ... and the ground-truth tf is the new pose.
        deadline = rospy.Time.now() + rospy.Duration(10)
        while rospy.Time.now() < deadline:
            t = self.tf_buffer.lookup_transform("world", "object_ground_truth", rospy.Time(0))
            if abs(t.transform.translation.y) < 1e-9:
                break
            rospy.sleep(0.05)
        self.assertAlmostEqual(t.transform.translation.y, 0.0, places=9)

    def test_5_place_part_refuses_invalid_requests_and_keeps_the_scene(self):
        no_such_part = PlacePartRequest(part=1, present=False)  # this scene has no distractor
        not_finite = PlacePartRequest(part=0, present=True)
        not_finite.pose.position.x = float("nan")
        not_finite.pose.orientation.w = 1.0
        zero_quaternion = PlacePartRequest(part=0, present=True)
        for request in (no_such_part, not_finite, zero_quaternion):
            response = self.place_part(request)
            self.assertFalse(response.success)
            self.assertTrue(response.message)
        self.assertIn("No part 1", self.place_part(no_such_part).message)
        # The mug is still where test 4 put it, and still in view.
        self.assertGreater(len(finite_points(self.cloud_after(rospy.Time.now()))), 100)


if __name__ == "__main__":
    rostest.rosrun("view_direction_classification", "simulated_camera", SimulatedCamera)
