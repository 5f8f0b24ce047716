"""The checks every scene gets (generic), and those of the default mode's contact handling for the
continuous-time and hybrid scenes (default_mode): see the section comment below and check.py."""
import math

from fosssim_traj import PE, PH, PP, add, cross, dot, mul, norm, segment_distance, sub, unit
from checks_common import (close, expect, halfplane_distance, kinetic, momentum, pair_polys_per_pass,
                           predicted_motion, worst_overlap)


# ---- checks every scene gets ---------------------------------------------------------------------

def generic(sc, tr, notes):
    for k, rec in enumerate(tr.ends + tr.mids):
        expect(all(math.isfinite(c) for c in rec.x + rec.v), 'non-finite number in a record')
    for i in range(sc.n):
        if sc.fixed[i]:
            for rec in tr.ends + tr.mids:
                expect(rec.pos(i) == sc.x0[i] and rec.vel(i) == (0.0, 0.0), 'fixed particle %d moved' % i)
    if any(sc.fixed):
        notes.append('fixed particles %s never move (bit-exact, every record)' %
                     [i for i in range(sc.n) if sc.fixed[i]])
    if sc.collision in ('continuous-time', 'hybrid'):
        tr.explained = default_mode(sc, tr, notes)
    if sc.collision == 'hybrid':
        worst, where = math.inf, None
        for k, rec in enumerate(tr.ends):
            g, w = worst_overlap(sc, rec)
            if g < worst:
                worst, where = g, (k,) + w
        expect(worst > -1e-9, 'overlap %.3g at step end %s' % (worst, where))
        notes.append('no overlap at any step end (PP, PE, PH; smallest gap %.2e)' % worst)
    if sc.collision == 'simple':
        expect(all(im[4] == 0.0 for rec in tr.ends for im in rec.impulses), 'simple impulse with time != 0')


# ---- the default mode's contact handling (continuous-time and hybrid scenes) ----------------------
#
# The oracle files are written by the default mode (not --compat): within each step contacts are
# resolved in time order with sequential impulses, each particle's path bends at its contact times,
# and what impulses cannot settle goes to impact zones solved by an inelastic projection. The
# checks below follow that mode's promises (docs: contact-physics.md) and are derived from the scene
# and the file alone:
#   - the polynomial log holds the reference-form polynomials of every pair over the integrator's
#     predicted motion, recomputed here from the previous record (so the prediction below is the
#     simulator's);
#   - a step is "explained by its impulses" when replaying the logged impulses in time order (each
#     against the current velocities, the standard impulse for the logged normal and the scene's
#     COR, the path bending at the logged time) reproduces the end record; otherwise the failsafe
#     acted in that step. Resting contact does not bounce: below COR 1, an impulse whose contact
#     closes no faster than twice the step's kicks along its normal (each side's |kick . n|
#     summed, a kick being the velocity change the integrator's prediction made, 0 for a fixed
#     particle) takes COR 0. Hits of one instant act together: consecutive impulses of one time
#     whose contacts all close faster than that at the first one's turn are a round, and hits of
#     a round that share a movable particle leave by Moreau's law (replay_step);
#   - contacts are time-ordered, nothing ends a step deeper than it began, no response adds kinetic
#     energy, momentum and angular momentum are kept for free scenes, and along every replayed path
#     no pair passes into another (no tunnelling).

def _pmul(a, b):
    out = [0.0] * (len(a) + len(b) - 1)
    for i, ca in enumerate(a):
        for j, cb in enumerate(b):
            out[i + j] += ca * cb
    return out


def _padd(*ps):
    L = max(len(p) for p in ps)
    out = [0.0] * L
    for p in ps:
        for i, c in enumerate(p):
            out[L - len(p) + i] += c
    return out


def _lin(x0, d):
    """A point moving linearly as two polynomials in t (highest power first)."""
    return ([d[0], x0[0]], [d[1], x0[1]])


