"""The one rule by which a refinement ladder proves an error bar, for both models' tables
(scripts/fem_study_table.py, scripts/sbm_study_table.py); the code's bars use the same rule in
C++ (include/gradfric/core/refinement_ladder.hpp, tested against known limits).

Three results at ratio 2 (coarse, medium, fine), deterministic or ensemble means (mean, standard
error, realisations): a statistical ladder proves nothing unless each difference exceeds its 95 %
half-width; it converges when the second difference stays below 1/sqrt(2) of the first (observed
order p > 0.5) across both half-widths; then Roache's GCI about the Richardson extrapolation (p
capped at 2) if the differences keep their sign, or the bracket of the last two values if they
alternate, each widened by its half-width and times 1.25.
"""
import math


def _t95(dof):
    from scipy.stats import t as student  # only statistical ladders need it
    return student.ppf(0.975, dof)


def _half(rungs, c):
    """95 % half-width of sum c_i value_i; rungs are (value, se, realisations); 0 if deterministic."""
    used = [r for r, k in zip(rungs, c) if k and r[1]]
    if not used:
        return 0.0
    var = sum((k * r[1]) ** 2 for r, k in zip(rungs, c))
    return _t95(min(r[2] for r in used) - 1) * math.sqrt(var)


def judge(rungs, member):
    """rungs: three values, or three (value, standard error, realisations). Returns a dict: outcome
    ('no signal', 'not converged', 'monotone', 'oscillating'), first, second, h1, h2, order,
    extrapolated (monotone), bound (relative, of the member; None if not converged)."""
    rungs = [r if isinstance(r, tuple) else (r, 0.0, 0) for r in rungs]
    a, b, c = (r[0] for r in rungs)
    first, second = b - a, c - b
    h1, h2 = _half(rungs, (-1, 1, 0)), _half(rungs, (0, -1, 1))
    order = math.log2(abs(first / second)) if second and first else (-math.inf if second else math.inf)
    v = dict(first=first, second=second, h1=h1, h2=h2, order=order, extrapolated=None, bound=None)
    statistical = any(r[1] for r in rungs)
    if statistical and (abs(first) <= h1 or abs(second) <= h2):
        return dict(v, outcome="no signal")
    if not abs(second) + h2 < (abs(first) - h1) / math.sqrt(2):
        return dict(v, outcome="not converged")
    run = rungs[member][0]
    if first * second <= 0:  # alternating: the limit lies between the last two values
        far = 1 if abs(run - b) > abs(run - c) else 2
        coeff = [0, 0, 0]
        coeff[member] += 1
        coeff[far] -= 1
        return dict(v, outcome="oscillating", bound=1.25 * (abs(run - rungs[far][0]) + _half(rungs, coeff)) / abs(c))
    ratio = 1 / (2 ** min(order, 2) - 1)
    ext = c + ratio * second
    coeff = [0, ratio, -1 - ratio]
    coeff[member] += 1
    return dict(v, outcome="monotone", extrapolated=ext,
                bound=1.25 * (abs(run - ext) + _half(rungs, coeff)) / abs(ext))


def finer_not_converged(ladders, i):
    """The coarsest mesh of the first ladder finer than ladders[i] that does not converge, or None.
    ladders: [(n, rungs)], coarsest first. Such a ladder takes the bar of ladders[i] away (as in the
    code's bars); one without a signal disproves nothing."""
    return next((n for n, rungs in ladders[i + 1:] if judge(rungs, 0)["outcome"] == "not converged"), None)


def through_finer(ladders, i):
    """A ladder ladders[i] that proves no bound (not converged, or no signal) still bounds its coarsest member through the finest
    value of the finer ladders, when there are some and every one converges (as the code's bars):
    |mu - mu_lim| <= |mu - mu_f| + f's bound. Returns (finest mesh, bound) or None."""
    finer = ladders[i + 1:]
    if not finer or finer_not_converged(ladders, i) or judge(ladders[i][1], 0)["bound"] is not None:
        return None
    n, rungs = finer[-1]
    bound = judge(rungs, 2)["bound"]
    if bound is None:  # the finest ladder shows no signal: nothing to bound through
        return None
    value, f = (r if isinstance(r, tuple) else (r, 0.0, 0) for r in (ladders[i][1][0], rungs[2]))
    # |mu - mu_lim| <= |mu - f| + h + b |f|, relative to |mu_lim| >= (1 - b) |f|
    return 4 * n, (abs(value[0] - f[0]) + _half([value, f, (0.0, 0.0, 0)], (1, -1, 0)) + bound * abs(f[0])) / (
        (1 - bound) * abs(f[0]))


def shares_a_limit(values):
    """Whether some limit L satisfies |v - L| <= b |L| for every (v, b): the intervals [v / (1 + b),
    v / (1 - b)] overlap (values of one sign), as the code's shareALimit (core/refinement_ladder.hpp)."""
    if any(v * values[0][0] <= 0 for v, _ in values[1:]):
        return False
    low = max(abs(v) / (1 + b) for v, b in values)
    high = min((abs(v) / (1 - b) for v, b in values if b < 1), default=math.inf)
    return low <= high
