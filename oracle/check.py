#!/usr/bin/env python3
"""Independent checks of the oracle trajectories in oracle/ (see oracle/README.md).

Every reference file oracle/<path>.bin was written by FOSSSim from assets/<path>.xml. This script
does not run FOSSSim and shares no code with it: it reads the scene with xml.etree and the
trajectory with its own reader (fosssim_traj.py), and asserts, for each scene, physical or
closed-form properties that the numbers must have if the simulator is right: closed-form discrete
solutions, conservation laws, exact velocity exchanges, predicted collision times, and (for the
hybrid handler) that nothing overlaps at any step end.

usage: check.py [--root DIR] [-v | --markdown] [SCENE...]   (SCENE as a path relative to assets/, e.g. examples/drag.xml)
Exit code 0 when every check passed.
"""
import argparse
import math
import os
import sys
import traceback

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosssim_traj import (PE, PH, PP, Scene, Trajectory, add, cross, dot, mul, norm,  # noqa: E402
                          segment_distance, sub, unit)

CHECKS = {}


def check(*paths):
    def register(fn):
        for p in paths:
            CHECKS[p] = fn
        return fn
    return register


class CheckFailed(AssertionError):
    pass


def expect(cond, what):
    if not cond:
        raise CheckFailed(what)


def close(a, b, tol, what):
    expect(abs(a - b) <= tol, '%s: %r vs %r (|diff| %.3g > %.3g)' % (what, a, b, abs(a - b), tol))


def close2(a, b, tol, what):
    close(a[0], b[0], tol, what + ' (x)')
    close(a[1], b[1], tol, what + ' (y)')


# ---- physics helpers ----------------------------------------------------------------------------

def momentum(sc, rec, which=None):
    px = py = 0.0
    for i in which if which is not None else range(sc.n):
        if not sc.fixed[i]:
            px += sc.m[i] * rec.v[2 * i]
            py += sc.m[i] * rec.v[2 * i + 1]
    return (px, py)


def kinetic(sc, rec, which=None):
    return sum(0.5 * sc.m[i] * dot(rec.vel(i), rec.vel(i))
               for i in (which if which is not None else range(sc.n)) if not sc.fixed[i])


def forces(sc, x, v):
    """Total force on every particle for the forces the checked scenes use (springs, simple gravity,
    gravitational, constant, drag, vortex), written from the spec's formulas."""
    f = [[0.0, 0.0] for _ in range(sc.n)]
    for (e, k, l0, b) in sc.springs:
        i, j, _ = sc.edges[e]
        d = sub(x[j], x[i])
        L = norm(d)
        nh = mul(1.0 / L, d)
        mag = k * (L - l0) + b * dot(sub(v[j], v[i]), nh)
        for c in range(2):
            f[i][c] += mag * nh[c]
            f[j][c] -= mag * nh[c]
    for g in sc.gravity:
        for i in range(sc.n):
            f[i][0] += sc.m[i] * g[0]
            f[i][1] += sc.m[i] * g[1]
    for (i, j, G) in sc.gravitational:
        d = sub(x[j], x[i])
        r = norm(d)
        mag = G * sc.m[i] * sc.m[j] / (r * r)
        for c in range(2):
            f[i][c] += mag * d[c] / r
            f[j][c] -= mag * d[c] / r
    for cf in sc.constant:
        for i in range(sc.n):
            f[i][0] += cf[0]
            f[i][1] += cf[1]
    for b in sc.drag:
        for i in range(sc.n):
            f[i][0] -= b * v[i][0]
            f[i][1] -= b * v[i][1]
    for (i, j, kbs, kvc) in sc.vortex:
        d = sub(x[j], x[i])
        r = norm(d)
        rh = mul(1.0 / r, d)
        perp = (-rh[1], rh[0])
        rel = sub(v[j], v[i])
        fj = mul(kvc / (r * r), sub(mul(kbs, perp), rel))
        for c in range(2):
            f[j][c] += fj[c]
            f[i][c] -= fj[c]
    return f


def explicit_prediction(sc, rec):
    """The integrator's step from `rec` with no collision response (explicit or symplectic Euler)."""
    h = sc.dt
    x = [rec.pos(i) for i in range(sc.n)]
    v = [rec.vel(i) for i in range(sc.n)]
    f = forces(sc, x, v)
    xs, vs = [], []
    for i in range(sc.n):
        if sc.fixed[i]:
            xs.append(x[i]); vs.append((0.0, 0.0))
            continue
        vn = (v[i][0] + h * f[i][0] / sc.m[i], v[i][1] + h * f[i][1] / sc.m[i])
        if sc.integrator == 'explicit-euler':
            xn = (x[i][0] + h * v[i][0], x[i][1] + h * v[i][1])
        else:
            assert sc.integrator in ('symplectic-euler', 'forward-backward-euler'), sc.integrator
            xn = (x[i][0] + h * vn[0], x[i][1] + h * vn[1])
        xs.append(xn); vs.append(vn)
    return xs, vs


def halfplane_distance(sc, x, r, h):
    p, m = sc.halfplanes[h]
    return dot(sub(x, p), unit(m)) - r


def worst_overlap(sc, rec):
    """The most negative gap (distance minus the sum of radii) over all the pairs the handlers
    consider: particle-particle, particle-edge (edges not incident to the particle), particle-half-plane."""
    worst, where = math.inf, None
    for i in range(sc.n):
        xi = rec.pos(i)
        for j in range(i + 1, sc.n):
            g = norm(sub(rec.pos(j), xi)) - sc.r[i] - sc.r[j]
            if g < worst:
                worst, where = g, ('PP', i, j)
        for e, (a, b, re) in enumerate(sc.edges):
            if i in (a, b):
                continue
            g = segment_distance(xi, rec.pos(a), rec.pos(b)) - sc.r[i] - re
            if g < worst:
                worst, where = g, ('PE', i, e)
        for h in range(len(sc.halfplanes)):
            g = halfplane_distance(sc, xi, sc.r[i], h)
            if g < worst:
                worst, where = g, ('PH', i, h)
    return worst, where


