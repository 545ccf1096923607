"""SpatialScene.stability (issue 34): the verdicts of the bundled box on a plane as the CLI gives them
(to_dict() == --json), with the certificate checked (tests/cli/cases/hostile_stab34.sh has the CLI's side)."""

from __future__ import annotations

import json
import os
import subprocess
from fractions import Fraction
from pathlib import Path

import contactcert

SCENES = Path(__file__).resolve().parents[2] / "scenes"
BOX = SCENES / "spatial_box_on_plane.json"


def test_box_under_gravity_is_strongly_stable_and_its_certificate_checks(tmp_path: Path) -> None:
    box = contactcert.SpatialScene.from_file(BOX)
    r = box.stability((0, 0, -1, 0, 0, 0), certificate=tmp_path / "c.json")
    assert r.verdict == "strongly_stable"
    assert r.moving_mode is None and r.resting_forces is not None
    assert sum(f[2] for f in r.resting_forces) == 1  # the normal forces carry the weight
    assert r.certificate is not None
    assert contactcert.check(tmp_path / "c.json").valid


def test_box_past_atan_mu_slides() -> None:
    r = contactcert.SpatialScene.from_file(BOX).stability(("3/5", 0, -1, 0, 0, 0))
    assert r.verdict == "unstable"
    assert r.moving_mode == "EEEE"
    assert r.acceleration == (Fraction(1, 10), 0, 0, 0, 0, 0)


def test_to_dict_is_the_cli_json() -> None:
    cli = os.environ.get("CONTACTCERT_CLI")
    if not cli:
        return
    out = subprocess.run([cli, "stability", str(BOX), "--wrench", "0,0,-1,0,2,0", "--json"], check=True,
                         capture_output=True, text=True).stdout
    assert contactcert.SpatialScene.from_file(BOX).stability((0, 0, -1, 0, 2, 0)).to_dict() == json.loads(out)


def test_cone_of_the_all_separating_mode() -> None:
    """ssss: four strict rows 5 f_z + 12 (y tau_x - x tau_y) > 0 at the corners (x, y) = (+-1, +-1) (I = 5/12)."""
    cone = contactcert.SpatialScene.from_file(BOX).cone("ssss").to_dict()
    assert cone["kind"] == "spatial" and cone["mode"] == "ssss"
    assert cone["cone"]["dimension"] == 6
    assert len(cone["cone"]["face"]["strict"]) == 4
