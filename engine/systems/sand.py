from engine.components import Sand
from engine.systems.surface import SurfaceProcessor


class SandProcessor(SurfaceProcessor):
    """Bunkers: heavy going, the green's drag times Sand.drag_scale."""

    name = "sand"
    marker = Sand
