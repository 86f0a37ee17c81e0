"""What the soak drivers (soak_client.py, patrol_soak_client.py) read of the nodes' processes: a
node's pid from its XML-RPC API (what rosnode info prints), and its resident memory and CPU time
from /proc."""
import os
import time
import xmlrpc.client

import rosgraph

CLOCK_TICKS = os.sysconf("SC_CLK_TCK")


def node_pid(caller, name):
    """The process id of the running node /name, asked as caller (a node name)."""
    master = rosgraph.Master(caller)
    uri = master.lookupNode("/" + name)
    code, _, pid = xmlrpc.client.ServerProxy(uri).getPid(caller)
    if code != 1:
        raise RuntimeError("node /%s did not give its pid" % name)
    return int(pid)


def wait_for_pid(caller, name, timeout=120.0):
    """node_pid, retried once a second until the node is up (rosgraph.MasterError, OSError or
    RuntimeError after timeout seconds)."""
    deadline = time.monotonic() + timeout
    while True:
        try:
            return node_pid(caller, name)
        except (rosgraph.MasterError, OSError, RuntimeError):
            if time.monotonic() > deadline:
                raise
            time.sleep(1.0)


def rss_kib(pid):
    """VmRSS of a process in KiB, None once it is gone."""
    try:
        with open("/proc/%d/status" % pid) as status:
            for line in status:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
    except FileNotFoundError:
        return None
    return None


def cpu_seconds(pid):
    """User plus system CPU time of a process [s], None once it is gone."""
    try:
        with open("/proc/%d/stat" % pid) as stat:
            fields = stat.read().rsplit(")", 1)[1].split()
    except FileNotFoundError:
        return None
    return (int(fields[11]) + int(fields[12])) / CLOCK_TICKS
