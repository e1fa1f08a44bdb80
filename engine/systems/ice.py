from polygolf.engine.components import Ice
from polygolf.engine.systems.surface import SurfaceProcessor


class IceProcessor(SurfaceProcessor):
    """Ice: the ball keeps only a small part of the green's drag and glides."""

    name = "ice"
    marker = Ice
