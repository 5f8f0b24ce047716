"""Checks of the oracle trajectories of assets/t2m2 (the four course families) and the creative
scene: predicted collision times, exact velocity exchanges, no overlap at step ends."""
import math

from fosssim_traj import (PE, PH, PP, add, cross, dot, mul, norm, segment_distance, sub, unit)
from checks_common import (CheckFailed, check, close, close2, conserved_kinetic, conserved_momentum,
                           expect, halfplane_distance, hybrid_failsafe_only, hybrid_impulses_only,
                           kinetic, pair_polys_per_pass, straight_line_gaps)

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
    conserved_kinetic(sc, tr)
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
    conserved_kinetic(sc, tr)
    last = tr.ends[-1]
    for i in range(sc.n - 1):
        close2(last.vel(i), (0.0, 0.0), 1e-12, 'ball %d at rest' % i)
    close2(last.vel(sc.n - 1), sc.v0[0], 1e-12, 'last ball leaves with the first ball\'s velocity')
    notes.append('kinetic energy conserved (1e-12); at the end only the last ball moves, at exactly the incoming velocity (1e-12)')


@check('t2m2/ImpulsesTests/mass_ladder.xml')
def _(sc, tr, notes):
    hybrid_impulses_only(sc, tr, notes, min_passes=3)
    conserved_momentum(sc, tr, notes)
    conserved_kinetic(sc, tr)
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
