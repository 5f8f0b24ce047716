"""Simulator and Scene arguments the docs promise to check: positions and velocities of shape
(N, 2) only (a flat (2N,) array may be N x-values then N y-values, and was reshaped silently), and
at most the command line's 1024 threads."""
import numpy as np
import pytest

import fosssim


@pytest.mark.parametrize("target", ["scene", "simulator"])
def test_flat_position_arrays_are_refused(target, one_disk_scene):
    s = one_disk_scene()
    s.add_particle((1.0, 0.0))
    obj = s if target == "scene" else fosssim.Simulator(s)
    with pytest.raises(fosssim.SceneError, match=r"positions: expected an array of shape \(2, 2\), got shape \(4\)"):
        obj.positions = np.array([5.0, 6.0, 7.0, 8.0])
    with pytest.raises(fosssim.SceneError, match=r"velocities: expected an array of shape \(2, 2\), got shape \(4\)"):
        obj.velocities = np.zeros(4)
    assert np.array_equal(obj.positions, [[0.0, 0.0], [1.0, 0.0]])


def test_threads_are_capped_as_on_the_command_line(one_disk_scene):
    with pytest.raises(ValueError, match="threads must be an integer from 1 to 1024, got 1000000"):
        fosssim.Simulator(one_disk_scene(), threads=10**6)
    with pytest.raises(ValueError, match="threads must be >= 1, got 0"):
        fosssim.Simulator(one_disk_scene(), threads=0)
    assert fosssim.Simulator(one_disk_scene(), threads=2).num_particles == 1
