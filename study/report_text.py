"""The words of docs/study.md around the generated tables and charts (report.py fills them in).

Every number in the prose is a placeholder that report.py (and report_contacts.py) fill from this
run's CSV files, and every sentence whose truth depends on a measurement (exact or not, bounced
or not, settled or frozen, gained or not) is chosen there by the measured outcome; what stays
literal here is the set-up of each experiment and the physics behind it.
"""

STABILITY_THEORY = {
    # (cells of a Markdown table: a literal | is written \\|)
    "explicit-euler": "never stable: \\|1 + iω dt\\| > 1 (the measured value is where the growth reached x{blow_up} within the probe)",
    "symplectic-euler": "stable for ω dt < 2",
    "implicit-euler": "stable for every dt: \\|1/(1 − iω dt)\\| < 1",
    "linearized-implicit-euler": "stable for every dt (the same as implicit Euler on a linear spring)",
}

MODES = """\
## The default mode and --compat

Sections 1 to 5 run the default mode, the one every scene gets without `--compat`; section 6 runs
the multi-contact problems in both. Without `--compat`, `continuous-time` and `hybrid` handle
contacts as README.md ("Contacts in the default mode") promises, and this run measured:

- **Time order.** Within a step, contacts are resolved in the order they happen (hits of one
  instant together), each with one impulse against the current velocities, and the particles fly on from the contact
  time: {promise_order}
- **No energy gained with COR ≤ 1.** Hits that meet at one instant are answered together by
  Moreau's law (the inelastic projection of their velocities, then the COR's share of its change
  again), never summed from stale velocities, so that a symmetric impact stays symmetric whatever
  the numbering; resting contacts are answered one after another; and the failsafe (projection of a zone's velocities,
  then the COR's restitution for hits where it adds no energy; warm starts that a solve leaves
  adding energy are scaled back) can only take energy away: {promise_energy}
- **No tunnelling.** Every candidate pair is queried over the whole step, again after every
  impulse: {promise_tunnel}
- **Momentum and angular momentum** change only by impulses along the line through the contact:
  {promise_momentum}
- **Capsules and units.** Edges are capsules at their ends too, and a scene's collisions do not
  depend on its units; the study does not measure these (`tests/core/` does, README.md says how).

**What `--compat` keeps**: the course's formulation, bit for bit (the trajectories the course's
grader compares), flaws included. Section 6 measures them: {compat_measured}
"""

# The billiard-break bullets, chosen by report.py from the data: whether the hybrid without its
# penalty layer (k = 0) still gains energy tells the course's summed impulses (the --compat
# formulation) from the default mode, where only the penalty layer's work is left.
BILLIARD_SUMMED = """\
- **On the billiard break the hybrid handler gains energy (about +{hybrid_gain} of the kinetic
  energy, at every dt; without the penalty layer about +{hybrid_k0_gain})**: an impulse pass sums
  impulses that were each computed from the same end-of-step positions, so a disk struck by two
  others at once (the rack's apex) is pushed twice for one approach. `simple` and
  `continuous-time` keep the energy to rounding."""

BILLIARD_PENALTY = """\
- **On the billiard break the hybrid handler's penalty layer changes the kinetic energy (about
  +{hybrid_gain}, at every dt)**; without it (k = 0) the hybrid keeps the energy to
  {hybrid_k0_gain}, as `continuous-time` does: the default mode answers the rack's simultaneous
  contacts together by Moreau's law, which keeps the energy at COR 1 (section 6), and what remains
  is the work of the penalty force,
  which symplectic Euler does not integrate exactly."""

ODDITY_SUMMED = """\
- The hybrid handler gains kinetic energy on simultaneous impacts (about +{hybrid_gain} on a
  symmetric billiard break, independent of dt and maxiters): impulses of one pass are computed from
  the same positions and summed. This is the reference's formulation, so it is reproduced on
  purpose, but users should know.
"""

