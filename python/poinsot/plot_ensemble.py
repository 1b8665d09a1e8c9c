"""Figures of an ensemble folder written by `poinsot ensemble` (samples.csv, summary.json).

``plot_ensemble_run(folder)`` writes, next to the data:

- ``histograms.png``: a histogram of every per-sample output that has values; the flip interval with the
  closed form 2K(k)/ω_p of the same samples (those with two flips before t_end) overlaid (a step line), a
  slew's pointing error with its requirement (a dashed line);
- ``cdf.png``: their empirical CDFs, the flip interval's theory overlaid;
- ``scatter.png``: a slew's pointing error, else the attitude error (or the first output with values),
  against the input that explains it best: the one of I1, I2, I3, misalignment, omega0 with the largest
  absolute Pearson correlation.

Without samples.csv (per-sample output off, or more rows than the CSV holds) only ``histograms.png`` is
drawn, from the fixed-edge histograms of summary.json (their edges and counts; the samples below and above
the edges are given in each title, the closed form is not overlaid: it needs the rows).

Returns the paths written. Raises ValueError when the folder has neither samples.csv nor histograms in
summary.json.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np

OUTPUTS = ("first_flip_time", "flip_interval", "attitude_error", "energy_error", "L_space_error", "pointing_error",
           "rate_error", "peak_torque", "peak_wheel_momentum")
INPUTS = ("I1", "I2", "I3", "misalignment", "omega0_x", "omega0_y", "omega0_z")


def load_ensemble(folder):
    """The columns of samples.csv as a dict of float arrays, and summary.json as a dict."""
    folder = Path(folder)
    path = folder / "samples.csv"
    if not path.exists():
        raise ValueError(f"plot: {path} does not exist; expected a folder of `poinsot ensemble` with "
                         "per-sample output on")
    data = np.genfromtxt(path, delimiter=",", names=True, dtype=float)
    data = np.atleast_1d(data)
    cols = {name: np.asarray(data[name], dtype=float) for name in data.dtype.names}
    with open(folder / "summary.json", encoding="utf-8") as f:
        return cols, json.load(f)


def _label(summary, name):
    unit = summary["outputs"].get(name, {}).get("unit", "")
    return f"{name} ({unit})" if unit else name


def _finite(x):
    return x[np.isfinite(x)]


def most_influential_input(cols, output):
    """The input column with the largest |Pearson correlation| with `output` over the samples where both are
    finite and the input varies; None when no input varies."""
    best, best_r = None, -1.0
    y = cols[output]
    for name in INPUTS:
        x = cols.get(name)
        if x is None:
            continue
        ok = np.isfinite(x) & np.isfinite(y)
        if ok.sum() < 3 or np.std(x[ok]) == 0 or np.std(y[ok]) == 0:
            continue
        r = abs(np.corrcoef(x[ok], y[ok])[0, 1])
        if r > best_r:
            best, best_r = name, r
    return best


def plot_summary_histograms(folder):
    """histograms.png from the fixed-edge histograms of summary.json (no rows needed); the paths written."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    folder = Path(folder)
    with open(folder / "summary.json", encoding="utf-8") as f:
        summary = json.load(f)
    outputs = summary.get("outputs", {})
    shown = [n for n in OUTPUTS if "histogram" in outputs.get(n, {}) and outputs[n].get("count", 0) > 0]
    if not shown:
        raise ValueError(f"plot: {folder} has no samples.csv and summary.json has no histogram with values; "
                         "expected a folder of `poinsot ensemble`")
    fig, axes = plt.subplots(1, len(shown), figsize=(4 * len(shown), 3.4), squeeze=False)
    for ax, name in zip(axes[0], shown):
        h = outputs[name]["histogram"]
        edges = np.asarray(h["edges"], dtype=float)
        ax.stairs(np.asarray(h["counts"], dtype=float), edges, fill=True, color="tab:blue", alpha=0.7)
        ax.set_xlabel(_label(summary, name))
        ax.set_title(f"{h['underflow']} below, {h['overflow']} above", fontsize=8)
    axes[0][0].set_ylabel("samples")
    fig.suptitle(f"{summary['scenario']}: {summary['completed']} samples, {summary['method']} (fixed edges)")
    fig.tight_layout()
    fig.savefig(folder / "histograms.png", dpi=110)
    plt.close(fig)
    return [folder / "histograms.png"]


def plot_ensemble_run(folder):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    folder = Path(folder)
    if not (folder / "samples.csv").exists():
        return plot_summary_histograms(folder)
    cols, summary = load_ensemble(folder)
    shown = [n for n in OUTPUTS if n in cols and _finite(cols[n]).size > 0]
    if not shown:
        raise ValueError(f"plot: {folder / 'samples.csv'} has no finite outputs")
    title = f"{summary['scenario']}: {summary['completed']} samples, {summary['method']}"
    # The closed form of the samples whose interval was measured (two flips before t_end), so that both
    # distributions describe the same samples.
    measured = np.isfinite(cols.get("flip_interval", np.array([])))
    theory = _finite(cols["flip_interval_theory"][measured]) if measured.any() else np.array([])
    written = []

    fig, axes = plt.subplots(1, len(shown), figsize=(4 * len(shown), 3.4), squeeze=False)
    for ax, name in zip(axes[0], shown):
        x = _finite(cols[name])
        _, edges, _ = ax.hist(x, bins=30, color="tab:blue", alpha=0.7, label="samples")
        if name == "flip_interval" and theory.size:
            ax.hist(theory, bins=edges, histtype="step", color="k", label="2K(k)/ω_p")
            ax.legend(fontsize=8)
        if name == "pointing_error" and "slew" in summary:
            ax.axvline(summary["slew"]["pointing_requirement"], color="r", ls="--", label="requirement")
            ax.legend(fontsize=8)
        ax.set_xlabel(_label(summary, name))
    axes[0][0].set_ylabel("samples")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(folder / "histograms.png", dpi=110)
    plt.close(fig)
    written.append(folder / "histograms.png")

    fig, axes = plt.subplots(1, len(shown), figsize=(4 * len(shown), 3.4), squeeze=False)
    for ax, name in zip(axes[0], shown):
        x = np.sort(_finite(cols[name]))
        ax.step(x, np.arange(1, x.size + 1) / x.size, where="post", label="samples")
        if name == "flip_interval" and theory.size:
            t = np.sort(theory)
            ax.step(t, np.arange(1, t.size + 1) / t.size, where="post", color="k", ls="--", label="2K(k)/ω_p")
            ax.legend(fontsize=8)
        ax.set_xlabel(_label(summary, name))
        ax.set_ylim(0, 1)
    axes[0][0].set_ylabel("empirical CDF")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(folder / "cdf.png", dpi=110)
    plt.close(fig)
    written.append(folder / "cdf.png")

    output = next((n for n in ("pointing_error", "attitude_error") if n in shown), shown[0])
    cause = most_influential_input(cols, output)
    if cause is not None:
        fig, ax = plt.subplots(figsize=(5, 4))
        ax.plot(cols[cause], cols[output], ".", ms=3, alpha=0.5)
        ax.set_xlabel(cause)
        ax.set_ylabel(_label(summary, output))
        ax.set_title(f"{output} against {cause} (largest |correlation|)")
        fig.tight_layout()
        fig.savefig(folder / "scatter.png", dpi=110)
        plt.close(fig)
        written.append(folder / "scatter.png")
    return written
