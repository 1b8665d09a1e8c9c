#!/usr/bin/env python3
"""The viewer's cost per frame, measured in headless Chromium (the test browser of tests/viewer/: Debian's
chromium + chromium-driver + python3-selenium, WebGL in software through SwiftShader). For each page given
(view.html files; default: every example run with --html into a temporary folder):

  update   the page's JavaScript per frame: player.update() (locate the time, slerp, move every object),
           the mean of 2000 calls at times spread over the run, timed with performance.now() in the page;
  chart    the chart of the page redrawn (canvas 2D), the mean of 200 calls;
  render   a whole frame: update, three.js drawing it (WebGL in software on the CPU) and the chart, median of
           100 calls, with the pipeline flushed by reading one pixel back (gl.readPixels), so that the drawing
           is counted;
  played   frames drawn per second while playing (requestAnimationFrame), counted over 3 s.

A laptop's GPU does the drawing that SwiftShader does here on the CPU; `update` is what the page adds on
any machine. Usage: scripts/viewer_frame_cost.py [VIEW.html ...] (POINSOT_CLI: the poinsot binary)."""
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "viewer"))

MEASURE = """
var v = window.poinsotView, p = v.player, n = 2000, times = [], k;
for (k = 0; k < n; k++) times.push(p.t0 + (p.t1 - p.t0) * ((k * 0.618034) % 1));
function median(a) { a.sort(function (x, y) { return x - y; }); return a[a.length >> 1]; }
// performance.now() is coarsened to 0.1 ms in a page: the update is timed over all n calls at once.
var s = performance.now();
for (k = 0; k < n; k++) { p.time = times[k]; p.update(); }
var update = (performance.now() - s) / n;
// The chart (canvas 2D, up to 1000 points a series) is redrawn every frame too.
var chart = v.chart();
s = performance.now();
for (k = 0; k < 200; k++) chart.draw(times[k]);
var chartMs = (performance.now() - s) / 200;
var gl = document.querySelector('#stage canvas').getContext('webgl') ||
         document.querySelector('#stage canvas').getContext('experimental-webgl');
var px = new Uint8Array(4), ren = [];
for (k = 0; k < 100; k++) {
  var s2 = performance.now(); p.seek(times[k]); gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
  ren.push(performance.now() - s2);
}
return {update_ms: update, chart_ms: chartMs, render_ms: median(ren)};
"""

PLAY = """
var done = arguments[arguments.length - 1], p = window.poinsotView.player, frames = 0, t0 = null;
p.seek(p.t0); p.setSpeed(0.1); p.toggle();
function count(now) {
  if (t0 === null) t0 = now;
  frames++;
  if (now - t0 < 3000) requestAnimationFrame(count);
  else { p.toggle(); done(frames / ((now - t0) / 1000)); }
}
requestAnimationFrame(count);
"""


def pages():
    if len(sys.argv) > 1:
        return [Path(a) for a in sys.argv[1:]]
    cli = os.environ.get("POINSOT_CLI", str(ROOT / "build" / "release" / "apps" / "poinsot" / "poinsot"))
    tmp = Path(tempfile.mkdtemp(prefix="viewer_frame_cost_"))
    out = []
    for toml in ["tennis_racket.toml", "gyroscope.toml", "mesh_body.toml", "multibody/double_pendulum.toml",
                 "multibody/chain16.toml"]:
        d = tmp / toml.replace("/", "_").removesuffix(".toml")
        subprocess.run([cli, "run", str(ROOT / "examples" / toml), "--out", str(d), "--html", "--quiet"],
                       check=True, capture_output=True)
        out.append(d / "view.html")
    return out


def main():
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from conftest import CHROMEDRIVER, CHROMIUM, WINDOW

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for arg in ("--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                f"--window-size={WINDOW[0]},{WINDOW[1]}"):
        options.add_argument(arg)
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    driver.set_script_timeout(120)
    print(f"window {WINDOW[0]}x{WINDOW[1]} CSS px, Chromium {driver.capabilities.get('browserVersion')}, "
          "WebGL in software (SwiftShader)")
    print(f"{'page':28s} {'frames':>6s} {'update (ms)':>12s} {'chart (ms)':>11s} {'render (ms)':>12s} "
          f"{'played (frames/s)':>18s}")
    try:
        for page in pages():
            driver.get(page.resolve().as_uri())
            n = driver.execute_script("return window.poinsotView.track.n")
            m = driver.execute_script(MEASURE)
            fps = driver.execute_async_script(PLAY)
            name = page.parent.name
            print(f"{name:28s} {n:6d} {m['update_ms']:12.4f} {m['chart_ms']:11.3f} {m['render_ms']:12.2f} {fps:18.1f}")
    finally:
        driver.quit()


if __name__ == "__main__":
    main()
