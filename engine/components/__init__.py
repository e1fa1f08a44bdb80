"""Plain-data components: no behaviour beyond small derived helpers."""

from polygolf.engine.components.ball import Ball
from polygolf.engine.components.body import Body, BodyScratch
from polygolf.engine.components.collider import Collider, Material
from polygolf.engine.components.cup import Cup
from polygolf.engine.components.drag import Drag
from polygolf.engine.components.hazards import Bumper, Ice, Region, Sand, Slope, Water, Windmill
from polygolf.engine.components.hole_state import HoleState
from polygolf.engine.components.launcher import Launcher
from polygolf.engine.components.name import Name
from polygolf.engine.components.shot import ShotInput
from polygolf.engine.components.wall import Wall

__all__ = ["Ball", "Body", "BodyScratch", "Bumper", "Collider", "Cup", "Drag", "HoleState", "Ice", "Launcher",
           "Material", "Name", "Region", "Sand", "ShotInput", "Slope", "Wall", "Water", "Windmill"]
