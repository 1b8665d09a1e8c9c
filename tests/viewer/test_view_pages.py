"""Every example's view.html in a real browser: it loads with no console error or warning, draws something,
redraws when the time slider moves, and plays."""
import pytest

from conftest import EXAMPLES


@pytest.mark.parametrize("example", EXAMPLES)
def test_page_of_every_example_loads_draws_and_plays(example, example_runs, load):
    page = load(example_runs[example] / "view.html")
    assert page.js("return !!window.poinsotView"), page.console()
    player = page.js("var p = window.poinsotView.player; return {t0: p.t0, t1: p.t1, n: p.n};")
    assert player["n"] >= 2 and player["t1"] > player["t0"]

    covered, digest = page.pixels()
    assert covered > 0.001, f"{example}: the canvas is blank ({covered:.4f} of the pixels drawn)"

    page.seek_with_slider(player["t0"] + 0.6 * (player["t1"] - player["t0"]))
    assert page.js("return window.poinsotView.player.time") == pytest.approx(
        player["t0"] + 0.6 * (player["t1"] - player["t0"]))
    assert page.pixels()[1] != digest, f"{example}: moving the time slider left the pixels unchanged"
    label = page.js("return document.getElementById('time-label').textContent")
    assert label.startswith("t = ") and " s / " in label

    page.seek_with_slider(player["t0"])
    page.driver.find_element("id", "play").click()
    assert page.js("return window.poinsotView.player.playing")
    # The next animation frame moves the time on: however slowly the browser draws, it comes.
    page.wait_for("var p = window.poinsotView.player; return p.time > arguments[0];", f"{example} to play",
                  player["t0"])
    page.driver.find_element("id", "play").click()  # pause
    assert not page.js("return window.poinsotView.player.playing")

    bad = [e for e in page.console() if e["level"] in ("SEVERE", "WARNING")]
    assert not bad, f"{example}: the console says {bad}"


def test_page_is_self_contained(example_runs):
    """Opens from disk with no server or network: no external script, style or image."""
    text = (example_runs["tennis_racket.toml"] / "view.html").read_text(encoding="utf-8")
    for ref in ("<script src", "<link", "<img", "@import", "url(http"):
        assert ref not in text, ref
    assert "THREE.REVISION" in text or 'REVISION="111"' in text


@pytest.mark.parametrize("example", ["tennis_racket.toml"])
def test_keyboard_shortcuts_and_controls(example, example_runs, load):
    """The help panel's keys do what it says; the speed stays within 0.1x to 10x; a frame step lands on the
    next frame's time; the body-fixed camera keeps the body still on screen while it turns."""
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.keys import Keys

    page = load(example_runs[example] / "view.html")
    keys = ActionChains(page.driver)
    state = "var p = window.poinsotView.player; return [p.playing, p.time, p.speed, p.cameraMode];"
    assert page.js("return document.getElementById('help').hidden")
    keys.send_keys("h").perform()
    assert not page.js("return document.getElementById('help').hidden")
    assert page.js("return document.getElementById('help-keys').rows.length") >= 9
    keys.send_keys("h").perform()
    ActionChains(page.driver).send_keys("+" * 20).perform()  # one round trip for the 20 keys
    assert page.js(state)[2] == 10
    ActionChains(page.driver).send_keys("-" * 40).perform()
    assert page.js(state)[2] == pytest.approx(0.1)
    keys.send_keys(Keys.ARROW_RIGHT).perform()
    keys.send_keys(Keys.ARROW_RIGHT).perform()
    assert page.js(state)[1] == page.js("return window.poinsotView.data.t[2]")
    keys.send_keys(Keys.END).perform()
    assert page.js(state)[1] == page.js("return window.poinsotView.player.t1")
    visible = "return window.poinsotView.scene.children.filter(function (o) { return o.type === 'Mesh' &&" \
              " o.geometry.type === 'CircleGeometry'; })[0].visible"
    assert page.js(visible)  # the invariable plane, overlay 7
    keys.send_keys("7").perform()
    assert not page.js(visible) and not page.js("return document.getElementById('overlay-plane').checked")
    keys.send_keys("7").perform()
    assert page.js(visible)

    # Only the body and what it carries stay drawn: the body-fixed camera then sees a still picture.
    for overlay in ("plane", "herpolhode", "polhode", "L", "omega", "contact"):
        page.js("document.getElementById('overlay-' + arguments[0]).click();", overlay)
    page.seek_with_slider(1.0)
    page.changed_since()
    page.seek_with_slider(1.05)
    assert page.changed_since() > 0.005  # space-fixed camera: the body turns on screen
    keys.send_keys("c").perform()
    assert page.js(state)[3] == "body"
    page.seek_with_slider(1.0)
    page.changed_since()
    page.seek_with_slider(1.05)
    assert page.changed_since() < 0.001, "the body-fixed camera should show the body still"
    keys.send_keys(Keys.SPACE).perform()
    assert page.js(state)[0]
    keys.send_keys(Keys.SPACE).perform()
    assert not page.js(state)[0]
    assert not [e for e in page.console() if e["level"] in ("SEVERE", "WARNING")]