def _pdot(a, b):
    return _padd(_pmul(a[0], b[0]), _pmul(a[1], b[1]))


def _psub(a, b):
    return (_padd(a[0], [-c for c in b[0]]), _padd(a[1], [-c for c in b[1]]))


def reference_polynomials(sc, xs, xe):
    """The polynomials of every pair over the motion xs -> xe, in pair order (spec section 4):
    PP [position, approach], PE [distance quartic, alpha > 0, alpha < 1, approach quintic (None:
    not recomputed)], PH [position, approach]."""
    out = []
    d = [sub(xe[i], xs[i]) for i in range(sc.n)]
    for i in range(sc.n):
        for j in range(i + 1, sc.n):
            x21, D21 = sub(xs[j], xs[i]), sub(d[j], d[i])
            R = sc.r[i] + sc.r[j]
            out.append([-dot(D21, D21), -2 * dot(D21, x21), R * R - dot(x21, x21)])
            out.append([-dot(D21, D21), dot(sub(d[i], d[j]), x21)])
        for (a, b, re) in sc.edges:
            if i in (a, b):
                continue
            P1, P2, P3 = _lin(xs[i], d[i]), _lin(xs[a], d[a]), _lin(xs[b], d[b])
            e, w = _psub(P3, P2), _psub(P1, P2)
            ee, we = _pdot(e, e), _pdot(w, e)
            R = sc.r[i] + re
            out.append(_padd([R * R * c for c in ee], [-c for c in _pmul(ee, _pdot(w, w))], _pmul(we, we)))
            out.append(we)
            out.append(_pdot(_psub(P1, P3), _psub(P2, P3)))
            out.append(None)
        for (p, m) in sc.halfplanes:
            A, B = dot(sub(p, xs[i]), m), dot(d[i], m)
            out.append([-B * B, 2 * A * B, sc.r[i] ** 2 * dot(m, m) - A * A])
            out.append([-B * B, A * B])
    return out


def strip_leading(p, cut=1e-12):
    """The logged form drops leading coefficients below 1e-12 in magnitude (spec section 4: the
    reference's absolute cut-off, which the log keeps)."""
    p = list(p)
    while p and abs(p[0]) < cut:
        p.pop(0)
    return p


def same_polynomial(got, want, tol=1e-9):
    """Equal up to a positive scale: both in the logged form (leading |c| < 1e-12 dropped), then
    L1-normalised (leading zeros padded) within tol."""
    got, want = strip_leading(got), strip_leading(want)
    L = max(len(got), len(want))
    g = [0.0] * (L - len(got)) + list(got)
    w = [0.0] * (L - len(want)) + list(want)
    ng, nw = sum(abs(c) for c in g), sum(abs(c) for c in w)
    if nw == 0 or ng == 0:
        return ng <= tol * max(1.0, nw) and nw <= tol * max(1.0, ng)
    return all(abs(a / ng - b / nw) <= tol for a, b in zip(g, w))


def _closest_param(p, a, b):
    e = sub(b, a)
    ee = dot(e, e)
    return 0.0 if ee == 0 else max(0.0, min(1.0, dot(sub(p, a), e) / ee))


def _solve(a, b):
    """Gaussian elimination with partial pivoting; None when a is singular."""
    n = len(b)
    m = [list(row) + [rhs] for row, rhs in zip(a, b)]
    for c in range(n):
        piv = max(range(c, n), key=lambda r: abs(m[r][c]))
        if abs(m[piv][c]) < 1e-300:
            return None
        m[c], m[piv] = m[piv], m[c]
        for r in range(c + 1, n):
            f = m[r][c] / m[c][c]
            for k in range(c, n + 1):
                m[r][k] -= f * m[c][k]
    x = [0.0] * n
    for r in reversed(range(n)):
        x[r] = (m[r][n] - sum(m[r][k] * x[k] for k in range(r + 1, n))) / m[r][r]
    return x


