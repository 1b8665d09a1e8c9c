"""Every example's view.html in a real browser: it loads with no console error or warning, draws something,
redraws when the time slider moves, and plays."""
import time

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
    deadline = time.monotonic() + 3.0  # software rendering may draw few frames a second
    while True:
        time.sleep(0.1)
        state = page.js("var p = window.poinsotView.player; return [p.playing, p.time];")
        if state[1] > player["t0"] or time.monotonic() > deadline:
            break
    assert state[0] and state[1] > player["t0"], f"{example}: play did not advance the time: {state}"
    page.driver.find_element("id", "play").click()  # pause

    bad = [e for e in page.console() if e["level"] in ("SEVERE", "WARNING")]
    assert not bad, f"{example}: the console says {bad}"


def test_page_is_self_contained(example_runs):
    """Opens from disk with no server or network: no external script, style or image."""
    text = (example_runs["tennis_racket.toml"] / "view.html").read_text(encoding="utf-8")
    for ref in ("<script src", "<link", "<img", "@import", "url(http"):
        assert ref not in text, ref
    assert "THREE.REVISION" in text or 'REVISION="111"' in text
