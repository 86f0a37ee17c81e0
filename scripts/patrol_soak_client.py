#!/usr/bin/python3
"""The patrol soak's driver (scripts/soak.sh with SOAK_PATROL=1 starts the nodes, then this): the
simulated camera passes along an arc over a table with known objects and distractors, stops,
looks away, and between passes a person moves, turns, takes away or puts back objects
(simulated_depth_camera's ~place_part, seeded). After each pass it asks the estimator's memory
(~query_instances) and scores it against the truth; once a second it samples each node's
resident memory and CPU time from /proc, and the estimator's heap in use and held as its last
/diagnostics status gave them (a rise of the first is a leak, of resident memory alone the
allocator keeping freed pages). Prints the per-pass log and a summary; exit 1 if a node
died, a service failed, or the memory held more instances than --max-instances.

A part is given as NAME:MODEL:X,Y,YAW:LIFT (MODEL "-" for a distractor; X, Y [m] and YAW [rad]
on the table; LIFT [m]: its origin above the table top). Part 0 is the camera's object."""
import argparse
import csv
import math
import random
import sys
import threading
import time

import geometry_msgs.msg
import rospy
from diagnostic_msgs.msg import DiagnosticArray
from view_direction_classification.msg import ObjectInstance
from view_direction_classification.srv import (MoveCamera, MoveCameraRequest, PlacePart,
                                               PlacePartRequest, QueryInstances,
                                               QueryInstancesRequest)
from soak_processes import cpu_seconds, rss_kib, wait_for_pid

NODES = ["simulated_depth_camera", "orientation_estimator"]
RIGHT_DISTANCE = 0.02  # [m] an instance within this of its object, of its model, is right
SAME_PLACE = 0.05      # [m] instances this near an object are about that object


def rss_and_cpu(pid):
    """(VmRSS [KiB], CPU time [s]) of a process, None once it is gone."""
    rss, cpu = rss_kib(pid), cpu_seconds(pid)
    return None if rss is None or cpu is None else (rss, cpu)


