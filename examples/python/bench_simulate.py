#!/usr/bin/env python3
"""Cost of simulating from Python compared with the C++ driver, and the overhead of a Python torque callback.

Not a test (no timing in tests). For each run: the wall time of the whole poinsot.simulate call seen from
Python, against the wall time the C++ driver measures inside dynamics::simulate (SimulationResult.wall_time_s:
the stepping loop and the sampling observer, i.e. what the same run costs from C++). The ratio is the price
of the Python layer (argument conversion, result arrays). Then the same rk4 run with a constant torque given
as a built-in TorqueModel and as a Python callable: the difference per step and per torque evaluation (rk4
evaluates the torque 4 times per step).

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/bench_simulate.py [--steps 1000000]
"""
import argparse
import time

import numpy as np

import poinsot


def best_of(n, fn):
    best = None
    for _ in range(n):
        t0 = time.perf_counter()
        r = fn()
        dt = time.perf_counter() - t0
        if best is None or dt < best[0]:
            best = (dt, r)
    return best


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--steps", type=int, default=1_000_000)
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    body = poinsot.RigidBody.from_principal_moments([0.00121, 0.01638, 0.01748])
    w0 = [0.05, 6.2832, 0.05]
    dt = 1e-4
    t_end = a.steps * dt
    print(f"free tennis racket, {a.steps} steps of {dt} s, a sample every 0.01 s ({int(t_end / 0.01) + 1} samples)")
    print(f"{'method':8} {'python call (s)':>16} {'C++ driver (s)':>15} {'ratio':>7} {'ns/step (C++)':>14}")
    for method in ("rk4", "dlm", "rattle"):
        wall, r = best_of(a.repeat, lambda: poinsot.simulate(body=body, omega_body=w0, method=method, dt=dt,
                                                             t_end=t_end, sample_dt=0.01))
        print(f"{method:8} {wall:16.4f} {r.wall_time_s:15.4f} {wall / r.wall_time_s:7.3f} "
              f"{r.wall_time_s / r.steps * 1e9:14.1f}")

    n_cb = max(a.steps // 10, 1000)
    tau = np.array([0.0, 0.0, 1e-3])
    kw = dict(body=body, omega_body=w0, method="rk4", dt=dt, t_end=n_cb * dt, sample_dt=0.01)
    w_builtin, r_builtin = best_of(a.repeat, lambda: poinsot.simulate(torque=poinsot.TorqueModel.constant_body(tau), **kw))
    w_cb, r_cb = best_of(a.repeat, lambda: poinsot.simulate(torque=lambda t, R, w: tau, **kw))
    per_step = (r_cb.wall_time_s - r_builtin.wall_time_s) / r_cb.steps
    print(f"\nrk4 with a constant torque, {r_cb.steps} steps: built-in {r_builtin.wall_time_s:.4f} s, "
          f"Python callback {r_cb.wall_time_s:.4f} s ({r_cb.wall_time_s / r_builtin.wall_time_s:.0f}x)")
    print(f"callback overhead: {per_step * 1e6:.2f} µs per step, {per_step / 4 * 1e6:.2f} µs per torque evaluation "
          f"(4 per rk4 step)")
    same = np.array_equal(r_builtin.R, r_cb.R)
    print(f"same trajectory with the callback as with the built-in torque: {same}")


if __name__ == "__main__":
    main()
