"""Checks of the oracle trajectories of assets/t2m2 (the four course families) and the creative
scene: predicted collision times, exact velocity exchanges, no overlap at step ends. This file holds
ContinuousTimeTests and ImpulsesTests; checks_t2m2_zones.py the rest.

These files are made by the default mode (contacts in time order, sequential impulses, paths that
bend at contact times, projection failsafe with the COR's restitution), not by the course's handlers (which --compat
reproduces). Every scene here also gets checks_default_mode.default_mode (polynomial log over the
predicted motion, impulses replayed in time order, no deepening, no tunnelling along the replayed
paths, no kinetic energy added, momenta of free scenes). Where a check used to encode the course's
behaviour (one impulse pass per contact, summed impulses, straight motion through a contact step,
rigid impact zones that freeze), it now checks what the default mode promises instead; each such
place says why."""
import math

from fosssim_traj import (PE, PH, PP, add, cross, dot, mul, norm, segment_distance, sub, unit)
from checks_common import (CheckFailed, check, close, close2, conserved_kinetic, conserved_momentum,
                           expect, halfplane_distance, kinetic, straight_line_gaps)

# ---- t2m2/ContinuousTimeTests ------------------------------------------------------------------

def impulses_by_step(tr):
    return [(k, im) for k, rec in enumerate(tr.ends) for im in rec.impulses]


