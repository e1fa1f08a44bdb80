from polygolf.engine.components import Sand
from polygolf.engine.systems.surface import SurfaceProcessor


class SandProcessor(SurfaceProcessor):
    """Bunkers: heavy going, the green's drag times Sand.drag_scale."""

    name = "sand"
    marker = Sand
