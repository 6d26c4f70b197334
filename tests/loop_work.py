"""The work of a cycle's closed steady loop, int P d(delta), computed independently of the cycle's energies.

A reference for Cycle.dissipated (the sum of the energy each jump dissipates: jkrcyl.analysis.cycle.loop_energy,
from the states' total potentials).  Here no energy is read: the loop is cut into its pieces along one branch
(between jumps, leg turns and branch changes) and each piece's work is a quadrature over states solved alone at
the held value (Contact.solve), only the choice among the roots there taken from the recorded path.  The held
quantity x is the integration variable, so a jump (fixed x) adds nothing:

* load (x = P): int P d(delta) = -oint delta dP round a closed loop (parts);
* grip (x = delta): oint P d(delta) itself;
* grip-work (x = delta_work = delta + c P): oint P d(delta_work) = oint P d(delta) (oint P dP = 0).

A piece ending at a fold has y ~ sqrt(x_fold - x) there: with x = x0 + (x1 - x0)(1 - cos t)/2 the integrand is
smooth in t on [0, pi] (both ends), so Gauss-Legendre in t converges spectrally; the interval is halved where a
rule and its halves' disagree (a near-turn or a corner inside a piece: the cohesive zone closing at the top).
"""
import math

import numpy as np

FIELD = {"load": "P", "grip": "delta", "grip-work": "delta_work"}


def _runs(cy, legs):
    """Index runs of the loop's points: same leg and branch throughout, no jump between two of them (a jump may
    stay on its branch: the cohesive S's zip; the path records its two states, Cycle.jumps names them)."""
    idx = [i for i in range(len(cy.P)) if cy.leg[i] in legs]
    jumps = {(j.before.P, j.before.delta, j.after.P, j.after.delta) for j in cy.jumps}
    runs, cur = [], [idx[0]]
    for i in idx[1:]:
        k = cur[-1]
        jump = (cy.P[k], cy.delta[k], cy.P[i], cy.delta[i]) in jumps
        if cy.leg[i] == cy.leg[k] and cy.branch[i] == cy.branch[k] and not jump:
            cur.append(i)
        else:
            runs.append(cur)
            cur = [i]
    return runs + [cur]


def _pick(c, control, branch, x, a_guess):
    """The stable, feasible state of the branch at the held value x nearest to the path's contact there."""
    xs = [s for s in c.solve(**{FIELD[control]: x}, branches=[branch]) if s.stable and s.feasible and
          s.branch == branch]
    if not xs:
        raise AssertionError(f"no stable state of {branch} at {FIELD[control]} = {x!r}")
    return min(xs, key=lambda s: abs(math.atan(s.a) - a_guess))



def _gauss(f, t0, t1, n):
    u, w = np.polynomial.legendre.leggauss(n)
    t = t0 + 0.5 * (t1 - t0) * (u + 1.0)
    return 0.5 * (t1 - t0) * sum(wi * f(ti) for ti, wi in zip(t, w))


def piece_work(c, control, branch, ends, x, a, tol, n=10, depth=12):
    """(int y dx along one branch piece from ends[0] to ends[1], an error bound): y = delta under load, P under
    grip; x, a the recorded held values (monotone) and contact parameters over the piece (which root to take).
    Adaptive Gauss-Legendre in t (x = x0 + (x1 - x0)(1 - cos t)/2): an interval's n-node rule against its two
    halves' until they agree within tol (shared out by length) or after depth halvings."""
    x0, x1 = float(ends[0]), float(ends[1])
    if x0 == x1 or branch == "separated":        # the free pin: P = 0 (grip); a point (load)
        return 0.0, 0.0
    order = np.argsort(x)
    guess = lambda v: float(np.interp(v, np.asarray(x)[order], np.arctan(np.asarray(a, float))[order]))

    def f(t):
        xi = x0 + 0.5 * (x1 - x0) * (1.0 - math.cos(t))
        s = _pick(c, control, branch, xi, guess(xi))
        return (s.delta if control == "load" else s.P) * 0.5 * (x1 - x0) * math.sin(t)

    def adapt(t0, t1, whole, level):
        m = 0.5 * (t0 + t1)
        left, right = _gauss(f, t0, m, n), _gauss(f, m, t1, n)
        err = abs(left + right - whole)
        if err <= tol * (t1 - t0) / math.pi or level >= depth:
            return left + right, err
        (w0, e0), (w1, e1) = adapt(t0, m, left, level + 1), adapt(m, t1, right, level + 1)
        return w0 + w1, e0 + e1
    return adapt(0.0, math.pi, _gauss(f, 0.0, math.pi, n), 0)


def _pieces(cy, held, runs):
    """(branch, held values, contact parameters) of each run, a run and the next on the same branch across a leg's
    turn (at the limit, the loop's closing included) merged into one piece from the first's start to the second's
    end: the stretch driven past and back cancels (one branch, one state at each held value)."""
    pieces = [[cy.branch[r[0]], list(r)] for r in runs]
    k = 0
    while k < len(pieces) and len(pieces) > 1:
        (b, r), (b2, q) = pieces[k], pieces[(k + 1) % len(pieces)]
        turn = cy.leg[r[-1]] != cy.leg[q[0]] and (cy.P[r[-1]], cy.delta[r[-1]]) == (cy.P[q[0]], cy.delta[q[0]])
        if b == b2 and turn:
            pieces[k] = [b, r + q]
            del pieces[(k + 1) % len(pieces)]
            k = min(k, len(pieces) - 1) if k < len(pieces) else 0
            continue
        k += 1
    out = []
    for b, r in pieces:
        x = held[r]
        lo, hi = x[0], x[-1]
        span = max((abs(x[i] - x[0]), i) for i in range(len(x)))[1]       # the turn: the longer side covers both
        side = r[:span + 1] if abs(x[span] - x[0]) >= abs(x[span] - x[-1]) else r[span:]
        out.append((b, (lo, hi), held[side], cy.a[side]))
    return out


def loop_work(c, cy, tol=1e-10, depth=12):
    """(int P d(delta) round the cycle's steady loop [J/m], an error bound: the sum of the pieces').  Each piece
    by :func:`piece_work` to tol of the loop's scale load_scale Delta.  Between two pieces the path is a jump at
    the held value (nothing) or, where a branch goes on as another at a different held value, the straight
    segment between them (its trapezoid)."""
    control = cy.control
    held = {"load": cy.P, "grip": cy.delta, "grip-work": cy.delta_work}[control]
    other = cy.delta if control == "load" else cy.P
    runs = _runs(cy, (cy.closed_from_leg, cy.closed_from_leg + 1))
    total, error = 0.0, 0.0
    for branch, ends, x, a in _pieces(cy, held, runs):
        w, e = piece_work(c, control, branch, ends, x, a, tol * c.load_scale * c.Delta, depth=depth)
        total, error = total + w, error + e
    for r, q in zip(runs, runs[1:]):
        i, j = r[-1], q[0]
        total += 0.5 * (other[i] + other[j]) * (held[j] - held[i])
    return (-total if control == "load" else total), error
