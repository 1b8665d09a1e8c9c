"""Figures of a `poinsot run` folder (PNG, Matplotlib).

Usage::

    python3 -m poinsot.plot DIR          # or: python3 path/to/poinsot/plot.py DIR

reads ``DIR/trajectory.csv`` and ``DIR/summary.json`` (written by ``poinsot run``) and writes into DIR:

- ``omega.png``: the body-frame components of ω (rad/s) against time (s), the flips of the intermediate axis
  marked;
- ``invariants.png``: the relative errors |E − E0|/|E0| of the energy and ||L| − |L0||/|L0| of the angular
  momentum's magnitude against time, on a log scale (exact zeros drawn at 1e-17);
- ``polhode.png``: the path of L_body/|L| on the unit sphere (the polhode) with the intersection of the
  sphere and the initial energy ellipsoid xᵀ J⁻¹ x = 2T/|L|² (its closed-form path for a free body), and a
  few neighbouring polhodes for context;
- ``top.png`` (tops only): the tip of the figure axis seen from above (along the vertical −g, or along L for a
  free symmetric top), showing precession and nutation.

A ``poinsot optimize`` folder (``"kind": "optimal"``) gets the figures of ``poinsot.plot_optimal``.

A multibody run (summary.json ``"kind": "multibody"``, with ``DIR/diagnostics.csv``) gets instead:

- ``paths.png``: each body's centre of mass (m) in the x–z and x–y planes (equal axes), start and end marked;
- ``energy.png``: the energy error (E − E0)/E_scale against time, E_scale the energy the motion moves around
  (the largest kinetic energy or change of potential energy over the run), above the kinetic and potential
  energies (J);
- ``constraints.png``: the largest joint gap (m), joint angle error and |RᵀR − I| against time, log scale.

Only NumPy and Matplotlib are imported (not the compiled ``poinsot._core``), so this module runs from a
build of the command-line tool alone. ``poinsot run --plot`` calls it.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

__all__ = ["load_run", "load_multibody_run", "plot_run", "main"]

ZERO_FLOOR = 1e-17  # where exact zeros are drawn on the log-scale error plot


def load_run(folder):
    """Returns (columns: dict name -> numpy array, summary: dict) of a run folder."""
    import numpy as np

    folder = Path(folder)
    csv = folder / "trajectory.csv"
    with open(csv, encoding="utf-8") as f:
        f.readline()  # the units comment
        names = f.readline().strip().split(",")
    data = np.loadtxt(csv, delimiter=",", skiprows=2, ndmin=2)
    cols = {name: data[:, i] for i, name in enumerate(names)}
    with open(folder / "summary.json", encoding="utf-8") as f:
        summary = json.load(f)
    return cols, summary


def _rotations(cols):
    """R (n, 3, 3), body to space, from the quaternion columns."""
    import numpy as np

    w, x, y, z = (cols[k] for k in ("qw", "qx", "qy", "qz"))
    R = np.empty((len(w), 3, 3))
    R[:, 0, 0] = 1 - 2 * (y * y + z * z)
    R[:, 0, 1] = 2 * (x * y - w * z)
    R[:, 0, 2] = 2 * (x * z + w * y)
    R[:, 1, 0] = 2 * (x * y + w * z)
    R[:, 1, 1] = 1 - 2 * (x * x + z * z)
    R[:, 1, 2] = 2 * (y * z - w * x)
    R[:, 2, 0] = 2 * (x * z - w * y)
    R[:, 2, 1] = 2 * (y * z + w * x)
    R[:, 2, 2] = 1 - 2 * (x * x + y * y)
    return R


def _title(summary):
    return f"{summary['scenario']} ({summary['method']})"


def _plot_omega(plt, cols, summary, out):
    fig, ax = plt.subplots(figsize=(9, 4.8), constrained_layout=True)
    t = cols["t"]
    for key, label, color in (("wx", "ω₁ (body x)", "C0"), ("wy", "ω₂ (body y)", "C1"), ("wz", "ω₃ (body z)", "C2")):
        ax.plot(t, cols[key], color=color, lw=1.4, label=label)
    flips = summary.get("events", {}).get("flip_times", [])
    for i, tf in enumerate(flips):
        ax.axvline(tf, color="0.5", lw=0.8, ls=":", label="flip (L₂ = 0)" if i == 0 else None)
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("angular velocity ω, body frame (rad/s)")
    ax.set_title(f"Angular velocity: {_title(summary)}")
    ax.grid(alpha=0.3)
    ax.legend(loc="best", fontsize=9)
    fig.savefig(out, dpi=120)
    plt.close(fig)


def _plot_invariants(plt, cols, summary, out):
    import numpy as np

    t = cols["t"]
    E = cols["energy"]
    L = np.sqrt(cols["L_space_x"] ** 2 + cols["L_space_y"] ** 2 + cols["L_space_z"] ** 2)
    e_rel = np.abs(E - E[0]) / max(abs(E[0]), 1e-300)
    l_rel = np.abs(L - L[0]) / max(L[0], 1e-300)
    fig, ax = plt.subplots(figsize=(9, 4.8), constrained_layout=True)
    ax.semilogy(t, np.maximum(e_rel, ZERO_FLOOR), lw=1.2, label="energy |E − E₀| / |E₀|")
    ax.semilogy(t, np.maximum(l_rel, ZERO_FLOOR), lw=1.2, label="angular momentum ||L| − |L₀|| / |L₀|")
    ax.axhline(np.finfo(float).eps, color="0.4", lw=0.8, ls="--", label="machine epsilon 2.2e-16")
    ax.set_ylim(bottom=ZERO_FLOOR / 2)
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("relative error (dimensionless)")
    ax.set_title(f"Conserved quantities: {_title(summary)}\n(exact zeros drawn at {ZERO_FLOOR:g})", fontsize=11)
    ax.grid(alpha=0.3, which="both")
    ax.legend(loc="best", fontsize=9)
    fig.savefig(out, dpi=120)
    plt.close(fig)


def _sphere_level_curves(Jinv, levels, n=241):
    """Curves on the unit sphere where xᵀ J⁻¹ x equals each level: a list (per level) of (m, 3) arrays."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    th = np.linspace(0.0, np.pi, n)
    ph = np.linspace(-np.pi, np.pi, 2 * n)
    PH, TH = np.meshgrid(ph, th)
    X = np.stack([np.sin(TH) * np.cos(PH), np.sin(TH) * np.sin(PH), np.cos(TH)], axis=-1)
    F = np.einsum("...i,ij,...j->...", X, Jinv, X)
    fig, ax = plt.subplots()
    out = []
    lo, hi = F.min(), F.max()
    for level in levels:
        segs = []
        if lo < level < hi:
            cs = ax.contour(PH, TH, F, levels=[level])
            for seg in cs.allsegs[0]:
                p, t = seg[:, 0], seg[:, 1]
                segs.append(np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], axis=-1))
        out.append(segs)
    plt.close(fig)
    return out


