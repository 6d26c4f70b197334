"""Edge laws: what holds the contact edge, the extension point of jkrcyl.

``jkrcyl.Contact(..., law=...)`` takes any law; every analysis reaches it only through the interface of
jkrcyl.model.edge_law (:class:`EdgeLaw`, dimensional) and jkrcyl.model.edge (:class:`Edge`, normalised).

* :class:`Griffith` -- JKR (the default): the edge a crack with critical energy release rate w (3.5)-(3.6);
* :class:`Dugdale` -- the Maugis-Dugdale cohesive zone of strength sigma0 and range h0 = w/sigma0;
* :class:`Kinetic` -- JKR with crack kinetics, G = w [1 + (v/v*)^n] at an opening edge (JKR at rest; time
  histories in jkrcyl.kinetics); :func:`CrackKinetics` its common case, :func:`wlf_shift`, :func:`arrhenius_shift`
  the temperature shift of v*.

Each has its normalised twin (:class:`GriffithEdge`, the one instance :data:`GRIFFITH_EDGE`; :class:`DugdaleEdge`),
what the model core asks (jkrcyl.model.edge).

A law of one's own subclasses one of them (or both classes of jkrcyl.model.edge); e.g. an edge whose critical
energy release rate is twice w:

>>> import jkrcyl
>>> class Doubled(jkrcyl.laws.Griffith):
...     def edge_work(self, w):
...         return 2 * w
>>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
>>> a = jkrcyl.Contact(R=1e-2, Delta=1e-6, w=0.025, materials=m, law=Doubled()).pull_off().P
>>> b = jkrcyl.Contact(R=1e-2, Delta=1e-6, w=0.05, materials=m).pull_off().P
>>> round(a), abs(a / b - 1) < 1e-12                  # N/m: JKR's pull-off at 2w
(-1555, True)
"""
from ..model.edge import Edge
from ..model.edge_law import EdgeLaw
from .dugdale import Dugdale, DugdaleEdge
from .griffith import GRIFFITH_EDGE, Griffith, GriffithEdge
from .kinetic import CrackKinetics, Kinetic, arrhenius_shift, wlf_shift

__all__ = ["Edge", "EdgeLaw", "Griffith", "GriffithEdge", "GRIFFITH_EDGE", "Dugdale", "DugdaleEdge", "Kinetic",
           "CrackKinetics", "wlf_shift", "arrhenius_shift"]
