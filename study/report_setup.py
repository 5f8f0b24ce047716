"""The set-up numbers docs/study.md quotes, from the data (report.py merges them into its facts):
the accuracy problems' set-ups and exact answers (problems.csv, written from the problems'
constants and closed_forms.h), the study's blow-up mark, and the thin-edge experiment's radii and
the collision methods' resolved settings (robustness.csv). Nothing here is typed by hand: a
changed constant in study/*.cpp changes the page.
"""
import math
import os

import study_data as sd


def num(x):
    """A set-up number as people write it: 9.81, 0.5, 1e2, 1e6, 1.5e-4 (a minus sign, not a hyphen)."""
    return _num(x).replace("-", "−")


def _num(x):
    if not sd.finite(x):
        return "—"
    if x == 0:
        return "0"
    exponent = math.floor(math.log10(abs(x)))
    if (exponent >= 2 or exponent <= -4) and x == 10.0 ** exponent:
        return f"1e{exponent}"
    if abs(x) >= 1e4 or abs(x) < 1e-3:
        mantissa, e = f"{x:.3e}".split("e")
        return f"{mantissa.rstrip('0').rstrip('.')}e{int(e)}"
    return f"{x:.4g}"


def problems_table(p):
    """The rows of the page's table of problems, every number from problems.csv."""
    pr, sp, dm, orb = p["projectile"], p["spring"], p["spring-damped"], p["orbit"]
    dk, fb, cr, bi = p["disks"], p["bounce-cor1"], p["cradle"], p["billiards"]
    omega = math.sqrt(sp["k"] / sp["mass"])
    bounces = sorted(name for name in p if name.startswith("bounce-cor"))
    cors = ", ".join(num(float(name[len("bounce-cor"):])) for name in bounces)
    rows = [
        ["projectile", f"mass {num(pr['mass'])} kg, x0 = ({num(pr['x0'])}, {num(pr['y0'])}) m, v0 = ({num(pr['vx'])}, "
         f"{num(pr['vy'])}) m/s, g = ({num(pr['gx'])}, {num(pr['gy'])}) m/s², {num(pr['duration'])} s",
         "x(t) = x0 + v0 t + g t²/2, v(t) = v0 + g t", "position error at the end"],
        ["undamped spring", f"mass {num(sp['mass'])} kg on a spring (k = {num(sp['k'])} N/m, rest length "
         f"{num(sp['rest'])} m) to a fixed anchor, stretched by {num(sp['stretch'])} m, {num(sp['duration'])} s",
         f"u(t) = u0 cos ωt, ω = √(k/m) = {num(omega)} rad/s", "position error at the end; energy error"],
        ["damped spring", f"the same with b = {num(dm['b'])} N·s/m, {num(dm['duration'])} s",
         "m u'' + b u' + k u = 0: γ = b/2m, ω_d = √(ω² − γ²), u = e^(−γt)(u0 cos ω_d t + (v0 + γu0)/ω_d sin ω_d t) "
         "(critical and over-damped forms in `closed_forms.cpp`)",
         "position error; error of the energy against m u'²/2 + k u²/2 of the exact solution"],
        ["two-body orbit", f"masses {num(orb['mass'])} + {num(orb['mass'])}, G = {num(orb['G'])} (μ = G(m1 + m2) = "
         f"{num(orb['mu'])}), relative position ({num(orb['rx'])}, {num(orb['ry'])}), relative velocity "
         f"({num(orb['vx'])}, {num(orb['vy'])}), {num(orb['periods'])} periods",
         f"vis-viva: ε = v²/2 − μ/r, a = −μ/2ε = {orb['a']:.3f}; h = r × v; e = √(1 + 2εh²/μ²) = {orb['e']:.2f}; "
         f"period T = 2π√(a³/μ) = {orb['period']:.2f} s; position from Kepler's equation M = E − e sin E, "
         "M = M0 + 2πt/T",
         "separation error at the end; energy, angular momentum and momentum drift; period of the first revolution"],
        ["two disks", f"masses {num(dk['m1'])} and {num(dk['m2'])}, radii {num(dk['r'])}, at ({num(dk['x1'])}, "
         f"{num(dk['y1'])}) and ({num(dk['x2'])}, {num(dk['y2'])}), velocities ({num(dk['v1'])}, 0) and "
         f"({num(dk['v2'])}, 0), COR {num(dk['cor'])}, {num(dk['duration'])} s",
         "contact at the first root of \\|d + w t\\| = r1 + r2 (here t_c = " f"{dk['contact_time']:.3f} s); along the "
         "contact normal n the approach speed u becomes −COR·u: J = (1 + COR) u / (1/m1 + 1/m2), v1 −= J n/m1, "
         "v2 += J n/m2; free flight before and after", "position error at the end; contact-time error"],
        [f"floor bounce, COR {cors}", f"mass {num(fb['mass'])} kg, radius {num(fb['r'])}, from ({num(fb['x0'])}, "
         f"{num(fb['y0'])}) at ({num(fb['vx'])}, {num(fb['vy'])}) m/s under gravity ({num(fb['g'])} m/s²) onto the "
         f"half-plane y ≥ 0, {num(fb['duration'])} s (one bounce)",
         f"contact when y = r: t_c = (v_y0 + √(v_y0² + 2g(y0 − r)))/g = {fb['contact_time']:.3f} s; the normal "
         "velocity becomes −COR·v_y(t_c); free flight after (COR 0: rests on the floor)",
         "position error at the end; contact-time error"],
        ["Newton's cradle", f"{num(cr['disks'])} unit disks (r = {num(cr['r'])}) in a row with {num(cr['gap'])} m "
         f"gaps, the first at {num(cr['speed'])} m/s from {num(cr['first_gap'])} m away, {num(cr['duration'])} s",
         "hard elastic disks pass the momentum on one contact at a time: each disk crosses its gap and stops, the "
         f"last leaves at {num(cr['speed'])} m/s", "position error at the end; energy and momentum error"],
        ["billiard break", f"a cue disk at {num(bi['speed'])} m/s into a {num(bi['rack'])}-disk rack "
         f"({num(bi['gap'])} m gaps, radius {num(bi['r'])}), no cushions, COR {num(bi['cor'])}, "
         f"{num(bi['duration'])} s", "momentum and kinetic energy are conserved",
         "relative kinetic-energy error; momentum error"],
    ]
    return rows


