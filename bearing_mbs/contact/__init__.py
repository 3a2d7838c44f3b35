"""Contact laws and pair kinematics (pure functions), and the two evaluators of a scene's forces.

* :mod:`.normal` — normal force laws (power, Lankarani–Nikravesh, Hunt–Crossley, Flores, Gonthier).
* :mod:`.friction` — regularised Coulomb friction (erf, tanh, linear), the document's dead zone, rolling
  resistance.
* :mod:`.kinematics` — gap, normal, gap rate and slip for circle–line, circle–circle, circle inside a
  hollow circle and circle–point pairs.
* :mod:`.kernel` — the compiled (numba) evaluation of all pairs, loads and drives of a scene.
* :mod:`.twin` — its readable numpy twin.
* :mod:`.lubricant` — a lubricant's viscosity and density against temperature (ASTM D341).

Nothing here imports an engine.
"""

from bearing_mbs.contact.friction import FRICTION_LAWS, FRICTION_SIGN, ZERO_SLIP_SLOPE
from bearing_mbs.contact.kernel import PAIR_OUTPUTS
from bearing_mbs.contact.kinematics import PAIR_KINDS
from bearing_mbs.contact.normal import DAMPING_FACTOR, NORMAL_LAWS

__all__ = [
    "DAMPING_FACTOR",
    "FRICTION_LAWS",
    "FRICTION_SIGN",
    "NORMAL_LAWS",
    "PAIR_KINDS",
    "PAIR_OUTPUTS",
    "ZERO_SLIP_SLOPE",
]
