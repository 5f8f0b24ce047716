"""Simulators: stepping, NumPy views and setters, diagnostics, compat."""
import _thread
import signal
import threading

import numpy as np
import pytest

import fosssim


def free_fall(n_steps=100, dt=0.01):
    s = fosssim.Scene()
    s.set_integrator("symplectic-euler", dt)
    s.duration = n_steps * dt
    s.add_particle((0.0, 10.0), velocity=(1.0, 0.0), mass=2.0)
    s.add_gravity((0.0, -9.81))
    return s


def test_steps_follow_free_fall():
    sim = fosssim.Simulator(free_fall())
    x = sim.positions  # a view: it follows the steps
    sim.step(50)
    assert sim.steps_taken == 50
    assert sim.time == pytest.approx(0.5)
    # symplectic Euler: v exact, x = x0 + v0 t - g dt^2 k(k+1)/2
    assert sim.velocities[0, 1] == pytest.approx(-9.81 * 0.5, abs=1e-12)
    assert x[0, 0] == pytest.approx(0.5, abs=1e-12)
    assert x[0, 1] == pytest.approx(10.0 - 9.81 * 0.01**2 * 50 * 51 / 2, abs=1e-12)


def test_views_are_read_only_and_setters_validate():
    sim = fosssim.Simulator(free_fall())
    with pytest.raises(ValueError):
        sim.positions[0, 0] = 5.0
    sim.positions = np.array([[1.0, 2.0]])
    np.testing.assert_array_equal(sim.positions, [[1.0, 2.0]])
    with pytest.raises(fosssim.SceneError, match=r"expected an array of shape \(1, 2\)"):
        sim.velocities = np.zeros((2, 2))
    # A bad value is a ValueError (SceneError), as a wrong shape here and a NaN assigned to a Scene:
    # it was a SimulationError, though nothing was simulated.
    with pytest.raises(fosssim.SceneError, match="velocities: particle 0 has a non-finite value"):
        sim.velocities = np.array([[np.nan, 0.0]])
    with pytest.raises(ValueError, match="positions: particle 0 has a non-finite value"):
        sim.positions = np.array([[0.0, np.inf]])
    assert sim.masses.tolist() == [2.0]
    assert not sim.masses.flags.writeable


def test_view_outlives_the_name():
    view = fosssim.Simulator(free_fall()).positions  # the view keeps its simulator alive
    assert view.shape == (1, 2) and view[0, 1] == 10.0


def test_run_every_and_callback_and_stop():
    sim = fosssim.Simulator(free_fall(100))
    seen = []
    taken = sim.run(every=10, callback=lambda s: seen.append(s.steps_taken))
    assert taken == 100 and seen == list(range(10, 101, 10))
    sim2 = fosssim.Simulator(free_fall(100))
    assert sim2.run(callback=lambda s: s.steps_taken < 30, every=10) == 30


def test_run_counts_every_from_its_own_start():
    sim = fosssim.Simulator(free_fall(100))
    sim.step(3)
    seen = []
    assert sim.run(25, every=10, callback=lambda s: seen.append(s.steps_taken)) == 25
    assert seen == [3 + 10, 3 + 20, 3 + 25]  # 10 and 20 steps into the run, then its last step


def test_any_false_value_from_the_callback_stops_the_run():
    for stop in (False, np.False_, 0, 0.0, ""):
        sim = fosssim.Simulator(free_fall(100))
        assert sim.run(every=5, callback=lambda s, stop=stop: stop if s.steps_taken >= 15 else True) == 15, stop
        assert sim.steps_taken == 15
    # None (a callback that returns nothing) goes on.
    assert fosssim.Simulator(free_fall(100)).run(every=5, callback=lambda s: None) == 100


def test_negative_counts_raise_value_error():
    # step(-5) did nothing and run(-1) raised a SimulationError: an argument out of range is a
    # ValueError for every call that takes a number of steps, and nothing is stepped.
    sim = fosssim.Simulator(free_fall())
    for call, message in ((lambda: sim.step(-5), "count must be >= 0, got -5"),
                          (lambda: sim.run(-1), "steps must be >= 0, got -1"),
                          (lambda: sim.run(10, every=0), "every must be >= 1, got 0")):
        with pytest.raises(ValueError, match=message) as info:
            call()
        assert not isinstance(info.value, fosssim.SimulationError)
    with pytest.raises(ValueError, match="threads must be >= 1, got 0"):
        fosssim.Simulator(free_fall(), threads=0)
    assert sim.steps_taken == 0
    sim.step(0)
    assert sim.run(0) == 0 and sim.steps_taken == 0


def test_ctrl_c_interrupts_a_long_step_or_run():
    # Python's SIGINT handler only notes the signal: with nothing checking for it between steps,
    # the KeyboardInterrupt came after the whole call (here about ten seconds of steps).
    # A shell starting Python as a background job without job control ignores SIGINT, and Python
    # then leaves it ignored (interrupt_main is a no-op): the handler Ctrl-C runs is set here.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        _interrupt_long_calls()
    finally:
        signal.signal(signal.SIGINT, previous)


def _interrupt_long_calls():
    total = 50_000_000
    for call in (lambda sim: sim.step(total), lambda sim: sim.run(total)):
        sim = fosssim.Simulator(free_fall(100, 1e-6), diagnostics=False)
        ctrl_c = threading.Timer(0.2, _thread.interrupt_main)  # as Ctrl-C does to the main thread
        ctrl_c.start()
        try:
            with pytest.raises(KeyboardInterrupt):
                call(sim)
        finally:
            ctrl_c.cancel()
        assert 0 < sim.steps_taken < total
        sim.step()  # the steps before the interrupt stand, and stepping goes on


