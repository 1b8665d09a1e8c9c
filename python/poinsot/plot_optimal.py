"""Figures of a `poinsot optimize` folder (PNG, Matplotlib); ``poinsot.plot.plot_run`` calls it when
summary.json says ``"kind": "optimal"`` (so ``poinsot optimize --plot`` and ``python3 -m poinsot.plot DIR``).

Reads ``trajectory.csv``, ``costates.csv`` and ``summary.json`` and writes into the folder:

- ``torque.png``: the body torques u_i (N·m) against their bounds (per axis ±u_max,i, or ±u_max and ‖u‖ for a
  norm bound), or with reaction wheels the wheels' motor torques, the switch times of the indirect solution as
  vertical lines;
- ``wheels.png`` (with reaction wheels): each wheel's angular momentum h_k (N·m·s) against its bound, if any;
- ``switching.png``: the switching functions σ = J⁻¹p_ω (the minimising control is u_i = −u_max,i sign σ_i);
- ``omega.png``: the body rates ω_i (rad/s) against the rate bound, if any;
- ``attitude_error.png``: the angle (rad) from the attitude to the target R_f, log scale (with a free final
  attitude: to the final attitude reached);
- ``pointing.png`` (with keep-out or keep-in cones): each boresight's angle (deg) to its cone's axis over
  time, its half-angle dashed (a keep-out curve stays above its line, a keep-in curve below);
- ``hamiltonian.png``: H − mean(H) along the indirect solution, log scale of its magnitude (0 for a free final
  time; only when the indirect solution ran).

Every title carries the status; a solution that is not verified optimal says "NOT OPTIMAL" there. Only NumPy
and Matplotlib are imported (not ``poinsot._core``).
"""
from __future__ import annotations

import json
from pathlib import Path

__all__ = ["load_optimal_run", "plot_optimal_run"]

ZERO_FLOOR = 1e-17  # where exact zeros are drawn on the log-scale plots


def _read_csv(path):
    """(column name -> array) of a CSV whose first line is the `# status: ...` comment."""
    import numpy as np

    with open(path, encoding="utf-8") as f:
        f.readline()
        names = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=2, ndmin=2)
    return {name: data[:, i] for i, name in enumerate(names)}


def load_optimal_run(folder):
    """(trajectory columns, costate columns, summary dict) of a `poinsot optimize` folder."""
    folder = Path(folder)
    with open(folder / "summary.json", encoding="utf-8") as f:
        summary = json.load(f)
    return _read_csv(folder / "trajectory.csv"), _read_csv(folder / "costates.csv"), summary


def _title(summary, what):
    status = "optimal (verified)" if summary.get("optimal") else "NOT OPTIMAL: " + summary.get("status", "")
    return f"{what} — {summary.get('objective', '')}, {status}"[:140]


def _switches(ax, summary):
    for s in summary.get("indirect", {}).get("switches", []):
        ax.axvline(s["t"], color="0.6", lw=0.6, ls=":")


def _quaternion_angle(q, target):
    """Angle (rad) of the rotation between unit quaternions q (n, 4) and the target (4,):
    4 atan2(‖q − s q_f‖, ‖q + s q_f‖) with s = sign⟨q, q_f⟩, accurate near 0 (unlike 2 acos |⟨q, q_f⟩|)."""
    import numpy as np

    s = np.where(q @ target < 0, -1.0, 1.0)[:, None]
    return 4 * np.arctan2(np.linalg.norm(q - s * target, axis=1), np.linalg.norm(q + s * target, axis=1))