def _plot_polhode(plt, cols, summary, out):
    import numpy as np

    Lb = np.stack([cols["L_body_x"], cols["L_body_y"], cols["L_body_z"]], axis=1)
    norms = np.linalg.norm(Lb, axis=1)
    ok = norms > 0
    u = Lb[ok] / norms[ok, None]
    J = np.array(summary["body"]["inertia"], dtype=float)
    Jinv = np.linalg.inv(J)
    E_kin0 = 0.5 * float(np.dot(Lb[0], Jinv @ Lb[0]))
    level0 = 2.0 * E_kin0 / norms[0] ** 2 if norms[0] > 0 else None
    m = np.linalg.eigvalsh(Jinv)
    others = list(np.linspace(m[0], m[2], 9)[1:-1])
    curves = _sphere_level_curves(Jinv, others + ([level0] if level0 else []))

    fig = plt.figure(figsize=(7.5, 7), constrained_layout=True)
    ax = fig.add_subplot(projection="3d")
    a, b = np.mgrid[0 : np.pi : 25j, -np.pi : np.pi : 49j]
    ax.plot_surface(np.sin(a) * np.cos(b), np.sin(a) * np.sin(b), np.cos(a), color="0.9", alpha=0.15, lw=0)
    for segs in curves[: len(others)]:
        for s in segs:
            ax.plot(s[:, 0], s[:, 1], s[:, 2], color="0.6", lw=0.6)
    ax.plot(u[:, 0], u[:, 1], u[:, 2], color="C3", lw=3.0, alpha=0.55, label="computed L_body / |L|")
    ax.scatter(*u[0], color="C3", s=30, label="t = 0")
    if level0:
        # The level set has two components (one about each end of the axis the motion circles): draw the one
        # the body is on, i.e. on the same side as the computed path's mean along its dominant coordinate.
        mean = u.mean(axis=0)
        k = int(np.argmax(np.abs(mean)))
        segs = [s for s in curves[-1] if np.sign(s[:, k].mean()) == np.sign(mean[k])] or curves[-1]
        free = str(summary.get("torque", "none")).startswith("none")
        label = ("theory: sphere ∩ initial energy ellipsoid" if free else
                 "sphere ∩ initial energy ellipsoid (a path only without torque)")
        for i, s in enumerate(segs):
            ax.plot(s[:, 0], s[:, 1], s[:, 2], color="k", lw=1.4, ls="--" if free else ":",
                    label=label if i == 0 else None)
    ax.set_xlabel("L₁/|L| (body x)")
    ax.set_ylabel("L₂/|L| (body y)")
    ax.set_zlabel("L₃/|L| (body z)")
    ax.set_xlim(-1, 1)
    ax.set_ylim(-1, 1)
    ax.set_zlim(-1, 1)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=22, azim=35)
    ax.set_title(f"Polhode (unit sphere, dimensionless): {_title(summary)}\n"
                 "grey: other polhodes xᵀJ⁻¹x = const", fontsize=10)
    ax.legend(loc="upper left", fontsize=8)
    fig.savefig(out, dpi=120)
    plt.close(fig)


