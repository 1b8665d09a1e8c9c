"""Fixtures of the viewer's tests: the built poinsot binary, every example run with --html, and one headless
Chromium (Debian's chromium + chromium-driver, driven by python3-selenium) shared by all the tests.

WebGL in a headless container: Chromium renders with SwiftShader (software) when started with
--use-angle=swiftshader --enable-unsafe-swiftshader; --disable-gpu or --use-gl=swiftshader leave no WebGL
context in Chromium 156.

Speed. Loading a page (parsing three.js, compiling shaders in software) is most of the time, so a page is
loaded once and the tests on it run one after the other (pytest_collection_modifyitems groups the tests of
one example); a test that finds the page already open puts it back in the state it opened in
(`poinsotView.player.restore()`) instead of reloading it. Nothing waits a fixed time: every wait is for a
condition (the page's `poinsotView.ready`, the time advancing), bounded by WAIT_S only so that a broken page
fails instead of hanging; on a loaded machine the waits last longer and pass all the same."""
import os
import shutil
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("POINSOT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"
WINDOW = (800, 520)  # CSS pixels; small, so that software rendering stays fast
WAIT_S = 300  # the most any wait for the browser may take (s): a bound for a broken page, not a speed

EXAMPLES = sorted(p.relative_to(SOURCE_DIR / "examples").as_posix()
                  for p in list((SOURCE_DIR / "examples").glob("*.toml")) +
                  list((SOURCE_DIR / "examples" / "multibody").glob("*.toml")))


@pytest.fixture(scope="session")
def cli():
    exe = os.environ.get("POINSOT_CLI")
    if not exe:
        pytest.fail("POINSOT_CLI is not set: run these tests through ctest")

    def run(*args, cwd=None, timeout=120):
        return subprocess.run([exe, *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=timeout)

    return run


@pytest.fixture(scope="session")
def example_runs(cli, tmp_path_factory):
    """Every example run once with --html: {example path: run folder}."""
    root = tmp_path_factory.mktemp("examples")
    runs = {}
    for name in EXAMPLES:
        out = root / name.replace("/", "_").removesuffix(".toml")
        r = cli("run", SOURCE_DIR / "examples" / name, "--out", out, "--html", "--quiet")
        assert r.returncode == 0, f"{name}: {r.stderr}"
        runs[name] = out
    return runs


@pytest.fixture(scope="session")
def slew_run(cli, tmp_path_factory):
    """examples/optimal/sphere_slew.toml solved by `poinsot optimize` (0.3 s) and its page by `poinsot view`."""
    out = tmp_path_factory.mktemp("optimal") / "slew"
    r = cli("optimize", SOURCE_DIR / "examples" / "optimal" / "sphere_slew.toml", "--out", out)
    assert r.returncode == 0, r.stdout + r.stderr
    r = cli("view", out)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == str(out / "view.html")
    return out


@pytest.fixture(scope="session")
def browser():
    """One headless Chromium for every test of the session."""
    webdriver = pytest.importorskip("selenium.webdriver", reason="python3-selenium is not installed")
    from selenium.webdriver.chrome.service import Service

    for exe in (CHROMIUM, CHROMEDRIVER):
        if not shutil.which(exe):
            pytest.skip(f"{exe} is not installed (Debian packages chromium, chromium-driver)")
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for arg in ("--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                f"--window-size={WINDOW[0]},{WINDOW[1]}", "--hide-scrollbars"):
        options.add_argument(arg)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    driver.set_page_load_timeout(WAIT_S)
    driver.set_script_timeout(WAIT_S)
    yield driver
    driver.quit()


class Page:
    """A view.html loaded in the browser, with helpers to read the page's state and pixels."""

    def __init__(self, driver, path, reuse=False):
        """Opens `path`, or takes the page already open there: as the previous test left it with `reuse`,
        else restored to the state it opened in."""
        self.driver = driver
        self.logs = []
        uri = Path(path).resolve().as_uri()
        if driver.current_url == uri and self.js("return !!(window.poinsotView && window.poinsotView.ready)"):
            if not reuse:
                self.js("window.poinsotView.player.restore();")
            return
        driver.get_log("browser")  # drop what earlier pages logged
        driver.get(uri)
        self.wait_for("return !!(window.poinsotView && window.poinsotView.ready)", "the page to be ready")

    def wait_for(self, script, what, *args):
        """Waits until the JavaScript `script` returns a true value (polled every 20 ms, at most WAIT_S);
        returns that value."""
        from selenium.common.exceptions import TimeoutException
        from selenium.webdriver.support.wait import WebDriverWait

        try:
            return WebDriverWait(self.driver, WAIT_S, poll_frequency=0.02).until(
                lambda d: d.execute_script(script, *args))
        except TimeoutException:
            pytest.fail(f"waited {WAIT_S} s for {what}; the console says {self.console()}")

    def resize(self, width, height):
        """Sets the window's size (CSS pixels) and waits until the page has redrawn its canvas at that size."""
        self.driver.set_window_size(width, height)
        self.wait_for("var s = document.getElementById('stage'), c = s.querySelector('canvas');"
                      "return c.clientWidth === s.clientWidth && c.clientHeight === s.clientHeight;",
                      "the canvas to follow the window's size")

    def js(self, script, *args):
        return self.driver.execute_script(script, *args)

    def console(self):
        """Messages the page logged so far (console, uncaught errors, resources): level, source, message."""
        self.logs += self.driver.get_log("browser")
        return self.logs

    def pixels(self):
        """(fraction of pixels that differ from the background, a digest of the canvas's pixels)."""
        return self.js("""
            var c = document.querySelector('#stage canvas');
            var t = document.createElement('canvas'); t.width = c.width; t.height = c.height;
            var g = t.getContext('2d'); g.drawImage(c, 0, 0);
            var d = g.getImageData(0, 0, c.width, c.height).data, n = 0, h = 0;
            for (var i = 0; i < d.length; i += 4) {
              if (Math.abs(d[i] - 244) + Math.abs(d[i + 1] - 244) + Math.abs(d[i + 2] - 242) > 24) n++;
              h = (h * 31 + d[i] + 7 * d[i + 1] + 13 * d[i + 2]) % 2147483647;
            }
            return [n / (c.width * c.height), h];""")

    def changed_since(self, snapshot=None):
        """Takes a copy of the canvas's pixels (kept in the page) and returns the fraction of pixels that differ
        from the copy taken before (by more than 24 in the sum of the colour channels), None the first time."""
        return self.js("""
            var c = document.querySelector('#stage canvas');
            var t = document.createElement('canvas'); t.width = c.width; t.height = c.height;
            var g = t.getContext('2d'); g.drawImage(c, 0, 0);
            var d = g.getImageData(0, 0, c.width, c.height).data, old = window.__snapshot, n = 0;
            window.__snapshot = d;
            if (!old) return null;
            for (var i = 0; i < d.length; i += 4)
              if (Math.abs(d[i] - old[i]) + Math.abs(d[i + 1] - old[i + 1]) + Math.abs(d[i + 2] - old[i + 2]) > 24) n++;
            return n / (c.width * c.height);""")

    def seek_with_slider(self, t):
        """Moves the time slider to t (s) as a user does: its value, then its input event."""
        self.js("var s = document.getElementById('time'); s.value = arguments[0];"
                "s.dispatchEvent(new Event('input'));", t)


def pytest_collection_modifyitems(items):
    """Runs the tests of one example one after the other (in the order collected otherwise), so that its page
    is loaded once: every test with the parameter `example` moves up to just after the first such test."""
    first = {}
    keys = []
    for k, item in enumerate(items):
        example = getattr(item, "callspec", None) and item.callspec.params.get("example")
        keys.append((first.setdefault(example, k), k) if example else (k, k))
    order = sorted(range(len(items)), key=lambda k: keys[k])
    items[:] = [items[k] for k in order]


@pytest.fixture
def load(browser):
    return lambda path, reuse=False: Page(browser, path, reuse)
