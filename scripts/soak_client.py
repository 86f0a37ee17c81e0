#!/usr/bin/python3
"""The soak's driver (scripts/soak.sh starts the nodes, then this): moves the simulated camera
round the object, sends the server its requests (every fifth one malformed), samples each node's
resident memory once a second from /proc and prints the summary. Exit 1 if a node died, a
request went unanswered or was answered wrongly (a malformed one accepted, a good one refused)."""
import argparse
import csv
import math
import sys
import threading
import time

import geometry_msgs.msg
import rospy
from diagnostic_msgs.msg import DiagnosticArray
from soak_processes import rss_kib, wait_for_pid
from view_direction_classification.srv import (GetHeatmap, GetHeatmapRequest, GetNextBestView,
                                               GetNextBestViewRequest, MoveCamera,
                                               MoveCameraRequest)

NODES = ["simulated_depth_camera", "orientation_estimator", "informativeness_server"]


def malformed_request(index):
    """The index-th malformed request, cycling over six kinds the server must refuse."""
    kind = index % 6
    if kind == 0:
        return "heatmap: view index out of range", GetHeatmapRequest(
            mode=GetHeatmapRequest.MODE_VIEW_INDEX, view_index=100000)
    if kind == 1:
        return "heatmap: unknown mode", GetHeatmapRequest(mode=7)
    if kind == 2:
        return "heatmap: unknown scaling", GetHeatmapRequest(
            mode=GetHeatmapRequest.MODE_GLOBAL, scaling="loudest")
    if kind == 3:
        return "next_best_view: no candidates, no sampling", GetNextBestViewRequest(
            utility="information_gain", sample_count=0)
    if kind == 4:
        return "next_best_view: unknown utility", GetNextBestViewRequest(
            utility="bogus", sample_count=20, sample_distance=0.6)
    request = GetNextBestViewRequest(utility="informativeness")
    request.candidates.header.frame_id = "world"
    pose = geometry_msgs.msg.Pose()
    pose.position.x = 0.6
    pose.orientation.w = 2.0  # not a unit quaternion
    request.candidates.poses = [pose]
    return "next_best_view: non-unit candidate orientation", request


def good_request(index, samples):
    if index % 2 == 0:
        return "next_best_view", GetNextBestViewRequest(
            utility="information_gain" if index % 4 == 0 else "informativeness",
            sample_count=samples, sample_distance=0.6)
    if index % 3 == 0:
        return "heatmap", GetHeatmapRequest(mode=GetHeatmapRequest.MODE_GLOBAL)
    direction = geometry_msgs.msg.Vector3(x=math.cos(index), y=math.sin(index), z=0.5)
    return "heatmap", GetHeatmapRequest(mode=GetHeatmapRequest.MODE_DIRECTION,
                                        direction=direction)