def _plot_top(plt, cols, summary, out):
    import numpy as np

    top = summary["top"]
    a_body = np.array(top["axis_body"], dtype=float)
    u = np.array(top["direction_space"], dtype=float)
    R = _rotations(cols)
    tip = R @ a_body  # (n, 3), space frame, unit
    # A right-handed basis (e1, e2, u) of space with u towards the viewer.
    helper = np.array([1.0, 0.0, 0.0]) if abs(u[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = helper - helper.dot(u) * u
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(u, e1)
    x, y = tip @ e1, tip @ e2
    t = cols["t"]
    theta = np.arccos(np.clip(tip @ u, -1.0, 1.0))
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(13, 6.2), constrained_layout=True,
                                  gridspec_kw={"width_ratios": [1.15, 1]})
    sc = ax.scatter(x, y, c=t, s=2, cmap="viridis")
    ax.plot(x, y, color="0.5", lw=0.4, alpha=0.6)
    ax.plot(x[0], y[0], "o", color="C3", label="t = 0")
    r = max(float(np.max(np.hypot(x, y))), 1e-3)
    circ = np.linspace(0, 2 * np.pi, 400)
    ax.plot(r * np.cos(circ), r * np.sin(circ), color="0.8", lw=0.8, ls=":")
    ax.set_aspect("equal")
    lim = 1.15 * r
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    about = "the vertical (−g)" if top["kind"] == "heavy top" else "L (space frame)"
    ax.set_xlabel("tip position along e₁ (per unit axis length, dimensionless)")
    ax.set_ylabel("tip position along e₂ (per unit axis length, dimensionless)")
    ev = summary.get("events", {})
    rate = ev.get("precession_rate_mean")
    sub = f"mean precession {rate:.4g} rad/s" if rate is not None else ""
    ax.set_title(f"Figure-axis tip seen from above, looking down {about}\n{sub}", fontsize=10)
    cb = fig.colorbar(sc, ax=ax, shrink=0.8)
    cb.set_label("time t (s)")
    ax.legend(loc="upper right", fontsize=9)
    ax.grid(alpha=0.3)
    # Nutation: the tilt of the axis from the direction, over about a dozen nutation periods.
    nu = ev.get("nutation_frequency")
    span = t[-1] - t[0]
    if nu:
        span = min(span, 12 * 2 * np.pi / nu)
    sel = t <= t[0] + span
    ax2.plot(t[sel], np.degrees(theta[sel]), color="C0", lw=1.2)
    ax2.set_xlabel("time t (s)")
    ax2.set_ylabel(f"tilt of the figure axis from {about} (degrees)")
    nut = f"nutation {nu:.4g} rad/s" if nu else "no nutation detected"
    ax2.set_title(f"Nutation: tilt against time ({nut})", fontsize=10)
    ax2.ticklabel_format(axis="y", useOffset=False)
    tilt = np.degrees(theta[sel])
    if np.ptp(tilt) < 1e-3:  # a steady tilt: show it on a readable half-degree window, not its round-off
        mid = float(np.mean(tilt))
        ax2.set_ylim(mid - 0.5, mid + 0.5)
    ax2.grid(alpha=0.3)
    fig.suptitle(f"{top['kind']}: {_title(summary)}", fontsize=12)
    fig.savefig(out, dpi=110)
    plt.close(fig)


def _read_csv(path):
    """Columns (dict name -> numpy array) of a CSV whose first line is the header."""
    import numpy as np

    with open(path, encoding="utf-8") as f:
        names = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {name: data[:, i] for i, name in enumerate(names)}


def load_multibody_run(folder):
    """Returns (trajectory columns, diagnostics columns, summary dict, body names) of a multibody run folder
    (trajectory.csv: t, then per body NAME.x ... NAME.wz; diagnostics.csv: include/poinsot/multibody/
    scenario.hpp)."""
    folder = Path(folder)
    traj = _read_csv(folder / "trajectory.csv")
    diag = _read_csv(folder / "diagnostics.csv")
    with open(folder / "summary.json", encoding="utf-8") as f:
        summary = json.load(f)
    bodies = [name[: -len(".x")] for name in traj if name.endswith(".x")]
    return traj, diag, summary, bodies


def _multibody_title(summary):
    name = Path(str(summary.get("scenario", "multibody run"))).stem
    return f"{name} (RATTLE order {summary.get('order', 2)}, dt = {summary['dt']:g} s)"


def _plot_paths(plt, traj, bodies, summary, out):
    import numpy as np

    fig, axes = plt.subplots(1, 2, figsize=(12, 5.6), constrained_layout=True)
    colors = plt.get_cmap("viridis")(np.linspace(0.0, 0.9, len(bodies))) if len(bodies) > 10 else None
    for ax, (a, b) in zip(axes, (("x", "z"), ("x", "y"))):
        for i, name in enumerate(bodies):
            c = colors[i] if colors is not None else f"C{i}"
            u, v = traj[f"{name}.{a}"], traj[f"{name}.{b}"]
            ax.plot(u, v, color=c, lw=1.2, label=name if len(bodies) <= 10 else None)
            ax.plot(u[0], v[0], "o", color=c, ms=4)
            ax.plot(u[-1], v[-1], "s", color=c, ms=4)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel(f"{a} (m)")
        ax.set_ylabel(f"{b} (m)")
        ax.set_title(f"{a}–{b} projection (o: start, ■: end)", fontsize=10)
        ax.grid(alpha=0.3)
    if len(bodies) <= 10:
        axes[0].legend(loc="best", fontsize=9, title="centre of mass of")
    else:
        axes[0].text(0.02, 0.02, f"{len(bodies)} bodies, coloured in file order", transform=axes[0].transAxes,
                     fontsize=9)
    fig.suptitle(f"Centre-of-mass paths: {_multibody_title(summary)}", fontsize=12)
    fig.savefig(out, dpi=120)
    plt.close(fig)


def energy_scale(diag):
    """The energy the motion moves around (J): the largest kinetic energy or |V − V(0)| over the rows. The zero
    of the potential is arbitrary, so |E0| is no scale (it can be 0 or huge); this is the
    "releasable energy". |E0| when both are 0 (a body at rest), 1 J if that is 0 too."""
    import numpy as np

    V = diag["potential"]
    scale = max(float(np.max(np.abs(diag["kinetic"]))), float(np.max(np.abs(V - V[0]))))
    if scale == 0.0:
        scale = abs(float(diag["energy"][0])) or 1.0
    return scale


def _plot_energy(plt, diag, summary, out):
    import numpy as np

    t = diag["t"]
    scale = energy_scale(diag)
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(9, 7), sharex=True, constrained_layout=True)
    ax.plot(t, diag["energy_error"] / scale, color="C3", lw=1.2)
    ax.axhline(0.0, color="0.4", lw=0.8)
    ax.set_ylabel("(E − E₀) / E_scale (dimensionless)")
    worst = float(np.max(np.abs(diag["energy_error"]))) / scale
    ax.set_title(f"Energy error: E₀ = {diag['energy'][0]:.6g} J, E_scale = {scale:.4g} J (largest T or |V − V₀|), "
                 f"max |E − E₀| / E_scale = {worst:.3g}", fontsize=10)
    ax.grid(alpha=0.3)
    ax2.plot(t, diag["kinetic"], color="C0", lw=1.2, label="kinetic T")
    ax2.plot(t, diag["potential"], color="C1", lw=1.2, label="potential V")
    ax2.plot(t, diag["energy"], color="k", lw=1.0, ls="--", label="total E = T + V")
    ax2.set_xlabel("time t (s)")
    ax2.set_ylabel("energy (J)")
    ax2.grid(alpha=0.3)
    ax2.legend(loc="best", fontsize=9)
    fig.suptitle(f"Energy: {_multibody_title(summary)}", fontsize=12)
    fig.savefig(out, dpi=120)
    plt.close(fig)


