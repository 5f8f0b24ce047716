"""What every oracle check shares: the registry of per-scene checks, assertions, and physics helpers
computed from the scene and trajectory alone (see check.py; the checks every scene gets are in
checks_default_mode.py)."""
import math

from fosssim_traj import add, dot, mul, norm, segment_distance, sub, unit

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


def explicit_prediction(sc, rec, with_penalty=False):
    """The integrator's step from `rec` with no collision response (explicit or symplectic Euler);
    `with_penalty` adds the hybrid's penalty force to the scene's forces."""
    h = sc.dt
    x = [rec.pos(i) for i in range(sc.n)]
    v = [rec.vel(i) for i in range(sc.n)]
    f = forces(sc, x, v)
    if with_penalty:
        fp = penalty_forces(sc, x)
        f = [[f[i][0] + fp[i][0], f[i][1] + fp[i][1]] for i in range(sc.n)]
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


# ---- conservation checks the scenes' checks share -------------------------------------------------

def conserved_kinetic(sc, tr, tol=1e-12):
    """Kinetic energy at every step end equals the first record's, relative to it."""
    ke0 = kinetic(sc, tr.ends[0])
    for n, rec in enumerate(tr.ends):
        close(kinetic(sc, rec) / ke0, 1.0, tol, 'kinetic energy at step %d' % n)


def conserved_momentum(sc, tr, notes, tol=1e-12, which=None, upto=None):
    p0 = momentum(sc, tr.ends[0], which)
    scale = max(1.0, norm(p0))
    for k, rec in enumerate(tr.ends[:upto]):
        close2(momentum(sc, rec, which), p0, tol * scale, 'momentum at step %d' % k)
    notes.append('total momentum conserved to %g' % tol)


# ---- forces and predictions the default-mode checks share -------------------------------------

def penalty_forces(sc, x):
    """The hybrid handler's penalty force (spec section 1): per pair within radii + thickness,
    energy k/2 (|n| - r_sum - thickness)^2; gradient only."""
    k, th = sc.penalty_k, sc.penalty_thickness
    f = [[0.0, 0.0] for _ in range(sc.n)]

    def push(i, n, R, w=1.0):
        d = norm(n)
        if d < R and d > 0:
            s = w * k * (d - R) / d
            f[i][0] += s * n[0]
            f[i][1] += s * n[1]
    for i in range(sc.n):
        for j in range(i + 1, sc.n):
            n = sub(x[j], x[i])
            R = sc.r[i] + sc.r[j] + th
            if norm(n) < R:
                push(i, n, R)
                push(j, mul(-1, n), R)
        for (a, b, re) in sc.edges:
            if i in (a, b):
                continue
            e = sub(x[b], x[a])
            ee = dot(e, e)
            al = 0.0 if ee == 0 else max(0.0, min(1.0, dot(sub(x[i], x[a]), e) / ee))
            n = sub(add(x[a], mul(al, e)), x[i])
            R = sc.r[i] + re + th
            if norm(n) < R:
                push(i, n, R)
                push(a, mul(-1, n), R, 1 - al)
                push(b, mul(-1, n), R, al)
        for (p, m) in sc.halfplanes:
            mh = unit(m)
            n = mul(dot(sub(p, x[i]), mh), mh)
            push(i, n, sc.r[i] + th)
    return f


def predicted_motion(sc, rec):
    """The integrator's step from `rec` before collision handling (explicit or symplectic Euler,
    plus the hybrid's penalty force): end positions and velocities."""
    return explicit_prediction(sc, rec, with_penalty=(sc.collision == 'hybrid'))
