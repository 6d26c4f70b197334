"""What the library answers, one naming throughout: states (:mod:`.states`), branches (:mod:`.curves`) and paths
(:mod:`.paths`).  Normalised fields (section 6) are always there -- a, eps [rad], eps_star, P_star,
delta_over_Delta, delta_work_over_Delta, h_pi_over_Delta, feasible, stable_load, stable_grip, stable_grip_work --
and the dimensional ones -- P [N/m], delta, delta_work, contact_width, h_pi [m] -- wherever a Contact made the
result (None otherwise), through one :class:`jkrcyl.units.Units` (``Contact.units``; ``with_units`` on a normalised
result).  The names a control's held quantity goes by in each scale are :data:`jkrcyl.units.CONTROLS`.  P_star
and M are P_R* and M_R* of (7.6) for vartheta = inf.

Every result type, by kind of answer (what returns it):

==============  =================================================================================================
state           :class:`Equilibrium` (Contact.solve: one patch, two patches, full contact or separated, with its
                stability) and its subtype :class:`Point` (Contact.adherence, jkrcyl.equilibria.stationary_points:
                the equilibrium at a fold of a branch, with its kind and outcome); jkrcyl.State (Contact.state:
                the fields at given contact parameters, arrays); :class:`TwoPatchState`, :class:`FullContact`
                (jkrcyl.equilibria, normalised, with the solver's own fields)
branch          :class:`Curve` (Contact.curve), :class:`TwoPatchCurve` (Contact.two_patch)
path and cycle  :class:`Cycle` with its :class:`Jump` list (Contact.cycle); jkrcyl.kinetics.RateCycle and
                jkrcyl.kinetics.History (at a rate, crack kinetics); :class:`ConfinedEvents`
pull-off        :class:`PullOff` (Contact.pull_off); jkrcyl.kinetics.RatePullOff (at a rate, a PullOff);
                jkrcyl.kinetics.RateSweep (pull-off against rate)
fit             jkrcyl.fit.FitResult (jkrcyl.fit.fit)
==============  =================================================================================================
"""
from .curves import Curve, Point, TwoPatchCurve
from .paths import ConfinedEvents, Cycle, Jump, PullOff
from .states import Equilibrium, FullContact, TwoPatchState

__all__ = ["ConfinedEvents", "Curve", "Cycle", "Equilibrium", "FullContact", "Jump", "Point", "PullOff",
           "TwoPatchCurve", "TwoPatchState"]