def _plot_constraints(plt, diag, summary, out):
    import numpy as np

    t = diag["t"]
    fig, axes = plt.subplots(3, 1, figsize=(9, 8), sharex=True, constrained_layout=True)
    for ax, key, label, color in ((axes[0], "joint_gap", "largest joint gap (m)", "C0"),
                                  (axes[1], "joint_angle", "largest joint angle error\n(dimensionless ≈ rad)", "C1"),
                                  (axes[2], "orthogonality", "max ‖RᵀR − I‖_F\n(dimensionless)", "C2")):
        ax.semilogy(t, np.maximum(np.abs(diag[key]), ZERO_FLOOR), color=color, lw=1.2)
        if key == "joint_gap":  # a length: RATTLE's Newton tolerance, not ε, is the reference
            ax.axhline(1e-12, color="0.4", lw=0.8, ls=":", label="1e-12 m (tested bound)")
        else:
            ax.axhline(np.finfo(float).eps, color="0.4", lw=0.8, ls="--", label="machine epsilon 2.2e-16")
        ax.legend(loc="lower right", fontsize=8)
        ax.set_ylim(bottom=ZERO_FLOOR / 2)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3, which="both")
        if not np.any(diag[key]):
            why = " (no joint with rotation rows)" if key == "joint_angle" else ""
            ax.text(0.02, 0.85, f"exactly 0 at every row{why}", transform=ax.transAxes, fontsize=9)
    axes[2].set_xlabel("time t (s)")
    fig.suptitle(f"Constraint violation: {_multibody_title(summary)}\n(exact zeros drawn at {ZERO_FLOOR:g})",
                 fontsize=12)
    fig.savefig(out, dpi=120)
    plt.close(fig)


