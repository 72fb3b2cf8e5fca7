#!/usr/bin/env python3
"""The twin node's standard CRTK face, driven as a standard CRTK client drives a robot.

Written from CRTK's own specification (../shared/reference/crtk.md: names, message types, the
operating state machine, is_busy during move and home) over a real rosmaster, with rospy: wait
for operating_state, enable, home (is_homed, busy up and down), measured_js, servo_jp, move_jp,
servo_cp, the jaw, measured_cf, query_cp / query_jp, a refused command, and lock-step.

Usage: standard_crtk_test.py <raven_twin_node>; PYTHONPATH must hold the build tree's python/.
"""

import math
import os
import subprocess
import sys
import threading
import time
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from ros_processes import RosMaster, TwinNode  # noqa: E402

NODE = sys.argv.pop(1) if len(sys.argv) > 1 else ""


class Latest:
    """A topic's latest message, and every one since `messages` was last cleared."""

    def __init__(self, rospy, topic, message_type, changed):
        self.last = None
        self.messages = []
        self.changed = changed
        self.subscriber = rospy.Subscriber(topic, message_type, self._received, queue_size=100)

    def _received(self, message):
        with self.changed:
            self.last = message
            self.messages.append(message)
            self.changed.notify_all()


class CrtkArm:
    """One arm's CRTK namespace, as crtk.md says a standard client sees it."""

    def __init__(self, rospy, ns):
        from crtk_msgs.msg import OperatingState, StringStamped
        from geometry_msgs.msg import PoseStamped, TwistStamped, WrenchStamped
        from sensor_msgs.msg import JointState

        self.rospy = rospy
        self.changed = threading.Condition()
        # Attributes by topic name ("jaw/measured_js" as jaw_measured_js).
        for name, kind in (("operating_state", OperatingState), ("measured_js", JointState),
                           ("setpoint_js", JointState), ("measured_cp", PoseStamped),
                           ("setpoint_cp", PoseStamped), ("measured_cv", TwistStamped),
                           ("measured_cf", WrenchStamped), ("jaw/measured_js", JointState)):
            setattr(self, name.replace("/", "_"), Latest(rospy, f"{ns}/{name}", kind, self.changed))
        for name, kind in (("state_command", StringStamped), ("servo_jp", JointState),
                           ("servo_cp", PoseStamped), ("move_jp", JointState),
                           ("move_cp", PoseStamped), ("jaw/move_jp", JointState)):
            setattr(self, name.replace("/", "_"),
                    rospy.Publisher(f"{ns}/{name}", kind, queue_size=10,
                                    latch=(name == "state_command")))
        self.ns = ns

    def wait(self, condition, what, timeout=20.0):
        """Waits for a message that makes `condition()` true (a Condition, not a sleep)."""
        deadline = time.monotonic() + timeout
        with self.changed:
            while not condition():
                left = deadline - time.monotonic()
                if left <= 0:
                    raise AssertionError(f"{self.ns}: timed out waiting for {what}")
                self.changed.wait(left)

    def send_state(self, command):
        from crtk_msgs.msg import StringStamped
        self.state_command.publish(StringStamped(string=command))

    def fresh(self, topic):
        """A message of `topic` published after this call (each topic comes in order, but not
        the topics among themselves: an older message may still be in flight)."""
        asked = self.rospy.Time.now()
        self.wait(lambda: topic.last is not None and topic.last.header.stamp > asked,
                  "a fresh message")
        return topic.last

    def joints(self, topic):
        return list(self.fresh(topic).position)


def joint_state(position):
    from sensor_msgs.msg import JointState
    return JointState(position=list(position))


MASTER = None


def setUpModule():
    global MASTER
    if not NODE:
        raise unittest.SkipTest("no raven_twin_node given")
    MASTER = RosMaster()
    import rospy
    rospy.init_node("standard_crtk_test", anonymous=True, disable_signals=True)


def tearDownModule():
    import rospy
    rospy.signal_shutdown("done")
    MASTER.stop()


