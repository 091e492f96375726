#!/usr/bin/python3
"""Clock-less check of the gdnav_client bindings: ports, field access, conversions and the error messages (a bad
field names the topic and its fields, a wrong array size names the expected length and the shape, an unknown topic
names the known topics). Exit 0 and "bindings check: all passed" when every check holds."""
import sys

import numpy as np

import gdnav_client as g

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print(f"FAILED: {what}")


def raises(exc_type, fn, *needles):
    """fn() must raise exc_type whose message contains every needle."""
    try:
        fn()
    except exc_type as e:
        msg = str(e)
        print(f"  {exc_type.__name__}: {msg[:160]}{'...' if len(msg) > 160 else ''}")
        for n in needles:
            check(n in msg, f"{exc_type.__name__} message {msg!r} lacks {n!r}")
        return
    except Exception as e:  # noqa: BLE001 - reported as a failure
        check(False, f"expected {exc_type.__name__}, got {type(e).__name__}: {e}")
        return
    check(False, f"expected {exc_type.__name__}, nothing raised")


m = g.Member("nav_att", domain=231)
imu = m.input("gdnav/ImuSample")
pos = m.input("gdnav/PositionEstimate", lag=g.Lag.Previous)
att = m.output("gdnav/AttitudeEstimate")
pos_out = g.Member("other", domain=231).output("gdnav/PositionEstimate")

print("unknown topic:")
raises(ValueError, lambda: m.input("gdnav/Nope"), "unknown topic 'gdnav/Nope'", "gdnav/ImuSample", "gdnav/Truth")
raises(ValueError, lambda: m.output("Attitude"), "unknown topic 'Attitude'", "gdnav/AttitudeEstimate")

print("bad field:")
raises(KeyError, lambda: att["q"], "gdnav/AttitudeEstimate has no field 'q'", "q_nb (double[4])", "stamp.t_s (double)")
raises(KeyError, lambda: imu["f_b"], "gdnav/ImuSample has no field 'f_b'", "f_b_mps2 (double[3])")
raises(KeyError, lambda: att.__setitem__("qnb", [1, 0, 0, 0]), "no field 'qnb'", "q_nb (double[4])")
raises(KeyError, lambda: att.update({"q_nb": [1, 0, 0, 0], "eul": [0, 0, 0]}), "no field 'eul'")

print("wrong size or type:")
raises(ValueError, lambda: att.__setitem__("q_nb", np.zeros(3)), "field 'q_nb' of gdnav/AttitudeEstimate (double[4])",
       "expected 4 values, got shape (3,)")
raises(ValueError, lambda: att.__setitem__("euler_rad", np.zeros((3, 1))), "expected 3 values, got shape (3, 1)")
raises(TypeError, lambda: att.__setitem__("q_nb", "abcd"), "field 'q_nb'", "expected an array of 4 numbers")
raises(TypeError, lambda: pos_out.__setitem__("lat_rad", "x"), "field 'lat_rad'", "cannot assign a value of type str")
raises(ValueError, lambda: att.__setitem__("stamp.step", 3), "set by the host")

print("inputs outside a step and read-only inputs:")
raises(RuntimeError, lambda: imu["f_b_mps2"], "input gdnav/ImuSample can be read only inside the step callback")
raises(RuntimeError, lambda: imu.__setitem__("f_b_mps2", [0, 0, 0]), "read-only")
check(not imu.available() and not pos.available() and not imu.lost(), "inputs unavailable outside a step")
check(att.available() and att.is_output and not imu.is_output, "port kinds")

print("values:")
att["q_nb"] = [1, 0, 0, 0]                      # any sequence of the right length; ints convert
att.update({"euler_rad": np.array([0.1, 0.2, 0.3]), "w_nb_b_rps": (1e-3, 0.0, -1e-3)})
q = att["q_nb"]
check(isinstance(q, np.ndarray) and q.dtype == np.float64 and q.tolist() == [1.0, 0.0, 0.0, 0.0], f"q_nb {q!r}")
q[0] = 5.0                                      # a copy: the output keeps its value
check(att["q_nb"][0] == 1.0, "reading returns a copy")
d = att.as_dict()
check(d["euler_rad"].tolist() == [0.1, 0.2, 0.3] and d["stamp.step"] == 0, f"as_dict {d}")
pos_out["lat_rad"] = 1                          # int -> float
pos_out["gnss_denied"] = True
check(isinstance(pos_out["lat_rad"], float) and pos_out["lat_rad"] == 1.0, "scalar float")
check(pos_out["gnss_denied"] is True, "scalar bool")
check(("q_nb", "double[4]") in att.fields() and ("stamp.step", "unsigned long long") in att.fields(),
      f"fields {att.fields()}")
check(repr(imu) == "<input gdnav/ImuSample>" and imu.topic == "gdnav/ImuSample", repr(imu))

print("options:")
a = g.Member.from_args(["prog", "--domain", "7", "--run", "2", "--x-gain", "3"], "nav_att")
check((a.name, a.domain, a.run_id, a.free_running, a.extra_args) == ("nav_att", 7, 2, False, ["--x-gain", "3"]),
      "from_args")
raises(ValueError, lambda: g.Member.from_args(["prog", "--bogus"], "nav_att"), "unknown argument '--bogus'")
raises(ValueError, lambda: g.Member.from_args(["prog", "--domain", "999"], "nav_att"), "--domain 999")
raises(ValueError, lambda: g.Member("two words"), "member name 'two words'")
raises(ValueError, lambda: g.Member("clock"), "reserved")
check("on_step" in g.__doc__ and "Lag.Previous" in g.__doc__, "module docstring documents the API")

if failures:
    print(f"bindings check: {len(failures)} FAILED")
    sys.exit(1)
print("bindings check: all passed")
