"""Plain-data components: no behaviour beyond small derived helpers."""

from engine.components.ball import Ball
from engine.components.body import Body
from engine.components.collider import Collider, Material
from engine.components.cup import Cup
from engine.components.drag import Drag
from engine.components.hazards import Bumper, Ice, Region, Sand, Slope, Water, Windmill
from engine.components.hole_state import HoleState
from engine.components.name import Name
from engine.components.shot import ShotInput
from engine.components.wall import Wall

__all__ = ["Ball", "Body", "Bumper", "Collider", "Cup", "Drag", "HoleState", "Ice", "Material", "Name", "Region",
           "Sand", "ShotInput", "Slope", "Wall", "Water", "Windmill"]
