"""Baney and Hui (1997), the Maugis-Dugdale cylinder on a flat, typed from issue 19 (tests only; mpmath).

    closure:  lam abar^2/2 [m sqrt(m^2-1) - ln(m + sqrt(m^2-1))] + lam^2 abar/2 [sqrt(m^2-1) ln(m + sqrt(m^2-1))
              - m ln m] = 1
    load:     Pbar = abar^2 - lam abar sqrt(m^2-1)

abar = a/[2 (w R^2/(pi E*))^(1/3)], Pbar = P/(pi E* w^2 R)^(1/3), m = c/a (zone end over contact half-width),
lam = 4 sigma0/(pi^2 E*^2 w/R)^(1/3).  Limits typed independently: JKR (lam -> inf, Barquins' cylinder,
Chaudhury's 2D JKR) Pbar = abar^2 - 2 sqrt(abar), pull-off -3/2^(4/3); the contactless limit abar -> 0 (the
zone alone, c = abar m finite): lam cbar^2/2 + lam^2 cbar ln(2)/2 = 1, Pbar = -lam cbar, and for lam -> 0 the
DMT-like pull-off -sqrt(2 lam).
"""
import mpmath as mp

DPS = 40


def closure(abar, m, lam):
    """Left side of the gap-closure equation minus 1."""
    sq = mp.sqrt(m * m - 1)
    ac = mp.log(m + sq)
    return lam * abar ** 2 / 2 * (m * sq - ac) + lam ** 2 * abar / 2 * (sq * ac - m * mp.log(m)) - 1


def zone_ratio(abar, lam):
    """m = c/a > 1 solving the closure at (abar, lam) (the left side increases with m)."""
    with mp.workdps(DPS):
        abar, lam = mp.mpf(abar), mp.mpf(lam)
        lo, hi = mp.mpf(1), mp.mpf(2)
        while closure(abar, hi, lam) < 0:
            lo, hi = hi, 2 * hi
        return mp.findroot(lambda x: closure(abar, x, lam), (lo, hi), solver="anderson")


def load(abar, lam):
    """Pbar at the contact half-width abar."""
    with mp.workdps(DPS):
        m = zone_ratio(abar, lam)
        abar, lam = mp.mpf(abar), mp.mpf(lam)
        return abar ** 2 - lam * abar * mp.sqrt(m * m - 1)


def touching_load(lam):
    """abar -> 0 (contact of zero width, the zone alone): lam cbar^2/2 + lam^2 cbar ln2/2 = 1, Pbar = -lam cbar."""
    with mp.workdps(DPS):
        lam = mp.mpf(lam)
        b = lam ** 2 * mp.log(2) / 2
        cbar = (-b + mp.sqrt(b * b + 2 * lam)) / lam
        return -lam * cbar


def pull_off(lam):
    """Load-control pull-off: the minimum of Pbar over abar > 0 (or its abar -> 0 limit when that is lower)."""
    with mp.workdps(DPS):
        f = lambda x: load(mp.exp(x), lam)
        # golden-section search in log abar between 1e-6 and 10 after a coarse scan
        xs = [mp.log(mp.mpf(10) ** (k / mp.mpf(8))) for k in range(-48, 9)]
        vals = [f(x) for x in xs]
        i = min(range(len(vals)), key=lambda j: vals[j])
        if i == 0:
            return min(vals[0], touching_load(lam))
        a, b = xs[i - 1], xs[min(i + 1, len(xs) - 1)]
        g = (mp.sqrt(5) - 1) / 2
        c, d = b - g * (b - a), a + g * (b - a)
        fc, fd = f(c), f(d)
        for _ in range(120):
            if fc < fd:
                b, d, fd = d, c, fc
                c = b - g * (b - a)
                fc = f(c)
            else:
                a, c, fc = c, d, fd
                d = a + g * (b - a)
                fd = f(d)
        return min(fc, fd, touching_load(lam))


def jkr_load(abar):
    """lam -> inf: Pbar = abar^2 - 2 sqrt(abar) (Barquins' half-plane JKR in these units)."""
    return mp.mpf(abar) ** 2 - 2 * mp.sqrt(abar)


JKR_PULL_OFF = -3 / mp.mpf(2) ** (mp.mpf(4) / 3)      # minimum of abar^2 - 2 sqrt(abar), at abar = 2^(-2/3)


def dmt_pull_off(lam):
    """lam -> 0: -sqrt(2 lam) (the zone alone at touching, lam cbar^2/2 = 1)."""
    return -mp.sqrt(2 * mp.mpf(lam))


# -Pbar_c printed in issue 19 (from Baney and Hui 1997 / the Adhesion package), three digits
PRINTED_PULL_OFF = {0.01: 0.141, 0.1: 0.444, 0.5: 0.917, 1: 1.113, 2: 1.180, 5: 1.190}