def facts(data_dir, r):
    """Placeholders for report_text.py."""
    f = {}
    if os.path.exists(os.path.join(data_dir, "problems.csv")):
        p = {}
        for row in sd.load(data_dir, "problems"):
            p.setdefault(row["problem"], {})[row["name"]] = row["value"]
        f["blow_up"] = num(p["study"]["blow_up"])
        threads = p["study"].get("hardware_threads", 0)
        f["machine"] = (f"{threads:.0f} hardware threads as the run counted them, shared with whatever else ran"
                        if sd.finite(threads) and threads > 0 else "its hardware threads uncounted")
        f["problems_table"] = r.table(["problem", "set-up", "exact answer", "error measured"], problems_table(p))
    def first_row(name):
        rows = sd.load(data_dir, name) if os.path.exists(os.path.join(data_dir, name + ".csv")) else []
        return rows[0] if rows else {}

    # The wildest run that still ended "ok": how wrong a run may be below the blow-up mark.
    acc = sd.load(data_dir, "accuracy") if os.path.exists(os.path.join(data_dir, "accuracy.csv")) else []
    ok = [row for row in acc if row["outcome"] == "ok" and sd.finite(row["energy_error_max"])]
    if ok:
        w = max(ok, key=lambda row: row["energy_error_max"])
        off = num(float(f"{w['energy_error_max']:.2g}"))
        f["wildest_ok"] = (f"`{w['method']}` on the {w['problem']} at dt = {num(w['dt'])} s ended \"ok\" with its "
                           f"energy off by up to {off} times its scale")
    else:
        f["wildest_ok"] = "no run of this regeneration was that wrong"
    contacts = first_row("contacts_summary")
    f["stopped_energy"] = num(contacts.get("stopped_energy", float("nan")))
    f["stopped_tail"] = f"{(1 - contacts.get('stopped_share', float('nan'))) * 100:.3g}"
    f["loosest_rest"] = num(contacts.get("loosest_rest", float("nan")))
    f["box_cor"] = num(first_row("hybrid").get("cor", float("nan")))
    f["damped_neutral"] = f"{first_row('damped_stability').get('neutral_margin', float('nan')) * 100:.2g}"
    stab = sd.load(data_dir, "stability")
    f["row_bobs"] = num(max(row["bobs"] for row in stab))
    if "horizon_periods" in stab[0]:
        f["stab_periods"] = num(stab[0]["horizon_periods"])
        f["stab_bisection"] = f"{(stab[0]['bisection_ratio'] - 1) * 100:.2g}"
    rob = sd.load(data_dir, "robustness")
    first = {}
    for row in rob:
        first.setdefault(row["method"], row)
    any_row = next(iter(first.values()))
    f["edge_disk_radius"] = num(any_row["disk_radius"])
    f["edge_radius"] = num(any_row["edge_radius"])
    f["edge_disk_mass"] = num(any_row["disk_mass"])
    f["edge_band"] = num(2 * (any_row["disk_radius"] + any_row["edge_radius"]))
    hybrid = first.get("hybrid")
    if hybrid:
        f["hybrid_maxiters"] = num(hybrid["maxiters"])
        f["hybrid_k"] = num(hybrid["penalty_k"])
        f["hybrid_thickness"] = num(hybrid["thickness"])
    penalty = [row for row in first.values() if row["collision"] == "penalty"]
    penalty.sort(key=lambda row: row["penalty_k"])
    default = [row for row in penalty if row["penalty_k"] == row["default_k"]]  # the collision table's default
    from charts_limits import contact_limit, tunnel_speed
    f["penalty_thickness"] = " / ".join(sorted(set(num(row["thickness"]) for row in penalty)))
    f["penalty_ks"] = ", ".join(num(row["penalty_k"]) + (" (the default)" if row in default else "")
                                for row in penalty[:-1]) + f" and {num(penalty[-1]['penalty_k'])}"
    f["penalty_k_list"] = (", ".join(num(row["penalty_k"]) for row in penalty[:-1])
                           + f" and {num(penalty[-1]['penalty_k'])}")
    f["edge_cor"] = num(any_row["cor"])
    f["penalty_speeds"] = (", ".join(f"{tunnel_speed(row):.2g}" for row in penalty[:-1])
                           + f" and {tunnel_speed(penalty[-1]):.2g}")
    f["penalty_default_k"] = num((default or penalty)[0]["penalty_k"])
    f["penalty_stiffest"] = num(penalty[-1]["penalty_k"])
    f["penalty_stiffest_dt"] = num(float(f"{contact_limit(penalty[-1]):.2g}"))
    return f