class Soak:
    def __init__(self, args):
        self.args = args
        self.stop = threading.Event()
        self.lock = threading.Lock()
        self.diagnostics = {}
        self.requests = {"sent": 0, "answered": 0, "good ok": 0, "malformed refused": 0,
                         "wrong": 0, "unanswered": 0}
        self.wrong_examples = []
        self.request_seconds = 0.0
        self.latencies = []
        self.moves = 0
        self.samples = []  # (t, node, rss KiB)
        self.pids = {name: wait_for_pid("/soak", name) for name in NODES}
        self.dead = set()
        rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diagnostics)

    def on_diagnostics(self, msg):
        for status in msg.status:
            if "orientation estimate" in status.name:
                with self.lock:
                    self.diagnostics = {kv.key: kv.value for kv in status.values}

    def move_camera(self):
        """Round the object at 20 deg/s, the elevation swinging between 10 and 60 deg: small
        steps at 10 Hz, so the estimator's camera-speed check lets the clouds through."""
        rospy.wait_for_service("simulated_depth_camera/move_to", timeout=60)
        move = rospy.ServiceProxy("simulated_depth_camera/move_to", MoveCamera, persistent=True)
        start = time.monotonic()
        while not self.stop.is_set():
            t = time.monotonic() - start
            azimuth = math.radians(20.0 * t)
            elevation = math.radians(35.0 + 25.0 * math.sin(2 * math.pi * t / 60.0))
            request = MoveCameraRequest(mode=MoveCameraRequest.MODE_DIRECTION, distance=0.6)
            request.direction.x = math.cos(elevation) * math.cos(azimuth)
            request.direction.y = math.cos(elevation) * math.sin(azimuth)
            request.direction.z = math.sin(elevation)
            try:
                if move(request).success:
                    self.moves += 1
            except (rospy.ServiceException, rospy.ROSException):
                move = rospy.ServiceProxy("simulated_depth_camera/move_to", MoveCamera,
                                          persistent=True)
            self.stop.wait(0.1)

    def send_requests(self):
        rospy.wait_for_service("informativeness_server/next_best_view", timeout=60)
        rospy.wait_for_service("informativeness_server/get_heatmap", timeout=60)
        services = {GetHeatmapRequest: ("informativeness_server/get_heatmap", GetHeatmap),
                    GetNextBestViewRequest: ("informativeness_server/next_best_view",
                                             GetNextBestView)}
        proxies = {kind: rospy.ServiceProxy(name, service, persistent=True)
                   for kind, (name, service) in services.items()}
        start = time.monotonic()
        for index in range(self.args.requests):
            if rospy.is_shutdown():
                break
            # Spread over the stream's duration (the server works throughout), and back to back
            # if it is slower than that pace.
            wait = start + index * self.args.seconds / self.args.requests - time.monotonic()
            if wait > 0:
                time.sleep(wait)
            malformed = index % 5 == 4
            what, request = (malformed_request(index // 5) if malformed
                             else good_request(index, self.args.samples))
            self.requests["sent"] += 1
            try:
                sent = time.monotonic()
                response = proxies[type(request)](request)
                self.latencies.append(time.monotonic() - sent)
            except (rospy.ServiceException, rospy.ROSException) as error:
                self.requests["unanswered"] += 1
                self.wrong_examples.append("%d %s: no answer (%s)" % (index, what, error))
                # A persistent connection is gone after a failure: open a new one.
                name, service = services[type(request)]
                proxies[type(request)] = rospy.ServiceProxy(name, service, persistent=True)
                continue
            self.requests["answered"] += 1
            if malformed and not response.success:
                self.requests["malformed refused"] += 1
            elif not malformed and response.success:
                self.requests["good ok"] += 1
            else:
                self.requests["wrong"] += 1
                self.wrong_examples.append("%d %s: success=%s %s" % (
                    index, what, response.success, response.message))
        self.request_seconds = time.monotonic() - start

    def sample_memory(self, out):
        start = time.monotonic()
        with open(out, "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(["seconds", "node", "rss_kib"])
            while not self.stop.is_set():
                t = time.monotonic() - start
                for name, pid in self.pids.items():
                    rss = rss_kib(pid)
                    if rss is None:
                        self.dead.add(name)
                        continue
                    self.samples.append((t, name, rss))
                    writer.writerow(["%.1f" % t, name, rss])
                f.flush()
                self.stop.wait(1.0)

    def run(self):
        start = time.monotonic()
        threads = [threading.Thread(target=self.sample_memory, args=(self.args.rss_csv,)),
                   threading.Thread(target=self.move_camera)]
        for thread in threads:
            thread.start()
        requests = threading.Thread(target=self.send_requests)
        requests.start()
        # The stream runs for the set duration, and on until every request was answered.
        while time.monotonic() - start < self.args.seconds and not rospy.is_shutdown():
            time.sleep(1.0)
        requests.join()
        self.elapsed = time.monotonic() - start
        time.sleep(2.0)  # one more diagnostics message
        self.stop.set()
        for thread in threads:
            thread.join()
        return self.report()

    def report(self):
        print("== soak: %.0f s of stream, %d camera moves" % (self.elapsed, self.moves))
        print("resident memory [MiB]    after 60 s    peak     end    slope over the 2nd half "
              "[MiB/min]")
        for name in NODES:
            rows = [(t, rss) for t, n, rss in self.samples if n == name]
            if not rows:
                print("%-24s no samples" % name)
                continue
            warm = next((rss for t, rss in rows if t >= 60.0), rows[-1][1])
            half = [(t, rss) for t, rss in rows if t >= rows[-1][0] / 2]
            slope = 0.0
            if len(half) > 2:
                mt = sum(t for t, _ in half) / len(half)
                mr = sum(r for _, r in half) / len(half)
                var = sum((t - mt) ** 2 for t, _ in half)
                slope = sum((t - mt) * (r - mr) for t, r in half) / var * 60.0 if var else 0.0
            print("%-24s %10.1f %8.1f %7.1f %12.2f" % (
                name, warm / 1024, max(r for _, r in rows) / 1024, rows[-1][1] / 1024,
                slope / 1024))
        r = self.requests
        rate = r["answered"] / self.request_seconds if self.request_seconds else 0.0
        print("requests: %d sent, %d answered in %.0f s (%.1f per second): %d good ones served, "
              "%d malformed ones refused, %d answered wrongly, %d unanswered" % (
                  r["sent"], r["answered"], self.request_seconds, rate, r["good ok"],
                  r["malformed refused"], r["wrong"], r["unanswered"]))
        if self.latencies:
            latencies = sorted(self.latencies)
            mean = sum(latencies) / len(latencies)
            print("request latency: mean %.1f ms, 99th percentile %.1f ms, max %.1f ms (one client: "
                  "%.0f requests per second back to back)" % (
                      1e3 * mean, 1e3 * latencies[int(0.99 * (len(latencies) - 1))],
                      1e3 * latencies[-1], 1.0 / mean if mean else 0.0))
        for example in self.wrong_examples[:5]:
            print("  " + example)
        with self.lock:
            d = dict(self.diagnostics)
        received = d.get("clouds received", "?")
        print("estimator: clouds received %s (%.1f per second), fused %s, not novel %s, "
              "dropped %s, skipped %s; views fused in the belief %s" % (
                  received, float(received) / self.elapsed if received != "?" else 0.0,
                  d.get("clouds fused (new views)", "?"),
                  d.get("clouds not novel (a view already fused)", "?"),
                  d.get("clouds dropped (a newer one arrived first)", "?"),
                  d.get("clouds skipped (bad input or no tf)", "?"),
                  d.get("views fused in the belief", "?")))
        print("crashes: %d%s" % (len(self.dead), (" (" + ", ".join(sorted(self.dead)) + ")")
                                 if self.dead else ""))
        ok = not self.dead and r["wrong"] == 0 and r["unanswered"] == 0 and \
            r["answered"] == self.args.requests
        return 0 if ok else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seconds", type=float, default=600.0)
    parser.add_argument("--requests", type=int, default=10000)
    parser.add_argument("--samples", type=int, default=50, help="candidates per next best view")
    parser.add_argument("--rss-csv", default="soak_rss.csv")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("soak", disable_signals=True)
    sys.exit(Soak(args).run())


if __name__ == "__main__":
    main()
