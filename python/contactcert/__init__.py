"""contactcert: exact answers for planar rigid bodies in frictional contact, in-process.

Scene (wrench cones, strong stability, stable regions, finger pushes, insertion), design (fixture design),
convert (a cone's other form), Ucp (the quasistatic contact problem) and Motion (quasistatic time-stepping) run the
same C++ code as the contactcert CLI; every result's to_dict() is the CLI's --json object for the same query. Exact
numbers are fractions.Fraction (inputs: int, str or Fraction). See
docs/python.md. `python -m contactcert ARGS` runs the CLI itself.
Assembly (several bodies: stability from rest, the quasistatic problem) likewise runs `contactcert assembly`;
SpatialScene (a body in space) lists its contact modes as `contactcert modes` does and decides its strong
stability as `contactcert stability` does;
demo and bench run `contactcert demo` and `contactcert bench`.
"""

from ._assembly import Assembly, AssemblyStability, AssemblyUcp
from ._core import BudgetExceeded, __version__
from ._demo_bench import Bench, Demo, bench, demo
from ._design import Converted, Design, convert, design
from ._motion import Motion, Simulation, Step
from ._results import Certificate, CheckResult, Cone, Contact, Finger, Insertion, Modes, Region, Stability, UcpResult
from ._results import SpatialStability
from ._certificate import check
from ._scene import Scene, Snap
from ._spatial import SpatialScene
from ._ucp import Ucp, generate_random, generate_reduction

__all__ = ["BudgetExceeded", "Certificate", "CheckResult", "Cone", "Contact", "Converted", "Design", "Finger",
           "Insertion", "Region", "Scene", "Snap", "Modes", "Stability", "Ucp", "UcpResult", "check", "convert",
           "design", "generate_random", "generate_reduction", "Motion", "Simulation", "Step"]
__all__ += ["Assembly", "AssemblyStability", "AssemblyUcp"]
__all__ += ["Bench", "Demo", "bench", "demo"]
__all__ += ["SpatialScene", "SpatialStability"]
