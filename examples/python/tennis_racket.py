#!/usr/bin/env python3
"""The tennis-racket demo from Python: the same scenario as `poinsot run examples/tennis_racket.toml`.

A racket (Brody's measured principal moments) spun mostly about its intermediate axis flips over again and
again. The script runs the scenario file, prints the flips beside the closed-form interval 2K(k)/ω_p, the
worst relative errors of the invariants, and compares the trajectory with the exact solution (Jacobi elliptic
functions). With --plot FILE it saves the body angular velocity against time (Matplotlib).

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/tennis_racket.py [--plot omega.png]
"""
import argparse
from pathlib import Path

import numpy as np

import poinsot

SCENARIO = Path(__file__).resolve().parents[1] / "tennis_racket.toml"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenario", default=str(SCENARIO), help="scenario file (default: the tennis racket)")
    ap.add_argument("--method", help="override the scenario's integrator, e.g. dop853, dlm, rattle")
    ap.add_argument("--plot", metavar="FILE", help="save a figure of omega_body(t)")
    a = ap.parse_args()

    scenario = poinsot.load_scenario(a.scenario)
    print(f"poinsot {poinsot.__version__}: {scenario.title}")
    body = scenario.body
    print(f"principal moments I1, I2, I3 = {body.principal_moments} kg·m²")
    print(f"omega_body(0) = {scenario.initial.omega_body} rad/s")
    r = poinsot.simulate(scenario, method=a.method)  # the scenario's method ("exact") unless overridden
    print(f"method {r.method}: {r.steps} steps to t = {r.final_state.time:g} s in {r.wall_time_s * 1e3:.1f} ms, "
          f"{len(r)} samples")

    flips = r.flip_times
    print(f"flips of the intermediate axis: {len(flips)}, at t = " + ", ".join(f"{t:.4f}" for t in flips) + " s")
    if len(flips) > 1 and r.flip_interval_theory:
        measured = np.diff(flips).mean()
        print(f"interval between flips: measured {measured:.9f} s, theory 2K(k)/ω_p = "
              f"{r.flip_interval_theory:.9f} s (relative difference {abs(measured / r.flip_interval_theory - 1):.1e})")
        print(f"period of omega: theory 4K(k)/ω_p = {r.period_theory:.9f} s")
    e = r.errors
    print(f"worst relative errors: energy {e['energy_rel_max']:.2e}, L_space {e['L_space_rel_max']:.2e}, "
          f"‖RᵀR − I‖ {e['orthogonality_max']:.2e}")

    exact = poinsot.ExactFreeBody(body, scenario.initial)
    R, w = exact.states_at(r.t)
    print(f"largest difference from the exact solution over the run: R {np.abs(R - r.R).max():.2e}, "
          f"omega {np.abs(w - r.omega_body).max():.2e} rad/s")

    if a.plot:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(8, 4))
        for i, name in enumerate(("ω1 (smallest axis)", "ω2 (intermediate axis)", "ω3 (largest axis)")):
            ax.plot(r.t, r.omega_body[:, i], label=name)
        for t in flips:
            ax.axvline(t, color="grey", lw=0.5, ls=":")
        ax.set_xlabel("t (s)")
        ax.set_ylabel("body angular velocity (rad/s)")
        ax.set_title("Tennis racket: the intermediate axis flips (dotted: located flips)")
        ax.legend(loc="lower right")
        fig.tight_layout()
        fig.savefig(a.plot, dpi=120)
        print(f"wrote {a.plot}")


if __name__ == "__main__":
    main()
