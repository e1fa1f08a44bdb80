"""Golf on top of the engine: hole layout, holes and courses, the hole as a world, the golfer."""
