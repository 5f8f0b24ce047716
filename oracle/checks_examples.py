"""Checks of the oracle trajectories of assets/examples (closed forms, conservation laws)."""
import math

from fosssim_traj import (PH, PP, add, cross, mul, norm, sub)
from checks_common import (check, close, close2, conserved_kinetic, conserved_momentum, expect,
                           explicit_prediction, forces, halfplane_distance, kinetic)

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
    conserved_kinetic(sc, tr)
    for rec in tr.ends:
        for i in range(sc.n):
            for h in range(len(sc.halfplanes)):
                expect(halfplane_distance(sc, rec.pos(i), 0.0, h) > 0, 'ball %d escaped through half-plane %d' % (i, h))
    kinds = {im[0] for r in tr.ends for im in r.impulses}
    expect(PH in kinds, 'no wall bounce')
    notes.append('kinetic energy conserved to 1e-12 (COR 1); no ball centre ever crosses a half-plane; %d wall bounces' %
                 sum(1 for r in tr.ends for im in r.impulses if im[0] == PH))
