"""contactcert: exact answers for planar rigid bodies in frictional contact, in-process.

Scene (wrench cones, strong stability, stable regions, finger pushes, insertion) and Ucp (the quasistatic
contact problem) run the same C++ code as the contactcert CLI; every result's to_dict() is the CLI's --json
object for the same query. Exact numbers are fractions.Fraction (inputs: int, str or Fraction). See
docs/python.md. `python -m contactcert ARGS` runs the CLI itself.
Assembly (several bodies: stability from rest, the quasistatic problem) likewise runs `contactcert assembly`.
"""

from ._assembly import Assembly, AssemblyStability, AssemblyUcp
from ._core import BudgetExceeded, __version__
from ._results import CheckResult, Cone, Finger, Insertion, Modes, Region, Stability, UcpResult
from ._scene import Scene, Snap
from ._ucp import Certificate, Ucp, check, generate_random, generate_reduction

__all__ = ["BudgetExceeded", "Certificate", "CheckResult", "Cone", "Finger", "Insertion", "Region", "Scene", "Snap",
           "Modes", "Stability", "Ucp", "UcpResult", "check", "generate_random", "generate_reduction"]
__all__ += ["Assembly", "AssemblyStability", "AssemblyUcp"]
