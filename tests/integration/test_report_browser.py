"""The report opens in a real browser (Debian's chromium, headless) and every figure loads.

Skipped only when chromium is not installed (CI installs it: `apt-get install -y chromium`)."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import warnings

import pytest

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")

pytestmark = [pytest.mark.browser,
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
    page = report.report.read_text(encoding="utf-8")
    checked = tmp_path / "checked.html"
    checked.write_text(page.replace("</body>", _CHECK + "</body>"), encoding="utf-8")
    result = _chromium(tmp_path / "profile", "--virtual-time-budget=10000", "--dump-dom", checked.as_uri())
    match = re.search(r'<pre id="tg-image-check">([^<]*)</pre>', result.stdout)
    assert match, f"the page did not finish loading in chromium: {result.stderr[-2000:]}"
    state = json.loads(match.group(1))
    assert state["total"] == len(report.figures) >= 9
    assert state["loaded"] == state["total"], f"broken images: {state['broken']}"


def test_screenshot_shows_the_report(report, tmp_path):
    import numpy as np
    from matplotlib.image import imread

    shot = tmp_path / "shot.png"
    _chromium(tmp_path / "profile", "--window-size=1280,2400", f"--screenshot={shot}", report.report.as_uri())
    assert shot.is_file(), "chromium wrote no screenshot"
    pixels = imread(shot)
    assert pixels.shape[0] >= 2000 and pixels.shape[1] >= 1200
    # not a blank page: the first screen holds text, a table and the first figure
    assert float(np.std(pixels[..., :3])) > 0.05