ODDITY_PENALTY = """\
- The hybrid's penalty layer changes the kinetic energy of a billiard break by about
  +{hybrid_gain} (without it, k = 0: {hybrid_k0_gain}); section 6 shows `--compat`, the course's
  summed impulses, gaining several times the energy on simultaneous contacts.
"""

CONTACTS_INTRO = """\
## 6. Multi-contact problems: the default mode next to --compat

Seven scenes where several contacts meet in one step, each run with the default mode (contacts in
time order, one impulse per contact and the hits of one instant together, the projection failsafe with the COR's restitution for hits; as its last resort a contact
still closing after its zone was solved again and again welds its particles and locks them
against its obstacles for the rest of the step, and a zone touching nothing moves rigidly) and with `--compat` (the course's formulation: impulses of a pass summed, continuous-time
in one pass, rigid impact zones that freeze against walls), for `continuous-time` and `hybrid`
(the hybrid without its penalty layer, k = 0, so that only contact handling differs). Symplectic
Euler throughout. The charts show energy (kinetic plus potential, relative to its start:
1 + (E - E0) / |E0|, which is E / E0 wherever E0 is positive), |momentum| and angular momentum
about the origin over time; the slot's curves add up its shots. Only the rack, the cradle and
the clump are isolated systems, where both momenta must stay flat; elsewhere walls, fixed edges
and gravity exchange momentum with the particles. \"Escaped\" is a centre that
crossed a wall's or an edge's line; \"frozen\" is a kinetic energy at or below {stopped_energy} of its peak
over at least the last {stopped_tail} % of the run (for the pile: while packed looser than {loosest_rest}, since
frictionless equal disks at rest pack at least as densely as random close packing, about 0.82 in 2D
(J. G. Berryman, Phys. Rev. A 27, 1053, 1983: 0.82 ± 0.02 for disks); its packing is judged from its mean height
against the N lowest sites of a triangular lattice in the V). Tests of each claim:
`tests/study/contacts_test.cpp`.
"""

CONTACTS_WORDS = """\
### What it says

- **Joint drop**: in the default mode the ball leaves the joint at its impact speed
  {joint_default_ratio} (an elastic flat contact reverses the normal velocity), and its energy peaks at
  {joint_default_gain} times its start (symplectic Euler's own error over the flights; the bounce
  itself is exact). `--compat`'s hybrid sums the impulses of the {joint_compat_contacts} contacts
  it finds in that step: the ball rebounds at {joint_compat_ratio} times its impact speed and the
  energy grows to {joint_compat_gain} times its start. `--compat`'s continuous-time rebounds at
  {joint_compat_ct_ratio} times the impact speed, its energy peaking at {joint_compat_ct_gain}
  times the start (its positions move as if the new velocity had held for the whole step).
- **Touching rack**: in the default mode the kinetic energy at the end differs from its start by
  {rack_default_energy}, momentum by {rack_default_momentum} and angular momentum by
  {rack_default_angular} of their scales. Its hits of one instant are answered together, so the
  rack breaks symmetric about its axis, as it is built (`tests/core/simultaneous_hits_test.cpp`
  checks every disk against its mirror image at every step). `--compat`'s energy peaks at
  {rack_compat_gain} times its start.
- **Corridor**: in the default mode the particle escapes in {corridor_default_escapes} of the
  runs, keeps its speed {corridor_default_speed} and bounces {corridor_default_bounces} times per
  step on average. With `--compat`, continuous-time {corridor_compat_ct}; the hybrid
  {corridor_compat_hybrid}.
- **Slot**: the default mode lets {slot_default_escaped} of {slot_disks} disks through over
  {slot_shots} shots, with up to {slot_contacts} contacts per step and shot (the busiest step,
  averaged over the shots). The contacts past a
  particle's quota of impulse events go to the failsafe (at most {slot_zones} of the
  disks in zones), {slot_loss}. `--compat`'s
  continuous-time lets {slot_compat_ct} through; its hybrid {slot_compat_hybrid}.
- **Newton's cradle**: {cradle_words}
- **Pile in a V** ({pile_disks} disks): in the default mode {pile_zone_mean} of the disks are in
  failsafe zones on average (continuous-time, hybrid; at most {pile_zone_max}), and
  {pile_rigid}. {pile_flows}: its mean height ends at
  {pile_default_height} m, against {pile_lattice} m for the lattice filling of the V and
  {pile_frozen_height} m for the column stopped at its first contact (packing
  {pile_default_packing}; {pile_default_flow}). `--compat`'s hybrid {pile_compat_hybrid}; its
  continuous-time {pile_compat_ct}.
- **Clump** ({clump_disks} disks held together by their own gravitation, no walls): in the
  default mode momentum and angular momentum stay within {clump_default_momentum} and
  {clump_default_angular} of their scales, though {clump_zone_mean} of the disks are in failsafe
  zones on average (continuous-time, hybrid) and a zone moves rigidly in {clump_rigid} of the
  {clump_steps} steps: a zone's rows are made again at the instant of each solve that changes
  them, so every impulse acts along the line through its contact then. `--compat`'s
  continuous-time {clump_compat_ct} (energy measured as 1 + (E - E0) / |E0|, since the
  gravitational energy makes E0 negative); its hybrid {clump_compat_hybrid}.
- {contacts_cost}
"""