def test_diagnostics_columns_and_physics():
    sim = fosssim.Simulator(free_fall(20))
    sim.run()
    d = sim.diagnostics()
    assert list(d) == sim.columns
    assert len(d["step"]) == 21  # the initial state, then every step
    np.testing.assert_array_equal(d["step"], np.arange(21))
    np.testing.assert_allclose(d["momentum_y"], 2.0 * -9.81 * d["time"], atol=1e-10)
    np.testing.assert_allclose(d["energy"], d["kinetic"] + d["potential"])
    assert (d["cost_total"][1:] > 0).all()
    df = sim.dataframe()
    assert list(df.columns) == sim.columns and len(df) == 21


def stiff_spring(dt, duration, k):
    """Two particles on a spring too stiff for explicit Euler at dt: their velocities grow until
    they are not finite."""
    s = fosssim.Scene()
    s.set_integrator("explicit-euler", dt)
    s.duration = duration
    a = s.add_particle((0, 0), mass=1)
    b = s.add_particle((1, 0), mass=1)
    s.add_spring(s.add_edge(a, b), k=k, l0=0.5)
    return fosssim.Simulator(s)


def test_failed_step_raises_with_the_step():
    sim = stiff_spring(dt=1.0, duration=100, k=1e6)
    with pytest.raises(fosssim.SimulationError, match="step"):
        sim.run()


def test_a_failed_step_leaves_the_last_good_state_and_stops_the_simulator():
    sim = stiff_spring(dt=0.01, duration=1.0, k=1e4)
    good = None
    with pytest.raises(fosssim.SimulationError, match="non-finite") as info:
        for _ in range(100):
            sim.step()
            good = (sim.steps_taken, sim.time, sim.positions.copy(), sim.velocities.copy())
    assert good is not None and np.isfinite(good[3]).all()
    failed_step = good[0] + 1
    assert str(info.value).startswith(f"step {failed_step} ")
    # Positions, velocities, time, steps and diagnostics are all the last good step's (the
    # steps and time used to count the failed step while the views did not show it).
    steps, time, x, v = good
    assert (sim.steps_taken, sim.time) == (steps, time)
    np.testing.assert_array_equal(sim.positions, x)
    np.testing.assert_array_equal(sim.velocities, v)
    np.testing.assert_array_equal(sim.diagnostics()["step"], np.arange(steps + 1))
    # And it goes no further: the next step used to go on from the failed step's hidden state.
    for call in (sim.step, sim.run):
        with pytest.raises(fosssim.SimulationError, match=f"cannot go on after its failed step {failed_step} "):
            call()
    assert sim.steps_taken == steps


def test_compat_is_an_option(assets):
    scene = fosssim.Scene.load(str(assets / "t2m2" / "ContinuousTimeTests" / "head_on_swap.xml"))
    a = fosssim.Simulator(scene, compat=True)
    assert a.compat
    a.run()
    assert a.steps_taken == scene.num_steps


def test_simulator_owns_a_copy_of_the_scene():
    s = free_fall()
    sim = fosssim.Simulator(s)
    s.add_particle((5, 5))  # changes the Scene, not the running simulation
    assert sim.num_particles == 1
    sim.step()


def resting_disk():
    s = fosssim.Scene()
    s.set_integrator("symplectic-euler", 0.01)
    s.duration = 10.0
    s.add_particle((0.0, 0.1), radius=0.1)
    s.add_halfplane((0.0, 0.0), (0.0, 1.0))
    s.add_gravity((0.0, -9.81))
    s.set_collision("hybrid", cor=0.0)
    return s


def test_a_resting_disk_sleeps_and_assigning_its_velocity_wakes_it():
    for sleep in (True, False):
        sim = fosssim.Simulator(resting_disk(), sleep=sleep)
        sim.step(200)
        rest = sim.positions.copy()
        sim.step(10)
        if sleep:  # asleep: not moved at all
            assert np.array_equal(sim.positions, rest)
            assert not sim.velocities.any()
        sim.velocities = np.array([[1.0, 0.0]])
        sim.step()
        # Frictionless floor, no horizontal force: one step of 0.01 s at 1 m/s.
        assert sim.positions[0, 0] == pytest.approx(rest[0, 0] + 0.01, abs=1e-12)



def test_threads_stepping_one_simulator_take_turns(assets):
    # step() releases the GIL: without the simulator's own lock two threads stepped one state at
    # once and the interpreter crashed (in about half of these ten rounds). With it every step is
    # whole: the state is the one a single thread reaches in as many steps, and the diagnostics
    # have a row per step.
    scene = fosssim.Scene.load(str(assets / "t2m2" / "HolisticTests" / "mixed_sizes.xml"))
    alone = fosssim.Simulator(scene)
    alone.step(400)
    for _ in range(10):
        sim = fosssim.Simulator(scene)
        errors = []

        def stepper():
            try:
                for _ in range(200):
                    sim.step()
            except Exception as e:  # noqa: BLE001 (reported in the test's thread)
                errors.append(e)

        def reader():
            try:
                while any(t.is_alive() for t in steppers):
                    d = sim.diagnostics()
                    assert len(d["step"]) == d["step"][-1] + 1
                    sim.svg(32, 32)
            except Exception as e:  # noqa: BLE001
                errors.append(e)

        steppers = [threading.Thread(target=stepper) for _ in range(2)]
        threads = steppers + [threading.Thread(target=reader)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        assert errors == []
        assert sim.steps_taken == 400
        np.testing.assert_array_equal(sim.diagnostics()["step"], np.arange(401))
        np.testing.assert_array_equal(sim.positions, alone.positions)
        np.testing.assert_array_equal(sim.velocities, alone.velocities)
