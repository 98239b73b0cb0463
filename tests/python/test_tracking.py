"""``python -m bonl control`` and bonl.experiment.run_tracking_experiment (docs/how-to/control.md, "Tracking
on the plant"): the JSON it writes is the C++ experiment's, the acceptance of issue 20 holds on the
numbers computed here, and the run's pieces agree with independent recomputations."""

import json
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import bonl
from figures import FIGURE_REL

ROOT = pathlib.Path(__file__).resolve().parents[2]
MODELS = ["ARX", "Hammerstein", "HammersteinWiener", "PrandtlIshlinskiiHammerstein", "PseudoHammersteinWiener"]


@pytest.fixture(scope="module")
def result():
    return bonl.experiment.run_tracking_experiment()


def test_the_cli_writes_the_tracking_rms_of_every_controller_and_a_figure(tmp_path, result):
    out = subprocess.run([sys.executable, "-m", "bonl", "control", "--json", str(tmp_path / "t.json"), "--figure",
                          str(tmp_path / "t.png")], capture_output=True, text=True, timeout=300, check=False)
    assert out.returncode == 0, out.stderr
    assert "PI + P-H-W (adaptive)" in out.stdout
    document = json.loads((tmp_path / "t.json").read_text())
    assert set(document["tracking_rms"]) == {"PI", *MODELS, "PseudoHammersteinWiener (exact switch)"}
    assert document["tracking_rms"] == pytest.approx(result.tracking_rms, rel=1e-12)
    assert set(document["plant_change"]) == {"PI", "PseudoHammersteinWiener", "PseudoHammersteinWiener (adaptive)"}
    assert (tmp_path / "t.png").read_bytes().startswith(b"\x89PNG\r\n\x1a\n")
    assert subprocess.run([sys.executable, "-m", "bonl", "control", "--method", "mrlsa"], capture_output=True,
                          check=False).returncode == 2


def test_the_p_h_w_feedforward_tracks_better_than_the_pi_loop_alone_and_the_other_models(result):
    rms = result.tracking_rms
    assert rms["PseudoHammersteinWiener"] <= 0.6 * rms["PI"]
    assert rms["PseudoHammersteinWiener"] < min(rms[name] for name in MODELS if name != "PseudoHammersteinWiener")
    adaptive = result.run("PseudoHammersteinWiener (adaptive)", True)
    fixed = result.run("PseudoHammersteinWiener", True)
    assert adaptive.rms_after_change <= 1.2 * adaptive.rms_before_change
    assert fixed.rms_after_change > 1.2 * fixed.rms_before_change


def test_each_run_is_scored_as_documented(result):
    # The RMS recomputed from the run's joint rate and the reference, over the windows docs/how-to/control.md names.
    t = result.time
    assert len(t) == 8000 and t[1] == pytest.approx(0.01)
    for run in result.runs:
        error = result.reference - run.joint_rate

        def window(a, b, error=error):
            return np.sqrt(np.mean(error[int(a * 100):int(b * 100)] ** 2))

        assert run.rms == pytest.approx(window(20, 80), rel=1e-12), run.controller
        assert run.rms_before_change == pytest.approx(window(20, 40), rel=1e-12)
        assert run.rms_after_change == pytest.approx(window(60, 80), rel=1e-12)
        assert np.all((run.command >= 0) & (run.command <= 5))
    assert np.all(result.run("PI").feedforward == 0)
    assert [run.label for run in result.runs] == [
        "PI", "PI + ARX", "PI + Hammerstein", "PI + H-W", "PI + P-I-H", "PI + P-H-W", "PI + P-H-W (exact switch)",
        "PI", "PI + P-H-W", "PI + P-H-W (adaptive)"]
    with pytest.raises(ValueError, match="tracking: no run of 'LQR'"):
        result.run("LQR")
    with pytest.raises(ValueError, match="method"):
        bonl.experiment.run_tracking_experiment(method="mrlsa")


def test_the_committed_tracking_figures_are_what_the_experiment_gives(result):
    """docs/results/tracking.json (bonl_demo --control --json, scripts/tracking.sh)."""
    committed = json.loads((ROOT / "docs" / "results" / "tracking.json").read_text())
    assert set(committed["tracking_rms"]) == set(result.tracking_rms)
    for name, value in committed["tracking_rms"].items():
        assert result.tracking_rms[name] == pytest.approx(value, rel=FIGURE_REL), name
    for name, entry in committed["plant_change"].items():
        run = result.run(name, True)
        assert run.rms_before_change == pytest.approx(entry["before"], rel=FIGURE_REL), name
        assert run.rms_after_change == pytest.approx(entry["after"], rel=FIGURE_REL), name
    assert result.proportional_gain == pytest.approx(committed["pi"]["proportional_gain"], rel=FIGURE_REL)
