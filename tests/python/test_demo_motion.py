"""`demo` on a scenes folder that holds a motion scene (issue 30): the scene is simulated for its first steps (at most
three) and listed as a motion, never as "not read"; Python's demo and the CLI's agree."""
import shutil

import contactcert as cc
from conftest import SCENES, cli_json


def test_a_motion_scene_is_simulated_not_refused(tmp_path):
    d = tmp_path / "scenes"
    d.mkdir()
    shutil.copy(SCENES / "motion_pushed_box.json", d / "motion_pushed_box.json")
    shutil.copy(SCENES / "motion_block_wall.json", d / "motion_block_wall.json")
    got = cc.demo(scenes=d, out=tmp_path / "out")
    rows = got["scenes_of_folder"]
    assert [(r["file"], r["kind"]) for r in rows] == [("motion_block_wall.json", "motion"),
                                                     ("motion_pushed_box.json", "motion")]
    assert all(r["verdict"] != "not read" for r in rows)
    assert rows[1]["evidence"].startswith("3 of its 5 steps simulated (dt = 1/10)")
    cli = cli_json("demo", "--scenes", d, "--out", tmp_path / "cli")
    assert cli["scenes_of_folder"] == rows