INTRO = """\
# The study: what each method costs, how wrong it is, and where it breaks

FOSSSim offers four integrators and five ways of handling collisions. This study runs a matrix of
methods and time steps on problems whose right answer is known without the simulator, and shows
for each one the error, the wall time, and where it breaks. Everything here (the CSV files, the
charts and this page) is made by one command:

    scripts/study

It builds `fosssim-study` (Release, in `build-study/`), runs every experiment into
`docs/study/*.csv`, draws the charts with `study/charts.py` and writes this page with
`study/report.py`. {elapsed}The program and its options are described in
[study/README.md](../study/README.md).

Time is wall time on the project's machine ({machine}). Every timed run is repeated and the
least time kept (the run least disturbed by other work); even so, single numbers move between
regenerations, so trust ratios between methods, not the last digit of a time.
"""

METHODS = """\
## What is compared

- **Integrators** (accuracy and stability): explicit Euler, symplectic Euler, implicit Euler
  (Newton's method until the update is below {newton_tolerance} of the step's velocities, at most {newton_limit}
  iterations, each step halved while it would not lower the residual's energy) and
  linearized implicit Euler (one Newton step), as in the scene format.
- **Collision methods** (with symplectic Euler, in the default mode): `simple` (discrete, at the
  end of the step), `continuous-time` (contacts in time order within the step, one impulse each;
  a particle that has used up its quota of impulse events in a step hands its contacts to the
  failsafe's impact zones), `hybrid` with its defaults (the same with a quota of maxiters =
  {hybrid_maxiters} events per particle, plus a penalty layer k = {hybrid_k}, thickness {hybrid_thickness}),
  `hybrid k=0` (the same without the penalty layer's strength), and `penalty` at k = {penalty_ks}
  (thickness {penalty_thickness}).
- **Unstable** means: the simulator reported a non-finite state (its error names the step and the
  particle), an implicit solve failed, or the mechanical energy moved by more than **{blow_up} times**
  its starting scale (max of |E0|, kinetic and |potential|). A run is stopped there and reported,
  never crashed on. {blow_up} marks a blow-up, not an accuracy limit: a run can be wildly wrong and
  still "ok" ({wildest_ok}); its error then says so.
"""

PROBLEMS = """\
## The problems and their exact answers

Every answer below is derived from the physics, independently of the simulator; the tests in
`tests/study/closed_forms_test.cpp` check each one against its own equation.

{problems_table}

A measured contact time is the first step end at which the disk's velocity differs from its free
flight by more than half the exact change (so it has the resolution of one step; a penalty force,
which brakes gradually, is caught in the middle of its contact).
"""