class StandardCrtkFace(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        import rospy
        from std_msgs.msg import String
        cls.rospy = rospy
        # Ideal servos: the face's semantics are checked to tight tolerances; the robot's own
        # friction band (the node's default actuation) would leave joints a few mrad short.
        cls.node = TwinNode(NODE, MASTER.dir.name, "/s1", "--crtk-arms", "PSM1", "PSM2",
                            "--actuation", "ideal")
        cls.arm = CrtkArm(rospy, "/s1/crtk/PSM1")
        cls.other = CrtkArm(rospy, "/s1/crtk/PSM2")
        cls.refusals = Latest(rospy, "/s1/raven_twin/refusals", String, cls.arm.changed)

    @classmethod
    def tearDownClass(cls):
        cls.node.stop()

    def test_a_standard_client_session(self):
        arm = self.arm
        # operating_state: latched, so it arrives without any command.
        arm.wait(lambda: arm.operating_state.last is not None, "operating_state (latched)")
        self.assertEqual(arm.operating_state.last.state, "DISABLED")

        # enable, then home: is_homed, with is_busy up while homing and down at the end.
        for peer in (arm.state_command,):
            arm.wait(lambda: peer.get_num_connections() > 0, "the node on state_command")
        arm.send_state("enable")
        arm.wait(lambda: arm.operating_state.last.state == "ENABLED", "ENABLED")
        arm.operating_state.messages.clear()
        arm.send_state("home")
        arm.wait(lambda: arm.operating_state.last.is_homed and not arm.operating_state.last.is_busy,
                 "homed and idle", timeout=60)
        busy = [m.is_busy for m in arm.operating_state.messages]
        self.assertIn(True, busy, "is_busy never rose while homing")
        self.assertFalse(busy[-1])

        # measured_js: the robot's 7 joints of this arm.
        start = arm.joints(arm.measured_js)
        self.assertEqual(len(start), 7)

        # Published on change, not every cycle: nothing new while the arm is idle.
        arm.operating_state.messages.clear()
        other_start = self.other.joints(self.other.measured_js)

        # servo_jp +0.02 rad on joint 0 moves this arm's measured_js by 0.02 rad (within 0.001).
        goal = arm.joints(arm.setpoint_js)
        goal[0] += 0.02
        arm.servo_jp.publish(joint_state(goal))
        arm.wait(lambda: abs(arm.measured_js.last.position[0] - goal[0]) < 0.001,
                 "measured_js at the servo_jp goal")
        self.assertAlmostEqual(arm.measured_js.last.position[0] - start[0], 0.02, delta=0.001)
        other_now = self.other.joints(self.other.measured_js)
        self.assertAlmostEqual(other_now[0], other_start[0], delta=1e-3,
                               msg="the other arm moved: state and command are not one arm")
        self.assertEqual(arm.operating_state.messages, [], "operating_state sent while idle")

        # move_jp: busy (stamped after the command), then idle at the goal.
        goal = arm.joints(arm.setpoint_js)
        goal[0] -= 0.1
        goal[1] += 0.05
        sent = self.rospy.Time.now()
        arm.move_jp.publish(joint_state(goal))
        arm.wait(lambda: any(m.is_busy and m.header.stamp > sent
                             for m in arm.operating_state.messages), "busy after move_jp")

        def tool_speed():
            v = arm.measured_cv.last.twist.linear if arm.measured_cv.last else None
            return math.sqrt(v.x ** 2 + v.y ** 2 + v.z ** 2) if v else 0.0

        arm.wait(lambda: tool_speed() > 0.005, "measured_cv: the tool moving")
        arm.wait(lambda: not arm.operating_state.last.is_busy, "idle after move_jp")
        arrived = arm.joints(arm.setpoint_js)
        for joint in range(7):
            self.assertAlmostEqual(arrived[joint], goal[joint], delta=1e-6)
        arm.wait(lambda: abs(arm.measured_js.last.position[0] - goal[0]) < 0.001,
                 "measured_js at the move_jp goal")

        # servo_cp +2 mm in z moves measured_cp by 2 mm (within 0.1 mm).
        before = arm.fresh(arm.measured_cp).pose.position
        command = arm.fresh(arm.setpoint_cp)
        command.pose.position.z += 0.002
        arm.servo_cp.publish(command)

        def moved_2mm():
            now = arm.measured_cp.last.pose.position
            return (abs(now.z - before.z - 0.002) < 1e-4 and abs(now.x - before.x) < 1e-4 and
                    abs(now.y - before.y) < 1e-4)

        arm.wait(moved_2mm, "measured_cp 2 mm higher")

        # move_cp 1 cm along x and y (crtk_python_client's example): busy, then idle with the
        # setpoint on the goal, orientation kept.
        goal = arm.fresh(arm.setpoint_cp)
        goal.pose.position.x += 0.01
        goal.pose.position.y += 0.01
        sent = self.rospy.Time.now()
        arm.move_cp.publish(goal)
        arm.wait(lambda: any(m.is_busy and m.header.stamp > sent
                             for m in arm.operating_state.messages), "busy after move_cp")
        arm.wait(lambda: not arm.operating_state.last.is_busy, "idle after move_cp")
        there = arm.fresh(arm.setpoint_cp).pose
        for axis in "xyz":
            self.assertAlmostEqual(getattr(there.position, axis),
                                   getattr(goal.pose.position, axis), delta=1e-6)
        q, g = there.orientation, goal.pose.orientation
        self.assertAlmostEqual(abs(q.x * g.x + q.y * g.y + q.z * g.z + q.w * g.w), 1.0, delta=1e-9)

        # The jaw: move_jp opens it, then closes it; jaw/measured_js follows.
        for opening in (0.9, 0.2):
            sent = self.rospy.Time.now()
            arm.jaw_move_jp.publish(joint_state([opening]))
            arm.wait(lambda: any(m.is_busy and m.header.stamp > sent
                                 for m in arm.operating_state.messages), "busy after jaw move")
            arm.wait(lambda: not arm.operating_state.last.is_busy, "idle after jaw move")
            arm.wait(lambda: abs(arm.jaw_measured_js.last.position[0] - opening) < 0.01,
                     f"jaw/measured_js at {opening}")

        # measured_cf arrives, finite.
        arm.wait(lambda: arm.measured_cf.last is not None, "measured_cf")
        force = arm.measured_cf.last.wrench.force
        self.assertTrue(all(math.isfinite(v) for v in (force.x, force.y, force.z)))

        # A refused command: named, published, and nothing moves.
        self.refusals.messages.clear()
        held = arm.joints(arm.setpoint_js)
        arm.servo_jp.publish(joint_state([float("nan")] + held[1:]))
        arm.wait(lambda: self.refusals.last is not None, "the refusal")
        self.assertIn("crtk/PSM1/servo_jp", self.refusals.last.data)
        self.assertIn("position[0]", self.refusals.last.data)
        self.assertEqual(arm.joints(arm.setpoint_js), held)

    def test_query_cp_and_query_jp_are_the_arms_kinematics(self):
        from crtk_msgs.srv import QueryForwardKinematics, QueryInverseKinematics
        arm = self.arm
        for name in ("query_cp", "query_jp"):
            self.rospy.wait_for_service(f"{arm.ns}/{name}", timeout=30)
        forward = self.rospy.ServiceProxy(f"{arm.ns}/query_cp", QueryForwardKinematics)
        inverse = self.rospy.ServiceProxy(f"{arm.ns}/query_jp", QueryInverseKinematics)
        arm.wait(lambda: arm.measured_cp.last is not None and arm.measured_js.last is not None,
                 "measured_cp and measured_js")
        # The same cycle's joints and pose: setpoint_js with setpoint_cp, when both are from it.
        q = arm.joints(arm.setpoint_js)
        answer = forward(jp=q)
        self.assertTrue(answer.result, answer.message)
        fk = answer.cp.position
        nudged = list(q)
        nudged[0] += 0.05
        back = inverse(cp=forward(jp=nudged).cp, jp=q)
        self.assertTrue(back.result, back.message)
        for joint in range(5):
            self.assertAlmostEqual(back.jp[joint], nudged[joint], delta=1e-6)
        refused = forward(jp=[0.0, 1.0])
        self.assertFalse(refused.result)
        self.assertIn("jp has 2 values", refused.message)
        self.assertTrue(all(math.isfinite(v) for v in (fk.x, fk.y, fk.z)))


    def test_the_documented_example_runs(self):
        import importlib.util
        path = os.path.join(os.path.dirname(__file__), "..", "..", "docs", "examples",
                            "standard_crtk.py")
        spec = importlib.util.spec_from_file_location("standard_crtk_example", path)
        example = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(example)
        example.session("/s1/crtk/PSM2")
        jaw = self.other.fresh(self.other.jaw_measured_js).position[0]
        self.assertAlmostEqual(jaw, 0.1, delta=0.01)


class FaceOnTheRobotsTopics(unittest.TestCase):
    def test_arm_names_that_would_take_the_robots_topics_are_refused(self):
        run = subprocess.run([NODE, "__ns:=/s4", "--crtk-namespace", "", "--crtk-arms", "arm2",
                              "PSM2"], capture_output=True, text=True, timeout=120)
        self.assertEqual(run.returncode, 1)
        self.assertIn("arm 'arm2' would take the robot's own /arm2 topics", run.stdout + run.stderr)


class LockStepCrtk(unittest.TestCase):
    """A standard-CRTK command named in a lock-step step runs in that step, on the simulated clock."""

    def test_servo_jp_in_a_step(self):
        import rospy
        from raven_twin.msg import Step, StepDone
        from sensor_msgs.msg import JointState
        node = TwinNode(NODE, MASTER.dir.name, "/s2", "--lock-step", "--actuation", "ideal")
        try:
            arm = CrtkArm(rospy, "/s2/crtk/arm1")
            done = Latest(rospy, "/s2/raven_twin/step_done", StepDone, arm.changed)
            step = rospy.Publisher("/s2/raven_twin/step", Step, queue_size=10)
            arm.wait(lambda: step.get_num_connections() > 0 and
                     arm.servo_jp.get_num_connections() > 0 and
                     arm.state_command.get_num_connections() > 0 and
                     done.subscriber.get_num_connections() > 0, "the lock-step node")
            # Ids: the robot's 16 topics, then arm 1's CRTK commands in their order
            # (state_command 16, servo_jp 17, ...).
            seq = 0

            def run(cycles, order):
                """One step; returns once its answer and its last cycle's setpoint_js are in
                (ROS orders each topic, not the topics among themselves)."""
                nonlocal seq
                seq += 1
                step.publish(Step(seq=seq, cycles=cycles, command_order=order))
                arm.wait(lambda: done.last is not None and done.last.seq == seq, f"step {seq}")
                self.assertEqual(done.last.refused, "")
                arm.wait(lambda: arm.setpoint_js.last is not None and
                         arm.setpoint_js.last.header.stamp >= done.last.header.stamp,
                         f"setpoint_js of step {seq}")

            arm.send_state("enable")
            run(1, [16])
            arm.send_state("home")
            run(1, [16])
            for _ in range(30):
                if arm.operating_state.last.is_homed:
                    break
                run(1000, [])
            arm.wait(lambda: arm.operating_state.last.is_homed, "homed on the simulated clock")
            goal = list(arm.setpoint_js.last.position)
            goal[0] += 0.02
            arm.servo_jp.publish(JointState(position=goal))
            run(20, [17])
            # 0.02 rad at 0.0025 rad a cycle: there after 8 of the step's 20 cycles.
            self.assertAlmostEqual(arm.setpoint_js.last.position[0], goal[0], delta=1e-9)
            self.assertAlmostEqual(arm.setpoint_js.last.header.stamp.to_sec(),
                                   done.last.header.stamp.to_sec(), delta=1e-9)
        finally:
            node.stop()


if __name__ == "__main__":
    unittest.main(warnings="ignore")  # rospy leaves sockets to the collector
