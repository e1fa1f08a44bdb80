"""The broadphase grid answers like a brute-force search, and neither huge items nor huge queries
make it slow or hungry."""

from __future__ import annotations

import time

from hypothesis import given, settings
from hypothesis import strategies as st

from polygolf.engine.loading.scene import Scene, build_scene
from polygolf.engine.physics.grid import SpatialGrid, overlaps

coord = st.floats(-3000, 3000, allow_nan=False)
size = st.floats(0.01, 2000, allow_nan=False)
boxes = st.builds(lambda x, y, w, h: (x, y, x + w, y + h), coord, coord, size, size)


@settings(max_examples=200, deadline=None)
@given(st.lists(boxes, min_size=1, max_size=30), st.lists(boxes, min_size=1, max_size=5))
def test_queries_and_pairs_match_brute_force(items, queries):
    grid = SpatialGrid(1.0)
    for i, box in enumerate(items):
        grid.insert(i, box)
    for query in queries:
        found = grid.query(query)
        assert len(found) == len(set(found))
        assert set(found) == {i for i, box in enumerate(items) if overlaps(query, box)}
    expected = {(i, j) for i in range(len(items)) for j in range(i + 1, len(items)) if overlaps(items[i], items[j])}
    assert set(grid.pairs()) == expected


def test_a_kilometre_wall_and_a_fast_body_stay_cheap():
    scene = Scene.model_validate({
        "name": "huge", "bodies": [{"name": "ball", "shape": {"regular": 5, "radius": 0.3},
                                    "position": [0.0, 2.0], "velocity": [1000.0, -1000.0]}],
        "walls": [{"box": {"center": [0.0, -1000.0], "half": [1000.0, 1000.0]}},
                  {"box": {"center": [0.0, 1000.0], "half": [1000.0, 1.0]}}],
    })
    started = time.perf_counter()
    with build_scene(scene, "fast") as sim:
        sim.run(2.0)
        ball = sim.body("ball")
        assert ball.y > 0.0  # the floor held
    assert time.perf_counter() - started < 10.0
