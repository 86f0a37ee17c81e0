#!/usr/bin/python3
"""Asks the informativeness server where to look next and prints the answer (README, "Your
object, your camera"). Run it beside estimator.launch and informativeness_server.launch (or
demo.launch):

    rosrun view_direction_classification next_best_view_client.py _utility:=information_gain

Private parameters: ~utility (information_gain or informativeness), ~sample_count and
~sample_distance [m] (candidate poses sampled around the object by the server).
"""
import sys

import rospy
from view_direction_classification.srv import GetNextBestView, GetNextBestViewRequest

SERVICE = "informativeness_server/next_best_view"


def main():
    rospy.init_node("next_best_view_client")
    rospy.wait_for_service(SERVICE, timeout=30.0)
    next_best_view = rospy.ServiceProxy(SERVICE, GetNextBestView)

    # No candidates given: the server samples them around the object. The belief is the
    # estimator's latest ~estimate, which the server tracks (use_belief=False).
    request = GetNextBestViewRequest(utility=rospy.get_param("~utility", "information_gain"),
                                     sample_count=rospy.get_param("~sample_count", 50),
                                     sample_distance=rospy.get_param("~sample_distance", 0.6))
    response = next_best_view(request)
    if not response.success:
        rospy.logerr("next_best_view refused the request: %s", response.message)
        return 1

    p = response.best.pose.position
    q = response.best.pose.orientation
    print("best of %d candidates (utility %s = %.3f): camera at (%.3f, %.3f, %.3f) in %s, "
          "optical-frame orientation (x y z w) (%.3f, %.3f, %.3f, %.3f)"
          % (len(response.ranked.poses), request.utility, response.utilities[0], p.x, p.y, p.z,
             response.best.header.frame_id, q.x, q.y, q.z, q.w))
    print("server: %s" % response.message)
    return 0


if __name__ == "__main__":
    sys.exit(main())
