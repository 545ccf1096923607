#!/usr/bin/env python3
"""Per-call cost of the Python module against a CLI subprocess on the same queries (docs/bench.md), and the
batch stability form against single calls. Run by hand, not in CI:

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py [--cli build/cli/contactcert]
        [--cxx-bench build/bench/stability_bench]

With --cxx-bench, the C++ work of one verdict (BM_Verdict, 2 fixels, verified, cold and warm) is measured in the
same run and set beside the same query from Python.
"""

import argparse
import json
import os
import pathlib
import random
import resource
import subprocess
import tempfile
import threading
import time

import contactcert as cc

ROOT = pathlib.Path(__file__).resolve().parents[1]
SCENES = ROOT / "scenes"


def cpu():
    """CPU seconds of this process and of its waited-for children (the CLI subprocesses)."""
    me, kids = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return me.ru_utime + me.ru_stime + kids.ru_utime + kids.ru_stime


def per_call(f, min_seconds=0.5):
    """Median over 5 rounds of the mean CPU seconds per call of f() (CPU time: the machine is shared, and
    wall time counts the other processes' share)."""
    n, rounds = 1, []
    while True:
        t = time.perf_counter()
        for _ in range(n):
            f()
        if time.perf_counter() - t > min_seconds / 5:
            break
        n *= 2
    for _ in range(5):
        t = cpu()
        for _ in range(n):
            f()
        rounds.append((cpu() - t) / n)
    return sorted(rounds)[2]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", default=str(ROOT / "build" / "cli" / "contactcert"))
    ap.add_argument("--cxx-bench", help="build/bench/stability_bench, for the C++ work of the same verdict")
    args = ap.parse_args()

    def cli(*a):
        return lambda: subprocess.run([args.cli, *map(str, a), "--json"], capture_output=True, check=True)

    disk7 = cc.Scene.from_file(SCENES / "bt2002_section7_disk.json")
    disk4 = cc.Scene.from_file(SCENES / "bt2002_section4_disk.json")
    ds1 = cc.Ucp.from_file(SCENES / "pang1994_dataset1.json")
    text = disk7._core.stability("1,-2,0", "verified", False, "", 0)[0]
    queries = [
        ("section 7 stability g = (1, -2, 0)", lambda: disk7.stability("1,-2,0"),
         cli("stability", SCENES / "bt2002_section7_disk.json", "--wrench", "1,-2,0")),
        ("section 4 cone, mode na", lambda: disk4.cone("na"),
         cli("cone", SCENES / "bt2002_section4_disk.json", "--mode", "na")),
        ("Data Set 1, ucp complete verified", lambda: ds1.solve(),
         cli("ucp", SCENES / "pang1994_dataset1.json")),
    ]
    print(f"CPU time per call; {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    print(f"{'query':40s} {'python us':>10s} {'CLI us':>10s} {'ratio':>7s}")
    for name, py, sub in queries:
        p, c = per_call(py), per_call(sub)
        print(f"{name:40s} {p * 1e6:10.1f} {c * 1e6:10.1f} {c / p:7.1f}")
    raw = per_call(lambda: disk7._core.stability("1,-2,0", "verified", False, "", 0))
    wrap = per_call(lambda: json.loads(text))
    print(f"section 7 stability: _core call {raw * 1e6:.1f} us, json.loads of its result {wrap * 1e6:.1f} us")

    wrenches = [[i % 7 - 3, -5 + i % 3, i % 5 - 2] for i in range(1000)]
    disk7.stability_many(wrenches[:1])  # prepares the oracle once
    for _ in range(2):  # interleaved rounds (the machine is shared)
        batch_against_single(disk7, wrenches,
                             f"stability per wrench on the section 7 disk (load {os.getloadavg()[0]:.1f})")
    # Distinct wrenches (a batch reuses certificates across the cone each one proves, not only for repeats).
    rng = random.Random(5)
    distinct = sorted({(rng.randint(-1000, 1000), rng.randint(-1000, 1000), rng.randint(-1000, 1000))
                       for _ in range(1000)})
    batch_against_single(disk7, distinct, f"the same on {len(distinct)} distinct random wrenches in [-1000, 1000]^3")

    two_threads(wrenches)
    if args.cxx_bench:
        against_cxx(args.cxx_bench, args.cli)


def batch_against_single(scene, wrenches, label):
    """CPU time per wrench of single calls (on the first 100) and of stability_many. A batch result's object is
    built when first read: `verdicts read` reads each verdict only, `every object built` builds each result's
    object as a single call does."""
    single = per_call(lambda: [scene.stability(w).verdict for w in wrenches[:100]]) / 100
    batch = per_call(lambda: [s.verdict for s in scene.stability_many(wrenches)]) / len(wrenches)
    built = per_call(lambda: [s["witness"] for s in scene.stability_many(wrenches)]) / len(wrenches)
    print(f"{label}: single {single * 1e6:.1f} us; batch, verdicts read {batch * 1e6:.1f} us, ratio "
          f"{single / batch:.1f}; batch, every object built {built * 1e6:.1f} us, ratio {single / built:.1f}")


def two_threads(wrenches):
    """Wall time of two batches run one after the other and on two threads (one Scene each)."""
    scenes = [cc.Scene.from_file(SCENES / "bt2002_section7_disk.json") for _ in range(2)]
    for s in scenes:
        s.stability_many(wrenches[:1])
    t = time.perf_counter()
    for s in scenes:
        s.stability_many(wrenches)
    serial = time.perf_counter() - t
    threads = [threading.Thread(target=s.stability_many, args=(wrenches,)) for s in scenes]
    t = time.perf_counter()
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    parallel = time.perf_counter() - t
    print(f"two batches of {len(wrenches)}: serial {serial:.3f} s, two threads {parallel:.3f} s, "
          f"speed-up {serial / parallel:.2f}")


# The scene of bench/stability_bench.cpp's BM_Verdict: a unit disk touching (0,-1) and (1,0), mu = 1/2.
BENCH_DISK = {"kind": "planar", "workpiece": {"shape": {"type": "disk", "center": [0, 0], "radius": 1}, "mass": 1,
                                              "inertia": 1},
              "fixels": [{"position": [0, -1]}, {"position": [1, 0]}], "mu_s": "1/2", "mu_k": "1/2"}


def against_cxx(binary, cli_binary):
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        subprocess.run([binary, "--benchmark_filter=BM_Verdict/2/", f"--benchmark_out={out.name}",
                        "--benchmark_out_format=json", "--benchmark_min_time=0.2"], capture_output=True, check=True)
        cxx = {b["label"]: b["cpu_time"] * 1e-6 for b in json.load(open(out.name))["benchmarks"]}
    scene = cc.Scene.from_dict(BENCH_DISK)
    cold = per_call(lambda: scene.stability("0,-1,0"))
    scene.stability_many(["0,-1,0"])
    warm = per_call(lambda: scene.stability_many(["0,-1,0"] * 100)) / 100
    with tempfile.NamedTemporaryFile("w", suffix=".json") as f:
        json.dump(BENCH_DISK, f)
        f.flush()
        sub = per_call(lambda: subprocess.run([cli_binary, "stability", f.name, "--wrench", "0,-1,0", "--json"],
                                              capture_output=True, check=True))
    for label, py in (("verified cold, 2 fixels", cold), ("verified warm, 2 fixels", warm)):
        c = cxx[label]
        print(f"BM_Verdict {label}: C++ {c * 1e6:.1f} us, Python {py * 1e6:.1f} us, above the C++ work "
              f"{(py - c) * 1e6:.1f} us")
    c = cxx["verified cold, 2 fixels"]
    ratio = f"{(sub - c) / (cold - c):.0f}x the Python call's" if cold > c else "the Python call's is within the noise"
    print(f"the same verdict by the CLI: {sub * 1e6:.1f} us, above the C++ work {(sub - c) * 1e6:.1f} us ({ratio})")


if __name__ == "__main__":
    main()
