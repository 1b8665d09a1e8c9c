"""The screenshots of docs/viewer.md and the README, made by the pages themselves in the test browser. Runs
only when POINSOT_VIEWER_SCREENSHOTS names the folder to write them to (scripts/viewer_screenshots.sh), so
that ordinary test runs leave the repository alone."""
import os
from pathlib import Path

import pytest

from conftest import WINDOW

OUT = os.environ.get("POINSOT_VIEWER_SCREENSHOTS")

# example, file name, fraction of the run's time, page set-up (JavaScript)
SHOTS = [
    ("tennis_racket.toml", "viewer_tennis_racket.png", 0.42, ""),
    ("square_plate.toml", "viewer_square_plate.png", 0.35, ""),
    ("gyroscope.toml", "viewer_gyroscope.png", 0.5, ""),
    ("multibody/double_pendulum.toml", "viewer_double_pendulum.png", 0.37, ""),
    ("multibody/double_pendulum.toml", "viewer_double_pendulum_multipliers.png", 0.2,
     "['reactions', 'stress'].forEach(function (k) { document.getElementById('overlay-' + k).click(); });"),
    ("mesh_body.toml", "viewer_mesh_body.png", 0.3, ""),
    ("optimal/sphere_slew.toml", "viewer_sphere_slew.png", 0.45, ""),
]


@pytest.mark.skipif(not OUT, reason="set POINSOT_VIEWER_SCREENSHOTS=FOLDER to write the screenshots")
@pytest.mark.parametrize("example,name,fraction,setup", SHOTS)
def test_screenshot(example, name, fraction, setup, example_runs, load, browser, request):
    run = request.getfixturevalue("slew_run") if example.startswith("optimal/") else example_runs[example]
    page = load(run / "view.html")
    page.resize(1200, 760)
    try:
        page.js("var p = window.poinsotView.player; p.seek(p.t0 + arguments[0] * (p.t1 - p.t0));" + setup, fraction)
        assert page.pixels()[0] > 0.001
        Path(OUT).mkdir(parents=True, exist_ok=True)
        browser.save_screenshot(str(Path(OUT) / name))
    finally:
        page.resize(*WINDOW)  # the other tests on this page expect the usual size
    assert not [e for e in page.console() if e["level"] in ("SEVERE", "WARNING")]
