"""The Body component is the physics layer's rigid-body state (engine.physics.body): the kernels
work on it directly, and an entity carries it as is."""

from polygolf.engine.physics.body import Body, BodyScratch

__all__ = ["Body", "BodyScratch"]