def quaternion_of(columns):
    """Unit quaternion (x, y, z, w) of the rotation whose columns are the three vectors."""
    m = [[columns[c][r] for c in range(3)] for r in range(3)]
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        s = 2.0 * math.sqrt(trace + 1.0)
        return ((m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, s / 4)
    i = max(range(3), key=lambda k: m[k][k])
    j, k = (i + 1) % 3, (i + 2) % 3
    s = 2.0 * math.sqrt(1.0 + m[i][i] - m[j][j] - m[k][k])
    q = [0.0, 0.0, 0.0]
    q[i] = s / 4
    q[j] = (m[j][i] + m[i][j]) / s
    q[k] = (m[k][i] + m[i][k]) / s
    return (q[0], q[1], q[2], (m[k][j] - m[j][k]) / s)


def normalised(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def optical_pose(eye, forward, up=(0.0, 0.0, 1.0)):
    """The optical frame (z forward, x right, y down) at eye looking along forward."""
    z = normalised(forward)
    x = normalised(cross(z, up))
    y = cross(z, x)
    pose = geometry_msgs.msg.Pose()
    pose.position = geometry_msgs.msg.Point(*eye)
    pose.orientation = geometry_msgs.msg.Quaternion(*quaternion_of((x, y, z)))
    return pose


class Part:
    def __init__(self, index, spec, table_top):
        name, model, place, lift = spec.split(":")
        x, y, yaw = (float(v) for v in place.split(","))
        self.index, self.name = index, name
        self.model = None if model == "-" else model
        self.x, self.y, self.yaw, self.z = x, y, yaw, table_top + float(lift)
        self.present = True

    def pose(self):
        pose = geometry_msgs.msg.Pose()
        pose.position = geometry_msgs.msg.Point(self.x, self.y, self.z)
        pose.orientation.z, pose.orientation.w = math.sin(self.yaw / 2), math.cos(self.yaw / 2)
        return pose


class PatrolSoak:
    def __init__(self, args):
        self.args = args
        self.rng = random.Random(args.seed)
        self.parts = [Part(i, spec, args.table_top) for i, spec in enumerate(args.part)]
        self.stop = threading.Event()
        self.samples = []  # (t, node, rss KiB, cpu s, heap in use MiB or None)
        self.dead = set()
        self.failures = []
        self.passes = []
        self.objects_ever = sum(1 for p in self.parts if p.model)
        self.diagnostics = {}
        self.lock = threading.Lock()
        self.pids = {name: wait_for_pid("/patrol_soak", name) for name in NODES}
        rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diagnostics)
        rospy.wait_for_service("simulated_depth_camera/move_to", timeout=60)
        rospy.wait_for_service("simulated_depth_camera/place_part", timeout=60)
        rospy.wait_for_service("orientation_estimator/query_instances", timeout=120)
        self.move = rospy.ServiceProxy("simulated_depth_camera/move_to", MoveCamera)
        self.place = rospy.ServiceProxy("simulated_depth_camera/place_part", PlacePart)
        self.query = rospy.ServiceProxy("orientation_estimator/query_instances", QueryInstances)

    def on_diagnostics(self, msg):
        for status in msg.status:
            if "scene estimate" in status.name:
                with self.lock:
                    self.diagnostics = {kv.key: kv.value for kv in status.values}

    def call(self, proxy, request, what):
        try:
            response = proxy(request)
        except (rospy.ServiceException, rospy.ROSException) as error:
            self.failures.append("%s: %s" % (what, error))
            return None
        if hasattr(response, "success") and not response.success:
            self.failures.append("%s: %s" % (what, response.message))
        return response

    def camera_to(self, pose):
        self.call(self.move, MoveCameraRequest(mode=MoveCameraRequest.MODE_POSE, pose=pose),
                  "move_to")

    def pass_along_the_table(self):
        """An arc at the set distance and elevation round the table's centre, at 20 deg/s in
        steps of 10 Hz (slow enough for the estimator's camera-speed check), then a still look."""
        a = self.args
        arc = math.radians(a.arc_deg)
        elevation = math.radians(a.elevation_deg)
        start = self.rng.uniform(0.0, 2.0 * math.pi)
        steps = max(1, int(a.arc_deg / 2.0))  # 2 degrees a step
        for step in range(steps + 1):
            if self.stop.is_set() or rospy.is_shutdown():
                return
            azimuth = start + arc * step / steps
            eye = (a.distance * math.cos(elevation) * math.cos(azimuth),
                   a.distance * math.cos(elevation) * math.sin(azimuth),
                   a.table_top + a.distance * math.sin(elevation))
            self.camera_to(optical_pose(eye, (-eye[0], -eye[1], a.table_top - eye[2])))
            time.sleep(0.1)
        time.sleep(a.still_seconds)

    def look_away(self):
        eye = (0.0, 0.0, self.args.table_top + 1.5)
        self.camera_to(optical_pose(eye, (0.0, 0.0, 1.0), up=(1.0, 0.0, 0.0)))
        time.sleep(self.args.away_seconds)

    def free_spot(self, moving=None):
        """A place on the table at least 15 cm from every other present part."""
        for _ in range(200):
            x, y = self.rng.uniform(-0.25, 0.25), self.rng.uniform(-0.2, 0.2)
            if all(math.hypot(x - p.x, y - p.y) >= 0.15 for p in self.parts
                   if p.present and p is not moving):
                return x, y
        return None

    def change(self):
        """One random change: a part taken away is put back half the time; else a present part
        is taken away (a third of the time, while more than two are present) or moved and
        turned. Four in five changes are to a known object where there is one to change."""
        present = [p for p in self.parts if p.present]
        gone = [p for p in self.parts if not p.present]
        if gone and self.rng.random() < 0.5:
            kind, pool = "put back", gone
        elif len(present) > 2 and self.rng.random() < 1.0 / 3.0:
            kind, pool = "removed", present
        else:
            kind, pool = "moved", present
        known = [p for p in pool if p.model]
        part = self.rng.choice(known if known and self.rng.random() < 0.8 else pool)
        if kind == "removed":
            part.present = False
            self.call(self.place, PlacePartRequest(part=part.index, present=False), "place_part")
            return "%s removed" % part.name
        spot = self.free_spot(moving=part)
        if spot is None:
            return "no free spot for %s" % part.name
        part.x, part.y = spot
        part.yaw = self.rng.uniform(-math.pi, math.pi)
        part.present = True
        self.call(self.place, PlacePartRequest(part=part.index, present=True, pose=part.pose()),
                  "place_part")
        return "%s %s" % (part.name, kind)

    def score(self):
        """Right, duplicate and stale instances against the present known objects."""
        response = self.call(self.query, QueryInstancesRequest(include_gone=True),
                             "query_instances")
        if response is None:
            return None
        instances = [i for i in response.instances if i.state == ObjectInstance.PRESENT]
        truths = [p for p in self.parts if p.present and p.model]

        def distance(instance, part):
            q = instance.pose.pose.position
            return math.hypot(q.x - part.x, q.y - part.y, q.z - part.z)

        right, duplicates, stale, used = 0, 0, 0, set()
        for part in truths:
            near = [i for i in instances if i.model == part.model and distance(i, part) < SAME_PLACE]
            close = [i for i in near if distance(i, part) < RIGHT_DISTANCE and i.id not in used]
            if close:
                right += 1
                used.add(min(close, key=lambda i: distance(i, part)).id)
            duplicates += max(0, len(near) - 1)
        for instance in instances:
            if not any(instance.model == p.model and distance(instance, p) < SAME_PLACE
                       for p in truths):
                stale += 1
        return {"present": len(truths), "right": right, "duplicates": duplicates,
                "stale": stale, "instances": len(response.instances),
                "gone": len(response.instances) - len(instances)}

    def sample(self, out):
        start = time.monotonic()
        with open(out, "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(["seconds", "node", "rss_kib", "cpu_seconds", "heap_in_use_mib",
                             "heap_held_mib"])
            while not self.stop.is_set():
                t = time.monotonic() - start
                with self.lock:
                    heap = (self.diagnostics.get("heap in use [MiB]"),
                            self.diagnostics.get("heap held [MiB]"))
                for name, pid in self.pids.items():
                    got = rss_and_cpu(pid)
                    if got is None:
                        self.dead.add(name)
                        continue
                    node_heap = heap if name == "orientation_estimator" else (None, None)
                    in_use = float(node_heap[0]) if node_heap[0] else None
                    self.samples.append((t, name) + got + (in_use,))
                    writer.writerow(["%.1f" % t, name, got[0], "%.2f" % got[1]] +
                                    [v or "" for v in node_heap])
                f.flush()
                self.stop.wait(1.0)

    def run(self):
        sampler = threading.Thread(target=self.sample, args=(self.args.samples_csv,))
        sampler.start()
        start = time.monotonic()
        changes = []
        with open(self.args.passes_csv, "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(["pass", "seconds", "changes", "present", "right", "duplicates",
                             "stale", "instances", "gone"])
            number = 0
            while time.monotonic() - start < self.args.seconds and not rospy.is_shutdown() \
                    and not self.dead:
                number += 1
                self.pass_along_the_table()
                scores = self.score()
                if scores is not None:
                    self.passes.append(scores)
                    writer.writerow([number, "%.0f" % (time.monotonic() - start),
                                     "; ".join(changes)] +
                                    [scores[k] for k in ("present", "right", "duplicates",
                                                         "stale", "instances", "gone")])
                    f.flush()
                self.look_away()
                changes = [self.change() for _ in range(self.args.changes_per_pass)]
        self.elapsed = time.monotonic() - start
        self.stop.set()
        sampler.join()
        return self.report()

    def quarter_figures(self, name, quarter):
        """Mean RSS [MiB], CPU use [% of a core] and mean heap in use [MiB] (None where not
        reported) of a node over one quarter of the run."""
        rows = [(t, rss, cpu, heap) for t, n, rss, cpu, heap in self.samples if n == name]
        if len(rows) < 8:
            return None
        end = rows[-1][0]
        part = [r for r in rows if quarter * end / 4 <= r[0] <= (quarter + 1) * end / 4]
        if len(part) < 2:
            return None
        rss = sum(r[1] for r in part) / len(part) / 1024
        cpu = 100.0 * (part[-1][2] - part[0][2]) / (part[-1][0] - part[0][0])
        heaps = [r[3] for r in part if r[3] is not None]
        return rss, cpu, (sum(heaps) / len(heaps) if heaps else None)

    def report(self):
        n = len(self.passes)
        print("== patrol soak: %.0f s, %d passes, %d changes per pass" % (
            self.elapsed, n, self.args.changes_per_pass))
        print("per node, each quarter of the run: mean resident memory [MiB] / CPU [% of a core]"
              " / mean heap in use [MiB] (where the node reports it)")
        for name in NODES:
            figures = [self.quarter_figures(name, q) for q in range(4)]
            print("%-24s %s" % (name, "   ".join(
                ("%7.1f / %5.1f" % f[:2] + (" / %6.1f" % f[2] if f[2] is not None else ""))
                if f else "      -" for f in figures)))
        if n:
            total = lambda key: sum(p[key] for p in self.passes)
            print("after each pass, summed over the %d passes: present %d, right %d (%.1f %%), "
                  "duplicates %d, stale %d" % (
                      n, total("present"), total("right"),
                      100.0 * total("right") / max(1, total("present")), total("duplicates"),
                      total("stale")))
            most = max(p["instances"] for p in self.passes)
            print("instances remembered: at most %d (%d known objects in the scene), "
                  "at the end %d (%d gone)" % (most, self.objects_ever,
                                               self.passes[-1]["instances"],
                                               self.passes[-1]["gone"]))
        with self.lock:
            d = dict(self.diagnostics)
        print("estimator: clouds received %s, segmented %s, not segmented (camera still) %s, "
              "dropped %s, skipped %s" % tuple(d.get(k, "?") for k in (
                  "clouds received", "clouds segmented",
                  "clouds not segmented (the camera did not move)",
                  "clouds dropped (a newer one arrived first)",
                  "clouds skipped (bad input or no tf)")))
        for failure in self.failures[:5]:
            print("  service failure: " + failure)
        print("crashes: %d%s" % (len(self.dead), (" (" + ", ".join(sorted(self.dead)) + ")")
                                 if self.dead else ""))
        bounded = not self.passes or max(p["instances"] for p in self.passes) <= \
            self.args.max_instances
        if not bounded:
            print("memory not bounded: more than %d instances" % self.args.max_instances)
        return 0 if not self.dead and not self.failures and bounded else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seconds", type=float, default=3600.0)
    parser.add_argument("--part", action="append", required=True,
                        help="NAME:MODEL:X,Y,YAW:LIFT, part 0 first")
    parser.add_argument("--table-top", type=float, required=True, help="[m] in the fixed frame")
    parser.add_argument("--distance", type=float, default=0.8, help="[m] camera to table centre")
    parser.add_argument("--elevation-deg", type=float, default=45.0)
    parser.add_argument("--arc-deg", type=float, default=90.0)
    parser.add_argument("--still-seconds", type=float, default=2.0)
    parser.add_argument("--away-seconds", type=float, default=2.0)
    parser.add_argument("--changes-per-pass", type=int, default=2)
    parser.add_argument("--max-instances", type=int, default=20,
                        help="more instances remembered than this fails the soak")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--samples-csv", default="patrol_samples.csv")
    parser.add_argument("--passes-csv", default="patrol_passes.csv")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("patrol_soak", disable_signals=True)
    sys.exit(PatrolSoak(args).run())


if __name__ == "__main__":
    main()