ACCURACY_WORDS = """\
### What it says

- **Projectile**: all four integrators are exactly first order with the same error, g·dt·T/2
  (explicit Euler lags, the others lead). The implicit ones cost several times more per step for
  nothing: with a constant force, backward Euler *is* symplectic Euler.
- **Springs and orbit**: at the same time step symplectic Euler's position error is
  {sympl_vs_explicit} than explicit Euler's, at the same cost per step; it needs {sympl_vs_implicit}.
  On the orbit it keeps the angular momentum exactly (to rounding) and {orbit_energy_words}.
  Explicit and implicit Euler drift instead (spiralling out and in).
- **Explicit Euler gains energy on every oscillation** (x{explicit_gain} in {spring_periods} periods at
  dt = {explicit_gain_dt}). {explicit_rule_words} Implicit Euler damps the energy away (the
  undamped spring loses {implicit_loss} % of it at that dt).
- **Implicit Euler on the orbit fails** {orbit_failure}: Newton's method does not converge in
  {newton_limit} iterations near the close approach and the simulator reports it.{orbit_collapse_words} Linearized implicit Euler runs
  on at those steps and returns nonsense (separation errors of tens to hundreds of metres, energy
  gains of thousands of times), without any sign of trouble.
{collision_words}
{layer_words}
{billiard_words}
- **Penalty ignores COR** (it is a conservative spring: every floor bounce is elastic) and a soft
  one lets disks through: at k = {penalty_default_k} (the default) the falling disk passes through the floor
  and the two disks through each other. A stiff one is only stable for ω·dt < 2 with ω = √(k/m) (the
  undamped limit of section 2): k = {penalty_stiffest} on unit masses needs dt < {penalty_stiffest_dt}.
{cradle_note}
- For collision problems the "order" in the table is erratic (including negative values): where
  the contact falls inside a step changes with dt, so errors do not fall on a straight line.
"""

STABILITY_WORDS = """\
### What it says

- {damped_match}. Damping gives explicit Euler a stable range it does not have undamped
  ({damped_explicit_undamped}): below b/k, i.e. ω dt < 2ζ, as long as ζ ≤ 1. Damping shrinks
  symplectic Euler's range: from 2/ω undamped to {symplectic_critical} at critical damping
  (closed form {symplectic_critical_exact}/ω); heavily damped, both limits approach dt = 1/γ.
  Both implicit methods held at every step tried, up to ω dt = {damped_top}.
- Without damping (the second table; springs of stiffness k on unit masses, bisection on ω_max·dt to
  {stab_bisection} %) symplectic Euler's limit is ω_max·dt = 2, where ω_max is the fastest mode: √(k/m) for
  one spring and {row_ratio}·√(k/m) for a row of {row_bobs}, so a chain of springs needs about half the step.
  Explicit Euler's energy grows by 1 + (ω dt)² every step at every dt; the table's value is only
  where that growth reached the study's blow-up mark (x{blow_up} within {stab_periods} periods of the fastest
  mode).
"""

ROBUSTNESS_WORDS = """\
### What it says

- **`simple` tunnels** as soon as one step carries the disk across the contact band (the first
  miss at speed·dt = {simple_band} m; the band is the disk's plus the edge's diameter, {edge_band} m): the
  red triangle above the dashed line. {simple_stuck}
- {ccd_robust}
- **Random shots, judged by energy** (the fourth chart and the third table; {shots_per_target} shots at each
  of the {shots_targets}, the same shots for every method): {shots_perfect} The others:
{shots_failures}
  {shots_compat}
- **`penalty` tunnels whenever the disk is fast enough to compress the penalty spring by the
  thickness plus the radii**: by energy balance (second chart) the compression is v·√(m/k), so it
  goes through above v = (r_disk + r_edge + thickness)·√(k/m) = {penalty_speeds} m/s for k =
  {penalty_k_list}, whatever the step; a large step only makes it worse (it skips the spring){penalty_unstable}.
  A disk that does bounce sinks in by v·√(m/k) − thickness, up to the whole radii sum just below
  the tunnelling speed (third chart and second table: where penalty stops bouncing against speed,
  stiffness and dt). {penalty_limit_words}
"""

