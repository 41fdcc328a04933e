import numpy as np
import pytest
from helpers import box_world

from haven_sim.sim.occupancy import OCCUPIED, rasterise
from haven_sim.sim.world import packaged_world
from haven_sim.sim.world_file import load_world


def test_grid_covers_world_with_padding_and_marks_walls():
    g = rasterise(box_world(4.0, thickness=0.1), resolution_m=0.05, padding_m=0.5)
    assert g.origin_x == pytest.approx(-0.55) and g.origin_y == pytest.approx(-0.55)
    assert g.width == g.height == round((4.05 + 0.5 + 0.55) / 0.05)
    assert g.is_occupied(0.0, 2.0) and g.is_occupied(4.02, 2.0) and g.is_occupied(2.0, 3.98)
    assert not g.is_occupied(2.0, 2.0) and not g.is_occupied(0.2, 0.2)
    assert g.is_occupied(-10, 0)  # outside the grid counts as occupied
    assert g.data.dtype == np.int8 and set(np.unique(g.data)) == {0, OCCUPIED}


def test_thin_walls_are_not_lost_at_coarse_resolution():
    g = rasterise(box_world(4.0, thickness=0.01), resolution_m=0.2)
    row = g.data[g.cell_of(2.0, 2.0)[0]]
    left, right = g.cell_of(0.0, 2.0)[1], g.cell_of(4.0, 2.0)[1]
    assert row[left] == OCCUPIED and row[right] == OCCUPIED  # a 1 cm wall in a 20 cm grid
    assert np.count_nonzero(row[left + 2 : right - 1]) == 0


def test_small_test_world_has_door_and_pillar():
    g = rasterise(load_world(packaged_world("small_test")))
    assert not g.is_occupied(4.0, 2.5)  # the door
    assert g.is_occupied(4.0, 1.0) and g.is_occupied(6.3, 3.8)


def test_resolution_must_be_positive():
    with pytest.raises(ValueError, match="resolution"):
        rasterise(box_world(), resolution_m=0.0)
