"""poinsot.view: the page written through the library's writer (the same bytes as `poinsot view`)."""
import json

import pytest

import poinsot


def test_view_writes_the_page_of_a_run(tmp_path):
    r = poinsot.run({"body": {"principal_moments": [1, 2, 3]}, "initial": {"omega_body": [0.1, 2, 0.1]},
                     "integrator": {"method": "exact"}, "output": {"t_end": 3, "sample_dt": 0.01}},
                    out_dir=tmp_path / "run")
    path = poinsot.view(r, display=False)
    assert path == str(tmp_path / "run" / "view.html")
    page = (tmp_path / "run" / "view.html").read_text(encoding="utf-8")
    data = json.loads(poinsot._core.view_data_json(str(tmp_path / "run")))
    assert data["samples"] == 301 and data["frames"] == 301 and data["kind"] == "body"
    start = page.index('<script id="poinsot-data" type="application/json">') + len(
        '<script id="poinsot-data" type="application/json">')
    assert json.loads(page[start:page.index("</script>", start)]) == data  # the page holds the io layer's data
    # Decimated: at most the frames asked for; the same folder given as a path.
    assert poinsot.view(tmp_path / "run", frames=50, display=False) == path
    assert json.loads(poinsot._core.view_data_json(str(tmp_path / "run"), 50))["frames"] <= 50


def test_view_refuses_what_is_not_a_finished_run(tmp_path):
    with pytest.raises(ValueError, match="has no summary.json"):
        poinsot.view(tmp_path, display=False)
    r = poinsot.run({"body": {"principal_moments": [1, 2, 3]}, "initial": {"omega_body": [0.1, 2, 0.1]},
                     "output": {"t_end": 0.1}})
    with pytest.raises(ValueError, match="no run folder"):
        poinsot.view(r, display=False)
    with pytest.raises(ValueError, match="--frames 1 is out of range"):
        poinsot.view(tmp_path, frames=1, display=False)
    assert list(tmp_path.iterdir()) == []


def test_view_shows_the_page_inline_in_jupyter(tmp_path, monkeypatch):
    """With display=True the page goes to IPython.display as an iframe holding the whole page (srcdoc), so the
    notebook needs no server for it; a stand-in IPython records what was shown."""
    import html
    import sys
    import types

    shown = []
    fake = types.ModuleType("IPython.display")
    fake.HTML = lambda text: ("HTML", text)
    fake.display = shown.append
    monkeypatch.setitem(sys.modules, "IPython", types.ModuleType("IPython"))
    monkeypatch.setitem(sys.modules, "IPython.display", fake)
    r = poinsot.run({"body": {"principal_moments": [1, 2, 3]}, "initial": {"omega_body": [0.1, 2, 0.1]},
                     "output": {"t_end": 1, "sample_dt": 0.01}}, out_dir=tmp_path / "run")
    path = poinsot.view(r, display=True, height=500)
    assert len(shown) == 1 and shown[0][0] == "HTML"
    frame = shown[0][1]
    assert frame.startswith('<iframe srcdoc="') and "height: 500px" in frame
    page = open(path, encoding="utf-8").read()
    assert html.unescape(frame[len('<iframe srcdoc="'):frame.index('" style=')]) == page