def _plot_multibody_run(plt, folder):
    traj, diag, summary, bodies = load_multibody_run(folder)
    if len(diag["t"]) < 2:
        raise ValueError(f"plot: {folder / 'diagnostics.csv'} has {len(diag['t'])} rows; expected at least 2")
    written = []
    for name, draw in (("paths.png", lambda o: _plot_paths(plt, traj, bodies, summary, o)),
                       ("energy.png", lambda o: _plot_energy(plt, diag, summary, o)),
                       ("constraints.png", lambda o: _plot_constraints(plt, diag, summary, o))):
        draw(folder / name)
        written.append(folder / name)
    return written


def _sibling_module(name):
    """The module `name` of this package. plot.py also runs as a script (the command line's --plot), possibly
    from a build without the compiled module (the sanitizer build), where importing the package would fail on
    _core: then the module is imported from this file's folder, which a script has first on sys.path."""
    import importlib

    try:
        return importlib.import_module(f"poinsot.{name}")
    except ImportError:
        return importlib.import_module(name)


def plot_run(folder):
    """Draws the figures of a run folder; returns the list of PNG paths written."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    folder = Path(folder)
    with open(folder / "summary.json", encoding="utf-8") as f:
        kind = json.load(f).get("kind")
    if kind == "multibody":
        return _plot_multibody_run(plt, folder)
    if kind == "ensemble":
        return _sibling_module("plot_ensemble").plot_ensemble_run(folder)
    if kind == "optimal":
        return _sibling_module("plot_optimal").plot_optimal_run(folder)
    cols, summary = load_run(folder)
    if len(cols["t"]) < 2:
        raise ValueError(f"plot: {folder / 'trajectory.csv'} has {len(cols['t'])} rows; expected at least 2")
    written = []
    for name, fn in (("omega.png", _plot_omega), ("invariants.png", _plot_invariants),
                     ("polhode.png", _plot_polhode)):
        fn(plt, cols, summary, folder / name)
        written.append(folder / name)
    if summary.get("top"):
        _plot_top(plt, cols, summary, folder / "top.png")
        written.append(folder / "top.png")
    return written


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1 or argv[0] in ("-h", "--help"):
        print("usage: python3 -m poinsot.plot RUN_FOLDER   (a folder written by `poinsot run`)", file=sys.stderr)
        return 2
    try:
        for path in plot_run(argv[0]):
            print(f"plot: wrote {path}")
    except (OSError, ValueError, KeyError) as e:
        print(f"poinsot: plot: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
