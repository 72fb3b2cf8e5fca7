#!/usr/bin/env python3
"""Standard CRTK against the Raven-II twin with nothing but rospy: enable, home, move_jp,
servo_cp 2 mm up, open and close the jaw, read measured_cf.

    source scripts/ros-env.sh            # the build tree's crtk_msgs on PYTHONPATH
    roscore &  ./build/twin/ros/raven_twin_node &
    /usr/bin/python3 docs/examples/standard_crtk.py /crtk/arm1

tests/bridge_ros/standard_crtk_test.py runs it against a node.
"""

import sys
import threading

import rospy
from crtk_msgs.msg import OperatingState, StringStamped
from geometry_msgs.msg import PoseStamped, WrenchStamped
from sensor_msgs.msg import JointState

STATE = {"operating_state": OperatingState, "measured_js": JointState,
         "setpoint_js": JointState, "setpoint_cp": PoseStamped,
         "measured_cf": WrenchStamped, "jaw/measured_js": JointState}
COMMANDS = {"state_command": StringStamped, "move_jp": JointState, "servo_cp": PoseStamped,
            "jaw/move_jp": JointState}


class Arm:
    """One CRTK device: its latest state messages, its command topics, waits on its state."""

    def __init__(self, ns):
        self.latest, self.busy_since, self.changed = {}, rospy.Time(0), threading.Condition()
        for name, kind in STATE.items():
            rospy.Subscriber(f"{ns}/{name}", kind, self._received, name)
        self.send = {name: rospy.Publisher(f"{ns}/{name}", kind, queue_size=10)
                     for name, kind in COMMANDS.items()}
        self.wait(lambda: len(self.latest) == len(STATE) and
                  all(p.get_num_connections() for p in self.send.values()))

    def _received(self, message, name):
        with self.changed:
            self.latest[name] = message
            if name == "operating_state" and message.is_busy:
                self.busy_since = message.header.stamp
            self.changed.notify_all()

    def wait(self, condition, timeout=60.0):
        with self.changed:
            if not self.changed.wait_for(condition, timeout):
                raise TimeoutError("the robot did not get there")

    def state(self):
        return self.latest["operating_state"]

    def run(self, topic, message, done=lambda state: True):
        """A command that keeps the arm busy (home, move_*): busy rises after it is sent (its
        stamp says so) and falls when the arm is there."""
        sent = rospy.Time.now()
        self.send[topic].publish(message)
        self.wait(lambda: self.busy_since > sent and not self.state().is_busy and
                  done(self.state()))


def session(ns):
    arm = Arm(ns)
    arm.send["state_command"].publish(StringStamped(string="enable"))
    arm.wait(lambda: arm.state().state == "ENABLED")
    arm.run("state_command", StringStamped(string="home"), lambda state: state.is_homed)

    goal = list(arm.latest["setpoint_js"].position)
    goal[0] += 0.1  # shoulder, rad
    arm.run("move_jp", JointState(position=goal))

    pose = arm.latest["setpoint_cp"]
    pose.pose.position.z += 0.002  # 2 mm up, in the arm's base frame
    arm.send["servo_cp"].publish(pose)

    for opening in (0.8, 0.1):  # jaw1 + jaw2, rad: open, then close
        arm.run("jaw/move_jp", JointState(position=[opening]))

    force = arm.latest["measured_cf"].wrench.force
    print(f"{ns}: jaw at {arm.latest['jaw/measured_js'].position[0]:.3f} rad, "
          f"grasp force ({force.x:.3f}, {force.y:.3f}, {force.z:.3f}) N")


if __name__ == "__main__":
    rospy.init_node("standard_crtk_example", anonymous=True)
    session(sys.argv[1] if len(sys.argv) > 1 else "/crtk/arm1")