NEWTON_INTRO = """\
### Where implicit Euler's Newton iteration fails

Two bodies (μ = {newton_mu}) started at apoapsis r = {newton_apoapsis} with eccentricities from low to \
high, so that the periapsis r_p comes closer and its pull stiffer (ω_p = √(μ/r_p³)), each run for \
{newton_periods} periods over a sweep of dt, with implicit Euler (Newton until the update is below \
{newton_tolerance} of the step's velocities, at most {newton_limit} iterations, each step halved while it would not \
lower the residual's energy) and linearized implicit Euler (one Newton step)."""

HYBRID_INTRO = """\
{box_disks} disks dropped into a box (three half-planes) under gravity, COR {box_cor}, dt = {box_dt} s,
for maxiters from {box_lo} to {box_hi}, and the other methods on the same pile for comparison. "In
a zone" counts the disks the failsafe moved (the study compares each step's end with the
handler's mid-step state); zone counts are the handler's own.
"""

HYBRID_WORDS = """\
### What it says

{pile_maxiters_words}

{pile_outcome_words} {pile_penalty_words}
"""

PROFILE_WORDS = """\
### What it says

"Model no more than a scene needs": the table lists, for each scene, the forces it has, the pair
kinds its collision handling visits, and the cost of each part per step. Forces are timed by
wrapping each of the scene's forces (the clock's own cost taken off); the integrator's solve is the
rest of its phase; detection, response and failsafe come from the simulator's own phase timings;
"rest" is what the step spends outside those (copying the state, the finite check, and collision
work that the handler does not itemise, such as all of `simple`'s).

- A small explicit scene costs well under a microsecond per step; **the implicit integrators cost
  {implicit_cost} times more on the same scene**, almost all of it in assembling and solving the
  linear system (once for linearized implicit Euler, once per Newton iteration for implicit Euler).
{detection_words} `continuous-time` costs {ct_over_simple} times what `simple` does on the
  billiard break; on the pile the hybrid costs {pile_hybrid_over_simple} times `simple`{pile_profile_words}.
- The penalty force is {penalty_share} of a penalty scene's step (billiard break, pile).
"""

PICK = """\
## What to pick, in plain words

- **Forces only (springs, gravity, orbits)**: symplectic Euler. Keep dt below 2/ω of the stiffest
  spring (ω = √(k/m)); with damping the limit is 2/(γ + √(γ² + ω²)), {symplectic_critical} at
  critical damping, and a chain of springs needs about half the step (section 2, measured). At the
  same step its error is {sympl_vs_explicit} than explicit Euler's, and it needs {sympl_vs_implicit}
  (section 1). Its energy error stays bounded and shrinks in proportion to dt. Take implicit Euler
  only when stiffness forces a step above that limit: it held at every step tried, but damps the
  motion and costs {implicit_cost} times more per step.
- **Never explicit Euler** for anything that oscillates or orbits: undamped it grew at every step
  tried, and with damping it is stable only below b/k ({explicit_gain_words}).
{fast_pick}
- **Dense contact (piles, stacks)**: {dense_pick}
- **Billiards-like scenes (many separate two-body impacts)**: `simple` with a small step, or
  `continuous-time` when the step is large or objects fast: {billiards_keep}.
{compat_pick_line}
- **Collisions in general**: {shots_ct}; see section 3 for the rest.
- **Penalty**: only with a stiffness chosen for the fastest impact (v < (radii + thickness)·√(k/m))
  and a step below 2·√(m/k); it ignores COR.
"""