def pair_polys_per_pass(sc):
    """Number of polynomials one detection pass logs: 2 per PP pair, 4 per PE pair, 2 per PH pair."""
    pe = sum(1 for i in range(sc.n) for (a, b, _) in sc.edges if i not in (a, b))
    return 2 * (sc.n * (sc.n - 1) // 2) + 4 * pe + 2 * sc.n * len(sc.halfplanes)


def straight_line_gaps(sc, i, j_or_edge, kind, steps):
    """Gaps at the step ends of the first `steps` steps if nothing collided (straight lines at the
    initial velocities): used to show that a scene really needs continuous-time detection."""
    h = sc.dt
    out = []
    for n in range(steps + 1):
        p = lambda k: add(sc.x0[k], mul(n * h, sc.v0[k]))
        if kind == 'PP':
            out.append(norm(sub(p(j_or_edge), p(i))) - sc.r[i] - sc.r[j_or_edge])
        else:
            a, b, re = sc.edges[j_or_edge]
            out.append(segment_distance(p(i), p(a), p(b)) - sc.r[i] - re)
    return out


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


def hybrid_impulses_only(sc, tr, notes, min_passes):
    """ImpulsesTests: the impulse passes resolve every step, so the failsafe never changes the state
    (mid-step record == end-of-step record), and some step needed at least `min_passes` passes."""
    per_pass = pair_polys_per_pass(sc)
    most = 0
    for k, mid in enumerate(tr.mids):
        end = tr.ends[k + 1]
        expect(mid.x == end.x and mid.v == end.v, 'step %d: the failsafe changed the state' % (k + 1))
        expect(len(mid.polys) % per_pass == 0, 'step %d: polynomial count not a whole number of passes' % (k + 1))
        passes = len(mid.polys) // per_pass
        expect(1 <= passes <= sc.maxiters, 'step %d: %d passes' % (k + 1, passes))
        most = max(most, passes)
    expect(most >= min_passes, 'at most %d impulse passes in a step, expected >= %d' % (most, min_passes))
    notes.append('failsafe never acted (mid-step == end-of-step state, bit-exact); up to %d impulse passes in a step' % most)


def hybrid_failsafe_only(sc, tr, notes):
    """GeometricTests (maxiters 0): no impulse pass runs, so the mid-step record holds no polynomial
    and is exactly the integrator's unconstrained prediction from the previous step end."""
    acted = 0
    for k, mid in enumerate(tr.mids):
        expect(len(mid.polys) == 0, 'step %d: polynomials before the failsafe' % (k + 1))
        xs, vs = explicit_prediction(sc, tr.ends[k])
        for i in range(sc.n):
            close2(mid.pos(i), xs[i], 1e-12, 'step %d mid x[%d] vs prediction' % (k + 1, i))
            close2(mid.vel(i), vs[i], 1e-12, 'step %d mid v[%d] vs prediction' % (k + 1, i))
        acted += mid.x != tr.ends[k + 1].x
    expect(acted > 0, 'the failsafe never acted')
    notes.append('mid-step record == unconstrained integrator prediction (1e-12) with no polynomial logged; failsafe acted in %d steps' % acted)
    return acted


def conserved_momentum(sc, tr, notes, tol=1e-12, which=None, upto=None):
    p0 = momentum(sc, tr.ends[0], which)
    scale = max(1.0, norm(p0))
    for k, rec in enumerate(tr.ends[:upto]):
        close2(momentum(sc, rec, which), p0, tol * scale, 'momentum at step %d' % k)
    notes.append('total momentum conserved to %g' % tol)


# ---- examples ---------------------------------------------------------------------------------------

@check('examples/projectile.xml')
def _(sc, tr, notes):
    h, g = sc.dt, sc.gravity[0]
    for n, rec in enumerate(tr.ends):
        x = add(add(sc.x0[0], mul(n * h, sc.v0[0])), mul(h * h * n * (n - 1) / 2, g))
        v = add(sc.v0[0], mul(n * h, g))
        close2(rec.pos(0), x, 1e-12 * (1 + n), 'x at step %d' % n)
        close2(rec.vel(0), v, 1e-12 * (1 + n), 'v at step %d' % n)
    notes.append('x_n = x0 + n h v0 + h^2 g n(n-1)/2 and v_n = v0 + n h g (explicit Euler closed form), every step')


def spring_1d(sc, tr, notes, stepper, invariant=None, what=''):
    """A spring along x from a fixed anchor: u = x - x_anchor - l0, v; a linear 2x2 map per step."""
    (e, k, l0, b) = sc.springs[0]
    m = sc.m[1]
    u, v = sc.x0[1][0] - sc.x0[0][0] - l0, sc.v0[1][0]
    w2 = k / m
    q0 = invariant(u, v, w2) if invariant else None
    for n, rec in enumerate(tr.ends):
        un, vn = rec.pos(1)[0] - sc.x0[0][0] - l0, rec.vel(1)[0]
        close(un, u, 1e-10, 'u at step %d' % n)
        close(vn, v, 1e-10, 'v at step %d' % n)
        expect(rec.pos(1)[1] == 0.0 and rec.vel(1)[1] == 0.0, 'motion left the x axis')
        if invariant:
            close(invariant(un, vn, w2) / q0, 1.0, 1e-10, what + ' at step %d' % n)
        u, v = stepper(u, v, w2, sc.dt)
    notes.append('matches the linear discrete map of this integrator (1e-10), every step')


def energy(u, v, w2):
    return w2 * u * u + v * v


@check('examples/spring_explicit.xml')
def _(sc, tr, notes):
    spring_1d(sc, tr, notes, lambda u, v, w2, h: (u + h * v, v - h * w2 * u))
    w2, h = sc.springs[0][1] / sc.m[1], sc.dt
    es = [energy(r.pos(1)[0] - sc.springs[0][2], r.vel(1)[0], w2) for r in tr.ends]
    for n in range(1, len(es)):
        close(es[n] / es[n - 1], 1 + h * h * w2, 1e-9, 'energy growth factor at step %d' % n)
    notes.append('energy grows by exactly 1 + h^2 k/m per step (1e-9): x%.3f over the run' % (es[-1] / es[0]))


@check('examples/spring_symplectic.xml')
def _(sc, tr, notes):
    def step(u, v, w2, h):
        v = v - h * w2 * u
        return u + h * v, v
    h = sc.dt
    spring_1d(sc, tr, notes, step, lambda u, v, w2: w2 * u * u + v * v - h * w2 * u * v,
              'modified energy k/m u^2 + v^2 - h k/m u v')
    w2 = sc.springs[0][1] / sc.m[1]
    es = [energy(r.pos(1)[0] - sc.springs[0][2], r.vel(1)[0], w2) for r in tr.ends]
    spread = max(es) / min(es)
    expect(spread < 1 + 2 * h * math.sqrt(w2), 'energy band too wide: %g' % spread)
    notes.append('its modified energy k/m u^2 + v^2 - h (k/m) u v is conserved to 1e-10; true energy stays in a band of +-%.1f%%' % (50 * (spread - 1)))


def implicit_spring(sc, tr, notes):
    def step(u, v, w2, h):
        # v' = v - h w2 u', u' = u + h v'  =>  v' = (v - h w2 u) / (1 + h^2 w2)
        v = (v - h * w2 * u) / (1 + h * h * w2)
        return u + h * v, v
    spring_1d(sc, tr, notes, step)
    w2, h = sc.springs[0][1] / sc.m[1], sc.dt
    es = [energy(r.pos(1)[0] - sc.springs[0][2], r.vel(1)[0], w2) for r in tr.ends]
    for n in range(1, len(es)):
        close(es[n] / es[n - 1], 1 / (1 + h * h * w2), 1e-9, 'energy decay factor at step %d' % n)
    notes.append('energy shrinks by exactly 1/(1 + h^2 k/m) per step (1e-9): x%.3f over the run' % (es[-1] / es[0]))


check('examples/spring_implicit.xml', 'examples/spring_linearized_implicit.xml')(implicit_spring)


@check('examples/spring_damped.xml')
def _(sc, tr, notes):
    conserved_momentum(sc, tr, notes)
    (e, k, l0, b) = sc.springs[0]
    mu = sc.m[0] * sc.m[1] / (sc.m[0] + sc.m[1])
    u = sc.x0[1][0] - sc.x0[0][0] - l0
    w = sc.v0[1][0] - sc.v0[0][0]
    h = sc.dt
    e0 = 0.5 * k * u * u
    for n, rec in enumerate(tr.ends):
        close(rec.pos(1)[0] - rec.pos(0)[0] - l0, u, 1e-10, 'stretch at step %d' % n)
        close(rec.vel(1)[0] - rec.vel(0)[0], w, 1e-10, 'relative velocity at step %d' % n)
        close(rec.pos(1)[1] - rec.pos(0)[1], 0.0, 1e-12, 'relative y at step %d' % n)
        w = w + h * (-k * u - b * w) / mu      # symplectic Euler on the reduced 1D system
        u = u + h * w
    last = tr.ends[-1]
    s = last.pos(1)[0] - last.pos(0)[0] - l0
    ws = last.vel(1)[0] - last.vel(0)[0]
    e_end = 0.5 * k * s * s + 0.5 * mu * ws * ws
    expect(e_end < 0.02 * e0, 'oscillation energy not damped: %g of %g' % (e_end, e0))
    notes.append('stretch and relative velocity follow the reduced damped oscillator (reduced mass) step by step (1e-10); oscillation energy ends at %.2g%% of its start' % (100 * e_end / e0))


@check('examples/pendulum_chain.xml')
def _(sc, tr, notes):
    # Backward Euler: v1 = v0 + h F(x1, v1)/m, x1 = x0 + h v1, at every step (Newton stops at |dv| < 1e-9).
    h, worst = sc.dt, 0.0
    for n in range(1, len(tr.ends)):
        a, b = tr.ends[n - 1], tr.ends[n]
        x1 = [b.pos(i) for i in range(sc.n)]
        v1 = [b.vel(i) for i in range(sc.n)]
        f = forces(sc, x1, v1)
        for i in range(sc.n):
            if sc.fixed[i]:
                continue
            rv = sub(sub(v1[i], a.vel(i)), mul(h / sc.m[i], f[i]))
            rx = sub(sub(x1[i], a.pos(i)), mul(h, v1[i]))
            expect(norm(rx) < 1e-13, 'position residual %g at step %d' % (norm(rx), n))
            worst = max(worst, norm(rv))
    expect(worst < 1e-8, 'backward Euler velocity residual %g' % worst)
    notes.append('every step solves the backward-Euler equations v1 = v0 + h F(x1,v1)/m, x1 = x0 + h v1 (largest residual %.1e)' % worst)


@check('examples/orbit.xml')
def _(sc, tr, notes):
    conserved_momentum(sc, tr, notes)
    G = sc.gravitational[0][2]

    def ang(rec):
        return sum(sc.m[i] * cross(rec.pos(i), rec.vel(i)) for i in range(sc.n))

    def en(rec):
        return kinetic(sc, rec) - G * sc.m[0] * sc.m[1] / norm(sub(rec.pos(1), rec.pos(0)))
    L0, E0 = ang(tr.ends[0]), en(tr.ends[0])
    drift = max(abs(en(r) / E0 - 1) for r in tr.ends)
    for n, rec in enumerate(tr.ends):
        close(ang(rec), L0, 1e-12 * abs(L0) * 10, 'angular momentum at step %d' % n)
    expect(drift < 0.02, 'energy drifts by %g' % drift)
    dist = [norm(sub(r.pos(1), r.pos(0))) for r in tr.ends]
    expect(min(dist) < 0.6 * dist[0], 'not an ellipse: closest approach %g' % min(dist))
    notes.append('angular momentum conserved to 1e-11 (symplectic Euler keeps it exactly for central forces); energy within %.2f%%; periapsis %.2f' % (100 * drift, min(dist)))


@check('examples/drag.xml')
def _(sc, tr, notes):
    h, b, m, g = sc.dt, sc.drag[0], sc.m[0], sc.gravity[0]
    q = 1 - h * b / m
    vt = (m * g[0] / b, m * g[1] / b)
    x = sc.x0[0]
    for n, rec in enumerate(tr.ends):
        v = (vt[0] + (sc.v0[0][0] - vt[0]) * q ** n, vt[1] + (sc.v0[0][1] - vt[1]) * q ** n)
        close2(rec.vel(0), v, 1e-11, 'v at step %d' % n)
        close2(rec.pos(0), x, 1e-11, 'x at step %d' % n)
        vn = (vt[0] + (sc.v0[0][0] - vt[0]) * q ** (n + 1), vt[1] + (sc.v0[0][1] - vt[1]) * q ** (n + 1))
        x = add(x, mul(h, vn))
    notes.append('v_n = v_t + (v0 - v_t)(1 - h b/m)^n with v_t = m g / b, x_n = x0 + h sum v_k (closed form, 1e-11)')


@check('examples/vortex.xml')
def _(sc, tr, notes):
    conserved_momentum(sc, tr, notes)
    for n in range(1, len(tr.ends)):
        xs, vs = explicit_prediction(sc, tr.ends[n - 1])
        for i in range(sc.n):
            close2(tr.ends[n].pos(i), xs[i], 1e-12, 'x[%d] step %d' % (i, n))
            close2(tr.ends[n].vel(i), vs[i], 1e-12, 'v[%d] step %d' % (i, n))
    r = [norm(sub(tr.ends[-1].pos(j), tr.ends[-1].pos(0))) for j in (1, 2)]
    turn = cross(sub(tr.ends[0].pos(1), tr.ends[0].pos(0)), sub(tr.ends[5].pos(1), tr.ends[5].pos(0)))
    expect(turn > 0, 'not anticlockwise')
    notes.append('each step equals an explicit Euler step with the spec\'s vortex formula recomputed here (1e-12); satellites end at r = %.2f, %.2f' % tuple(r))


@check('examples/constant_force.xml')
def _(sc, tr, notes):
    h, F = sc.dt, sc.constant[0]
    for n, rec in enumerate(tr.ends):
        for i in range(sc.n):
            a = mul(1.0 / sc.m[i], F)
            close2(rec.vel(i), mul(n * h, a), 1e-12 * (1 + n), 'v[%d] step %d' % (i, n))
            close2(rec.pos(i), add(sc.x0[i], mul(h * h * n * (n + 1) / 2, a)), 1e-12 * (1 + n), 'x[%d] step %d' % (i, n))
    d = [norm(sub(tr.ends[-1].pos(i), sc.x0[i])) for i in range(3)]
    close(d[0] / d[2], 4.0, 1e-12, 'distance ratio light/heavy')
    notes.append('x_n = x0 + h^2 (F/m) n(n+1)/2 (symplectic Euler closed form, 1e-12); distances in ratio 4:2:1')


@check('examples/billiards.xml')
def _(sc, tr, notes):
    conserved_momentum(sc, tr, notes)
    ke = [kinetic(sc, r) for r in tr.ends]
    for n in range(1, len(ke)):
        expect(ke[n] <= ke[n - 1] * (1 + 1e-12), 'kinetic energy rose at step %d' % n)
    hits = sum(len(r.impulses) for r in tr.ends)
    expect(all(im[0] == PP for r in tr.ends for im in r.impulses), 'non-PP impulse')
    expect(hits >= 10 and ke[-1] < 0.95 * ke[0], 'too little happened: %d impulses' % hits)
    notes.append('kinetic energy never increases and ends at %.1f%% (COR 0.9, %d impulses, all at time 0)' % (100 * ke[-1] / ke[0], hits))


@check('examples/penalty.xml')
def _(sc, tr, notes):
    # The pair 0-1 interacts only with itself (checked): its momentum is conserved exactly.
    reach = lambda i, j: sc.r[i] + sc.r[j] + sc.penalty_thickness
    for n, rec in enumerate(tr.ends):
        for i in range(4):
            for j in range(i + 1, sc.n):
                if (i, j) != (0, 1) and not (i, j) in ((3, 4), (3, 5)):
                    expect(norm(sub(rec.pos(j), rec.pos(i))) > reach(i, j), 'unplanned contact %d-%d' % (i, j))
    conserved_momentum(sc, tr, notes, which=[0, 1])
    last = tr.ends[-1]
    close2(last.vel(0), sc.v0[1], 0.01, 'ball 0 leaves with ball 1\'s velocity')
    close2(last.vel(1), sc.v0[0], 0.01, 'ball 1 leaves with ball 0\'s velocity')
    close2(last.vel(2), (sc.v0[2][0], -sc.v0[2][1]), 0.01, 'floor bounce mirrors ball 2')
    close2(last.vel(3), (-sc.v0[3][0], sc.v0[3][1]), 0.01, 'wall bounce mirrors ball 3')
    depth = -min(min(norm(sub(r.pos(1), r.pos(0))) - 0.2 for r in tr.ends), 0)
    expect(0 < depth < 0.03, 'penetration depth %g' % depth)
    notes[-1] = 'momentum of the colliding pair conserved to 1e-12 (no other contact, checked)'
    notes.append('velocities swapped and both bounces mirrored within 0.01 m/s; balls sink %.1f mm into each other' % (1000 * depth))


@check('examples/halfplanes.xml')
def _(sc, tr, notes):
    ke0 = kinetic(sc, tr.ends[0])
    vmax = max(norm(v) for v in sc.v0) * 3
    for n, rec in enumerate(tr.ends):
        close(kinetic(sc, rec) / ke0, 1.0, 1e-12, 'kinetic energy at step %d' % n)
        for i in range(sc.n):
            for h in range(len(sc.halfplanes)):
                expect(halfplane_distance(sc, rec.pos(i), 0.0, h) > 0, 'ball %d escaped through half-plane %d' % (i, h))
    kinds = {im[0] for r in tr.ends for im in r.impulses}
    expect(PH in kinds, 'no wall bounce')
    notes.append('kinetic energy conserved to 1e-12 (COR 1); no ball centre ever crosses a half-plane; %d wall bounces' %
                 sum(1 for r in tr.ends for im in r.impulses if im[0] == PH))


# ---- t2m2/ContinuousTimeTests ------------------------------------------------------------------

def impulses_by_step(tr):
    return [(k, im) for k, rec in enumerate(tr.ends) for im in rec.impulses]


def ct_common(sc, tr):
    """Continuous-time: the end record repeats the mid record's state, impulses and polynomials."""
    for k, mid in enumerate(tr.mids):
        end = tr.ends[k + 1]
        expect(mid.x == end.x and mid.v == end.v and mid.impulses == end.impulses and mid.polys == end.polys,
               'step %d: mid and end records differ' % (k + 1))
        expect(len(end.polys) == pair_polys_per_pass(sc), 'step %d: %d polynomials' % (k + 1, len(end.polys)))


def tunnels(sc, i, j, kind, steps):
    gaps = straight_line_gaps(sc, i, j, kind, steps)
    expect(min(gaps) > 0, 'an end-of-step test would see this contact')
    return gaps


@check('t2m2/ContinuousTimeTests/tunnel_fixed_edge.xml')
def _(sc, tr, notes):
    ct_common(sc, tr)
    h, r = sc.dt, sc.r[0] + sc.edges[0][2]
    tunnels(sc, 0, 0, 'PE', sc.num_steps)
    hits = impulses_by_step(tr)
    t_hit = (sc.x0[1][0] - r - sc.x0[0][0]) / sc.v0[0][0]
    step = math.floor(t_hit / h) + 1
    expect(len(hits) == 1 and hits[0][0] == step and hits[0][1][:3] == (PE, 0, 0), 'impulses %s' % hits)
    close(hits[0][1][4], t_hit / h - (step - 1), 1e-9, 'collision time within the step')
    close2(unit(hits[0][1][3]), (1.0, 0.0), 1e-12, 'contact normal')
    for n, rec in enumerate(tr.ends):
        expect(rec.pos(0)[0] < sc.x0[1][0] - r, 'the ball passed the wall at step %d' % n)
        close2(rec.vel(0), sc.v0[0] if n < step else mul(-1, sc.v0[0]), 1e-12, 'velocity at step %d' % n)
    notes.append('straight-line step ends never overlap the wall (tunnelling scene); one PE impulse at the predicted step %d, tau %.3f (1e-9); velocity exactly reversed (1e-12); never past the wall' % (step, hits[0][1][4]))


@check('t2m2/ContinuousTimeTests/tunnel_free_edge.xml')
def _(sc, tr, notes):
    ct_common(sc, tr)
    tunnels(sc, 0, 0, 'PE', 6)
    conserved_momentum(sc, tr, notes)
    hits = impulses_by_step(tr)
    expect(len(hits) == 1 and hits[0][1][:3] == (PE, 0, 0), 'impulses %s' % hits)
    for n, rec in enumerate(tr.ends):
        # While the ball is over the edge (its projection falls on the segment) it is above it.
        e = sub(rec.pos(2), rec.pos(1))
        w = sub(rec.pos(0), rec.pos(1))
        if 0 <= dot(w, e) <= dot(e, e):
            expect(cross(e, w) > 0, 'the ball is below the edge at step %d' % n)
    last = tr.ends[-1]
    expect(last.vel(0)[1] > 0 and last.vel(1)[1] < 0 and last.vel(2)[1] < 0, 'no bounce')
    notes.append('tunnelling scene (no straight-line step end overlaps); one PE impulse; ball always above the edge line; ball up, edge down')


@check('t2m2/ContinuousTimeTests/head_on_swap.xml')
def _(sc, tr, notes):
    ct_common(sc, tr)
    tunnels(sc, 0, 1, 'PP', sc.num_steps)
    h = sc.dt
    rel_speed = norm(sub(sc.v0[0], sc.v0[1]))
    t_hit = (norm(sub(sc.x0[1], sc.x0[0])) - sc.r[0] - sc.r[1]) / rel_speed
    step = math.floor(t_hit / h) + 1
    hits = impulses_by_step(tr)
    expect(len(hits) == 1 and hits[0][0] == step and hits[0][1][:3] == (PP, 0, 1), 'impulses %s' % hits)
    close(hits[0][1][4], t_hit / h - (step - 1), 1e-9, 'collision time within the step')
    for n in range(step, len(tr.ends)):
        close2(tr.ends[n].vel(0), sc.v0[1], 1e-12, 'v0 after the swap, step %d' % n)
        close2(tr.ends[n].vel(1), sc.v0[0], 1e-12, 'v1 after the swap, step %d' % n)
    notes.append('tunnelling scene; one PP impulse at the predicted step %d, tau %.3f (1e-9); velocities exactly exchanged (1e-12)' % (step, hits[0][1][4]))


@check('t2m2/ContinuousTimeTests/simultaneous.xml')
def _(sc, tr, notes):
    ct_common(sc, tr)
    conserved_momentum(sc, tr, notes)
    ke0 = kinetic(sc, tr.ends[0])
    for n, rec in enumerate(tr.ends):
        close(kinetic(sc, rec) / ke0, 1.0, 1e-12, 'kinetic energy at step %d' % n)
    hits = impulses_by_step(tr)
    first = hits[0][0]
    same = [im[:3] for k, im in hits if k == first]
    expect(same == [(PP, 0, 1), (PP, 1, 2)], 'first step impulses %s' % same)
    expect(any(k > first and im[:3] == (PP, 0, 1) for k, im in hits), 'no second collision')
    v = [tr.ends[first].vel(i)[0] for i in range(3)]
    # Sequential 1D elastic collisions: (0,1) then (1,2) with the updated velocity of 1.
    m = sc.m
    u0, u1, u2 = sc.v0[0][0], sc.v0[1][0], sc.v0[2][0]
    a0 = ((m[0] - m[1]) * u0 + 2 * m[1] * u1) / (m[0] + m[1])
    a1 = ((m[1] - m[0]) * u1 + 2 * m[0] * u0) / (m[0] + m[1])
    b1 = ((m[1] - m[2]) * a1 + 2 * m[2] * u2) / (m[1] + m[2])
    b2 = ((m[2] - m[1]) * u2 + 2 * m[1] * a1) / (m[1] + m[2])
    for got, want, name in zip(v, (a0, b1, b2), 'left middle right'.split()):
        close(got, want, 1e-9, name + ' velocity after the double hit')
    notes.append('both contacts in step %d, resolved in pair order to the sequential 1D elastic result (1e-9); momentum (1e-12) and kinetic energy (1e-12) conserved' % first)


def halfplane_cor(sc, tr, notes):
    ct_common(sc, tr)
    h, e = sc.dt, sc.cor
    p, m = sc.halfplanes[0]
    nh = unit(m)
    hits = impulses_by_step(tr)
    expect(len(hits) == sc.n, 'impulses %s' % hits)
    for i in range(sc.n):
        x0, v0 = sc.x0[i], sc.v0[i]
        d0 = dot(sub(x0, p), nh) - sc.r[i]
        t_hit = d0 / -dot(v0, nh)
        step = math.floor(t_hit / h) + 1
        mine = [(k, im) for k, im in hits if im[1] == i]
        expect(len(mine) == 1 and mine[0][0] == step and mine[0][1][:3] == (PH, i, 0), 'impulses of %d: %s' % (i, mine))
        close(mine[0][1][4], t_hit / h - (step - 1), 1e-9, 'collision time of %d' % i)
        close2(unit(mine[0][1][3]), mul(-1, nh), 1e-12, 'contact normal of %d' % i)
        v1 = sub(v0, mul((1 + e) * dot(v0, nh), nh))
        for n, rec in enumerate(tr.ends):
            v = v0 if n < step else v1
            close2(rec.vel(i), v, 1e-12, 'v[%d] at step %d' % (i, n))
            if n > 0:
                close2(rec.pos(i), add(tr.ends[n - 1].pos(i), mul(h, v)), 1e-12, 'x[%d] at step %d' % (i, n))
        close(dot(v1, nh), -e * dot(v0, nh), 1e-12, 'normal speed ratio')
        notes.append('ball %d: one PH impulse at the predicted step %d, tau %.3f (1e-9); leaves with normal velocity -COR times incoming (%.3f -> %.3f m/s) and tangential unchanged (1e-12)'
                     % (i, step, mine[0][1][4], dot(v0, nh), dot(tr.ends[-1].vel(i), nh)))


check('t2m2/ContinuousTimeTests/halfplane_cor0.xml', 't2m2/ContinuousTimeTests/halfplane_cor05.xml',
      't2m2/ContinuousTimeTests/halfplane_cor1.xml')(halfplane_cor)


@check('t2m2/ContinuousTimeTests/near_miss.xml')
def _(sc, tr, notes):
    ct_common(sc, tr)
    expect(not impulses_by_step(tr), 'an impulse was recorded')
    h = sc.dt
    for n, rec in enumerate(tr.ends):
        for i in range(sc.n):
            close2(rec.pos(i), add(sc.x0[i], mul(n * h, sc.v0[i])), 1e-12 * (1 + n), 'x[%d] at step %d' % (i, n))
    # The closest approach of each planned pass (straight lines, computed on a fine grid).
    T = sc.duration
    fine = [T * s / 20000 for s in range(20001)]
    at = lambda i, t: add(sc.x0[i], mul(t, sc.v0[i]))
    g1 = min(norm(sub(at(0, t), at(1, t))) for t in fine) - sc.r[0] - sc.r[1]
    g2 = min(segment_distance(at(2, t), at(3, t), at(4, t)) for t in fine) - sc.r[2] - sc.edges[0][2]
    g3 = min(halfplane_distance(sc, at(5, t), sc.r[5], 0) for t in fine)
    for g in (g1, g2, g3):
        expect(0.004 < g < 0.006, 'gap %g is not a near miss' % g)
    notes.append('no impulse; every ball moves on its straight line (1e-12); the planned passes miss by %.4f, %.4f, %.4f m' % (g1, g2, g3))


# ---- t2m2/ImpulsesTests ------------------------------------------------------------------------

@check('t2m2/ImpulsesTests/cradle.xml')
def _(sc, tr, notes):
    hybrid_impulses_only(sc, tr, notes, min_passes=4)
    conserved_momentum(sc, tr, notes)
    ke0 = kinetic(sc, tr.ends[0])
    for n, rec in enumerate(tr.ends):
        close(kinetic(sc, rec) / ke0, 1.0, 1e-12, 'kinetic energy at step %d' % n)
    last = tr.ends[-1]
    for i in range(sc.n - 1):
        close2(last.vel(i), (0.0, 0.0), 1e-12, 'ball %d at rest' % i)
    close2(last.vel(sc.n - 1), sc.v0[0], 1e-12, 'last ball leaves with the first ball\'s velocity')
    notes.append('kinetic energy conserved (1e-12); at the end only the last ball moves, at exactly the incoming velocity (1e-12)')


@check('t2m2/ImpulsesTests/mass_ladder.xml')
def _(sc, tr, notes):
    hybrid_impulses_only(sc, tr, notes, min_passes=3)
    conserved_momentum(sc, tr, notes)
    ke0 = kinetic(sc, tr.ends[0])
    for n, rec in enumerate(tr.ends):
        close(kinetic(sc, rec) / ke0, 1.0, 1e-12, 'kinetic energy at step %d' % n)
    # Sequential 1D elastic collisions down the ladder.
    v = [sc.v0[i][0] for i in range(sc.n)]
    for i in range(sc.n - 1):
        m1, m2 = sc.m[i], sc.m[i + 1]
        v[i], v[i + 1] = ((m1 - m2) * v[i] + 2 * m2 * v[i + 1]) / (m1 + m2), ((m2 - m1) * v[i + 1] + 2 * m1 * v[i]) / (m1 + m2)
    for i in range(sc.n):
        close2(tr.ends[-1].vel(i), (v[i], 0.0), 1e-12, 'final velocity of ball %d' % i)
    notes.append('kinetic energy conserved (1e-12); final velocities equal the chain of 1D elastic collisions (1e-12), last ball %.3f m/s' % v[-1])


@check('t2m2/ImpulsesTests/fixed_posts.xml')
def _(sc, tr, notes):
    hybrid_impulses_only(sc, tr, notes, min_passes=2)
    bounces = 0
    for n, rec in enumerate(tr.ends):
        close(norm(rec.vel(2)), 4.0, 1e-12, 'ping-pong speed at step %d' % n)
        expect(sc.x0[1][1] < rec.pos(2)[1] < sc.x0[0][1], 'ping-pong ball left the posts')
        close(rec.pos(2)[0], sc.x0[2][0], 0.0, 'ping-pong ball moved sideways')
        if n and rec.vel(2)[1] != tr.ends[n - 1].vel(2)[1]:
            bounces += 1
    ke = [kinetic(sc, r, [3, 4]) for r in tr.ends]
    close(ke[-1] / ke[0], 1.0, 1e-12, 'kinetic energy of the pushed pair')
    expect(tr.ends[-1].vel(4)[0] < 0 and tr.ends[-1].vel(3)[0] < 0, 'the pair did not bounce back off the post')
    notes.append('the ball between the posts keeps speed 4 exactly (1e-12) through %d bounces; the pair on the right keeps its kinetic energy (1e-12) and comes back' % bounces)


@check('t2m2/ImpulsesTests/shelf_bounce.xml')
def _(sc, tr, notes):
    hybrid_impulses_only(sc, tr, notes, min_passes=2)
    # First floor bounce of ball 3: the step's velocity is -COR times the predicted one (normal y).
    g, h = sc.gravity[0][1], sc.dt
    for n in range(1, len(tr.ends)):
        before, after = tr.ends[n - 1].vel(3), tr.ends[n].vel(3)
        if after[1] > 0:
            predicted = before[1] + h * g
            close(after[1], -sc.cor * predicted, 1e-12, 'floor bounce of ball 3 at step %d' % n)
            close(after[0], before[0], 1e-12, 'tangential velocity kept')
            notes.append('first floor bounce (step %d): upward speed = COR x predicted downward speed (%.4f = 0.5 x %.4f, 1e-12)' % (n, after[1], -predicted))
            break
    else:
        raise CheckFailed('ball 3 never bounced')


# ---- t2m2/GeometricTests -----------------------------------------------------------------------

def frozen_from(tr, i):
    """The first step from which particle i never moves again (None if it moves in the last step)."""
    last = tr.ends[-1].pos(i)
    k = len(tr.ends) - 1
    while k > 0 and tr.ends[k - 1].pos(i) == last:
        k -= 1
    return k if k < len(tr.ends) - 1 else None


@check('t2m2/GeometricTests/stack.xml')
def _(sc, tr, notes):
    hybrid_failsafe_only(sc, tr, notes)
    steps = [frozen_from(tr, i) for i in range(sc.n)]
    expect(all(s is not None for s in steps), 'not all at rest: %s' % steps)
    for i in range(sc.n):
        expect(tr.ends[-1].vel(i) == (0.0, 0.0), 'ball %d still has velocity' % i)
    expect(steps == sorted(steps), 'balls froze out of order: %s' % steps)
    notes.append('balls come to rest bottom-up (steps %s) and never move again (bit-exact)' % steps)


@check('t2m2/GeometricTests/trapped.xml')
def _(sc, tr, notes):
    hybrid_failsafe_only(sc, tr, notes)
    for i in (2, 3):
        k = frozen_from(tr, i)
        expect(k is not None, 'ball %d never stops' % i)
        # It stops where its straight-line motion would have hit a post in the next step.
        for n in range(k):
            close2(tr.ends[n].pos(i), add(sc.x0[i], mul(n * sc.dt, sc.v0[i])), 1e-12, 'free flight of %d' % i)
        nxt = add(tr.ends[k].pos(i), mul(sc.dt, sc.v0[i]))
        gap = min(norm(sub(nxt, sc.x0[p])) - sc.r[i] - sc.r[p] for p in (0, 1))
        expect(gap < 0, 'ball %d stopped without reason' % i)
        expect(tr.ends[-1].vel(i) == (0.0, 0.0), 'ball %d has velocity' % i)
        notes.append('ball %d flies straight (1e-12), stops dead at step %d, the step whose straight-line motion would reach a post, and never moves again' % (i, k))


@check('t2m2/GeometricTests/zone_halfplane.xml')
def _(sc, tr, notes):
    hybrid_failsafe_only(sc, tr, notes)
    floor = sc.halfplanes[0]
    for i in range(sc.n):
        expect(frozen_from(tr, i) is not None and tr.ends[-1].vel(i) == (0.0, 0.0), 'ball %d not at rest' % i)
    air = [i for i in range(sc.n) if halfplane_distance(sc, tr.ends[-1].pos(i), sc.r[i], 0) > 0.05]
    expect(air == [1, 3], 'balls frozen in mid-air: %s' % air)
    # The mid-air pair: rigid while it flies (distance kept after its first contact).
    d = [norm(sub(r.pos(3), r.pos(2))) - sc.r[2] - sc.r[3] for r in tr.ends]
    expect(min(d) >= -1e-12, 'pair overlapped')
    notes.append('all balls end at rest; balls 1 and 3 are frozen in mid-air (%.3f and %.3f m above the floor) as members of zones that touch the floor' %
                 tuple(halfplane_distance(sc, tr.ends[-1].pos(i), sc.r[i], 0) for i in (1, 3)))


@check('t2m2/GeometricTests/edge_triangle.xml')
def _(sc, tr, notes):
    hybrid_failsafe_only(sc, tr, notes)
    conserved_momentum(sc, tr, notes)
    for n, rec in enumerate(tr.ends):
        e = sub(rec.pos(1), rec.pos(0))
        expect(cross(e, sub(rec.pos(3), rec.pos(0))) > 0, 'ball passed the leading edge at step %d' % n)
    expect(tr.ends[-1].vel(3)[0] > 1.0, 'ball not carried along')
    notes.append('the ball stays ahead of the leading edge at every step end and is carried along at %.2f m/s' % tr.ends[-1].vel(3)[0])


@check('t2m2/GeometricTests/glancing.xml')
def _(sc, tr, notes):
    acted = hybrid_failsafe_only(sc, tr, notes)
    conserved_momentum(sc, tr, notes)
    expect(acted == 1, 'failsafe acted in %d steps' % acted)
    k = next(k for k, mid in enumerate(tr.mids) if mid.x != tr.ends[k + 1].x) + 1
    a, b = tr.ends[k - 1], tr.ends[k]
    close(norm(sub(b.pos(1), b.pos(0))), norm(sub(a.pos(1), a.pos(0))), 1e-12, 'distance kept by the rigid step')
    # Rigid rotation about the centre of mass: same angle for both arms.
    M = sc.m[0] + sc.m[1]
    cm = lambda r: mul(1.0 / M, add(mul(sc.m[0], r.pos(0)), mul(sc.m[1], r.pos(1))))
    arm0, arm1 = sub(a.pos(0), cm(a)), sub(b.pos(0), cm(b))
    angle = math.atan2(cross(arm0, arm1), dot(arm0, arm1))
    notes.append('the failsafe acts in exactly one step (%d), keeps the pair distance (1e-12), turns the pair by %.3f rad' % (k, angle))


# ---- t2m2/HolisticTests and the creative scene -------------------------------------------------

def hybrid_stats(sc, tr, notes):
    per_pass = pair_polys_per_pass(sc)
    failsafe = sum(1 for k, mid in enumerate(tr.mids) if mid.x != tr.ends[k + 1].x or mid.v != tr.ends[k + 1].v)
    most = max(len(m.polys) // per_pass for m in tr.mids)
    notes.append('%d steps needed the failsafe; up to %d impulse passes in a step' % (failsafe, most))


@check('t2m2/HolisticTests/v_pile.xml')
def _(sc, tr, notes):
    hybrid_stats(sc, tr, notes)
    ke = [kinetic(sc, r) for r in tr.ends]
    fastest = max(norm(tr.ends[-1].vel(i)) for i in range(sc.n))
    expect(fastest < 0.05 and ke[-1] < 1e-3 * max(ke), 'not settled: speed %g' % fastest)
    for i in range(sc.n):
        expect(tr.ends[-1].pos(i)[1] < sc.x0[i][1], 'ball %d did not fall' % i)
    notes.append('the heap settles: final speeds below %.3f m/s, kinetic energy %.1e of its peak; every ball ends below its start' % (fastest, ke[-1] / max(ke)))


@check('t2m2/HolisticTests/chains_floor.xml')
def _(sc, tr, notes):
    hybrid_stats(sc, tr, notes)
    worst = 0.0
    for rec in tr.ends:
        for (e, k, l0, b) in sc.springs:
            i, j, _ = sc.edges[e]
            worst = max(worst, abs(norm(sub(rec.pos(j), rec.pos(i))) / l0 - 1))
    expect(worst < 0.1, 'a link stretched by %g' % worst)
    expect(any(cross(sub(r.pos(2), r.pos(1)), sub(r.pos(4), r.pos(1))) > 0 and r.vel(4)[1] > 0 for r in tr.ends), 'ball never bounced off the chain')
    notes.append('links keep their length within %.1f%%; the ball bounces off the chain from above' % (100 * worst))


@check('t2m2/HolisticTests/mixed_sizes.xml')
def _(sc, tr, notes):
    hybrid_stats(sc, tr, notes)
    ratio = norm(tr.ends[-1].vel(0)) / norm(sc.v0[0])
    expect(0.05 < ratio < 0.5, 'big ball speed ratio %g' % ratio)
    expect(max(r.pos(3)[1] for r in tr.ends) > 0.0, 'the smallest ball never popped up')
    notes.append('big ball slowed to %.0f%% of its speed; smallest ball pops up above y = 0' % (100 * ratio))


@check('t2m2/HolisticTests/seesaw.xml')
def _(sc, tr, notes):
    hybrid_stats(sc, tr, notes)
    expect(max(r.pos(4)[1] for r in tr.ends) > 2.0, 'the light ball was not tossed')
    notes.append('the light ball is tossed above y = 2')


@check('t2m2/creative.xml')
def _(sc, tr, notes):
    hybrid_stats(sc, tr, notes)
    pins = [i for i in range(sc.n) if sc.fixed[i]]
    balls = [i for i in range(sc.n) if not sc.fixed[i]]
    clear = min(sc.r[p] for p in pins) + min(sc.r[b] for b in balls)
    step = max(norm(sub(tr.ends[k + 1].pos(b), tr.ends[k].pos(b))) for k in range(sc.num_steps) for b in balls)
    expect(step > 2 * clear, 'balls are too slow to need continuous-time detection')
    for rec in tr.ends:
        for b in balls:
            for h in range(len(sc.halfplanes)):
                expect(halfplane_distance(sc, rec.pos(b), sc.r[b], h) > -1e-9, 'ball left the box')
    notes.append('balls move up to %.2f m in one step (pin clearance %.2f m); nobody leaves the box' % (step, clear))


# ---- driver ------------------------------------------------------------------------------------------

def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--root', default=os.path.dirname(here), help='the repository (default: this file\'s parent)')
    ap.add_argument('--oracle', default=None, help='folder of the .bin files (default ROOT/oracle)')
    ap.add_argument('-v', '--verbose', action='store_true', help='print what each check established')
    ap.add_argument('--markdown', action='store_true', help='print one Markdown list item per scene (for oracle/README.md)')
    ap.add_argument('scenes', nargs='*')
    args = ap.parse_args()
    assets = os.path.join(args.root, 'assets')
    oracle = args.oracle or os.path.join(args.root, 'oracle')
    found = sorted(os.path.relpath(os.path.join(d, f), assets)
                   for d, _, files in os.walk(assets) for f in files
                   if f.endswith('.xml') and not os.path.relpath(d, assets).split(os.sep)[0] == 'showcase')
    scenes = args.scenes or found
    failed = 0
    for rel in scenes:
        notes = []
        try:
            expect(rel in CHECKS, 'no check written for this scene')
            bin_path = os.path.join(oracle, os.path.splitext(rel)[0] + '.bin')
            expect(os.path.exists(bin_path), 'no oracle file %s' % bin_path)
            sc = Scene(os.path.join(assets, rel))
            tr = Trajectory(bin_path, sc)
            generic(sc, tr, notes)
            CHECKS[rel](sc, tr, notes)
            if args.markdown:
                print('- `%s`: %s.' % (os.path.splitext(rel)[0] + '.bin', '; '.join(notes)))
                continue
            print('ok   %s' % rel)
            if args.verbose:
                for n in notes:
                    print('       - ' + n)
        except Exception as e:  # noqa: BLE001 - report every scene
            failed += 1
            print('FAIL %s: %s' % (rel, e))
            if not isinstance(e, (CheckFailed, AssertionError)):
                traceback.print_exc()
    stale = sorted(set(CHECKS) - set(found))
    for rel in stale if not args.scenes else []:
        failed += 1
        print('FAIL %s: a check exists but the scene does not' % rel)
    if not args.markdown or failed:
        print('%d passed, %d failed' % (len(scenes) - min(failed, len(scenes)), failed))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