def plot_optimal_run(folder):
    """Draws the figures of a `poinsot optimize` folder; returns the list of PNG paths written."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    folder = Path(folder)
    traj, co, summary = load_optimal_run(folder)
    if len(traj["t"]) < 2:
        raise ValueError(f"plot: {folder / 'trajectory.csv'} has {len(traj['t'])} rows; expected at least 2")
    problem = summary.get("problem", {})
    t = traj["t"]
    written = []

    def save(fig, name):
        fig.tight_layout()
        fig.savefig(folder / name, dpi=110)
        plt.close(fig)
        written.append(folder / name)

    colours = ("C0", "C1", "C2")
    fig, ax = plt.subplots(figsize=(8, 4.5))
    bound = problem.get("torque_max")
    wheels = summary.get("reaction_wheels")
    u_columns = ("u1", "u2", "u3") if wheels else ("ux", "uy", "uz")
    for i, c in enumerate(colours):
        ax.plot(t, traj[u_columns[i]], color=c, lw=1.2, label=f"u{i + 1}")
        if problem.get("torque_bound") == "per_axis" and bound is not None:
            for sign in (1, -1):
                ax.axhline(sign * bound[i], color=c, lw=0.7, ls="--")
    if problem.get("torque_bound") == "norm" and bound is not None:
        norm = np.sqrt(sum(traj[name] ** 2 for name in u_columns))
        ax.plot(t, norm, color="k", lw=1.0, label="‖u‖")
        for sign in (1, -1):
            ax.axhline(sign * bound, color="k", lw=0.7, ls="--")
    _switches(ax, summary)
    ax.set(xlabel="t (s)", ylabel="wheel motor torque (N·m)" if wheels else "body torque (N·m)",
           title=_title(summary, "torques and bounds"))
    ax.legend(loc="best", fontsize=8)
    save(fig, "torque.png")

    if wheels:
        fig, ax = plt.subplots(figsize=(8, 4.5))
        bounds = wheels.get("momentum_max") or [None] * 3
        for i, c in enumerate(colours):
            ax.plot(t, traj[f"h{i + 1}"], color=c, lw=1.2, label=f"h{i + 1}")
            if bounds[i] is not None:
                for sign in (1, -1):
                    ax.axhline(sign * bounds[i], color=c, lw=0.7, ls="--")
        ax.set(xlabel="t (s)", ylabel="wheel angular momentum (N·m·s)",
               title=_title(summary, "reaction wheels (dashed: the bounds)"))
        ax.legend(loc="best", fontsize=8)
        save(fig, "wheels.png")

    fig, ax = plt.subplots(figsize=(8, 4.5))
    for i, c in enumerate(colours):
        ax.plot(co["t"], co[f"sigma_{'xyz'[i]}"], color=c, lw=1.2, label=f"σ{i + 1}")
    ax.axhline(0.0, color="k", lw=0.6)
    _switches(ax, summary)
    ax.set(xlabel="t (s)", ylabel="σ = J⁻¹ p_ω", title=_title(summary, "switching functions"))
    ax.legend(loc="best", fontsize=8)
    save(fig, "switching.png")

    fig, ax = plt.subplots(figsize=(8, 4.5))
    for i, c in enumerate(colours):
        ax.plot(t, traj[f"w{'xyz'[i]}"], color=c, lw=1.2, label=f"ω{i + 1}")
    if problem.get("rate_max") is not None:
        for sign in (1, -1):
            ax.axhline(sign * problem["rate_max"], color="k", lw=0.7, ls="--", label="rate bound" if sign > 0
                       else None)
    _switches(ax, summary)
    ax.set(xlabel="t (s)", ylabel="ω body (rad/s)", title=_title(summary, "body rates"))
    ax.legend(loc="best", fontsize=8)
    save(fig, "omega.png")

    q = np.column_stack([traj["qw"], traj["qx"], traj["qy"], traj["qz"]])
    free = problem.get("free_final_attitude", False)
    target = q[-1] if free or "attitude_final" not in problem else np.asarray(problem["attitude_final"])
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.semilogy(t, np.maximum(_quaternion_angle(q, target), ZERO_FLOOR), color="C3", lw=1.2)
    _switches(ax, summary)
    ax.set(xlabel="t (s)", ylabel="angle to the " + ("final attitude" if free else "target") + " (rad)",
           title=_title(summary, "attitude error"))
    save(fig, "attitude_error.png")

    cones = summary.get("pointing", [])
    if cones:
        fig, ax = plt.subplots(figsize=(8, 4.5))
        for i, cone in enumerate(cones):
            c = f"C{i % 10}"
            label = cone["kind"].replace("_", "-") + (f" {cone['name']}" if cone["name"] else f" {i + 1}")
            ax.plot(t, np.degrees(traj[cone["column"]]), color=c, lw=1.2, label=label)
            ax.axhline(np.degrees(cone["half_angle"]), color=c, lw=0.8, ls="--")
        _switches(ax, summary)
        ax.set(xlabel="t (s)", ylabel="boresight angle to the cone's axis (deg)",
               title=_title(summary, "pointing constraints (dashed: the limits)"))
        ax.legend(loc="best", fontsize=8)
        save(fig, "pointing.png")

    H = co.get("H")
    if H is not None and np.all(np.isfinite(H)):
        fig, ax = plt.subplots(figsize=(8, 4.5))
        ax.semilogy(co["t"], np.maximum(np.abs(H - np.mean(H)), ZERO_FLOOR), color="C4", lw=1.0,
                    label="|H − mean H|")
        ax.axhline(max(abs(np.mean(H)), ZERO_FLOOR), color="k", lw=0.7, ls="--", label="|mean H|")
        _switches(ax, summary)
        ax.set(xlabel="t (s)", ylabel="Hamiltonian", title=_title(summary, "Hamiltonian (constant along an extremal)"))
        ax.legend(loc="best", fontsize=8)
        save(fig, "hamiltonian.png")
    return written
