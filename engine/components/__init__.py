"""Plain-data components: no behaviour beyond small derived helpers."""

from engine.components.body import Body
from engine.components.collider import Collider, Material
from engine.components.drag import Drag
from engine.components.name import Name
from engine.components.wall import Wall

__all__ = ["Body", "Collider", "Drag", "Material", "Name", "Wall"]
