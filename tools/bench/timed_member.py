# The example's member class (examples/python/complementary_attitude.py) with its own step timed from inside Python:
# the calling thread's CPU time around each step, printed when the run ends as "timed_member: body X us per step".
# Its outputs are the example's. Used as an in-process member (python:tools/bench/timed_member.py:Timed) by
# tools/bench/python_inprocess_cost.sh and tools/bench/member_batch_speed.sh.
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "python"))
from complementary_attitude import ComplementaryAttitude  # noqa: E402


class Timed(ComplementaryAttitude):
    def __init__(self, m):
        super().__init__(m)
        self.ns, self.n = 0, 0

    def step(self, k, t_s):
        t0 = time.thread_time_ns()
        super().step(k, t_s)
        self.ns += time.thread_time_ns() - t0
        self.n += 1

    def finish(self, completed):
        print(f"timed_member: body {self.ns / max(self.n, 1) / 1000:.3f} us per step", flush=True)
