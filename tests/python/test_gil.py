"""Solves release the GIL: Python code in another thread runs while one is inside a long C++ call."""

import threading
import time

import contactcert as cc
from conftest import SCENES


def test_other_thread_runs_during_a_batch():
    scene = cc.Scene.from_file(SCENES / "bt2002_section7_disk.json")
    wrenches = [[i % 7 - 3, -5 + i % 3, i % 5 - 2] for i in range(3000)]
    inside = threading.Event()
    done = threading.Event()

    def work():
        inside.set()
        scene.stability_many(wrenches)
        done.set()

    t = threading.Thread(target=work)
    t.start()
    inside.wait()
    time.sleep(0.005)  # let the worker enter the C++ call
    ticks = 0
    start = time.perf_counter()
    while not done.is_set():
        ticks += 1
    elapsed = time.perf_counter() - start
    t.join()
    # With the GIL held for the whole batch this loop could not run until the batch returned (a few ticks at
    # most, from the interpreter's switch interval before the call); released, it spins throughout.
    assert elapsed > 0.02, "the batch was too short to tell"
    assert ticks > 10000


def test_two_threads_agree_with_serial():
    wrenches = [[1, -2, 0], [-1, -1, 0], [0, -1, 0]] * 50
    scenes = [cc.Scene.from_file(SCENES / "bt2002_section7_disk.json") for _ in range(2)]
    serial = [s.to_dict()["verdict"] for s in scenes[0].stability_many(wrenches)]
    out = [None, None]

    def work(i):
        out[i] = [s.to_dict()["verdict"] for s in scenes[i].stability_many(wrenches)]

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert out == [serial, serial]
