#!/usr/bin/env python3
"""crtk_msgs from the build tree is upstream's (1.3): the standard CRTK Python client imports
crtk_msgs.msg and crtk_msgs.srv, and a message's MD5 follows its text (reference/crtk.md)."""

import hashlib
import sys
import unittest

import crtk_msgs.msg
import crtk_msgs.srv


class UpstreamCrtkMsgs(unittest.TestCase):
    def test_every_upstream_message_and_service_is_there(self):
        for name in ("OperatingState", "StringStamped", "CartesianState", "CartesianServo",
                     "JointServo", "SetpointMode", "CartesianImpedance",
                     "CartesianImpedanceHalfPlaneGains"):
            self.assertTrue(hasattr(crtk_msgs.msg, name), name)
        for name in ("TriggerOperatingState", "QueryForwardKinematics", "QueryInverseKinematics"):
            self.assertTrue(hasattr(crtk_msgs.srv, name), name)

    def test_the_robots_old_operating_state_is_the_same_message(self):
        self.assertEqual(crtk_msgs.msg.OperatingState._md5sum,
                         crtk_msgs.msg.operating_state._md5sum)
        self.assertEqual(crtk_msgs.msg.OperatingState.__slots__,
                         ["header", "state", "is_homed", "is_busy"])

    def test_md5_follows_the_text_as_ros_computes_it(self):
        # ROS 1: md5 of the field lines "type name" (constants first), nested types by their md5.
        header = "2176decaecbce78abc3b96ef049fabed"  # std_msgs/Header
        text = f"{header} header\nstring state\nbool is_homed\nbool is_busy"
        self.assertEqual(crtk_msgs.msg.OperatingState._md5sum,
                         hashlib.md5(text.encode()).hexdigest())

    def test_services_carry_upstreams_fields(self):
        fk = crtk_msgs.srv.QueryForwardKinematicsRequest()
        self.assertEqual(fk.__slots__, ["jp", "cp"])
        ik = crtk_msgs.srv.QueryInverseKinematicsResponse()
        self.assertEqual(ik.__slots__, ["jp", "result", "message"])
        trigger = crtk_msgs.srv.TriggerOperatingStateResponse()
        self.assertIsInstance(trigger.operating_state, crtk_msgs.msg.OperatingState)
        self.assertEqual(len(crtk_msgs.msg.CartesianServo().axis_mode), 6)


if __name__ == "__main__":
    sys.exit(unittest.main())