ODDITIES = """\
## Things in the simulator that look wrong or cost more than they should

{billiard_oddity}{layer_oddity}{shots_oddity}{compat_oddity}- Implicit Euler fails on the orbit {orbit_failure}: Newton does not converge in
  {newton_limit} iterations. Linearized implicit Euler returns large errors there, silently.
{oddity_broad}{oddity_stats}"""


def document(sections, facts, elapsed):
    when = ""
    if elapsed:
        when = (f"The last regeneration ran the experiments in {elapsed:.0f} s of wall time (the whole "
                "command, build included, prints its own total). ")
    parts = [
        INTRO.format(elapsed=when, machine=facts.get("machine", "its hardware threads uncounted")),
        PICK.format(**facts),
        MODES.format(**facts),
        METHODS.format(**facts),
        PROBLEMS.format(**facts),
        "## 1. Accuracy against cost\n\nOne chart per problem: the error (log) against the wall time per "
        "simulated second (log) for every method over its sweep of dt. Circled points are the Pareto "
        "front: no other run of any method is both cheaper and more accurate.",
        sections["accuracy"],
        ACCURACY_WORDS.format(**facts),
        sections.get("audit", ""),
        "## 2. Stability: where each integrator's step limit is\n\nA damped spring, u'' = −ω²u − 2γu' "
        f"(unit mass, ω = {facts['damped_omega']} rad/s, damping ratio ζ = γ/ω), is where the limits are "
        "real: explicit Euler is stable only with damping, symplectic Euler's limit moves with it, and "
        "both have closed forms (derived in `study/damped_stability.h` from the eigenvalues of one step, "
        "and checked against them in `tests/study/damped_stability_test.cpp`). Each probe runs the "
        f"spring in the simulator for {facts['damped_steps']} steps and calls it stable when its energy's "
        f"maximum over the second half is not above the first half's (by more than {facts['damped_neutral']} %, so "
        "that a "
        "neutral oscillation counts as stable); a bisection over a grid of time steps "
        f"{facts['damped_grid']} apart finds the largest stable one.",
        sections["damped"],
        sections["stability"],
        STABILITY_WORDS.format(**facts),
        NEWTON_INTRO.format(**facts) if sections.get("newton") else "",
        sections.get("newton", ""),
        facts.get("newton_words", ""),
        "### Implicit Euler's Newton iterations per step" if sections.get("newton_iterations") else "",
        sections.get("newton_iterations", ""),
        facts.get("newton_iteration_words", ""),
        f"## 3. Collision robustness\n\nA disk (radius {facts['edge_disk_radius']} m, mass "
        f"{facts['edge_disk_mass']} kg) thrown straight at a thin fixed edge (radius {facts['edge_radius']} m), "
        f"COR {facts['edge_cor']}, for every collision method over speed x dt. At the end it "
        "has *bounced* (its own side, moving away), *tunnelled* (the far side), got *stuck* (overlapping "
        "the edge, or stopped on its own side), or the run was *unstable*. The second chart shows how "
        "deep the penalty methods let it sink, the third where penalty stops bouncing, and the fourth judges "
        "random shots by energy as well.",
        sections["robustness"],
        sections["penalty"],
        sections["shots"],
        ROBUSTNESS_WORDS.format(**facts),
        "## 4. The hybrid handler's cost on a dense pile\n\n" + HYBRID_INTRO.format(**facts),
        sections["hybrid"],
        HYBRID_WORDS.format(**facts),
        "## 5. Where the time goes, per scene",
        sections["profile"],
        PROFILE_WORDS.format(**facts),
        CONTACTS_INTRO.format(**facts) if sections.get("contacts") else "",
        sections.get("contacts", ""),
        facts.get("contacts_words", "") if sections.get("contacts") else "",
        ODDITIES.format(**facts),
    ]
    return "\n\n".join(p.strip("\n") for p in parts if p.strip()) + "\n"
