"""ROS processes for Python tests: a private rosmaster on a free port (ROS_* pointed at it and at
a temp dir) and raven_twin_node in a namespace of its own, logging to a file, each stopped by its
PID."""

import os
import socket
import subprocess
import tempfile
import time


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class RosMaster:
    """A private rosmaster on a free port; ROS_* point at it and at a temp dir."""

    def __init__(self):
        self.dir = tempfile.TemporaryDirectory()
        port = free_port()
        os.environ.update(ROS_MASTER_URI=f"http://127.0.0.1:{port}", ROS_HOME=self.dir.name,
                          ROS_LOG_DIR=os.path.join(self.dir.name, "log"), ROS_IP="127.0.0.1")
        self.log = open(os.path.join(self.dir.name, "rosmaster.log"), "w")
        self.process = subprocess.Popen(
            ["/usr/bin/python3", "/usr/bin/rosmaster", "--core", "-p", str(port)],
            stdout=self.log, stderr=subprocess.STDOUT)
        deadline = time.monotonic() + 30
        while True:  # a child process coming up: nothing to wait on but its port
            with socket.socket() as s:
                if s.connect_ex(("127.0.0.1", port)) == 0:
                    break
            if time.monotonic() > deadline or self.process.poll() is not None:
                raise RuntimeError("rosmaster did not come up")
            time.sleep(0.05)

    def stop(self):
        self.process.terminate()
        self.process.wait(10)
        self.log.close()


class TwinNode:
    """The program `node` (raven_twin_node) in namespace `ns`, logging to a file in `directory`."""

    def __init__(self, node, directory, ns, *args):
        self.log_path = os.path.join(directory, ns.strip("/") + ".log")
        self.log = open(self.log_path, "w")
        self.process = subprocess.Popen([node, f"__ns:={ns}", "__name:=twin", *args],
                                        stdout=self.log, stderr=subprocess.STDOUT)

    def stop(self):
        self.process.send_signal(2)
        self.process.wait(20)
        self.log.close()

    def output(self):
        with open(self.log_path) as f:
            return f.read()
