#!/usr/bin/python3
"""A nav_att member whose step 300 takes 3 s, twice run.member_timeout_s (tests/integration/external/python_member_test.cpp)."""
import sys
import time

import gdnav_client as g

m = g.Member.from_args(sys.argv, "nav_att")
imu = m.input("gdnav/ImuSample")
att = m.output("gdnav/AttitudeEstimate")


def step(k, t_s):
    if imu.available():
        att["q_nb"] = imu["align_q_nb"]
    if k == 300:
        time.sleep(3.0)


m.on_step(step)
sys.exit(m.run())