def ct_common(sc, tr):
    """Continuous-time: default_mode (run by generic) checked the records, the polynomial log (one
    set per pair) and the replay; here no step may need the failsafe (a particle may take 32
    impulses in a step before it does, far more than these scenes need)."""
    bad = [k for k in range(1, len(tr.explained)) if not tr.explained[k]]
    expect(not bad, 'steps not explained by their impulses (failsafe): %s' % bad)


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
    # The course applied the two contacts once each, one after the other, from positions moved as
    # if the new velocities held for the whole step, so the middle ball met the left one again a few
    # steps later. The default mode brings all three balls to the contact instant, where both
    # contacts close at once: they are one round of hits, answered together by Moreau's law,
    # v+ = P v + e (P v - v) with P v the inelastic projection. Both rows are active in P v (the
    # three balls' common velocity V = sum m v / sum m closes neither contact, and the multipliers
    # that reach it are positive), so every ball leaves at V + e (V - v): the symmetric scene stays
    # symmetric (the middle ball keeps still, the light balls bounce back at their speed).
    ct_common(sc, tr)
    conserved_momentum(sc, tr, notes)
    conserved_kinetic(sc, tr)
    hits = impulses_by_step(tr)
    h = sc.dt
    t_hit = (sc.x0[1][0] - sc.x0[0][0] - sc.r[0] - sc.r[1]) / (sc.v0[0][0] - sc.v0[1][0])
    t_hit2 = (sc.x0[2][0] - sc.x0[1][0] - sc.r[1] - sc.r[2]) / (sc.v0[1][0] - sc.v0[2][0])
    close(t_hit, t_hit2, 1e-12, 'both balls reach the middle one at once')
    step = math.floor(t_hit / h) + 1
    v0 = [sc.v0[i][0] for i in range(3)]
    V = sum(m * v for m, v in zip(sc.m, v0)) / sum(sc.m)
    want_v = [V + sc.cor * (V - v) for v in v0]
    expect([im[:3] for k, im in hits] == [(PP, 0, 1), (PP, 1, 2)] and all(k == step for k, im in hits),
           'impulses %s, expected (0, 1) and (1, 2), once each, in step %d' % (hits, step))
    for k, im in hits:
        close(im[4], t_hit / h - (step - 1), 1e-9, 'contact instant within the step')
    for i in range(3):
        close2(tr.ends[step].vel(i), (want_v[i], 0.0), 1e-9, 'velocity of ball %d after the contact instant' % i)
    for k in range(step, len(tr.ends)):
        close(tr.ends[k].vel(0)[0], -tr.ends[k].vel(2)[0], 1e-12, 'step %d: the outer balls mirror each other' % k)
    notes.append('both contacts at the predicted instant of step %d (tau %.3f, 1e-9), once each; velocities %s equal Moreau\'s law for the two hits together (1e-9): the outer balls bounce back mirrored, the middle one keeps still; momentum (1e-12) and kinetic energy (1e-12) conserved'
                 % (step, hits[0][1][4], ', '.join('%.3f' % x for x in want_v)))


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
            if n == step:
                # The path bends at the contact time (the course moved the whole step at v1).
                tau = mine[0][1][4]
                close2(rec.pos(i), add(tr.ends[n - 1].pos(i), add(mul(tau * h, v0), mul((1 - tau) * h, v1))), 1e-12,
                       'x[%d] at the contact step %d (bent path)' % (i, n))
            elif n > 0:
                close2(rec.pos(i), add(tr.ends[n - 1].pos(i), mul(h, v)), 1e-12, 'x[%d] at step %d' % (i, n))
        close(dot(v1, nh), -e * dot(v0, nh), 1e-12, 'normal speed ratio')
        notes.append('ball %d: one PH impulse at the predicted step %d, tau %.3f (1e-9); leaves with normal velocity -COR times incoming (%.3f -> %.3f m/s) and tangential unchanged (1e-12); its path bends at the contact time (1e-12)'
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

def impulses_only(sc, tr, notes, min_cascade):
    """ImpulsesTests: the impulses resolve every step. The course counted impulse passes and showed
    that its failsafe never changed the state; the default mode has no passes (contacts come one
    at a time, in time order) and no separate failsafe record, so the same claim is: replaying the
    step's logged impulses reproduces every step (default_mode), and some step holds a cascade of
    at least `min_cascade` time-ordered impulses."""
    bad = [k for k in range(1, len(tr.explained)) if not tr.explained[k]]
    expect(not bad, 'steps not explained by their impulses (the failsafe acted): %s' % bad)
    most = max(len(r.impulses) for r in tr.ends)
    expect(most >= min_cascade, 'at most %d impulses in a step, expected >= %d' % (most, min_cascade))
    notes.append('the impulses alone explain every step (failsafe never acted); up to %d time-ordered impulses in a step' % most)


def chain_times(sc, tr, notes):
    """A row of balls on the x axis, struck by ball 0: the contacts (k, k+1) come one after another,
    each when ball k, moving at the velocity its own hit gave it, closes the gap to ball k+1 (at
    rest). Checks the logged pairs and their absolute times (in steps, 1e-9) and returns the
    predicted final velocities (sequential 1D elastic collisions)."""
    h = sc.dt
    v = [sc.v0[i][0] for i in range(sc.n)]
    t = 0.0
    hits = [((k - 1) + im[4], im) for k, rec in enumerate(tr.ends) for im in rec.impulses]
    expect(len(hits) == sc.n - 1, 'impulses %s' % [im for _, im in hits])
    for i in range(sc.n - 1):
        # Ball i + 1 is at rest and ball i has not moved before its own hit: the initial gap.
        gap = sc.x0[i + 1][0] - sc.x0[i][0] - sc.r[i] - sc.r[i + 1]
        t += gap / ((v[i] - v[i + 1]) * h)
        when, im = hits[i]
        expect(im[:3] == (PP, i, i + 1), 'contact %d is %s' % (i, im[:3]))
        close(when, t, 1e-9, 'time of contact (%d, %d) in steps' % (i, i + 1))
        m1, m2 = sc.m[i], sc.m[i + 1]
        v[i], v[i + 1] = ((m1 - m2) * v[i] + 2 * m2 * v[i + 1]) / (m1 + m2), ((m2 - m1) * v[i + 1] + 2 * m1 * v[i]) / (m1 + m2)
    notes.append('contacts (0,1), (1,2), ... at the predicted times (1e-9 of a step): %s' % ', '.join('%.4f' % w for w, _ in hits))
    return v


@check('t2m2/ImpulsesTests/cradle.xml')
def _(sc, tr, notes):
    impulses_only(sc, tr, notes, min_cascade=3)
    conserved_momentum(sc, tr, notes)
    conserved_kinetic(sc, tr)
    chain_times(sc, tr, notes)
    last = tr.ends[-1]
    for i in range(sc.n - 1):
        close2(last.vel(i), (0.0, 0.0), 1e-12, 'ball %d at rest' % i)
    close2(last.vel(sc.n - 1), sc.v0[0], 1e-12, 'last ball leaves with the first ball\'s velocity')
    notes.append('kinetic energy conserved (1e-12); at the end only the last ball moves, at exactly the incoming velocity (1e-12)')


@check('t2m2/ImpulsesTests/mass_ladder.xml')
def _(sc, tr, notes):
    impulses_only(sc, tr, notes, min_cascade=3)
    conserved_momentum(sc, tr, notes)
    conserved_kinetic(sc, tr)
    v = chain_times(sc, tr, notes)
    for i in range(sc.n):
        close2(tr.ends[-1].vel(i), (v[i], 0.0), 1e-12, 'final velocity of ball %d' % i)
    notes.append('kinetic energy conserved (1e-12); final velocities equal the chain of 1D elastic collisions (1e-12), last ball %.3f m/s' % v[-1])


@check('t2m2/ImpulsesTests/fixed_posts.xml')
def _(sc, tr, notes):
    impulses_only(sc, tr, notes, min_cascade=1)
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
    impulses_only(sc, tr, notes, min_cascade=1)
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
