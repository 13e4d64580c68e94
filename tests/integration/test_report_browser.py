"""The report opens in a real browser (Debian's chromium, headless): every figure loads, and the first screen
(1280 × 800) shows the headline block (case, predictions within tolerance, known gaps, key figures).

Skipped only when chromium is not installed (CI installs it: `apt-get install -y chromium`)."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import warnings

import pytest

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")

# one test worker builds each report once for all the tests of the module (pytest-xdist --dist loadgroup)
pytestmark = [pytest.mark.browser, pytest.mark.xdist_group(name="report-browser"),
              pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed (apt-get install -y chromium)")]

_CHECK = ("<script>window.addEventListener('load',function(){var im=document.images,ok=0,bad=[];"
          "for(var i=0;i<im.length;i++){if(im[i].complete&&im[i].naturalWidth>0){ok++}else{bad.push(i)}}"
          "var d=document.createElement('pre');d.id='tg-image-check';"
          "d.textContent=JSON.stringify({total:im.length,loaded:ok,broken:bad});document.body.appendChild(d);});"
          "</script>")


def _chromium(profile, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                           "--disable-component-update", "--disable-sync", "--no-first-run",
                           f"--user-data-dir={profile}", *args], capture_output=True, text=True, timeout=120)


def _page_state(report_page, script: str, marker: str, tmp_path, *arguments: str) -> dict:
    """Open the report with ``script`` added in chromium and return the JSON that the script wrote into the
    element ``marker`` once the page had loaded."""
    checked = tmp_path / f"{marker}.html"
    checked.write_text(report_page.read_text(encoding="utf-8").replace("</body>", script + "</body>"),
                       encoding="utf-8")
    result = _chromium(tmp_path / "profile", *arguments, "--virtual-time-budget=10000", "--dump-dom",
                       checked.as_uri())
    match = re.search(f'<pre id="{marker}">([^<]*)</pre>', result.stdout)
    assert match, f"the page did not finish loading in chromium: {result.stderr[-2000:]}"
    return json.loads(match.group(1))


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    from thermogear.case import load_case
    from thermogear.report.build import build_report

    out = tmp_path_factory.mktemp("browser") / "report"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        outcome = build_report(load_case("luo2019"), out)
    return outcome


def test_every_image_loads(report, tmp_path):
    state = _page_state(report.report, _CHECK, "tg-image-check", tmp_path)
    assert state["total"] >= len(report.figures) >= 9  # every figure, plus the key figures of the headline
    assert state["loaded"] == state["total"], f"broken images: {state['broken']}"


_HEADLINE = ("<script>window.addEventListener('load',function(){function box(id){var e=document.getElementById(id);"
             "if(!e){return null}var r=e.getBoundingClientRect();return {top:r.top,bottom:r.bottom,left:r.left,"
             "right:r.right}}var d=document.createElement('pre');d.id='tg-headline-check';"
             "d.textContent=JSON.stringify({viewport:[window.innerWidth,window.innerHeight],"
             "headline:box('headline'),numbers:box('headline-numbers'),paper:box('paper')});"
             "document.body.appendChild(d);});</script>")
FIRST_SCREEN = (1280, 800)


def test_headline_is_on_the_first_screen(report, tmp_path):
    """Chromium lays the page out in a 1280 × 800 window: the headline block starts on the first screen and its
    numbers (predictions within, known gaps) lie wholly inside it; the long table starts below it."""
    state = _page_state(report.report, _HEADLINE, "tg-headline-check", tmp_path,
                        f"--window-size={FIRST_SCREEN[0]},{FIRST_SCREEN[1]}")
    width, height = state["viewport"]
    assert state["headline"] is not None and state["numbers"] is not None, "no headline block in the page"
    assert 0 <= state["headline"]["top"] < height / 2, state
    assert 0 <= state["numbers"]["top"] and state["numbers"]["bottom"] <= height, state
    assert state["numbers"]["right"] <= width, state
    assert state["paper"]["top"] > height, "the long table must not push the headline off the first screen"


def test_screenshot_shows_the_report(report, tmp_path):
    import numpy as np
    from matplotlib.image import imread

    shot = tmp_path / "shot.png"
    _chromium(tmp_path / "profile", "--hide-scrollbars", f"--window-size={FIRST_SCREEN[0]},{FIRST_SCREEN[1]}",
              f"--screenshot={shot}", report.report.as_uri())
    assert shot.is_file(), "chromium wrote no screenshot"
    pixels = imread(shot)
    assert pixels.shape[0] == FIRST_SCREEN[1] and pixels.shape[1] == FIRST_SCREEN[0]
    # not a blank page: the first screen holds text and the key figures
    assert float(np.std(pixels[..., :3])) > 0.05
    # the headline block's tinted background (#f7fafc) fills a good part of the first screen
    tint = np.all(np.abs(pixels[..., :3] - np.array([0xF7, 0xFA, 0xFC]) / 255.0) < 0.01, axis=-1)
    assert tint.mean() > 0.15, tint.mean()


@pytest.fixture(scope="module")
def drivetrain_report(tmp_path_factory):
    from pathlib import Path

    from thermogear.case import load_case
    from thermogear.report.build import build_report

    out = tmp_path_factory.mktemp("browser") / "drivetrain"
    case = Path(__file__).resolve().parents[1] / "data" / "two_shaft_drivetrain.toml"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return build_report(load_case(case), out)


_PICTURE_CHECK = ("<script>window.addEventListener('load',function(){var r={};"
                  "['drivetrain_layout','drivetrain_modes','drivetrain_campbell','drivetrain_bearing_spectra']"
                  ".forEach(function(n){var f=document.getElementById(n);var i=f&&f.querySelector('img');"
                  "r[n]=i?{loaded:i.complete&&i.naturalWidth>0,width:i.getBoundingClientRect().width,"
                  "height:i.getBoundingClientRect().height}:null});var a=document.querySelector("
                  "\"a[href='#drivetrain_layout']\");r.link=a?a.getBoundingClientRect().top:null;"
                  "var d=document.createElement('pre');d.id='tg-picture-check';d.textContent=JSON.stringify(r);"
                  "document.body.appendChild(d);});</script>")


def test_the_drivetrain_pictures_load_and_are_readable_in_the_page(drivetrain_report, tmp_path):
    """Chromium at 1280 × 800: each of the four drivetrain pictures loads and is laid out at a readable size (at
    least 600 px wide: the page's 1180 px column, not a thumbnail), and the link to them is on the first screen."""
    state = _page_state(drivetrain_report.report, _PICTURE_CHECK, "tg-picture-check", tmp_path,
                        f"--window-size={FIRST_SCREEN[0]},{FIRST_SCREEN[1]}")
    for name in ("drivetrain_layout", "drivetrain_modes", "drivetrain_campbell", "drivetrain_bearing_spectra"):
        assert state[name] is not None and state[name]["loaded"], (name, state)
        assert state[name]["width"] >= 600 and state[name]["height"] >= 250, (name, state)
    assert state["link"] is not None and 0 <= state["link"] < FIRST_SCREEN[1], state