def _project(rows, inv, u):
    """The inelastic projection of velocities u (a dict particle -> velocity) onto the rows
    (each a list of (particle, coefficient) with sum coef . v >= 0), closest in the kinetic-energy
    norm, by enumerating active sets (KKT: lambda >= 0, every row satisfied; the optimum is unique
    in the velocities). Returns v* as a dict, or None."""
    scale = max(norm(x) for x in u.values()) or 1.0
    rowv = lambda row, v: sum(dot(c, v[p]) for p, c in row)
    for size in range(1, len(rows) + 1):
        for active in _subsets(len(rows), size):
            g = [rows[k] for k in active]
            a = [[sum(inv(p) * dot(c, c2) for p, c in r1 for p2, c2 in r2 if p == p2) for r2 in g] for r1 in g]
            lam = _solve(a, [-rowv(r, u) for r in g])
            if lam is None or min(lam) < 0.0:
                continue
            v = dict(u)
            for r, l in zip(g, lam):
                for p, c in r:
                    v[p] = add(v[p], mul(inv(p) * l, c))
            if all(rowv(r, v) >= -1e-12 * scale for r in rows):
                return v
    return None


def _subsets(n, size, first=0):
    if size == 0:
        yield []
        return
    for k in range(first, n - size + 1):
        for rest in _subsets(n, size - 1, k + 1):
            yield [k] + rest


def replay_step(sc, start, end, pred_x, pred_v):
    """Replays the step's logged impulses in time order from the predicted motion. Returns
    (pieces, x, v): pieces lists (t0, positions at t0, rates) for every straight piece of the
    paths (a rate is a displacement per whole step), x and v the replayed end state.

    Hits of one instant act together: consecutive impulses of one time whose contacts all close
    faster than resting contact at the round's start are one round, and hits of a round that share
    a movable particle leave by Moreau's law, v + (1 + COR)(P v - v) with P v the inelastic
    projection onto their rows (a hit alone: its standard impulse)."""
    h, e = sc.dt, sc.cor
    x = [start.pos(i) for i in range(sc.n)]
    rate = [sub(pred_x[i], start.pos(i)) for i in range(sc.n)]
    v = list(pred_v)
    inv = lambda p: 0.0 if sc.fixed[p] else 1.0 / sc.m[p]
    kick = [(0.0, 0.0) if sc.fixed[p] else sub(pred_v[p], start.vel(p)) for p in range(sc.n)]
    along = lambda p, nh: abs(dot(kick[p], nh))
    # COR 0 for resting contact (see the section comment): closing (m/s) against the kicks.
    resting = lambda closing, kicks: closing <= 2.0 * kicks
    cor = lambda closing, kicks: 0.0 if e < 1 and resting(closing, kicks) else e
    u = lambda p: mul(1.0 / h, rate[p])   # the velocity the path moves with

    def contact(im):
        """The impulse's row (n . relative velocity >= 0), closing speed and kicks along it."""
        kind, i, j, n, tau = im
        nh = unit(n)
        if kind == PP:
            row, kicks = [(i, mul(-1, nh)), (j, nh)], along(i, nh) + along(j, nh)
        elif kind == PE:
            a, b, _ = sc.edges[j]
            al = _closest_param(x[i], x[a], x[b])
            row = [(i, mul(-1, nh)), (a, mul(1 - al, nh)), (b, mul(al, nh))]
            kicks = along(i, nh) + (1 - al) * along(a, nh) + al * along(b, nh)
        else:
            row, kicks = [(i, mul(-1, nh))], along(i, nh)
        return row, -sum(dot(c, u(p)) for p, c in row), kicks

    def change(dv):
        for p, d in dv:
            if not sc.fixed[p]:
                v[p] = add(v[p], d)
                rate[p] = add(rate[p], mul(h, d))

    def alone(row, closing, kicks):
        w = sum(inv(p) * dot(c, c) for p, c in row)
        N = (1 + cor(closing, kicks)) * closing / w
        change([(p, mul(N * inv(p), c)) for p, c in row])

    t, pieces, ims, q = 0.0, [], end.impulses, 0
    while q < len(ims):
        tau = ims[q][4]
        if tau > t:
            pieces.append((t, list(x), list(rate)))
            x = [add(x[p], mul(tau - t, rate[p])) for p in range(sc.n)]
            t = tau
        # The round: this impulse and the next ones of its time whose contacts close as hits now.
        rnd = [contact(ims[q])]
        while (q + len(rnd) < len(ims) and ims[q + len(rnd)][4] == tau and rnd[0][1] > 0 and
               not resting(rnd[0][1], rnd[0][2])):
            c = contact(ims[q + len(rnd)])
            if c[1] <= 0 or resting(c[1], c[2]):
                break
            rnd.append(c)
        q += len(rnd) if len(rnd) > 1 else 1
        if len(rnd) == 1:
            alone(*rnd[0])
            continue
        # Its groups, joined through movable particles.
        groups = []
        for c in rnd:
            mine = {p for p, _ in c[0] if not sc.fixed[p]}
            joined = [g for g in groups if mine & g[0]]
            for g in joined:
                groups.remove(g)
            groups.append((mine.union(*[g[0] for g in joined]), [c] + [m for g in joined for m in g[1]]))
        for _, members in groups:
            if len(members) == 1:
                alone(*members[0])
                continue
            rows = [m[0] for m in members]
            uu = {p: u(p) for r in rows for p, _ in r}
            vs = _project(rows, inv, uu)
            if vs is None:
                return pieces + [(t, list(x), list(rate))], [(math.nan, math.nan)] * sc.n, v
            change([(p, mul(1 + e, sub(vs[p], uu[p]))) for p in uu])
    pieces.append((t, list(x), list(rate)))
    x = [add(x[p], mul(1.0 - t, rate[p])) for p in range(sc.n)]
    return pieces, x, v


