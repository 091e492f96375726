#!/usr/bin/python3
"""A nav_att member whose step callback raises at step 300 (tests/integration/external/python_member_test.cpp)."""
import sys

import gdnav_client as g

m = g.Member.from_args(sys.argv, "nav_att")
imu = m.input("gdnav/ImuSample")
att = m.output("gdnav/AttitudeEstimate")


def step(k, t_s):
    if imu.available():
        att["q_nb"] = imu["align_q_nb"]        # a valid attitude for nav_pos until the failure
    if k == 300:
        raise ZeroDivisionError(f"deliberate failure at step {k}")


m.on_step(step)
sys.exit(m.run())
