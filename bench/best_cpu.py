#!/usr/bin/env python3
"""The best user + sys CPU seconds of RUNS runs of a command (from getrusage of the children), for the side-by-side
scripts (bench/modes_peer.sh, bench/spatial_peer.sh).

    bench/best_cpu.py RUNS COMMAND [ARGS...]
"""
import resource
import subprocess
import sys

best = None
for _ in range(int(sys.argv[1])):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(sys.argv[2:], stdout=subprocess.DEVNULL, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    best = t if best is None else min(best, t)
print("%.4f" % best)