def state_scale(sc, rec):
    """Magnitudes for relative tolerances: coordinates and velocities."""
    X = max([1e-300] + [abs(c) for c in rec.x])
    V = max([1e-300] + [abs(c) for c in rec.v])
    return X, V


def path_gaps(sc, xs_at, t0, t1, samples):
    """The smallest gap of every pair over [t0, t1] given positions xs_at(t) (piecewise linear),
    PP and PH exactly per piece ends plus samples, PE sampled: dict pair -> gap."""
    best = {}
    ts = [t0 + (t1 - t0) * s / samples for s in range(samples + 1)]
    for t in ts:
        x = xs_at(t)
        for i in range(sc.n):
            for j in range(i + 1, sc.n):
                if sc.fixed[i] and sc.fixed[j]:
                    continue
                g = norm(sub(x[j], x[i])) - sc.r[i] - sc.r[j]
                key = (PP, i, j)
                if g < best.get(key, math.inf):
                    best[key] = g
            for ei, (a, b, re) in enumerate(sc.edges):
                if i in (a, b):
                    continue
                g = segment_distance(x[i], x[a], x[b]) - sc.r[i] - re
                key = (PE, i, ei)
                if g < best.get(key, math.inf):
                    best[key] = g
            for hi in range(len(sc.halfplanes)):
                g = halfplane_distance(sc, x[i], sc.r[i], hi)
                key = (PH, i, hi)
                if g < best.get(key, math.inf):
                    best[key] = g
    return best


def pair_gaps(sc, rec):
    x = [rec.pos(i) for i in range(sc.n)]
    return path_gaps(sc, lambda t: x, 0.0, 0.0, 1)


def pair_radius(sc, key):
    kind, i, j = key
    return sc.r[i] + (sc.r[j] if kind == PP else sc.edges[j][2] if kind == PE else 0.0)


def angular_momentum(sc, xs, vs):
    return sum(sc.m[i] * cross(xs[i], vs[i]) for i in range(sc.n) if not sc.fixed[i])


def default_mode(sc, tr, notes, samples=24):
    """Every continuous-time and hybrid scene (see the section comment). Returns per step (index =
    step number, 0 unused) whether the logged impulses explain it."""
    free = not any(sc.fixed) and not sc.halfplanes
    per_pass = pair_polys_per_pass(sc)
    explained = [True]
    worst_deeper, worst_path, ke_ratio, worst_mom, worst_L, worst_L_fs = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    impulses = 0
    for k, mid in enumerate(tr.mids):
        s, end = tr.ends[k], tr.ends[k + 1]
        step = k + 1
        # One record per step in effect: the handler writes its mid-step record when it is done.
        expect(mid.x == end.x and mid.v == end.v and mid.impulses == end.impulses and mid.polys == end.polys,
               'step %d: mid and end records differ' % step)
        # The polynomial log: every pair over the predicted motion, in pair order.
        px, pv = predicted_motion(sc, s)
        want = reference_polynomials(sc, [s.pos(i) for i in range(sc.n)], px)
        expect(len(end.polys) == per_pass == len(want), 'step %d: %d polynomials, expected %d' % (step, len(end.polys), per_pass))
        for q, (got, w) in enumerate(zip(end.polys, want)):
            if w is None:
                expect(len(got) <= 6, 'step %d: polynomial %d is not a quintic' % (step, q))
            else:
                expect(same_polynomial(got, w), 'step %d: polynomial %d %s is not the predicted motion\'s %s' % (step, q, got, w))
        # Impulses: valid pairs, unit normals, in time order within [0, 1].
        times = [im[4] for im in end.impulses]
        expect(times == sorted(times) and all(0.0 <= t <= 1.0 for t in times), 'step %d: impulse times %s not ordered in [0, 1]' % (step, times))
        for (kind, i, j, n, tau) in end.impulses:
            close(norm(n), 1.0, 1e-12, 'step %d: impulse normal length' % step)
            expect((kind == PP and i < j < sc.n) or (kind == PE and i not in sc.edges[j][:2]) or
                   (kind == PH and j < len(sc.halfplanes)), 'step %d: impulse pair %s' % (step, (kind, i, j)))
        impulses += len(end.impulses)
        # Replay the impulses.
        pieces, rx, rv = replay_step(sc, s, end, px, pv)
        X, V = state_scale(sc, end)
        ok = all(abs(a - b) <= 1e-11 * X for i in range(sc.n) for a, b in zip(rx[i], end.pos(i))) and \
            all(abs(a - b) <= 1e-11 * V for i in range(sc.n) for a, b in zip(rv[i], end.vel(i)))
        explained.append(ok)
        # Nothing ends the step deeper than it began (relative to the pair's radii).
        g0, g1 = pair_gaps(sc, s), pair_gaps(sc, end)
        for key, g in g1.items():
            deeper = (min(g0[key], 0.0) - g) / pair_radius(sc, key)
            expect(deeper <= 1e-9, 'step %d: %s ends %.3g deeper than at the step start (gap %.3g -> %.3g)' % (step, key, deeper, g0[key], g))
            worst_deeper = max(worst_deeper, deeper)
        # No tunnelling: along the replayed paths (known when the impulses explain the step) no pair
        # gets deeper than it was at the step start.
        if ok:
            for q, (t0, xq, rq) in enumerate(pieces):
                t1 = pieces[q + 1][0] if q + 1 < len(pieces) else 1.0
                at = lambda t, t0=t0, xq=xq, rq=rq: [add(xq[p], mul(t - t0, rq[p])) for p in range(sc.n)]
                for key, g in path_gaps(sc, at, t0, t1, samples).items():
                    deeper = (min(g0[key], 0.0) - g) / pair_radius(sc, key)
                    expect(deeper <= 1e-9, 'step %d: %s passes %.3g deep into the other along its path (t in [%.3f, %.3f])' % (step, key, -g, t0, t1))
                    worst_path = max(worst_path, deeper)
        # Kinetic energy: no response adds any (the path velocities are the predicted velocities
        # when the integrator moves by h v_new, or when no force acts).
        if sc.cor <= 1 and (sc.integrator == 'symplectic-euler' or not (sc.springs or sc.gravity)):
            ke_p = sum(0.5 * sc.m[i] * dot(pv[i], pv[i]) for i in range(sc.n) if not sc.fixed[i])
            ke_e = kinetic(sc, end)
            expect(ke_e <= ke_p * (1 + 1e-12) + 1e-300, 'step %d: collision handling added kinetic energy %.6g -> %.6g' % (step, ke_p, ke_e))
            if ke_p > 0:
                ke_ratio = max(ke_ratio, ke_e / ke_p)
        # Free scenes: momentum and angular momentum of the predicted motion are kept.
        if free:
            P = sum(sc.m[i] * norm(pv[i]) for i in range(sc.n))
            mom_p = (sum(sc.m[i] * pv[i][0] for i in range(sc.n)), sum(sc.m[i] * pv[i][1] for i in range(sc.n)))
            mom_e = momentum(sc, end)
            worst_mom = max(worst_mom, norm(sub(mom_e, mom_p)) / P if P else 0.0)
            # Angular momentum: impulses act along the line through the contact and free flight
            # is straight, so it is kept to rounding in the steps the impulses explain. The
            # failsafe's row for a contact that deepens only by rotation uses the normal where the
            # overlap would be deepest, later in the step, whose line misses the contact points by
            # at most a step's displacement: there it is kept to first order, |dL| <= sum m |dv|
            # times the largest displacement of the step (the project's own tests: 1e-6 of L).
            if sc.integrator == 'symplectic-euler' or not (sc.springs or sc.gravity):
                Ls = sum(sc.m[i] * norm(px[i]) * norm(pv[i]) for i in range(sc.n))
                dL = abs(angular_momentum(sc, [end.pos(i) for i in range(sc.n)], [end.vel(i) for i in range(sc.n)]) -
                         angular_momentum(sc, px, pv))
                if ok:
                    expect(dL <= 1e-10 * Ls, 'step %d: angular momentum changed by %.3g (scale %.3g) by impulses' % (step, dL, Ls))
                    worst_L = max(worst_L, dL / Ls if Ls else 0.0)
                else:
                    J = sum(sc.m[i] * norm(sub(end.vel(i), pv[i])) for i in range(sc.n))
                    arm = max(norm(sub(px[i], s.pos(i))) for i in range(sc.n))
                    expect(dL <= J * arm + 1e-10 * Ls, 'step %d: the failsafe changed angular momentum by %.3g > first-order bound %.3g' % (step, dL, J * arm))
                    worst_L_fs = max(worst_L_fs, dL / (J * arm) if J * arm else 0.0)
    expect(worst_mom <= 1e-12, 'momentum changed by %.3g of its scale in a step' % worst_mom)
    acted = sum(1 for ok in explained[1:] if not ok)
    notes.append('default mode: the polynomial log is every pair\'s reference-form polynomials over the predicted motion (recomputed, 1e-9); '
                 '%d impulses, in time order within each step; %d of %d steps reproduced by replaying them (1e-11), the failsafe acted in %d'
                 % (impulses, len(explained) - 1 - acted, len(explained) - 1, acted))
    notes.append('no pair ends a step deeper than it began (worst %.1e of its radii); along the replayed paths no pair passes into another (worst %.1e)'
                 % (worst_deeper, worst_path))
    if ke_ratio:
        notes.append('collision handling never adds kinetic energy (largest end/predicted ratio %.12f)' % ke_ratio)
    if free:
        notes.append('free scene: momentum kept every step (1e-12); angular momentum kept by the impulses (worst %.1e of its scale)%s'
                     % (worst_L, '' if not acted else ' and to first order by the failsafe (worst %.3f of the bound)' % worst_L_fs))
    return explained
